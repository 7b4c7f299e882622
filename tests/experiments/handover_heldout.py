"""Held-out rephrasings of the eight Table III handover instructions, written after the rules and kept
apart from `handover_rephrasings.py` (the 31 the rules were checked on). Each must give a spec equal,
node by node, to the task's written one."""

HELD_OUT: dict[int, list[str]] = {
    1: [
        "The red block should be placed before the blue block. Move the three blocks to the opposite side.",
        "Please transfer the three blocks to the opposite side, and the red block should be placed before "
        "the blue block.",
        "Take the three blocks across to the opposite regions, placing the red block before the blue block.",
    ],
    2: [
        "Put the three blocks into region H, region I and region J. Each goal region can only hold one "
        "object.",
        "Move the three blocks into the three goal regions H, I and J, with only one block in each region.",
    ],
    3: [
        "Move the three pillars to the placement area on the side of arm a and arm b (region E, F, G). No "
        "object can be placed on an area other than the target region.",
        "Please move all three pillars to region E, F and G. Objects cannot be placed on any area other "
        "than the target region.",
    ],
    4: [
        "Move the three blocks into the opposite regions. No robot arm can touch the blue block until an "
        "arm has touched the red block. After all of these, put the yellow block back to region G.",
        "Transfer the three blocks to the opposite regions; the arms cannot touch the blue block until one "
        "of them touched the red block. After all of this, the yellow block should go back to region G.",
    ],
    5: [
        "Exchange the positions of the red block and the blue block, and the red block should be placed "
        "before the blue block. Put the yellow block into the opposite side at any time.",
        "At any time, move the yellow block to the opposite side. Swap the red block and the blue block; "
        "red should be placed before blue.",
    ],
    6: [
        "Place the three blocks separately on regions G, H and I, the red block before the blue block.",
        "Please put the three objects separately into region G, region H and region I. The red block "
        "should be placed before the blue block.",
    ],
    7: [
        "Place the three blocks one after another on region I; during this period no object can be placed "
        "on region F, G or H. The red block should be placed before the blue block.",
        "The red block should be placed before the blue block. Put the three objects to region I one after "
        "another, and no objects can be placed on regions F, G and H during this period.",
    ],
    8: [
        "Place the yellow block on region I first and then on region G; at any time, move the red and blue "
        "blocks to any empty region.",
        "Move the red block and the blue block to any empty region at any time. First put the yellow block "
        "on region I, then put the yellow block on region G.",
    ],
}


# Seen while fixing (issue 24): of the lead's second held-out set (16 rephrasings, never shared), 8 gave the
# written specs and 8 were refused, never a different spec. Those 8 are below and no longer held out: the
# phrase classes they use are now read generally ("the red one", "gets placed / goes down / comes
# before", "making sure", "fill R with the blocks", "next to arm a and arm b" beside a named place,
# "anywhere other than the target region", "but" before a rule, "while exchanging their positions").
SEEN_WHILE_FIXING: dict[int, list[str]] = {
    1: [
        "Bring all three blocks over to the opposite side, making sure the red one gets placed before the"
        " blue one.",
        "The red block goes down before the blue block; move three blocks to the opposite.",
    ],
    2: [
        "Fill the goal regions H, I and J with the three blocks so that each region holds only one object.",
    ],
    3: [
        "Move the three pillars over to regions E, F and G, next to arm a and arm b. Do not place any "
        "object on an area other than the target region.",
        "Please get the three pillars into the placement area (regions E, F and G). Objects must not be "
        "placed anywhere other than the target region.",
    ],
    4: [
        "Transfer the three blocks into the opposite regions, but the blue block cannot be touched by any"
        " arm until the red block has been touched. Finally, return the yellow block to region G.",
    ],
    5: [
        "Place the red block before the blue block while exchanging their positions. The yellow block "
        "goes to the opposite side at any time.",
    ],
    7: [
        "One after another, put the three blocks on region I, and during this period nothing can be "
        "placed on region F, G and H; the red block comes before the blue block.",
    ],
}

