"""Issue 28 (h234): an order remark said in other words: tasks named by their treatment, their place, a
treatment verb, or as "the rest / everything else / both / all of them", with first / before / last /
can wait / whenever (`grammar/order_remarks.txt`, `remark_edges.py`). Before h234 each gave "the base tasks
are not ordered" or, for "The X whenever." / "The X can wait.", a second task for X."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

APPLE = "place Apple -> Fridge"
CLEAN_MUG = "clean_place Mug -> SinkBasin"
BREAD = "place Bread -> CounterTop"
TASKS = "Put the apple in the fridge, rinse the mug and put it in the sink, and put the bread on the counter."


@pytest.mark.parametrize(
    ("remark", "order"),
    [
        ("Rinse the mug before anything else.", {(CLEAN_MUG, APPLE), (CLEAN_MUG, BREAD)}),  # a treatment verb
        ("The counter one can wait until the rest is done.", {(APPLE, BREAD), (CLEAN_MUG, BREAD)}),  # a place
        ("Everything else before the apple.", {(CLEAN_MUG, APPLE), (BREAD, APPLE)}),
        ("The bread can wait.", {(APPLE, BREAD), (CLEAN_MUG, BREAD)}),  # before: a second bread task
        ("The bread whenever.", set()),  # before: a second bread task; the guide: "X whenever": no order
    ],
)
def test_an_order_remark_in_other_words(remark, order):
    tasks, said, unread = read(f"{TASKS} {remark}")
    assert sorted(tasks) == sorted([APPLE, CLEAN_MUG, BREAD]) and said == order and not unread


def test_a_task_after_both_said_with_when():
    """ "Y when both are finished" as "Y once both are done" (before: 'when' unread)."""
    tasks, said, unread = read(
        "Heat the egg and put it in the fridge, and rinse the mug and put it in the sink. Put the bread on "
        "the counter when both are finished."
    )
    egg = "heat_place Egg -> Fridge"
    assert said == {(egg, BREAD), (CLEAN_MUG, BREAD)} and not unread


def test_near_miss_a_treatment_no_task_has_is_no_order():
    """ "Heat the bread first." where the bread is only carried: the verb names no task, so it is unread (a
    refusal), never an order for the bread's task."""
    tasks, said, unread = read(f"{TASKS} Heat the bread first.")
    assert unread and not any(BREAD == b for _, b in said)


def test_throw_it_out_in_the_bin_at_the_end():
    """ "throw it out in the bin": "out" the particle, as "away" (before: no destination for the tomato)."""
    text = "Put the mug in the sink. Chill the tomato and throw it out in the bin at the end."
    tasks, said, unread = read(text)
    assert tasks == ["place Mug -> SinkBasin", "cool_place Tomato -> GarbageCan"] and not unread
    assert said == {("place Mug -> SinkBasin", "cool_place Tomato -> GarbageCan")}


def test_near_miss_a_thing_named_nowhere_before_whenever_is_the_task_before_for_it():
    """ "A, then B. The bread whenever.": no bread said before, so no remark: the task before, for it."""
    text = "Put the apple in the fridge, then rinse the mug and put it in the sink. The bread whenever."
    tasks, said, unread = read(text)
    assert tasks[:2] == [APPLE, CLEAN_MUG] and len(tasks) == 3 and "Bread" in tasks[2] and not unread
