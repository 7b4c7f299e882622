"""h217 (issue 28 item 5, the paper's 5-9 base-task instructions): the shapes long instructions chain, each
tested on lines of our own (never a line of the dataset).

- "put each of them / each one in X" after a list: every thing of the list goes to X (a task was left with
  no place, or kept the list's appliance as its place);
- "wash X and Y in the sink and put them on the counter": the list is still in its treatment's appliance,
  so "them" is the list (X kept the sink as its place);
- "after putting those away" names the list said just before (three things or more were refused);
- "an empty and one full toilet paper": two of one thing whose noun is said once ("an empty" was a thing of
  its own with no object), and "and one" there is one of the pair, not a count of one.
"""

from __future__ import annotations

import pytest
from household_readings import shared_world

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.language.translate import translate

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def _read(text: str, world: str) -> tuple[list[tuple[object, ...]], set[tuple[str, str]], bool]:
    res = translate(text, shared_world(world), "offline", build=False, actions="none")
    tasks = [(t.kind, t.object[0], (t.receptacle or [None])[0], t.count) for t in res.tasks]
    return tasks, {(a, b) for a, b in res.before}, res.partial


@needs_data
@pytest.mark.parametrize(
    "text",
    [
        "Rinse a bowl and a plate and put each of them in the cabinet.",
        "Rinse a bowl and a plate in the sink and put them in the cabinet.",
    ],
)
def test_each_thing_of_a_treated_list_goes_to_the_place_said_for_them(text):
    tasks, _, partial = _read(text, "FloorPlan1")
    assert (sorted(tasks), partial) == (
        [("clean_place", "Bowl", "Cabinet", 1), ("clean_place", "Plate", "Cabinet", 1)],
        False,
    )


@needs_data
def test_a_list_put_in_an_appliance_is_not_a_treatment_left_open():
    # "put" says where the things go: the microwave is the first place, not a treatment, so "then put them
    # on the counter" stays unread (refused), never a silent reading
    text = "Put a tomato and an egg in the microwave and then put them on the counter."
    assert _read(text, "FloorPlan1")[2]


@needs_data
def test_putting_those_away_names_the_list_said_just_before():
    text = (
        "Put a ladle, a spatula and a fork in a drawer. After putting those away, wash a pan and put it "
        "on the stove."
    )
    tasks, before, partial = _read(text, "FloorPlan8")
    assert [t[:3] for t in tasks] == [
        ("place", "Ladle", "Drawer"),
        ("place", "Spatula", "Drawer"),
        ("place", "Fork", "Drawer"),
        ("clean_place", "Pan", "StoveBurner"),
    ]
    assert (before, partial) == ({("A", "D"), ("B", "D"), ("C", "D")}, False)


@needs_data
def test_two_of_one_thing_whose_noun_is_said_once():
    assert _read("Put an empty and one full toilet paper on the toilet.", "FloorPlan401") == (
        [("place_two", "ToiletPaper", "Toilet", 2)],
        set(),
        False,
    )
    # a treatment word before the left-out noun is not read as a pair of one thing
    assert _read("Put a clean and a dirty cloth in the bathtub.", "FloorPlan401")[2]
