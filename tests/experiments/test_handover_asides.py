"""Issue 24, h95: asides in parentheses read by what their words name (`language/handover_asides.py`): an
aside that only stresses its clause is dropped, one that interrupts a clause before its place is said
after the place, one inside a clause is read in its place, and one that names or describes the thing
before it is left to the readers of such phrases. Each reading gives the written spec; each near miss (an
order reversed, a place changed, an emphatic negation after a clause that is not negated, a description
the reader cannot check) is refused or gives another spec."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_written_spec

from nl2hltl2plan.language.handover_asides import read_asides

READINGS = [
    (
        3,
        "Dear Sam,\nMove the three pillars to regions E, F and G beside arms a and b. Put nothing on any"
        " other region.",
    ),
    (
        1,
        "Carry the three blocks (all three of them) to the opposite side; the red block (first) before the"
        " blue.",
    ),
    (2, "Put the three blocks (one block each) on regions H, I and J."),
    (
        3,
        "Place the three pillars on regions E, F and G (by arms a and b); put nothing (nothing whatsoever) on"
        " any other region.",
    ),
    (
        4,
        "Move the three blocks to the opposite regions; the arms must not touch the blue block (not once)"
        " until the red block has been touched; after all of that, put the yellow block back on region G.",
    ),
    (
        5,
        "Exchange the red and blue blocks (red placed before blue) and put the yellow block (at any time) on"
        " the opposite side.",
    ),
    (
        6,
        "The red block goes before the blue block (remember). Put the three objects (one per region) on"
        " regions G, H and I.",
    ),
    (
        7,
        "Place the three objects (one after another) on region I, red before blue; put nothing on regions F,"
        " G or H (during this period).",
    ),
    (
        8,
        "Put the yellow block on region I (first), then on region G; the red and blue blocks (whenever) go to"
        " any empty region.",
    ),
    (
        3,
        "Dear all,\nplease move the three pillars to regions E, F and G beside arms a and b, and place"
        " nothing on any other region.\nBest,\nAna",
    ),
]

NEAR_MISSES = [
    # an aside that says another order, a negation or an exception is still read, and refused or kept apart
    (1, "Move all three blocks (blue first) to the opposite side; red before blue."),
    (
        6,
        "Put the three objects (except the red block) on regions G, H and I, one per region; red before"
        " blue.",
    ),
    (
        8,
        "Put the yellow block on region I (then on region G), and move the red and blue blocks (never) to any"
        " empty region.",
    ),
    # a greeting's name that the reader reads as a block is no greeting
    (
        3,
        "Dear Red,\nmove the three pillars to regions E, F and G beside arms a and b; nothing on other"
        " regions.",
    ),
    (
        5,
        "Exchange the red and blue blocks (blue placed before red) and put the yellow block (at any time) on"
        " the opposite side.",
    ),
    (
        6,
        "The red block goes before the blue block. Put the three objects (one per region) on regions G, H"
        " and J.",
    ),
    (
        8,
        "Put the yellow block on region I (first), then on region H; the red and blue blocks (whenever) go to"
        " any empty region.",
    ),
    # an emphatic negation after a clause that says no "no" stresses nothing: left to be read, and refused
    (1, "Move the three blocks to the opposite side (not even briefly), red before blue."),
    # a description of a block's place that the reader cannot check is never dropped
    (
        4,
        "Move the three blocks to the opposite regions; do not touch the blue block until the red block has"
        " been touched. After that, put the yellow block back on region G (its starting region).",
    ),
]


@pytest.mark.parametrize(("task_id", "text"), READINGS)
def test_asides_are_read_by_what_their_words_name(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), NEAR_MISSES)
def test_aside_near_misses_are_refused_or_give_another_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


def test_list_markers_counts_and_descriptions_keep_their_parentheses():
    for text in (
        "(1) move",
        "(b) place",
        "pillars (three) must",
        "g (the ones beside arms a and b)",
        "g (where the red block is)",
    ):
        assert read_asides(text) == text


def test_an_interrupting_aside_is_said_after_the_place():
    moved = " ".join(read_asides("put them (one per region) on regions g, h and i, then stop").split())
    assert moved == "put them on regions g, h and i , one per region , , then stop"
