"""A plate that waits (`tabletop_waits`): read as an order where that is all it says, refused otherwise."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.task_specs import transitive_closure
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.tabletop_world import tabletop_world

WORLD = tabletop_world()
YELLOW_THEN_BLUE = [
    (("GreenApple", "YellowPlate"), ("Carrot", "BluePlate")),
    (("Orange", "YellowPlate"), ("Carrot", "BluePlate")),
]


def _order(text: str) -> list | None:
    """The closed order by (object, plate) of a full reading; None on a refusal or a partial reading."""
    try:
        r = translate(text, WORLD, build=False)
    except HTTError:
        return None
    if r.partial:
        return None
    key = {t.id: (t.object[0], t.receptacle[0]) for t in r.tasks}
    return sorted((key[a], key[b]) for a, b in transitive_closure(r.before, list(key)))


@pytest.mark.parametrize(
    "text",
    [
        "Don't touch the blue plate until the green apple and the orange are on the yellow plate. Then put "
        "the carrot on the blue plate.",
        "Keep the blue plate empty until the green apple and the orange are on the yellow plate; the carrot "
        "goes on the blue plate.",
        "Nothing goes onto the blue plate until the green apple and the orange are on the yellow plate, then "
        "the carrot goes on the blue plate.",
        "Put the green apple and the orange on the yellow plate before anything goes on the blue plate. Then "
        "put the carrot on the blue plate.",
        "The yellow plate gets the green apple and the orange before the blue plate gets anything; the "
        "carrot goes on the blue plate.",
    ],
)
def test_a_plate_that_waits_orders_its_placements_after_what_it_waits_for(text):
    assert _order(text) == YELLOW_THEN_BLUE


@pytest.mark.parametrize(
    "text",
    [
        # a placement after the clause on another plate: the clause does not order it
        "Don't touch the blue plate until the green apple is on the yellow plate. Then put the carrot on "
        "the blue plate and the orange on the pink plate.",
        # the placement after it names no plate ("it" could be either)
        "Nothing goes onto the blue plate until the green apple is on the yellow plate, then the carrot goes "
        "on it.",
        # what it waits for is on the waiting plate itself
        "Leave the blue plate alone until the green apple is on the blue plate, then put the carrot on the "
        "blue plate.",
        # the clause does not open the text
        "Put the orange on the pink plate. Don't touch the blue plate until the green apple is on the "
        "yellow plate, then put the carrot on the blue plate.",
    ],
)
def test_a_plate_that_waits_and_says_more_is_not_read_as_an_order(text):
    assert _order(text) is None
