"""Issue 23 (h313): trust_h303's leftovers after the session-35 merges, as classes, through `translate`.
A cyclic order said with ", but" after a state reference is named as the cycle (the reference used to run
on into the next command and be refused as an unclear referent); "Repeat." as a sentence of its own is
named as a repetition, never dropped; the pieces of a cut into two taken together ("put both in the
fridge") are two slices, while a cut into three keeps its "both" named; a set line's `xN` count is every
instance of its world."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


Reading = tuple[list[str], list[tuple[str, str]], list[str], list[str]]


def read(text: str, plan: str = "FloorPlan28") -> Reading:
    from trust_sets import world_of

    return full_reading(text, world_of(plan))


def refusal(text: str, plan: str = "FloorPlan28") -> str:
    """The error's message, or "" where the text is read (partial or not)."""
    from nl2hltl2plan.errors import Nl2Hltl2PlanError

    try:
        read(text, plan)
    except Nl2Hltl2PlanError as exc:
        return str(exc)
    return ""


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "put the apple in the fridge after the bread is on the table, but put the bread on the table after "
        "the apple is in the fridge",
        "put the apple in the fridge once the bread is on the table, but put the bread on the table only "
        "after the apple is in the fridge",
    ],
)
def test_a_cycle_said_with_but_is_named_as_the_cycle(text: str) -> None:
    said = refusal(text)
    assert "contradictory ordering" in said and "before" in said, said


@pytest.mark.data
def test_a_command_after_but_that_names_no_thing_stays_the_clause_s_own() -> None:
    # "but put it there carefully" says how, of the clause itself: read as at base, the bread first
    text = "put the apple in the fridge after the bread is on the counter, but put it there carefully"
    tasks, order, unread, _ = read(text)
    assert tasks == ["place Apple -> Fridge", "place Bread -> CounterTop"] and order == [("B", "A")], unread


@pytest.mark.data
def test_a_new_command_after_but_keeps_the_reference_s_order() -> None:
    text = "put the apple in the fridge after the bread is on the counter, but put the egg in the sink"
    tasks, order, unread, _ = read(text)
    assert sorted(tasks) == ["place Apple -> Fridge", "place Bread -> CounterTop", "place Egg -> SinkBasin"]
    assert len(order) == 1 and not unread, (order, unread)


@pytest.mark.data
def test_repeat_as_a_sentence_of_its_own_is_named() -> None:
    _, _, unread, _ = read("Put the apple in the fridge. Repeat.")
    assert any("'repeat'" in u and "(count)" in u for u in unread), unread


@pytest.mark.data
def test_repeat_with_another_thing_is_still_a_task_for_it() -> None:
    tasks, _, unread, _ = read("Put the apple in the fridge. Repeat with the tomato.")
    assert tasks == ["place Apple -> Fridge", "place Tomato -> Fridge"] and not unread, unread


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "cut the bread into two slices and put both in the fridge",
        "cut the bread into two slices and put them in the fridge",
    ],
)
def test_the_two_pieces_of_a_cut_taken_together_are_two_slices(text: str) -> None:
    tasks, _, unread, _ = read(text)
    assert tasks == ["place_two 2x Bread(sliced) -> Fridge"] and not unread, (tasks, unread)


@pytest.mark.data
def test_both_after_a_cut_into_three_is_still_named() -> None:
    _, _, unread, _ = read("cut the bread into three slices and put both in the fridge")
    assert any("'into three slices'" in u for u in unread), unread


@pytest.mark.data
def test_a_count_above_two_in_a_set_line_is_every_instance_of_its_world() -> None:
    from trust_sets import check_counts, parse_line

    line = "FloorPlan301 | put all the watches in the drawer | place_two Watch Drawer x{} |"
    row = parse_line(line.format(4), "t", 1)
    check_counts(row)  # FloorPlan301's default world holds 4 watches
    assert row["tasks"][0]["count"] == 4
    with pytest.raises(ValueError, match="x3 is not every instance"):
        check_counts(parse_line(line.format(3), "t", 1))
    tasks, _, unread, _ = read("put all the watches in the drawer", "FloorPlan301")
    assert tasks == ["place_two 4x Watch -> Drawer"] and not unread, (tasks, unread)


@pytest.mark.data
@pytest.mark.parametrize("text", ["put every single candle on the counter",
    "put every last candle on the counter"])
def test_every_single_is_every_instance(text: str) -> None:
    # found by the held probe (read as one candle at exit 0): the stressing word counts nothing
    tasks, _, unread, _ = read(text, "FloorPlan426")
    assert tasks == ["place_two 3x Candle -> CounterTop"] and not unread, (tasks, unread)
