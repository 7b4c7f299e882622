"""Issue 28 (h276): two things of one type, or two slices of one thing, told apart as "one" and "the other"
after the pair is named ("Take two mugs:", "There are two tomatoes:", "Slice an apple."). Before, these were
refused, read as a count of two for one task, or the second slice lost its slicing, at exit 0."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.grammar.one_and_other import one_and_the_other
from tests.language.test_unseen_classes import read

MUG_SINK, MUG_FRIDGE = "place Mug -> SinkBasin", "place Mug -> Fridge"


@pytest.mark.parametrize(
    "text",
    [
        "Take two mugs: put one in the sink and the other in the fridge.",
        "Grab two mugs. Put one of them in the sink and the other one in the fridge.",
        "Two mugs: one goes in the sink, the other in the fridge.",
    ],
)
def test_a_pair_named_first_is_two_tasks_on_its_type(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG_SINK, MUG_FRIDGE]) and order == set() and not unread


def test_the_pairs_count_is_not_one_tasks_count():
    """Before: "heat_place 2x Tomato -> Fridge" at exit 0 (the "two" read as the first task's count)."""
    tasks, _, unread = read(
        "There are two tomatoes: microwave one and put it in the fridge, and chill the other one and put it "
        "on the counter."
    )
    assert sorted(tasks) == ["cool_place Tomato -> CounterTop", "heat_place Tomato -> Fridge"] and not unread


def test_the_other_slice_is_a_slice_too():
    """Before: "the other one" after "one of the slices" was a whole tomato at exit 0."""
    tasks, order, unread = read(
        "Slice a tomato, chill one of the slices and put it in the sink, and put the other one in the fridge."
    )
    assert sorted(tasks) == ["cool_place Tomato(sliced) -> SinkBasin", "place Tomato(sliced) -> Fridge"]
    assert order == set() and not unread


def test_one_thing_and_the_other_in_a_sentence_are_two_things():
    """Before: "the other" took no apple, and the first task's place was unread (refused)."""
    text = "Warm one apple and put it in the sink, and warm the other and keep it in the fridge."
    tasks, _, unread = read(text)
    assert sorted(tasks) == ["heat_place Apple -> Fridge", "heat_place Apple -> SinkBasin"] and not unread


def test_a_treatment_said_of_the_pair_is_said_of_each():
    text = "Warm up two tomatoes. Throw one of them in the bin and put the other one in the sink."
    tasks, _, unread = read(text)
    assert sorted(tasks) == ["heat_place Tomato -> GarbageCan", "heat_place Tomato -> SinkBasin"]
    assert not unread


@pytest.mark.parametrize(
    "text",
    [
        # passive: "one slice gets chilled" names no place for the rule to give it
        "Cut the tomato up. One slice goes in the sink; the other slice gets heated and thrown in the bin.",
        # "the other" before any "one"
        "Take two mugs: put the other in the fridge.",
        # two "one"s: which is which is not certain
        "Take two mugs: put one in the sink, one in the cabinet and the other in the fridge.",
    ],
)
def test_what_is_not_one_and_the_other_stays_as_written(text):
    assert one_and_the_other(text) == text


@pytest.mark.parametrize(
    "text, task",
    [
        ("Chill a round of tomato and put it in the sink.", "cool_place Tomato(sliced) -> SinkBasin"),
        ("Heat a potato slab and put it in the fridge.", "heat_place Potato(sliced) -> Fridge"),
        ("Chill the heel of the loaf and put it in the microwave.", "cool_place Bread(sliced) -> Microwave"),
    ],
)
def test_a_piece_said_without_slice_is_a_slice(text, task):
    """Before: the whole tomato, potato or loaf, at exit 0 (h276)."""
    tasks, _, unread = read(text)
    assert tasks == [task] and not unread


def test_a_part_that_may_be_no_slice_is_refused_by_name():
    _, _, unread = read("Put a leaf of lettuce in the fridge.")
    assert any("a leaf of lettuce" in u for u in unread)


def test_round_as_a_shape_is_no_piece():
    tasks, _, unread = read("Put the round tomato in the fridge.")
    assert tasks == ["place Tomato -> Fridge"] and not unread
