"""h245 (issues 24, 28): the voices h233's and h235's held-out batches left refused, read by class:
vocatives (a single noun set off at a sentence's start or end, "my ADJ NOUN"), British spellings, "Right
then,", idioms of moving ("makes its way to", "sets off for", "heads on over to"), a dialect's dropped
letters ("movin'", "'fore", "y'all") - and what must stay refused or keep its reading.

The sentences of the batch tests are the committed dev batches `dev_h245` (handover_styles_session10.json)
and `DEV_H245` (rephrasings.py), written with the held-out `held_h245` and `HELD_H245` before the rules.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import assert_refused_by_name, assert_written_spec
from rephrasings import DEV_H245
from test_tabletop import TASKS, assert_read_right_or_refused, signature

from nl2hltl2plan.language.frame_filler import filler
from nl2hltl2plan.language.spelling import american

DEV = [(int(task), text) for style in STYLES["dev_h245"].values() for task, text in style.items()]


@pytest.mark.data
@pytest.mark.parametrize(
    ("task", "text"),
    [
        (1, STYLES["dev_h245"]["british_foreman"]["1"]),  # "Right then, lads. ... Cheers, mate."
        (4, STYLES["dev_h245"]["british_foreman"]["4"]),  # "Listen up, guv. ... Brilliant work, keep it up!"
        (1, STYLES["dev_h245"]["ranch_hand"]["1"]),  # "Would y'all mind movin' ... red 'fore blue?"
        (1, "Transfer the three blocks to the opposite side, red before blue, sweetheart."),
        (3, "The three pillars set off for E, F and G beside arms a and b. No pillar may go on any other "
            "region."),
        (8, "The yellow block makes its way to I, then back to G. Red and blue head off to any empty "
            "region."),
    ],
)
def test_new_voices_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(
    ("task", "text"),
    [
        (1, "Transfer the three blocks to the opposite side, red before blue. Zebra."),  # a sentence alone
        (1, "Transfer the zebra, sweetheart, to the opposite side, red before blue."),  # a thing's phrase
    ],
)
def test_a_noun_that_may_name_a_thing_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


def test_vocatives_and_british_spellings_are_filler() -> None:
    assert american("marvellous") == "marvelous" and american("colour") == "color"
    assert filler(("my", "lovely", "assistants"), 2, set_off=True) and filler(("marvellous",), 0)
    assert not filler(("my", "lovely", "assistants"), 2)  # not set off: may be a thing's phrase


@pytest.mark.parametrize(
    "text",
    [
        DEV_H245["british_foreman"][3][0],  # "The robot arm gently places the carrot ... my good man."
        "First, the green apple and the orange make their way into the yellow plate, in either order. Only "
        "once both have arrived do the carrot and the red apple set off for the blue plate, again in either "
        "order.",
    ],
)
def test_tabletop_idioms_and_vocatives_give_the_tasks_and_order(text: str) -> None:
    task_id = 4 if "Only once" in text else 3
    assert signature(text) == signature(TASKS[task_id].instruction)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), DEV)
def test_development_batch_is_read_right_or_refused(task: int, text: str) -> None:
    from handover_specs import assert_written_spec_or_refused

    assert_written_spec_or_refused(task, text)


@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(DEV_H245))
def test_tabletop_development_voices_are_read_right_or_refused(style: str) -> None:
    assert_read_right_or_refused(DEV_H245[style])
