"""h203's lamp lists (issue 28): the things listed after an examination under a lamp ("..., then the remote
closest to the vase, and finally the phone on the TV stand", "Do the same with the newspaper on the TV
stand", "check three things under the lamp: A on L, B and C") are each looked at under that lamp, and the
place said with one is where it is, not where it goes."""

from __future__ import annotations

import pytest
from household_readings import reading

from nl2hltl2plan.language.grammar.lamp_phrases import items_under_lamp, lamp_phrasing
from nl2hltl2plan.language.grammar.repeats import repeated_for_another


@pytest.mark.parametrize(
    "text, said",
    [
        (
            "Hold the pencil under the desk lamp. After that, the pillow from the bed, and lastly the cd on "
            "the desk.",
            "Hold the pencil under the desk lamp. After that, look at the pillow from the bed under the desk "
            "lamp, and lastly look at the cd on the desk under the desk lamp.",
        ),
        (
            "Switch on the floor lamp to look at the laptop. Do the same with the newspaper on the TV stand.",
            "Switch on the floor lamp to look at the laptop. Look at the newspaper on the TV stand under the "
            "floor lamp.",
        ),
        (
            "Check two things under the floor lamp: the statue on the table and the vase. Any order.",
            "Look at the statue on the table under the floor lamp and look at the vase under the floor lamp. "
            "Any order.",
        ),
        (
            "Look at the book by the chair and the pillow on the sofa under the desk lamp.",
            "Look at the book by the chair under the desk lamp and look at the pillow on the sofa under the "
            "desk lamp.",
        ),
        # a destination ("into"), or a task of another kind between the lamp and the item: left as written
        ("Look at the book under the lamp, then the pen into the drawer.",) * 2,
        ("Look at the book under the lamp. Put the mug in the sink, then the cup on the shelf.",) * 2,
        # a list in another sentence than the examination's: its things are placed
        ("Look at the remote under the lamp. Both statues on the dresser. Then the keys in a box.",) * 2,
        # an order said inside the item ("after that"): left to the repeat, whose order the rules read
        ("Check the laptop under the lamp, and do the same with the alarm clock after that.",) * 2,
        # the count said before the list is not the number of things listed
        ("Check three things under the lamp: the book and the vase.",) * 2,
    ],
)
def test_things_listed_after_a_lamp_are_looked_at_under_it(text, said):
    assert items_under_lamp(text) == said


def test_switch_on_and_give_a_look_are_the_read_forms():
    assert lamp_phrasing("Switch on the floor lamp and give the watch a look.") == (
        "Turn on the floor lamp and look at the watch."
    )


def test_a_verb_that_names_an_appliance_is_repeated_as_the_verb():
    # "Microwave" opening the task before is its verb: the repeat is written out, with the tomato's article
    said = "Microwave an egg and set it on the counter, then do the same with a tomato but put that in a bin"
    assert repeated_for_another(said) == (
        "Microwave an egg and set it on the counter. Then microwave a tomato and set it in a bin"
    )


@pytest.fixture(scope="module")
def living_room(world):
    return world("FloorPlan219")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks, before",
    [
        # before: the newspaper and the TV stand were read as places no task used (partial)
        (
            "Pick up the statue and switch on the floor lamp to look at it. Do the same with the newspaper "
            "on the dresser.",
            ["examine_in_light Statue under FloorLamp", "examine_in_light Newspaper under FloorLamp"],
            [],
        ),
        # before: "on the dresser" was given to every examination, and the vase read as a place (partial)
        (
            "Turn on the floor lamp and look at the statue in its light, then the tissue box closest to the "
            "vase, and finally the newspaper on the dresser.",
            [
                "examine_in_light Statue under FloorLamp",
                "examine_in_light TissueBox under FloorLamp",
                "examine_in_light Newspaper under FloorLamp",
            ],
            [("A", "B"), ("B", "C")],
        ),
        # before: refused (no task understood)
        (
            "I'd like you to check two things under the floor lamp: the statue on the dresser and the "
            "newspaper on the table. Any order's fine.",
            ["examine_in_light Statue under FloorLamp", "examine_in_light Newspaper under FloorLamp"],
            [],
        ),
    ],
)
def test_lamp_lists_read_each_thing_looked_at_where_it_is(living_room, text, tasks, before):
    assert reading(text, living_room) == (tasks, before)
