"""The tabletop reader's methods-section and support-agent wordings (issue 28, h106): "respectively" after a
passive duty, a "Method:" recipe whose steps a remark frees, "each item is to be placed on its plate:",
"after them" closing a clause, and an agent's "Sure!" / "No problem!" opening the text; with the refusals
each rule keeps."""

from __future__ import annotations

import pytest
from tabletop_readings import pairs_read as _reading

from nl2hltl2plan.language.tabletop_fields import fields_read

_TWO = ([("Carrot", "BluePlate"), ("Orange", "YellowPlate")], [])
_ORDERED = (
    [
        ("Carrot", "BluePlate"),
        ("GreenApple", "YellowPlate"),
        ("Orange", "YellowPlate"),
        ("RedApple", "BluePlate"),
    ],
    sorted(
        (a, b)
        for a in [("GreenApple", "YellowPlate"), ("Orange", "YellowPlate")]
        for b in [("Carrot", "BluePlate"), ("RedApple", "BluePlate")]
    ),
)




@pytest.mark.parametrize(
    "text",
    [
        "The carrot and the orange are to be placed on the blue and yellow plates respectively.",
        "The carrot and the orange should be set on the blue and yellow plates, respectively, in no "
        "prescribed order.",
    ],
)
def test_respectively_after_a_passive_duty_pairs_in_turn(text):
    assert _reading(text) == _TWO


def test_respectively_after_a_state_is_no_request():
    assert _reading("The carrot and the orange are on the blue and yellow plates respectively.") is None


@pytest.mark.parametrize(
    "text",
    [
        "Method: 1. Carrot onto the blue plate. 2. Orange onto the yellow plate. Either step may come first.",
        "Method: Step 1 - carrot onto the blue plate. Step 2 - orange onto the yellow plate. The steps may "
        "be done in any order.",
    ],
)
def test_a_method_whose_steps_a_remark_frees_is_unordered(text):
    assert _reading(text) == _TWO


def test_a_method_with_no_remark_keeps_its_steps_in_turn():
    text = "Method: Step 1 - carrot onto the blue plate. Step 2 - orange onto the yellow plate."
    assert _reading(text) == (_TWO[0], [(("Carrot", "BluePlate"), ("Orange", "YellowPlate"))])


def test_a_remark_beside_steps_of_two_placements_does_not_free_the_steps():
    # "in any order" may free the order within each step only: the steps stay in turn
    text = (
        "Step 1: the green apple and the orange on the yellow plate. Step 2: the carrot and the red apple on "
        "the blue plate. In any order."
    )
    assert _reading(text) == _ORDERED


def test_each_item_on_its_plate_is_the_list_after_it():
    text = (
        "Each item is to be placed on its plate: first the green apple and the orange on the yellow one, "
        "then the carrot and the red apple on the blue one."
    )
    assert _reading(text) == _ORDERED
    reversed_order = "Each item is to be placed on its plate in reverse order: the carrot on the blue one."
    assert _reading(reversed_order) is None


def test_after_them_closing_a_clause_orders_it_after_the_one_before():
    text = (
        "The green apple and the orange are to be placed on the yellow plate first, and the carrot and the "
        "red apple on the blue plate after them."
    )
    assert _reading(text) == _ORDERED


@pytest.mark.parametrize("opening", ["Sure!", "No problem!", "Of course!", "Absolutely,", "No worries."])
def test_an_agents_reply_opening_the_text_asks_nothing(opening):
    assert _reading(f"{opening} Put the carrot on the blue plate and the orange on the yellow plate.") == _TWO


def test_a_reply_with_a_negation_after_it_is_not_dropped():
    assert _reading("Of course not! Put the carrot on the blue plate.") is None


@pytest.mark.parametrize(
    ("label", "free"),
    [
        ("Order: any.", True),
        ("Order: whatever.", True),
        ("Order: in any order.", True),
        ("Order: reverse.", False),
    ],
)
def test_an_order_label_is_free_where_the_shared_list_says_so(label, free):
    kinds = {"carrot": False, "blue plate": True}
    read = fields_read(f"Carrot on the blue plate. {label}", kinds)
    assert ("In any order" in read) is free


@pytest.mark.parametrize(
    "remark", ["(steps may be performed in any order)", "order not prescribed", "the order is not imposed"]
)
def test_a_freedom_said_with_a_verb_of_doing_or_not_prescribed_frees_the_list(remark):
    assert _reading(f"Carrot onto the blue plate, orange onto the yellow plate, {remark}.") == _TWO


@pytest.mark.parametrize(
    "text",
    [
        "The carrot and the orange are respectively to be placed on the blue and yellow plates.",
        "Respectively, the carrot and the orange go on the blue and yellow plates.",
        "The carrot and the orange are to be transferred to the blue and yellow plates respectively; no "
        "order is prescribed.",
        "No problem at all! Put the carrot on the blue plate and the orange on the yellow plate.",
        "Each of the two fruits is to be placed on its plate: the carrot on the blue one, the orange on the "
        "yellow one.",
    ],
)
def test_more_methods_and_replies_wordings(text):
    assert _reading(text) == _TWO


def test_a_count_after_each_of_the_must_be_the_placements_listed():
    text = "Each of the three fruits is to be placed on its plate: the carrot on the blue one, the orange on "
    assert _reading(text + "the yellow one.") is None


def test_first_and_then_inside_a_passive_duty_order_its_clauses():
    text = (
        "The green apple and the orange are first to be placed on the yellow plate; the carrot and the red "
        "apple are then to be placed on the blue plate."
    )
    assert _reading(text) == _ORDERED


def test_questions_and_answers_read_as_the_instruction_they_state():
    # the shared `headings.answered` runs in the tabletop reader too
    text = "Q: Where does the carrot go? A: On the blue plate. Q: And the orange? A: The yellow plate."
    assert _reading(text) == _TWO
    ordered = text + " Q: Order? A: Carrot first."
    assert _reading(ordered) == (_TWO[0], [(("Carrot", "BluePlate"), ("Orange", "YellowPlate"))])
    # an answer that says nothing certain is refused, never guessed
    unsure = "Q: Where does the carrot go? A: Not sure. Q: And the orange? A: The yellow plate."
    assert _reading(unsure) is None
