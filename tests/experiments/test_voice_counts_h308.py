"""h308 (issue 24): a handover voice's opening or closing that holds a count or an ordinal of its own things
("Two coats today.", "Right, first course.", "First things first.", "Three slates to lay.") is frame, as is
a call for the listener's eyes ("Look this way, please.", "Eyes front!") and a clause opened by a participle
("reading glasses on"). A count in a goal sentence, a count of a scene's things, a count said as an adverb
("One apiece.") and a pace ("One at a time.") stay read or refused.

The sentences are the committed batch `dev_h308` (handover_styles_session10.json), written with the
held-out `held_h308` before the rules.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.voice_remarks import attention, commanded

DEV = STYLES["dev_h308"]
PLACEMENT = "Put the three blocks into regions H, I and J, one block in each region."

WRITTEN = [
    (1, DEV["roofer"]["1"]),  # "First job of the day."
    (3, DEV["roofer"]["3"]),  # "Three slates to lay."
    (7, DEV["roofer"]["7"]),  # "First things first, ladder's footed."
    (4, DEV["optician"]["4"]),  # "Look this way, please."
    (8, DEV["optician"]["8"]),  # "Nice and still, reading glasses on."
    (2, "Two jobs today. " + PLACEMENT),
]

KEPT = [
    (2, "Three blocks to lay. " + PLACEMENT),  # a count of the scene's things
    (2, "One at a time. " + PLACEMENT),  # a pace
    (6, "Place the three objects on regions G, H and I, one each. The red block goes down before the blue"
     " block, second coat."),  # an ordinal inside a goal sentence
    (2, "Look at region K. " + PLACEMENT),  # a look at a thing
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_a_voices_counts_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), KEPT)
def test_a_count_a_task_may_need_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


def test_calls_for_the_eyes_and_participles() -> None:
    assert attention("Eyes front!") and attention("Look this way, please.")
    assert not attention("Look at the red block")
    assert not commanded("Nice and still, reading glasses on") and commanded("Bring the mug")
