"""Issue 28 (h260): a request said in the passive with its place said as where the thing goes ("the bowl
wants chilling and then goes on the shelf", "the soap gets rinsed and ends up on the toilet"), as a passive
question ("can the spoon be washed and put on the table?"), hedged ("do you think you could ...", "any
chance you could ...", `courtesy.txt`), or as a checklist item whose state follows its thing ("lettuce,
chilled -> table"). A question that asks nothing to be done stays a refusal that says so."""

from __future__ import annotations

import pytest
from household_readings import outcome

from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grammar.treatments_said import treatments_said
from nl2hltl2plan.worlds import load_world


@pytest.mark.parametrize(
    "text, rewritten",
    [
        ("the bowl wants chilling and then goes on the shelf", "chill the bowl and put it on the shelf"),
        ("the soap gets rinsed and ends up on the toilet", "rinse the soap and put it on the toilet"),
        ("can the spoon be washed and put on the table?", "wash the spoon and put it on the table?"),
        ("first the tomato is to be chilled", "first chill the tomato"),
        ("another mug should be heated and go back in the cabinet",
         "heat another mug and put it back in the cabinet"),
    ],
)  # fmt: skip
def test_passive_requests_and_their_places_are_rewritten(text, rewritten):
    assert treatments_said(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "can the idea be washed and put away?",  # no name the lexicon knows
        "the mug goes on the shelf",  # no treatment: the grammar reads the placing itself
        "can the mug be on the shelf?",  # a state, no treatment
    ],
)
def test_the_same_words_asking_no_treatment_are_left(text):
    assert treatments_said(text) == text


def test_a_state_after_a_checklist_thing_goes_before_it():
    assert everyday("lettuce, chilled -> table") == "chilled lettuce onto table"
    assert "idea, chilled" in everyday("the idea, chilled -> table")  # no name: left


@pytest.fixture(scope="module")
def kitchen():
    return load_world("FloorPlan7")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        ("Can the apple be chilled and put on the counter?", ["cool_place Apple -> CounterTop"]),
        ("Any chance you could heat a mug and leave it on the coffee maker?",
         ["heat_place Mug -> CoffeeMachine"]),
        ("Do you think you could wash a bowl and put it on a shelf?", ["clean_place Bowl -> Shelf"]),
        ("The pan needs washing and ends up on the counter.", ["clean_place Pan -> CounterTop"]),
        ("Is the mug clean?", "refused"),  # a question, not a request
        ("Where is the mug?", "refused"),
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert outcome(text, kitchen) == read
