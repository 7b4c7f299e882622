"""Issue 24, h132 (session 22): the handover wordings h129 left. The arms named as the subject of a
question or wish about any placing verb ("Could the arms stack ... while keeping F, G and H empty during
this period?", "I'd like the arms to put ..."), a count of blocks with their colours after it ("the 2 blocks
red and blue", "the two blocks (red and blue)") where the colours are as many as the count, and the regions
said first as the subject of the one-block rule ("Regions H, I and J each get one block: put the three
blocks there") are read. A count that the colours after it do not fill, regions that "get one block" with
no "each", and a goal under "if" stay refused. `dev96` and the held-out `validation29` are read right or
refused, never misread (the `sweep` run)."""

from __future__ import annotations

import re

from handover_specs import round_tests

from nl2hltl2plan.language.handover_phrases import _COUNTED_COLOURS, _colours_counted

READ = {
    2: ["Regions H, I and J each get one block: put the three blocks there.",
        "Regions H, I and J take one block each: place the three blocks there."],
    5: ["Exchange the positions of the 2 blocks red and blue, red placed before blue. At any time, put the "
        "yellow block on the opposite side.",
        "Swap the two blocks (red and blue), red first. At any time, put the yellow block on the opposite "
        "side.",
        # refused in h129's round (a count with no comma before its colours)
        "Swap the 2 blocks red and blue, red first. Yellow to the opposite side at any time."],
    6: ["Regions G, H and I each get one object: place the three objects there, red before blue."],
    7: ["Could the arms stack the three blocks on region I one at a time, red before blue, while keeping "
        "regions F, G and H empty during this period?",
        "The arms should stack the three blocks on region I one at a time, red before blue, keeping regions "
        "F, G and H empty during this period.",
        "I'd like the arms to put the three objects one by one on region I, red before blue, while keeping "
        "F, G and H clear during this period."],
    8: ["First place the yellow block on region I, then on region G, and move the 2 blocks red and blue to "
        "any empty region at any time."],
}

REFUSED = [
    # a count that the colours after it do not fill: which blocks?
    (8, "First place the yellow block on region I, then on region G, and move the 3 blocks red and blue to "
        "any empty region at any time."),
    # "get one block" without "each": one block in all, or one on each?
    (2, "Regions H, I and J get one block: put the three blocks there."),
    # a condition the plan cannot test
    (7, "Could the arms stack the three blocks on region I one at a time, red before blue, if regions F, G "
        "and H are empty?"),
]

NEAR_MISSES = [
    # the colours are read as said: red and yellow are not task 8's blocks
    (8, "First place the yellow block on region I, then on region G, and move the 2 blocks red and yellow "
        "to any empty region at any time."),
    # the regions said first are the ones the blocks go to: E is not task 2's
    (2, "Regions E, I and J each get one block: put the three blocks there."),
]

(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h132_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev96", "validation29"))


def _counted(text: str) -> str:
    return " ".join(re.sub(_COUNTED_COLOURS, _colours_counted, text).split())


def test_a_count_of_blocks_is_their_colours_only_where_it_counts_them() -> None:
    assert _counted("swap the 2 blocks red and blue") == "swap the red and blue blocks"
    assert _counted("swap both blocks (red and blue) now") == "swap the red and blue blocks now"
    # a colour said again ends the list: what follows is kept
    said = _counted("swap the two blocks , red and blue , red first")
    assert said == "swap the red and blue blocks , red first"
    # two colours for three blocks: left as said (and refused where it is read)
    assert _counted("move the 3 blocks red and blue") == "move the 3 blocks red and blue"
