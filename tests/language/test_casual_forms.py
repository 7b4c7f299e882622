"""Casual forms of issue 28 (grammar/everyday.py): "there" for the last destination, a thing named first
with where it is, "ur", "nuke"; and check 1 never takes the place after "put it" for where a thing is."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.task_specs import BaseTaskSpec

KITCHEN = {"Bread", "Egg", "Mug", "Cup", "Apple", "Potato", "Knife", "Fridge", "CounterTop", "SinkBasin",
           "Microwave", "GarbageCan", "DiningTable"}  # fmt: skip
BREAD, EGG = "place Bread -> Fridge", "place Egg -> Fridge"


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str]]:
    r = parse_instruction(text, KITCHEN, "kitchen")
    return [t.summary() for t in r.tasks], r.before, r.unparsed


@pytest.mark.parametrize(
    "text, tasks, before",
    [
        # "there" / "in there": the last destination named before it
        ("put the bread in the fridge, then put the egg there too", [BREAD, EGG], [("A", "B")]),
        ("put the bread in the fridge. when ur done put the egg in there too", [BREAD, EGG], [("A", "B")]),
        ("put the bread in the fridge and put the egg in there too", [BREAD, EGG], []),
        ("walk to the sink and put the cup in there", ["place Cup -> SinkBasin"], []),
        ("put the bread in the fridge, then the egg in there too", [BREAD, EGG], [("A", "B")]),
        # a thing named first, with where it is, then what to do with "it"
        ("the mug thats on the counter, put it in the microwave", ["place Mug -> Microwave"], []),
        ("the apple that's in the fridge, throw it away", ["place Apple -> GarbageCan"], []),
        # "nuke" heats
        ("nuke the potato and then put it on the table", ["heat_place Potato -> DiningTable"], []),
        ("put a nuked potato on the table", ["heat_place Potato -> DiningTable"], []),
    ],
)
def test_casual_forms_are_read(text, tasks, before):
    assert read(text) == (tasks, before, [])


def test_there_after_a_thing_of_one_word_keeps_its_preposition_once():
    # "put an egg in there": the thing's name takes no preposition (it was "put an egg in in the fridge")
    assert everyday("put the bread in the fridge, then put an egg in there") == (
        "put the bread in the fridge, then put an egg in the fridge"
    )
    assert everyday("put the bread on the table and then the red apple on there") == (
        "put the bread on the table and then the red apple on the table"
    )


def test_there_with_nothing_before_it_or_after_a_negation_stays():
    assert everyday("put the egg there") == "put the egg there"
    negated = "put the bread on the counter but don't put the knife there"
    assert everyday(negated) == negated  # the constraint reader reads "there" itself
    assert everyday("when ur done put the mug in ur sink") == "when you're done put the mug in your sink"


def test_check_one_reads_the_place_after_put_it_as_a_destination():
    """ "the mug on the counter, put it in the microwave" read as "put the mug on the counter" leaves the
    microwave out: it is where the mug goes, not where something is."""
    on_counter = [BaseTaskSpec(id="A", kind="place", object=["Mug"], receptacle=["CounterTop"])]
    text = "the mug thats on the counter, put it in the microwave"
    assert [u.words for u in account(text, on_counter, [])] == ["microwave"]