# Our own variants of those phrase classes, written while fixing (tests only).
FIXING_VARIANTS: dict[int, list[str]] = {
    1: [
        "Move the three blocks over to the opposite side, making sure that the red one is placed before "
        "the blue one.",
        "Carry the three blocks to the opposite side; the red block has to be placed earlier than the "
        "blue block.",
        "The red one comes ahead of the blue one. Move all three blocks to the other side.",
        "Bring the three blocks to the opposite side, but the red block gets put down before the blue block.",
        "Ensure the red block lands before the blue block, and move three blocks into the opposite regions.",
    ],
    2: [
        "Fill regions H, I and J with the three blocks; each region can have only one block.",
        "Occupy the goal regions H, I and J with all three blocks. Each region takes only one object.",
    ],
    3: [
        "Move the three pillars to regions E, F and G, beside arm a and arm b. Objects may not be placed "
        "anywhere other than the target region.",
        "Bring the three pillars over to regions E, F and G near arms a and b. Never place any object on "
        "an area other than the target region.",
        "Move the three pillars to the placement area (regions E, F and G). Objects must never be placed "
        "anywhere else.",
        "Move the three blocks to regions E, F and G on the side of arm a and arm b, but no object can be"
        " placed on any area other than the target region.",
        "Transfer the three pillars to regions E, F and G. Do not place any object anywhere other than "
        "the target region.",
    ],
    4: [
        "Move the three blocks to the opposite regions, but the blue block may not be picked up by any "
        "arm until the red block has been picked up. When all that is done, put the yellow block back to "
        "region G.",
        "Transfer the three blocks into the opposite regions. The blue block cannot be touched by an arm "
        "until the red block is touched. Finally, return the yellow block to region G.",
    ],
    5: [
        "Swap the red block and the blue block, making sure the red one gets placed before the blue one. "
        "The yellow block goes to the opposite side at any time.",
        "Put the red block before the blue block while swapping their positions. At any time, move the "
        "yellow block to the opposite side.",
        "Place the red block before the blue block and swap them. The yellow block goes to the other side"
        " at any time.",
    ],
    6: [
        "Put the three blocks separately on regions G, H and I; the red block is placed before the blue "
        "block.",
        "Fill regions G, H and I with the three blocks, the red block ahead of the blue block.",
    ],
    7: [
        "One by one, move the three blocks to region I, but nothing may be placed on region F, G and H "
        "during this period; the red block comes before the blue block.",
        "Put the three blocks on region I one after another; the red block gets placed earlier than the "
        "blue block. Meanwhile nothing can be put on region F, G or H.",
    ],
    8: [
        "First put the yellow block on region I, then on region G, and move the red and blue blocks to "
        "any empty region at any time.",
        "The red and blue blocks go to any empty region at any time, and the yellow block goes to region "
        "I first and then to region G.",
    ],
}


# Written by the lead in session 8 before h37's fixes and never shown to whoever wrote the rules; run
# once, after those fixes: 8 of 16 gave the written spec and 8 were refused, naming the words; none gave
# a different spec. The test asserts that last property: read right, or refused, never misread.
LEAD_HELD_OUT: dict[int, list[str]] = {
    1: [
        "Move the three blocks to the opposite side; the red block has to be placed before the blue "
        "block.",
        "Please carry three blocks into the opposite, placing the red block earlier than the blue block.",
    ],
    2: [
        "Move the three blocks to region H, region I and region J, with only one object allowed in each "
        "goal region.",
        "Each goal region can hold only one object: put the three blocks into region H, region I and "
        "region J.",
    ],
    3: [
        "Transfer the three pillars to the placement area next to arm a and arm b, that is region E, F "
        "and G. No object may be put on an area other than the target region.",
        "Move all three pillars to regions E, F and G; never place an object on an area other than the "
        "target region.",
    ],
    4: [
        "Transfer the three blocks to the opposite regions. Until some arm has touched the red block, no "
        "arm may touch the blue block. After that, move the yellow block back to region G.",
        "Put the three blocks into the opposite regions; no robot arm can touch the blue block until a "
        "robot arm has touched the red block. Once all of this is done, place the yellow block back to "
        "region G.",
    ],
    5: [
        "Exchange the red block's and the blue block's positions, and place the red block before the blue"
        " block. At any time, move the yellow block into the opposite side.",
        "Put the yellow block into the opposite side at any time. Exchange the position of the red block "
        "and the blue block, the red block being placed before the blue block.",
    ],
    6: [
        "Place the three blocks on regions G, H and I separately. Place the red block before the blue "
        "block.",
        "Separately place the three objects to region G, region H and region I, and the red block should "
        "be placed first, before the blue block.",
    ],
    7: [
        "Place the red block before the blue block. Put the three blocks one after another onto region I,"
        " and no object can be placed on region F, G or H during this period.",
        "Please place the three objects to region I one after another; the red block should be placed "
        "before the blue block, and during this period no objects can be placed on regions F, G and H.",
    ],
    8: [
        "Put the yellow block on region I first, then put it on region G, and at any time move the red "
        "and blue blocks to any empty region.",
        "At any time, move the red block and the blue block into any empty region. Place the yellow block"
        " to region I, then place the yellow block to region G.",
    ],
}
