"""Plain users' multi-task lines (h304, issue 28): a closing "when the rest is done" / "once everything else
is done" in the sentence that says the other tasks orders its own clause after them; such a clause said with
no comma before the verbless item it orders; "the other X" / "a second X" as a verbless list item after a
container chain. Floor plans' default worlds, through the public reading path."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.alfred.conversion import scenario_world

pytestmark = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def read(scene: str, text: str):
    world = scenario_world({"scene": scene, "source_trials": []})
    res = translate(text, world, "offline", build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks], sorted(res.before)


KEYS, REMOTES = "place KeyChain -> Ottoman", "place_two 2x RemoteControl -> Ottoman"
WATCH = "examine_in_light Watch under FloorLamp"


@pytest.mark.parametrize(
    "text",
    [
        # h304dev's voice: the clause the words close is the last; "the rest" is the clauses before it
        "keys on the ottoman, 2 remotes on the ottoman too, and look at the watch under the lamp when the "
        "rest is done",
        # was refused as a contradictory order (each clause after the others)
        "put the keys on the ottoman and 2 remotes on the ottoman, and look at the watch under the lamp once "
        "everything else is done",
    ],
)
def test_the_rest_said_in_its_own_sentence_is_the_clauses_before(text):
    tasks, before = read("FloorPlan203", text)
    assert tasks == [KEYS, REMOTES, WATCH]
    assert before == [("A", "C"), ("B", "C")]


def test_a_verbless_item_after_the_clause_with_no_comma_is_a_clause_of_its_own():
    text = "put the keys on the ottoman, and once everything else is done 2 remotes on the ottoman"
    assert read("FloorPlan203", text) == ([KEYS, REMOTES], [("A", "B")])


def test_the_rest_with_nothing_said_before_it_is_still_left_unread():
    world = scenario_world({"scene": "FloorPlan203", "source_trials": []})
    res = translate("look at the watch under the lamp when the rest is done", world, "offline", build=False)
    assert res.partial and "what it names is not certain" in res.unparsed[0]


@pytest.mark.parametrize("other", ["the other card", "a second card"])
def test_the_other_thing_is_a_list_item_after_a_container_chain(other):
    text = f"credit card on a plate and that plate on the shelf, {other} in a box on the armchair"
    tasks, before = read("FloorPlan214", text)
    assert tasks == [
        "place_in_container CreditCard in Plate -> Shelf",
        "place_in_container CreditCard in Box -> ArmChair",
    ]
    assert before == []


def test_a_thing_held_under_it_is_held_under_the_lamp_said_before():
    # users_h284's voice: "it" after the lamp's examination is that lamp, not a place the rules cannot read
    text = "hold the box under the desk lamp, and once you've done that, hold a CD under it as well"
    tasks, before = read("FloorPlan301", text)
    assert tasks == ["examine_in_light Box under DeskLamp", "examine_in_light CD under DeskLamp"]
    assert before == [("A", "B")]
