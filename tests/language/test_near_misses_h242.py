"""h242 (issue 23): near misses of session 31's new rules, read through `translate` (`plan`'s language stage).

- "..., and take the mug out of the microwave" with no placing after: a removal, refused by name (h236's
  `taken_out` read the thing's first naming as where it comes from, and the clause as a placing into it);
- a treatment with no destination whose thing another task moves ("the cup and the pot both need chilling,
  and the cup goes on the table"; "Heat an egg and a tomato. The egg goes on the counter, the potato ..."):
  two goals for one thing, refused by name (`state_tasks.treated_apart`);
- a place said only after "from" ("..., and the mug from the microwave as well") is where the thing is, never
  its destination, though "microwave" is also a verb that names the microwave (check 1's invented slots).
"""

from __future__ import annotations

import pytest
from household_readings import outcome, refusal

from nl2hltl2plan.language.state_tasks import treated_apart
from nl2hltl2plan.language.task_specs import BaseTaskSpec


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, unread",
    [
        # main: place Mug -> Microwave at exit 0
        ("Chill the apple, put it on the counter, and take the mug out of the microwave.", "take the mug"),
        # main: place Cup -> DiningTable, cool_place Cup -> ?, cool_place Pot -> ? at exit 0
        ("The cup and the pot both need chilling, and the cup goes on the counter.", "treated in one task"),
        # main: four tasks, the egg heated and placed apart, at exit 0
        ("Heat an egg and a tomato. The egg goes on the counter, the potato in the fridge.", "treated in"),
    ],
)
def test_a_near_miss_of_the_new_rules_is_refused_by_name(kitchen, text, unread):
    assert unread in refusal(text, kitchen)


@pytest.mark.data
def test_a_thing_from_a_place_as_well_is_read_as_the_thing_without_a_source(kitchen):
    """ "..., and the mug from the microwave as well": the microwave is where the mug is, never its
    destination (main read place Mug -> Microwave at exit 0); since h238 the mug shares the task before, as
    "and the mug as well" does."""
    text = "Wash the cup and put it on the counter, and the mug from the microwave as well."
    assert outcome(text, kitchen) == outcome(text.replace(" from the microwave", ""), kitchen)
    assert outcome(text, kitchen) == ["clean_place Cup -> CounterTop", "clean_place Mug -> CounterTop"]


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        ("Take the mug out of the microwave and put it on the counter.", ["place Mug -> CounterTop"]),
        ("Take the egg out of the fridge, heat it, put it back in the fridge.", ["heat_place Egg -> Fridge"]),
        ("Microwave the mug and put it on the counter.", ["heat_place Mug -> CounterTop"]),
        ("Heat an egg.", ["heat_place Egg -> ?"]),
    ],
)
def test_the_rules_own_shapes_still_read(kitchen, text, tasks):
    assert outcome(text, kitchen) == tasks


def test_treated_apart_names_only_a_thing_both_treated_alone_and_moved():
    heat = BaseTaskSpec(id="A", text="heat the egg", kind="heat_place", object=["Egg"], receptacle=None)
    put = BaseTaskSpec(id="B", text="the egg goes on it", kind="place", object=["Egg"], receptacle=["Plate"])
    other = BaseTaskSpec(id="C", text="put the apple", kind="place", object=["Apple"], receptacle=["Plate"])
    assert [u.words for u in treated_apart([heat, put])] == ["heat the egg"]
    assert treated_apart([heat, other]) == []
