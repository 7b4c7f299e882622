"""Issue 28: what an order connective between tasks covers (`order_scope.txt`): "before that" / "but first"
comes before the last step said (every clause of it), the clauses of a "before that" sentence joined by
"and" are all before it and in any order, a clause added to it by "also" / "plus" is refused by name (is it
before too?), and "The last thing:" opens the last step."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.grammar import parse_instruction as grammar_parse
from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"
BREAD = "place Bread -> CounterTop"


@pytest.mark.parametrize("join", ["; also", ", and also", " and"])
def test_first_in_a_sentence_comes_before_each_of_its_clauses(join):
    tasks, order, unread = read(
        f"Put the mug in the sink{join} put the apple in the fridge, though first put the egg in the "
        "microwave."
    )
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(EGG, MUG), (EGG, APPLE)}


def test_before_that_comes_before_the_step_said_not_only_its_last_clause():
    tasks, order, unread = read(
        "Put the mug in the sink; also put the apple in the fridge. Before that, put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and order == {(EGG, MUG), (EGG, APPLE)} and not unread


def test_before_that_after_then_goes_in_between():
    """ "W, then X. Before that, Y": Y before X only, after W (span_order's PRE)."""
    tasks, order, unread = read(
        "Put the mug in the sink, then put the apple in the fridge. Before that, put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and order == {(MUG, APPLE), (MUG, EGG), (EGG, APPLE)} and not unread


@pytest.mark.parametrize("ending", ["", " in any order"])
def test_clauses_of_a_before_that_sentence_are_all_before_it_in_any_order(ending):
    tasks, order, unread = read(
        "Put the mug in the sink. Then put the apple in the fridge, but before that put the egg in the "
        f"microwave and put the bread on the counter{ending}."
    )
    assert len(tasks) == 4 and not unread
    assert order == {(MUG, APPLE), (MUG, EGG), (MUG, BREAD), (EGG, APPLE), (BREAD, APPLE)}


def test_then_inside_a_before_that_sentence_still_orders_its_clauses():
    tasks, order, unread = read(
        "Put the mug in the sink. Before that, put the egg in the microwave, then put the bread on the "
        "counter."
    )
    assert len(tasks) == 3 and not unread
    assert order == {(EGG, BREAD), (EGG, MUG), (BREAD, MUG)}


@pytest.mark.parametrize("added", ["; also put", ", plus put", ", and also put"])
def test_the_grammar_refuses_a_task_added_to_a_before_that_clause_by_name(added):
    """The grammar's own reading (the structure model may still read such a text, `structured.decide`)."""
    p = grammar_parse(
        f"Put the mug in the sink. Ahead of that, put the egg in the microwave{added} the bread on the "
        "counter."
    )
    said = "the bread on the counter' ("
    assert [u for u in p.unparsed if said in u and "after a 'before that' clause" in u]


@pytest.mark.parametrize("lead", ["make sure you first", "be sure to first", "remember to first"])
def test_but_make_sure_you_first_is_but_first(lead):
    tasks, order, unread = read(f"Put the mug in the sink, but {lead} put the egg in the microwave.")
    assert sorted(tasks) == sorted([MUG, EGG]) and order == {(EGG, MUG)} and not unread


@pytest.mark.parametrize("lead", ["The last thing:", "the final step:", "The very last task,"])
def test_the_last_thing_opens_the_last_step(lead):
    tasks, order, unread = read(
        f"Put the mug in the sink. Whenever you like, put the apple in the fridge. {lead} put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and order == {(MUG, EGG)} and not unread


def test_the_last_thing_as_a_subject_is_no_connective():
    _, order, _ = read("Put the mug in the sink. The last thing I need is the egg in the microwave.")
    assert (MUG, EGG) not in order


@pytest.mark.parametrize("then", ["Then", "After it's finished,"])
def test_then_after_a_list_in_any_order_comes_after_the_whole_list(then):
    tasks, order, unread = read(
        f"Put the mug in the sink, and put the apple in the fridge, in any order. {then} put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and order == {(MUG, EGG), (APPLE, EGG)} and not unread


def test_then_after_a_task_at_any_time_comes_after_the_other_task_only():
    tasks, order, unread = read(
        "Put the mug in the sink at any time and put the apple in the fridge. Then put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and order == {(APPLE, EGG)} and not unread


def test_but_first_in_a_sentence_whose_place_says_next_to():
    """ "next to the stove" is a place, not the later word "next" (which leaves "but first" unread)."""
    p = grammar_parse(
        "Put the mug in the sink, and put the apple in the fridge, though first put the egg in the microwave "
        "next to the stove."
    )
    assert len(p.tasks) == 3 and not p.unparsed and sorted(p.before) == [("C", "A"), ("C", "B")]
