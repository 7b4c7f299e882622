"""h196 (issue 28 item 5, the paper's 5-9 base-task instructions, dev half of `bench_multiagent_long.py
--half dev`): a thing's next step said as a particle or a subordinate clause, a list's "at any time", a
treatment said as a purpose, and a side that says which drawer.

- "cook the potato and throw it out": one task, heat_place Potato -> GarbageCan ("out" is the particle of
  "throw out" as "away" is; it was a heat task with no place plus a second task on the same potato).
- "wash an egg before throwing it away" / "before you put it in the fridge": the egg's next step (the place
  was lost: silently for "away", refused for a named place).
- "put salt and pepper in the cabinet at any time": both are free (neither was: both came before
  "finally"). "in any order" after a list still frees the order inside it only.
- "slice an apple to be cooked in the microwave ...", "put a mug in the sink to be washed": a treatment said
  as a purpose, right after the thing or after its own appliance (the treatment was dropped).
- "move the soap bottle to the lid of the toilet": the toilet, as "the back of the toilet" is ('lid' was
  unread after "to"; the lexicon names the part).
- "inside the top drawer on the right side of the counter": the side says which drawer (was refused as two
  places); a side after a whole thing ("on the counter on the left side of the desk") stays refused.
"""

from __future__ import annotations

import pytest
from household_readings import shared_world

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import translate

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def _read(text: str, world: str = "FloorPlan12") -> tuple[list[tuple[object, ...]], bool]:
    res = translate(text, shared_world(world), "offline", build=False, actions="none")
    tasks = [(t.kind, t.object[0], (t.receptacle or [None])[0]) for t in res.tasks]
    return tasks, res.partial


@needs_data
@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("Cook the potato and throw it out.", ("heat_place", "Potato", "GarbageCan")),
        ("Wash an egg before throwing it away.", ("clean_place", "Egg", "GarbageCan")),
        ("Wash an egg before you put it in the fridge.", ("clean_place", "Egg", "Fridge")),
        ("Put a salt shaker inside the top drawer on the right side of the counter.",
         ("place", "SaltShaker", "Drawer")),
    ],
)  # fmt: skip
def test_the_things_next_step_and_the_drawer_a_side_names(text, task):
    assert _read(text) == ([task], False)


@needs_data
def test_the_lid_of_the_toilet_is_the_toilet():
    assert _read("Move the soap bottle to the lid of the toilet.", "FloorPlan425") == (
        [("place", "SoapBottle", "Toilet")],
        False,
    )


@needs_data
def test_take_it_out_of_a_place_is_still_a_source():
    """Near miss: "out of the fridge" says where the apple is; the trailing "out" is the particle."""
    assert _read("Take the apple out of the fridge and throw it out.") == (
        [("place", "Apple", "GarbageCan")],
        False,
    )


@needs_data
def test_before_treating_it_and_a_side_of_a_whole_thing_stay_unread():
    """Near misses: "before heating it" is no placing (the treatment's order is refused as before), and a
    side after a whole place may be where on it (two places: refused)."""
    _, partial = _read("Put the apple in the fridge before heating it.")
    assert partial
    with pytest.raises(Nl2Hltl2PlanError, match="two places it could go"):
        _read("Put the apple on the counter on the left side of the desk.")


@needs_data
@pytest.mark.parametrize(
    ("text", "before"),
    [
        # a list's closing "at any time" frees every thing of the list (both were ordered before D)
        ("Put salt and pepper in the kitchen cabinet at any time. Put a bowl on the counter. Finally, put a "
         "tomato in the sink.", {("C", "D")}),
        # near miss: "in any order" frees the order inside the list, as before
        ("Put salt and pepper in the kitchen cabinet in any order. Put a bowl on the counter. Finally, put a "
         "tomato in the sink.", {("A", "D"), ("B", "D"), ("C", "D")}),
    ],
)  # fmt: skip
def test_a_lists_closing_any_time_frees_each_thing(text, before):
    res = translate(text, shared_world("FloorPlan17"), "offline", build=False, actions="none")
    assert not res.partial and set(res.before) == before


@needs_data
@pytest.mark.parametrize(
    ("text", "task", "partial"),
    [
        # a purpose right after the thing: the heating was dropped (silently where another task heats)
        ("Slice an apple to be cooked in the microwave to be placed into the fridge.",
         ("heat_place", "Apple", "Fridge"), False),
        ("Put a mug in the sink to be washed.", ("clean_place", "Mug", "SinkBasin"), False),
        # near miss: after another place, which comes first is not said (refused as before)
        ("Put a mug in the cabinet to be heated.", ("place", "Mug", "Cabinet"), True),
    ],
)  # fmt: skip
def test_a_treatment_said_as_a_purpose(text, task, partial):
    assert _read(text, "FloorPlan26") == ([task], partial)
