"""Issue 23, order words: which clause an order word is about. "A before B, but after C" restricts A;
"A and B, then C" puts C after both; "first A and B, then C" puts both first; "before all that" is before
every earlier task; "Do them in that order." orders the tasks stated before it. Each case was read with
an order other than the words' before (exit 0); near misses keep their reading."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

APPLE, EGG, TOMATO = "place Apple -> Fridge", "place Egg -> Fridge", "place Tomato -> SinkBasin"
SINK_EGG, FORK, BREAD = "place Egg -> SinkBasin", "place Fork -> Drawer", "place Bread -> CounterTop"
MUG, CUP, PLATE_TABLE = "place Mug -> SinkBasin", "place Cup -> SinkBasin", "place Plate -> DiningTable"


def chain(*tasks: str) -> set[tuple[str, str]]:
    """The closure of a sequence: every task before every later one."""
    return {(a, b) for k, a in enumerate(tasks) for b in tasks[k + 1 :]}


# ----- "A before B, but after C": both references are about A, the clause the sentence states ---------
@pytest.mark.parametrize(
    ("text", "order"),
    [
        (
            "put the apple in the fridge before you put the egg in the fridge, but after the tomato goes "
            "in the sink",
            chain(TOMATO, APPLE, EGG),
        ),
        (
            "put the apple in the fridge after the tomato goes in the sink but before you put the egg in the "
            "fridge",
            chain(TOMATO, APPLE, EGG),
        ),
        (
            "put the mug in the sink after you put the plate in the cabinet and before you put the bowl on "
            "the counter",
            chain("place Plate -> Cabinet", MUG, "place Bowl -> CounterTop"),
        ),
    ],
)
def test_a_second_reference_restricts_the_main_clause(text, order):
    _, got, unread = read(text)
    assert got == order and not unread


# ----- "A and B then C": C after B, the clause before "then" (h243, ANNOTATION_GUIDE.md) ----------------
@pytest.mark.parametrize(
    "text",
    [
        "put the apple in the fridge and put the egg in the sink and after that put the fork in a drawer",
        "put the apple in the fridge and put the egg in the sink then put the fork in a drawer",
    ],
)
def test_then_after_two_clauses_follows_the_last(text):
    _, order, unread = read(text)
    assert order == {(SINK_EGG, FORK)} and not unread


# ----- "A and B, then C" (a comma), "first ...", "... in any order": C after the whole step ----------------
@pytest.mark.parametrize(
    "text",
    [
        "put the apple in the fridge and put the egg in the sink, and once thats done put the fork in a "
        "drawer",
        "first put the apple in the fridge and put the egg in the sink, then put the fork in a drawer",
        "put the apple in the fridge and put the egg in the sink in any order, then put the fork in a drawer",
        "put the apple in the fridge. put the egg in the sink. do these in either order, then put the fork "
        "in a drawer",
    ],
)
def test_then_after_a_list_follows_all_of_it(text):
    _, order, unread = read(text)
    assert order == {(APPLE, FORK), (SINK_EGG, FORK)} and not unread


def test_then_before_a_list_precedes_all_of_it():
    """ "and" alone (no comma) may join one clause's two tasks: the guide leaves it open, both after."""
    _, order, unread = read(
        "put the apple in the fridge, then put the egg in the sink and put the fork in a drawer"
    )
    assert order == {(APPLE, SINK_EGG), (APPLE, FORK)} and not unread


def test_then_orders_its_own_clause_only():
    """ANNOTATION_GUIDE.md: "Then Y" -> [previous task, Y]; ", and drop the fork in a drawer too", a clause
    set apart by a comma and a verb of its own, has no order word (before h213: after the apple too)."""
    _, order, unread = read(
        "put the apple in the fridge, then put the egg in the sink, and drop the fork in a drawer too"
    )
    assert order == {(APPLE, SINK_EGG)} and not unread


def test_then_after_commas_follows_the_clause_before_it():
    """The guide's previous task is "the one stated in the immediately preceding clause": "A, B, then C" is
    [B, C], not the sequence A < B < C read before h213."""
    _, order, unread = read(
        "put the apple in the fridge, put the egg in the sink, then put the fork in a drawer"
    )
    assert order == {(SINK_EGG, FORK)} and not unread


def test_a_task_allowed_at_any_time_stays_out_of_the_step():
    """Near miss: "at any time" frees the apple from the "then"."""
    _, order, unread = read(
        "put the apple in the fridge at any time and put the egg in the sink, then put the fork in a drawer"
    )
    assert order == {(SINK_EGG, FORK)} and not unread


