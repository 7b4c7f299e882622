"""Tabletop wordings read since h99 (issue 28), each with what must stay a refusal: misspelt names and order
words (`tabletop_spelling`), a chat log's time stamps and "the plate that's blue" (`tabletop_lines`), a
label whose value says nothing is asked and a user story's role and reasons (`tabletop_remarks`), and a
step's turn said by an ordinal noun (`tabletop_order.ordinal_things_read`)."""

from __future__ import annotations

import re

import pytest

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.tabletop_lines import lines_joined
from nl2hltl2plan.language.tabletop_order import robot_addressed, turn_phrases_read
from nl2hltl2plan.language.tabletop_remarks import role_dropped
from nl2hltl2plan.language.tabletop_spelling import misspelt_order_words, names_respelt, order_words_spelt
from tests.language.test_tabletop_lines import YELLOW_THEN_BLUE
from tests.language.test_tabletop_pairs import _reading

TWO_FREE = ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])
PLACEMENTS = "the green apple on the blue plate and the orange on the yellow plate"
YELLOW = "the green apple and the orange on the yellow plate"
BLUE = "the carrot and the red apple on the blue plate"


def _read(text: str) -> tuple[list, list] | None:
    """As `_reading`, a world error (a name the world lacks) a refusal too."""
    try:
        return _reading(text)
    except WorldError:
        return None


def test_misspellings_of_the_worlds_names_and_of_order_words_are_respelt():
    kinds = {"green apple": False, "red apple": False, "pink plate": True, "yellow plate": True}
    assert names_respelt("the grean aple, the red appel, the pinc plate", kinds) == (
        "the green apple, the red apple, the pink plate"
    )
    assert names_respelt("the pine apple and the ample plate", kinds) == "the pine apple and the ample plate"
    assert order_words_spelt("Frist A, than B and than C. Than D") == "First A, then B and then C. Then D"
    assert order_words_spelt("more apples than oranges") == "more apples than oranges"  # a comparison
    assert misspelt_order_words("frist") == ["frist"] and misspelt_order_words("first, then") == []


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (f"frist put {YELLOW}, than {BLUE}", YELLOW_THEN_BLUE),  # was read unordered
        ("put the grean apple on the blue plate and the orange on the yelow plate", TWO_FREE),
        ("put the green appel on the blue plate and the oragne on the yellow plate", TWO_FREE),
    ],
)
def test_misspelt_names_and_order_words_are_read(text, expected):
    assert _read(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        f"put {YELLOW} rather than {BLUE}",  # what is not wanted: never a placement
        "Put the carrot on the blue plate sooner than the orange on the yellow plate.",  # an order
        "put the green apple on the blu plate and the orange on the yellow plate",  # "blu" is English
    ],
)
def test_a_comparison_or_an_unread_name_is_refused(text):
    assert _read(text) is None


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("[09:14] Dana: put the green apple on the blue plate\n[09:15] Dana: and the orange on the yellow "
         "one", TWO_FREE),
        (f"09:14 Kai: first {YELLOW}\n09:15 Kai: after that {BLUE}", YELLOW_THEN_BLUE),
        ("Put the green apple on the plate that's blue, the orange on the plate which is yellow.", TWO_FREE),
    ],
)
def test_chat_time_stamps_and_a_colour_said_after_its_plate(text, expected):
    assert _read(text) == expected


def test_a_time_with_no_chat_mark_may_say_when_and_stays_in_the_text():
    kinds = {"green apple": False, "blue plate": True}
    assert lines_joined(["12:00 put the green apple on the blue plate"], kinds).startswith("12:00 put")
    assert lines_joined(["[12:00] Jo: put the green apple on the blue plate"], kinds).startswith("Jo: put")


@pytest.mark.parametrize(
    "text",
    [
        f"Goal - put {PLACEMENTS}. Condition - none.",
        f"Goal: put {PLACEMENTS}.\nConstraints: n/a",
        f"Put {PLACEMENTS}. Notes: nothing.",
    ],
)
def test_a_label_whose_value_says_nothing_is_asked_is_no_request(text):
    assert _read(text) == TWO_FREE


@pytest.mark.parametrize("value", ["none", "n/a", "nothing"])
def test_an_order_label_that_says_nothing_frees_the_order_of_a_record_list(value):
    # the shared labels keep an order label's value for the readers: "Order: none" asks for no order
    records = "Item: green apple | Plate: blue\nItem: orange | Plate: yellow"
    assert _read(f"{records}\nOrder: {value}") == TWO_FREE
    assert _read(f"{records}\nOrder: red first") is None  # a value that says something stays unread


@pytest.mark.parametrize(
    "text",
    [
        f"Put {PLACEMENTS}. Carrots: none.",  # a label that names a thing: none of them, which no task says
        f"Put {PLACEMENTS}. Condition - none of the apples.",  # the value is no "nothing"
        f"Put {PLACEMENTS}. Condition - only after noon.",
    ],
)
def test_a_label_that_names_something_or_says_something_stays_unread(text):
    assert _read(text) is None


