"""Issue 24, h161 (session 26): handover and tabletop rephrasings in voices the paper's users might use,
written before any rule: a development part (`DEV_HANDOVER`, `DEV_TABLETOP`, read by the tests) and a
held-out part written at the same time (`HELD_HANDOVER`, `HELD_TABLETOP`, scored once at the end, read
right or refused by the `sweep` test).

Classes (key: the Table III task each sentence restates):
- "touch_guard_with": the task-4 guard said as "with the arms not touching ... until ...", "with no arm
  touching ...";
- "modal_perfect": an end state with a modal in the perfect ("should have gone to any empty region");
- "steps_partly_freed": labelled or numbered steps, some of them freed by a later sentence ("Step 3 may
  happen at any time", "Steps 1 to 3 may happen in any order");
- "voices": terse notation, numbered lists, passive, "make sure", "don't let", "at no point", "while",
  "as long as".
"""

from __future__ import annotations

DEV_HANDOVER: dict[str, dict[int, list[str]]] = {
    "touch_guard_with": {
        4: ["Move the three blocks to the opposite regions, with the arms not touching the blue block until "
            "an arm has touched the red block. After that, put the yellow block back on region G.",
            "Transfer the three blocks into the opposite regions, with no arm touching the blue block until "
            "an arm has touched the red block. After all of these, place the yellow block back on region G."],
    },
    "modal_perfect": {
        8: ["First put the yellow block on region I, then put it on region G. The red and blue blocks should "
            "have gone to any empty region, at any time."],
        2: ["The three blocks should have gone to regions H, I and J, one block per region."],
    },
    "steps_partly_freed": {
        5: ["Step 1: put the red block where the blue block is. Step 2: put the blue block where the red "
            "block was. Step 3: put the yellow block on the opposite side. Step 3 may happen at any time."],
        8: ["Step 1: put the yellow block on region I. Step 2: put the yellow block on region G. Step 3: put "
            "the red block on any empty region. Step 4: put the blue block on any empty region. Steps 3 and "
            "4 may happen at any time."],
    },
    "voices": {
        7: ["Red before blue. All three objects to region I, one after another. At no point may an object "
            "be placed on region F, G or H during this period.",
            "Place the red block before the blue block, and put the three objects on region I one after "
            "another. Don't let any object be placed on regions F, G and H during this period."],
        6: ["1. The red block is placed before the blue block. 2. The three objects are placed separately "
            "on regions G, H and I."],
        3: ["Make sure the three pillars end up on regions E, F and G, next to arm a and arm b, and make "
            "sure no object is placed on any other region."],
        1: ["Move the three blocks to the opposite regions, as long as the red block is placed before the "
            "blue block."],
        4: ["While moving the three blocks to the opposite regions, the arms cannot touch the blue block "
            "until an arm has touched the red block. After all of that, put the yellow block back on "
            "region G."],
    },
}

HELD_HANDOVER: dict[str, dict[int, list[str]]] = {
    "touch_guard_with": {
        4: ["Put the three blocks on the opposite regions, with the robot arms not touching the blue block "
            "until one of them has touched the red block. Then place the yellow block back on region G.",
            "Transfer three blocks into the opposite regions with neither arm touching the blue block until "
            "the red block has been touched by an arm; after that, the yellow block goes back to region G."],
    },
    "modal_perfect": {
        8: ["The yellow block goes to region I first and then to region G; the red block and the blue block "
            "should have been moved to any empty region at any time."],
        1: ["The red block should be placed before the blue block, and the three blocks should have gone to "
            "the opposite regions."],
    },
    "steps_partly_freed": {
        6: ["Step 1: put the red block on region G, H or I. Step 2: put the blue block on region G, H or I. "
            "Step 3: put the yellow block on region G, H or I, one block per region. Step 3 can happen at "
            "any time."],
        8: ["1. Put the yellow block on region I. 2. Put the yellow block on region G. 3. Put the red block "
            "on any empty region. 4. Put the blue block on any empty region. Steps 3 and 4 can be done at "
            "any time."],
    },
    "voices": {
        7: ["Red block before blue block; all three objects onto region I one after another; no object on "
            "regions F, G or H during this period.",
            "Make sure the red block is placed before the blue block. The three objects are placed on region "
            "I one after another, and at no point during this period is an object placed on F, G or H."],
        6: ["1) Place the red block before the blue block. 2) Place the three objects separately on regions "
            "G, H and I."],
        3: ["The three pillars should be moved to regions E, F and G beside arm a and arm b; don't let any "
            "object be placed on a region other than those."],
        2: ["Make sure each of regions H, I and J ends up with exactly one of the three blocks."],
        4: ["As long as no arm touches the blue block until an arm has touched the red block, move the three "
            "blocks into the opposite regions. After all of these, put the yellow block back on region G."],
    },
}

DEV_TABLETOP: dict[int, list[str]] = {
    1: ["1. Green apple -> blue plate. 2. Orange -> yellow plate. Any order."],
    2: ["Make sure the green apple ends up in the pink plate, the orange in the yellow plate and the red "
        "apple in the blue plate; the order is up to you."],
    3: ["The carrot is placed in the blue plate, the orange in the yellow plate, the green apple in the "
        "green plate and the red apple in the pink plate, in any order."],
    4: ["Put the carrot and the red apple in the blue plate in any order, as long as the green apple and the "
        "orange are in the yellow plate first."],
}

HELD_TABLETOP: dict[int, list[str]] = {
    1: ["green apple: blue plate; orange: yellow plate"],
    2: ["1) Green apple in the pink plate. 2) Orange in the yellow plate. 3) Red apple in the blue plate. "
        "Do these in any order."],
    3: ["Make sure that the carrot is in the blue plate, the orange in the yellow plate, the green apple in "
        "the green plate and the red apple in the pink plate. Any order is fine."],
    4: ["The green apple and the orange are placed in the yellow plate first. Only after that are the carrot "
        "and the red apple placed in the blue plate, in any order."],
}

# Added after the held-out part was written, while probing the tabletop steps (development only, no
# held-out counterpart): runs of numbered steps freed by number, and a free-order remark inside each item
# of a numbered list.
DEV_TABLETOP_STEPS: dict[int, list[str]] = {
    4: ["Step 1: put the green apple in the yellow plate. Step 2: put the orange in the yellow plate. "
        "Step 3: put the carrot in the blue plate. Step 4: put the red apple in the blue plate. Steps 1 and "
        "2 may happen in any order, and so may steps 3 and 4.",
        "1. Put the green apple in the yellow plate. 2. Put the orange in the yellow plate. 3. Put the "
        "carrot in the blue plate. 4. Put the red apple in the blue plate. The first two steps can be done "
        "in either order, and so can the last two.",
        "1) Put the green apple in the yellow plate. 2) Put the orange in the yellow plate. 3) Put the "
        "carrot in the blue plate. 4) Put the red apple in the blue plate. Steps 1 and 2 in either order; "
        "steps 3 and 4 in either order.",
        "1) Put the green apple in the yellow plate and put the orange in the yellow plate, in any order. "
        "2) Put the carrot in the blue plate and put the red apple in the blue plate, in any order."],
}
