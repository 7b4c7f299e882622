"""Issue 24, h114 (session 20): bullets without a verb under a heading that has it ("Move to the opposite
side:" over "- three blocks"; "Exchange the positions of:" over one bullet per block), hedges of time that
open a step ("eventually", "sooner or later", "at some point they will ..."), telegraphic goals ("Three
blocks, opposite side."), "nowhere else", closing restrictions on what moves ("Nothing else moves.": read
only where every block has a goal), "place no object on ... during such period", labelled fields ("move:
three blocks" and "to: opposite side", "not allowed meanwhile: any object on ..."); "at any time" on a
clause of several blocks keeps their "at once" leaf. `dev88` and the held-out `validation21` are read
right or refused, never misread (the `sweep` run)."""

from __future__ import annotations

import pytest
from handover_specs import round_tests

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_closing import check_closing, closing_said
from nl2hltl2plan.language.handover_layout import block_bullets_read

READ = {
    1: [
        "To the opposite side:\n* the three blocks\nPlace the red block before the blue block.",
        "Blocks, opposite side. Red first, then blue. Nothing else moves.",
        "Three blocks, opposite side, go! Red before blue! Move it!",
        "Make the three blocks end up on the opposite side, and have the red block land before the blue "
        "block.",
        "move: three blocks\nto: opposite side\norder: red before blue",
    ],
    2: [
        # "at any time" frees the goals' time, not the place they end in: all three there at once
        "Put the three blocks on regions H, I and J at any time, one block per region.",
        "The arms need to set down:\n* the three blocks onto regions H, I and J\n* no more than one block "
        "per region",
        "One block per region, no more. The three blocks are to go into regions H, I and J.",
        "Blocks to move to regions H, I and J:\n- red\n- blue\n- yellow\nOne per region.",
        "The arms should move:\n- the three blocks\n- to regions H, I and J\n- one per region",
        # a sentence that only names the blocks, then their place
        "Blocks! H, I, J! One each! Let's go!",
        "- three blocks\n- regions H, I and J\n- one block per region",
        "The Arms shall place the three blocks on regions H, I and J, and no more than one block shall be "
        "placed on each of said regions.",
    ],
    3: [
        "Bring to regions E, F and G:\n- all three pillars\nNothing may be placed on any other region.",
        "Move the three pillars to regions E, F and G, and nowhere else.",
        "Pillars! E, F, G, by arms a and b! Nothing anywhere else! Move!",
        "Move the three pillars to regions E, F and G; until they are all on E, F and G, nothing may be "
        "placed on any other region.",
    ],
    5: [
        "Exchange the places of:\n- the red block\n- the blue block\nThe red block goes first. The yellow "
        "block goes to the opposite side at any time.",
        "Swap the red and blue blocks, red first. Sooner or later the yellow block goes to the opposite "
        "side.",
        "Red and blue, swap! Red down first! Yellow, opposite side, whenever!",
        "The arms will swap the red and blue blocks, red first. Later on, they will also take the yellow "
        "block to the opposite side.",
        "Red and blue: swap. Red first. Yellow: opposite side. Whenever.",
        "The arms will swap the red and blue blocks, red first. At some point, they'll also need to take the "
        "yellow block to the opposite side.",
        "The arms will swap the red and blue blocks, placing red first. The yellow block will go to the "
        "opposite side eventually.",
        # "it": the one block of the clause before
        "Swap red and blue, red placed first. Move the yellow block to the opposite side. It can go at any "
        "time.",
    ],
    6: ["Three objects, G, H, I, one each. Red before blue.",
        "At some point the three objects will be placed on regions G, H and I, one per region, the red one "
        "before the blue one.",
        "Objects, regions G, H, I. One per region. Red, then blue. No other moves.",
        "The arms should place on regions G, H and I:\n- the three objects, one in each\n- the red one "
        "before the blue one",
        "Please put, one in each region:\n1. the three objects on regions G, H and I\n2. red before blue"],
    7: [
        "Put on region I, one by one:\n- the three objects\nRed before blue, and no object on regions F, G "
        "or H meanwhile.",
        "Red before blue. Place the three objects on region I one after another; place no object on regions "
        "F, G and H during such period.",
        "Three objects on I, one after another, red before blue. Nothing on F, G or H until the last one is "
        "on I.",
        "Place the three objects on region I one after another, red before blue, placing no object on "
        "regions F, G or H during such period.",
        "Place the three objects on region I one after another, red before blue; while this is in progress, "
        "no object may be placed on regions F, G or H.",
        "The arms will put the three objects on region I one after another, red before blue, and at no point "
        "will they place anything on regions F, G or H.",
        "order: red before blue\nplace: three blocks, one after another\nto: region I\nnot allowed "
        "meanwhile: any object on regions F, G and H",
    ],
    8: [
        "Yellow: I, then G. Red and blue: any empty region, any time. Nothing else.",
        "To any empty region, at any time:\n* the red block\n* the blue block\nAlso place the yellow block "
        "on region I first and then on region G.",
        "The arms will first put the yellow block on region I and then on region G. At some point they will "
        "also move the red and blue blocks to any empty region.",
    ],
}

