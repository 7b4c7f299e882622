"""h177's four classes of paper-style wording (issue 28, issue 23), read through `translate`: a lamp named
before a list of things to look at lights each of them; a closing or opening "whenever" / "at any time"
frees its own clause only; "it" moved on after a thing is put in a movable receptacle is ALFRED's
movable-container task; and the look-at-under-lamp phrasings "to get a good look at it" / "turn the lamp
on". The sentences are new (not paper_h176's or paper_h177held's lines); a few run by default, the rest
under `-m sweep`."""

from __future__ import annotations

import pytest
from household_readings import reading, shared_world

from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.world import World

pytestmark = pytest.mark.data

def world(name: str) -> World:
    return shared_world(name)


LAMP_BEFORE_A_LIST = [
    (
        "FloorPlan324",
        "Using the desk lamp, look at the CD, the pillow and the alarm clock in any order.",
        ["examine_in_light CD under DeskLamp", "examine_in_light Pillow under DeskLamp",
         "examine_in_light AlarmClock under DeskLamp"],
        [],
    ),
    (
        "FloorPlan324",
        "Put the pen in the mug and set the mug on the dresser. Then, by the light of the desk lamp, study "
        "the CD and the tennis racket one after the other.",
        ["place_in_container Pen in Mug -> Dresser", "examine_in_light CD under DeskLamp",
         "examine_in_light TennisRacket under DeskLamp"],
        [("A", "B"), ("B", "C")],
    ),
    (
        "FloorPlan211",
        "With the floor lamp switched on, inspect the statue and a remote.",
        ["examine_in_light Statue under FloorLamp", "examine_in_light RemoteControl under FloorLamp"],
        [],
    ),
    (
        "FloorPlan211",
        "Use the floor lamp to examine the statue and the remote.",
        ["examine_in_light Statue under FloorLamp", "examine_in_light RemoteControl under FloorLamp"],
        [],
    ),
]

FREED_CLAUSE = [
    (
        "FloorPlan420",
        "Put the candle on the side table. After that, hang the toilet paper on its holder, and throw the "
        "hand towel in the trash whenever you like.",
        ["place Candle -> SideTable", "place ToiletPaper -> ToiletPaperHanger",
         "place HandTowel -> GarbageCan"],
        [("A", "B")],
    ),
    (
        "FloorPlan420",
        "Put the candle on the side table. Then hang the toilet paper on its holder, and at any point throw "
        "the hand towel in the trash.",
        ["place Candle -> SideTable", "place ToiletPaper -> ToiletPaperHanger",
         "place HandTowel -> GarbageCan"],
        [("A", "B")],
    ),
    (
        # "Then" after a sentence whose last clause is freed comes after the clause before it
        "FloorPlan420",
        "Put the candle on the side table, and throw the hand towel in the trash whenever you like. Then "
        "hang the toilet paper on its holder.",
        ["place Candle -> SideTable", "place HandTowel -> GarbageCan",
         "place ToiletPaper -> ToiletPaperHanger"],
        [("A", "C")],
    ),
]

CARRIED_IN_HOLDER = [
    (
        "FloorPlan211",
        "Put the remote in a box and carry it over to the coffee table.",
        ["place_in_container RemoteControl in Box -> CoffeeTable"],
        [],
    ),
    (
        "FloorPlan305",
        "Drop a pencil into a bowl and move it from the desk to the dresser.",
        ["place_in_container Pencil in Bowl -> Dresser"],
        [],
    ),
]

LOOK_UNDER_LAMP = [
    ("FloorPlan211", "Pick up the statue and turn on the floor lamp to get a good look at it.",
     ["examine_in_light Statue under FloorLamp"], []),
    ("FloorPlan211", "Carry the statue over to the floor lamp and switch the lamp on.",
     ["examine_in_light Statue under FloorLamp"], []),
    ("FloorPlan211", "Hold the statue and switch the floor lamp on to see it better.",
     ["examine_in_light Statue under FloorLamp"], []),
]

ALL = LAMP_BEFORE_A_LIST + FREED_CLAUSE + CARRIED_IN_HOLDER + LOOK_UNDER_LAMP
DEFAULT = [LAMP_BEFORE_A_LIST[0], FREED_CLAUSE[0], CARRIED_IN_HOLDER[0], LOOK_UNDER_LAMP[1]]


@pytest.mark.parametrize("scene, text, tasks, before", DEFAULT)
def test_each_class_reads_its_tasks_and_order(scene, text, tasks, before):
    assert reading(text, world(scene)) == (tasks, before)


@pytest.mark.sweep
@pytest.mark.parametrize("scene, text, tasks, before", [c for c in ALL if c not in DEFAULT])
def test_each_class_reads_its_tasks_and_order_sweep(scene, text, tasks, before):
    assert reading(text, world(scene)) == (tasks, before)


def test_it_moved_back_still_asks_which():
    # "put it back": back where the remote was, or where the box was: two tasks, so "it" is named
    text = "Put the remote in a box, then put it back on the sofa."
    res = translate(text, world("FloorPlan211"), build=False)
    assert any("'it' may be the remote or the box" in u for u in res.unparsed)
