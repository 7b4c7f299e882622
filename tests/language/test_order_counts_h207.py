"""Order words and counts read wrong at exit 0 (issue 23, h207): a "last" / "finally" on a step that "then"
follows, two opening "first"s, a "first" no step takes, "A finally, and B", "two of the three cups",
"both of the three cups", "all of the mugs but one". Each reads right, or names the words unread."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

from nl2hltl2plan.errors import HTTError

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    from trust_sets import world_of

    return full_reading(text, world_of("FloorPlan28"))


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "Last the egg goes in the fridge, then the mug goes in the sink",  # the egg was first, 'last' lost
        "Finally put the egg in the fridge, then put the mug in the sink",
    ],
)
def test_a_leading_last_that_then_follows_is_a_cycle_refused(text):
    with pytest.raises(HTTError, match="contradictory ordering"):
        read(text)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, unread",
    [
        ("First put the egg in the fridge, first put the mug in the sink", "'first' said of 2 steps"),
        ("First put the egg in the fridge. First put the mug in the sink.", "'first' said of 2 steps"),
        ("Put the egg in the fridge, then the mug in the sink, but first the apple in the microwave, and "
         "finally the tomato in the garbage can", "'first' (no step"),
        ("Put the egg in the fridge finally, and put the mug in the sink", "'finally': an order word"),
        ("Put both of the three cups in the sink", "'both' of more than two"),
        ("Put all of the mugs but one in the sink", "'all' but some"),
    ],
)  # fmt: skip
def test_an_order_word_or_count_left_unread_is_named(text, unread):
    _, _, left, _ = read(text)
    assert any(unread in why for why in left), left


@pytest.mark.data
def test_a_count_of_those_there_is_the_tasks_count():
    tasks, _, left, _ = read("Put two of the three cups in the sink")  # it took all three cups
    assert (tasks, left) == (["place_two 2x Cup -> SinkBasin"], [])
    tasks, _, left, _ = read("Put both of the two mugs in the sink")
    assert (tasks, left) == (["place_two 2x Mug -> SinkBasin"], [])


@pytest.mark.data
def test_one_first_and_then_still_read():
    tasks, before, left, _ = read("First put the egg in the fridge, then put the mug in the sink")
    assert left == [] and len(before) == 1
