"""Issue 23 (h266): paper_h249's readings that were wrong at exit 0, by class. Each class is read right or
refused by name, never read as another instruction."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.numbered_steps import step_order
from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"


@pytest.mark.parametrize(
    "text",
    [
        "Checklist (any order): 1) put the mug in the sink 2) put the apple in the fridge",
        "To-do, in any order: 1. put the mug in the sink 2. put the apple in the fridge",
    ],
)
def test_a_heading_that_frees_numbered_steps_leaves_them_unordered(text):
    """Before: the steps' numbers ordered the mug before the apple at exit 0."""
    tasks, order, unread = read(step_order(text))
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == set() and not unread


def test_a_heading_without_a_free_order_keeps_the_numbered_turn():
    tasks, order, _ = read(step_order("Checklist: 1) put the mug in the sink 2) put the apple in the fridge"))
    assert order == {(MUG, APPLE)}


@pytest.mark.parametrize(
    "text",
    [
        "hey! 3 things: 1) put the mug in the sink 2) put the apple in the fridge 3) put the egg in the "
        "microwave. do 1 n 2 first, 3 after",
        # ("Do 2 and 3 before 1." is read since h292: test_label_orders.py)
        "1. put the mug in the sink 2. put the apple in the fridge 3. put the egg in the microwave. "
        "Do 2 n 3 before 1, 4 after.",
    ],
)
def test_an_order_between_groups_of_numbered_steps_is_refused_by_name(text):
    """Before: "do 1 n 2 first, 3 n 4 after" was read as the numbered turn, 1 < 2 < 3 < 4, at exit 0."""
    with pytest.raises(HTTError, match="say the steps' order"):
        step_order(text)


@pytest.mark.parametrize(
    "text",
    [
        "Chore chart. Zoe: put the mug in the sink. Finn: put the apple in the fridge. Zoe does hers first.",
        "Chore chart, Sun. Ava: put the mug in the sink. Sam: put the apple in the fridge. Sam goes first.",
    ],
)
def test_an_order_said_by_a_chore_charts_person_is_refused_by_name(text):
    """Before: the labels were read in turn and "Zoe does hers first" as nothing (1 < 2 < 3 at exit 0)."""
    with pytest.raises(HTTError, match="by who does them"):
        step_order(text)


def test_a_first_said_of_a_thing_not_a_label_is_no_person_order():
    text = "Zoe: put the mug in the sink. Finn: put the apple in the fridge. The apple goes first."
    assert step_order(text) == text
