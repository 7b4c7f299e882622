"""The semantic checks of LLM answers (issue 10.7): unit cases, and no false alarm on the recipes."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from nl2hltl2plan.language.semantic_check import (
    action_problems,
    cycle_problem,
    decomposition_problems,
    find_cycle,
)

DEMO_TYPES = {"Apple", "AppleSliced", "Plate", "Mug", "Cup", "Fork", "Knife", "SinkBasin", "Faucet", "Fridge",
              "Microwave", "DiningTable", "CounterTop", "Cabinet", "KeyChain", "FloorLamp", "Book"}


def test_plates_asked_mugs_moved_is_named():
    task = {"id": "1.2", "kind": "place", "object": ["Plate"], "receptacle": ["Cabinet"]}
    problems = action_problems(["pickup(Mug)", "put(Mug,Cabinet)"], task, DEMO_TYPES)
    assert "pickup(Mug): 1.2 is about Plate, not Mug" in problems
    assert "nothing picks up the Plate that 1.2 is about" in problems
    assert "1.2 must end with the Plate in/on Cabinet; it is never put down" in problems
    assert action_problems(["pickup(Plate)", "put(Plate,Cabinet)"], task, DEMO_TYPES) == []


APPLE_TO_FRIDGE = {"object": ["Apple"], "receptacle": ["Fridge"]}
FORK_IN_CUP = {"kind": "place_in_container", "object": ["Fork"], "container": ["Cup"],
               "receptacle": ["DiningTable"]}
STATUE = {"kind": "place", "object": ["Statue"], "receptacle": ["Fridge"]}


@pytest.mark.parametrize(
    "actions, task, fragment",
    [
        (["pickup(Apple)", "put(Apple,DiningTable)"], {"kind": "place", **APPLE_TO_FRIDGE},
         "it ends in/on DiningTable"),
        (["pickup(Apple)", "put(Apple,Fridge)"], {"kind": "clean_place", **APPLE_TO_FRIDGE},
         "must put the object into the SinkBasin"),
        (["pickup(Apple)", "put(Apple,SinkBasin)", "pickup(Apple)", "put(Apple,Fridge)"],
         {"kind": "clean_place", **APPLE_TO_FRIDGE}, "must switch on the Faucet"),
        (["pickup(KeyChain)"], {"kind": "examine_in_light", "object": ["KeyChain"], "light": ["FloorLamp"]},
         "must switch on FloorLamp"),
        (["pickup(Fork)", "put(Fork,DiningTable)"], FORK_IN_CUP, "must put the Fork into Cup"),
        (["pickup(Statue)", "put(Statue,Fridge)"], STATUE, "there is no Statue in the world"),
    ],
)
def test_action_problems(actions, task, fragment):
    assert any(fragment in p for p in action_problems(actions, task, DEMO_TYPES)), action_problems(
        actions, task, DEMO_TYPES
    )


def test_every_recipe_of_the_demo_world_passes():
    """No false alarm: the worlds' recipes (what a perfect answer looks like) for every task kind."""
    from nl2hltl2plan.worlds import load_world
    from nl2hltl2plan.worlds.tasks import BaseTask

    world = load_world("demo")
    types = set(world.object_types())
    cases = [
        dict(kind="clean_place", object=["Apple"], receptacle=["Fridge"]),
        dict(kind="heat_place", object=["Mug"], receptacle=["DiningTable"]),
        dict(kind="cool_place", object=["Tomato"], receptacle=["CounterTop"]),
        dict(kind="cool_place", object=["Tomato"], receptacle=["Fridge"]),
        dict(kind="place_in_container", object=["Fork"], container=["Cup"], receptacle=["DiningTable"]),
        dict(kind="examine_in_light", object=["KeyChain"], light=["FloorLamp"]),
        dict(kind="place", object=["Book"], receptacle=["DiningTable"]),
        dict(kind="place_two", object=["Mug"], count=2, receptacle=["CounterTop"]),
        dict(kind="heat_place", object=["Apple"], sliced=True, receptacle=["Plate"]),
        dict(kind="place", object=["Bread"], sliced=True, receptacle=["Plate"]),
        dict(kind="clean_place", object=["Plate"], receptacle=["Dishwasher"]),
    ]
    checked = 0
    for fields in cases:
        for spec in BaseTask(id="A", **fields).leaf_specs(world):
            assert isinstance(spec, list)
            assert action_problems(spec, {**fields, "id": "A"}, types) == [], (fields, spec)
            checked += 1
    assert checked == 12


@dataclass
class Words:
    kind: str
    object: str
    sliced: bool = False
    container: str | None = None
    receptacle: str | None = None
    light: str | None = None


def test_decomposition_must_cover_every_named_object():
    text = "Put the apple in the fridge, then put the mug on the table and slice the bread with a knife."
    tasks = [Words("place", "apple", receptacle="fridge")]
    problems = decomposition_problems(text, tasks)
    assert any("'mug'" in p for p in problems) and any("'bread'" in p for p in problems)
    assert not any("'table'" in p or "'fridge'" in p for p in problems)  # places, not things
    tasks += [Words("place", "Mug", receptacle="DiningTable"), Words("place", "bread", sliced=True,
                                                                      receptacle="CounterTop")]
    assert decomposition_problems(text, tasks) == []  # the knife is implied by slicing


def test_places_and_implied_appliances_are_not_required():
    text = "Wash the keys from the desk in the sink and examine them under the lamp on the dresser."
    tasks = [Words("examine_in_light", "keys", light="lamp")]
    assert decomposition_problems(text, tasks) == []


def test_cycles_are_named_in_full():
    assert find_cycle([("1.1", "1.2"), ("1.2", "1.3")]) is None
    assert find_cycle([("1.1", "1.2"), ("1.2", "1.3"), ("1.3", "1.1")]) == ["1.1", "1.2", "1.3", "1.1"]
    assert cycle_problem([("A", "B"), ("B", "A")], "the orderings") == (
        "the orderings form a cycle: A before B before A (each must come before itself)"
    )
