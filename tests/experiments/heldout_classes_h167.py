"""Issue 24, h167 (session 26): handover rephrasings in four classes the readers refused, written before
any rule: a development part (`DEV_HANDOVER`, read by the tests) and a held-out part written at the same
time (`HELD_HANDOVER`, scored once at the end, read right or refused by the `sweep` test).

Classes (key: the Table III task each sentence restates):
- "only_places": a region constraint said positively, as the only places allowed ("only ever put a
  pillar down on one of those three regions");
- "after_everything_else": a last step said as "as soon as everything else is done" / "once everything
  else is finished", where the object had its own earlier goal;
- "so_that_each": a one-per-region distribution said with a purpose clause ("so that each region gets
  one of them");
- "inserted_order": an order phrase inserted between a thing's two places ("on region I and, only after
  that, on region G").
"""

from __future__ import annotations

DEV_HANDOVER: dict[str, dict[int, list[str]]] = {
    "only_places": {
        3: ["Move the three pillars to regions E, F and G, next to arm a and arm b, and only ever put a "
            "pillar down on one of those three regions.",
            "Put the three pillars on the placement area, regions E, F and G, beside arm a and arm b. "
            "Objects may only be placed on those regions."],
    },
    "after_everything_else": {
        4: ["Transfer the three blocks into the opposite regions. The arms cannot touch the blue block "
            "until an arm has touched the red block. As soon as everything else is done, return the "
            "yellow block to G.",
            "Move the three blocks to the opposite regions; no arm may touch the blue block until an arm "
            "has touched the red block. Once everything else is finished, put the yellow block back on "
            "region G."],
    },
    "so_that_each": {
        2: ["Place the three blocks on H, I and J so that each region gets one of them."],
        6: ["The red block should be placed before the blue block. Place the three objects on regions G, H "
            "and I so that each region gets one of them."],
    },
    "inserted_order": {
        8: ["Place the yellow block on region I and, only after that, on region G. Put the red and blue "
            "blocks on any empty region at any time.",
            "Put the yellow block on region I and then, after that, on region G; the red and blue blocks go "
            "to any empty region at any time."],
    },
}

HELD_HANDOVER: dict[str, dict[int, list[str]]] = {
    "only_places": {
        3: ["Bring the three pillars to the placement area (regions E, F and G) by arm a and arm b; objects "
            "are only allowed on those three regions.",
            "Move the three pillars to regions E, F and G next to arm a and arm b. Only ever set an object "
            "down on one of those regions."],
    },
    "after_everything_else": {
        4: ["Move the three blocks into the opposite regions. The robot arms cannot touch the blue block "
            "until an arm has touched the red block. When everything else is done, put the yellow block "
            "back on region G.",
            "Transfer three blocks to the opposite regions, and the arms cannot touch the blue block until "
            "an arm touched the red block. Once all the rest is done, return the yellow block to region G."],
    },
    "so_that_each": {
        2: ["Put the three blocks on regions H, I and J so that every region gets one block."],
        6: ["The red block should be placed before the blue block. Put the three objects on G, H and I so "
            "that each of those regions holds one of them."],
    },
    "inserted_order": {
        8: ["Put the yellow block on region I and, only then, on region G. The red and blue blocks go to any "
            "empty region at any time.",
            "Place the yellow block on region I and, after that, on region G, and move the red and blue "
            "blocks to any empty region at any time."],
    },
}