REFUSED = [
    # a closing restriction that keeps a block without a goal in place: a constraint the spec cannot carry
    (8, "Put the yellow block on region I, then on region G. Nothing else moves."),
    (8, "Put the yellow block on region I, then on region G, and leave everything else where it is."),
    # a hedge after a goal of the same sentence may mean "then" ("later on" opening a later sentence is
    # "after that" since h121: test_handover_sixteenth_round.py)
    (8, "Put the yellow block on region I, and eventually put it on region G. Move the red and blue blocks "
        "to any empty region at any time."),
    # a telegraphic place where the block starts (the red block starts on J on instance 0 of task 8): where
    # it is, or where it goes?
    (8, "Red, region J. Blue, any empty region. Yellow: I, then G."),
    # "until the last one is on" a region no goal names: a period the reader does not model
    (7, "Put the three objects on region I one after another, red before blue. Until the last one is on "
        "region H, no object may be put on regions F, G or H."),
    (8, "Put the yellow block on region I, then on region G. Nothing else."),
    # "it" after a clause of two blocks, or of one block's steps in order
    (8, "Put the yellow block on region I first and then on region G. Move the red and blue blocks to any "
        "empty region. It can go at any time."),
    (8, "Put the yellow block on region I, then on region G. It can go at any time."),
    # a time alone after steps in order; a hedge that ends a sentence of two clauses
    (8, "Put the yellow block on region I, then on region G. Whenever. Red and blue: any empty region."),
    (8, "Put the yellow block on region I, and put it on region G eventually. Move the red and blue blocks "
        "to any empty region at any time."),
    # "leave the rest alone": the other blocks, or the other regions?
    (3, "Move the three pillars to regions E, F and G. Leave the rest alone."),
]

NEAR_MISSES = [
    # a bullet's block, a heading's place, the order or a forbidden region changed under the new forms
    (1, "Move to the opposite side:\n- the red block\n- the blue block\nRed before blue."),
    (1, "Three blocks, opposite side. Blue before red."),
    (3, "Move the three pillars to regions E, F and H, and nowhere else."),
    (2, "Put the three blocks on regions H, I and J, one per region. Nowhere else."),
    (5, "Exchange the places of:\n- the red block\n- the yellow block\nThe red block goes first. The blue "
        "block goes to the opposite side at any time."),
    (7, "Red before blue. Place the three objects on region I one after another; place no object on regions "
        "F and G during such period."),
    (7, "order: red before blue\nplace: three blocks, one after another\nto: region H\nnot allowed "
        "meanwhile: any object on regions F, G and I"),
    (2, "Onto regions H, I and G:\n* three blocks\nOnly one block may go on each region."),
    (1, "Move:\n- three blocks\n- to the opposite side\n- blue before red"),
    (2, "Blocks! H, I, G! One each! Let's go!"),
    (1, "Make the three blocks end up on the opposite side, and have the blue block land before the red "
        "block."),
    (2, "Put the three blocks on regions H, I and G at any time, one block per region."),
    (7, "Place the three objects on region I one after another, red before blue, placing no object on "
        "regions F or G during such period."),
    (7, "The arms should place on region H:\n- three objects, one after another\n- red before blue\n- "
        "nothing on F, G or I meanwhile"),
]


(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h114_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev88", "validation21"))


def test_bullets_that_only_name_blocks_are_one_list_under_their_heading() -> None:
    text = "Swap:\n- the red block\n- the blue block\nRed first."
    assert block_bullets_read(text) == "Swap:\n- the red block and the blue block\nRed first."
    # not under a heading, or a bullet that says more: left as they are
    assert block_bullets_read("- the red block\n- the blue block") == "- the red block\n- the blue block"
    kept = "Move:\n- the red block to H\n- the blue block"
    assert block_bullets_read(kept) == kept


def test_a_closing_restriction_is_nothing_only_where_every_block_has_a_goal() -> None:
    kept, said = closing_said(
        ["Move the blocks to H", "Nothing else moves", "Red first, and no other block moves"]
    )
    assert kept == ["Move the blocks to H", "Red first"]
    assert said == ["Nothing else moves", "and no other block moves"]
    check_closing(said, {"Red", "Blue", "Yellow"}, ["Red", "Blue", "Yellow"])
    with pytest.raises(HTTError, match="blue"):
        check_closing(said, {"Red", "Yellow"}, ["Red", "Blue", "Yellow"])
