"""Issue 24 (h98): rewrites of the handover reader that no committed sentence used, each probed with a
sentence of its class (a rephrasing of a Table III task in that wording). The rules kept must give the
written spec on their probe; twelve rules whose wordings other rules already read were deleted (their
probes are here too, read by the rules that remain). And the speed-up's literal test (`handover_regex`)
never skips a rewrite that could match."""

from __future__ import annotations

import re

import pytest
from handover_specs import assert_written_spec, cases

from nl2hltl2plan.language import handover_phrases, handover_spoken, handover_wishes
from nl2hltl2plan.language.handover_regex import apply, required, rewrite_table, sub

PROBES = {
    1: [
        "Transfer three blocks into the opposite. The blue block should be placed following the red "
        "block.",
        "Transfer three blocks into the opposite. The blue block should be placed later than the red "
        "block.",
        "Please have the three blocks moved to the opposite side, with the red block placed before the "
        "blue block.",
        "So, like, move the three blocks to the opposite side, and, like, the red block goes before the "
        "blue block.",
        "Kinda move the three blocks to the opposite side, with the red block placed before the blue "
        "block.",
        "Try to move the three blocks to the opposite side, with red placed before blue.",
        "I wanna move the three blocks to the opposite side, red before blue.",
        "Move the three blocks to the opposite side, red before blue, if possible.",
        "Could you possibly move the three blocks to the opposite side, red before blue?",
        # read by other rules since their own were deleted
        "Here is the task: transfer three blocks into the opposite. The red block should be placed before"
        " the blue block.",
        "Move the three blocks to the opposite side, red before blue, got it",
        "Move the three blocks to the opposite side, red before blue, if that's okay.",
    ],
    2: [
        "Your task is as follows: put the three blocks on regions H, I and J, one block per region.",
    ],
    4: [
        "Transfer three blocks into the opposite regions. Avoid touching the blue block until the red "
        "block has been touched. After all of these, put the yellow block back to region G.",
        "Transfer three blocks into the opposite regions. The arm wont touch the blue block until the red"
        " block has been touched. After all of these, put the yellow block back to region G.",
        "Transfer three blocks into the opposite regions. We are not touching the blue block until the "
        "red block has been touched. After all of these, put the yellow block back to region G.",
        "Transfer three blocks into the opposite regions, leaving the blue block untouched until the red "
        "block has been touched. After all of these, put the yellow block back to region G.",
        "Transfer three blocks into the opposite regions. The arm cannot touching the blue block until "
        "the red block is touched. After all of these, put the yellow block back to region G.",
    ],
    6: [
        "The red block should be placed before the blue block. Please place the three objects separately "
        "amongst regions G, H and I.",
        "We are placing the red block before the blue block. We are transferring the three objects "
        "separately to regions G, H and I.",
        "Red before blue. We are bringing the three objects separately to regions G, H and I.",
    ],
    7: [
        "Place the red block before the blue block. Put the three objects one after another on region I, "
        "and refrain from putting anything on regions F, G and H during this period.",
        "Place the red block before the blue block. Put the three objects one after another on region I, "
        "and avoid dropping anything on regions F, G and H during this period.",
        "The red block should be placed before the blue block. Place the three objects one after another "
        "to region I; no objects can be placed on regions F, G and H during this period, whilst doing so.",
        "The red block should be placed before the blue block. Place the three objects one after another "
        "to region I, never dropping anything on regions F, G and H during this period.",
        "We will be placing the red block before the blue block. We will be placing the three objects one"
        " after another on region I, and no objects can be placed on regions F, G and H during this "
        "period.",
        "Red goes before blue. We are putting the three objects one after another on region I and we are "
        "not dropping anything on regions F, G and H during this period.",
        "Red before blue. Place the three objects one after another to region I, with nothing placed on "
        "regions F, G and H until then.",
    ],
    8: [
        "First place the yellow block on region I, then on region G, as well as moving the red and blue "
        "blocks to any empty region at any time.",
        "The first step is to place the yellow block on region I. The next step is to place it on region "
        "G. Move the red and blue blocks to any empty region at any time.",
        "You put the yellow block on region I first, then you put it on region G, and you move the red "
        "and blue blocks to any empty region at any time.",
        "First the yellow block goes to region I and then goes on to region G; move the red and blue "
        "blocks to any empty region at any time.",
        "Please first place the yellow block to region I, then place it to region G, and move red and "
        "blue blocks anywhere empty at any time.",
    ],
}


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), cases(PROBES))
def test_each_probed_rewrite_class_gives_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


def test_required_literals_follow_the_parse() -> None:
    assert required(re.compile(r"\s*,?\s*\bwhereas\b")) == (frozenset({"whereas"}),)
    assert frozenset({"red", "blue"}) in required(re.compile(r"\b(?:red|blue)\s+block\b"))
    assert required(re.compile(r"(?:red)?\s*x?")) == ()  # nothing is required
    assert required(re.compile(r"(?i)whereas")) == ()  # case-insensitive: not filtered
    assert required(re.compile(r"(?:a\w|b)c")) == (frozenset({"c"}), frozenset({"a", "b"}))  # each set needed
    # a repeated letter joins the literals on both sides ("uh" in every "u+h+"); a lookaround's literals are
    # in the text too
    assert frozenset({"uh", "hmm"}) in required(re.compile(r"\b(?:u+h+|hmm+)\b"))
    assert frozenset({"touched", "picked"}) in required(re.compile(r"\bs\s+(?=(?:touched|picked)\b)"))
    assert set(required(re.compile(r"(?<=point)x"))) == {frozenset({"x"}), frozenset({"point"})}
    assert required(re.compile(r"(?!point)x")) == (frozenset({"x"}),)  # a negative one requires nothing
    assert sub(r"\bred\b", "blue", "a red block") == "a blue block"
    assert sub(r"\bred\b", "blue", "a yellow block") == "a yellow block"


TABLES = [handover_phrases._TABLE, *handover_spoken._STEPS, handover_wishes._COMPILED]
TEXTS = [t.lower() for texts in PROBES.values() for t in texts] + ["i.e. , the whereas , like , kinda red"]


@pytest.mark.parametrize("table", TABLES, ids=["phrases", "contractions", "fillers", "narration", "wishes"])
def test_a_rewrite_is_skipped_only_where_it_cannot_match(table) -> None:
    for text in TEXTS:
        plain = text
        for pattern, replacement, _ in table:
            plain = pattern.sub(replacement, plain)
        assert apply(table, text) == plain
        for pattern, _, requirement in table:
            if pattern.search(text):
                assert all(any(s in text for s in literals) for literals in requirement), pattern.pattern


def test_rewrite_table_keeps_each_pattern_and_replacement() -> None:
    rows = rewrite_table([(re.compile("ab"), "x")])
    assert rows[0][:2] == (re.compile("ab"), "x") and rows[0][2] == (("ab",),)
