"""Task 4 said in stages (issues 28, 24; h241): a stage label or marker opens a group, the group's items
are free among themselves, and a later stage follows every item of the one before; a label out of turn is
refused by name, never read by where it is written."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.translate import translate
from tests.language.tabletop_readings import WORLD, pairs_read

FIRST = [("GreenApple", "YellowPlate"), ("Orange", "YellowPlate")]
SECOND = [("Carrot", "BluePlate"), ("RedApple", "BluePlate")]
STAGED = (sorted(FIRST + SECOND), sorted((a, b) for a in FIRST for b in SECOND))


@pytest.mark.parametrize(
    "text",
    [
        # a stage noun with a number word and a comma ("Wave one, ...")
        "Wave one, the green apple and the orange into the yellow plate. Wave two, the carrot and the red "
        "apple into the blue plate.",
        # a later stage's reference to the one just before it says the order the labels say already
        "Batch one: the green apple and the orange into the yellow plate. Batch two, once batch one is in: "
        "the carrot and the red apple into the blue plate.",
        # a stage named by its ordinal opening a sentence, with its reference back to the stage before
        "The first batch is the green apple and the orange, into the yellow plate. The second batch is the "
        "carrot and the red apple, into the blue plate, after the first batch.",
        # stages named by their place (tabletop_stages.txt)
        "Warm-up: the green apple and the orange go in the yellow plate. Main event: the carrot and the red "
        "apple go in the blue plate.",
        # a remark inside each item of a numbered list frees that item, not the list
        "1. Green apple and orange into the yellow plate, either order.\n2. Carrot and red apple into the "
        "blue plate, either order.",
        # a lettered list is in turn as a numbered one
        "a) the orange and the green apple in the yellow plate\nb) the carrot and the red apple in the blue "
        "plate",
        # what is said before the others comes first; "when that's all set" looks back on it
        "Put the green apple and the orange in the yellow plate before touching the others. Put the carrot "
        "and the red apple in the blue plate.",
        "To begin, the green apple and the orange into the yellow plate, whichever order. When that's all "
        "set, the carrot and the red apple into the blue plate.",
    ],
)
def test_stages_order_their_groups_and_free_each_group(text):
    assert pairs_read(text) == STAGED


def test_a_lettered_list_freed_as_a_whole_only_lists():
    text = "a) the orange in the yellow plate\nb) the carrot in the blue plate\nAny order."
    assert pairs_read(text) == (sorted([("Orange", "YellowPlate"), ("Carrot", "BluePlate")]), [])


def test_letters_inside_a_sentence_are_no_lettered_list():
    # a method's steps named by letter after a colon and a semicolon, freed by letter, as before (h106)
    text = (
        "Method: a) green apple onto blue plate; b) orange onto yellow plate. Steps a and b may be done in "
        "either order."
    )
    assert pairs_read(text) == (sorted([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")]), [])


def test_letters_out_of_turn_are_refused_by_name():
    res = translate("b) the orange in the yellow plate\na) the carrot in the blue plate", WORLD, build=False)
    assert res.partial and any("'b), a)' (order): steps numbered out of turn" in u for u in res.unparsed)


@pytest.mark.parametrize(
    "text",
    [
        "Main event: the carrot and the red apple go in the blue plate. Warm-up: the green apple and the "
        "orange go in the yellow plate.",
        "The second batch is the carrot and the red apple, into the blue plate. The first batch is the "
        "green apple and the orange, into the yellow plate.",
    ],
)
def test_named_stages_out_of_turn_are_not_read(text):
    assert pairs_read(text) is None  # refused or partial: the command exits 2
