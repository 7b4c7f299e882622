"""Issue 24, eighth round (h69). Forms read in this round, each with sentences of our own that must give
the written spec and near misses that must be refused or give another spec (never the written one):

- a note's label before a rule ("Careful: ...", "Note: ...", "Heads up: ...", "N.B. ...", "Please note
  that ...") and a reminder of a prohibition ("remember not to put ...", "be sure not to touch ...");
- the whole team addressed inside a clause or step ("Then, robots, put ..."); never one arm by name;
- progressive narration ("nothing is being placed on F", "nobody is touching X until ...", "we are
  putting ..."), "you are not going to VERB", the plan said as what one would do ("you'd move ...");
- a user story's role ("As the operator, I want ..."), a need after a step word ("After that, I want X
  back on G"), manner adverbs that every plan already meets ("carefully", "quickly"; "gently" stays
  refused), polite tags ("if you don't mind", "when you get a chance");
- particle verbs ("drop X off on G", "keep off X until ...") and an open checklist box ("[ ] ...");
- a clause added with "plus", "on top of that", "as well as keeping"; what is said "before you start" or
  "first things first" comes first; a sentence that only cheers ("Great!", "Here we go!") is dropped;
- office English ("kindly", "do the needful", "itself") and a requirement's identifier ("R1:", "REQ-2:");
- "let X VERB" ("let nothing be placed on F", "don't let anyone touch X until ..."), a group in other words
  ("the whole lot of blocks", "every single block", "the trio of objects"), a range of region letters
  ("regions H through J") and "slot" for a region;
- "first off" / "to start with" (the step comes first), "bear in mind" without "that", "at no point"
  (never; "at no point may a region hold ..."), "no restrictions on when" (at any time). A negated order
  ("under no circumstances place blue before red") stays refused.
"""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_refused_by_name, assert_written_spec

READ = [
    # a note's label before a rule or a goal
    (1, "Get all three blocks over to the opposite side. Be careful: red has to go down before blue."),
    (2, "Place the three blocks on H, I and J. Please note: only one block per region."),
    (7, "Put the three objects on region I, one after another, red before blue. Heads-up: nothing goes on "
     "F, G or H during this period."),
    (5, "Swap red and blue, with red placed first. N.B. the yellow block goes to the opposite side at any "
     "time."),
    (8, "Yellow block to region I first, then to region G. Keep in mind that red and blue go to any empty "
     "region at any time."),
    # the whole team addressed inside a clause or a step
    (4, "Take the three blocks to the opposite regions and, robots, leave the blue block alone until the red "
     "block has been touched. After all of that, everyone, put the yellow block back on G."),
    (6, "Then, team, place the three objects separately on G, H and I, red before blue."),
    # progressive narration
    (3, "The arms are bringing the three pillars to E, F and G beside arms a and b, and no object is being "
     "put on any other region."),
    (4, "We are taking the three blocks to the opposite regions, and nobody is touching the blue block until "
     "the red block has been touched. Once that's all done, we are returning the yellow block to G."),
    # "you are not going to VERB"
    (2, "You're going to place the three blocks on H, I and J, and you're not going to put two blocks on "
     "one region."),
    # a user story's role; a need after a step word; manner adverbs
    (3, "As the lab technician, I need the three pillars moved to E, F and G beside arms a and b, and "
     "nothing placed on any other region."),
    (4, "Move the three blocks to the opposite regions, and don't touch the blue block until the red block "
     "has been touched. Then I want the yellow block back on region G."),
    (7, "Swiftly place the three objects on region I one after another, red before blue, and cautiously keep "
     "F, G and H empty during this period."),
    # the plan said as what one would do; open checklist boxes
    (2, "Ideally you would put the three blocks on H, I and J, and you would never put two blocks on one "
     "region."),
    # "plus", "on top of that"; "before you start"; cheers
    (7, "Cool, here we go! Put the three objects on region I one after another, red before blue. On top of "
     "that, nothing may be placed on F, G or H during this period."),
    (5, "Before you begin, know that red must be placed before blue. Exchange the red and blue blocks, plus "
     "take the yellow block to the opposite side at any time."),
    # office English; requirement identifiers
    (4, "Kindly move the three blocks to the opposite regions and do the needful so that blue is not touched "
     "until red has been touched. Once all that is done, kindly return yellow to G itself."),
    (2, "REQ-1: the three blocks go onto H, I and J. REQ-2: each region holds one block only."),
    # "let"; a group in other words; a range of regions; "slot"
    (7, "Let the trio of objects go on region I one after another, red before blue, and let nothing be "
     "placed on regions F through H during this period."),
    (4, "Move the whole lot of blocks to the opposite regions, but don't let anybody touch the blue block "
     "until the red block has been touched. After all of that, return the yellow block to slot G."),
    # discourse ordinals; "bear in mind"; "at no point"; "no restrictions on when"
    (3, "First off, take the three pillars to regions E, F and G beside arms a and b. Bear in mind, at no "
     "point put anything on any other region."),
    (8, "To start with, put the yellow block on region I, then on region G, and move the red and blue blocks "
     "to any empty region - no restrictions on when."),
    # reminders, polite tags, particle verbs
    (3, "Bring the three pillars to E, F and G beside arms a and b, if that's okay, and be sure not to put "
     "anything on any other region."),
    (4, "When you have a minute, move the three blocks to the opposite regions and stay away from the blue "
     "block until the red block has been touched. Then drop the yellow block back off on G."),
    (4, "[ ] take the three blocks to the opposite regions\n[ ] hands off the blue block until the red block "
     "has been touched\n[ ] after all of that, yellow back on G"),
]

