"""Issue 24, h138 (session 23): an e-mail's quote marks ("> " at a line's start), a list's heading ("To do
list below:"), "see below" and "Sent from my phone" are read as the frame they are; a non-native speaker's
"not can", "a plan for move", "at (the) side of", "where is X now", "in each region is possible only one
object", "any region empty", "again on G" (back), "cannot touch X if Y is not touched before" (until Y has
been touched), "and after on G" and "first X and after Y" (then) are read, and so is a question to the arms
with a courtesy word after them ("Would the arms please put ...?") and a goal said as "the idea / plan /
intention is to ... / that ..." (as "the aim is"). A subject line that names an
arm and ", after put ..." (then, or after putting?) stay refused. `dev97` and the held-out `validation30`
and `validation31` are read right or refused, never misread (the `sweep` run)."""

from __future__ import annotations

import re

from handover_specs import round_tests

from nl2hltl2plan.language.handover_registers import REGISTERS
from nl2hltl2plan.language.handover_sentences import split_sentences

READ = {
    2: [">> Please put the three blocks on regions H, I and J, one block per region.",
        "Put the three blocks in region H, I and J, in every region is permitted just one block."],
    3: ["Make a plan for move the three pillars to region E, F and G at the side of arm a and arm b. Not any "
        "object can be placed on a region different from the target region."],
    4: ["> Move the three blocks to the opposite regions.\n> Do not touch the blue block until the red block "
        "has been touched.\n> After all of these, put the yellow block back on region G.",
        "Move the three blocks to the opposite regions. The arms not can touch the blue block before the red "
        "block has been touched. After all of this, put the yellow block again on region G.",
        "Move the three blocks to the opposite regions, no arm may touch blue block if red block was not "
        "touched before. After all of this, put yellow block back on region G, where is the red block now."],
    5: ["First red block and after blue block. Exchange the positions of the red and blue blocks. Yellow "
        "block to the opposite side at any time."],
    6: ["Our plan is that the red block is placed before the blue block, and the three objects are placed "
        "separately on regions G, H and I.",
        "Hi,\nSee below.\nThe red block goes before the blue block. Place the three objects separately on "
        "regions G, H and I.\nSent from my phone"],
    # the arms asked with a courtesy word after them (h132 read them without one)
    7: ["Could the robots kindly stack the three blocks on region I one after another, red before blue, "
        "keeping regions F, G and H clear during this period?"],
    8: ["To do list below:\n- put the yellow block on region I first\n- then put it on region G\n- move the "
        "red and blue blocks to any empty region at any time",
        "The idea is to put the yellow block on region I first, then on region G. Move the red and blue "
        "blocks to any empty region at any time.",
        "Yellow block goes first on region I and after on region G. Red and blue blocks go to any region "
        "free at any time."],
}

REFUSED = [
    # a subject line that names an arm: a title, or a word the body leaves out?
    (8, "Subject: arm tasks\n- put the yellow block on region I first\n- then put it on region G\n- move the "
        "red and blue blocks to any empty region at any time"),
    # a condition the plan cannot test ("if ... is free"), under the quote marks as anywhere
    (1, "> If the opposite side is free, move the three blocks there, red before blue."),
]

NEAR_MISSES = [
    # two blocks allowed in each region is not the one-block rule
    (2, "Put the three blocks in region H, I and J, in every region is possible only two blocks."),
    # "again on H": the place said is read, not the task's G
    (4, "Move the three blocks to the opposite regions. The arms not can touch the blue block before the red "
        "block has been touched. After all of this, put the yellow block again on region H."),
    # "if the red block is touched" (no "not"): another rule than "until"
    (4, "Move the three blocks to the opposite regions, no arm may touch blue block if red block was "
        "touched. After all of this, put yellow block back on region G."),
]

(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h138_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev97", "validation30", "validation31"))


def _registered(text: str) -> str:
    for pattern, replacement in REGISTERS:
        text = pattern.sub(replacement, text)
    return " ".join(text.split())


def test_non_native_forms_become_their_english() -> None:
    assert _registered("the arms not can touch the blue block") == "the arms cannot touch the blue block"
    assert _registered("put it again on region g") == "put it back on region g"
    assert _registered("first red block and after blue block") == "first red block and then blue block"
    # "after" before a verb is left as said: "then put", or "after putting"?
    assert _registered("put it on i first , after put it on g") == "put it on i first , after put it on g"
    # "first ... and after the blue block is placed": a clause, not a block that ends the sentence
    said = "first put red and after the blue block is placed put yellow"
    assert _registered(said) == said


def test_quote_marks_open_no_sentence() -> None:
    assert split_sentences("> Put the red block on G.\n>> Then the blue block on H.") == [
        "Put the red block on G", "Then the blue block on H"
    ]
    assert not any(re.match(r"\s*>", s) for s in split_sentences("> > red first"))
