"""Issue 28: names ALFRED's annotators give things, counted over the non-excluded train annotations
(scripts/alfred_names.py, results/language/h171.md): a name is read as the first of its types that the
world builds (`household_names.txt`), refused by name where it could be two (`: either`), and left alone
where the world has none of them or where it is part of a longer name; plain everyday names
(`everyday_names.txt`) are written as the lexicon's names everywhere."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar.everyday import everyday_names
from nl2hltl2plan.language.household_words import descriptive_name_notes, descriptive_names

BATHROOM_CART = {"Cart", "HandTowelHolder", "Toilet", "SoapBar"}  # FloorPlan430's world: no Shelf built
KITCHEN_STAND = {"SideTable", "Microwave"}  # FloorPlan3's: "the microwave stand" is its SideTable
LIVING_ROOM = {"WateringCan", "FloorLamp"}  # no Kettle


@pytest.mark.parametrize(
    "text, types, read",
    [
        ("put the soap on the metal rack", BATHROOM_CART, "put the soap on the cart"),
        ("put the soap on the rack", BATHROOM_CART, "put the soap on the cart"),
        ("put the soap on the shelf", BATHROOM_CART, "put the soap on the cart"),
        # a world that builds a Shelf keeps it; one with neither leaves the word to the grammar
        ("put the soap on the shelf", BATHROOM_CART | {"Shelf"}, "put the soap on the shelf"),
        ("put the soap on the rack", {"TowelHolder", "Toilet"}, "put the soap on the rack"),
        # part of a longer name of the lexicon: the towel rack stays the towel rack
        ("hang the towel on the towel rack", BATHROOM_CART, "hang the towel on the towel rack"),
        ("put the apple on the microwave stand", KITCHEN_STAND, "put the apple on the side table"),
        ("put the bread on the stand", KITCHEN_STAND, "put the bread on the side table"),
        # "stand" after "on" only: the verb is left alone
        ("stand the book on the desk", {"SideTable", "Desk"}, "stand the book on the desk"),
        ("look at the tea pot by the lamp", LIVING_ROOM, "look at the watering can by the lamp"),
        ("look at the tea pot by the lamp", {"Kettle", "WateringCan"}, "look at the kettle by the lamp"),
        ("put the vase in the cabinet", {"Glassbottle", "Cabinet"}, "put the glassbottle in the cabinet"),
        ("put the vase in the cabinet", {"Vase", "Glassbottle"}, "put the vase in the cabinet"),
    ],
)
def test_a_name_is_the_first_of_its_types_the_world_builds(text: str, types: set[str], read: str) -> None:
    assert descriptive_names(text, types) == read


def test_a_stand_of_two_kinds_is_refused_by_name() -> None:
    with pytest.raises(HTTError, match="'stand' could be the SideTable or the CoffeeTable here"):
        descriptive_names("put the remote on the stand", {"SideTable", "CoffeeTable", "Sofa"})


@pytest.mark.parametrize(
    "text, read",
    [
        ("put the keys on the loveseat", "put the keys on the sofa"),
        ("put the keys on the love seat", "put the keys on the sofa"),
        ("put the pen in the book case", "put the pen in the bookshelf"),
        ("put the statue of a dog on the shelf", "put the statue on the shelf"),
        ("move both dog statues to the table", "move both statues to the table"),
    ],
)
def test_everyday_names_of_sofas_shelves_and_statues(text: str, read: str) -> None:
    assert everyday_names(text) == read


def test_a_name_read_as_another_type_is_said_in_the_assumptions() -> None:
    """The lead (session 27): "kettle" was read as the watering can and nothing said so; every descriptive
    name that writes another word is a note ("read 'x' as 'y'"), which `translate` adds to `assumptions`."""
    said = descriptive_name_notes("put the kettle on the sofa", LIVING_ROOM)
    assert said == ["read 'kettle' as 'watering can'"]
    assert descriptive_name_notes("put the kettle on the stove", {"Kettle", "WateringCan"}) == []
    assert descriptive_name_notes("put the vase in the cabinet", {"Vase"}) == []
