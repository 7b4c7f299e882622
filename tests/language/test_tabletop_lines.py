"""The tabletop world's text as its readers read it (`tabletop_lines`): each line break read by what the
lines name (the ALFRED worlds still join the lines with spaces), names spelt otherwise, and an "after"
with nothing after it in its clause."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.demo import demo_world
from tests.language.test_tabletop_pairs import _reading

YELLOW_THEN_BLUE = (
    [
        ("Carrot", "BluePlate"),
        ("GreenApple", "YellowPlate"),
        ("Orange", "YellowPlate"),
        ("RedApple", "BluePlate"),
    ],
    [
        (("GreenApple", "YellowPlate"), ("Carrot", "BluePlate")),
        (("GreenApple", "YellowPlate"), ("RedApple", "BluePlate")),
        (("Orange", "YellowPlate"), ("Carrot", "BluePlate")),
        (("Orange", "YellowPlate"), ("RedApple", "BluePlate")),
    ],
)


@pytest.mark.parametrize(
    "text",
    [
        "Step 1: yellow plate\n - green apple\n - orange\nStep 2: blue plate\n - carrot\n - red apple",
        "First the yellow plate\n* green apple\n* orange\nThen the blue plate\n* carrot\n* red apple",
        "Yellow plate first\n- green apple\n- orange\nthen blue plate\n- carrot\n- red apple",
    ],
)
def test_a_plate_heading_takes_the_objects_listed_under_it(text):
    assert _reading(text) == YELLOW_THEN_BLUE


def test_a_bullet_list_of_placements_is_read_one_placement_a_line():
    text = "[ ] green apple -> blue plate\n[x] orange -> yellow plate"
    assert _reading(text) == ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])


def test_a_line_that_stops_mid_sentence_goes_on_past_the_break():
    text = "put the green apple on the\nblue plate and the orange on the yellow plate"
    assert _reading(text) == ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])


def test_a_plate_heading_with_nothing_listed_under_it_is_refused():
    assert _reading("Step 1: yellow plate\nStep 2: blue plate\n - carrot") is None


def test_other_worlds_join_the_lines_with_spaces():
    res = translate("put the apple\nin the fridge", demo_world(), build=False)
    assert res.instruction == "put the apple in the fridge"


@pytest.mark.parametrize(
    "text",
    [
        "Put the carrot in the plate blue, the orange in the plate yellow, the green apple in the plate "
        "green and the red apple in the plate pink, the order is free.",
        "carrot -> blue_plate, orange -> yellow_plate, green_apple -> green_plate, red_apple -> pink_plate",
    ],
)
def test_names_spelt_otherwise_are_the_worlds_names(text):
    assert _reading(text) == (
        [
            ("Carrot", "BluePlate"),
            ("GreenApple", "GreenPlate"),
            ("Orange", "YellowPlate"),
            ("RedApple", "PinkPlate"),
        ],
        [],
    )


def test_a_colour_after_a_plate_before_another_names_noun_stays_as_it_was():
    # "the yellow plate green apple": no "plate green" here; the list still pairs each object with its plate
    text = "carrot on the blue plate green apple on the green plate"
    assert _reading(text) == ([("Carrot", "BluePlate"), ("GreenApple", "GreenPlate")], [])


@pytest.mark.parametrize(
    "text",
    [
        "First, green apple and orange -> yellow plate. After, carrot and red apple -> blue plate.",
        "yellow plate first: green apple, orange. blue plate after: carrot, red apple.",
    ],
)
def test_an_after_that_opens_a_clause_or_closes_a_plates_heading_orders_the_steps(text):
    assert _reading(text) == YELLOW_THEN_BLUE


@pytest.mark.parametrize(
    "text",
    [
        "Green apple and orange on the yellow plate to start; carrot and red apple on the blue plate to "
        "finish.",
        "The yellow plate comes first with the green apple and the orange, and the blue plate comes second "
        "with the carrot and the red apple.",
    ],
)
def test_where_a_clause_stands_in_the_whole_orders_it(text):
    assert _reading(text) == YELLOW_THEN_BLUE


def test_a_clause_closed_by_to_finish_with_nothing_to_follow_is_refused():
    # which placement comes last is not said: no reading with no order is given
    assert _reading("Put the carrot on the blue plate and the orange on the yellow plate to finish.") is None


def test_plates_said_with_no_colour_are_the_plates_paired():
    text = "Grocery list for the plates:\ngreen apple (blue plate)\norange (yellow plate)"
    assert _reading(text) == ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])


def test_number_words_opening_sentences_number_a_list():
    ordered = (
        "One, the green apple and the orange on the yellow plate. Two, the carrot and the red apple on the "
        "blue plate."
    )
    assert _reading(ordered) == YELLOW_THEN_BLUE
    listed = "One, the carrot on the blue plate; two, the orange on the yellow plate. Any order!"
    assert _reading(listed) == ([("Carrot", "BluePlate"), ("Orange", "YellowPlate")], [])
    assert _reading("Two, the carrot on the blue plate; one, the orange on the yellow plate.") is None


@pytest.mark.parametrize(
    "text",
    [
        "Item the first: the green apple upon the blue plate. Item the second: the orange upon the yellow "
        "plate.",
        "Point 1: the green apple on the blue plate. Point 2: the orange on the yellow plate.",
    ],
)
def test_numbered_entries_of_a_list_are_refused_as_neither_steps_nor_free(text):
    # main read them as two ordered steps: the entries of a list may or may not be steps in turn
    assert _reading(text) is None
