"""h309 (issues 23/28): the classes of users_h300's wrong lines and of its "lamp on, look at X" notes, on my
own sentences (styles/probes_h309dev.txt; the held-out half is probes_h309held.txt). Before, each of the
first four was read at exit 0 with an order lost, a task moved or two placings for one container chain;
the lamp notes were refused."""

from __future__ import annotations

import pytest
from household_readings import refusal, shared_world

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.language.grammar.lamp_phrases import lamp_phrasing
from nl2hltl2plan.language.grammar.one_and_other import one_and_the_other
from nl2hltl2plan.language.headings import heading_dropped
from nl2hltl2plan.language.translate import translate

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def test_a_wished_pair_in_a_state_is_each_treated():
    """ "i also need two clean X, put one ... the other one ...": before, 2 cleaned cloths on the counter
    and a third, uncleaned, in the cabinet."""
    said = one_and_the_other(
        "i also need two clean bars of soap, put one on the counter and the other one in the cabinet"
    )
    assert said == (
        "also wash a bar of soap and put it on the counter and wash another bar of soap and put it in the "
        "cabinet"
    )


def test_counted_things_joined_by_and_are_no_heading():
    """ "armchair: 2 remotes + 1 pen.": before, dropped as a heading ("cards" taken for a document)."""
    dropped: list[str] = []
    said = heading_dropped("armchair: 2 newspapers and 2 cards. sofa: the box", dropped)
    assert said.startswith("armchair")
    assert dropped == []


@pytest.mark.parametrize(
    ("said", "written"),
    [
        ("lamp on, look at the cd", "turn on the lamp and look at the cd"),
        ("after that, lamp on and check the pen", "after that, turn on the lamp and check the pen"),
        ("then with the floor lamp on look at my keys, my phone and a card",
         "then look at my keys, my phone and a card under the floor lamp"),
        ("Then with floor lamp, look the pen and also the cd, any order.",
         "Then look at the pen and also the cd under the floor lamp, any order."),
    ],
)
def test_lamp_notes_are_written_as_examinations(said, written):
    assert lamp_phrasing(said) == written


@needs_data
def test_a_second_treatment_of_a_done_thing_is_another_thing():
    """Before: "rinse the pink soap and drop it in the tub" moved the first soap there (3 tasks)."""
    res = translate(
        "rinse a cloth and a soap bar and put them on the cart, then rinse another soap bar and drop it in "
        "the tub",
        shared_world("FloorPlan401"),
        build=False,
        actions="none",
    )
    assert not res.partial
    assert [t.summary() for t in res.tasks] == [
        "clean_place Cloth -> Cart", "clean_place SoapBar -> Cart", "clean_place SoapBar -> BathtubBasin"
    ]
    assert sorted(res.before) == [("A", "C"), ("B", "C")]


@needs_data
@pytest.mark.parametrize(
    ("plan", "text"),
    [
        # a bare noun names the container said before: one task, never two placings (refused by name)
        ("FloorPlan1", "Please: knife in mug and mug on counter, apple in fridge"),
        # "once both X are done" after two tasks on X: never Y after the second alone
        (
            "FloorPlan1",
            "chill a mug and put it on the counter, heat another mug and put it in the coffee maker. throw "
            "an apple in the trash once both mugs are done",
        ),
    ],
)
def test_what_cannot_be_read_right_is_refused_by_name(plan, text):
    assert refusal(text, shared_world(plan)) != ""


@needs_data
def test_then_before_a_free_order_still_orders():
    """Before: no order at all (the structure model's reading, which check 1 let "any order" excuse)."""
    res = translate(
        "Put the cd on the desk. Then with the lamp on, look at the watch and also the pencil, any order.",
        shared_world("FloorPlan301"), build=False, actions="none",
    )
    assert not res.partial and sorted(res.before) == [("A", "B"), ("A", "C")]
    assert [t.summary() for t in res.tasks] == [
        "place CD -> Desk", "examine_in_light Watch under DeskLamp", "examine_in_light Pencil under DeskLamp"
    ]


@needs_data
def test_a_glass_bowl_is_a_bowl():
    """Before: "'glass bowl' (place): no base task uses it" ("glass" read as the drinking glass)."""
    res = translate(
        "put a pen in the glass bowl and the bowl on the desk", shared_world("FloorPlan301"), build=False,
        actions="none",
    )
    assert not res.partial and [t.summary() for t in res.tasks] == ["place_in_container Pen in Bowl -> Desk"]
