"""Our own rephrasings of the eight Table III handover instructions (tests only; never used to write
rules). Each must give a spec equal, node by node, to the task's written one."""

REPHRASINGS: dict[int, list[str]] = {
    1: [
        "Move all three blocks to the opposite side. The red one must be placed before the blue one.",
        "Bring the three cubes over to the other side; the blue block should be placed after the red block.",
        "Carry every block into the opposite regions. Place the red block before the blue block.",
        "Move the 3 blocks across to the opposite side. Red goes before blue.",
    ],
    2: [
        "Place the three blocks into the goal regions H, I and J; each region can hold only one block.",
        "Put all the blocks in regions H, I and J, one block per region.",
        "Place each block in a different goal region: region H, I and J.",
    ],
    3: [
        "Move the three pillars to regions E, F and G. No block may be placed on any area other than the "
        "target regions.",
        "Transfer all three objects to the side of arm a and arm b. Each block must not be placed on the "
        "area other than the target region.",
        "Move the three blocks to region E, F and G and never place any block on the other regions.",
        "Bring the three pillars to regions E, F and G on the side of arms a and b. A block may not be "
        "placed on any region other than the target regions.",
    ],
    4: [
        "Move the three blocks to the opposite side. No arm may touch the blue block until an arm has "
        "touched the red block. Finally, put the yellow block back to region G.",
        "Transfer all blocks into the opposite regions. The blue block cannot be picked up until the red "
        "block has been picked up. After all of this, place the yellow block on region G.",
        "Move all three blocks to the opposite regions. Do not touch the blue block before the red block "
        "has been touched. At the end, put the yellow block back on region G.",
    ],
    5: [
        "Swap the positions of the red and blue blocks; the red block must be placed before the blue "
        "block. Put the yellow block on the opposite side at any time.",
        "Exchange the red block and the blue block. The blue block should be placed after the red block. "
        "At any time, move the yellow block to the other side.",
        "Please swap the positions of the red and blue blocks, with the red block placed before the blue "
        "block. Put the yellow block on the opposite side at any time.",
    ],
    6: [
        "Put the three blocks separately into regions G, H and I. The red block must be placed before the"
        " blue block.",
        "Place the red block before the blue block. Move all three objects to region G, H and I, one "
        "block per region.",
        "The red block should be placed before the blue block. Place the three blocks in region G, H and "
        "I, one in each.",
    ],
    7: [
        "Place the three blocks one by one on region I, the red block before the blue block; no blocks "
        "can be placed on regions F, G and H in the meantime.",
        "Move the three objects one after another to region I. The red block should be placed before the "
        "blue block. No blocks may be put on region F, G or H during this period.",
        "Place the three blocks on region I one by one, the red block before the blue block. Meanwhile no"
        " block may be placed on region F, G or H.",
        "One by one, put all three blocks on region I, the red block before the blue block, and do not "
        "put any block on regions F, G and H meanwhile.",
    ],
    8: [
        "First move the yellow block to region I, then move the yellow block to region G, and put the red"
        " and blue blocks on any empty region at any time.",
        "At any time, move the red and blue blocks to any free region. First place the yellow block on "
        "region I, then place the yellow block on region G.",
        "Put the yellow block on region I first, then put it on region G. Move the red and blue blocks to"
        " any empty region at any time.",
        "Move the yellow block to region I, then to region G. Move the red and blue blocks to any empty "
        "region at any time.",
    ],
}
