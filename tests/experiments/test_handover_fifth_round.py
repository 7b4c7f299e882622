"""Issue 24, fifth round (h62): wishes and indirect requests, a goal stated as the final state, completion
clauses ("once they're all over,"), "X left alone until ...", order words after their blocks ("red first and
blue later"), a block's next place after "then finish on", kept-empty regions ("free of objects", "while
keeping ... empty") and "never more than one object in a region" (`language/handover_wishes.py`). Each class
has sentences of our own that must give the written spec and near misses that must be refused or give
another spec (never the written one)."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.handover_wishes import unwished

READ = [
    # wishes and indirect requests before a verb; a wish with its object and participle
    (1, "Let's have the three blocks placed on the opposite side, red before blue."),
    (1, "Let's move the three blocks to the opposite side, red before blue."),
    (8, "Have the arms move the yellow block to region I and then to region G; red and blue go to any empty "
     "region at any time."),
    (6, "Would it be okay to put the three objects on G, H and I, one per region, with red before blue?"),
    (2, "We were hoping you could put the three blocks on H, I and J, one per region."),
    (3, "I want the three pillars taken to regions E, F and G beside arms a and b; no object may go on any "
     "other region."),
    # a past-tense wish, going on after "and"
    (5, "It would be nice if the red and blue blocks were swapped, red placed first, and the yellow block "
     "went to the opposite side at any time."),
    # a goal stated as the final state
    (2, "In the end, the three blocks should be resting on H, I and J, one per region."),
    (3, "The final layout should be the three pillars on E, F and G beside arms a and b; nothing may be "
     "placed on any other region."),
    (5, "The red and blue blocks should have exchanged positions with red placed first, and yellow should be "
     "on the opposite side at any time."),
    (4, "Move the three blocks to the opposite regions without touching blue before red has been touched. "
     "When you're done, the yellow block should be back on G."),
    (7, "The aim is to have the three objects on region I one by one, red before blue, with nothing put on "
     "F, G or H until then."),
    (8, "The yellow block goes to I first, then carries on to G; the red and blue blocks go to any empty "
     "region at any time."),
    # completion clauses
    (4, "Move the three blocks to the opposite regions; don't touch blue until red has been touched. Once "
     "everything is in place, put yellow back on G."),
    (4, "Move the three blocks to the opposite regions; don't touch blue until red has been touched. Once "
     "they are there, put yellow back on G."),
    # a block left alone until another is touched
    (4, "Move the three blocks to the opposite regions, leaving the blue block alone until the red one has "
     "been touched, then put yellow back on G."),
    # order words after their blocks
    (7, "Put the three objects on region I one by one, red first and blue afterwards; nothing on F, G or H "
     "meanwhile."),
    (6, "Place the blue one later and the red one first, three objects on G, H and I, one per region."),
    # kept-empty regions; one object per region
    (7, "Place the three objects on region I one after another, red before blue, while you keep F, G and H "
     "clear of blocks."),
    (2, "Put the three blocks on H, I and J, no more than one block on any region."),
    (2, "Put the three blocks on H, I and J; there should never be more than one object in a region."),
    # more forms of the same classes
    (5, "Swap the red and blue blocks with red placed first, and move the yellow block to the opposite side "
     "at your convenience."),
    (1, "By the time you're done, the three blocks should be on the opposite side, red placed before blue."),
    (4, "Move the three blocks to the opposite regions without touching blue before red has been touched. "
     "When all of them are over, the yellow one goes back to G."),
    # one block per region said as a prohibition of two, or with the place first (non-native); "after this,"
    (2, "Put the three blocks on H, I and J, one on each, you can't have two on the same region."),
    (2, "Put the three block into region H, I, J, in each region only one block."),
    (4, "Move three blocks to opposite regions. Before red block is touched, blue block can not be touched. "
     "After this, put yellow block back to region G."),
    # after dev19: a polite tag, "possibly", "hoping the arms could", a swap wished in the past, "let's
    # have X go", "we'd like F to stay empty", "should have stayed empty", "first and end up on", "never
    # two on the same region", "X going down first and Y later"
    (1, "Could you get all three blocks to the opposite side? Red goes down before blue, if that's okay."),
    (3, "Could you possibly have the arms take the three pillars to E, F and G by arms a and b? Nothing may "
     "go on any other region."),
    (6, "I was hoping the arms could put the three objects on G, H and I, one per region, red before blue."),
    (5, "It would be nice if red and blue swapped positions, with red placed first; the yellow block goes to "
     "the opposite side at any time."),
    (8, "Let's have the yellow block go to region I first and then on to G. Red and blue go to any empty "
     "region at any time."),
    (7, "Put the three objects on region I one at a time, red before blue; we'd like F, G and H to stay "
     "empty during this period."),
    (7, "All three objects should be placed on region I one after another, red before blue, and F, G and H "
     "should have stayed empty throughout."),
    (8, "The yellow block should be on region I first and end up on region G; red and blue go to any empty "
     "region at any time."),
    (2, "Three blocks onto H, I and J; never two on the same region."),
    (6, "Put the three objects on G, H and I, one per region, with red going down first and blue later."),
    # near misses of the third and fourth rounds (unread then), read by this round's rules
    (6, "place the three objects separately on g h and i red placed first blue after"),
    (4, "Carry the three blocks to the opposite regions, leaving the blue block alone until the red one has "
     "been touched. To conclude, the yellow block goes back to G."),
]

REFUSED = [
    (6, "Have arm a place the three objects on G, H and I, one per region, red before blue."),  # one arm
    (1, "Let's not move the three blocks to the opposite side, red before blue."),
    (1, "It would be great if the three blocks went to the opposite side, red before blue, but I'm not "
     "sure."),
    (2, "I'd like the three blocks moved to H, I and J, two per region."),
    (8, "The yellow block went to region I. Red and blue go to any empty region at any time."),  # no wish
    (2, "The end result should be the three blocks on H, I and K, one per region."),  # no region K
    # a last step said before the goals it follows
    (4, "When you're done, the yellow block should be back on G. Move the three blocks to the opposite "
     "regions without touching blue before red has been touched."),
    (3, "Move the three pillars to E, F and G beside arms a and b, and put no object anywhere on the way "
     "there."),
    (4, "Move the three blocks to the opposite regions; don't touch blue until red has been touched. Once "
     "they are all hot, put yellow back on G."),
    (4, "Move the three blocks to the opposite regions, with blue left alone until G is empty, then put "
     "yellow back on G."),
    (6, "Place the red block first and the blue block on H later. Put the three objects on G, H and I, one "
     "per region."),
    (2, "Put the three blocks on H, I and J, never more than two blocks in a region."),
    (2, "Put the three blocks on H, I and J; there should never be more than two objects in a region."),
    (2, "Put the three blocks on H, I and J, you can't have three on the same region."),
    (2, "Put the three blocks on H, I and J, you can't have two on region H."),
    (2, "Put the three block into region H, I, J, in each region two blocks."),
    (1, "Could you get all three blocks to the opposite side? Red goes down before blue, if that's not "
     "hard."),
    (6, "I was hoping arm a could put the three objects on G, H and I, one per region, red before blue."),
    (7, "Put the three objects on region I one at a time, red before blue; we'd like F, G and K to stay "
     "empty during this period."),
    (8, "The yellow block should be on region I first and end up on region K; red and blue go to any empty "
     "region at any time."),
    (4, "Move three blocks to opposite regions. Before red block is touched, blue block can not be touched. "
     "After this one, put yellow block back to region G."),
    (8, "Yellow should visit region I and then finish on region K; red and blue should each end up on any "
     "empty region, whenever."),
]

OTHER = [
    # the order said after the blocks, the other way round
    (6, "Place the blue block first and the red block later. Put the three objects on G, H and I, one per "
     "region."),
    (1, "It would be great if the three blocks went to the opposite side, blue before red."),
    (6, "Put the three objects on G, H and I, one per region, with blue going down first and red later."),
    (6, "place the three objects separately on g h and i blue placed first red after"),
    (8, "Yellow should visit region I and then finish on region H; red and blue should each end up on any "
     "empty region, whenever."),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_fifth_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_fifth_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_fifth_round_forms_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("would you be able to move the red block to g", "move the red block to g"),
        ("i would like the red block put on g", "put the red block on g"),
        ("it would be great if the red block went to g", "move the red block to g"),
        ("by the end , the red block should be sitting on g", "at the end , the red block should be on g"),
        ("the red and blue blocks should have swapped places", "the red and blue blocks should swap places"),
        ("when that s all done , put it on g", "when that is all done , put it on g"),
        ("once they are all over , put it on g", "once that is done , put it on g"),
        ("with blue left alone until red is touched", ", blue must not be touched until red is touched"),
        ("place the red block first and the blue block later", "place the red block before the blue block"),
        ("keep f and g free of objects", "keep f and g empty"),
        ("never more than one object in a region", "one object per region"),
    ],
)
def test_wishes_and_final_states_in_words(text, expected):
    assert " ".join(unwished(text).split()) == expected


@pytest.mark.parametrize(
    "text",
    [
        "the red block went to g",  # a past event, not a wish
        "have arm a move the red block to g",  # one arm named
        "i would like the red block on g",  # no participle: left to the word tables
        "at the end , put the red block on g",  # already a last step
        "place the red block first and the blue block on h later",
        "place the red block first and the blue block next to it",
    ],
)
def test_other_forms_are_left_to_the_reader(text):
    assert unwished(text) == text
