"""Check 1: a place-in-container reading needs a text that says the container holds the thing (issue 23;
`language/containers_said.py`)."""

from __future__ import annotations

import pytest
from household_readings import shared_world

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import translate


@pytest.fixture(scope="module")
def kitchen():
    return shared_world("FloorPlan9")


def _read(text: str, world) -> list[tuple[str, list[str], list[str], list[str]]] | None:
    try:
        r = translate(text, world, "offline", build=False, actions="none")
    except Nl2Hltl2PlanError:
        return None
    if r.partial:
        return None
    return [(t.kind, t.object, t.container or [], t.receptacle or []) for t in r.tasks]


@pytest.mark.parametrize(
    "text",
    [
        # the learned re-read once put the tomato in the pan and the pan in the fridge, the sink dropped
        "put the tomato in the fridge and the pan in the sink, blah first",
        "put the tomato in the fridge and the pan in the sink, foo first",
    ],
)
def test_a_container_the_text_never_says_holds_anything_is_refused(text, kitchen):
    assert _read(text, kitchen) is None


@pytest.mark.parametrize(
    "free",
    ["whichever first", "whatever first", "whichever one you like first", "either first", "either one first"],
)
def test_whichever_first_leaves_the_order_free(free, kitchen):
    text = f"put the tomato in the fridge and the pan in the sink, {free}"
    tasks = [("place", ["Tomato"], [], ["Fridge"]), ("place", ["Pan"], [], ["SinkBasin"])]
    assert _read(text, kitchen) == tasks
    assert translate(text, kitchen, "offline", build=False, actions="none").before == []


@pytest.mark.parametrize(
    "text",
    [
        "put the tomato in a pan and put the pan in the fridge",
        "put the pan with the tomato in the fridge",
        "take a pan, put the tomato in it, and put it in the fridge",
    ],
)
def test_a_container_said_to_hold_the_thing_is_read(text, kitchen):
    assert _read(text, kitchen) == [("place_in_container", ["Tomato"], ["Pan"], ["Fridge"])]


@pytest.mark.parametrize(
    "text",
    [
        # the container's own place first: the content once went into the pan and the fridge was dropped
        "put the pan in the fridge and the tomato in the pan",
        "put the tomato in the pan and the pan in the fridge",
        "put the pan and the tomato in the fridge",
    ],
)
def test_a_container_and_its_content_listed_in_one_clause_go_together(text, kitchen):
    assert _read(text, kitchen) == [("place_in_container", ["Tomato"], ["Pan"], ["Fridge"])]


def test_two_things_of_one_clause_with_places_of_their_own_are_two_tasks(kitchen):
    # never the one put in the other's place (the two were once merged, and check 1 refused the reading)
    assert _read("put the tomato in the bowl and the pan in the sink", kitchen) == [
        ("place", ["Tomato"], [], ["Bowl"]),
        ("place", ["Pan"], [], ["SinkBasin"]),
    ]
