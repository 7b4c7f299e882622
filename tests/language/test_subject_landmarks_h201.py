"""Issue 28 (h201): a place said in the subject is where the thing is (results/language/h201.md).

A noun phrase before "goes/belongs/should go/needs to go/is going/ends up" is the subject: every place
inside it says where the thing is now, and the place after the verb is where it goes. The same for a
wish's object before its participle ("I'd like X on L put in D"), and after "put away" the last of two
places is the destination. A landmark as the only place after the verb stays refused.
"""

from __future__ import annotations

import pytest
from household_readings import reading, shared_world

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import translate

READ = [
    ("FloorPlan1", "The mug in the sink goes in the microwave.", ["place Mug -> Microwave"]),
    ("FloorPlan229", "I'd like the keys on the coffee table put in the box.", ["place KeyChain -> Box"]),
    ("FloorPlan3", "Put away the mug on the counter in the cabinet.", ["place Mug -> Cabinet"]),
    ("FloorPlan1", "The apple next to the sink should go in the fridge.", ["place Apple -> Fridge"]),
]
READ_SWEEP = [
    ("FloorPlan229", "The keys on the coffee table go on the couch.", ["place KeyChain -> Sofa"]),
    ("FloorPlan3", "Make sure the apple on the table ends up in the fridge.", ["place Apple -> Fridge"]),
    (
        "FloorPlan3",
        "The bread on the counter is going in the fridge, then the mug in the sink goes in the microwave.",
        ["place Bread -> Fridge", "place Mug -> Microwave"],
    ),
    (
        "FloorPlan229",
        "Also, the book on the armchair in the corner belongs on the coffee table.",
        ["place Book -> CoffeeTable"],
    ),
    (
        "FloorPlan403",
        "The two spray bottles on the back of the toilet go in the garbage can.",
        ["place_two 2x SprayBottle -> GarbageCan"],
    ),
    (
        "FloorPlan229",
        "The car keys between the tissue boxes on the coffee table go on the grey couch.",
        ["place KeyChain -> Sofa"],
    ),
    ("FloorPlan3", "The apple goes in the fridge.", ["place Apple -> Fridge"]),
    (
        "FloorPlan3",
        "The cup with a fork in it goes on the table.",
        ["place_in_container Fork in Cup -> SideTable"],
    ),
]


@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, tasks", READ)
def test_a_place_in_the_subject_is_where_the_thing_is(floor_plan: str, text: str, tasks: list[str]) -> None:
    assert reading(text, shared_world(floor_plan))[0] == tasks


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, tasks", READ_SWEEP)
def test_more_places_in_subjects(floor_plan: str, text: str, tasks: list[str]) -> None:
    assert reading(text, shared_world(floor_plan))[0] == tasks


@pytest.mark.data
def test_a_landmark_after_the_verb_is_no_destination() -> None:
    """ "goes next to the stove" says no place to put it: refused, as "put it next to the stove" is."""
    with pytest.raises(Nl2Hltl2PlanError, match="next to the stove"):
        translate("The apple by the sink goes next to the stove.", shared_world("FloorPlan1"), build=False)
