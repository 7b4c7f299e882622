"""Issue 28 (h197): landmarks versus destinations (results/language/h197.md).

- A landmark on the thing says where it is now: after a thing a clause only treats or throws away ("wash
  the fork next to the coffee machine and ...", "throw away the apple next to the sink"), or picks up
  ("grab the mug by the sink."), after a posture ("the apple sitting next to the bread"), and on every
  item of a list that has one destination ("the mug by the sink and the bowl next to the stove in the
  cabinet").
- Of two fixed places with "on"/"in", a toilet, tub or TV stand first, or a part said of another piece of
  furniture second ("on the dining table in the middle drawer of the dresser"), the first says where the
  thing is and the second where it goes.
- Near misses stay refused, naming the words: a landmark as the only place ("put it next to the coffee
  machine"), one item of a list with a landmark and the other with the destination, a part of the first
  place ("on the desk in the drawer").
"""

from __future__ import annotations

import pytest
from household_readings import reading, refusal, shared_world

READ = [
    (
        "FloorPlan3",
        "Wash the fork next to the coffee machine and put it on the table.",
        ["clean_place Fork -> SideTable"],
    ),
    ("FloorPlan3", "Put the apple sitting next to the bread in the fridge.", ["place Apple -> Fridge"]),
    ("FloorPlan17", "Grab the mug by the sink. Put it in the microwave.", ["place Mug -> Microwave"]),
    (
        "FloorPlan3",
        "Put the mug by the sink and the bowl next to the stove in the cabinet.",
        ["place Mug -> Cabinet", "place Bowl -> Cabinet"],
    ),
    (
        "FloorPlan403",
        "Put the spray bottle on the toilet in the garbage can.",
        ["place SprayBottle -> GarbageCan"],
    ),
]
READ_SWEEP = [
    ("FloorPlan3", "Rinse the fork by the bread and put it on the table.", ["clean_place Fork -> SideTable"]),
    (
        "FloorPlan3",
        "Clean the fork on the counter and put it on the table.",
        ["clean_place Fork -> SideTable"],
    ),
    (
        "FloorPlan17",
        "Heat the tomato next to the bread and put it on the counter.",
        ["heat_place Tomato -> CounterTop"],
    ),
    (
        "FloorPlan17",
        "Chill the tomato by the sink and put it on the counter.",
        ["cool_place Tomato -> CounterTop"],
    ),
    ("FloorPlan3", "Put the apple lying by the sink in the fridge.", ["place Apple -> Fridge"]),
    ("FloorPlan3", "Put the apple located next to the bread in the fridge.", ["place Apple -> Fridge"]),
    (
        "FloorPlan3",
        "Put the mug by the sink, the bowl next to the stove and the cup beside the kettle in the cabinet.",
        ["place Mug -> Cabinet", "place Bowl -> Cabinet", "place Cup -> Cabinet"],
    ),
    ("FloorPlan403", "Put the soap bar in the tub on the counter.", ["place SoapBar -> CounterTop"]),
    (
        "FloorPlan17",
        "Heat up the potato on the table and put it in the fridge.",
        ["heat_place Potato -> Fridge"],
    ),
    ("FloorPlan17", "Throw the apple by the microwave away.", ["place Apple -> GarbageCan"]),
    ("FloorPlan17", "Put the apple close to the sink in the fridge.", ["place Apple -> Fridge"]),
    ("FloorPlan17", "Throw away the apple next to the sink.", ["place Apple -> GarbageCan"]),
    ("FloorPlan211", "Put the remote on the TV stand on the sofa.", ["place RemoteControl -> Sofa"]),
]
# each with the words its refusal names
REFUSED = [
    ("FloorPlan3", "Wash the fork and put it next to the coffee machine.", "coffee machine"),
    ("FloorPlan3", "Put the mug by the sink and the bowl in the cabinet.", "'sink'"),
    ("FloorPlan316", "Put the pen on the desk in the drawer.", "the desk / the drawer"),
]
REFUSED_SWEEP = [
    ("FloorPlan3", "Wash the fork, set it by the coffee machine.", "coffee machine"),
    ("FloorPlan3", "Put the mug by the sink, and put the bowl next to the stove in the cabinet.", "'sink'"),
    ("FloorPlan403", "Put the soap bar in the sink on the counter.", "the sink / the counter"),
    ("FloorPlan211", "Put the remote on the TV stand in the drawer.", "the tv stand / the drawer"),
]


@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, tasks", READ)
def test_a_landmark_of_the_thing_is_where_it_is(floor_plan: str, text: str, tasks: list[str]) -> None:
    assert reading(text, shared_world(floor_plan))[0] == tasks


@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, words", REFUSED)
def test_a_landmark_that_may_be_the_destination_is_refused(floor_plan: str, text: str, words: str) -> None:
    assert words in refusal(text, shared_world(floor_plan))


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, tasks", READ_SWEEP)
def test_more_landmarks_of_the_thing(floor_plan: str, text: str, tasks: list[str]) -> None:
    assert reading(text, shared_world(floor_plan))[0] == tasks


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, words", REFUSED_SWEEP)
def test_more_landmarks_that_may_be_the_destination(floor_plan: str, text: str, words: str) -> None:
    assert words in refusal(text, shared_world(floor_plan))
