"""Issue 24, h148 (session 24): instructions said as the END STATE rather than as a command ("By the end I
want X on Y", "At the end, X should be / sit / have been ...", "I'd like X on Y", "The goal is X on Y",
"X sitting on Y"), written before any rule: a development part (`DEV_*`, read by the tests) and a held-out
part written at the same time (`HELD_*`, read only by the `sweep` test, scored once at the end)."""

from __future__ import annotations

DEV_TABLETOP: dict[int, list[str]] = {
    1: ["By the end I want the green apple sitting on the blue plate and the orange on the yellow plate.",
        "At the end, the orange should be on the yellow plate and the green apple on the blue plate, in any "
        "order."],
    2: ["I'd like the green apple on the pink plate, the orange on the yellow plate and the red apple on the "
        "blue plate, in any order.",
        "The goal is the green apple on the pink plate, the orange on the yellow plate and the red apple on "
        "the blue plate. Any order is fine."],
    3: ["By the end I want the carrot on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate, in any order.",
        "At the end, the carrot should sit on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate, in any order."],
    4: ["First I want the green apple and the orange sitting on the yellow plate. After that, I'd like the "
        "carrot and the red apple on the blue plate, in any order.",
        "Goal 1: the green apple and the orange on the yellow plate.\nGoal 2 (after goal 1): the carrot and "
        "the red apple on the blue plate."],
}

HELD_TABLETOP: dict[int, list[str]] = {
    1: ["In the end, I'd like the orange sitting on the yellow plate and the green apple sitting on the blue "
        "plate, any order.",
        "The goal is the green apple on the blue plate and the orange on the yellow plate."],
    2: ["By the end I want the red apple on the blue plate, the green apple on the pink plate and the orange "
        "on the yellow plate, order doesn't matter.",
        "At the end, the green apple should sit on the pink plate, the orange on the yellow plate and the "
        "red apple on the blue plate, in whatever order."],
    3: ["I'd like the carrot on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate and the red apple on the pink plate, in any order.",
        "The goal is the carrot sitting on the blue plate, the orange on the yellow plate, the green apple "
        "on the green plate and the red apple on the pink plate, in any order."],
    4: ["At the end, the carrot and the red apple should be on the blue plate, but only after the green "
        "apple and the orange are on the yellow plate.",
        "Goal 1: the green apple and the orange on the yellow plate.\nGoal 2 (once goal 1 is done): the "
        "carrot and the red apple on the blue plate, in any order."],
}

DEV_HANDOVER: dict[int, list[str]] = {
    1: ["At the end, the three blocks should be at the opposite side, with the red block placed before the "
        "blue block."],
    2: ["At the end, the three blocks should sit on regions H, I and J, exactly one block per region."],
    3: ["At the end, the three pillars should sit on regions E, F and G, beside arm a and arm b, and no "
        "other region should ever have been used."],
    4: ["At the end, the three blocks should be in the opposite regions; the arms must not touch the blue "
        "block until the red block has been touched; after all that, the yellow block should be back on "
        "region G."],
    5: ["At the end, the red and blue blocks should have exchanged positions, with red placed first, and at "
        "any time the yellow block should go to the opposite side."],
    6: ["By the end I want the three objects on regions G, H and I, one each, with the red block placed "
        "before the blue block."],
    7: ["The goal is the three objects on region I, one after another, the red block before the blue block; "
        "regions F, G and H stay empty during this period."],
    8: ["I'd like the yellow block on region I first and then on region G, and the red and blue blocks on "
        "any empty region at any time."],
}

HELD_HANDOVER: dict[int, list[str]] = {
    1: ["By the end I want all three blocks sitting at the opposite side, the red block placed before the "
        "blue block."],
    2: ["The goal is the three blocks on regions H, I and J, one block per region."],
    3: ["By the end, the three pillars should be on regions E, F and G, next to arm a and arm b, and no "
        "other region should have been used."],
    4: ["By the end I want the three blocks in the opposite regions, with no arm touching the blue block "
        "until an arm has touched the red block, and after all of that the yellow block back on region G."],
    5: ["At the end, the red and blue blocks should have swapped positions, the red block placed before the "
        "blue block, and the yellow block should be on the opposite side at any time."],
    6: ["At the end, the three objects should sit on regions G, H and I, one per region, and the red block "
        "should be placed before the blue block."],
    7: ["I'd like the three objects on region I one after another, red block before blue block, and no "
        "object should be on region F, G or H during this period."],
    8: ["At the end, the yellow block should have been on region I first and then on region G, and the red "
        "and blue blocks should be in any empty region, at any time."],
}
