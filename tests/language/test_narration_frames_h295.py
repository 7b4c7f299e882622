"""Narration and the frames that carry across voices (issue 28, h295): a story's past tense or a caster's
present about the robot is read as the commands it tells of (`household_narration.narrated`); a bare closing
"sorry", a channel's patter, a record's credit and an ordinal date are frame; a diary's "I took" and a
request to the robot ("could the robot put ...") are no narration; "pillows x2" is never one pillow. The dev
set's lines (paper_h295dev.txt) are measured by `scripts/trust_sets.py measure --sets paper_h295dev`."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.household_narration import narrated
from tests.language.test_household_frames_h244 import EGG, MUG, read

BOTH = ([EGG, MUG], [("A", "B")], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        # a story's past tense, a verb no command form shares ("carried", "tucked")
        "Once upon a time, a little robot carried the egg to the fridge, and then it tucked the mug in the"
        " sink.",
        # a commentator's present, "it" after the robot
        "The robot takes the egg to the fridge - lovely! Then it puts the mug in the sink.",
        # what the robot is about to do, after a show's opening
        "In today's video our robot is going to put the egg in the fridge, then put the mug in the sink.",
    ],
)
def test_narration_of_the_robot_is_read_as_its_commands(text: str) -> None:
    assert read(text)[:3] == BOTH


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "Kids are asleep, sorry! Put the egg in the fridge, then put the mug in the sink.",
        "Put the egg in the fridge, then put the mug in the sink. Smash that like button! Checked by: Dave.",
        "Night of the 14th: put the egg in the fridge, then put the mug in the sink.",
    ],
)
def test_an_apology_patter_a_credit_and_a_date_are_frame(text: str) -> None:
    assert read(text)[:3] == BOTH


def test_a_request_to_the_robot_or_a_diary_is_no_narration() -> None:
    asked = "Could the robot put the egg in the fridge?"
    assert narrated(asked) == asked
    diary = "Yesterday I took the egg to the fridge."
    assert narrated(diary) == diary


@pytest.mark.data
def test_a_multiplier_is_a_count_never_one_thing() -> None:
    """"eggs x2 - place in the fridge" is two eggs (h294's `counts_before`), or, where a reading took one,
    check 1 names the count (h295's `multipliers_unread`): never one egg at exit 0."""
    try:
        tasks, _, unparsed, _ = read("eggs x2 - place in the fridge.")
    except Nl2Hltl2PlanError as refused:
        assert "x2" in str(refused)
        return
    assert tasks == ["place_two 2x Egg -> Fridge"] or any("x2" in u for u in unparsed), (tasks, unparsed)


@pytest.mark.data
def test_a_sorry_after_a_request_stays_a_correction_with_nothing_after_it() -> None:
    with pytest.raises(Nl2Hltl2PlanError, match="sorry"):
        read("Put the egg in the fridge, sorry")
