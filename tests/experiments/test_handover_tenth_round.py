"""Issue 24, tenth round (h75): the frame words of `handover_discourse` in their one place (a record's
header in the first sentence, a label's words before a colon), relayed commands, the team named as the
subject of what it is about to do, an order said before its clause ("After it, ..."), "one of" a region
list for one block, quoted commands, markdown's bold, postscripts, commands received ("we were asked to
...", "plan how the arms ...", "let me ..."), asides ("btw"), bug reports' labels. The development
batches `dev32`-`dev37` must give the written specs (but for the sentences refused on purpose); near
misses must be refused or read as their words say.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import (
    assert_not_the_written_spec,
    assert_refused_by_name,
    assert_written_spec,
    assert_written_spec_or_refused,
)

from nl2hltl2plan.language.handover_discourse import empty, plain
from nl2hltl2plan.language.handover_narration import first_person_as_team

# dev32 and dev33 sentences refused on purpose: a name called alone ("Siri" may be any word), a problem
# stated with a negation ("blocks not on targets"), an order as a participle after a block's heading, a
# label that names an order ("Last round:"); "by the end" before other goals is read as the goal it states
# where each other goal is at any time (h148: `handover_reading._opening_end_state`)
STILL_REFUSED = {
    "Bug #301. Reproduce: move all three blocks to the opposite side. Expected: the red block is placed "
    "before the blue block. Actual: not yet run.",
    "First the red block: region G, H or I. After it, the blue block: region G, H or I. The yellow block: "
    "region G, H or I. One block per region.",
    "How to play: transfer the three blocks to the opposite regions. Rule: nobody touches the blue block "
    "until the red block has been touched. Last round: after all of these, put the yellow block back on "
    "region G.",
    "Siri, swap the red and blue blocks, red placed first, and move the yellow block to the opposite side at "
    "any time.",
    "Issue: blocks not on targets. Fix: put the three blocks on regions H, I and J, one block per region.",
    "Red block: region G, H or I, placed before blue. Blue block: region G, H or I. Yellow block: region G, "
    "H or I. One block per region.",
}

REFUSED = [
    # a record's number after the first sentence may number a step
    (8, "Day 2: put the yellow block on region G. Day 1: put it on region I. Red and blue go to any empty "
     "region at any time."),
    (8, "Run 1. Put the yellow block on region I. Run 2. Put it on region G. Red and blue go to any empty "
     "region at any time."),
    # a relay that is not at the sentence's start, or that forbids the goal
    (1, "Then, tell the arms to move all three blocks to the opposite side, red before blue."),
    # a command received as a prohibition or a question; an explanation asked for; a record's range
    (1, "We were asked not to move all three blocks to the opposite side, red before blue."),
    (2, "We were asked whether to put the three blocks on regions H, I and J, one block per region."),
    (1, "Explain how the arms move all three blocks to the opposite side, red before blue."),
    (2, "Question 1 of 3. Put the three blocks on regions H, I and J, one block per region."),
    # what happened is no requirement
    (1, "Bug 3. Reproduce: move all three blocks to the opposite side. Actual: the red block was placed "
     "after the blue block."),
    (3, "Let me move the three pillars to regions E, F and G beside arms a and b. Let me see, any other "
     "region is fine too."),
    (1, 'The instruction reads: "Move all three blocks to the opposite side." The note said not to place the '
     "red block before the blue block."),
    (2, "Tell the arms not to put the three blocks on regions H, I and J, one block per region."),
    # words the frame does not know; a name the reader reads
    (4, "Otherwise, move the three blocks to the opposite regions. Don't touch blue until red has been "
     "touched. After all of that, put the yellow block back on region G."),
    (6, "Hey Red, place the three objects on regions G, H and I, one each, red before blue."),
    # "they" of the blocks, not the team; "one of" after two blocks (one region for both?)
    (1, "Our arms are going to move all three blocks to the opposite side. They will move to it before the "
     "blue block."),
    (2, "Red and blue: one of H, I or J. Yellow block: one of H, I or J. One block per region."),
    (8, "Job 1. First put the yellow block on region I, then on region G. Job 2. Move the red and blue "
     "blocks to any empty region at any time."),
    (3, "Trial 3 of 5. Move the three pillars to regions E, F and G beside arms a and b. No object may go on "
     "any other region."),
]

OTHER = [
    # the order the other way round, in the narrated future or before its clause
    (1, "Today our arms are going to move all three blocks to the opposite side, and the blue block is going "
     "to be placed before the red block."),
    (7, "The red block goes on region I. Before it, the blue block goes on region I. The yellow block also "
     "goes on region I. Nothing goes on regions F, G or H during this period."),
    (6, "Work order 106. Items: the three objects. Destination: regions G, H and I, separately. Sequence: "
     "blue before red."),
    (4, "First, the three blocks will have been moved to the opposite regions, and the red block will not "
     "have been touched until the blue block has been touched. After all of these, the yellow block will "
     "have been put back on region G."),
    # a bug report's expectation, a block's heading with another order
    (1, "Bug #301. Reproduce: move all three blocks to the opposite side. Expected: the blue block is placed "
     "before the red block."),
    (7, "Red block: onto region I. Blue block: onto region I, before the red one. Yellow block: onto "
     "region I too. Meanwhile nothing on regions F, G or H."),
    # received, asked for or narrated, with another order or guard
    (1, "Let me move all three blocks to the opposite side, with the blue block placed before the red "
     "block."),
    (1, "Plan how the arms move all three blocks to the opposite side, blue before red."),
    (4, "We were told to transfer the three blocks to the opposite regions and not to touch the red block "
     "until the blue block has been touched. After all of these, we were told to put the yellow block back "
     "on region G."),
    # quoted, in markdown or after a postscript, with another meaning
    (1, 'The note says: "Move all three blocks to the opposite side, blue before red."'),
    (2, "The sticky note says: 'Put the three blocks on regions H, I and J, one block per region'. P.S. "
     "nothing on region G."),
    (6, "**Task:** place the three objects separately on regions G, H and I.\n**Order:** blue before red."),
    # one block's choice of regions differs: no "at once"
    (2, "Red block: one of H, I or J. Blue block: one of H, I or J. Yellow block: H or I. One block per "
     "region."),
]

READ = [
    (2, "Put the red block on one of regions H, I or J, the blue block on one of regions H, I or J and the "
     "yellow block on one of regions H, I or J, one block per region."),
    (5, "OK Kim, tell the arms to swap the red and blue blocks, red placed first, and to move the yellow "
     "block to the opposite side at any time."),
    (3, "The robots will move the three pillars to regions E, F and G beside arms a and b, and they won't "
     "put any object on any other region."),
]


@pytest.mark.parametrize(
    ("batch", "style"),
    [(b, s) for b in ("dev32", "dev33", "dev34", "dev35", "dev36", "dev37") for s in sorted(STYLES[b])],
)
def test_tenth_round_batches_give_the_written_specs_or_are_refused_by_name(batch, style):
    for task, text in STYLES[batch][style].items():
        if text in STILL_REFUSED:
            assert_refused_by_name(int(task), text)
        else:
            assert_written_spec(int(task), text)


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_tenth_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_tenth_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_tenth_round_sentences_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


def test_records_count_only_in_the_first_sentence():
    assert empty("Run 5, setup B", header=True) and empty("3 Dec, trial 2", header=True)
    assert not empty("Run 5, setup B") and not empty("Day 2", label=True)
    assert not empty("Run 3 blocks", header=True)  # a count of blocks, not a record's number
    assert plain(["Ticket #48", "Summary: move the red block to G"]) == ["move the red block to G"]


def test_the_team_named_as_subject_is_we():
    narrated = first_person_as_team("then the arms will put the red block on G")
    assert narrated == "then we will put the red block on G"
    assert first_person_as_team("they will move to G") == "they will move to G"  # the blocks
    assert first_person_as_team("regions by the arms are going to be empty") == (
        "regions by the arms will be empty"
    )


@pytest.mark.parametrize(
    ("batch", "style"), [(b, s) for b in ("validation11", "validation12") for s in STYLES[b]]
)
def test_held_out_batches_are_read_right_or_refused_never_misread(batch, style):
    """validation11 (h71) and validation12 (this round), each written before its round's reader changes
    and measured on the frozen reader (validation12: 3 of 24 read right, 21 refused, 0 other)."""
    for task, text in STYLES[batch][style].items():
        assert_written_spec_or_refused(int(task), text)
