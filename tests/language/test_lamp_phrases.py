"""h159's paper-style phrasings of looking at a thing under a lamp (issue 28): the purpose of switching on
the lamp a thing was carried to is no second examination, and "check X out" is "check X"."""

from __future__ import annotations

import pytest
from household_readings import reading

from nl2hltl2plan.language.grammar.lamp_phrases import lamp_phrasing


@pytest.mark.parametrize(
    "text, said",
    [
        (
            "bring the box to the floor lamp and turn it on to look at the box",
            "bring the box to the floor lamp and turn it on",
        ),
        (
            "carry the pen to the desk lamp and switch it on to see it.",
            "carry the pen to the desk lamp and switch it on.",
        ),
        # the purpose names another thing than the one carried: kept (it is a task of its own)
        (
            "bring the box to the floor lamp and turn it on to look at the vase",
            "bring the box to the floor lamp and turn it on to look at the vase",
        ),
        # no lamp the thing was carried to: the purpose is the examination itself, kept
        ("pick up the pen and turn on the lamp to look at it",) * 2,
        ("check it out under the lamp", "check it under the lamp"),
        ("check out the vase by the light of the lamp", "check the vase by the light of the lamp"),
        ("use the lamp to look at the book", "look at the book by the light of the lamp"),
    ],
)
def test_lamp_phrasings_are_rewritten_onto_the_read_forms(text, said):
    assert lamp_phrasing(text) == said


@pytest.fixture(scope="module")
def living_room(world):
    return world("FloorPlan219")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        # read before as two examinations of the box (a wrong reading)
        (
            "Bring the box from the blue chair to the floor lamp and turn it on to look at the box.",
            ["examine_in_light Box under FloorLamp"],
        ),
        # read before as nothing ("check" with its particle was no examining verb)
        (
            "Pick up the phone and check it out under the floor lamp.",
            ["examine_in_light CellPhone under FloorLamp"],
        ),
        # another thing named in the purpose stays a task of its own
        (
            "Bring the box to the floor lamp and turn it on to look at the vase.",
            ["examine_in_light Box under FloorLamp", "examine_in_light Vase under FloorLamp"],
        ),
    ],
)
def test_lamp_phrasings_read_one_examination_each(living_room, text, tasks):
    assert reading(text, living_room)[0] == tasks
