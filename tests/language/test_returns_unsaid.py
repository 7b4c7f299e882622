"""Issue 23 (h140): a return whose place no source names ("return it", "put it back where it was") and a
thing said after a source and "and" ("the apple from the counter and the egg ...") are named by check 1,
whatever reading a backend made; the sentences of users_h140dev.txt read as their ground truth says."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar.put_back import put_back_where_taken
from nl2hltl2plan.language.task_specs import BaseTaskSpec

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


def place(obj: str, where: str, task_id: str = "A", kind: str = "place") -> BaseTaskSpec:
    return BaseTaskSpec(id=task_id, kind=kind, object=[obj], receptacle=[where], text="")


MUG_IN_SINK = [place("Mug", "SinkBasin")]


@pytest.mark.parametrize(
    "text, unread",
    [
        ("put the mug in the sink and then return it", ["return it"]),
        ("put the mug in the sink, then return them later", ["return them", "later"]),  # "later": h282
        ("put the mug in the sink, then put it back where it was", ["back where it was"]),
        ("put the mug in the sink and put it back where it came from", ["back where it came from"]),
        ("put the mug in the sink, then put it back in its usual place", ["back in its usual place"]),
        ("put the mug in the sink and then bring it back", ["back"]),
        # a place said after the return, or no return at all: nothing to name
        ("put the mug in the sink and then return it to the sink", []),
        ("put the mug in the sink", []),
    ],
)
def test_a_return_whose_place_no_source_names_is_named(text, unread):
    assert [u.words for u in account(text, MUG_IN_SINK, [])] == unread


def test_a_return_to_the_one_source_a_task_fills_is_read():
    tasks = [place("Mug", "Cabinet", kind="clean_place")]
    assert account("take the mug from the cabinet, rinse it, then return it", tasks, []) == []


@pytest.mark.parametrize(
    "text",
    [
        "take the apple from the counter and the egg out of the fridge and put them back",
        "take the apple from the counter and the egg out of the fridge",
        "grab the apple off the counter or the egg",
    ],
)
def test_a_thing_after_a_source_and_and_is_not_from_that_source(text):
    """The egg is not "from the counter": the scan for its preposition stops at "and" / "or"."""
    assert "egg" in [u.words for u in account(text, [place("Apple", "CounterTop")], [])]


def test_a_bare_place_after_a_source_and_and_shares_its_source():
    # "from the sink and table": both are where the spoons come from; "and the X" opens a thing of its own
    text = "pick up the spoons from the sink and table, put them both on the counter"
    assert account(text, [place("Spoon", "CounterTop", kind="place_two")], []) == []


def test_a_place_between_two_others_is_still_where_a_thing_is():
    """ "between the sink and the stove": the stove's preposition is the sink's (`landmarks.pair_start`)."""
    text = "put the mug on the counter between the sink and the stove"
    assert account(text, [place("Mug", "CounterTop")], []) == []


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h140dev", "users_h140held"])
def test_the_return_sets_read_no_line_wrong(name):
    import trust_sets

    gts = trust_sets.load(name)
    outcomes = {gt.instruction: trust_sets.outcome(gt)[0] for gt in gts}
    assert [t for t, what in outcomes.items() if what == "wrong"] == []
    assert len(gts) >= 12
    assert all(outcomes[gt.instruction] == "converted" for gt in gts if gt.feasible)



@pytest.mark.parametrize(
    "text, back",
    [
        (
            "take the apple from the counter and the egg out of the fridge and put them back",
            "put the apple back in the counter and put the egg back in the fridge",
        ),
        (
            "please grab the mug off the table, the cup from the sink and return them",
            "please put the mug back in the table and put the cup back in the sink",
        ),
        # as the grammar's normalizing gathers a "take ... and put them back"
        (
            "put the apple from the counter and the egg out of the fridge back",
            "put the apple back in the counter and put the egg back in the fridge",
        ),
    ],
)
def test_things_taken_each_from_its_place_and_returned_go_back_each_to_its_own(text, back):
    assert put_back_where_taken(text) == back


@pytest.mark.parametrize(
    "text",
    [
        "take the apple from the counter and the egg out of the fridge, wash them and put them back",
        "take the apple from the counter and the egg out of the fridge and put it back",  # "it": which one
        "take the apple from the counter and the apple from the fridge and put them back",  # one type, two
    ],
)
def test_a_return_the_sources_cannot_pair_with_their_things_is_left_as_written(text):
    assert put_back_where_taken(text) == text


@pytest.mark.parametrize(
    "text, unread",
    [
        ("put the mug in the sink and then return the mug", ["return the mug"]),
        ("put the mug in the sink and return both", ["return both"]),
        ("put the mug in the sink and put it back after", ["back"]),
        ("put the mug in the sink and then return it please", ["return it"]),
        # the place is said after the things: nothing to name
        ("put the mug in the sink and then return the mug and the cup to the sink", ["cup"]),
    ],
)
def test_a_return_of_a_named_thing_whose_place_no_source_names_is_named(text, unread):
    assert [u.words for u in account(text, MUG_IN_SINK, [])] == unread
