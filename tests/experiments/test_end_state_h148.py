"""Issue 24, h148 (session 24): an instruction said as the END STATE rather than as a command reads as the
goal it states, on both readers. Tabletop: an end-state opener with no comma before its wish ("By the end I
want X sitting on Y"), and spec-sheet goals that each name the one before ("Goal 2 (after goal 1): ...", the
order the words say). Handover: a posture as the end state's verb ("should sit on"), "no other region should
(ever) have been used", and an end state said once opening the message ("At the end, X should ...") where
every other goal is at any time or later still. The development sentences (`end_state_h148.DEV_*`) give the
written spec; the held-out ones (`HELD_*`) are read right or refused, never misread (`sweep`)."""

from __future__ import annotations

import pytest
from end_state_h148 import DEV_HANDOVER, DEV_TABLETOP, HELD_HANDOVER, HELD_TABLETOP
from handover_specs import (
    assert_not_the_written_spec,
    assert_refused_by_name,
    assert_written_spec,
    assert_written_spec_or_refused,
    cases,
)
from test_tabletop import TASKS, signature, signature_or_none

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.tabletop_steps import identifiers_chained_read


@pytest.mark.parametrize(("task", "text"), cases(DEV_TABLETOP))
def test_tabletop_end_states_give_the_tasks_and_order(task: int, text: str) -> None:
    assert signature(text) == signature(TASKS[task].instruction), text


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), cases(DEV_HANDOVER))
def test_handover_end_states_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


def test_spec_sheet_goals_are_steps_only_where_each_names_the_one_before() -> None:
    chained = "Goal 1: A on P. Goal 2 (after goal 1): B on Q. Goal 3, only after goal 2: C on R."
    assert identifiers_chained_read(chained) == "Step 1: A on P. Step 2: B on Q. Step 3: C on R."
    for loose in (
        "Goal 1: A on P. Goal 2: B on Q. Goal 3 (after goal 2): C on R.",  # goal 2 names none
        "Goal 1: A on P. Goal 2 (after goal 1): B on Q. Goal 3: C on R.",  # goal 3 names none
        "Goal 1: A on P. Goal 2 (after goal 2): B on Q.",  # not the one before
        "Goal 1: A on P. Requirement 2 (after goal 1): B on Q.",  # two nouns
    ):
        assert identifiers_chained_read(loose) == loose


def test_tabletop_unchained_goals_keep_no_order_of_their_own() -> None:
    text = ("Goal 1: the green apple on the yellow plate.\nGoal 2: the carrot on the blue plate.\n"
            "Goal 3 (after goal 2): the orange on the blue plate.")
    try:
        _, order = signature(text)
    except Nl2Hltl2PlanError:
        return  # refused: honest
    # never "green apple before carrot": goal 2 says no order to goal 1
    assert (("place", ("GreenApple",), ("YellowPlate",)), ("place", ("Carrot",), ("BluePlate",))) not in order


@pytest.mark.data
@pytest.mark.parametrize(
    ("task", "text"),
    [
        # a last step said before goals with no time of their own: which is last is not said
        (4, "At the end, the yellow block should be back on region G. Move the three blocks to the opposite "
            "regions, and the arms must not touch the blue block until the red block has been touched."),
        # "at the end" twice: both final, or one after the other?
        (4, "At the end, the yellow block should be back on region G; at the end, the three blocks should be "
            "in the opposite regions."),
        # the other goal has no time of its own
        (5, "At the end, the red and blue blocks should have exchanged positions, with red placed first, and "
            "the yellow block should go to the opposite side."),
        (3, "At the end, the three pillars should sit on regions E, F and G, beside arm a and arm b, and no "
            "other region except H should ever have been used."),
    ],
)
def test_unclear_end_states_are_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.data
def test_an_end_state_without_its_order_is_not_the_written_spec() -> None:
    # red placed first is not said: not task 5's spec
    assert_not_the_written_spec(5, "At the end, the red and blue blocks should have exchanged positions, and "
                                   "at any time the yellow block should go to the opposite side.")


@pytest.mark.sweep
@pytest.mark.data
def test_held_out_end_states_are_read_right_or_refused() -> None:
    for task, text in cases(HELD_TABLETOP):
        said = signature_or_none(text)
        assert said is None or said == signature(TASKS[task].instruction), text
    for task, text in cases(HELD_HANDOVER):
        assert_written_spec_or_refused(task, text)
