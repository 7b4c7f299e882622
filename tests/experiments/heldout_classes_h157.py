"""Issue 24, h157 (session 25): four classes of handover rephrasing the readers refused, written before any
rule: a development part (`DEV_HANDOVER`, read by the tests) and a held-out part written at the same time
(`HELD_HANDOVER`, scored once at the end, read right or refused by the `sweep` test).

Classes (key: the Table III task each sentence restates):
- "steps_then_free": "Step 1: ... Step 2: ..." followed by an unlabelled sentence that frees a block's goal
  ("... also goes ..., at any step") or the steps themselves ("The steps may happen in any order");
- "anonymous_counted": "one block on H", "another block on I", "the last block on J" (any block per region);
- "region_set_referred": "on one of G, H and I", "on another of them", "on the remaining one";
- "terse_arms": terse notation with a parenthesised arm list ("Pillars to E, F, G (arms a, b); ...").
"""

from __future__ import annotations

DEV_HANDOVER: dict[str, dict[int, list[str]]] = {
    "steps_then_free": {
        8: ["Step 1: put the yellow block on region I. Step 2: put the yellow block on region G. The red and "
            "blue blocks also go to any empty region, at any step."],
        2: ["Step 1: the red block goes on region H, I or J. Step 2: the blue block goes on region H, I or "
            "J. Step 3: the yellow block goes on region H, I or J, one block per region. The steps may "
            "happen in any order."],
    },
    "anonymous_counted": {
        2: ["Step 1: put one block on region H. Step 2: put another block on region I. Step 3: put the last "
            "block on region J. The steps may happen in any order.",
            "Put one block on region H, another block on region I and the last block on region J."],
    },
    "region_set_referred": {
        6: ["The red block should be placed before the blue block. Put the red block on one of regions G, H "
            "and I, put the blue block on another of them, and the yellow block goes on the remaining one."],
        2: ["Put the red block on one of regions H, I and J, the blue block on another of them, and the "
            "yellow block goes on the remaining one."],
    },
    "terse_arms": {
        3: ["Pillars to E, F, G (arms a, b); no other regions.",
            "Three pillars to regions E, F and G (arm a, arm b). No other regions."],
    },
}

HELD_HANDOVER: dict[str, dict[int, list[str]]] = {
    "steps_then_free": {
        8: ["Step 1: the yellow block to region I. Step 2: the yellow block to region G. The red block and "
            "the blue block also go to any empty region, at any step."],
        5: ["Step 1: place the red block where the blue block is. Step 2: place the blue block where the red "
            "block was. The yellow block also goes to the opposite side, at any step."],
    },
    "anonymous_counted": {
        2: ["Step 1: one block on region H. Step 2: another block on region I. Step 3: the last block on "
            "region J. The steps can happen in any order.",
            "Place one block on region H, another one on region I, and the last block on region J."],
    },
    "region_set_referred": {
        6: ["Place the red block before the blue block. The red block goes on one of regions G, H and I, the "
            "blue block on another of them, and the yellow block on the remaining one."],
        2: ["Put the blue block on one of regions H, I and J, the red block on another of them, and the "
            "yellow block goes on the remaining one."],
    },
    "terse_arms": {
        3: ["Pillars to E, F and G (arms a and b); no other region.",
            "Move pillars to E, F, G (arms a, b). Nowhere else."],
    },
}
