"""Issue 28 (h254): an order remark that names one task by its thing and orders it against "the rest": "X can
wait until Y is done" (Y before X), "The rest can wait until Y is done" (Y first), "Save X for last: <its
clause>", "<clause> when you've done the rest", "<clause>; that one comes first", "- do those first", "Once
the table is sorted, Y", "Any time you like, Y" (Y free). Before h254 each left the order unread."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

APPLE = "place Apple -> Fridge"
CLEAN_MUG = "clean_place Mug -> SinkBasin"
BREAD = "place Bread -> CounterTop"
TASKS = "Put the apple in the fridge, rinse the mug and put it in the sink, and put the bread on the counter."


@pytest.mark.parametrize(
    ("text", "order"),
    [
        (f"{TASKS} The bread can wait until the apple is done.", {(APPLE, BREAD)}),
        (f"{TASKS} The rest can wait until the mug is done.", {(CLEAN_MUG, APPLE), (CLEAN_MUG, BREAD)}),
        (f"{TASKS} The bread can wait till you've done the apple.", {(APPLE, BREAD)}),
        (f"{TASKS} Leave the apple until the others are done.", {(CLEAN_MUG, APPLE), (BREAD, APPLE)}),
        (
            "Put the apple in the fridge and put the bread on the counter. Save the mug for last: rinse it "
            "and put it in the sink.",
            {(APPLE, CLEAN_MUG), (BREAD, CLEAN_MUG)},
        ),
        (
            "Put the apple in the fridge and put the bread on the counter. Rinse the mug and put it in the "
            "sink when you've done the rest.",
            {(APPLE, CLEAN_MUG), (BREAD, CLEAN_MUG)},
        ),
        (
            "Put the apple in the fridge and put the bread on the counter. Rinse the mug and put it in the "
            "sink; that one comes first.",
            {(CLEAN_MUG, APPLE), (CLEAN_MUG, BREAD)},
        ),
    ],
)
def test_a_remark_naming_one_task_against_the_rest(text, order):
    tasks, said, unread = read(text)
    assert sorted(tasks) == sorted([APPLE, CLEAN_MUG, BREAD]) and said == order and not unread


def test_once_a_place_is_sorted_and_any_time_you_like():
    """ "Once the counter is sorted, Y": the counter's task before Y ('sorted' is no action); "Any time you
    like, Z": Z free (before: 'you like' unread)."""
    text = (
        "Put the bread on the counter. Once the counter is sorted, put the apple in the fridge. Any time you "
        "like, rinse the mug and put it in the sink."
    )
    tasks, said, unread = read(text)
    assert tasks == [BREAD, APPLE, CLEAN_MUG] and said == {(BREAD, APPLE)} and not unread


def test_near_miss_that_one_after_a_sentence_of_two_tasks_is_unread_by_name():
    """ "that one" where the sentence before says two tasks names no one task: a refusal, never a guess."""
    tasks, said, unread = read(
        "Put the bread on the counter. Put the apple in the fridge and rinse the mug and put it in the sink; "
        "that one comes first."
    )
    assert unread and not said


def test_near_miss_can_wait_until_a_thing_no_task_has_is_unread():
    """ "The bread can wait until the knife is done" with no knife task: unread by name, no order."""
    tasks, said, unread = read(f"{TASKS} The bread can wait until the knife is done.")
    assert unread and not said


def test_near_miss_the_table_one_with_two_table_tasks_is_unread_by_name():
    """ "The table one goes first." where two tasks end on the table: one task is meant and two fit, so it
    is unread (before h254 both were put first, a guess); "The table ones" names both."""
    text = "Put the apple on the table, put the bread on the counter, and rinse the mug and put it on the "
    text += "table."
    _, said, unread = read(f"{text} The table one goes first.")
    assert unread and not said
    _, said, unread = read(f"{text} The table ones go first.")
    assert len(said) == 2 and not unread
