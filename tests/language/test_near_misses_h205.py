"""Near misses of this session's framing and list rules (issue 23, h205): where a word that the rules
might drop or rewrite carries an object, a count, a negation or an order, the reading keeps it, or names
it unread (a refusal), and never reports a different task at exit 0."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.negations import unmoved_said

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    from trust_sets import world_of

    return full_reading(text, world_of("FloorPlan28"))


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks, before",
    [
        # "Oh, and" was "At any time,", which hid "before that" from the order words
        ("Put the mug in the sink. Oh, and put the egg in the fridge before that.", [MUG, EGG], [(EGG, MUG)]),
        ("Put the egg in the fridge. Oh, and put the mug in the sink.", [EGG, MUG], []),
        # a heading's treatment goes to the item after "then" too (the apple was only put)
        ("Chill these and put them away: the egg in the fridge, then the apple in the garbage can",
         ["cool_place Egg -> Fridge", "cool_place Apple -> GarbageCan"],
         [("cool_place Egg -> Fridge", "cool_place Apple -> GarbageCan")]),
    ],
)  # fmt: skip
def test_an_order_word_and_a_treatment_are_kept(text, tasks, before):
    got, order, unread, forbids = read(text)
    names = dict(zip(["A", "B"], got, strict=False))
    assert (got, sorted((names[a], names[b]) for a, b in order), unread, forbids) == (tasks, before, [], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "Put the egg in the fridge. P.S. the mug stays where it is.",  # was: the mug put in the fridge
        "Put the egg in the fridge. The mug stays put.",
        "Put the egg in the fridge. Leave the mug alone.",
    ],
)
def test_a_thing_said_to_stay_is_not_moved(text):
    assert read(text) == ([EGG], [], [], ["don't move the mug: forbids pickup(Mug)"])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, word",
    [
        # the negation was dropped: the mug was put in the sink at exit 0
        ("It would be great if the egg were in the fridge and the mug weren't in the sink", "weren't"),
        ("Make sure the egg is in the fridge and the mug isn't in the sink", "isn't"),
        # "At any time, put the egg in the fridge first" read no order, at exit 0
        ("Put the mug in the sink. Oh, and put the egg in the fridge first.", "first"),
    ],
)
def test_a_negation_or_order_no_rule_reads_is_named(text, word):
    _, _, unread, _ = read(text)
    assert any(u.startswith(f"'{word}'") or u.startswith(f'"{word}"') for u in unread), unread


@pytest.mark.data
def test_a_count_through_a_state_word_is_checked_against_the_scene():
    """ "three cold eggs" made three eggs of FloorPlan28's two at exit 0."""
    with pytest.raises(HTTError, match="'three cold eggs': FloorPlan28 holds only 2 egg"):
        read("three cold eggs in the fridge")


def test_stays_is_read_only_where_the_thing_is_named_and_nothing_else_follows():
    # where it stays is where it is now (h236): kept there, not a placing ("the keys stay on the table")
    assert unmoved_said("The mug stays in the sink.") == "don't move the mug."
    assert unmoved_said("The mug stays in the sink to soak.") == "The mug stays in the sink to soak."
    assert unmoved_said("Put it in the fridge so it stays cold.") == "Put it in the fridge so it stays cold."
    assert unmoved_said("The banana stays put.") == "The banana stays put."  # no such name: left to refuse


@pytest.mark.data
def test_an_item_that_stays_under_a_place_heading_is_not_moved():
    """ "Everything below goes in the fridge: the egg, the mug stays put" put the mug in the fridge."""
    got = read("Everything below goes in the fridge: the egg, the mug stays put")
    assert got == ([EGG], [], [], ["don't move the mug: forbids pickup(Mug)"])


@pytest.mark.data
def test_a_lamp_said_off_is_named():
    """ "light off" after the lamp was dropped: the book was examined with the lamp on, at exit 0."""
    from trust_sets import world_of

    with pytest.raises(HTTError, match="'light off' \\(action\\): no base task switches something off"):
        full_reading("the book under the desk lamp, light off", world_of("FloorPlan301"))


@pytest.mark.data
def test_isnt_in_a_free_order_remark_is_no_negation():
    # "isn't" became a negation word (h205); "Order isn't important" frees the order and forbids nothing
    text = "Put the egg in the fridge and the mug in the sink. Order isn't important."
    tasks, before, unread, forbids = read(text)
    assert (sorted(tasks), before, unread, forbids) == (sorted([EGG, MUG]), [], [], [])
