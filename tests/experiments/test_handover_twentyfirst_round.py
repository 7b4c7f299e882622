"""Issue 24, h142 (session 24): four voices no batch used as such. A hurried supervisor's urgency ("Hurry
up.", "Chop chop!", "Need this done now:") and a teacher's words around the work ("Let me explain what the
arms have to do.", "Think of it like this:", "Here is what I want you to notice.", "Does that make
sense?") are the message's frame; a spec sheet's numbered goals ("Goal 1:", "Constraint 2:") are
identifiers, not steps, and its goal said as where the blocks are ("three blocks at the opposite side") is
the goal; "lands" is "goes"; a phone's "one block each region" is one per region; a terse "No other region
used." is the constraint it states, and a hesitation after a conjunction ("but uh dont touch") restates
nothing. "Quick, no time:" stays unread ("no time" may be "at no time", a constraint), and so does a list
of objects apart from its places ("Objects: pillars x3"). `dev98` and the held-out `validation32` are read
right or refused, never misread (the `sweep` run)."""

from __future__ import annotations

from handover_specs import round_tests

from nl2hltl2plan.language.handover_discourse import empty

READ = {
    1: ["Hurry up. Move the three blocks to the opposite side, the red block before the blue block. "
        "Chop chop!",
        "Goal: three blocks at the opposite side.\nConstraint: red block placed before blue block."],
    2: ["put the three blocks on h i and j one block each region"],
    3: ["Move the three pillars to regions E, F and G, next to arm a and arm b. No other regions are used.",
        "Need this done now: three pillars to E F and G, beside arm a and arm b. Nothing lands outside the "
        "target region."],
    4: ["Move the three blocks to the opposite regions, but uh dont touch the blue block until the red "
        "block has been touched, and after all that put the yellow block back on region G."],
    5: ["Let me explain what the arms have to do. First, remember that the red block must be placed before "
        "the blue block. The red and blue blocks swap places. And at any point, the yellow block goes to "
        "the opposite side. Does that make sense?",
        "Goal 1: swap the positions of the red and blue blocks.\nGoal 2: yellow block to the opposite "
        "side, any time.\nConstraint: red placed before blue."],
    7: ["Think of it like this: the three objects are placed on region I one after another, the red block "
        "before the blue block. While that is happening, regions F, G and H must stay empty."],
    8: ["Here is what I want you to notice. The yellow block goes to region I first, and only then to "
        "region G. The red and blue blocks can go to any empty region, whenever you like."],
}

REFUSED = [
    # "no time" may be "at no time" (a constraint): never dropped as a hurry
    (1, "Quick, no time: all three blocks over to the opposite side. Red goes down before blue. Move it."),
    # a region the constraint leaves free ("except H") that the task does not use
    (3, "Move the three pillars to regions E, F and G, next to arm a and arm b. No other regions used "
        "except H."),
    # the objects listed apart from the places they go to
    (3, "Objects: pillars x3\nGoal: regions E, F, G (arm a / arm b side)\nConstraint: no object on any "
        "region other than its target region."),
]

NEAR_MISSES = [
    # two blocks each region is not the one-block rule
    (2, "put the three blocks on h i and j two blocks each region"),
    # the order as said, not the task's: blue first
    (1, "Goal: three blocks at the opposite side.\nConstraint: blue block placed before red block."),
    # "Goal 2" after "Goal 1" adds no order of its own: without the constraint, red is not before blue
    (5, "Goal 1: swap the positions of the red and blue blocks.\nGoal 2: yellow block to the opposite "
        "side, any time."),
]

(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h142_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev98", "validation32"))


def test_urgency_and_a_teachers_asides_are_frame_but_not_a_constraint() -> None:
    for said in ("Hurry up", "Chop chop", "Quick as you can", "Does that make sense", "Think of it like this",
                 "Let me explain what the arms have to do", "Sharpish"):
        assert empty(said, whole=True), said
    # a time, a negation or a place stays to be read
    for said in ("At no time", "No time", "Hurry up to region G", "Think of the red block"):
        assert not empty(said, whole=True), said
