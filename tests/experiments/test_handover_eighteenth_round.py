"""Issue 24, h129 (session 22): handover wordings in styles the earlier batches lack. The noun before its
colour ("block red is to be placed before block blue"), a region's letter in single quotes ("region 'I'"),
a step numbered in Roman numerals ("Step II:"), "outside those (target) regions", "never put one anywhere
else", a touch rule said as a permission ("only touch the blue block once the red block has been
touched"), the goal's own region said to be free first ("once region G is free, put the yellow block back
there"), a greeting that names its readers ("Dear operators,", "Hi both,") and a block said first before
any goal of it ("The red block should be placed first. Exchange ...") are read; a goal under "if" (a
condition the plan cannot test), a permission ("may be moved there") and "first" among blocks that the
text leaves unsaid are refused. `dev94` and the held-out `validation28` are read right or refused, never
misread (the `sweep` run), as is the second round `dev95` (ordinals in figures, "1st"; "you two" set
off by a dash; "when you get a chance", which leaves the time free; "outside it")."""

from __future__ import annotations

from handover_specs import round_tests

from nl2hltl2plan.language.handover_phrases import normalise
from nl2hltl2plan.language.handover_sentences import split_sentences

READ = {
    1: ["Block red is to be placed before block blue. Move the three blocks to the opposite side.",
        "Hi both, move the three blocks to the opposite side, the red block before the blue block.",
        # dev95: an ordinal in figures, "you two" set off by a dash
        "Move 3 blocks to the opposite side (red 1st, blue 2nd).",
        "Right, you two - shift the three blocks to the opposite side, red before blue."],
    2: ["Dear operators, put the three blocks on regions 'H', 'I' and 'J', one block per region."],
    3: ["Move the three pillars to regions E, F and G. Do not set any pillar down outside those regions.",
        "Move the three pillars to regions E, F and G; no object may be placed outside those target regions.",
        "Move the three pillars to regions E, F and G. Never put one anywhere else.",
        "Move the three pillars to the placement area (E, F and G) and never put a pillar outside it."],
    4: ["Transfer the three blocks to the opposite regions, but only touch the blue block once the red "
        "block has been touched. After all of these, once region G is free, put the yellow block back there.",
        "Transfer the three blocks to the opposite regions; no arm may touch the blue block until the red "
        "block has been touched. Once everything is done and region G is free, put the yellow block back "
        "there."],
    5: ["The red block should be placed first. Exchange the positions of the red and blue blocks. At any "
        "time, put the yellow block on the opposite side.",
        "Swap the red and blue blocks, red first; and when you get a chance, put the yellow block on the "
        "opposite side."],
    6: ["The three objects are to be placed separately on regions G, H and I, block red before block blue."],
    7: ["Place the three objects one after another on region I, red before blue. Don't put one on F, G or H "
        "meanwhile."],
    8: ["Step I: put the yellow block on region I. Step II: put it on region G. Step III: move the red and "
        "blue blocks to any empty region at any time.",
        "First put the yellow block on region I, then, once G is free, put it there. Move red and blue to "
        "any empty region at any time."],
}

REFUSED = [
    # a condition the plan cannot test: the goal is not said to hold whatever happens
    (4, "Transfer the three blocks to the opposite regions. The arm cannot touch the blue block until the "
        "red block has been touched. After all of these, if region G is free, put the yellow block back "
        "there."),
    (1, "If the opposite side is free, move the three blocks there; red before blue."),
    # a permission, not a goal
    (8, "First place the yellow block on region I, then on region G. Whenever a region is empty, the red and "
        "blue blocks may be moved there."),
    # "first" before any goal, where a later goal of another block is not free of order: first among which?
    (5, "The red block should be placed first. Exchange the positions of the red and blue blocks. The yellow "
        "block eventually ends up on the opposite side."),
    (5, "The red block should be placed first. Exchange the positions of the red and blue blocks. Put the "
        "yellow block on the opposite side."),
    # a condition that restates the world's rule (h132 reads "the 2 blocks red and blue": its round's tests)
    (2, "Put the three blocks into regions H, I and J; if a region already holds a block, use another one."),
    # "outside these two regions" after three regions: the count disagrees
    (3, "Move the three pillars to regions E, F and G. Do not put any pillar outside these two regions."),
]

NEAR_MISSES = [
    # the noun-first colours read as said: blue before red is not task 1
    (1, "Block blue is to be placed before block red. Move the three blocks to the opposite side."),
    # the quoted letters are read as the regions they name: J left out
    (2, "Put the three blocks on regions 'H', 'I' and 'E', one block per region."),
    # the exchange without "red first" has no order: not task 5
    (5, "Exchange the positions of the red and blue blocks. At any time, put the yellow block on the "
        "opposite side."),
    # once G is free, the yellow block goes there: H is another place
    (4, "Transfer the three blocks to the opposite regions; no arm may touch the blue block until the red "
        "block has been touched. After all of these, once region H is free, put the yellow block there."),
]

(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h129_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev94", "dev95", "validation28"))


def test_noun_before_colour_is_read_only_where_no_colour_word_precedes_it() -> None:
    assert normalise("Block red goes before block blue") == "the red block goes before the blue block"
    assert normalise("put a block red on G").startswith("put a red block")
    # dictated without commas: "the yellow block red first" is two phrases (`handover_spoken`)
    assert normalise("move the yellow block red first") == "move the yellow block , red first"


def test_roman_step_numbers_and_quoted_letters() -> None:
    said = split_sentences("Step I: put it on region 'I'. Step II: put it on G.")
    assert said == ["Step 1: put it on region I", "Step 2: put it on G"]
    # a Roman numeral not before a colon, bracket or dash is left (here: region I)
    assert split_sentences("Put the yellow block on step I") == ["Put the yellow block on step I"]
