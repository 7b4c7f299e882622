"""Issue 24, h89: voices related to the held-out validation15's (nominal steps, "would you mind / might I
ask" questions, texting abbreviations, clauses in reversed order). Each reading gives the written spec;
its near miss (an order reversed, a guard or a region changed) is refused or gives another spec.
"""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_written_spec

READINGS = [
    (
        5,
        "Placement of the red block before placement of the blue block; an exchange of the positions of the "
        "red and blue blocks; and, at any time, transfer of the yellow block to the opposite side.",
    ),
    (
        3,
        "Delivery of the three pillars to regions E, F and G beside arms a and b; no placement of any object "
        "on any other region.",
    ),
    (
        1,
        "Would you mind moving the three blocks to the opposite side? Might I ask that the red block be "
        "placed before the blue block?",
    ),
    (3, "pls move the 3 pillars 2 regions E, F n G next 2 arms a n b, nothin on any other region"),
    (7, "red b4 blue pls. put the 3 objects on I 1 after another n put nothin on F, G n H meanwhile"),
    (2, "Only one block on each region, and the three blocks on regions H, I and J."),
    (
        4,
        "Put the yellow block back on region G after all of this: move the three blocks to the opposite "
        "regions, and no arm may touch the blue block until the red block has been touched.",
    ),
    (
        4,
        "After all of that, put the yellow block back on region G; but first move the three blocks to the "
        "opposite regions, and do not touch the blue block until the red block has been touched.",
    ),
    # h86's unread development refusals
    (2, "Put the three blocks in H, I and J. Only one block in each one."),
    (
        3,
        "The three pillars should go to regions E, F and G, beside arms a and b, and I'd rather nothing went "
        "on any other region.",
    ),
    (
        3,
        "Move the three pillars to regions E, F and G (the ones beside arms a and b), and nothing goes on "
        "any other region.",
    ),
    (
        4,
        "Move the three blocks to the opposite regions. No arm touches the blue block until the red block "
        "has been touched. Then, after all of that, make sure the yellow block is back on region G.",
    ),
]

NEAR_MISSES = [
    (
        5,
        "Placement of the blue block before placement of the red block; an exchange of the positions of the "
        "red and blue blocks; and, at any time, transfer of the yellow block to the opposite side.",
    ),
    (
        3,
        "Delivery of the three pillars to regions E, F and G beside arms a and b; no placement of any object "
        "on regions H and I.",
    ),
    (
        1,
        "Would you mind moving the three blocks to the opposite side? Might I ask that the blue block be "
        "placed before the red block?",
    ),
    (3, "pls move the 3 pillars 2 regions E, F n G next 2 arms a n b, nothin on regions H n I"),
    (7, "blue b4 red pls. put the 3 objects on I 1 after another n put nothin on F, G n H meanwhile"),
    (2, "Only one block on each region, and the three blocks on regions H and I."),
    (
        4,
        "Put the yellow block back on region G after all of this: move the three blocks to the opposite "
        "regions, and no arm may touch the red block until the blue block has been touched.",
    ),
    (
        4,
        "After all of that, put the yellow block back on region H; but first move the three blocks to the "
        "opposite regions, and do not touch the blue block until the red block has been touched.",
    ),
    (2, "Put the three blocks in H and I. Only one block in each one."),
    (
        3,
        "The three pillars should go to regions E, F and G, beside arms a and b, and I'd rather nothing went "
        "on regions H and I.",
    ),
    (
        3,
        "Move the three pillars to regions E, F and G (the ones beside arms a and b), and nothing goes on "
        "region H.",
    ),
    (
        4,
        "Move the three blocks to the opposite regions. No arm touches the blue block until the red block "
        "has been touched. Then, after all of that, make sure the yellow block is back on region H.",
    ),
]


@pytest.mark.parametrize(("task_id", "text"), READINGS)
def test_the_voices_give_the_written_spec(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), NEAR_MISSES)
def test_their_near_misses_do_not(task_id, text):
    assert_not_the_written_spec(task_id, text)


def test_an_announced_number_of_things_must_be_the_number_said():
    rules = (
        " The red block has to be placed before the blue block. And the three objects need to be placed on "
        "regions G, H and I, with one object on each region."
    )
    assert_written_spec(6, "There are two things to keep in mind." + rules)
    assert_written_spec(6, "There are a few things to keep in mind." + rules)
    assert_not_the_written_spec(6, "There are three things to keep in mind." + rules)
    assert_written_spec(
        5,
        "Swap the red and blue blocks, red before blue, and the yellow block goes to the "
        "opposite side at any time that works.",
    )


@pytest.mark.parametrize(
    ("task_id", "text", "near_miss"),
    [
        (
            6,
            "The red block must come before the blue block as you place the three objects on regions G, H "
            "and I, one on each.",
            "The blue block must come before the red block as you place the three objects on regions G, H "
            "and I, one on each.",
        ),
        (
            8,
            "Putting the yellow block on region I first and then on region G is the job; moving the red "
            "and blue blocks to any empty region can happen at any time.",
            "Putting the yellow block on region I first and then on region H is the job; moving the red "
            "and blue blocks to any empty region can happen at any time.",
        ),
        (
            5,
            "red b4 blue pls & swap red n blue. yellow 2 opposite side whenever u like ty",
            "blue b4 red pls & swap red n blue. yellow 2 opposite side whenever u like ty",
        ),
    ],
)
def test_as_you_gerund_subjects_and_texting(task_id, text, near_miss):
    assert_written_spec(task_id, text)
    assert_not_the_written_spec(task_id, near_miss)


def test_a_forbidden_gerund_and_a_last_step_said_as_a_noun():
    job = (
        "Moving the three blocks to the opposite regions is the job, and touching the {} block before the {} "
    )
    last = (
        "block has been touched is not allowed. After all of that, putting the yellow block back on {} is "
        "the last step."
    )
    assert_written_spec(4, job.format("blue", "red") + last.format("region G"))
    assert_not_the_written_spec(4, job.format("red", "blue") + last.format("region G"))
    assert_not_the_written_spec(4, job.format("blue", "red") + last.format("region H"))


@pytest.mark.parametrize(
    ("task_id", "text", "near_miss"),
    [
        (
            6,
            "I wonder if you could place the red block before the blue block, and put the three objects on "
            "regions G, H and I, one on each?",
            "I wonder if you could place the blue block before the red block, and put the three objects on "
            "regions G, H and I, one on each?",
        ),
        (
            2,
            "3 blocks 2 H I n J pls 1 per region k thx",
            "3 blocks 2 H I n G pls 1 per region k thx",
        ),
        (
            5,
            "Before the blue block goes the red block; the red and blue blocks swap positions; and "
            "at any time, to the opposite side goes the yellow block.",
            "Before the red block goes the blue block; the red and blue blocks swap positions; and "
            "at any time, to the opposite side goes the yellow block.",
        ),
    ],
)
def test_wondering_unpunctuated_letters_and_an_inverted_order(task_id, text, near_miss):
    assert_written_spec(task_id, text)
    assert_not_the_written_spec(task_id, near_miss)
