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
