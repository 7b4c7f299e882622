"""Issue 24, h95: a pseudo-cleft's head of a wish, need or task ("what needs doing is ...", "what you do is
...", "what is required is ..."), a pseudo-cleft of an order ("what comes first is the red block"), the last
step said first ("last of all, X; before that, Y"), a note's group and regions as fragments ("three blocks;
regions H, I and J; ..."), a pair's bare "swap" after its heading and a block's heading before its order
("red: before blue"), bare region letters in a block's steps ("yellow: I first, then G"), "every object is
used (once)" after a goal for all three, a prohibition said as a label ("Don't: touch ..."), a noun of
placing after a heading ("three blocks: placement on regions H, I and J"), a block's heading before its
time alone ("Yellow: whenever"), a step with no place over the items that say where ("1. Move the
blocks." then "   - All three go to the opposite side."). Each reading gives the written
spec; each near miss (an order reversed, a pronoun with no one block to stand for, a region left out) is
refused or gives another spec."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_written_spec

READINGS = [
    # "have X go down before Y" is X's placing before Y's, never its pick-up (`dev73`'s one misreading)
    (
        6,
        "Get the three objects onto regions G, H and I, one per region, and have the red block go down"
        " before the blue block.",
    ),
    (1, "1. Move the blocks.\n   - All three go to the opposite side.\n   - Red is placed before blue."),
    (
        5,
        "Swap the red and blue blocks, red first. Move the yellow block to the opposite side. Yellow:"
        " whenever.",
    ),
    (6, "Order: red before blue. The three objects: placement on regions G, H and I, one each."),
    (
        8,
        "Yellow block: transfer to region I, then to region G. Red and blue blocks: delivery to any empty"
        " region at any time.",
    ),
    (
        7,
        "Place the three objects on region I one after another, red before blue.\n- Never: place anything on"
        " regions F, G or H during this period.",
    ),
    (
        4,
        "Do: move the three blocks to the opposite regions, then put the yellow block back on region G.\nDo"
        " not: touch the blue block before the red block has been touched.",
    ),
    (8, "Yellow: I first, then G. Red and blue: any empty region, any time."),
    (
        6,
        "Place the three objects on regions G, H and I, one object per region, and each object is used"
        " exactly once; red before blue.",
    ),
    (
        1,
        "What needs to be done is moving the three blocks to the opposite side; what goes first is the red"
        " block, ahead of the blue block.",
    ),
    (
        6,
        "What is required is the three objects on regions G, H and I, one each. What is placed first is the"
        " red block, before the blue block.",
    ),
    (2, "What you have to do is put the three blocks on regions H, I and J, one block per region."),
    (
        4,
        "Finally, put the yellow block back on region G; before that, move the three blocks to the opposite"
        " regions, and do not touch the blue block until the red block has been touched.",
    ),
    (
        8,
        "Last, the yellow block goes to region G; before this, it goes to region I. The red and blue blocks"
        " go to any empty region at any time.",
    ),
    (2, "Memo: the three blocks; regions H, I and J; one block per region."),
    (5, "Red and blue: swap. Red: ahead of blue. Yellow: the opposite side, any time."),
]

NEAR_MISSES = [
    (
        6,
        "Get the three objects onto regions G, H and I, one per region, and have the blue block go down"
        " before the red block.",
    ),
    # a step with no place followed by steps of its own level (not items under it) is no heading: unread
    (1, "1. Move the blocks.\n2. All three go to the opposite side.\n3. Red is placed before blue."),
    # a time for a block whose goal is not the clause before it: left unread
    (
        5,
        "Swap the red and blue blocks, red first. Move the yellow block to the opposite side. Red: whenever.",
    ),
    (6, "Order: red block before blue block. Three objects: placement on regions G, H and J, one each."),
    # a prohibition's label over a list negates no item: left unread (never "place the blue block first")
    (
        7,
        "Place the three objects on region I one after another.\nDon't:\n- place anything on regions F, G or"
        " H during this period\n- place the blue block after the red block",
    ),
    (8, "Yellow: G first, then I. Red and blue: any empty region, any time."),
    # "every object is used" with no goal for the three before it says something the reader does not check
    (
        6,
        "Every object is used once. Put the three objects on regions G, H and I, one per region; red before"
        " blue.",
    ),
    (
        1,
        "What needs to be done is moving the three blocks to the opposite side; what goes first is the blue"
        " block, ahead of the red block.",
    ),
    (
        8,
        "Last, the yellow block goes to region I; before this, it goes to region G. The red and blue blocks"
        " go to any empty region at any time.",
    ),
    # "it" with two blocks before it stands for neither: left unread
    (
        8,
        "Last, the yellow and red blocks go to region G; before this, it goes to region I. The red and blue"
        " blocks go to any empty region at any time.",
    ),
    (2, "Memo: the three blocks; regions H and I; one block per region."),
    (5, "Red and blue: swap. Blue: ahead of red. Yellow: the opposite side, any time."),
]


@pytest.mark.parametrize(("task_id", "text"), READINGS)
def test_clefts_and_steps_said_last_first_are_read(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), NEAR_MISSES)
def test_cleft_near_misses_are_refused_or_give_another_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)
