"""Remarks that ask nothing (`tabletop_remarks.asks_nothing`), a telegram's STOP and a pause before a word
of place (`tabletop_lines.stops_read`), a heading with its colon left out
(`tabletop_order.heading_colon_put_back`) and a step label that names the one before it: read in the
tabletop world; a remark that could ask something stays a refusal."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.tabletop_remarks import asks_nothing
from tests.language.test_tabletop_lines import YELLOW_THEN_BLUE
from tests.language.test_tabletop_pairs import _reading

TWO_FREE = ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])
PLACEMENTS = "the green apple on the blue plate and the orange on the yellow plate"


@pytest.mark.parametrize(
    "text",
    [
        f"Put {PLACEMENTS}, me hearty.",  # a person addressed, closing the text
        f"Put {PLACEMENTS}. Thank you for flying with us.",  # thanks for something
        f"I've got a bit of a weird request. Put {PLACEMENTS}.",  # a remark with a subject of its own
        f"Put {PLACEMENTS}. Hope that's fine.",  # an opinion, its "I" left out
        f"hey it's me, put {PLACEMENTS}",  # a clause opening the text before a comma
        f"Put {PLACEMENTS}, because it matches.",  # a reason that names nothing
    ],
)
def test_a_remark_that_asks_nothing_is_no_request(text):
    assert _reading(text) == TWO_FREE


@pytest.mark.parametrize(
    "text",
    [
        f"Put {PLACEMENTS}. Wear gloves.",  # an imperative: a request this world cannot take
        f"Put {PLACEMENTS}. It can wait.",  # a wait
        f"Put {PLACEMENTS}. Do it twice.",  # a count
        f"Put {PLACEMENTS}. I'm setting the table.",  # a verb of placing and a table
        f"Put {PLACEMENTS}, thanks for doing it twice.",
        f"Put {PLACEMENTS}, so that it's done first.",  # a reason that says an order
        f"Put {PLACEMENTS}. We need it by noon.",
    ],
)
def test_a_remark_that_could_ask_something_stays_unread(text):
    assert _reading(text) is None


@pytest.mark.parametrize(
    ("clause", "asks"),
    [("me hearty", False), ("it blends in", False), ("be careful", True), ("think of me", True)],
)
def test_only_a_clause_with_a_subject_or_a_person_addressed_is_an_aside(clause, asks):
    assert asks_nothing(clause) is not asks


@pytest.mark.parametrize(
    "text",
    [
        "GREEN APPLE AND ORANGE TO YELLOW PLATE FIRST STOP THEN CARROT AND RED APPLE TO BLUE PLATE STOP",
        "YELLOW PLATE FIRST GREEN APPLE AND ORANGE STOP BLUE PLATE NEXT CARROT AND RED APPLE STOP",
        "yellow plate first green apple and orange. blue plate next carrot and red apple.",
        "Chapter one: the green apple and the orange on the yellow plate. Chapter two, only after chapter "
        "one: the carrot and the red apple on the blue plate.",
    ],
)
def test_a_telegram_a_heading_without_its_colon_and_a_label_naming_the_one_before(text):
    assert _reading(text) == YELLOW_THEN_BLUE


def test_a_pause_before_a_word_of_place_goes_on_and_a_label_naming_another_is_refused():
    assert _reading("the green apple on the blue plate... and the orange... on the yellow plate") == TWO_FREE
    text = (
        "Chapter one: the green apple and the orange on the yellow plate. Chapter two, only after chapter "
        "three: the carrot and the red apple on the blue plate."
    )
    assert _reading(text) is None
    assert _reading("blue plate next green plate carrot and orange") is None  # two plates: no heading


def test_a_plate_said_done_is_the_step_on_it_and_an_order_label_may_be_asked():
    text = (
        "Yellow plate first, with the green apple and the orange; when the yellow plate is done, the blue "
        "plate gets the carrot and the red apple."
    )
    assert _reading(text) == YELLOW_THEN_BLUE
    # the plate said done is not the step just said: which step it waits for is not said
    text = "Green apple, orange on the yellow plate. When the blue plate is done, carrot, red apple on it."
    assert _reading(text) is None
    asked = "Green apple? Blue plate. Orange? Yellow plate. Order? Doesn't matter."
    assert _reading(asked) == TWO_FREE
    assert _reading("Green apple? Blue plate. Orange? Yellow plate. Order? Matters.") is None


def test_a_thing_placed_by_two_tasks_is_refused():
    # the grammar reads "I hate oranges" as a placement too (exit 0 on main with the orange on two plates)
    text = "Put the green apple on the blue plate. I hate oranges. Put the orange on the yellow plate."
    assert _reading(text) is None


@pytest.mark.parametrize(
    "remark",
    ["That's wrong.", "Ignore that.", "I'd prefer it the other way.", "They're swapped.", "Just kidding."],
)
def test_a_remark_that_may_take_back_what_was_asked_stays_unread(remark):
    assert _reading(f"Put {PLACEMENTS}. {remark}") is None
