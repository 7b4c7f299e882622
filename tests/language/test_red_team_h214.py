"""The red team's leftovers of session 29 (issue 23, h214), each a class read right or refused by name:
a self-correction "..., not the egg, the apple" (read as a ban next to the egg's task: exit 1), a treatment
said not to be done ("without washing it", "no need to wash it": refused, now a ban), "put away X in P"
where P is a place things are left out (read as P, at exit 0; which one is meant no reading can tell) and
"but first" inside an elided-verb list (the list reader keeps the marker; the order is unclear)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

from nl2hltl2plan.errors import HTTError

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    from trust_sets import world_of

    return full_reading(text, world_of("FloorPlan28"))


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        ("Put the egg in the fridge, not the egg, the apple", ["place Apple -> Fridge"]),
        ("Put the egg in the fridge, not the fridge, the microwave", ["place Egg -> Microwave"]),
    ],
)
def test_not_this_that_takes_back_what_it_names(text, tasks):
    got, _, unread, forbids = read(text)
    assert (got, unread, forbids) == (tasks, [], [])


@pytest.mark.data
def test_not_this_that_naming_nothing_said_is_refused():
    with pytest.raises(HTTError, match="'not the mug, the apple' takes back no one thing"):
        read("Put the egg in the fridge, not the mug, the apple")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, ban",
    [
        ("Put the mug in the sink without washing it", "forbids clean(Mug)"),
        ("Put the apple in the fridge, no need to chill it.", "forbids cool(Apple)"),
    ],
)
def test_a_treatment_not_to_do_is_a_ban(text, ban):
    tasks, _, unread, forbids = read(text)
    assert unread == [] and len(tasks) == 1 and any(ban in f for f in forbids), (tasks, unread, forbids)


@pytest.mark.data
def test_a_treatment_not_to_do_after_that_treatment_stays_refused():
    # refused as a contradiction at the spec since h255 (was: the ban left unread by a special case)
    with pytest.raises(HTTError, match="'without washing it' forbids clean\\(Mug\\), which the task 'Wash"):
        read("Wash the mug and put it in the cabinet without washing it")


@pytest.mark.data
def test_put_away_at_a_place_things_are_left_out_is_named():
    _, _, unread, _ = read("put away the mug in the sink")
    assert any("put away the mug in the sink" in u for u in unread), unread
    tasks, _, unread, _ = read("Put away the mug in the cabinet.")
    assert (tasks, unread) == (["place Mug -> Cabinet"], [])


@pytest.mark.data
def test_but_first_inside_an_elided_verb_list_is_named():
    text = "Put the mug in the sink, but first the egg in the fridge, then the apple in the microwave"
    _, _, unread, _ = read(text)
    assert any("'first' (no step" in u for u in unread), unread
