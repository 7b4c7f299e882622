"""Issue 28, a treatment said once for several things, said as an outcome, or said after its thing (h204,
`grammar/treated_lists.py`; paper_h189 and paper_h204dev.txt): before, each of these was refused or left
partial ("Chill these in the fridge ...: a potato slice in the bin, ...": "no object to act on"). The same
words where something is not a name, or where no place is said, are left as they were."""

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
        ("Chill these in the fridge and then put them away: an egg in the microwave and a potato slice in "
         "the bin.",
         "Chill an egg and put it in the microwave, chill a potato slice and put it in the bin."),
        ("After that, warm these up and set them on the table: a plate and a mug.",
         "After that, warm a plate and put it on the table and warm a mug and put it on the table."),
        ("Make sure the pan gets washed and left on the counter once that's done.",
         "Once that's done, wash the pan and put it on the counter."),
        ("make sure the mug and the bowl get chilled and end up in the sink",
         "chill the mug and the bowl and put them in the sink"),
        ("I'd like a cup heated in the microwave and left on the shelf",
         "I'd like a heated cup on the shelf"),
        ("Next, a slice of potato: heat it up and drop it in the sink.",
         "Next, heat up a slice of potato and drop it in the sink."),
        ("rinse out a bowl and leave it on the counter and a glass in the cupboard",
         "rinse out a bowl and leave it on the counter, and rinse a glass and leave it in the cupboard"),
    ],
)  # fmt: skip
def test_treatments_said_once_or_as_outcomes_are_rewritten(text, rewritten):
    assert treated_lists(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "Chill these in the fridge: an egg in the microwave and a potato in the bin.",  # no placement said
        "Chill these and put them away: the idea in the bin and a potato in the bin.",  # "idea" names nothing
        "Chill these and put them away: an egg.",  # one item is no list
        "the pan gets washed and left on the counter",  # an outcome only after "make sure"
        "Make sure the plate is washed.",  # no place
        "Make sure the pan on the stove gets hot and left on the counter.",  # "hot" is no participle
        "the idea: heat it up",  # names nothing
    ],
)
def test_the_same_words_asking_nothing_more_are_left(text):
    assert treated_lists(text) == text


def _read(text: str, world) -> tuple[list[str], list[tuple[str, str]]] | str:
    try:
        res = translate(text, world, "offline", build=False, actions="none")
    except Nl2Hltl2PlanError:
        return "refused"
    return "partial" if res.partial else ([t.summary() for t in res.tasks], sorted(res.before))


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan7")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        # main: partial ("no object to act on in: Chill these in the fridge")
        ("Chill these in the fridge, then put them away: a potato slice in the bin and an egg in the sink.",
         (["cool_place Potato(sliced) -> GarbageCan", "cool_place Egg -> SinkBasin"], [])),
        # main: refused ("'washed' (action): no clean_place task")
        ("Make sure the bowl gets washed and left on the shelf, and the cup gets heated and put on the "
         "table.",
         (["clean_place Bowl -> Shelf", "heat_place Cup -> DiningTable"], [])),
        # main: partial ("Do the tomato first; Do the fork")
        ("I'd like a bowl washed and left on the shelf, a chilled egg in the sink and a cup heated and put "
         "on the table. Do the egg first and the cup last.",
         (["clean_place Bowl -> Shelf", "cool_place Egg -> SinkBasin", "heat_place Cup -> DiningTable"],
          [("A", "C"), ("B", "A")])),  # B<C follows
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert _read(text, kitchen) == read


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize("name, least", [("paper_h204dev", 22), ("paper_h204held", 12)])
def test_the_h204_sets_read_nothing_wrong(name, least):
    """h204's lines, read as `plan` reads them: nothing read wrong, and at least `least` converted."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load(name)]
    assert [gt.instruction for gt, what in outcomes if what == "wrong"] == []
    assert sum(what == "converted" for _, what in outcomes) >= least
