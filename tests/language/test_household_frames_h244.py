"""The household reader drops frame by every reader's rule (issue 28, h244; `frame_drops`): a name, a
card's or note's label and a time set off from the request that orders nothing ("For Saturday: ...",
"Today, please.", "Shopping day tomorrow.", "..., by 5 please") are dropped, and each drop is said in the
result's assumptions; a fragment with an order word ("After Friday, ...") or a thing's name stays. The
dev set's lines (paper_h244dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"
REQUEST = "Put the egg in the fridge, then put the mug in the sink."


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    """(the tasks' summaries, the order, what is left unread, the assumptions)."""
    from trust_sets import world_of

    res = translate(text, world_of("FloorPlan28"), build=False, actions="none")
    return [t.summary() for t in res.tasks], sorted(res.before), res.unparsed, res.assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, dropped",
    [
        (f"For Saturday: {REQUEST} Love, Mum", "For Saturday"),
        (f"Shopping day tomorrow. {REQUEST}", "Shopping day tomorrow"),
        (f"{REQUEST} Today, please.", "Today, please"),
        (f"For Tuesday, {REQUEST[0].lower()}{REQUEST[1:]}", "For Tuesday"),
        (f"{REQUEST[:-1]}, by 5 please.", "by 5 please"),
    ],
)
def test_a_time_or_label_that_orders_nothing_is_dropped_and_said(text: str, dropped: str) -> None:
    tasks, before, unparsed, assumptions = read(text)
    assert (tasks, before, unparsed) == ([EGG, MUG], [("A", "B")], [])
    assert any("dropped as frame" in a and repr(dropped) in a for a in assumptions), assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, kept",
    [
        # an order word keeps the time: no task waits for an event or a time
        (f"Until tomorrow, {REQUEST[0].lower()}{REQUEST[1:]}", "until"),
        # (a deadline, "Before Friday, ...", is met by doing the tasks now since h258: a start time stays)
        ("Put the egg in the fridge. After Friday, put the mug in the sink.", "after"),
        # a thing's name keeps a label whose head is no heading's ("card": a credit card; h259 drops
        # "Prep card:", whose head is a document's word, test_heading_names_h259.py)
        (f"Card corner: {REQUEST[0].lower()}{REQUEST[1:]}", "card"),
    ],
)
def test_a_fragment_with_an_order_word_or_a_thing_stays(text: str, kept: str) -> None:
    _, _, unparsed, assumptions = read(text)
    assert any(kept in u.lower() for u in unparsed), unparsed
    assert not any("dropped as frame" in a for a in assumptions), assumptions


@pytest.mark.sweep
@pytest.mark.data
def test_h244_dev_set() -> None:
    """No line of h244's dev set is read wrong."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("paper_h244dev")]
    assert [gt.instruction for gt, what in rows if what == "wrong"] == []
