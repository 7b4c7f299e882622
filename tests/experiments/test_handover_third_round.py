"""Session 11, third round (h55): a left-dislocated topic taken up by a pronoun, a scene statement that
introduces the blocks, word-table forms ("be careful to", "when you have finished", "whenever's
convenient", "right by arm a"), the commas of an unpunctuated dictation restored at its clause breaks, and a
narrated command or prohibition after its period ("meanwhile you won't ..."). Each class has sentences that
must give the written spec and near misses that must be refused (never the written spec)."""

from __future__ import annotations

import pytest
from handover_specs import assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.handover_spoken import unspoken

READ = [
    # topics: blocks (plural "them", "their positions"; singular "it"), region lists, "each of those regions"
    (
        5,
        "The red and blue blocks, swap their positions, red placed first. The yellow one, it goes to the "
        "opposite side at any time.",
    ),
    (
        4,
        "The three blocks, carry them to the opposite regions. The blue one, nobody touches it until the red "
        "one has been touched. After that, the yellow block, it goes back on region G.",
    ),
    (
        7,
        "Regions F, G and H, nothing may be placed on them while the three objects go on region I one after "
        "another, red before blue.",
    ),
    (2, "The three blocks, I want them on H, I and J, and each of those regions, it takes only one object."),
    # scene statements that introduce every block of the scene, as a sentence or a clause
    (1, "We've got three blocks on the table. Carry them across to the opposite side, red before blue."),
    (1, "So we've got three blocks here, and they go to the opposite side, red before blue."),
    (6, "There are three objects in front of you. Put them on G, H and I, one per region, red before blue."),
    # unpunctuated dictation: a clause begins where a colour follows a block, a region or "placed first"
    (5, "swap the red and blue blocks red placed first yellow to the opposite side at any time"),
    (8, "put yellow on i then on g red and blue to any empty region at any time"),
    # word-table forms: "be careful to", "when you have finished", "whenever's convenient", "right by"
    (
        1,
        "Move the three blocks to the opposite side. Be careful to put the red block down before the "
        "blue block.",
    ),
    (
        4,
        "Transfer the three blocks to the opposite regions. Do not touch the blue block until the red block "
        "has been touched. When you have finished, the yellow block goes back to region G.",
    ),
    (
        5,
        "Exchange the positions of the red and blue blocks, red placed first, and put the yellow block on "
        "the opposite side whenever's convenient.",
    ),
    (
        3,
        "Move the three pillars to regions E, F and G, right by arm a and arm b. Place nothing on any "
        "other region.",
    ),
    # a narrated prohibition after its period
    (
        7,
        "You'll place the three objects on I one after another, red before blue. During this period you "
        "won't put anything on F, G or H.",
    ),
]

REFUSED = [
    # a pronoun of the other number is no resumption; a list of blocks is no topic
    (1, "The three blocks, move it to the opposite side. Red before blue."),
    (1, "The red block, the blue block and the yellow block, move to the opposite side, red before blue."),
    # a scene statement that is not the whole scene (the yellow block is there too), or a wrong count
    (
        5,
        "Here we have the red and blue blocks. Exchange their positions, red placed first, and put the "
        "yellow block on the opposite side at any time.",
    ),
    (1, "There are two blocks here. Move the three blocks to the opposite side, red before blue."),
    # a permission after the period is not a prohibition
    (
        7,
        "You'll place the three objects on I one after another, red before blue. Meanwhile you can put "
        "objects on F, G or H.",
    ),
    # the same words with a meaning they do not drop: a negation, a landmark that contradicts the place
    (
        1,
        "Move the three blocks to the opposite side. Be careful not to place the blue block before the "
        "red block.",
    ),
    (
        4,
        "Transfer the three blocks to the opposite regions. Do not touch the blue block until the red block "
        "has been touched. When you have not finished, put the yellow block back on region G.",
    ),
    (
        5,
        "Exchange the positions of the red and blue blocks, red placed first, and put the yellow block on "
        "the opposite side whenever is not convenient.",
    ),
    (
        3,
        "Move the three pillars to regions H, I and J, right next to arm a and arm b. Place nothing on any "
        "other region.",
    ),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_third_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_third_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("the blue block , do not touch it until red", "do not touch the blue block until red"),
        (
            "the red and blue blocks , i want their positions swapped",
            "i want the positions of the red and blue blocks swapped",
        ),
        ("the three blocks , move it to h", "the three blocks , move it to h"),  # number disagrees
        ("exchange red and blue blocks red first", "exchange red and blue blocks , red first"),
        ("then to g red and blue to h", "then to g , red and blue to h"),
        ("touched after that yellow back to g", "touched after that , yellow back to g"),
        ("after that yellow block to g", "after that yellow block to g"),  # "that": maybe a determiner
        ("put a red block on g", "put a red block on g"),  # "a": the article
        ("put one red block on g", "put one red block on g"),  # "one": a count
        ("put red on g , blue on h", "put red on g , blue on h"),  # punctuated: left as it is
    ],
)
def test_topics_and_clause_breaks_in_words(text, expected):
    assert unspoken(text) == expected
