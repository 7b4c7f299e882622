"""h212 (issue 28): a thing put in a movable container and the container moved, in people's words. One
place-in-container task however the two steps are said ("..., and the box goes on the sofa", "... in the
box. Then put the box on ...", "X in a mug, with the mug on ...", an item "a bowl with a pen in it" of a
list whose place is said once, "another bowl", "set both on ..."); refused by name where the text cannot
be one task (the container moved before the thing is put in it, in another sentence) or does not say which
of two containers is moved."""

from __future__ import annotations

import pytest
from household_readings import reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar.sentence_joins import container_moved_on
from nl2hltl2plan.language.translate import translate

PHONE_BOX = "place_in_container CellPhone in Box -> Sofa"
PEN_BOWL = "place_in_container Pen in Bowl -> Dresser"
PENCIL_BOWL = "place_in_container Pencil in Bowl -> SideTable"


@pytest.fixture(scope="module")
def living_room(world):
    return world("FloorPlan229")


@pytest.fixture(scope="module")
def bedroom(world):
    return world("FloorPlan330")


@pytest.mark.parametrize(
    "text, said",
    [
        (
            "Put the phone in the box. Then put the box on the sofa.",
            "Put the phone in the box, then put the box on the sofa.",
        ),
        (
            "put the pen in a bowl. set that bowl on the desk.",
            "put the pen in a bowl, then set that bowl on the desk.",
        ),
        # kept apart: another container, another thing moved, a first sentence that ends elsewhere
        ("Put the pen in a bowl. Put another bowl on the desk.",) * 2,
        ("Put the pen in the bowl. Then put the book on the desk.",) * 2,
        ("Put the pen on the desk. Then put the bowl on the shelf.",) * 2,
    ],
)
def test_a_container_moved_in_the_next_sentence_is_joined(text, said):
    assert container_moved_on(text) == said


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "the phone goes in the box, and the box goes on the sofa",
        "Put the phone in the cardboard box. Then put the box on the sofa.",
        "Put the phone in the box, with the box on the sofa.",
    ],
)
def test_the_two_steps_read_one_task(living_room, text):
    assert reading(text, living_room) == ([PHONE_BOX], [])


@pytest.mark.data
def test_an_item_with_its_content_takes_the_place_said_once(bedroom):
    text = "Everything below goes on the dresser: a book, a bowl with a pen in it, and a pencil."
    tasks, _ = reading(text, bedroom)
    assert tasks == ["place Book -> Dresser", PEN_BOWL, "place Pencil -> Dresser"]


@pytest.mark.data
def test_another_container_is_a_second_task(bedroom):
    text = "Put a bowl on the dresser, and put the pencil in another bowl and set that bowl on the side table"
    assert reading(text, bedroom)[0] == ["place Bowl -> Dresser", PENCIL_BOWL]
    text = "Put a pen in a bowl and a pencil in another bowl, and set both bowls on the dresser."
    assert reading(text, bedroom)[0] == [PEN_BOWL, PENCIL_BOWL.replace("SideTable", "Dresser")]


@pytest.mark.data
@pytest.mark.parametrize(
    "text, words",
    [
        # moved first, filled in the next sentence: two tasks could take two bowls
        ("Put the bowl on the dresser. Then put the pen in the bowl.", "'the bowl' is what task A moves"),
        # two bowls filled, one moved: which one is not said
        (
            "Put the pen in a bowl and a pencil in a bowl, then put the bowl on the dresser.",
            "'the bowl': tasks A and B each put a thing in a bowl",
        ),
    ],
)
def test_a_container_the_text_cannot_keep_to_one_task_is_refused(bedroom, text, words):
    with pytest.raises(HTTError, match=words):
        translate(text, bedroom, build=False, actions="none")


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks, before",
    [
        ("put the phone in the box, and then set the box on the sofa", [PHONE_BOX], []),
        ("drop the phone into the box, then carry the box over to the sofa", [PHONE_BOX], []),
        ("The phone goes in the box. The box goes on the sofa.", [PHONE_BOX], []),
        (
            "Put the pen on the dresser. Put the phone in the box. Then put the box on the sofa.",
            ["place Pen -> Dresser", PHONE_BOX],
            [],
        ),
        (
            "Put the phone in the box. Then put the box on the sofa. Then put the pen on the dresser.",
            [PHONE_BOX, "place Pen -> Dresser"],
            [("A", "B")],
        ),
        (
            "Put these on the sofa: a box with the phone in it and a pillow.",
            [PHONE_BOX, "place Pillow -> Sofa"],
            [],
        ),
    ],
)
def test_more_ways_of_saying_it(living_room, text, tasks, before):
    assert reading(text, living_room) == (tasks, before)
