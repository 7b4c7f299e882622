"""Issue 28, new user voices (h147, tests/language/data/styles/users_h147dev.txt): a note to a robot
babysitter, a voice-assistant transcript, a to-do list of bullets, run-on sentences with "oh and". An
afterthought after "oh" takes no order from the clause before it, a call or a note's heading carries
nothing and a bullet says no order (a correction said again as a whole clause: test_self_corrections.py);
each with a near miss that must still be read or refused, never dropped."""

from __future__ import annotations

import pytest
from grammar_readings import Reading, sorted_reading

from nl2hltl2plan.language.courtesy import without_call, without_courtesy, without_greetings
from nl2hltl2plan.language.numbered_steps import bullets_apart, step_order

KITCHEN = {"Apple", "Egg", "Mug", "Cup", "Spoon", "Fridge", "Microwave", "CounterTop", "SinkBasin", "Drawer"}
EGG, MUG, APPLE = "place Egg -> Fridge", "place Mug -> SinkBasin", "place Apple -> Microwave"


def read(text: str) -> Reading:
    """The grammar's reading after the greetings and courtesy the translator removes first."""
    return sorted_reading(without_courtesy(without_greetings(text, lambda name: False)), KITCHEN)


@pytest.mark.parametrize(
    "text, order",
    [
        # an afterthought after "oh" is a request of its own: the apple is free of the then-chain
        ("put the egg in the fridge and then put the mug in the sink oh and put the apple in the microwave "
         "too", {(EGG, MUG)}),
        ("put the egg in the fridge, then the mug in the sink, oh, and also the apple in the microwave",
         {(EGG, MUG)}),
        # near miss: "and also" with no "oh" stays inside the "then" (both after the egg), as before
        ("put the egg in the fridge, then put the mug in the sink and also put the apple in the microwave",
         {(EGG, MUG), (EGG, APPLE)}),
    ],
)  # fmt: skip
def test_an_afterthought_takes_no_order_from_the_clause_before(text, order):
    assert read(text) == (sorted([APPLE, EGG, MUG]), order, [])


@pytest.mark.parametrize(
    "text",
    [
        "hey robot could you um put the egg in the fridge and then uh the mug in the sink",
        "okay so robot, uh, put the egg in the fridge and then the mug in the sink",
        "robot can you put the egg in the fridge and then the mug in the sink",
        "Robot: after you put the egg in the fridge, please put the mug in the sink.",
        "Note for the robot: the egg goes in the fridge. After that, the mug goes in the sink.",
        "so the egg needs to go in the fridge and after that put the mug in the sink",
        "grab the egg and put it in the fridge and then the mug in the sink",
    ],
)
def test_calls_headings_and_spoken_forms_carry_nothing(text):
    assert read(text) == ([EGG, MUG], {(EGG, MUG)}, [])


def test_near_misses_of_a_call_are_left_as_written():
    assert without_call("robot arms must not touch the mug") == "robot arms must not touch the mug"
    assert without_call("the robot put the egg away") == "the robot put the egg away"
    # "don't forget to" asks; "don't forget the mug" stays, to be read or refused; a reminder of a negation is
    # the negation (h200: it stayed, and was refused)
    assert without_courtesy("don't forget to put the egg in the fridge") == "put the egg in the fridge"
    assert "don't forget the mug" in without_courtesy("put the egg in the fridge, don't forget the mug")
    assert without_courtesy("don't forget to not put the mug in the sink") == "do not put the mug in the sink"
    # "oh" with no "and" / "also" after it is no afterthought ("oh no, the cup" is a correction)
    said = "put the egg in the fridge, oh no, the mug"
    assert without_courtesy(said) == said
    # an afterthought that opens a sentence is one already ("..". would end no sentence): before a verb it
    # is "At any time," (h200: "Oh, and look at the CD too" left "Oh" unread; an afterthought takes no order)
    said = "put the egg in the fridge. Oh and put the mug in the sink!"
    assert without_courtesy(said) == "put the egg in the fridge. At any time, put the mug in the sink!"


def test_a_pronoun_clause_restores_the_verb_only_where_each_thing_has_its_place():
    # "wash it and put it on the counter, then the mug": is the mug washed too? left to the rules' refusal
    tasks, _, unread = read("wash the egg and put it in the fridge and then the mug")
    assert unread or tasks != ["clean_place Egg -> Fridge", "place Mug -> Fridge"]


def test_bullets_are_sentences_in_no_order():
    assert bullets_apart("To do: - put the egg in the fridge - put the mug in the sink.") == (
        "To do: put the egg in the fridge. put the mug in the sink."
    )
    assert read(step_order("- egg in the fridge - mug in the sink")) == ([EGG, MUG], set(), [])
    # a dash inside a sentence opens no list; numbered steps keep their order
    assert bullets_apart("Robot - put the egg in the fridge") == "Robot - put the egg in the fridge"
    steps = "1) kitchen - put the egg away - wash the mug"
    assert bullets_apart(steps) == steps
    assert read(step_order("1. put the egg in the fridge 2. put the mug in the sink")) == (
        [EGG, MUG], {(EGG, MUG)}, [],
    )  # fmt: skip
