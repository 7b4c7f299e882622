"""Issue 24, fourth round (h60): the letter around a command (greetings and sign-offs), a count set off
after its noun ("the blocks, all three, ..."), "shan't", a time said before a scene statement ("right now,
the red block is on G"), "another region" / "the other regions" in a prohibition, "during this", "one to a
region", enumerated steps in words and letters, verbless fragments and labelled records. Each class has
sentences of our own that must give the written spec and near misses that must be refused (never the
written spec)."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.handover_discourse import plain
from nl2hltl2plan.language.handover_spoken import unspoken

READ = [
    # a greeting before the first command, a sign-off (with a name) after the last one
    (6, "Good morning everyone! Place the three objects on G, H and I, one per region, with red before blue. "
     "Many thanks,\nSam"),
    (8, "Hey there: first put the yellow block on region I, then on region G; the red and blue blocks go to "
     "any empty region at any time. Cheers, team"),
    # "shan't" is "shall not" (the spoken step would leave "sha not")
    (7, "Put the three objects on region I one after another, red before blue; you shan't place anything on "
     "F, G or H meanwhile."),
    # a time before a scene statement keeps it a statement of the scene
    (4, "At this point the red block sits on region G. Move the three blocks to the opposite regions, but "
     "don't touch the blue block until the red one has been touched. After all of this, return the yellow "
     "block to region G."),
    # a count set off after its noun, by commas or parentheses
    (1, "Move the blocks (all three) across to the opposite side, red before blue."),
    (5, "Swap the red and blue blocks, both of them, with red placed first, and move the yellow block to the "
     "opposite side at any time."),
    (6, "Put the objects, every one of them, on G, H and I, one to a region; red goes before blue."),
    # "another region" in a prohibition: every labelled region but the targets
    (3, "Move the three pillars to regions E, F and G, and never put an object on another region."),
    # enumerated steps in words and letters
    (8, "Stage 1: put the yellow block on region I. Stage 2: move it on to region G. Red and blue go to any "
     "empty region at any time."),
    (6, "a) Place the three objects on G, H and I, one per region. b) Red is placed before blue."),
    (4, "First thing: carry the three blocks to the opposite regions without touching blue before red has "
     "been touched. Second thing: the yellow block goes back to G."),
    # labelled records, in sentences or on lines, in either order; a place heading with its modifier
    (2, "Where: regions H, I and J, one block each. What: the three blocks."),
    (3, "Target area: regions E, F and G beside arms a and b\nObjects: the three pillars\nRule: no object "
     "on any other region"),
    (7, "Target: region I, all three objects in turn. Order: red before blue. Meanwhile: nothing on F, G or "
     "H."),
    # verbless bullets: places first before what may not go there, a pair before its exchange; a dash or a
    # parenthesis after a region list
    (7, "- all three objects → region I, one after another\n- red before blue\n- F, G, H: nothing placed"),
    (5, "- red and blue: swap places (red first)\n- yellow: opposite side, whenever"),
    (6, "• objects: G, H, I — one per region\n• red first, then blue"),
    (6, "Objects: G, H, I (one per region). Red before blue."),
    # headings of procedures and presentations: labels of the whole text, of a rule (with a modifier or
    # its period), of what it is about ("Scope:", "You will need:": every block of the scene), the verb
    # after a blocks' heading; "check that", "to conclude", "while you're at it", "leaving X untouched"
    (3, "Scope: the three pillars. Action: take them to regions E, F and G beside arms a and b. Warning: no "
     "object may go on any other region."),
    (7, "Important: red before blue. Work instructions: put the three objects on region I one after "
     "another. Rule for the whole task: regions F, G and H stay empty."),
    (4, "Carry the three blocks to the opposite regions, keeping the blue block untouched until the red one "
     "has been touched. To conclude, the yellow block goes back to G."),
    (6, "Set the three objects out on G, H and I, 1 each. Check that red is placed before blue."),
    (8, "Here's what needs doing: yellow block to region I, then to region G. Red and blue blocks: move to "
     "any empty region at any time."),
    (2, "Here's what I want: the three blocks on H, I and J, one per region. All done."),
    (7, "Put the three objects on region I one after another, red before blue, and while you're at it, keep "
     "F, G and H empty."),
    # run-on and dictated forms: "but" before a negated command, an unpunctuated count after its noun, a
    # verbless step after "first", "then region G", a heading of counts
    (4, "carry the blocks all three to the opposite regions but never touch the blue one until the red one "
     "has been touched and after all of that put the yellow one back on g"),
    (8, "first yellow to region i then region g and red and blue to any empty region at any time"),
    (6, "Three objects, three regions: G, H and I, one each. Red before blue."),
    # registers (handover_registers): academic nouns, narrative subjects and periods, emphasis
    (1, "The objective is the relocation of all three blocks to the opposite side, with the red block placed "
     "prior to the blue block."),
    (3, "The three pillars are to be moved to regions E, F and G beside arms a and b; placements on any "
     "region other than these are forbidden."),
    (4, "The arms carry the three blocks to the opposite regions; do not touch the blue block until you have "
     "touched the red block. After that, the yellow block goes back to G."),
    (5, "The red and blue blocks trade places, red placed first, and somewhere along the way the yellow "
     "block goes to the opposite side."),
    (7, "The three objects must be placed on region I one after another, red before blue, while regions F, "
     "G and H stay empty."),
    (2, "Put the three blocks on H, I and J. Only one block can go on each one."),
    (8, "The yellow block must be put on I and then on G; the red and blue blocks are each to be moved to an "
     "arbitrary empty region at any time."),
    (2, "Three blocks onto H, I and J, one per region, no exceptions."),
    # one block per bullet to the same regions, under the one-block rule: at once, as one clause says it
    (6, "- red: G, H or I\n- blue: G, H or I\n- yellow: G, H or I\n- one per region, red before blue"),
    (6, "red -> G/H/I, blue -> G/H/I, yellow -> G/H/I; one per region; red before blue"),
    # a later step said inside the sentence
    (8, "First step, put the yellow block on region I, second step, put it on region G. Red and blue go to "
     "any empty region at any time."),
]

REFUSED = [
    # a greeting that names one arm says who acts; a "signature" that names a block
    (6, "Hi arm a, place the three objects on G, H and I, one per region, red before blue."),
    (2, "Put the three blocks on H, I and J, one per region. Thanks, Yellow"),
    # a scene statement after its time that the layout contradicts
    (4, "Right now the red block is on region H. Move the three blocks to the opposite regions, but don't "
     "touch the blue block until the red one has been touched. After all of this, return the yellow block "
     "to region G."),
    # a count that is not the noun's (three pillars), or a part of the group ("two of them": which two?)
    (3, "The pillars, both of them, go to regions E, F and G; no object goes on any other region meanwhile."),
    (1, "The blocks, two of them, go to the opposite side, red before blue."),
    # "another region" as a goal says nowhere in particular
    (1, "Move the red block to another region, and the three blocks to the opposite side, red before blue."),
    # "after this" is no period; "shan't" before an order negates it; "one to two regions" is no rule
    (7, "Place the objects on region I one after another, red before blue; regions F, G and H stay empty "
     "after this."),
    (1, "Move the three blocks to the opposite side; the red block shan't be placed before the blue block."),
    (2, "Put the three blocks on H, I and J, one to two regions."),
    # steps numbered out of the text's order; "(e)" is region E, not a list's letter
    (8, "Step 2: yellow block to region G. Step 1: yellow block to region I. Red and blue blocks to any "
     "empty region at any time."),
    (6, "(e) Place the three objects on G, H and I, one per region. (f) Red before blue."),
    # a verb the heading does not read; region I left out of a list is never dropped as the pronoun "I"
    (7, "- all three objects → region I, one after another\n- red before blue\n- F, G, H: nothing removed"),
    (6, "Put the three objects on G, H, also I. Red before blue."),
    # a scope that is not the whole scene; "to start", "check whether": not read
    (1, "You will need: the red and blue blocks. Method: move each block to the opposite side, red before "
     "blue."),
    (4, "Carry the three blocks to the opposite regions, leaving the blue block untouched until the red one "
     "has been touched. To start, the yellow block goes back to G."),
    (6, "Set the three objects out on G, H and I, 1 each. Check whether red is placed before blue."),
    (7, "Put the three objects on region I one after another, red before blue, and during it, keep F, G and "
     "H empty."),
    # "but" before a command that is not read; a count that is not the noun's; a heading whose regions'
    # count is not their number
    (1, "Move all blocks to the opposite side but don't move red. Red before blue."),
    # ", after put": "then put", or "after putting"? (an "after" before a verb stays unread)
    (8, "Put yellow block on region I first, after put it on region G; red and blue block to any empty "
     "region any time."),
    (3, "the pillars both go to e f g by the arms a and b and don't put anything on the other regions"),
    (6, "Three objects, three regions: G and H, one each. Red before blue."),
    # the same registers with a meaning changed or a word they do not read
    (1, "The objective is the relocation of the red block to the opposite side, with the red block placed "
     "prior to the blue block."),
    (3, "The three pillars are to be moved to regions E, F and G beside arms a and b; placements on any "
     "region other than these are welcome."),
    (4, "The arms carry the three blocks to the opposite regions; do not touch the blue block until you have "
     "moved the red block. After that, the yellow block goes back to G."),
    (7, "The three objects must be placed on region I one after another, red before blue, while regions F, "
     "G and H stay full."),
    (2, "Put the three blocks on H, I and J. Only one block can go on each block."),
]

# records that say something else: read as they say, never as the written spec
OTHER = [
    (6, "Objects: red and blue. Regions: G, H and I, one each. Order: red before blue."),
    (2, "Blocks: all three\nTargets: H and I"),
    (5, "- red and yellow: swap places (red first)\n- blue: opposite side, whenever"),
    (1, "Scope: the three blocks. Action: move them to the opposite side. Warning: blue before red."),
    # per-block goals without the one-block rule, or to different region sets: no "at once"
    (6, "red -> G/H/I, blue -> G/H/I, yellow -> G/H/I; red before blue"),
    (6, "red -> G/H/I, blue -> G/H, yellow -> G/H/I; one per region; red before blue"),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_fourth_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_fourth_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_records_and_headings_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


@pytest.mark.parametrize(
    ("sentences", "expected"),
    [
        (["Dear robots, move the red block to G", "Kind regards"], ["move the red block to G"]),
        (["Morning folks - move the red block to G", "Thanks in advance"], ["move the red block to G"]),
        (["Hi robots", "Move the red block to G, cheers"], ["Move the red block to G"]),
        (["Move the red block to G", "Best", "Ana"], ["Move the red block to G"]),
        (["Move the red block to G", "Kind regards, Ana"], ["Move the red block to G"]),
        (["Good afternoon", "Move the red block to G", "Thanks a lot!", "Done"], ["Move the red block to G"]),
        (["Okay, awesome", "Steps: move the red block to G"], ["move the red block to G"]),
        (["Here's the idea: move the red block to G", "Cool"], ["move the red block to G"]),
    ],
)
def test_greetings_and_sign_offs_are_dropped(sentences, expected):
    assert plain(sentences) == expected


@pytest.mark.parametrize(
    ("sentences", "kept"),
    [
        (["Hi arm b, move the red block to G"], "Hi arm b"),  # names who acts
        (["Move the red block to G", "Thanks, Blue"], "Blue"),  # a name the reader knows
        (["Hey all three blocks go to G"], "Hey all three"),  # "all" is the blocks' count here
        (["Move the red block to G", "Ana"], "Ana"),  # a name that signs no sign-off
        (["Done: move the red block to G"], "Done"),  # says what is done
        (["Put red on H, blue on I, and so on"], "so on"),  # "and so on": more goals, unsaid
        (["This morning, put red on H"], "This morning"),  # says when
    ],
)
def test_other_greetings_and_thanks_are_left_to_the_reader(sentences, kept):
    assert kept in " ".join(plain(sentences))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("right now , the red block is on g", "currently the red block is on g"),
        ("as things stand the red one sits on region g", "currently the red one sits on region g"),
        ("right now , move the blocks to h", "move the blocks to h"),  # no statement: a filler
        ("we shan't place anything on f", "do not place anything on f"),
    ],
)
def test_scene_times_and_shant_in_words(text, expected):
    assert unspoken(text) == expected