REFUSED = [
    # a note that says what the reader does not model, or names a region the world lacks
    (1, "Move all three blocks to the opposite side, red before blue. Tip: use arm c for the red block."),
    (8, "Put the yellow block on region I, then on region G. Please note that red and blue go to region K "
     "at any time."),
    # one arm by name says who acts: not read as an address
    (4, "Move the three blocks to the opposite regions, and don't touch the blue block until the red block "
     "has been touched. Then, arm a, put the yellow block back on region G."),
    (4, "Move the three blocks to the opposite regions, and don't touch the blue block until the red block "
     "has been touched. After that, arms a and b, put the yellow block back on region G."),
    (7, "We're placing the three objects on region I one after another, red before blue, and nothing is "
     "being placed on regions F, G or K during this period."),
    # a role that is no person; a manner word outside the list ("immediately" may say when)
    (1, "As the red block, I want to go to the opposite side before the blue block, and move all three "
     "blocks there."),
    (1, "Immediately move all three blocks to the opposite side, red before blue."),
    # a way of moving that the planner does not model
    (6, "Gently place the three objects on regions G, H and I, one per region, red before blue."),
    # "on top of that" as a place
    (8, "Put the red block on top of that, and move the yellow block to region I and then to region G."),
    # "do the needful" alone asks for nothing
    (6, "Kindly do the needful."),
    # a range the wrong way round, or past the world's regions
    (2, "Put the three blocks on regions J through H, one block per region."),
    (2, "Put the three blocks on regions H to K, one block per region."),
    # a negated order
    (6, "Place the three objects on regions G, H and I, one per region, and under no circumstances place "
     "the blue one before the red one."),
    # a condition is no polite tag
    (6, "If the red block is on G, place the three objects on regions G, H and I, one per region, red before "
     "blue."),
    # a ticked box says what is done, not what to do
    (5, "[x] swap the red and blue blocks, red placed first\n[ ] yellow block to the opposite side, at any "
     "time"),
    # a permission is not a command
    (8, "Put the yellow block on region I and then on region G, and feel free to move the red and blue "
     "blocks to any empty region at any time."),
]

OTHER = [
    # the noted order the other way round
    (1, "Move all three blocks to the opposite side. Note: the blue block goes down before the red block."),
    (6, "Place the three objects on regions G, H and I, one per region, and, team, place the blue one before "
     "the red one."),
    # the touch guard the other way round; one region left out of the prohibition
    (4, "We're moving the three blocks to the opposite regions, and nobody is touching the red block until "
     "the blue block has been touched. After all of this, we're putting the yellow block back on region G."),
    (7, "You're going to place the three objects on region I one after another, red before blue, and you're "
     "not going to place anything on regions F or G during this period."),
    (6, "Carefully place the three objects on regions G, H and I, one per region, and quickly place the blue "
     "one before the red one."),
    # what is done before the work starts is a first step
    (4, "Before you start, move the red block to region G. Move the three blocks to the opposite regions, "
     "and don't touch the blue block until the red block has been touched. After all of that, put the "
     "yellow block back on region G."),
    (6, "R1: the three objects are placed on regions G, H and I, one per region. R2: blue is placed before "
     "red."),
    (1, "Move all three blocks to the opposite side, and let the blue block go down before the red block."),
    (7, "Place the three objects on region I one after another, red before blue, and put nothing on "
     "regions F to G during this period."),
    (5, "First off, move the yellow block to the opposite side. Then swap the red and blue blocks, red "
     "placed first."),
    (1, "Move all three blocks to the opposite side, plus the blue block has to be placed before the red "
     "block."),
    (3, "Take the three pillars to regions E, F and G beside arms a and b, and remember not to put any "
     "object on regions H and I."),
    (1, "You would move all three blocks to the opposite side, and you would place the blue block before the "
     "red block."),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_eighth_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_eighth_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_eighth_round_forms_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)
