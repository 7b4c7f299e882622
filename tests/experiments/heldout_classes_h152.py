"""Issues 24 and 28, h152 (session 25): six classes of rephrasing that the handover and tabletop readers
refused, written before any rule: a development part (`DEV_*`, read by the tests) and a held-out part
written at the same time (`HELD_*`, read only by the `sweep` test, scored once at the end).

Handover classes (key: the Table III task each sentence restates):
- "at_end_then": an "At the end" goal followed by a later step in a sentence of its own;
- "stacked": the objects "should be stacked / piled ... one at a time";
- "perfect": an end state in the perfect ("should have been on I and then on G");
- "run_on": lower case with no punctuation between the goals;
- "question": a request as a question ending "... without using any other region?".
Tabletop class (key: the tabletop task): "goal_then": a goal label followed by "Then ..." for the next goal.
"""

from __future__ import annotations

DEV_HANDOVER: dict[str, dict[int, list[str]]] = {
    "at_end_then": {
        4: ["At the end, the three blocks should be in the opposite regions, and no arm may touch the "
            "blue block before the red block has been touched. After that, put the yellow block back on "
            "region G."],
        8: ["At the end, the yellow block should be on region I. Then put the yellow block on region G, and "
            "at any time move the red and blue blocks to any empty region."],
    },
    "stacked": {
        7: ["The three objects should be stacked on region I one at a time, the red block before the blue "
            "block, and nothing may be placed on regions F, G and H during this period.",
            "Red block before blue block: all three objects should be piled on region I, one at a time; "
            "regions F, G and H must stay empty during this period."],
    },
    "perfect": {
        8: ["By the end, the yellow block should have been on region I and then on region G, and the red and "
            "blue blocks should have been moved to any empty region at any time."],
        1: ["The three blocks should have been transferred to the opposite side by the end, with the red "
            "block placed before the blue block."],
    },
    "run_on": {
        8: ["put the yellow block on region i then put the yellow block on region g and move the red and "
            "blue blocks to any empty region at any time"],
        4: ["move the three blocks to the opposite regions dont touch the blue block until the red block has "
            "been touched after all of that put the yellow block back on region g"],
    },
    "question": {
        3: ["Could you move the three pillars to regions E, F and G beside arm a and arm b without using any "
            "other region?",
            "Can you put the three pillars on region E, F and G, next to arm a and arm b, without placing "
            "them on any other region?"],
    },
}

HELD_HANDOVER: dict[str, dict[int, list[str]]] = {
    "at_end_then": {
        4: ["At the end the three blocks should sit in the opposite regions, with the arms not touching the "
            "blue block until an arm has touched the red block. Once that is done, place the yellow block "
            "back on region G."],
        8: ["At the end, the yellow block should sit on region I; afterwards move it to region G. The red "
            "and blue blocks can go to any empty region at any time."],
    },
    "stacked": {
        7: ["The three objects should be stacked one at a time on region I, with the red block placed before "
            "the blue block; no object can be placed on region F, G or H during this period.",
            "Place the red block before the blue block. The three objects should be stacked on region I one "
            "at a time, and regions F, G and H should stay empty during this period."],
    },
    "perfect": {
        8: ["The yellow block should have been on region I first and on region G after that, and the red and "
            "blue blocks should have gone to any empty region at any time."],
        2: ["By the end, the three blocks should have been put on regions H, I and J, one block per region."],
    },
    "run_on": {
        8: ["first put the yellow block on region i then on region g and put the red and blue blocks on any "
            "empty region at any time"],
        5: ["the red block should be placed before the blue block swap the red block and the blue block and "
            "put the yellow block on the opposite side at any time"],
    },
    "question": {
        3: ["Would you place the three pillars on regions E, F and G, by arm a and arm b, without using any "
            "region other than those?",
            "Could the three pillars go to regions E, F and G next to arm a and arm b, without putting any "
            "of them on any other region?"],
    },
}

DEV_TABLETOP: dict[int, list[str]] = {
    4: ["Goal 1: the orange and the green apple on the yellow plate. Then the red apple and the carrot on "
        "the blue plate, in any order.",
        "Goal 1 - put the green apple and the orange on the yellow plate.\nThen the carrot and the red apple "
        "go on the blue plate."],
}

HELD_TABLETOP: dict[int, list[str]] = {
    4: ["Goal 1: green apple and orange onto the yellow plate. Then: carrot and red apple onto the blue "
        "plate, any order.",
        "Goal 1: the green apple and the orange should be on the yellow plate. Then the carrot and the red "
        "apple on the blue plate."],
}
