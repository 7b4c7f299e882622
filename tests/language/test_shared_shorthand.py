"""The words every world shares (issue 28, h113): chat shorthand read in every world by the shared spelling
step (`spelling.shorthand_read`), greetings, forms of address and thanks from one list (`courtesy.txt`),
and the prepositions of places taken from the grammar's one list (`prepositions`). A lone "n" or "u" that
names something by a letter stays as written."""

from __future__ import annotations

import pytest
from household_readings import reading
from tabletop_readings import pairs_read

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.courtesy import courtesy_words, without_greetings
from nl2hltl2plan.language.grammar.word_tables import PREPOSITIONS
from nl2hltl2plan.language.handover_discourse import frame_words
from nl2hltl2plan.language.prepositions import ONE_PLACE, PLACE_OR_LANDMARK, preposition_pattern
from nl2hltl2plan.language.spelling import shorthand_read
from nl2hltl2plan.language.translate import translate


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("the carrot n the orange", "the carrot and the orange"),
        ("carrot & orange", "carrot and orange"),
        ("carrot&orange", "carrot and orange"),
        ("carrot+orange", "carrot+orange"),  # "+" only between spaced words
        ("carrot + orange", "carrot and orange"),
        ("can u put it", "can you put it"),
        ("put it in the sink w/ the lid", "put it in the sink with the lid"),
        ("put it in the sink w/o the lid", "put it in the sink without the lid"),
        ("the yellow plate n the green apple", "the yellow plate and the green apple"),
        ("green plate n red apple", "green plate and red apple"),  # a plate: by colour, never a letter
        ("region i n the blue block", "region i and the blue block"),
        ("on shelf u", "on shelf u"),
        ("an orange", "an orange"),  # "n" inside a word stays
        ("put it on region n and the cup on shelf u", "put it on region n and the cup on shelf u"),
        ("take plan n or option u", "take plan n or option u"),  # a letter that names a plan or option
        ("the n", "the n"),  # "n" not between two words
        ("a u-turn", "a u-turn"),
    ],
)
def test_shorthand_is_read_and_letters_stay(text, read):
    assert shorthand_read(text) == read


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


@pytest.mark.data
@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("put the mug n the apple in the sink", ["place Mug -> SinkBasin", "place Apple -> SinkBasin"]),
        ("can u put the mug in the microwave & the apple in the fridge",
         ["place Mug -> Microwave", "place Apple -> Fridge"]),
        ("Hiya folks, put the mug in the sink. Much appreciated!", ["place Mug -> SinkBasin"]),
        ("Put the mug in the sink. Cheers, Ana", ["place Mug -> SinkBasin"]),
    ],
)
def test_household_reads_the_shared_words(kitchen, text, tasks):
    assert reading(text, kitchen)[0] == tasks


@pytest.mark.data
def test_with_said_as_w_slash_is_never_dropped(kitchen):
    """Before, "w/ the apple" was passed over and the mug alone put in the sink: a wrong reading."""
    try:
        res = translate("put the mug in the sink w/ the apple", kitchen, build=False, actions="none")
    except HTTError:
        return
    assert res.partial


def test_tabletop_reads_the_shared_words():
    two = [("GreenApple", "BluePlate"), ("Orange", "YellowPlate")]
    said = "hey mate, could u put the orange on the yellow plate & the green apple on the blue plate? cheers"
    assert pairs_read(said) == (two, [])
    said = "Hiya folks! Put the green apple on the blue plate n the orange on the yellow plate."
    assert pairs_read(said) == (two, [])


@pytest.fixture(scope="module")
def square(world):
    return world("handover-square")


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # "I n the": the "n" after region I's letter joins two placements
        ("Hiya folks, put the red block on region I n the blue block on region J.",
         ["place RedBlock -> RegionI", "place BlueBlock -> RegionJ"]),
        ("Hey buddy! can u put the yellow block on region G? Much appreciated!",
         ["place YellowBlock -> RegionG"]),
        ("Hello mate, move the red block to region I, then the blue block to region J. Cheers, Ana",
         ["place RedBlock -> RegionI", "place BlueBlock -> RegionJ"]),
        # h113's held-out handover wordings, written with the ones above and scored once at the end
        ("Heya team, put the blue block on region I n the red block on region H.",
         ["place BlueBlock -> RegionI", "place RedBlock -> RegionH"]),
        ("Hi friend! could u move the yellow block to region J? Thanks in advance!",
         ["place YellowBlock -> RegionJ"]),
        ("Howdy everyone, place the blue block & the yellow block on region G. Many thanks!",
         ["place BlueBlock -> RegionG", "place YellowBlock -> RegionG"]),
    ],
)
def test_handover_reads_the_shared_words(square, text, tasks):
    assert [t.summary() for t in translate(text, square, build=False, actions="none").tasks] == tasks


def test_one_list_of_greetings_and_addresses_for_every_reader():
    assert {"hiya", "hello"} <= courtesy_words("greeting")
    assert {"team", "buddy", "folks"} <= courtesy_words("address")
    assert frame_words()["greeting"] == courtesy_words("greeting")
    assert frame_words()["address"] == courtesy_words("address")
    assert courtesy_words("greeting") | courtesy_words("address") <= courtesy_words("courtesy_word")


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("Hi team, put it down. Much appreciated!", "put it down."),
        ("Hey robot put it down.", "Hey robot put it down."),  # a greeting that runs on stays
        ("Hey, when you're done, put it down.", "when you're done, put it down."),  # before any clause
        ("Put it down. Thanks, but not the mug.", "Put it down. Thanks, but not the mug."),
        ("Put it down. Cheers, Mug", "Put it down. Cheers, Mug"),  # the name names a thing
    ],
)
def test_greetings_and_thanks_removed_alike(text, read):
    assert without_greetings(text, lambda name: name == "Mug") == read


def test_prepositions_come_from_the_grammar_list():
    listed = {" ".join(p) for p in PREPOSITIONS}
    assert ONE_PLACE <= listed and PLACE_OR_LANDMARK <= listed
    assert {"in", "into", "inside", "on", "onto", "on top of", "to", "under", "at"} <= ONE_PLACE
    assert {"between", "among", "with", "from"}.isdisjoint(ONE_PLACE)
    assert {"beside", "next to", "in front of", "behind", "by"} <= PLACE_OR_LANDMARK
    with pytest.raises(ValueError, match="beyond"):
        preposition_pattern({"in", "beyond"})
