"""h310 (issues 23, 28): paper_h301's classes. An order said after its task ("Y once you're done with those
two", "X, but they can wait till you've put Z ..."); a contract's or a decree's wording ("The Contractor shall
wash X and shall thereafter place the said X ...", "X shall be washed and laid on Y", "X shall be taken from A
and laid upon B"); a container put "in a box; place the box on Y"; a relative clause of where a thing is ("the
plate thats in the microwave") as a source; "footrest" for the ottoman. Sentences of probes_h310dev."""

from __future__ import annotations

import pytest
from household_readings import reading, refusal, shared_world

from nl2hltl2plan.language.grammar.restated import restated
from nl2hltl2plan.language.grammar.sentence_joins import container_again


def test_an_order_said_after_its_task_is_read() -> None:
    tasks, before = reading(
        "Put a pen on the desk, then a cd in a drawer. Put the mug on the shelf once you're done with those "
        "two",
        shared_world("FloorPlan301"),
    )
    assert len(tasks) == 3 and sorted(before) == [("A", "B"), ("B", "C")]
    tasks, before = reading(
        "Both candles go in the cabinet, but they can wait till you've put the soap bar in the tub.",
        shared_world("FloorPlan402"),
    )
    assert len(tasks) == 2 and before == [("B", "A")]


@pytest.mark.parametrize(
    "text",
    [
        "Put the remote on the sofa. Put both watches on the end table, but they can wait till you've done "
        "that.",
        # (the "while" of one examination under a lamp frees no order between tasks)
        "Pick up the remote on the dresser and turn the floor lamp on while you hold it. Both watches on the "
        "coffee table go to the round black end table, but they can wait till you've done the lamp.",
    ],
)
def test_a_wait_till_the_task_before_is_done_is_named_when_no_reading_orders_it(text: str) -> None:
    """ "till" is an order word of check 1 (session 35): the learned reading of "..., but they can wait till
    you've done that" (no order) passed check 1 at exit 0 before; now the clause is named."""
    assert "can wait till you've done" in refusal(text, shared_world("FloorPlan217"))


def test_those_two_after_three_tasks_is_refused_by_name() -> None:
    text = (
        "Put a pen on the desk, then a cd in a drawer, then a watch on the dresser. Put the mug on the shelf "
        "once you're done with those two."
    )
    assert "both are done" in refusal(text, shared_world("FloorPlan301"))


@pytest.mark.parametrize(
    "plan, text, thing, place",
    [
        (
            "FloorPlan22",
            "The Contractor shall wash the mug found on the counter beside the kettle and place it in the "
            "coffee machine.",
            "Mug",
            "CoffeeMachine",
        ),
        ("FloorPlan413", "A bar of soap shall be washed and laid on the toilet.", "SoapBar", "Toilet"),
        ("FloorPlan208", "move a key chain onto the footrest", "KeyChain", "Ottoman"),
        ("FloorPlan5", "chill the plate thats in the microwave and put it on the shelf", "Plate", "Shelf"),
    ],
)
def test_a_decree_a_footrest_and_where_a_thing_is_read_as_one_task(plan, text, thing, place) -> None:
    tasks, _ = reading(text, shared_world(plan))
    assert len(tasks) == 1 and thing in tasks[0] and place in tasks[0], tasks


def test_a_passive_taking_and_laying_down_is_a_placing() -> None:
    said = restated("Two cell phones shall be taken from the shelves and laid upon the desk!")
    assert said == "take Two cell phones from the shelves and put them on the desk!"
    assert restated("two moods shall be taken from the house and laid upon us") == (
        "two moods shall be taken from the house and laid upon us"  # no thing of the lexicon: left
    )


def test_a_container_put_and_moved_after_a_semicolon_is_one_chain() -> None:
    assert container_again("place the red vase in a cardboard box; place the box on the dining table") == (
        "place the red vase in a cardboard box and put the box on the dining table"
    )
