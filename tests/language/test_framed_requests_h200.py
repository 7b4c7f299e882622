"""Household requests wrapped in framing (issues 23 and 28, h200): a reminder is the request it reminds of
("remember to put ...", "make sure you heat ...") and a reminder of a negation is the negation ("remember not
to put ...": a constraint, never a request); a request passed on ("Mom says put ..."), a "P.S.", a wish
frame ("It'd be great if you could ...", "I was hoping you could ...") and a wished state ("it would be
great if both mugs were in the sink") are read as the request; "if you get a chance" and "no rush" free
nothing and order nothing. The dev set's lines (users_h200dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.courtesy import without_courtesy, without_framing

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    from trust_sets import world_of

    return full_reading(text, world_of("FloorPlan28"))


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks, before",
    [
        # a reminder with "you" left "you heat", which lost the heating and gained an order (wrong at exit 0)
        ("Put the egg in the fridge. Make sure you heat the mug and put it in the sink.",
         [EGG, "heat_place Mug -> SinkBasin"], []),
        # a relayed request: "mom" was read as a person to hand things to
        ("Mom says put the egg in the fridge, then put the mug in the sink.", [EGG, MUG], [(EGG, MUG)]),
        # "if you get a chance" was read as a condition; "P.S." was left unread
        ("If you get a chance, put the egg in the fridge. P.S. the mug goes in the sink.", [EGG, MUG], []),
        # a wish frame and a wished state: their "if" was refused as a condition
        ("It'd be great if you could put the egg in the fridge. It would be great if the mug was in the "
         "sink.", [EGG, MUG], []),
    ],
)  # fmt: skip
def test_framing_reads_as_the_request(text, tasks, before):
    got, order, unread, forbids = read(text)
    names = dict(zip(["A", "B"], got, strict=False))
    assert (sorted(got), [(names[a], names[b]) for a, b in order], unread, forbids) == (
        sorted(tasks),
        before,
        [],
        [],
    )


@pytest.mark.data
def test_a_reminder_of_a_negation_is_the_negation():
    """ "remember not to put the mug in the sink" forbids it (it was refused), and alone asks nothing."""
    got, _, unread, forbids = read("Remember not to put the mug in the sink, but put the egg in the fridge.")
    assert (got, unread) == ([EGG], [])
    assert forbids == ["do not put the mug in the sink: forbids put(Mug,SinkBasin)"]
    with pytest.raises(HTTError, match="nothing to do"):
        read("Make sure you never put the mug in the sink.")


def test_near_misses_stay_as_written():
    """A goal after "make sure" is the goal's own rule's (`grammar/restated`); a name's "Mom's" and a wish
    for anything but a request stay, to be read or refused by name."""
    said = "make sure the mug ends up in the sink"
    assert without_courtesy(said) == said
    assert without_framing("Mom's mug goes in the sink.") == "Mom's mug goes in the sink."
    assert without_framing("It would be great if it rained.") == "It would be great if it rained."


@pytest.mark.sweep
@pytest.mark.data
def test_h200_dev_set():
    """No line of h200's dev set is read wrong, every line to refuse is refused or partial, and every
    feasible line converts."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("users_h200dev")]
    assert [gt.instruction for gt, what in rows if what == "wrong"] == []
    assert [gt.instruction for gt, what in rows if not gt.feasible and what == "converted"] == []
    assert all(what == "converted" for gt, what in rows if gt.feasible)