def test_finally_after_tasks_in_any_order_follows_the_guide():
    """Near miss: "finally" comes after no task whose order is left open (ANNOTATION_GUIDE.md), as when the
    sentence ends after "in any order"."""
    _, order, unread = read(
        "put the apple in the fridge and put the egg in the sink in any order, and finally put the fork in "
        "a drawer"
    )
    assert order == set() and not unread


def test_a_named_reference_inside_a_sentence_opens_the_next_clause():
    _, order, unread = read(
        "put the plate in the cabinet and the mug in the sink, and once the mug is done put the bread on the "
        "counter"
    )
    assert order == {(MUG, BREAD)} and not unread
    _, order, unread = read(
        "put the apple in the fridge, and after you put the egg in the sink put the bread on the counter"
    )
    assert order == {(SINK_EGG, BREAD)} and not unread


# ----- "before all that", "do them in that order", "the egg before the apple" ---------------------------
def test_before_all_that_is_before_every_earlier_task():
    _, order, unread = read(
        "put the cup in the sink, then the mug in the sink. Before all that, put the plate on the table"
    )
    assert order == chain(PLATE_TABLE, CUP, MUG) and not unread


def test_before_all_that_outranks_a_first():
    _, order, unread = read("First put the cup in the sink. Before all that, put the plate on the table.")
    assert order == chain(PLATE_TABLE, CUP) and not unread


@pytest.mark.parametrize(
    "text",
    [
        "put the apple in the fridge. put the egg in the sink. put the bread on the counter, then put the "
        "fork in a drawer. do them in that order.",
        "put the apple in the fridge, put the egg in the sink and put the bread on the counter, then put the "
        "fork in a drawer, in exactly that order",
    ],
)
def test_in_that_order_orders_every_task_named(text):
    _, order, unread = read(text)
    assert order == chain(APPLE, SINK_EGG, BREAD, FORK) and not unread


@pytest.mark.parametrize(
    "text",
    [
        "put the egg in the sink and put the apple in the fridge, the apple before the egg",
        "put the egg in the sink and put the apple in the fridge, but do the apple first",
        "put the egg in the sink and put the apple in the fridge, the egg last",
    ],
)
def test_a_closing_order_between_named_tasks(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([SINK_EGG, APPLE]) and order == {(APPLE, SINK_EGG)} and not unread


# ----- negated orders, leading compound references, "only then", "after those two" ---------------------
def test_do_not_put_before_is_after():
    _, order, unread = read("do not put the egg in the fridge before the apple is in the fridge")
    assert order == {(APPLE, EGG)} and not unread


def test_two_leading_references_are_both_about_the_clause():
    _, order, unread = read(
        "after you put the mug in the sink and before you put the egg in the fridge, put the apple in the "
        "fridge"
    )
    assert order == chain(MUG, APPLE, EGG) and not unread


@pytest.mark.parametrize(
    "text",
    [
        "put the apple in the fridge, then, after putting the egg in the sink, put the fork in a drawer",
        "put the apple in the fridge, and then after putting the egg in the sink put the fork in a drawer",
    ],
)
def test_then_before_a_reference_keeps_its_then(text):
    _, order, unread = read(text)
    assert order == {(APPLE, FORK), (SINK_EGG, FORK)} and not unread


@pytest.mark.parametrize(
    ("text", "order"),
    [
        ("put the apple in the fridge, and only then put the fork in a drawer", {(APPLE, FORK)}),
        (
            "put the apple in the fridge, then the egg in the sink, and after those two the fork in a "
            "drawer",
            chain(APPLE, SINK_EGG, FORK),
        ),
        (
            "put the apple in the fridge and put the egg in the sink, and once both are done put the fork "
            "in a drawer",
            {(APPLE, FORK), (SINK_EGG, FORK)},
        ),
        (
            "put the egg in the sink and put the apple in the fridge. Do the apple before the egg.",
            {(APPLE, SINK_EGG)},
        ),
    ],
)
def test_more_ways_to_say_then(text, order):
    _, got, unread = read(text)
    assert got == order and not unread


def test_an_order_word_left_inside_a_clause_is_unread():
    _, _, unread = read(
        "put the potato in the microwave last and the apple in the fridge first. put the egg in the sink"
    )
    assert any("'last'" in u for u in unread)