@pytest.mark.parametrize(
    "text",
    [
        f"As a hungry user, I want {PLACEMENTS}, so that I can find them.",
        f"As a tidy person, I'd like {PLACEMENTS}, so that the table looks neat.",
    ],
)
def test_a_user_storys_role_and_the_askers_own_reason_ask_nothing(text):
    assert _read(text) == TWO_FREE


def test_a_role_or_reason_that_may_ask_something_stays():
    mention = re.compile("carrot|blue plate")
    for text in ("As a first step, I want it.", "As the carrot man, I want it.", "As a rule, put it there."):
        assert role_dropped(text, mention) == text  # an order word, a name, no "I want" after it
    assert _read(f"Put {PLACEMENTS} so that the kids can grab them.") is None  # a verb of taking


@pytest.mark.parametrize(
    "text",
    [
        f"The first thing to do is put {YELLOW}. The second thing, once that's done, is to put {BLUE}.",
        f"The first job is to put {YELLOW}. The second job, after the first one, is to put {BLUE}.",
        f"The first task is {YELLOW}. The next task is {BLUE}.",
    ],
)
def test_a_steps_turn_said_by_an_ordinal_noun(text):
    assert _read(text) == YELLOW_THEN_BLUE


def test_an_ordinal_noun_with_no_second_step_or_a_named_wait_stays_unread():
    assert _read(f"The first thing to do is put {PLACEMENTS}.") is None
    once = f"The first thing is {YELLOW}. The second thing, once the carrot is ready, is {BLUE}."
    assert _read(once) is None
    assert re.search("carrot", once)  # the aside names a thing: not read as a restated turn


@pytest.mark.parametrize(
    "text",
    [
        f"When the robot has put {YELLOW}, then it puts {BLUE}.",  # a test scenario's voice
        f"Once the robot has put {YELLOW}, it puts {BLUE}.",
    ],
)
def test_the_robot_named_as_the_one_who_places(text):
    assert _read(text) == YELLOW_THEN_BLUE


def test_it_is_the_robot_only_after_the_robot_is_named_and_before_a_verb_of_placing():
    assert robot_addressed("It puts A on P. The robot is ready.") == "It puts A on P. The robot is ready."
    assert robot_addressed("The robot is ready; it goes on P.") == "The robot is ready; it goes on P."
    assert robot_addressed("The robot will place A; it moves B.") == "You will place A; you move B."


@pytest.mark.parametrize(
    "text",
    [
        f"Put {YELLOW}. Having done that, put {BLUE}.",
        f"Put {YELLOW}. That done, put {BLUE}.",
        f"Put {YELLOW}. Once you've got that sorted, put {BLUE}.",
        f"Put {YELLOW}. Thereafter, {BLUE}.",
        f"Begin with {YELLOW} and end with {BLUE}.",
        f"Start off with {YELLOW}. Finish with {BLUE}.",
    ],
)
def test_a_clause_that_looks_back_on_the_step_before_orders_the_next(text):
    assert _read(text) == YELLOW_THEN_BLUE


def test_end_with_needs_a_begin_with_and_end_up_with_is_no_turn():
    assert turn_phrases_read("Finish with A.") == "Finish with A."
    end_state = "Start with A. P should end up with B."
    assert turn_phrases_read(end_state) == end_state
    assert _read(f"Put {PLACEMENTS}. That done, relax.") is None  # "then" with no step after it


THREE_FREE = ([("GreenApple", "PinkPlate"), ("Orange", "YellowPlate"), ("RedApple", "BluePlate")], [])


def test_a_list_in_brackets_after_words_that_name_nothing_is_the_list_asked_for():
    text = "chore: sort fruit (green apple -> pink plate, orange -> yellow plate, red apple -> blue plate)"
    assert _read(f"{text}, any order") == THREE_FREE
    assert _read("Put the carrot (the long one) on the blue plate.") == ([("Carrot", "BluePlate")], [])


def test_each_one_independent_of_the_others_frees_the_order_and_never_undoes_a_then():
    free = "green apple on pink plate, orange on yellow plate, red apple on blue plate - each one independent"
    assert _read(f"{free} of the others") == THREE_FREE
    then = "Put the carrot on the blue plate, then the orange on the yellow plate"
    assert _read(f"{then}, each one independent of the others") is None  # it frees no pair the "then" leaves


def test_keycap_emoji_numbers_are_a_lists_numbers():
    listed = "1️⃣ green apple ➡️ pink plate\n2️⃣ orange ➡️ yellow plate\n3️⃣ red apple ➡️ blue plate"
    assert _read(f"pls:\n{listed}\norder doesn't matter") == THREE_FREE
    steps = "1️⃣ green apple and orange ➡️ yellow plate\n2️⃣ carrot and red apple ➡️ blue plate"
    assert _read(steps) == YELLOW_THEN_BLUE  # numbered steps, as "1. ... 2. ..." are read
