"""The time a household request is for (issues 28 and 23, h258; `request_times`): a deadline by a time, an
occasion or an outside event ("Before I'm back, ...", "By the time the kids get back, ...") is met by doing
the tasks now, and the result says so in its assumptions; a start time or a wait on an outside event
("Wait until I'm home, then ...", "At 5 pm, ...") is never read as done now: it is left unread, by name; a
remark on a past time ("Thanks again for last week. This time could you ...") is frame. The dev set's lines
(paper_h258dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"
REQUEST = "put the egg in the fridge, then put the mug in the sink."


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    """(the tasks' summaries, the order, what is left unread, the assumptions)."""
    from trust_sets import world_of

    res = translate(text, world_of("FloorPlan28"), build=False, actions="none")
    return [t.summary() for t in res.tasks], sorted(res.before), res.unparsed, res.assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, deadline",
    [
        (f"Before I'm back, {REQUEST}", "Before I'm back"),
        (f"By the time the kids get back, {REQUEST}", "By the time the kids get back"),
        (f"Quick one before the guests arrive: {REQUEST}", "Quick one before the guests arrive"),
    ],
)
def test_a_deadline_is_met_by_doing_the_tasks_now(text: str, deadline: str) -> None:
    tasks, before, unparsed, assumptions = read(text)
    assert (tasks, before, unparsed) == ([EGG, MUG], [("A", "B")], [])
    assert any(a.startswith("done now") and deadline in a for a in assumptions), assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, start",
    [
        (f"Wait until I'm home, then {REQUEST}", "wait until i'm home"),
        (f"At 5 pm, {REQUEST}", "at 5 pm"),
        (f"Once the guests leave, {REQUEST}", "the guests leave"),
    ],
)
def test_a_start_time_is_never_read_as_done_now(text: str, start: str) -> None:
    _, _, unparsed, assumptions = read(text)
    assert any(start in u.lower() for u in unparsed), unparsed
    assert not any(a.startswith("done now") for a in assumptions), assumptions


@pytest.mark.data
def test_a_remark_on_a_past_time_is_frame() -> None:
    tasks, before, unparsed, assumptions = read(f"Thanks again for last week. This time could you {REQUEST}")
    assert (tasks, before, unparsed) == ([EGG, MUG], [("A", "B")], [])
    assert any("dropped as frame" in a and "last week" in a for a in assumptions), assumptions


@pytest.mark.sweep
@pytest.mark.data
def test_h258_dev_set() -> None:
    """No line of h258's dev set is read wrong."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("paper_h258dev")]
    assert [gt.instruction for gt, what in rows if what == "wrong"] == []
