"""Issue 24, h98 (session 18): the world's one-block rule in new words, discourse openers that close the
steps said so far ("Once that's sorted,", "With that done,"), "left alone until" touch guards, a record's
"Protocol 4." header; the arms named as the subject are refused by name (which arms act is the plan's
choice), and so are "after all of these" after goals said "at any time" (it would order them). `dev80`
must give the written specs but for the sentences refused on purpose; `validation18`, held out, is read
right or refused, never misread; `dev81` (a forum post, a recipe, a teacher, legal English) as `dev80` (all
three in the `sweep` run)."""

from __future__ import annotations

from handover_specs import round_tests

READ = {
    2: [
        "Put the three blocks on regions H, I and J; no region may hold two blocks.",
        "I need the three blocks on regions H, I and J, one block in each of them. Any help appreciated!",
        "The three blocks go to regions H, I and J, and a region never gets more than one block.",
    ],
    1: [
        "Transfer the three blocks to the opposite side, red before blue, and no doubling up on a region.",
        "Now, class, the arms have to carry all three blocks across to the opposite side, and remember, red "
        "goes down before blue.",
    ],
    7: [
        "Ingredients: three objects. Method: place them one after another on region I, the red before the "
        "blue. Keep regions F, G and H empty throughout.",
    ],
    6: [
        "The red block should be placed before the blue block. Place the three objects on regions G, H and "
        "I, never two in one spot.",
        "Red before blue. Never put two blocks in one region: the three objects go on regions G, H and I.",
    ],
    4: [
        "Transfer three blocks into the opposite regions. The arm cannot touch the blue block until an arm "
        "has touched the red block. Once that's sorted, put the yellow block back on region G.",
        "Transfer three blocks into the opposite regions. The blue block is left alone until the red block "
        "has been touched. With that done, the yellow block goes back to region G.",
        "The three blocks shall be transferred to the opposite regions. No arm shall touch the blue block "
        "unless and until the red block has been touched. Upon completion of the foregoing, the yellow block "
        "shall be returned to region G.",
        "Protocol 4. Step 1: transfer the three blocks to the opposite regions. Step 2: the blue block "
        "must not be touched until the red block has been touched. Step 3: after all of these, return the "
        "yellow block to region G.",
    ],
    8: [
        "Place the yellow block on region I. With that done, place it on region G. Move the red and blue "
        "blocks to any empty region at any time.",
        "Place the yellow block on region I. Once that is taken care of, place it on region G. The red and "
        "blue blocks go to any empty region at any time.",
    ],
}

REFUSED = [
    # the arms that do the work: the plan chooses them
    (
        1,
        "Arm a and arm b shall move the three blocks to the opposite side, the red block before the blue "
        "block.",
    ),
    (6, "Arm c and arm d place the three objects separately on regions G, H and I; red goes before blue."),
    # "once that is done" after goals said "at any time" would order them after those goals
    (
        8,
        "Move the red and blue blocks to any empty region at any time. Place the yellow block on region I. "
        "Once that is done, place it on region G.",
    ),
    # regions "left alone": no block placed, or none picked up? (blocks start on regions)
    (
        7,
        "The red block should be placed before the blue block. Place the three objects one after another on "
        "region I; regions F, G and H are left alone during this period.",
    ),
]

NEAR_MISSES = [
    # the guard reversed, and a rule about two blocks that is not the one-block rule
    (
        4,
        "Transfer three blocks into the opposite regions. The red block is left alone until the blue block "
        "has been touched. With that done, the yellow block goes back to region G.",
    ),
    (2, "Put the three blocks on regions H, I and J; no region may hold three blocks."),
]


(
    test_new_wordings_give_the_written_spec,
    test_unreadable_classes_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h98_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev80", "dev81", "validation18"))
