"""Issue 24, h174 (session 27): handover and tabletop rephrasings in three classes the readers refused,
written before any rule: a development part (`DEV_HANDOVER`, `DEV_TABLETOP`, read by the tests) and a
held-out part written at the same time (`HELD_HANDOVER`, `HELD_TABLETOP`, scored once at the end, read
right or refused by the `sweep` test).

Classes (key: the Table III task, or the tabletop task, each sentence restates):
- "after_the_rest" (handover task 4): the last step said after "(all) the rest" ("once all the rest is
  done, return the yellow block to G");
- "inverted_prohibition" (handover tasks 7 and 3): a prohibition opened by a negative phrase, with the
  subject after its verb ("at no point during this period is an object placed on F, G or H", "never may a
  block be put on H", "nowhere but E, F or G may a pillar be put down");
- "both_there" (tabletop task 4): a placement that waits on two things at once ("put the carrot and the
  red apple in the blue plate only when both are there").
"""

from __future__ import annotations

_TOUCH = (
    "Transfer the three blocks into the opposite regions. The arms cannot touch the blue block until an "
    "arm has touched the red block. "
)
_ORDER_7 = (
    "The red block should be placed before the blue block. Place the three objects one after another on "
    "region I. "
)
_PILLARS = "Move the three pillars to regions E, F and G, next to arm a and arm b. "

DEV_HANDOVER: dict[str, dict[int, list[str]]] = {
    "after_the_rest": {
        4: [_TOUCH + "Once all the rest is done, put the yellow block back on G.",
            "Move the three blocks to the opposite regions; no arm may touch the blue block until an arm has "
            "touched the red block. When the rest is finished, return the yellow block to region G.",
            "Move the three blocks to the opposite regions. Do not touch the blue block until an arm has "
            "touched the red block. After all the rest, bring the yellow block back to G."],
    },
    "inverted_prohibition": {
        7: [_ORDER_7 + "At no point during this period is an object placed on F, G or H.",
            "Put the three objects on region I one after another, the red block before the blue block. Never "
            "may a block be put on region F, G or H during this period.",
            _ORDER_7 + "At no time during this period may any object be placed on regions F, G and H."],
        3: [_PILLARS + "Nowhere but E, F or G may a pillar be put down.",
            "Put the three pillars on the placement area, regions E, F and G, beside arm a and arm b. Never "
            "may an object be placed on a region other than E, F and G."],
    },
}

HELD_HANDOVER: dict[str, dict[int, list[str]]] = {
    "after_the_rest": {
        4: ["Transfer three blocks to the opposite regions. The arms may not touch the blue block until an "
            "arm has touched the red block. Once the rest has been done, return the yellow block to region "
            "G.",
            "Put the three blocks into the opposite regions, and the arms cannot touch the blue block until "
            "an "
            "arm touched the red block. When all the rest is complete, move the yellow block back to G.",
            "Move three blocks to the opposite regions. No arm touches the blue block until an arm has "
            "touched "
            "the red block. After the rest is over, put the yellow block back on region G."],
    },
    "inverted_prohibition": {
        7: ["The red block should be placed before the blue block. Put the three objects on region I one "
            "after another. At no moment during this period may an object be put on F, G or H.",
            _ORDER_7 + "Under no circumstances, during this period, should a block be placed on regions F, G "
            "or H.",
            _ORDER_7 + "Not once during this period is a block placed on F, G or H."],
        3: ["Bring the three pillars to regions E, F and G beside arm a and arm b. Nowhere other than E, F "
            "and "
            "G may an object be placed.",
            "Move the three pillars to the placement area (regions E, F, G) next to arm a and arm b. A "
            "pillar "
            "may be put down nowhere except E, F or G."],
    },
}

DEV_TABLETOP: dict[int, list[str]] = {
    4: ["Put the green apple and the orange in the yellow plate, in any order. The carrot and the red apple "
        "go "
        "in the blue plate in any order, but only when both are there.",
        "Green apple and orange into the yellow plate. Carrot and red apple into the blue plate, only when "
        "both are there.",
        "Put the green apple and the orange on the yellow plate. Put the carrot and the red apple on the "
        "blue "
        "plate only if both are already there.",
        "Only when both the green apple and the orange are in the yellow plate should the carrot and the red "
        "apple go in the blue plate."],
}

HELD_TABLETOP: dict[int, list[str]] = {
    4: ["Place the green apple and the orange in the yellow plate in either order; the carrot and the red "
        "apple go in the blue plate, in either order, but only once both are there.",
        "Put the green apple and the orange in the yellow plate. Put the carrot and the red apple in the "
        "blue "
        "plate only if both of them are in the yellow plate.",
        "Only once both the green apple and the orange are on the yellow plate should the carrot and the red "
        "apple be put on the blue plate.",
        "Green apple and orange into the yellow plate, any order. Carrot and red apple into the blue plate, "
        "any order, only when both are there."],
}
