"""Issue 28, one treatment or two said for two things, each thing's place said after them, or one place for
both (h247, `grammar/treated_lists.py`; paper_h231's split treatments, users_h247dev.txt): before, "Chill a
mug and wash a plate. The mug goes on ..." read each treatment as a task of its own ("a thing treated in one
task and moved in another"), "..., and put both on the side table" gave one of them no place, and "Heat two
mugs: one goes on ..., the other in ..." was refused. Words that do not give each thing one place are left."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.grammar.treated_lists import treated_lists
from nl2hltl2plan.language.translate import translate


@pytest.mark.parametrize(
    "text, rewritten",
    [
        ("Chill a mug and wash a plate. The mug goes on the coffee maker and the plate in the microwave.",
         "Chill a mug and put it on the coffee maker, wash a plate and put it in the microwave."),
        ("Wash a slice of lettuce and heat a tomato, and put both on the side table.",
         "Wash a slice of lettuce and put it on the side table, heat a tomato and put it on the side table."),
        ("Chill a plate and heat a mug: plate on the shelf, mug on the coffee maker.",
         "Chill a plate and put it on the shelf, heat a mug and put it on the coffee maker."),
        ("After that, heat a tomato slice and an apple - the slice goes in the sink and the apple in the "
         "fridge.",
         "After that, heat a tomato slice and put it in the sink, heat an apple and put it in the fridge."),
        ("Chill a plate and a potato, then put the former in the cabinet and the latter on the white table.",
         "Chill a plate and put it in the cabinet, chill a potato and put it on the white table."),
        ("Heat two mugs: one goes on the coffee maker, the other in a cabinet.",
         "Heat a mug and put it on the coffee maker, heat another mug and put it in a cabinet."),
    ],
)  # fmt: skip
def test_places_said_after_the_things_are_given_to_each(text, rewritten):
    assert treated_lists(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "Chill a mug and wash a plate: the mug goes on the coffee maker.",  # the plate has no place
        "Chill a mug and wash a plate. The cup goes on the shelf, the plate in the sink.",  # "cup" is no item
        "Chill a mug and wash a plate, and put it on the counter.",  # "it" is one of them
        "Put a mug in the sink and wash a plate, and put both on the counter.",  # "put" is no treatment
        "Heat two slices of bread - one on the plate and the other in the bin.",  # "slices" names no kind
        "Wash a mug, a plate and a cup, then put the former in the sink and the latter on the table.",  # 3
    ],
)
def test_words_that_give_no_thing_one_place_are_left(text):
    assert treated_lists(text) == text


@pytest.mark.data
def test_read_in_a_kitchen():
    """Main read the split as four tasks and the shared place as one task's only."""
    from nl2hltl2plan.worlds import load_world

    text = "Chill a potato and heat an apple slice, and put them both on the counter."
    try:
        res = translate(text, load_world("FloorPlan7"), "offline", build=False, actions="none")
    except Nl2Hltl2PlanError as exc:
        pytest.fail(str(exc))
    assert not res.partial
    assert [t.summary() for t in res.tasks] == [
        "cool_place Potato -> CounterTop", "heat_place Apple(sliced) -> CounterTop"
    ]  # fmt: skip


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize("name, least", [("users_h247dev", 24), ("users_h247held", 0)])
def test_the_h247_sets_read_nothing_wrong(name, least):
    """h247's lines, read as `plan` reads them: nothing read wrong, and at least `least` converted."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load(name)]
    assert [gt.instruction for gt, what in outcomes if what == "wrong"] == []
    assert sum(what == "converted" for _, what in outcomes) >= least
