"""Headings whose words are taken for things (issues 28 and 23, h259; `headings.heading_dropped`): a note's
heading whose head is a word for a document, a list, an activity or a time ("Prep card:", "Lamp game:",
"Kitchen bingo!", "Fridge duty.") names no task and is dropped, said in the assumptions; a count in it is
checked against the reading, and a heading with another head, a verb or a thing's whole name stays to be
read or refused as before. The dev set's lines (users_h259dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"
REQUEST = "put the egg in the fridge and put the mug in the sink."


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    """(the tasks' summaries, the order, what is left unread, the assumptions)."""
    from trust_sets import world_of

    res = translate(text, world_of("FloorPlan28"), build=False, actions="none")
    return [t.summary() for t in res.tasks], sorted(res.before), res.unparsed, res.assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, heading",
    [
        (f"Prep card: {REQUEST}", "Prep card"),  # 'card' names a credit card elsewhere
        (f"Mug game: {REQUEST}", "Mug game"),  # the heading's thing is one a task uses
        (f"Kitchen bingo! {REQUEST.capitalize()}", "Kitchen bingo"),
        (f"Fridge duty. {REQUEST.capitalize()}", "Fridge duty"),
        (f"Two jobs, any order: {REQUEST}", "Two jobs, any order"),
    ],
)
def test_a_heading_named_by_a_thing_is_dropped_and_said(text: str, heading: str) -> None:
    tasks, before, unparsed, assumptions = read(text)
    assert (tasks, before, unparsed) == ([EGG, MUG], [], [])
    assert any("read as a heading" in a and repr(heading) in a for a in assumptions), assumptions


@pytest.mark.data
def test_a_heading_count_that_does_not_match_is_refused_by_name() -> None:
    _, _, unparsed, _ = read(f"Three jobs, any order: {REQUEST}")
    assert any("'Three jobs' (count)" in u for u in unparsed), unparsed


@pytest.mark.data
@pytest.mark.parametrize(
    "text, kept",
    [
        (f"Card corner: {REQUEST}", "card"),  # 'corner' is no heading's head: the card stays unread
        (f"Lamp spot: {REQUEST}", "lamp"),
    ],
)
def test_a_thing_before_another_head_stays_unread(text: str, kept: str) -> None:
    _, _, unparsed, assumptions = read(text)
    assert any(kept in u.lower() for u in unparsed), unparsed
    assert not any("read as a heading" in a for a in assumptions), assumptions


def test_headings_with_a_verb_an_order_or_a_things_name_are_kept() -> None:
    from nl2hltl2plan.language.headings import heading_dropped

    kept = ("Chill time: chill the egg.", "Jobs in order: put ...", "Credit card: look at it.", "Task: put")
    for text in kept:
        dropped: list[str] = []
        assert heading_dropped(text, dropped) == text and dropped == []


@pytest.mark.sweep
@pytest.mark.data
def test_h259_dev_set() -> None:
    """Every line of h259's dev set converts."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("users_h259dev")]
    assert [gt.instruction for gt, what in rows if what != "converted"] == []
