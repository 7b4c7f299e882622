"""Issue 28, everyday wordings that were refused (h173, `grammar/treatments_said.py`): a treatment said as a
need ("the plate needs a wash"), a causative ("get the potato sliced"), a terse order ("mug first, then
the bowl"), and a self-correction after "wait," or "nah"; the same words where nothing is asked (a
negation, a condition, no subject) are left, and refused."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import outcome

from nl2hltl2plan.language.grammar.treatments_said import treatments_said


@pytest.mark.parametrize(
    "text, rewritten",
    [
        ("the plate needs a wash before it goes in the cabinet",
         "wash the plate before it goes in the cabinet"),
        ("the bowl needs a good clean, then put it in the fridge",
         "clean the bowl, then put it in the fridge"),
        ("that potato needs warming up and then", "warm the potato and then"),
        ("the apple needs to be chilled", "chill the apple"),
        ("the plate needs to get washed", "wash the plate"),
        ("have the bread cut up and put a slice in the fridge",
         "cut the bread and put a slice in the fridge"),
        ("get the potato sliced", "slice the potato"),
        ("have the robot slice the bread", "slice the bread"),
        ("get someone to wash the plate", "wash the plate"),
        ("wash the plate, it should end up in the cabinet", "wash the plate, put it in the cabinet"),
        ("id like the bread on the counter", "I'd like the bread on the counter"),
        ("the apple in the fridge and the bread on the counter, the bread first pls",
         "the apple in the fridge and the bread on the counter, the bread first"),
        ("the apple in the fridge and the bread on the counter. bread first",
         "the apple in the fridge and the bread on the counter. the bread first"),
        ("put the mug and the bowl in the sink, mug first, then the bowl",
         "put the mug and the bowl in the sink, the mug before the bowl"),
        ("put the mug and the bowl in the sink, first the mug, then the bowl",
         "put the mug and the bowl in the sink, the mug before the bowl"),
    ],
)  # fmt: skip
def test_needs_causatives_and_terse_orders_are_rewritten(text, rewritten):
    assert treatments_said(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "the plate doesn't need a wash",  # a negation: no subject right before the need
        "if the plate needs a wash, put it in the sink",  # a condition
        "does the plate need a wash",
        "the plate needs a spot on the shelf",  # not a treatment
        "have the knife and the bread",  # no participle: a possession
        "get the washed mug",
        "have the robot the mug",  # no verb after the robot
        "the idea needs a wash",  # no name the lexicon knows
        "it should end up in the cabinet",  # "it" stands for nothing said before
        "wash the plate, it should end up somewhere",  # no place
        # three placements: "then the apple" also orders the apple before the bread
        "put the apple in the fridge, the bread on the counter and the egg in the microwave, the egg first, "
        "then the apple",
    ],
)
def test_the_same_words_asking_nothing_are_left(text):
    assert treatments_said(text) == text


def test_an_order_naming_a_thing_in_no_placement_orders_nothing():
    """ "then the bread": the bread is in no placement, so "mug first" stays a "first" of its own."""
    said = "put the mug and the bowl in the sink, mug first, then the bread"
    assert treatments_said(said) == "put the mug and the bowl in the sink, the mug first, then the bread"


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan7")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        ("put the apple in the fridge... wait, the microwave", ["place Apple -> Microwave"]),
        ("put the pan on the stove.. nah, the counter", ["place Pan -> CounterTop"]),
        ("get the potato sliced", ["set_state Potato sliced"]),
        ("the apple needs to be chilled and then put it on the counter", ["cool_place Apple -> CounterTop"]),
        # main read "the cup first, then the plate" as a third placement (of the cup again)
        ("put the cup and the plate in the sink. cup first then the plate",
         ["place Cup -> SinkBasin", "place Plate -> SinkBasin"]),
        ("put the pan on the stove... no, wait", "refused"),  # the correction names nothing
        ("the plate doesn't need a wash", "refused"),
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert outcome(text, kitchen) == read


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h173dev", "users_h173held"])
def test_the_h173_user_set_reads_nothing_wrong(name):
    """h173's lines, read as `plan` reads them: nothing read wrong, and each line converted or, where its
    ground truth says so, refused (or left partial)."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load(name)]
    assert [gt.instruction for gt, what in outcomes if what == "wrong"] == []
    right = sum(what == "converted" if gt.feasible else what != "converted" for gt, what in outcomes)
    assert right >= 30
