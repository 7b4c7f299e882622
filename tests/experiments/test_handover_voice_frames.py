"""h187 (issue 24): the frames of new voices around a handover instruction, and five near classes that
held-out rephrasings left refused (h181's report). The sentences are committed batches of
handover_styles_session10.json: `dev100` (written with the held-out `validation34` before the rules) and
`validation34` (scored once at the end; read right or refused, never misread: `sweep`).

- Frames that say nothing, dropped as whole sentences or set phrases (`handover_frame_words.txt`): a
  stage manager's "Places, please." / "Curtain up!" / "That's a wrap.", a recipe's "Enjoy!", a coach's
  "huddle up" / "eyes on me", a letter's "I hope you are well" and "With love, <name>", "Safety first".
- `handover_registers`: "pillars, three, to ..." (a count after its noun); "are each set / meant to
  receive"; "none / not one of them (may be) put down ..." (no object); "comes back to".
- `handover_rewrites`: "it is hereby agreed that"; "only" before a completion clause.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import (
    assert_not_the_written_spec,
    assert_refused_by_name,
    assert_written_spec,
    assert_written_spec_or_refused,
)

from nl2hltl2plan.language.handover_phrases import normalise

DEV = [(int(task), text) for style in STYLES["dev100"].values() for task, text in style.items()]
HELD = [(int(task), text) for style in STYLES["validation34"].values() for task, text in style.items()]
# dev100's sentences still refused on purpose: a past-tense story tells what happened, never what to do;
# "Stand by" is a wait the frame does not know
STILL_REFUSED = {
    STYLES["dev100"]["story"]["1"],
    STYLES["dev100"]["story"]["6"],
    STYLES["dev100"]["stage_manager"]["5"],
}
PILLARS = "Move the three pillars to regions E, F and G beside arm a and arm b"
TOUCH = (
    "Move the three blocks to the opposite regions. No arm may touch the blue block until an arm has "
    "touched the red block. "
)

WRITTEN = [
    (1, STYLES["dev100"]["stage_manager"]["1"]),
    (2, STYLES["dev100"]["letter"]["2"]),
    (2, STYLES["dev100"]["legal"]["2"]),
    (2, STYLES["dev100"]["inverted_count"]["2"]),
    (3, "Safety first: " + PILLARS + ". No object may be placed anywhere other than the target regions."),
    (4, TOUCH + "Only after every other step is over, put the yellow block back on region G."),
    (2, "Put the three blocks on regions H, I and J. Regions H, I and J are each set to receive exactly one "
        "of the three blocks."),
    (3, PILLARS + ", not one of them put down anywhere except those three regions."),
    (4, TOUCH + "Once the rest is over, the yellow block comes back to region G."),
]

UNCLEAR = [
    # a sign-off's "name" that is a word the reader knows (a farewell no list holds, "Kisses, Sam", is general
    # filler since h235: test_general_frames_h235)
    (1, "Transfer the three blocks to the opposite side, the red block before the blue block. Love, Red"),
    # "places" is the regions inside a clause: never a stage call
    (1, "Put the blocks in their places. The red block before the blue block."),
    # a count after its noun that is not the scene's
    (2, "Blocks, two, to H, I and J, one per region."),
]

NEAR_MISSES = [
    # another region for "not a single pillar": a different prohibition
    (3, PILLARS + ". Not a single pillar may be put down on region E."),
    (4, TOUCH + "Only after every other step is over, put the yellow block back on region H."),
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_voice_frames_and_near_classes_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), UNCLEAR)
def test_unclear_neighbours_stay_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), NEAR_MISSES)
def test_near_misses_are_not_the_written_spec(task: int, text: str) -> None:
    assert_not_the_written_spec(task, text)


def test_none_of_them_is_no_object_only_before_a_placing_verb() -> None:
    assert normalise("None of them may be put on F") == "no object may be put on f"
    assert "none of them may hold" in normalise("None of them may hold two blocks")  # the regions: kept


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), [case for case in DEV if case[1] not in STILL_REFUSED])
def test_development_batch_gives_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), [case for case in DEV if case[1] in STILL_REFUSED])
def test_development_sentences_left_are_refused_by_name(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), HELD)
def test_held_out_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
