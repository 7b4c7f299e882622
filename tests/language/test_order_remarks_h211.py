"""The order said in a remark of its own, after or before the tasks (issue 28, h211): "Save the egg for
last.", "Mug first, egg last.", "The first two in any order, the apple last.", "The washing last.", "Start
with the mug; the rest in any order." are mapped to the tasks they name, by object, place or treatment; a
remark whose words fit two tasks is unread by name, and one that contradicts a "then" is refused. The dev
set's lines (users_h211dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from grammar_readings import sorted_reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar.order_remarks import order_remark, remarks_said_plainly

TYPES = {"Egg", "Mug", "Apple", "Fridge", "SinkBasin", "CounterTop", "Microwave", "Cup", "Knife"}
EGG, MUG, APPLE = "place Egg -> Fridge", "place Mug -> SinkBasin", "place Apple -> CounterTop"
BOTH = "Put the egg in the fridge and the mug in the sink."

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


@pytest.mark.parametrize(
    "text, order",
    [
        (f"{BOTH} Save the egg for last.", {(MUG, EGG)}),
        (f"{BOTH} The egg can wait till the end.", {(MUG, EGG)}),
        (f"{BOTH} Mug first, egg last.", {(MUG, EGG)}),
        (f"{BOTH} The fridge one first, please.", {(EGG, MUG)}),  # a task named by its place
        (
            "Put the egg in the fridge, the mug in the sink and the apple on the counter. The first two in "
            "any order, the apple last.",
            {(EGG, APPLE), (MUG, APPLE)},
        ),
        (
            "Put the egg in the fridge, the mug in the sink and the apple on the counter. Start with the "
            "apple; the rest in any order.",
            {(APPLE, EGG), (APPLE, MUG)},
        ),
        (
            "Put the egg in the fridge, the mug in the sink and the apple on the counter. Apple first; order "
            "doesn't matter for the rest.",
            {(APPLE, EGG), (APPLE, MUG)},
        ),
        # a closing "after everything else" is the last clause's (each clause took it: a cycle, exit 2)
        ("Put the egg in the fridge and put the mug in the sink after everything else.", {(EGG, MUG)}),
    ],
)
def test_a_remark_orders_the_tasks_it_names(text, order):
    tasks, said, unread = sorted_reading(text, TYPES)
    assert unread == [] and said == order, tasks


def test_a_task_named_by_its_treatment():
    text = "Wash the mug and put it in the sink, and heat the egg and put it in the fridge. The washing last."
    tasks, said, unread = sorted_reading(text, TYPES)
    assert unread == [] and said == {("heat_place Egg -> Fridge", "clean_place Mug -> SinkBasin")}, tasks


def test_words_that_fit_two_tasks_are_unread_never_a_guess():
    # the cup is carried with the knife in it in one task and chilled in the other: which is "the cup"?
    text = (
        "Put a knife in a cup and the cup in the sink, and chill a cup and put it in the fridge. "
        "Do the cup first."
    )
    _, said, unread = sorted_reading(text, TYPES)
    assert any("the cup first" in u and "not certain" in u for u in unread), (said, unread)


def test_a_remark_against_a_then_is_refused():
    with pytest.raises(HTTError, match="contradictory ordering"):
        sorted_reading("Put the egg in the fridge, then put the mug in the sink. Mug first.", TYPES)


def test_the_rest_with_nothing_said_first_stays_unread():
    _, said, unread = sorted_reading(f"{BOTH} The rest in any order.", TYPES)
    assert said == set() and unread, unread


def test_a_clause_is_no_remark():
    assert order_remark("Put the mug in the sink first") is None
    assert order_remark("Save the mug for last") == [("last", "the mug", "")]
    assert remarks_said_plainly("A. The potato can wait till the end.") == "A. The potato last."


@pytest.mark.sweep
@pytest.mark.data
def test_h211_dev_set():
    """No line of h211's dev set is read wrong, the lines to refuse are refused, and every feasible line
    converts."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("users_h211dev")]
    assert [gt.instruction for gt, what in rows if what == "wrong"] == []
    assert [gt.instruction for gt, what in rows if not gt.feasible and what == "converted"] == []
    assert all(what == "converted" for gt, what in rows if gt.feasible)
