"""The tabletop reader's chat forms (issue 28, h109): "in any order you find convenient", greetings,
replies, thanks and sign-offs around the request, and "when both are on it" ("n" / "&" / "+" for "and"
and "u" for "you" are every world's: test_shared_shorthand.py); with the near misses each rule must still
refuse or leave as written."""

from __future__ import annotations

import pytest
from tabletop_readings import pairs_read as _reading

from nl2hltl2plan.language.tabletop_chat import chat_read

KINDS = {"orange": False, "carrot": False, "blue plate": True, "yellow plate": True}
_TWO = ([("Carrot", "BluePlate"), ("Orange", "YellowPlate")], [])
_FIRST = [("GreenApple", "YellowPlate"), ("Orange", "YellowPlate")]
_THEN = [("Carrot", "BluePlate"), ("RedApple", "BluePlate")]
_ORDERED = (sorted(_FIRST + _THEN), sorted((a, b) for a in _FIRST for b in _THEN))




@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("in any order you find most convenient", "in any order you like"),
        ("whatever order you find easiest", "whatever order you like"),
        ("Hi there, put the carrot down.", "put the carrot down."),
        ("Hi! Sure thing! Put it down.", "Put it down."),
        ("Put it down. Thank you so much!", "Put it down."),
        ("Put it down. Cheers, Ana", "Put it down."),
        # one greeting policy in every world: a greeting or reply goes before any clause, at any sentence
        ("Hey, when you're done, put it down.", "when you're done, put it down."),
        ("No problem! Once that's done, put it down.", "Once that's done, put it down."),
        ("Put the carrot down. Hi there! Put it down.", "Put the carrot down. Put it down."),
    ],
)
def test_chat_forms_read_as_plain_words(text, read):
    assert chat_read(text, KINDS) == read


@pytest.mark.parametrize(
    "text",
    [
        "Hey robot put it down.",  # a greeting that goes on is left as written
        "Put it down. Thanks, but not the carrot.",  # thanks with more to say stays
        "Put it down. Cheers, Orange",  # a sign-off's name that names a thing stays
        "Put it down in any order you find the carrot.",  # "find" that is no leave stays
        "when it is on it, put it down",  # only "both" / "they" / "all" ... are on it
    ],
)
def test_near_misses_left_as_written(text):
    assert chat_read(text, KINDS) == text


@pytest.mark.parametrize(
    "text",
    [
        "hey, can u put the carrot on the blue plate n the orange on the yellow plate? thx",
        "Hello! Put the orange on the yellow plate & the carrot on the blue plate, dont care what order. "
        "Cheers, Ana",
        "carrot on the blue plate + orange on the yellow plate, in any order you find convenient",
        "Good morning, please put the carrot on the blue plate and the orange on the yellow plate. Thanks!",
    ],
)
def test_chat_wordings_read(text):
    assert _reading(text) == _TWO


@pytest.mark.parametrize(
    "text",
    [
        "Hi, please put the green apple and the orange on the yellow plate first. After both are on it, put "
        "the carrot and the red apple on the blue plate. Thanks!",
        "No problem! Start with the green apple and the orange on the yellow plate, and when both are on it, "
        "move the carrot and the red apple to the blue plate.",
    ],
)
def test_back_references_after_a_greeting_or_reply_keep_the_order(text):
    assert _reading(text) == _ORDERED


@pytest.mark.parametrize(
    "text",
    [
        "Hi, put the orange n the carrot on the blue plate. Thanks, but not the red apple.",
        "Hello! Don't put the orange on the blue plate. Thanks!",
        "No problem! Don't put the orange on the blue plate.",
        "Put the orange on the blue plate in any order you find the red apple.",
    ],
)
def test_near_misses_still_refused(text):
    assert _reading(text) is None


def test_when_it_is_on_it_names_the_one_thing_just_placed():
    # "it is on it" after one placing: that thing on that plate (h190's "once the bottle is on it"), so the
    # carrot waits for the green apple; it was a refused near miss before the household reader read it
    text = "Put the green apple on the yellow plate, and when it is on it, move the carrot to the blue plate."
    assert _reading(text) == (
        [("Carrot", "BluePlate"), ("GreenApple", "YellowPlate")],
        [(("GreenApple", "YellowPlate"), ("Carrot", "BluePlate"))],
    )


@pytest.mark.parametrize("opener", ["", "Hey, ", "Hi! ", "No problem! "])
def test_a_greeting_before_a_waiting_clause_changes_no_reading(opener):
    """One greeting policy with the household reader (test_household_forms): the greeting goes, and what
    follows reads as it reads alone."""
    text = f"{opener}when you're done, put the carrot on the blue plate and the orange on the yellow plate."
    assert _reading(text) == _TWO


def test_a_thing_taken_up_again_by_that_one_is_the_subject():
    # h229: "the orange, that one can go in ..." is "the orange can go in ..."; a plate taken up stays
    assert chat_read("the orange, that one can go in the yellow plate", KINDS) == (
        "the orange can go in the yellow plate"
    )
    assert chat_read("the blue plate, that one can go", KINDS) == "the blue plate, that one can go"
    assert _reading("Take the carrot and pop it in the blue plate, and the orange, that one can go in the "
                    "yellow plate. No rush at all, whenever you get to it.") == _TWO


def test_once_you_have_got_them_in_there_waits_for_them_to_be_there():
    # h229: what the one asked has placed, said as the things being there
    assert chat_read("Once you've got them both in there, put the carrot on the blue plate", KINDS) == (
        "Once they're both there, put the carrot on the blue plate"
    )
    text = ("First the green apple and the orange go into the yellow plate, in either order. Once you've got "
            "them both in there, the carrot and the red apple go into the blue plate.")
    assert _reading(text) == _ORDERED
