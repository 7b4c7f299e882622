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
        "Transfer the three blocks to the opposite regions; the arms cannot touch the blue block until "
        "one of them touched the red block. After all of this, the yellow block should go back to region "
        "G.",
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
        "The red block should be placed before the blue block. Put the three objects to region I one "
        "after another, and no objects can be placed on regions F, G and H during this period.",
    ],
    8: [
        "Place the yellow block on region I first and then on region G; at any time, move the red and "
        "blue blocks to any empty region.",
        "Move the red block and the blue block to any empty region at any time. First put the yellow "
        "block on region I, then put the yellow block on region G.",
    ],
}


# Seen while fixing (issue 24). Of the lead's second held-out set (16 rephrasings, never shared), 8 gave the
# written specs and 8 were refused, never a different spec; of the lead's third set (LEAD_HELD_OUT below,
# 16), again 8 and 8. Both sets' refused sentences are here and are no longer held out: the phrase classes
# they use are now read generally ("the red one", "gets placed / goes down / comes before", "making sure",
# "fill R with the blocks", "next to arm a and arm b" beside a named place, "anywhere other than the target
# region", "but" before a rule, "while exchanging their positions"; then "only one object allowed in each
# region", "the area next to arm a and arm b, that is region E, F and G", "never place an object on ...",
# "until Y has been touched, no arm may touch X", "once all of this is done", "the red block's and the
# blue block's positions", "the red block being placed before", "should be placed first, before").
# The 5 refused sentences of the lead's session-9 batches (LEAD_SESSION9 below) are here too, no longer
# held out (h43): "X on P before Y" with X's goal restated, "any other area than the target region",
# "with each goal region holding just one object", "put the red block down", "plan how to ...".
SEEN_WHILE_FIXING: dict[int, list[str]] = {
    1: [
        "Bring all three blocks over to the opposite side, making sure the red one gets placed before the "
        "blue one.",
        "The red block goes down before the blue block; move three blocks to the opposite.",
        "Place the red block on the opposite side before the blue block, and get all three blocks across to "
        "the opposite regions.",
    ],
    2: [
        "Fill the goal regions H, I and J with the three blocks so that each region holds only one object.",
        "Move the three blocks to region H, region I and region J, with only one object allowed in each "
        "goal region.",
        "I want the three blocks in regions H, I and J, with each goal region holding just one object.",
    ],
    3: [
        "Move the three pillars over to regions E, F and G, next to arm a and arm b. Do not place any "
        "object on an area other than the target region.",
        "Please get the three pillars into the placement area (regions E, F and G). Objects must not be "
        "placed anywhere other than the target region.",
        "Transfer the three pillars to the placement area next to arm a and arm b, that is region E, F "
        "and G. No object may be put on an area other than the target region.",
        "Move all three pillars to regions E, F and G; never place an object on an area other than the "
        "target region.",
        "Please bring the three pillars to the placement area (regions E, F and G). No object may be placed "
        "on any other area than the target region.",
        "Plan how to move the three pillars to the placement area at the side of arm a and arm b, which is "
        "region E, F and G. No object can be placed on an area other than the target region.",
    ],
    4: [
        "Transfer the three blocks into the opposite regions, but the blue block cannot be touched by any "
        "arm until the red block has been touched. Finally, return the yellow block to region G.",
        "Transfer the three blocks to the opposite regions. Until some arm has touched the red block, no "
        "arm may touch the blue block. After that, move the yellow block back to region G.",
        "Put the three blocks into the opposite regions; no robot arm can touch the blue block until a "
        "robot arm has touched the red block. Once all of this is done, place the yellow block back to "
        "region G.",
    ],
    5: [
        "Place the red block before the blue block while exchanging their positions. The yellow block "
        "goes to the opposite side at any time.",
        "Exchange the red block's and the blue block's positions, and place the red block before the blue "
        "block. At any time, move the yellow block into the opposite side.",
        "Put the yellow block into the opposite side at any time. Exchange the position of the red block "
        "and the blue block, the red block being placed before the blue block.",
    ],
    6: [
        "Separately place the three objects to region G, region H and region I, and the red block should "
        "be placed first, before the blue block.",
        "Could you place the three objects separately in region G, region H and region I? Please put the red "
        "block down before the blue block.",
    ],
    7: [
        "One after another, put the three blocks on region I, and during this period nothing can be "
        "placed on region F, G and H; the red block comes before the blue block.",
    ],
}

# Our own variants (tests only), written while fixing: first of the phrase classes above, then (h38) along
# each axis a careful writer varies for these eight tasks: verbs, clause order, passive voice, order words,
# counts and plurals, region lists, the opposite side, empty regions, exchange, "back to G", negations and
# guards, "at any time", polite forms, digits and typos.
FIXING_VARIANTS: dict[int, list[str]] = {
    1: [
        "Move the three blocks over to the opposite side, making sure that the red one is placed before "
        "the blue one.",
        "Carry the three blocks to the opposite side; the red block has to be placed earlier than the "
        "blue block.",
        "The red one comes ahead of the blue one. Move all three blocks to the other side.",
        "Bring the three blocks to the opposite side, but the red block gets put down before the blue block.",
        "Ensure the red block lands before the blue block, and move three blocks into the opposite regions.",
        "The red block must be placed before the blue block; transfer the three blocks to the opposite side.",
        "Relocate the 3 blocks to the far side. Red has to be placed before blue.",
        "Shift every block across to the opposite regions, and place the red block prior to the blue block.",
        "Please move each of the blocks to the opposite side. The blue block should be placed after the "
        "red block.",
        "The blocks should all be moved to the opposite side, with the red block placed ahead of the blue "
        "block.",
        "All three blocks are to be moved to the opposite side; the red block is to be placed before the "
        "blue one.",
        "Transfer the three blocks to the opposite side. Place the red block first, then the blue block.",
        "Once the red block has been placed, the blue block may be placed. Move the three blocks to the "
        "opposite side.",
        "Move the three blocks to the opposite side; don't place the blue block until the red block has "
        "been placed.",
        "Transfer three blokcs into the oposite. The red block should be placed before the blue block.",
        "Kindly move the three blocks to the opposite side, the red block before the blue block.",
        "Could you move the three blocks across to the opposite side? The red block needs to be placed "
        "before the blue block.",
        "I'd like you to take all three blocks to the opposite side; place the red block earlier than the "
        "blue block.",
        "Move the three blocks to the opposite side, the red block followed by the blue block.",
        "Bring the three blocks to the side of arm c and arm d. The red block should be placed before the "
        "blue block.",
        "The blue block may only be placed after the red block has been placed. Move all 3 blocks to the "
        "opposite side.",
        "Get the three blocks to the opposite regions; the red one must go before the blue one.",
        "Your job: get all three blocks over to the opposite side. Make sure red is placed before blue.",
        "Move every block to the opposite side of the workspace; red must be put down before blue.",
        "The three blocks need to end up on the opposite side, and the red block should be placed prior "
        "to the blue block.",
        "Blue may not be placed until red has been placed. All three blocks go to the opposite side.",
        "Transfer the 3 blocks to the opposite regions. Red first, then blue.",
        "please move the three blocks to the opposite side. the red block needs to be placed before the "
        "blue block",
        "Relocate all the blocks to the opposite side, with red placed before blue.",
        "Move the three blocks to the other side. Place red before blue.",
        "I need all three blocks moved over to the opposite side, and the red block has to land before "
        "the blue block.",
        "Move the three cubes to the regions across from where they are now. Red should be placed before "
        "blue.",
        "Please transfer the three blocks to the opposite side, but place the red block before you place "
        "the blue block.",
        "Before the blue block is placed, the red block must be placed. Move all three blocks to the "
        "opposite side.",
        "Can you please move the three blocks to the opposite side? Remember to place the red block "
        "before the blue block.",
        "All three blocks must be relocated to the opposite regions. The red one should be put down "
        "before the blue one.",
        "Shift the three blocks over to the opposite side, making sure red is put down earlier than blue.",
        "Take the 3 blocks to the opposite side of the table and place red before blue.",
        "The task is to move three blocks to the opposite side; red must precede blue.",
        "Move the three blocks to the far side. The blue block must be placed after the red block has "
        "been placed.",
        "Step 1: move the three blocks to the opposite side. Step 2: the red block must be placed before "
        "the blue block.",
        "It is required that all three blocks be moved to the opposite side, and that the red block is "
        "placed before the blue block.",
        "Move the three blocks to the opposite side; note that red needs to come before blue.",
        "We want the three blocks on the opposite side, with the red block placed before the blue block.",
        "Put every block on the opposite side of the table. Place red earlier than blue.",
        "Move all blocks from their current regions to the opposite ones. The red block goes before the "
        "blue block.",
        "Transfer the three blocks to the opposite side. Place the red block before placing the blue block.",
        "Transfer the three blocks to opposite side. Red block should be placed before blue block.",
        "Please move three block into the opposite, the red block need to be placed before blue block.",
        "Move three blocks to opposite regions, red block placed before the blue block.",
        "Three blocks should be transfer to the opposite. Red is placed before blue.",
        "Put the blocks into opposite side, and please place red block earlier than blue block.",
        "Relocate all three blocks to the regions on the opposite side of the workspace, ensuring that "
        "the red block is placed prior to the blue block.",
        "All three cubes are to be transferred to the opposite side; the placement of the red cube must "
        "precede that of the blue cube.",
        "Move the three blocks to the opposite side such that the red block is placed before the blue block.",
        "Transfer the three blocks to the opposite regions. The red block has to be in place before the "
        "blue block.",
        "Transfer the blocks to the opposite side, in an order where red is placed before blue.",
        "Transfer the three blocks into the opposite regions. Make the red block be placed before the "
        "blue block.",
        "Move three blocks into the opposite; place the red block before you place the blue one.",
        "Please transfer three blocks to the opposite. Placing of the red block should happen before the "
        "blue block.",
        "Transfer three blocks into the opposite side, and the red block is to be placed ahead of the "
        "blue block.",
        "The red block should be put before the blue block. Transfer three blocks into the opposite.",
        "Move the three blocks to the opposite side. Do the red one before the blue one.",
        "The blocks must be moved across to the opposite side, with red going before blue.",
        "Move the three blocks over to the opposite side. The first block to be placed must be red, and "
        "blue has to come after red.",
        "Get all three blocks over to the opposite regions, and be sure to place red before blue.",
        "Move each block to the opposite side; red should be placed sooner than blue.",
        "Move the three blocks from the side of arms a and b to the side of arms c and d. The red block "
        "should be placed before the blue block.",
        "Transfer the three blocks from regions E, F and G to the opposite regions; red before blue.",
        "Transfer all of the blocks into the opposite regions, and make sure the red block gets there "
        "before the blue block does.",
        "Move each of the three blocks to the side across from it. Red is to be placed before blue.",
        "Please bring the three blocks over to the opposite side; however, the blue block can only be "
        "placed after the red one.",
        "Transfer the three blocks into the opposite side. Place the red block before the blue block.",
        "Move three blocks into the opposite regions, the red block placed earlier than the blue block.",
        "Carry the three blocks to the opposite; the red block has to be placed ahead of the blue block.",
        "Get all 3 blocks to the oppsite side, red before blue please.",
        "Move the blocks across to the other side - the red one needs to land before the blue one.",
        "Transfer the three blocks to the opposite side, and the red block needs to be put before the "
        "blue block.",
        "Bring three blocks into the opposite. Red block must be placed before the blue block.",
        "I would like the three blocks to be moved to the opposite side. Please note that the red block "
        "has to be placed before the blue block.",
        "Your goal is to get the three blocks to the opposite regions. There is one ordering requirement: "
        "red must be placed before blue.",
        "Please relocate the three blocks onto the opposite regions; make certain the red one is set down "
        "before the blue one.",
        "All blocks go to the opposite side. Order: red before blue.",
    ],
    2: [
        "Fill regions H, I and J with the three blocks; each region can have only one block.",
        "Occupy the goal regions H, I and J with all three blocks. Each region takes only one object.",
        "Move the three blocks to region H, region I and region J, with only one object allowed in each "
        "goal region.",
        "Place the blocks in H, I and J, one per region.",
        "Move the 3 blocks to the goal regions H, I, and J (one object per region).",
        "The three blocks should be placed in regions H, I and J, with one block in each region.",
        "Put the three blocks into the zones H, I and J. Only one object is allowed in each zone.",
        "Distribute the three blocks over regions H, I and J, one per region.",
        "Put the three blocks in regions H, I and J, no more than one block per region.",
        "Each region may hold at most one block: place all three blocks on regions H/I/J.",
        "No region can hold more than one block. Transfer the three blocks to regions H, I and J.",
        "Please put every block into a separate region among H, I and J.",
        "Place each of the three blocks in its own region: H, I or J.",
        "Put the three cubes into areas H, I and J, one cube per area.",
        "Put the three blocks in regions H, I, and J. Only one block may occupy each region.",
        "Each of the regions H, I and J should receive exactly one of the three blocks.",
        "Place the three blocks into the regions H, I and J so that every region holds a single block.",
        "Move the three blocks onto H, I and J, one block to each region.",
        "Put the three blocks into the three goal regions: H, I, and J. Each goal region can take only "
        "one object.",
        "The three blocks should go to regions H, I and J, at most one per region.",
        "Put the three blocks into the three goal regions H, I and J, making sure each goal region holds "
        "just one object.",
        "Place the blocks into region H, region I and region J. A region can only hold one block.",
        "Put the three blocks on regions H, I and J - one block per region.",
        "Put the three blocks into goal regions H, I, J; every goal region can contain only one object.",
        "Move the blocks into the goal regions (H, I and J), one object in each.",
        "Place the three blocks in the goal regions H, I and J. Each goal region can only take one object.",
        "Put the three blocks into regions H, I and J, so that no region has more than one block.",
        "Please move the 3 blocks into region H, region I and region J; only a single object is allowed "
        "per region.",
        "Arrange the three blocks in regions H, I and J, one block in every region.",
        "Each goal region can hold only a single object. Move the three blocks to H, I and J.",
        "1) Put the three blocks into regions H, I and J. 2) Each region can hold only one object.",
        "Three blocks go into H, I and J, one per region.",
        "Please place the three blocks into the target regions H, I and J; there can be only one object "
        "in each region.",
        "The three blocks should end up in regions H, I and J, with no two blocks sharing a region.",
        "Put the three blocks into H, I and J. Do not put more than one block in a region.",
        "Put one block in each of the regions H, I and J.",
        "Put three blocks into region H, region I and region J, each region only can be placed one object.",
        "Please put the three blocks in the goal regions H, I, J; every goal region only can have one "
        "object.",
        "Place three blocks into three goal regions which are region H, I and J, each goal region can "
        "only place one object.",
        "Put the three block into region H, I and J, one region only one object.",
        "Place the three blocks in target regions H, I and J, with at most one object per target region.",
        "Transfer the three blocks to regions H, I and J. No two objects may occupy the same region.",
        "Put the three blocks into the goal regions H, I and J, such that each goal region contains "
        "exactly one object.",
        "The three blocks must be distributed among regions H, I and J, one object per region.",
        "Put the three blocks into the three goal regions, which are region H, region I and region J; "
        "each goal region can only hold one object.",
        "Place the three blocks at region H, region I and region J. Each goal region can be placed with "
        "only one object.",
        "Put the three blocks into three goal regions (region H, region I and region J). Each of the goal "
        "regions can only contain one object.",
        "Put three blocks in goal regions H, I and J, and each goal region can only take one of the objects.",
        "Put the blocks in the goal regions H, I and J; no region may have two blocks.",
        "Put the three blocks into regions H, I and J (one object per goal region).",
        "Put the three blocks into regions H, I and J, and don't put two objects in the same region.",
        "Put the three blocks in goal regions H, I and J; a goal region can take at most one object.",
        "Move the three blocks into H, I and J, placing exactly one block in each region.",
        "Please put the three blocks into the three goal regions H, I and J. Only one object fits in each "
        "goal region.",
        "Put the three blocks in the three goal regions H, I and J; each goal region can be placed with "
        "only one object.",
        "Place the three blocks into goal region H, goal region I and goal region J; each goal region can "
        "hold one object only.",
        "Put the three blocks into three goal regions, namely region H, region I and region J; only one "
        "object can be placed in each goal region.",
        "Put the blocks on H, I, J (one each).",
        "Place the three blocks into regions H, I and J so every region ends up with exactly one block.",
        "Put the three blocks in regions H, I and J, making sure that no region holds more than one object.",
        "Move the three blocks to the goal regions H, I and J, where each goal region takes just one object.",
        "Place the three blocks onto region H, region I and region J; a single object per goal region.",
        "Put the three blocks into the three goal regions: region H, region I and region J. Every goal "
        "region can be placed with only a single object.",
        "Please put three blocks into goal regions at region H, region I and region J; only one object "
        "can be placed in each goal region.",
        "The three blocks need to go into regions H, I and J. Keep in mind that each of these goal "
        "regions can only hold a single object.",
        "Please arrange the three blocks in the goal regions H, I and J. Since each region holds only one "
        "object, each block gets its own region.",
        "Distribute the three blocks among regions H, I and J, with no region receiving more than one "
        "object.",
        "Load regions H, I and J with the three blocks, one block per region.",
    ],
    3: [
        "Move the three pillars to regions E, F and G, beside arm a and arm b. Objects may not be placed "
        "anywhere other than the target region.",
        "Bring the three pillars over to regions E, F and G near arms a and b. Never place any object on "
        "an area other than the target region.",
        "Move the three pillars to the placement area (regions E, F and G). Objects must never be placed "
        "anywhere else.",
        "Move the three blocks to regions E, F and G on the side of arm a and arm b, but no object can be "
        "placed on any area other than the target region.",
        "Transfer the three pillars to regions E, F and G. Do not place any object anywhere other than "
        "the target region.",
        "Transfer the three pillars to the placement area next to arm a and arm b, that is region E, F "
        "and G. No object may be put on an area other than the target region.",
        "Move all three pillars to regions E, F and G; never place an object on an area other than the "
        "target region.",
        "Move the three pillars to regions E, F and G, which are next to arms a and b. Do not put any "
        "pillar anywhere else.",
        "Pillars must not be dropped on any region except E, F and G. Move the three pillars to regions "
        "E, F and G.",
        "Place the three pillars in the goal area (E, F, G) beside arms a and b; no object may be set "
        "down outside the target regions.",
        "Take the pillars to regions E, F and G. No object may be placed on any other region.",
        "Objects may be placed only on the target regions. Move the three pillars to regions E, F and G.",
        "Please move the three pillars to the placement area by arms a and b (regions E, F and G); "
        "objects must not be placed on any region other than E, F and G.",
        "The three pillars should be moved to regions E, F and G. Avoid placing any object on the other "
        "regions.",
        "No object may ever be placed on regions H, I or J. Move the three pillars to regions E, F and G.",
        "Move the three pillars to the placement area beside arm a and arm b, which is regions E, F and "
        "G. Objects may not be put anywhere outside the target regions.",
        "Please carry the three pillars to regions E, F and G. Do not put objects on any region other "
        "than the targets.",
        "Move all three pillars to E, F and G, on the side of arms a and b. No object may be placed in "
        "any other region.",
        "Bring the three pillars to the placement area (regions E, F, G) next to arms a and b. Never put "
        "any object on an area that is not a target region.",
        "Transfer the three pillars to regions E, F and G. Objects can only be placed on the target regions.",
        "Move the three pillars into regions E, F and G on the side of arm a and arm b; nothing may be "
        "placed on any region except the target regions.",
        "Please move the three pillars to the placement area next to arms a and b, namely regions E, F "
        "and G. No object should ever be placed on a region other than the target regions.",
        "Move the three pillars to regions E, F and G. Objects must not be placed in any region besides "
        "the target regions.",
        "Bring all three pillars to E, F and G, near arm a and arm b; do not place anything on regions "
        "other than these.",
        "Transfer the pillars to the placement area on the side of arm a and arm b (regions E, F and G). "
        "Each object must not be placed on an area other than its target region.",
        "Move the three pillars to regions E, F and G without placing any object on any other region.",
        "Move the three pillars to the placement area, which consists of regions E, F and G on the side "
        "of arms a and b. No object may be placed anywhere except the target regions.",
        "Relocate the three pillars to regions E, F and G. Objects are not allowed on any area other than "
        "the target region.",
        "Place the three pillars onto regions E, F and G next to arm a and arm b. No object can ever be "
        "put on the other regions.",
        "Carry the three pillars to E, F and G. An object must never be placed on an area other than its "
        "target region.",
        "The three pillars go to regions E, F and G; do not place any objects outside the target regions.",
        "Pillars to E, F and G. No object on any other region.",
        "Move the three pillars to the area near arm a and arm b (regions E, F and G). Make sure no "
        "object is placed on an area other than the target region.",
        "The three pillars are to be moved to regions E, F and G. Placing any object on a region other "
        "than the target regions is not allowed.",
        "Please move the three pillars into the placement area on arm a and arm b's side, regions E, F "
        "and G, and never put an object on a non-target region.",
        "Move the three pillars to regions E, F and G, and only ever place objects on the target regions.",
        "Please move three pillars to placement area region E, F, G which is at the side of arm a and arm "
        "b. Each object can not be placed on other area except target region.",
        "Move the three pillars into the placement area (region E, F and G) beside arm a and arm b. "
        "Objects can not be put on the areas other than target regions.",
        "Move three pillars to region E, F, G. Every object cannot be placed on area other than the "
        "target region.",
        "Move the three pillars to the area of arm a and arm b side, region E, F, G. Each object should "
        "not be placed in other regions except the target regions.",
        "Relocate the three pillars to the placement area adjacent to manipulators a and b (regions E, F "
        "and G). No object may be placed in any region other than its target region.",
        "Transfer the three pillars to regions E, F and G, which lie on the side of arms a and b. At no "
        "time may an object be placed on a non-target region.",
        "Move the three pillars to regions E, F and G. Under no circumstances should an object be put on "
        "a region other than the target regions.",
        "Move the three pillars to regions E, F and G, placing objects only on the target regions.",
        "Please plan a solution that moves the three pillars to the placement area (regions E, F and G) "
        "on the side of arm a and arm b. No object can be placed on an area other than the target region.",
        "Move the three pillars to the placement area, region E, F and G, beside arm a and arm b. Each "
        "object can't be placed on any area other than its target region.",
        "Plan to move the three pillars into the placement area at the side of arm a and arm b, i.e. "
        "regions E, F and G. Objects cannot be placed on the areas other than the target regions.",
        "Move the three pillars to the area on the side of arms a and b (region E, F, G); every object "
        "must not be placed on the area other than the target region.",
        "Move the three pillars to regions E, F and G, and keep all other regions free of objects.",
        "Move the three pillars to regions E, F and G. No object may be set down on the remaining regions.",
        "Move the three pillars to regions E, F and G; no other region may receive an object.",
        "Move the three pillars into the placement area next to arm a and arm b, which is made up of "
        "regions E, F and G. Do not put any object on the other areas.",
        "Carry the three pillars to regions E, F and G on arm a and arm b's side, and make sure no object "
        "is ever placed on an area that is not a target.",
        "Move the three pillars to regions E, F and G. Objects are only allowed on the target regions.",
        "Plan a solution to move the three pillars to the placement area (region E, F, G) beside arm a "
        "and arm b. Objects cannot be placed on areas other than the target regions.",
        "Move the three pillars to the placement area of arm a and arm b, region E, F and G. No object "
        "can be placed on any area other than the target region.",
        "Move the three pillars to the placement area (regions E, F and G) at the side of arm a and arm "
        "b; every object cannot be placed on other areas than the target region.",
        "Bring the three pillars over to E, F and G on the a/b side. Don't put anything anywhere else.",
        "Move the three pillars to the placement area near arms a and b (regions E, F, G), never placing "
        "an object outside the target regions.",
        "Move the three pillars to regions E, F and G, the placement area by arm a and arm b. Placing an "
        "object on any area besides the target regions is forbidden.",
        "Move the three pillars into the placement area (regions E, F and G) next to arms a and b, and "
        "never put any object on a region that is not one of the target regions.",
        "Please move the three pillars to the placement area on arm a and arm b's side, that is, regions "
        "E, F and G; no object may be placed on any other area.",
        "Please move the three pillars to the placement area (region E, F, G) on the side of arm a and "
        "arm b. An object cannot be placed on any area except the target region.",
        "Move the three pillars to the placement area at arm a and arm b's side (regions E, F and G). "
        "Don't place any object on an area other than its target region.",
        "The task is to move the three pillars to the placement area beside arm a and arm b, which "
        "consists of regions E, F and G. Objects must never be placed anywhere except the target regions.",
        "Move the three pillars to regions E, F and G. While doing this, no object may be put down on any "
        "region that is not a target region.",
        "Shift the three pillars over to regions E, F and G beside arms a and b, and under no "
        "circumstances place an object on a region other than these.",
        "Move the three pillars onto E, F and G. Do not drop any object onto the other regions at any point.",
    ],
    4: [
        "Move the three blocks to the opposite regions, but the blue block may not be picked up by any "
        "arm until the red block has been picked up. When all that is done, put the yellow block back to "
        "region G.",
        "Transfer the three blocks into the opposite regions. The blue block cannot be touched by an arm "
        "until the red block is touched. Finally, return the yellow block to region G.",
        "Transfer the three blocks to the opposite regions. Until some arm has touched the red block, no "
        "arm may touch the blue block. After that, move the yellow block back to region G.",
        "Put the three blocks into the opposite regions; no robot arm can touch the blue block until a "
        "robot arm has touched the red block. Once all of this is done, place the yellow block back to "
        "region G.",
        "Move the three blocks to the opposite side. Only after the red block has been touched may an arm "
        "touch the blue block. Finally, put the yellow block back on region G.",
        "No arm may grab the blue block before the red block has been grabbed. Move the three blocks to "
        "the opposite regions, and after all of this, return the yellow block to region G.",
        "Move all three blocks to the opposite side. The red block has to be picked up before the blue "
        "block. When everything else is done, bring the yellow block back to region G.",
        "Transfer the three blocks into the opposite regions; the blue block must not be touched before "
        "the red block. Lastly, the yellow block goes back to region G.",
        "Move the three blocks to the opposite regions, and leave the blue block alone until the red "
        "block has been touched. In the end, move the yellow block back to region G, where the red block "
        "is now.",
        "Transfer three blocks to the opposite regions. The blue block may only be touched after the red "
        "block has been touched. After all of these, put the yellow block back where the red block is.",
        "Move the 3 blocks to the opposite side. The robot arms must not touch the blue block until the "
        "red block has been picked up. After everything else, place the yellow block on region G.",
        "Move the three blocks to the opposite regions. The blue block may not be touched until the red "
        "block has been touched. Then, once everything is done, put the yellow block back in region G.",
        "Transfer the three blocks to the opposite side. An arm may only touch the blue block after an "
        "arm has touched the red block. When all of this is finished, place the yellow block back on "
        "region G.",
        "First move the three blocks to the opposite regions, never touching the blue block before the "
        "red block has been touched. After all of this, return the yellow block to region G.",
        "Move the three blocks across to the opposite regions. Do not pick up the blue block before the "
        "red block has been picked up. At the end, the yellow block goes back to region G.",
        "Put all three blocks in the opposite regions; no arm should touch the blue block until some arm "
        "has touched the red block. Afterwards, move the yellow block back to G.",
        "Transfer three blocks into the opposite regions. The robot arms must not touch the blue block "
        "before touching the red block. After all of these, place the yellow block back to region G, "
        "where the red block is now.",
        "Transfer the three blocks to the opposite regions. An arm must not touch the blue block unless "
        "the red block has already been touched. Once that is done, return the yellow block to region G.",
        "Move the three blocks to the opposite regions. Don't let any arm touch the blue block until the "
        "red block has been touched. Finally, move the yellow block back into region G.",
        "Move the three blocks to the opposite regions; the blue block cannot be touched until after the "
        "red block is touched. After all of that, put the yellow block back on region G where the red "
        "block is.",
        "Transfer all three blocks to the opposite regions, and the robot arm cannot touch the blue block "
        "until any of the robot arms has touched the red block. Finally, place the yellow block back in "
        "region G.",
        "Move three blocks into the opposite regions. The blue block may only be picked up once the red "
        "block has been picked up. At the very end, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. The blue block is not to be touched before the "
        "red block has been touched. After everything, place the yellow block back on region G.",
        "Send the three blocks to the opposite regions. Touch the red block before touching the blue "
        "block. At the end, put the yellow block back to region G.",
        "Transfer the three blocks to the opposite regions. No arm is allowed to touch the blue block "
        "until an arm has touched the red block. When that is all done, move the yellow block back to "
        "region G.",
        "Move the three blocks to the opposite regions; however, the blue block must not be picked up "
        "until the red block has been picked up. Finally the yellow block should be returned to region G.",
        "Transfer the three blocks into the opposite regions. Nobody may touch the blue block until the "
        "red block has been touched. Lastly, put the yellow block back to region G.",
        "Step 1: move the three blocks to the opposite regions, and no arm may touch the blue block until "
        "an arm has touched the red block. Step 2: put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. The red block has to be touched first, before any "
        "arm touches the blue block. Finally, put the yellow block back to region G.",
        "Transfer the three blocks into the opposite regions, touching the red block before the blue "
        "block. After all of these, place the yellow block back to region G.",
        "Move three blocks to the opposite regions. Keep the arms off the blue block until the red block "
        "has been touched. Then, when all that is done, put the yellow block back in region G.",
        "The three blocks go to the opposite regions; the arms may touch the blue block only after "
        "touching the red block. After all this, the yellow block goes back to region G.",
        "Move the three blocks to the opposite regions. No arm may touch the blue block until the red "
        "block has been touched. Put the yellow block back on region G at the end.",
        "Move the three blocks to the opposite regions. No arm may touch the blue block until the red "
        "block has been touched. Then put the yellow block back to region G.",
        "Transfer three blocks into opposite regions. Robot arm can not touch blue block until any robot "
        "arm touched red block. After all these, place yellow block back to region G where red block is "
        "located now.",
        "Move three blocks to the opposite regions. The robot arms can not touch the blue block before "
        "any arm touched red block. After all of this, yellow block should be placed back to region G.",
        "Transfer three blocks into opposite regions; the arm is not allowed to touch blue block until "
        "the red block is touched by any arm. After these are all done, please place the yellow block "
        "back to region G.",
        "Transfer the three blocks into the opposite regions. Any robot arm can not touch the blue block "
        "until some arm touched red block. After all of these, you should put yellow block back to region "
        "G (where red block locates currently).",
        "Transfer the three blocks to the opposite regions, subject to the constraint that no manipulator "
        "touches the blue block before the red block has been touched. Subsequently, return the yellow "
        "block to region G.",
        "Move the three blocks to the opposite regions. The blue block must remain untouched until the "
        "red block has been touched. Once this is complete, place the yellow block back in region G.",
        "Transfer the three blocks to the opposite regions. No gripper may grasp the blue block until the "
        "red block has been grasped. Finally, move the yellow block back to region G.",
        "Transfer the three blocks to the opposite regions; do not pick up the blue block until after the "
        "red block has been picked up. When finished, put the yellow block back to region G.",
        "Transfer three blocks into the opposite regions. Robot arms cannot touch the blue block until "
        "any robot arm has touched the red block. After all of that, place the yellow block back to "
        "region G, where the red block currently is.",
        "Move the three blocks into the opposite regions. The blue block cannot be touched by a robot arm "
        "until the red block has been touched by any robot arm. After all of these are done, you should "
        "put the yellow block back to region G.",
        "Transfer three blocks to the opposite regions. A robot arm can't touch the blue block until one "
        "of the robot arms has touched the red block. After all of these, return the yellow block back to "
        "region G, where the red block is currently located.",
        "Transfer three blocks into the opposite regions; the robot arms must not touch the blue block "
        "until some robot arm has touched the red block; after all these, put the yellow block back to "
        "region G.",
        "Move the three blocks to the opposite regions; the red block must be touched before the blue "
        "block. As the final step, put the yellow block back on region G.",
        "Move the three blocks to the opposite regions. No arm may touch the blue block until the red "
        "block has been touched. The last step is to put the yellow block back on region G.",
        "Move the three blocks to the opposite regions, but leave the blue block untouched until the red "
        "block has been touched. After that is done, put the yellow block back to region G.",
        "Transfer the three blocks to the opposite regions. None of the arms may touch the blue block "
        "before some arm has touched the red block. Once everything is done, move the yellow block back "
        "to region G.",
        "Move the three blocks into the opposite regions, with no arm touching the blue block until the "
        "red block has been touched, and then, after all that, put the yellow block back to region G.",
        "Transfer three blocks into the opposite regions. The blue block is off limits until an arm has "
        "touched the red block. After all of these, place the yellow block back to region G, where the "
        "red block is.",
        "Transfer three blocks into the opposite regions. The robot arm cannot touch the blue block until "
        "any robot arm has touched the red block. After all of these, place the yellow block back on "
        "region G, where the red block currently is.",
        "Transfer the three blocks into the opposite regions. No robot arm can touch the blue block "
        "before a robot arm touched the red block. When all of these are done, put the yellow block back "
        "to region G.",
        "Transfer three blocks into the opposite regions; the blue block may not be touched by the robot "
        "arms until the red block has been touched. After all of these, you should put the yellow block "
        "back to region G.",
        "Move all three blocks to the opposite regions. Don't touch blue until red has been touched. When "
        "you're done, put yellow back on G.",
        "Transfer the three blocks to the opposite regions, but the arms must leave the blue block alone "
        "until the red block has been picked up. Afterwards, put the yellow block back on region G.",
        "Transfer the three blocks to the opposite regions. The blue block must not be touched by any arm "
        "until the red block has been touched. After all that, put the yellow block back to region G, "
        "where the red block currently sits.",
        "Move the three blocks into the opposite regions. Until the red block has been touched by an arm, "
        "no arm may touch the blue block. When all of this is finished, place the yellow block back on "
        "region G.",
        "Transfer all three blocks into the opposite regions, and do not let any robot arm touch the blue "
        "block until the red block has been touched. After all of these, return the yellow block to "
        "region G.",
        "Transfer three blocks to the opposite regions. A robot arm cannot touch the blue block until a "
        "robot arm has touched the red block. After all of this, put the yellow block back to region G, "
        "where the red block is located.",
        "Move the three blocks into the opposite regions. The blue block cannot be touched until the red "
        "block is touched. After everything, put the yellow block back on region G (where the red block "
        "currently is).",
        "First, transfer the three blocks to the opposite regions, with the rule that the blue block may "
        "not be touched until the red block has been touched. Then, once this is all done, put the yellow "
        "block back to region G.",
        "Please move the three blocks to the opposite regions. There is a restriction: no robot arm may "
        "touch the blue block before some arm has touched the red block. Finally, bring the yellow block "
        "back to region G.",
        "Move the three blocks to the opposite regions; no arm is permitted to touch the blue block until "
        "an arm has touched the red block. Once that is finished, put the yellow block back to region G.",
        "Move the three blocks into the opposite regions. The blue block has to wait until the red block "
        "has been touched. After all of these, return the yellow block to G.",
    ],
    5: [
        "Swap the red block and the blue block, making sure the red one gets placed before the blue one. "
        "The yellow block goes to the opposite side at any time.",
        "Put the red block before the blue block while swapping their positions. At any time, move the "
        "yellow block to the opposite side.",
        "Place the red block before the blue block and swap them. The yellow block goes to the other side "
        "at any time.",
        "Exchange the red block's and the blue block's positions, and place the red block before the blue "
        "block. At any time, move the yellow block into the opposite side.",
        "Put the yellow block into the opposite side at any time. Exchange the position of the red block "
        "and the blue block, the red block being placed before the blue block.",
        "The red and blue blocks should trade places, with red placed before blue. Whenever you like, "
        "move the yellow block to the other side.",
        "Swap red and blue; red should go before blue. The yellow block can be moved to the opposite side "
        "at any point.",
        "The yellow block may be moved to the far side at any time. Swap the positions of the red block "
        "and the blue block; the red block is placed first, before the blue block.",
        "Trade the positions of the red and blue blocks, and the red block must be placed earlier than "
        "the blue block. Also move the yellow block to the opposite side at any time.",
        "The red block and the blue block must swap positions, with the red block placed before the blue "
        "block. Put the yellow block on the opposite side whenever.",
        "Exchange the places of the red block and the blue block; the blue block should be placed after "
        "the red block. In any order, move the yellow block across to the opposite side.",
        "Swap the positions of the red and blue blocks, red block first. Move the yellow block to the "
        "opposite side at any time.",
        "The red block and the blue block should swap places; place the red one before the blue one. The "
        "yellow block can be moved to the opposite side whenever.",
        "Exchange the red and blue blocks' positions, placing the red block before the blue block. At any "
        "time, put the yellow block on the opposite side.",
        "Put the yellow block on the opposite side at any time. Also swap the red and blue blocks; the "
        "red block is to be placed before the blue block.",
        "Exchange the positions of the red block and the blue block. The red block should be placed "
        "before the blue block. The yellow block goes to the opposite side at any time.",
        "Switch red and blue, placing red before blue. Move yellow to the opposite side at any time.",
        "Exchange the positions of the red block and the blue block, with the red block being placed "
        "first. At any time, move the yellow block to the other side.",
        "The positions of the red and blue blocks should be swapped, and the red block should be placed "
        "before the blue block. The yellow block should be moved to the opposite side at any time.",
        "Swap the red and blue blocks' positions; the red block is placed before the blue block. Whenever "
        "you want, put the yellow block on the opposite side.",
        "Please exchange the red block and the blue block so that each ends up where the other was, "
        "placing red before blue. At any time put the yellow block on the opposite side.",
        "Red and blue must trade places, red placed before blue; the yellow block goes to the opposite "
        "side at any time.",
        "Exchange the places of the red and blue blocks, and make sure the red block is placed before the "
        "blue block. Move the yellow block to the opposite side at any time.",
        "Swap red and blue around, red before blue. At any time, the yellow block should go to the "
        "opposite side.",
        "Interchange the positions of the red block and the blue block; the red block has to be placed "
        "first. Whenever, move the yellow block to the opposite side.",
        "Move the yellow block to the opposite side whenever you like. Also, exchange the positions of "
        "the red and the blue block, placing the red block prior to the blue block.",
        "Please swap the red block with the blue block, the red one being placed before the blue one, and "
        "at any time put the yellow block into the opposite side.",
        "Swap the red block and the blue block (red placed first) and move the yellow block to the "
        "opposite side at any time.",
        "Exchange the positions of red and blue. Red should be placed before blue. Yellow goes to the "
        "opposite side at any time.",
        "The red block and blue block exchange positions, with red going before blue; the yellow block "
        "can go to the opposite side at any time.",
        "At any point, move the yellow block to the opposite side. The red block and the blue block need "
        "to switch places, and the red block must be placed before the blue block.",
        "Switch the positions of the red block and the blue block, red before blue, and put the yellow "
        "block on the other side at any time.",
        "Exchange red and blue with each other, red first. Put the yellow block on the opposite side at "
        "any time.",
        "Red block should be placed before blue block. Please exchange the positions of red block and "
        "blue block. Yellow block can be put into the opposite side at any time.",
        "Please exchange red block and blue block position, red block should be placed before blue block. "
        "Put yellow block into the opposite side in any time.",
        "Exchange the position of red and blue block, the red block is placed before the blue block. At "
        "any time put the yellow block to opposite side.",
        "The red block should be placed earlier than the blue block. Exchange the positions of the red "
        "block and the blue block. Anytime put the yellow block into the opposite side.",
        "Interchange the locations of the red and blue blocks, with the red block placed before the blue "
        "block. The yellow block may be moved to the opposite side at any time.",
        "Swap the red and blue blocks so that each occupies the other's original position; place red "
        "before blue. At any time, move the yellow block to the opposite side.",
        "Exchange the positions of the red block and the blue block, placing the red block first. "
        "Independently, move the yellow block to the opposite side at any time.",
        "The red and blue blocks must swap positions (red is placed before blue). The yellow block must "
        "be transferred to the opposite side, at any time.",
        "The red block must be placed before the blue block. Exchange the position of the red block and "
        "the blue block. Put the yellow block into the opposite side at any time.",
        "Please exchange the positions of the red block and the blue block, where the red block should be "
        "placed before the blue block. The yellow block can go to the opposite side at any time.",
        "Exchange the positions of the red and blue blocks, placing the red block before the blue block, "
        "and at any time put the yellow block into the opposite side.",
        "Red block should be placed before blue block. Please exchange red block's position and blue "
        "block's position. At any time, put yellow block into the opposite.",
        "Put the red block where the blue block is and the blue block where the red block is, red first. "
        "The yellow block goes to the opposite side at any time.",
        "Place the red block where the blue block started and the blue block where the red block started; "
        "the red block before the blue block. At any time, move the yellow block to the opposite side.",
        "Put the red block where the blue block is. Then put the blue block where the red block was. The "
        "yellow block goes to the opposite side at any time.",
        "Swap the red block and the blue block. The red block should be placed before the blue block. The "
        "yellow block goes to the opposite side, at any moment.",
        "Red and blue should swap positions, red first; yellow to the opposite side at any time.",
        "Move the red block to the blue block's position and the blue block to the red block's position, "
        "red before blue. Move the yellow block to the opposite side at any time.",
        "Exchange where the red block and the blue block are, placing red before blue. At any time, move "
        "the yellow block to the opposite side.",
        "Swap the red block's position with the blue block's position; the red block should be placed "
        "before the blue block. Put the yellow block on the opposite side at any time.",
        "The red block should be placed before the blue block while the two exchange positions. The "
        "yellow block may go to the opposite side at any time.",
        "Place the red block before the blue block. Exchange the positions of the red block and the blue "
        "block. Put the yellow block into the opposite side at any time.",
        "Exchange the position of the red block and the blue block, and the red block should be placed "
        "before the blue one. The yellow block can be put into the opposite side at any time.",
        "The red block should be placed before the blue block. Please swap the positions of the red block "
        "and the blue block. At any time, put the yellow block to the opposite side.",
        "Swap red and blue (red goes first) and put yellow on the opposite side whenever.",
        "Swap the positions of red and blue, with red placed first; yellow goes to the other side at any "
        "time.",
        "Place the red block before the blue block. Exchange the positions of red and blue blocks. Put "
        "the yellow block on the opposite side at any time.",
        "Please exchange the red block's position with the blue block's position, placing the red block "
        "before the blue block. The yellow block goes to the opposite side at any time.",
        "The positions of the red block and the blue block should be exchanged, and the red block needs "
        "to be placed before the blue block. In addition, move the yellow block to the opposite side at "
        "any time.",
        "I need the red and blue blocks to swap places, with red going first. The yellow block should "
        "also be moved to the opposite side at any time.",
        "Trade the places of the red and blue blocks, red before blue, and at some point move yellow over "
        "to the opposite side.",
        "Swap the red and blue blocks, putting red down first. Yellow goes to the opposite side, in any "
        "order.",
    ],
    6: [
        "Put the three blocks separately on regions G, H and I; the red block is placed before the blue "
        "block.",
        "Fill regions G, H and I with the three blocks, the red block ahead of the blue block.",
        "Separately place the three objects to region G, region H and region I, and the red block should "
        "be placed first, before the blue block.",
        "Put the three blocks on G, H and I, one per region, and red before blue.",
        "Place the red block before the blue block, with the three blocks placed separately on regions G, "
        "H and I.",
        "The three blocks must each go to a different region among G, H and I; place the red block before "
        "the blue block.",
        "Move the 3 blocks individually into regions G, H and I. The red block is to be placed ahead of "
        "the blue block.",
        "Place the three objects in the zones G, H and I, one in each; the red object must come before "
        "the blue object.",
        "The red block should be placed before the blue block. Separately put the blocks in G/H/I.",
        "Put all of the blocks onto regions G, H, I separately; the blue block is placed after the red "
        "block.",
        "Put the three blocks separately on regions G, H and I. Red must be placed before blue.",
        "Place the three objects in regions G, H and I, one each. The red object should be placed before "
        "the blue object.",
        "The red block goes before the blue block. Place the three blocks separately onto regions G, H, "
        "and I.",
        "Please place the three blocks on G, H and I separately, putting the red block before the blue "
        "block.",
        "Move the three objects separately to regions G, H and I, with the red block being placed before "
        "the blue block.",
        "Separately place the 3 blocks in regions G, H and I; red is placed ahead of blue.",
        "Place the three objects separately on region G, region H and region I, placing the red object "
        "before the blue object.",
        "Put the three blocks separately into G, H and I. Make sure the red block is placed before the "
        "blue block.",
        "Place the red block before the blue block; the three blocks go separately to regions G, H and I.",
        "Separately move the three blocks to the regions G, H and I, and the blue block should be placed "
        "after the red block.",
        "The three objects should be put separately in regions G, H and I, and red must come before blue.",
        "Place the three blocks on regions G, H and I, separately; place the red block before you place "
        "the blue block.",
        "The three objects should be placed separately on regions G, H and I, with the red object placed "
        "before the blue object.",
        "Move each of the three blocks separately to regions G, H and I. Red has to be placed before blue.",
        "Put the three blocks separately to region G, H and I; the red block should be placed before the "
        "blue block is placed.",
        "Separately place the blocks on G, H, and I. The red block must go down before the blue block.",
        "Three objects, separately, to regions G, H and I; red before blue.",
        "Place the three objects separately on regions G, H and I. The red one has to be placed before "
        "the blue one.",
        "I want the three blocks placed separately on G, H and I, and the red block must be placed before "
        "the blue block.",
        "Place the three objects separately into regions G, H, and I, making sure to place the red block "
        "before the blue block.",
        "Please place the red block before the blue block while placing the three blocks separately on "
        "regions G, H and I.",
        "Place one block on each of regions G, H and I. Red before blue.",
        "Red block should be placed before blue block. Please place three objects separately to region G, "
        "H and I.",
        "Please place three objects to region G, H, I separately, the red block should be placed before "
        "blue block.",
        "Place the three objects separately into region G, region H, region I. Red block is placed before "
        "blue block.",
        "The red block need to be placed before the blue block. Place three objects separately on the "
        "region G, H and I.",
        "Place the three objects individually in regions G, H and I, placing the red object prior to the "
        "blue object.",
        "Distribute the three blocks separately over regions G, H and I; the red block must be placed "
        "before the blue block.",
        "Place the three blocks in regions G, H and I, one per region, red before blue.",
        "Put the three objects separately onto regions G, H and I. The red one must precede the blue one.",
        "The red block should be placed before the blue block. Please place the three objects separately "
        "into region G, H and I.",
        "Please place the three objects to region G, H and I separately. The red block should be placed "
        "earlier than the blue block.",
        "Please place three objects separately to regions G, H, I, and the red block should be placed "
        "before the blue block.",
        "Place the three objects separately to region G, H and I; red block before blue block.",
        "Place the three blocks on G, H and I, one on each. Red before blue.",
        "Place the three objects separately in regions G, H and I, and the red object needs to be placed "
        "before the blue object.",
        "Red before blue: place the three blocks separately onto regions G, H and I.",
        "Please put the three blocks into regions G, H and I separately, with red going down before blue.",
        "The red block should be placed before the blue block. Please place the three objects separately "
        "on region G, H and I.",
        "Place the three objects separately to region G, region H and region I; the red one should be "
        "placed before the blue one.",
        "Separately place the three objects into region G, H and I, and place the red block before the "
        "blue block.",
        "Put the 3 objects on G, H and I separately. Red has to go before blue.",
        "Separately place the blocks onto G, H and I, making sure red is placed before blue.",
        "Place the three objects to region G, H and I separately, and the red block must be placed before "
        "the blue block.",
        "Red block should be placed before blue block. Place the three objects to regions G, H and I, "
        "separately.",
        "The three objects should be placed separately on regions G, H and I. There is one ordering "
        "requirement: the red block before the blue block.",
        "Please place the three objects separately onto regions G, H and I. Note that the red block must "
        "be placed before the blue block.",
        "Place one object on each of regions G, H and I; the red block is to be placed before the blue "
        "block.",
        "Put the three objects on regions G, H and I, one on each region, red before blue.",
    ],
    7: [
        "One by one, move the three blocks to region I, but nothing may be placed on region F, G and H "
        "during this period; the red block comes before the blue block.",
        "Put the three blocks on region I one after another; the red block gets placed earlier than the "
        "blue block. Meanwhile nothing can be put on region F, G or H.",
        "Place the three blocks on region I one after another. While doing so, no block may be put on F, "
        "G or H. The red block should be placed before the blue block.",
        "The red block should be placed before the blue block. Move the three blocks one by one to region "
        "I; regions F, G and H must stay empty meanwhile.",
        "One at a time, put the three blocks on region I, the red block before the blue block. Do not "
        "place anything on regions F, G and H in the meantime.",
        "Move the blocks to region I sequentially, red before blue, and nothing may be dropped on region "
        "F, G or H during this time.",
        "Put the red block before the blue block. Place the three objects one after another onto region "
        "I, and avoid placing any block on regions F, G and H during this period.",
        "Place the three objects one after another to region I; no objects can be placed on region F, G "
        "and H during this period. The red block should be placed before the blue block.",
        "The three blocks go to region I one after the other, with the red block placed before the blue "
        "block; in the meantime no object may be placed on region F, G or H.",
        "Place all 3 blocks one by one in region I. The red block has to be placed before the blue block, "
        "and no block can be placed on regions F, G and H while doing so.",
        "Put the three blocks on region I one after another, the red block before the blue block. During "
        "this period, nothing may be placed on regions F, G and H.",
        "Place the three objects one after another onto region I. Red goes before blue. No objects may be "
        "put on F, G or H meanwhile.",
        "One after another, place the three blocks on region I, with the red block placed before the blue "
        "block; during this time do not place any object on regions F, G, or H.",
        "Place the three blocks one by one on region I (red before blue). Regions F, G and H must remain "
        "empty during this period.",
        "Move the three objects one after another to region I; the red block should come before the blue "
        "block. No objects can be placed on regions F, G, and H in the meantime.",
        "Place the three objects on region I one after another. Red should be placed before blue. "
        "Meanwhile, don't put any object on regions F, G or H.",
        "One after another, move the three blocks onto region I; the red block needs to be placed before "
        "the blue block, and during this period no object may be placed on regions F, G, and H.",
        "Please put the three objects one after another to region I and do not place objects on regions "
        "F, G and H during this period; the red block should be placed before the blue block.",
        "Place the three blocks one by one on region I with red before blue, and keep regions F, G and H "
        "empty while doing so.",
        "The red block should be placed before the blue block. Place the three objects one after another "
        "to region I, and no object may be placed on the regions F, G and H during this period.",
        "Put the three blocks on region I one after another, red before blue, and do not put any object "
        "on F, G or H in the meantime.",
        "One after another, place all three objects on region I. The red object should be placed before "
        "the blue object. No objects may be placed on region F, G or H during this time.",
        "Place the three objects to region I one after the other, with the red block before the blue "
        "block; nothing should be placed on regions F, G and H meanwhile.",
        "Move the three blocks to region I one by one; the red one goes before the blue one, and regions "
        "F, G, and H stay empty throughout.",
        "The red block should be placed before the blue block. One at a time, put the three objects on "
        "region I, and no object can be dropped on regions F, G or H during this period.",
        "Put the three objects on region I, one after another. The red block should be placed before the "
        "blue block. No object may be put on regions F, G or H while this is happening.",
        "Three blocks to region I one after another, red before blue, nothing on F, G or H in the meantime.",
        "Place the three blocks one after another on region I; the red block is placed before the blue "
        "block. During this period, regions F, G and H must be kept empty.",
        "While placing the three blocks one after another on region I, do not place anything on regions "
        "F, G and H. The red block should be placed before the blue block.",
        "Place the three objects one after another to region I, red before blue, and make sure that "
        "nothing is placed on regions F, G and H during this period.",
        "Red block should be placed before blue block. Please place three objects one after another to "
        "region I, no object can be put on region F, G and H during this period.",
        "Please place three objects to region I one after another, and the red block should be placed "
        "before the blue block, during this period no objects can be placed on region F, G and H.",
        "Place the three objects one by one to the region I. The red block should be placed before the "
        "blue block. During this period, region F, G and H can not be placed any object.",
        "Place three objects one after another to region I, red block before blue block, and no object "
        "can be placed on the region F, G, H in this period.",
        "Place the three objects one after another onto region I, with the red block preceding the blue "
        "block. Throughout this process, no object may be placed on regions F, G or H.",
        "Sequentially place the three blocks on region I, red before blue; regions F, G and H must remain "
        "unoccupied during this period.",
        "Place the three blocks on region I one at a time, the red block before the blue block, while "
        "ensuring that no object is placed on regions F, G and H.",
        "Move the three objects to region I one after another, red block first and blue block after it. "
        "During this period, nothing may be put on region F, G or H.",
        "The red block should be placed before the blue block. Please place the three objects to region I "
        "one after another; no object can be placed on region F, G or H during this period.",
        "The red block should be placed before the blue block. Place the three objects one after another "
        "to region I, and during this period, no objects may be placed on regions F, G and H.",
        "Please place the three objects one after another to region I, the red block before the blue "
        "block; no objects can be put on region F, G and H during this period.",
        "Please place the three objects one after another into region I. The red block is placed before "
        "the blue block. No object can be placed on region F, G and H in the meantime.",
        "Put the three blocks on region I one after another, red before blue; regions F, G and H must not "
        "be used during this period.",
        "Place the three blocks on region I one after another, the red block before the blue block, and "
        "no object may be placed on any of regions F, G and H meanwhile.",
        "Place the three blocks one after another on region I, red before blue. Nothing else may be put "
        "on regions F, G or H during this period.",
        "Place the three blocks one after another on region I, the red block before the blue block; no "
        "other objects can be placed on regions F, G and H during this period.",
        "The red block should be placed before the blue block. Place the three objects on region I one "
        "after another, and keep regions F, G and H empty during this period.",
        "Place the three blocks one by one on region I, red before blue, and throughout, nothing may be "
        "placed on region F, G or H.",
        "Move the three objects, one after another, to region I (red before blue). No objects can be "
        "placed on regions F, G and H during this period.",
        "The red block should be placed before the blue block. Please place the three objects one after "
        "another on region I; during this period no object can be placed on region F, G and H.",
        "Please place the three objects to region I one by one, with the red block placed before the blue "
        "block; no objects can be placed on region F, G and H during this period.",
        "Place the three objects one after another to region I. The red block should be placed before the "
        "blue block. No object can be placed on regions F, G and H in this period.",
        "One after another, put the three blocks on I (red before blue). Nothing goes on F, G or H in the "
        "meantime.",
        "Place the three objects on region I one after another. The red block must be placed before the "
        "blue block, and while this is going on, no object can be placed on regions F, G and H.",
        "The red block should be placed before the blue block. Place the three blocks one after another "
        "onto region I, and no blocks may be placed on region F, G or H during this period.",
        "Put the three objects into region I one after another, placing the red one before the blue one; "
        "during this time, regions F, G and H cannot receive any object.",
        "Place the three objects to region I one after another, the red block must be placed before the "
        "blue block, and during this period no object can be placed on region F, G and H.",
        "Red block should be placed before blue block. Place the three objects one after another to "
        "region I; in the meantime, no objects may be put on regions F, G and H.",
        "The three objects should be placed one after another on region I, with the red block before the "
        "blue block. During this whole period, nothing may be placed on regions F, G or H.",
        "Put the three objects one after another to region I. Keep in mind that the red block is placed "
        "before the blue block, and that no object may be placed on regions F, G and H during this "
        "period.",
        "Place all three objects on region I, one after another, with red before blue. Throughout, "
        "regions F, G and H are off limits.",
        "Put the three objects on region I in turn (red ahead of blue) and do not place anything on F, G "
        "and H while that is happening.",
    ],
    8: [
        "First put the yellow block on region I, then on region G, and move the red and blue blocks to "
        "any empty region at any time.",
        "The red and blue blocks go to any empty region at any time, and the yellow block goes to region "
        "I first and then to region G.",
        "Move the yellow block to region I and then to region G. The red and blue blocks can go to any "
        "empty region at any time.",
        "First the yellow block goes to region I, then it goes to region G; the red and blue blocks may "
        "be moved to any free spot whenever.",
        "Put the yellow block on region I before putting it on region G. Move the red and blue blocks to "
        "any empty region at any time.",
        "Place yellow on region I, and afterwards on region G. Meanwhile, at any time, move the red and "
        "blue blocks to any unoccupied area.",
        "The yellow block must first be placed on region I and then on region G; move the red and blue "
        "blocks to any empty region at any time.",
        "Move the red and blue blocks to any empty region, in any order, at any time. Place the yellow "
        "block on region I first and then on region G.",
        "At any time, the red and blue blocks should be moved to any empty region. Put the yellow block "
        "on I, then on G.",
        "Yellow goes to region I, then to region G; red and blue go to any empty region at any time.",
        "Please put the yellow block onto region I first, and then onto region G. Whenever you like, move "
        "the red block and the blue block into any empty region.",
        "Put the yellow block on region I, then on region G. At any time, move the red and blue blocks to "
        "any empty region.",
        "First, place the yellow block on region I; then place it on region G. The red and blue blocks go "
        "to any empty region at any time.",
        "Move the yellow block first to region I and then to region G, and at any time move the red and "
        "blue blocks into any empty region.",
        "Place the yellow block on region I, and then place the yellow block on region G. Move the red "
        "and blue blocks to empty regions at any time.",
        "The yellow block must go to region I first and then to region G. Whenever, put the red and blue "
        "blocks on any empty region.",
        "Please first put the yellow block on region I, then put the yellow block on region G, and move "
        "the red block and the blue block to any vacant region at any time.",
        "First move the yellow block to region I, then to region G, and put the red and blue blocks in "
        "any empty regions at any time.",
        "Put the yellow block first on region I and then on region G. At any time, the red and blue "
        "blocks should be placed on any empty region.",
        "Place the yellow block on region I, then move it to region G. The red and blue blocks can be "
        "moved to any empty region whenever.",
        "The yellow block goes to region I and then to region G. Move the red and blue blocks to any "
        "empty region at any time.",
        "Please place the yellow block on region I first, after that on region G; also move the red and "
        "blue blocks to any empty region at any time.",
        "Place the yellow block on region I, and after that, place it on region G. Put the red and blue "
        "blocks on any empty region at any time.",
        "Move the red and blue blocks to any empty regions whenever you like, and move the yellow block "
        "to region I and then to region G.",
        "First, put the yellow block onto region I. Then put the yellow block onto region G. The red and "
        "blue blocks may be moved to any empty region at any time.",
        "Put the yellow block on region I first and on region G second. At any time, move the red and "
        "blue blocks to any empty region.",
        "Please place the yellow block to region I first, then place the yellow block to region G, and "
        "move the red block and the blue block to any free region at any time.",
        "Yellow block: region I first, then region G. Red and blue blocks: any empty region, at any time.",
        "Put the yellow block on region I and afterwards put it on region G. The red and blue blocks can "
        "be put on any empty region at any time.",
        "Place the yellow block first on region I, then on region G; the red and blue blocks should go to "
        "any empty region at any time.",
        "The yellow block has to go to region I first and then to region G. Meanwhile, the red and blue "
        "blocks can be moved to any empty region at any time.",
        "Move the yellow block to region I, followed by region G. Move the red and blue blocks to any "
        "empty region at any time.",
        "Please first place yellow block to region I, then place yellow block to region G, and move red "
        "block and blue block to any empty region at any time.",
        "First place the yellow block to region I and then to region G. Move red and blue block to any "
        "empty region at any time.",
        "Please place yellow block to region I first, after that place it to region G. Red and blue "
        "blocks move to any empty regions at any time.",
        "Place yellow block on region I, then on region G; red and blue blocks can be moved to any empty "
        "region in any time.",
        "Place the yellow block on region I, and subsequently on region G. The red and blue blocks may be "
        "moved to any empty region at any time.",
        "First move the yellow block to region I, and then move it to region G. At any time, relocate the "
        "red and blue blocks to any unoccupied region.",
        "The yellow block goes first to region I and then to region G, while the red and blue blocks go "
        "to any empty region at any time.",
        "Place the yellow block on region I and afterwards on region G; independently, move the red and "
        "blue blocks to any empty region at any time.",
        "Please place the yellow block to region I first, and then place the yellow block to region G. "
        "Move the red and blue blocks to any empty region at any time.",
        "First place the yellow block to region I, then to region G, and move the red block and blue "
        "block to any empty region at any time.",
        "Please first put the yellow block on region I, then put the yellow block on region G; red and "
        "blue blocks can be moved to any empty region at any time.",
        "Please place the yellow block first to region I, then to region G, and at any time move red and "
        "blue blocks to any empty region.",
        "Take the yellow block to region I and from there to region G. Move the red and blue blocks to "
        "any empty region at any time.",
        "Put the yellow block on region I, after which put it on region G. The red and blue blocks can go "
        "to any empty region at any time.",
        "Move the yellow block to region I; after that, move it on to region G. Move the red and blue "
        "blocks to any empty region at any time.",
        "Move the yellow block first to region I, then on to region G; the red and blue blocks may go to "
        "any empty region at any time.",
        "First put the yellow block on region I and afterwards on region G. Red and blue: move them to "
        "any empty region at any time.",
        "Put the yellow block on region I and then on region G, and at any time put the red and the blue "
        "block on any empty region.",
        "Please place the yellow block on region I first, then on region G, and move the red and blue "
        "blocks to any empty region at any time.",
        "First place the yellow block to region I, then place it to region G; move the red and blue "
        "blocks to any empty regions at any time.",
        "Please first put the yellow block to region I and then to region G, and put the red block and "
        "blue block to any empty region at any time.",
        "Yellow goes to I and then to G. Red and blue can go to any empty region whenever.",
        "Put the yellow block on I, then move it to G; put red and blue on any free region at any time.",
        "First place the yellow block on region I, then place it on region G. Move the red block and the "
        "blue block to any empty region at any time.",
        "Place the yellow block to region I first and to region G next; at any time, move the red and "
        "blue blocks to any empty region.",
        "The yellow block should first go to region I and afterwards to region G. In addition, the red "
        "and blue blocks should be moved to any empty region, at any time.",
        "Start by placing the yellow block on region I, then place it on region G. At any time, the red "
        "and blue blocks can be moved to any empty region.",
        "Place the yellow block on region I and subsequently on region G. Red and blue may be put on any "
        "empty region at any time.",
        "Yellow: region I, then region G. Red and blue: any empty region, at any time.",
    ],
}


# Near misses of the eight tasks (h38): one thing changed (a region, the order reversed, a constraint or a
# block left out, "respectively", "one after another" where the blocks must lie there at once). Each must be
# refused or give a spec other than the task's written one.
NEAR_MISSES: dict[int, list[str]] = {
    1: [
        "Move the three blocks to the opposite side; the red block after the blue block.",
        "The blue block must be placed before the red block; transfer the three blocks to the opposite side.",
        "Move the three blocks to the opposite side.",
        "Move the three blocks to the opposite side; the red block before the yellow block.",
        "Move the three blocks to the opposite side, one after another. Place the red block before the "
        "blue block.",
        "Move the red and blue blocks to the opposite side; the red block before the blue block.",
        "Move the three blocks to the opposite side; place the blue block first, then the red block.",
        "Move the three blocks to the opposite side; don't place the red block until the blue block has "
        "been placed.",
        "Move the three blocks to the opposite side, red first.",
        "Move the three blocks to the opposite side, but place the blue block before you place the red "
        "block.",
        "Before the red block is placed, the blue block must be placed. Move all three blocks to the "
        "opposite side.",
        "Once the blue block has been placed, the red block may be placed. Move the three blocks to the "
        "opposite side.",
        "Transfer the three blcoks to the oposite side; the red block after the blue block.",
        "Move the three cubes to the regions across from where they are now, one after another; red "
        "before blue.",
        "Move the three blocks to the opposite side. Place the red block first and the blue block after "
        "the yellow block.",
        "Move the three blocks to the opposite side; red must precede yellow.",
        "Move the three blocks to the opposite side; red goes first, yellow after red.",
        "Can you please move the three blocks to the opposite side? Remember to place the blue block "
        "before the red block.",
        "Step 1: move the three blocks to the opposite side. Step 2: the blue block must be placed before "
        "the red block.",
        "Three blocks should be transfer to the opposite. Blue is placed before red.",
        "All three cubes are to be transferred to the opposite side; the placement of the blue cube must "
        "precede that of the red cube.",
        "Transfer the blocks to the opposite side, in an order where blue is placed before red.",
        "Please transfer three blocks to the opposite. Placing of the blue block should happen before the "
        "red block.",
        "Move the three blocks to the opposite side. Do the blue one before the red one.",
        "Move the three blocks over to the opposite side. The first block to be placed must be blue, and "
        "red has to come after blue.",
        "Move the three blocks from the side of arms c and d to the side of arms a and b. The red block "
        "should be placed before the blue block.",
        "Transfer the three blocks from regions H, I and J to the opposite regions; red before blue.",
        "Transfer all of the blocks into the opposite regions, and make sure the blue block gets there "
        "before the red block does.",
        "Move each of the three blocks to the side across from it. Blue is to be placed before red.",
        "Your goal is to get the three blocks to the opposite regions. There is one ordering requirement: "
        "blue must be placed before red.",
        "I would like the three blocks to be moved to regions H and I. Please note that the red block has "
        "to be placed before the blue block.",
        "All blocks go to the opposite side. Order: blue before red.",
    ],
    2: [
        "Put the three blocks into regions H, I and G, one per region.",
        "Put the three blocks into regions H, I and J respectively.",
        "Put the three blocks into region H, I and J one after another.",
        "Put the three blocks into region H, I and J; the red block before the blue block.",
        "A region can hold two blocks. Put the three blocks in H, I and J.",
        "Put the three blocks in H, I and G, one per region.",
        "Each of the regions H, I and G should receive exactly one of the three blocks.",
        "Arrange the three blocks in regions H, I and G, one block in every region.",
        "The three blocks should end up in regions H, I and G, with no two blocks sharing a region.",
        "Put one block in each of the regions H and I.",
        "Put the three block into region H, I and G, one region only one object.",
        "Put the three blocks into three goal regions (region H, region I and region G). Each of the goal "
        "regions can only contain one object.",
        "Move the three blocks into H, I and G, placing exactly one block in each region.",
        "Place the three blocks into goal region H, goal region I and goal region G; each goal region can "
        "hold one object only.",
        "Move the three blocks to the goal regions H, I and G, where each goal region takes just one object.",
        "Please arrange the three blocks in the goal regions H, I and G. Since each region holds only one "
        "object, each block gets its own region.",
        "Load regions H, I and G with the three blocks, one block per region.",
    ],
    3: [
        "Move the three pillars to regions E, F and G.",
        "Move the three pillars to regions E, F and G. No object may be placed on region H.",
        "Move the three pillars to regions E, F and H. No object may be placed on any other region.",
        "Move the three pillars to regions E, F and G. No object may be placed on regions H or I.",
        "Move the three pillars to E, F and G; do not place anything on regions other than H.",
        "Move the pillars to E, F and G. Objects can only be placed on regions E and F.",
        "Move the three pillars to regions E, F and G without placing any object on region H.",
        "Relocate the three pillars to regions E, F and G. Objects are not allowed on region H.",
        "Move the three pillars to the placement area, which consists of regions E, F and H. No object "
        "may be placed anywhere except the target regions.",
        "Pillars to E, F and G. No object on region H.",
        "Move the three pillars to regions E, F and G. Placing any object on region H is not allowed.",
        "Move the three pillars to E, F and H. No object may be placed on any other region.",
        "Transfer the three pillars to regions E, F and H, which lie on the side of arms a and b. At no "
        "time may an object be placed on a non-target region.",
        "Move the three pillars to regions E, F and G, and keep region H free of objects.",
        "Move the three pillars to regions E, F and G; no region other than H may receive an object.",
        "Move the three pillars to regions E, F and G. Objects are only allowed on regions E and F.",
        "Move the three pillars to the placement area of arm c and arm d, region H, I and J. No object "
        "can be placed on any area other than the target region.",
        "Move the three pillars to the placement area (regions E, F and G) at the side of arm a and arm "
        "b; every object cannot be placed on other areas than regions E and F.",
        "Bring the three pillars over to E, F and H on the a/b side. Don't put anything anywhere else.",
        "Move the three pillars to the placement area near arms a and b (regions E, F, G), never placing "
        "an object on region H.",
    ],
    4: [
        "Move the three blocks to the opposite regions. No arm may touch the red block until an arm has "
        "touched the blue block. Finally, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. Finally, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. No arm may touch the blue block until an arm has "
        "touched the red block. Then put the yellow block on region H.",
        "Move the three blocks to the opposite regions. No arm may touch the blue block until an arm has "
        "touched the red block. At any time, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. An arm must not touch the red block unless the "
        "blue block has already been touched. Finally, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. Don't let any arm touch the blue block until the "
        "yellow block has been touched. Finally, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. The blue block has to be picked up before the red "
        "block. Finally, put the yellow block back to region G.",
        "Move the three blocks to the opposite regions. No arm may touch the blue block until the red "
        "block has been touched. Then, once everything is done, put the yellow block back in region H.",
        "Move the three blocks to the opposite regions. The red block is not to be touched before the "
        "blue block has been touched. After everything, place the yellow block back on region G.",
        "Move the three blocks to the opposite regions. Nobody may touch the blue block until the red "
        "block has been touched. When that is all done, move the yellow block back to region H.",
        "Move three blocks to the opposite regions. Keep the arms off the red block until the blue block "
        "has been touched. Then, when all that is done, put the yellow block back in region G.",
        "Transfer the three blocks into the opposite regions, touching the blue block before the red "
        "block. After all of these, place the yellow block back to region G.",
        "Step 1: put the yellow block back to region G. Step 2: move the three blocks to the opposite "
        "regions, and no arm may touch the blue block until an arm has touched the red block.",
        "Transfer three blocks into opposite regions; the arm is not allowed to touch red block until the "
        "blue block is touched by any arm. After these are all done, please place the yellow block back "
        "to region G.",
        "Move the three blocks to the opposite regions. The red block must remain untouched until the "
        "blue block has been touched. Once this is complete, place the yellow block back in region G.",
        "Transfer three blocks to the opposite regions. A robot arm can't touch the red block until one "
        "of the robot arms has touched the blue block. After all of these, return the yellow block back "
        "to region G, where the red block is currently located.",
        "Transfer three blocks into the opposite regions. The red block is off limits until an arm has "
        "touched the blue block. After all of these, place the yellow block back to region G, where the "
        "red block is.",
        "Move the three blocks into the opposite regions, with no arm touching the red block until the "
        "blue block has been touched, and then, after all that, put the yellow block back to region G.",
        "Move all three blocks to the opposite regions. Don't touch red until blue has been touched. When "
        "you're done, put yellow back on G.",
        "Move all three blocks to the opposite regions. Don't touch blue until red has been touched. When "
        "you're done, put yellow back on H.",
        "Move the three blocks into the opposite regions. The red block has to wait until the blue block "
        "has been touched. After all of these, return the yellow block to G.",
    ],
    5: [
        "Exchange the positions of the red and yellow blocks; the red block before the blue block. Put "
        "the yellow block on the opposite side at any time.",
        "Exchange the positions of the red and blue blocks; the blue block before the red block. Put the "
        "yellow block on the opposite side at any time.",
        "Exchange the positions of the red and blue blocks. Put the yellow block on the opposite side at "
        "any time.",
        "Exchange the positions of the red and blue blocks; the red block before the blue block.",
        "Exchange the positions of the red block and the blue block, with the blue block being placed "
        "first. At any time, move the yellow block to the other side.",
        "The positions of the red and yellow blocks should be swapped, and the red block should be placed "
        "before the blue block.",
        "Swap red and blue around, blue before red. At any time, the yellow block should go to the "
        "opposite side.",
        "Please swap the red block with the yellow block, the red one being placed before the blue one, "
        "and at any time put the yellow block into the opposite side.",
        "Swap the red and yellow blocks so that each occupies the other's original position; place red "
        "before blue. At any time, move the yellow block to the opposite side.",
        "Please exchange the positions of the red block and the blue block, where the blue block should "
        "be placed before the red block. The yellow block can go to the opposite side at any time.",
        "Red block should be placed before blue block. Please exchange red block's position and yellow "
        "block's position. At any time, put yellow block into the opposite.",
        "Put the red block where the blue block is and the blue block where the yellow block is, red "
        "first. The yellow block goes to the opposite side at any time.",
        "Put the red block where the blue block is and the blue block where the red block is, blue first. "
        "The yellow block goes to the opposite side at any time.",
        "Put the blue block where the red block is. Then put the red block where the blue block was. The "
        "yellow block goes to the opposite side at any time.",
        "Move the red block to the blue block's position and the blue block to the yellow block's "
        "position, red before blue. Move the yellow block to the opposite side at any time.",
        "Exchange where the red block and the yellow block are, placing red before blue. At any time, "
        "move the yellow block to the opposite side.",
        "The blue block should be placed before the red block while the two exchange positions. The "
        "yellow block may go to the opposite side at any time.",
        "I need the red and yellow blocks to swap places, with red going first. The yellow block should "
        "also be moved to the opposite side at any time.",
        "Swap the red and blue blocks, putting blue down first. Yellow goes to the opposite side, in any "
        "order.",
    ],
    6: [
        "Place the three blocks separately on regions G, H and J; the red block before the blue block.",
        "Place the three blocks separately on regions G, H and I; the blue block before the red block.",
        "Place the three blocks on regions G, H and I one after another; the red block before the blue "
        "block.",
    ],
    7: [
        "Place the three blocks one after another on region I; no object may be placed on region F or G "
        "meanwhile. The red block before the blue block.",
        "Place the three blocks one after another on region H; no object may be placed on region F, G or "
        "I meanwhile. The red block before the blue block.",
        "Place the three blocks one after another on region I. The red block before the blue block.",
        "Place the three blocks one by one on region I with red before blue, and keep regions F and G "
        "empty while doing so.",
        "Three blocks to region I one after another, red before blue, nothing on F or G in the meantime.",
        "Place the three objects one by one to the region I. The red block should be placed before the "
        "blue block. During this period, region F and G can not be placed any object.",
        "Place the three objects one after another onto region I, with the blue block preceding the red "
        "block. Throughout this process, no object may be placed on regions F, G or H.",
        "Put the three blocks on region I one after another, red before blue; regions F and G must not be "
        "used during this period.",
        "Place the three blocks one after another on region I, the red block before the blue block; no "
        "other objects can be placed on regions F and G during this period.",
        "One after another, put the three blocks on I (red before blue). Nothing goes on F or G in the "
        "meantime.",
        "Put the three objects into region I one after another, placing the red one before the blue one; "
        "during this time, regions F and H cannot receive any object.",
        "Place the three objects on region I one after another. The blue block must be placed before the "
        "red block, and while this is going on, no object can be placed on regions F, G and H.",
        "The three objects should be placed one after another on region I, with the red block before the "
        "blue block. During this whole period, nothing may be placed on regions F or G.",
        "Place all three objects on region I, one after another, with red before blue. Throughout, "
        "regions F and G are off limits.",
    ],
    8: [
        "First place the yellow block on region G, then on region I. Move the red and blue blocks to any "
        "empty region at any time.",
        "Place the yellow block on region I and on region G. Move the red and blue blocks to any empty "
        "region at any time.",
        "First place the yellow block on region I, then on region G. Move the red and blue blocks to "
        "region E at any time.",
        "First place the yellow block on region I, then on region G. Move the red block to any empty "
        "region at any time.",
        "Place the yellow block on region G before putting it on region I. Move the red and blue blocks "
        "to any empty region at any time.",
        "Put the yellow block on region I; then place it on region H. Move the red and blue blocks to any "
        "empty region at any time.",
        "Put the yellow block on region G first and on region I second. At any time, move the red and "
        "blue blocks to any empty region.",
        "Step 1: put the yellow block on region G. Step 2: put it on region I. Red and blue blocks: any "
        "empty region, at any time.",
        "Yellow block: region G first, then region I. Red and blue blocks: any empty region, at any time.",
        "Please place yellow block to region I first, after that place it to region G. Red and blue "
        "blocks move to region E at any time.",
        "Take the yellow block to region G and from there to region I. Move the red and blue blocks to "
        "any empty region at any time.",
        "First put the yellow block on region I and afterwards on region G. Red and blue: move them to "
        "region E at any time.",
    ],
}


# Written by the lead in session 8 before h37's fixes and never shown to whoever wrote the rules; run
# once, after those fixes: 8 of 16 gave the written spec and 8 were refused, naming the words; none gave
# a different spec. The 8 refused moved to SEEN_WHILE_FIXING (h38); the 8 below gave the spec then and
# were read (not tuned on) while h38 worked. The test asserts that they are read right or refused, never
# misread.
LEAD_HELD_OUT: dict[int, list[str]] = {
    1: [
        "Move the three blocks to the opposite side; the red block has to be placed before the blue block.",
        "Please carry three blocks into the opposite, placing the red block earlier than the blue block.",
    ],
    2: [
        "Each goal region can hold only one object: put the three blocks into region H, region I and "
        "region J.",
    ],
    6: [
        "Place the three blocks on regions G, H and I separately. Place the red block before the blue block.",
    ],
    7: [
        "Place the red block before the blue block. Put the three blocks one after another onto region I, "
        "and no object can be placed on region F, G or H during this period.",
        "Please place the three objects to region I one after another; the red block should be placed "
        "before the blue block, and during this period no objects can be placed on regions F, G and H.",
    ],
    8: [
        "Put the yellow block on region I first, then put it on region G, and at any time move the red "
        "and blue blocks to any empty region.",
        "At any time, move the red block and the blue block into any empty region. Place the yellow block "
        "to region I, then place the yellow block to region G.",
    ],
}


# Written by the lead in session 9 (batches 5, 6 and 7, 16 sentences each) and never shown to whoever wrote
# the rules. First contact (instance 0): batch 5 at main before h38: 7 gave the written spec, 9 were
# refused, 0 another spec; after h38: 14 / 2 / 0. Batch 6: before h38 9 / 7 / 0, after h38 14 / 2 / 0.
# Batch 7 (written after h38 finished): 15 / 1 / 0. So 43 of 48 gave the spec and 5 were refused by name,
# none misread. The 5 refused are now read (h43) and also sit in SEEN_WHILE_FIXING; the test asserts that
# every sentence here is read right or refused, never misread.
LEAD_SESSION9: dict[int, list[str]] = {
    1: [
        "Move all three blocks over to the opposite side. Red has to be placed before blue.",
        "Place the red block on the opposite side before the blue block, and get all three blocks across to "
        "the opposite regions.",
        "Move the 3 blocks to the opposite side, red before blue.",
        "Could you transfer the three blocks across to the opposite side? The red block needs to be placed "
        "before the blue block.",
        "Transfer the three blocks to the opposite side, and make sure that the red block is placed before "
        "the blue block.",
        "The red block must be put down before the blue block. Move the three blocks into the opposite "
        "regions.",
    ],
    2: [
        "Put the three blocks in regions H, I and J, one object per goal region.",
        "Move the blocks into the goal regions H, I and J so that every region holds exactly one object.",
        "Place the three blocks in region H, region I and region J, only one object per region.",
        "I want the three blocks in regions H, I and J, with each goal region holding just one object.",
        "Please put the three blocks into the goal regions, region H, region I and region J; each goal "
        "region can take only one object.",
        "Move the three blocks to regions H, I and J. Only one object can be placed in each goal region.",
    ],
    3: [
        "Move the three pillars to regions E, F and G beside arm a and arm b, and don't put any object on an "
        "area other than the target region.",
        "Please bring the three pillars to the placement area (regions E, F and G). No object may be placed "
        "on any other area than the target region.",
        "Move the three pillars to region E, F and G next to arm a and arm b. Objects must not be placed on "
        "any area except the target region.",
        "The three pillars go to the placement area, regions E, F and G. Do not place any object on an area "
        "other than the target region.",
        "Plan how to move the three pillars to the placement area at the side of arm a and arm b, which is "
        "region E, F and G. No object can be placed on an area other than the target region.",
        "Move the three pillars to the regions E, F and G. An object may not be placed on any area other "
        "than the target region.",
    ],
    4: [
        "Move the three blocks to the opposite regions. The blue block must not be touched by any arm until "
        "the red block has been touched by an arm. After all that, put the yellow block back in region G.",
        "Transfer the three blocks to the opposite regions, and no arm can touch the blue block before an "
        "arm has touched the red block. Then, after everything else, place the yellow block back to region "
        "G.",
        "Transfer the three blocks to the opposite regions. No arm may touch the blue block until the red "
        "block has been touched. Afterwards, put the yellow block back to region G.",
        "Move three blocks into the opposite regions; the blue block cannot be touched until an arm touches "
        "the red block. When that is all done, place the yellow block back in region G.",
        "Transfer the three blocks into the opposite regions. A robot arm may touch the blue block only "
        "after a robot arm has touched the red block. After all of that, put the yellow block back to region "
        "G.",
        "Move the three blocks to the opposite regions, but do not let any arm touch the blue block until an "
        "arm has touched the red block. After all of these, put the yellow block back into region G.",
    ],
    5: [
        "Swap the positions of the red block and the blue block, placing the red block first. At any time, "
        "move the yellow block to the opposite side.",
        "Exchange the red and blue blocks' positions; the red block should be placed before the blue block. "
        "The yellow block can be moved to the opposite side at any time.",
        "Swap the red block and the blue block, with the red block placed before the blue block, and move "
        "the yellow block to the opposite side at any time.",
        "Please exchange the positions of the red and the blue block. Place the red block before the blue "
        "block. Put the yellow block on the opposite side at any time.",
        "Exchange the position of the red block and the blue block, and the red block should be placed "
        "before the blue block. Put the yellow block on the opposite side at any time.",
        "The red block should be placed before the blue block. Swap the positions of the red block and the "
        "blue block, and at any time put the yellow block to the opposite side.",
    ],
    6: [
        "Put the three blocks separately on region G, region H and region I, and place the red block before "
        "the blue block.",
        "The red block must be placed before the blue block. Place the three blocks separately into regions "
        "G, H and I.",
        "Red block before blue block. Put the three blocks separately onto regions G, H and I.",
        "Could you place the three objects separately in region G, region H and region I? Please put the red "
        "block down before the blue block.",
        "Place the three objects separately to region G, region H and region I, and the red block should be "
        "placed before the blue block.",
        "Put the three blocks on regions G, H and I separately, and the red block has to be placed before "
        "the blue block.",
    ],
    7: [
        "Place the three blocks on region I one after another, placing the red block before the blue block. "
        "During this period, nothing can be placed on region F, G or H.",
        "One after another, place the three objects on region I. No object can be put on regions F, G and H "
        "during this period, and the red block should be placed before the blue block.",
        "Put the 3 objects on region I one after another, red before blue, and during this period nothing "
        "may be placed on regions F, G and H.",
        "The red block should be placed before the blue block. Place the three blocks one after the other on "
        "region I; no object can be placed on region F, G or H during this period.",
        "Please place the three blocks to region I one after another, the red block before the blue block. "
        "During this period, no objects can be placed on region F, G and H.",
        "Place the three objects to region I one after another. The red block should be placed before the "
        "blue block. No objects can be placed on regions F, G and H during this period.",
    ],
    8: [
        "First put the yellow block on region I, and then put it on region G. At any time, move the red "
        "block and the blue block to any empty region.",
        "Move the red and blue blocks to any empty region at any time, and place the yellow block on region "
        "I first and then on region G.",
        "Put the yellow block on region I and after that on region G. Move the red and the blue block to any "
        "empty region at any time.",
        "At any time, the red and blue blocks should be moved to any empty region. The yellow block goes "
        "first to region I, then to region G.",
        "Please place the yellow block to region I first, then place it to region G, and move the red block "
        "and the blue block to any empty region at any time.",
        "Move the red and blue blocks to any empty region at any time. The yellow block should be placed on "
        "region I first and then on region G.",
    ],
}


# Our own (h43), written along the phrase classes of the 5 refused session-9 sentences ("X on P before Y"
# with X's goal restated, "any other area than the target region", "with each goal region holding just one
# object", particle verbs "put ... down" / "pick ... up", "plan how to / find a way to" framing) and of the
# refusals of our rounds below ("all three" without a noun, bare region lists "F, G, H", "region I receives
# the blocks one after another", "upon completion", "provided that", "it is requested that", "to be
# placed", "deposited", "belong in", "Objective:", "arrange for", "on I first and on G thereafter", "as for
# X, they ...", "the arms are required to", "occupy regions", "->", "P for B" / "P: B" headings, "being
# grasped", "the other regions are not to be used", "receive no object", "X and Y shall exchange their
# positions", "whereas", "at an arbitrary time", "the only ordering rule is that", "having been placed",
# "the desired outcome is that ... rest on", "single object per region", "accommodating", "no placement
# outside", "whereby", "there is a rule about touching:", "should be swapped", "it does not matter when",
# "gets its own region among", "for as long as this takes", "F/G/H: nothing", "note that", "it being
# understood that", "being regions E, F and G", "blue only after red has been touched", "under the
# condition that", "here is what should happen", "travel", "red <-> blue", "use R for B", "with F, G and H
# kept free", "H, I and J get one block each", "yellow: back to G last", "yellow block on I, then on G",
# "on the other hand", "as for the order,", "once it is there,", "while doing so" before a touch rule, "end
# up with one block each"): each gives the written spec.
H43_VARIANTS: dict[int, list[str]] = {
    1: [
        "Put the red block on the opposite side before the blue block, and move all three blocks to the "
        "opposite side.",
        "Place the blue block on the opposite side after the red block, and take all three blocks across to "
        "the opposite regions.",
        "Work out how to transfer the three blocks to the opposite side, with the red block placed before "
        "the blue block.",
        "Move all three to the opposite side, red before blue.",
        "Objective: relocate the three blocks to the opposite side. Constraint: the red block is placed "
        "before the blue block.",
        "It is requested that the three blocks be transferred to the opposite side, the red block being "
        "placed prior to the blue block.",
        "Kindly arrange for all three blocks to be moved to the opposite side, with the red block placed "
        "ahead of the blue block.",
        "The arms are required to transfer the three blocks to the opposite side; the red block is placed "
        "before the blue block.",
        "You must move all three blocks to the opposite side. The only ordering rule is that red goes before "
        "blue.",
        "Opposite side for all three blocks, red before blue.",
        "Move: the 3 blocks -> the opposite side, with the red block having been placed before the blue "
        "block.",
        "The desired result is that the three blocks rest on the opposite side; red goes before blue.",
        "Note that the three blocks are to be moved to the opposite side, and that red must be placed before "
        "blue.",
    ],
    2: [
        "I want the three blocks in regions H, I and J, with each region holding only one object.",
        "I would like the three blocks in region H, region I and region J, each goal region taking just one "
        "block.",
        "I need the three blocks in regions H, I and J, with every goal region containing exactly one "
        "object.",
        "We want the three blocks to be in regions H, I and J, with each region holding a single block.",
        "Move all 3 into regions H, I and J, one object per region.",
        "Each of the three blocks is to be deposited in one of the goal regions H, I and J, and no goal "
        "region may contain more than one object.",
        "The three blocks belong in regions H, I and J; each region holds one object.",
        "The three blocks shall occupy regions H, I and J, max one object per region.",
        "Blocks → regions H, I and J; at most one object per region.",
        "Put the three blocks in regions H, I and J, each region accommodating a single object.",
        "Here is the task: the three blocks go to regions H, I and J (single block per region).",
        "Regions H, I and J receive one block each.",
        "Use regions H, I and J for the three blocks, one block per region.",
        "The three blocks shall be placed in regions H, I and J, it being understood that a region holds one "
        "object.",
    ],
    3: [
        "Move the three pillars to regions E, F and G. No object may be put on any other region than the "
        "target regions.",
        "Bring the three pillars to regions E, F and G, and no object can go on any other zone than the goal "
        "region.",
        "Move the three pillars to regions E, F and G; do not place any object on another area than the "
        "target region.",
        "Figure out how to move the three pillars to regions E, F and G. No object can be placed on an area "
        "other than the target region.",
        "Please find a way to move the three pillars to region E, F and G, without putting any object on an "
        "area other than the target region.",
        "Three pillars to regions E, F, G. No other region may be used.",
        "Task: move the three pillars to regions E, F and G. No object on any other area than the target "
        "region.",
        "The three pillars are to be conveyed to regions E, F and G, situated on the side of arm a and arm "
        "b. Regions H, I and J shall receive no object.",
        "Move the three pillars to regions E, F and G. The other regions are not to be used for anything.",
        "Move the three pillars to regions E, F and G; no placement outside the target regions.",
        "It is necessary to move the three pillars to regions E, F and G, whereby no object may be placed on "
        "an area other than the target region.",
        "Pillars: regions E, F and G. Other regions: forbidden.",
        "Move the three pillars to the area beside arm a and arm b, being regions E, F and G. No object on "
        "any other area than the target region.",
    ],
    4: [
        "Move the three blocks into the opposite regions. No arm may pick the blue block up until an arm has "
        "picked the red block up. After all of these, put the yellow block back down on region G.",
        "The three blocks shall be transferred to the opposite regions. No arm shall touch the blue block "
        "before the red block has been touched. Upon completion, the yellow block shall be returned to "
        "region G.",
        "The three blocks are to be moved into the opposite regions, provided that no arm touches the blue "
        "block until the red block has been touched. Subsequently, the yellow block is to be returned to "
        "region G.",
        "Move the three blocks to the opposite regions, the blue block staying untouched until the red block "
        "has been touched. On completion of this, put the yellow block back to region G.",
        "All three blocks go to the opposite regions. The blue block may not be picked up by any arm prior "
        "to the red block being picked up. At the end, the yellow block returns to region G.",
        "The three blocks must be delivered to the opposite regions; be careful about one thing: the blue "
        "block remains untouched until the red block has been touched. Finally, return the yellow block to "
        "region G.",
        "Move the three blocks to the opposite regions. There is a rule about touching: no arm may touch the "
        "blue block until an arm has touched the red block. Thereafter, put the yellow block back on region "
        "G.",
        "Three blocks to the opposite regions. Blue only after red has been touched. Yellow: back to region "
        "G at the end.",
        "Transfer the three blocks into the opposite regions under the condition that no arm touches the "
        "blue block before an arm touches the red block. Upon finishing, return the yellow block to region "
        "G.",
        "Here is what should happen. The three blocks travel to the opposite regions; no arm may touch the "
        "blue block until the red block has been touched. Finally the yellow block goes back to region G.",
        "Transfer the three blocks into the opposite regions; in the meantime, the blue block may only be "
        "touched after the red block has been touched. Finally, put the yellow block back on region G.",
    ],
    5: [
        "Plan how to exchange the positions of the red block and the blue block, red before blue, and move "
        "the yellow block to the opposite side at any time.",
        "The red block and the blue block are to exchange positions, the red block to be placed before the "
        "blue block. The yellow block is to be moved to the opposite side at any time.",
        "The red block and the blue block shall exchange their positions, the red block being placed first. "
        "The yellow block goes to the opposite side at an arbitrary time.",
        "The red and blue blocks swap their places, red first, whereas the yellow block goes to the opposite "
        "side at any time.",
        "The red and blue blocks should be swapped, red placed first. The yellow block also has to reach the "
        "opposite side, but it does not matter when.",
        "Red <-> blue, red first. The yellow block to the opposite side, at any time.",
    ],
    6: [
        "Could you place the three objects separately in region G, region H and region I? Please set the red "
        "block down before the blue block.",
        "Set the three blocks down separately on regions G, H and I, and lay the red block down before the "
        "blue block.",
        "Put down the three blocks separately on regions G, H and I. Put the red block down first, then the "
        "blue block.",
        "Lay the three blocks separately on regions G, H and I, laying the red block down before the blue "
        "block.",
        "Distribute the three blocks over regions G, H and I so that each region gets one block. The red "
        "block has to go down before the blue block.",
        "The three blocks shall be placed separately in regions G, H and I, where the red block is required "
        "to be placed before the blue block.",
        "Each of the three blocks gets its own region among G, H and I. When placing them, do the red block "
        "before the blue block.",
        "Regions G, H and I should end up with one block each; as for the order, the red block goes before "
        "the blue block.",
    ],
    7: [
        "All three to region I, one after another; red before blue. Regions F, G and H stay empty meanwhile.",
        "Put all three on region I one after another, the red block before the blue block, and during this "
        "period no object can be placed on regions F, G and H.",
        "Region I should receive the three blocks one after another. Red has to come before blue, and while "
        "this happens, regions F, G and H must stay empty.",
        "All three to I, one after another, red before blue. F, G, H stay empty meanwhile.",
        "Region I: all three blocks, one after another, red before blue; F, G and H off limits.",
        "The three blocks shall be placed on region I in succession, red prior to blue; regions F, G and H "
        "receive no object during this period.",
        "3 objects -> region I one after another (red before blue); F/G/H: nothing during this period.",
        "Put the three blocks on region I one after another, red before blue. For as long as this takes, "
        "regions F, G and H must not receive any object.",
        "Region I gets the three blocks in turn, the red block before the blue block, with regions F, G and "
        "H kept free during this period.",
    ],
    8: [
        "Come up with a plan to put the yellow block on region I and then on region G, and to move the red "
        "and blue blocks to any empty region at any time.",
        "The yellow block is to be placed on region I first and on region G thereafter; the red and blue "
        "blocks are to be moved to any empty region at any time.",
        "Take the yellow block to region I and, after that, to region G. As for the red and blue blocks, "
        "they simply need to be moved to any empty region at any time.",
        "The yellow block visits region I first and then region G. The red and blue blocks go to any empty "
        "region at any time you like.",
        "Two things: yellow block on region I, then on region G; the red and blue blocks to any empty region "
        "at any time.",
        "Put the yellow block on region I, and once it is there, put it on region G. The red and blue "
        "blocks, on the other hand, also go to any empty region at any time.",
    ],
}

# The same classes with one meaning changed (an order reversed, a region or a block changed, the
# prohibition or a count changed, "one after another" dropped): each is refused or gives another spec.
H43_NEAR_MISSES: dict[int, list[str]] = {
    1: [
        "Place the blue block on the opposite side before the red block, and get all three blocks across to "
        "the opposite regions.",
        "Place the red block on region H before the blue block, and get all three blocks across to the "
        "opposite regions.",
        "Place the red block on the opposite side before the blue block.",
        "Move all two to the opposite side, red before blue.",
        "Work out how to transfer the three blocks to the opposite side.",
        "Kindly arrange for all three blocks to be moved to region H, with the red block placed ahead of the "
        "blue block.",
        "Opposite side for the red and blue blocks, red before blue.",
        "The arms are required to transfer the three blocks to the opposite side; the blue block is placed "
        "before the red block.",
        "Move: the 3 blocks -> the opposite side, with the blue block having been placed before the red "
        "block.",
        "The desired result is that the red and blue blocks rest on the opposite side; red goes before blue.",
    ],
    2: [
        "I want the three blocks in regions H and I, with each goal region holding just one object.",
        "I want the red and blue blocks in regions H, I and J, with each goal region holding just one "
        "object.",
        "I want the three blocks in regions H, I and J, with each goal region holding two objects.",
        "Each of the three blocks is to be deposited in one of the goal regions H, I and E.",
        "The three blocks shall occupy regions H, I and E, max one object per region.",
        "Blocks → regions H and I; at most one object per region.",
        "Put the three blocks in regions H, I and E, each region accommodating a single object.",
        "Regions H, I and E receive one block each.",
        "Use regions H and I for the three blocks, one block per region.",
    ],
    3: [
        "Move the three pillars to regions E, F and G. No object may be placed on any other area than region "
        "H.",
        "Plan how to move the three pillars to the placement area at the side of arm a and arm b, which is "
        "region E, F and G.",
        "Explain how to move the three pillars to regions E, F and G. No object can be placed on an area "
        "other than the target region.",
        "Three pillars to regions E, F, G. Region H may be used.",
        "Three pillars to regions E, F, G. No object on H, I.",
        "Move the three pillars to regions E, F and G. Regions H and I shall receive no object.",
        "Move the three pillars to regions E, F and G. The other regions may be used for anything.",
        "Pillars → E, F, G. Keep H, I empty.",
        "It is necessary to move the three pillars to regions E, F and G, whereby no object may be placed on "
        "region H.",
        "Pillars: regions E, F and G. Region H: forbidden.",
    ],
    4: [
        "Move the three blocks into the opposite regions. No arm may pick the red block up until an arm has "
        "picked the blue block up. After all of these, put the yellow block back down on region G.",
        "The three blocks are to be moved into the opposite regions, provided that no arm touches the red "
        "block until the blue block has been touched. Subsequently, the yellow block is to be returned to "
        "region G.",
        "The three blocks shall be transferred to the opposite regions. Upon completion, the yellow block "
        "shall be returned to region G.",
        "All three blocks go to the opposite regions. The blue block may not be picked up by any arm prior "
        "to the yellow block being picked up. At the end, the yellow block returns to region G.",
        "All three blocks go to the opposite regions. The red block may not be picked up by any arm prior to "
        "the blue block being picked up. At the end, the yellow block returns to region G.",
        "Three blocks to the opposite regions. Red only after blue has been touched. Yellow: back to region "
        "G at the end.",
        "Three blocks to the opposite regions. Blue only after red has been touched. Yellow: back to region "
        "H at the end.",
        "Transfer the three blocks into the opposite regions; in the meantime, the red block may only be "
        "touched after the blue block has been touched. Finally, put the yellow block back on region G.",
    ],
    5: [
        "The red block and the blue block shall exchange their positions, the blue block being placed first. "
        "The yellow block goes to the opposite side at any time.",
        "The red and yellow blocks shall exchange their positions, the red block being placed first. The "
        "yellow block goes to the opposite side at any time.",
        "The red and yellow blocks should be swapped, red placed first. The blue block also has to reach the "
        "opposite side, but it does not matter when.",
        "Red <-> yellow, red first. The blue block to the opposite side, at any time.",
        "Red <-> blue, blue first. The yellow block to the opposite side, at any time.",
    ],
    6: [
        "Could you place the three objects separately in region G, region H and region I? Please put the "
        "blue block down before the red block.",
        "Place the three objects separately in region G, region H and region I. Put the red block down on "
        "region H before the blue block.",
        "Each of the three blocks gets its own region among G, H and J. When placing them, do the red block "
        "before the blue block.",
        "Regions G, H and I should end up with one block each; as for the order, the blue block goes before "
        "the red block.",
    ],
    7: [
        "Region I should receive the three blocks. Red has to come before blue, and while this happens, "
        "regions F, G and H must stay empty.",
        "All three to I, one after another, red before blue. F, G stay empty meanwhile.",
        "Region I should receive the three blocks one after another. Blue has to come before red, and while "
        "this happens, regions F, G and H must stay empty.",
        "Region I: all three blocks, one after another, blue before red; F, G and H off limits.",
        "Region I: all three blocks, one after another, red before blue; F and G off limits.",
        "3 objects -> region I one after another (red before blue); F/G: nothing during this period.",
        "Region I gets the three blocks in turn, the red block before the blue block, with regions F and G "
        "kept free during this period.",
    ],
    8: [
        "The yellow block is to be placed on region G first and on region I thereafter; the red and blue "
        "blocks are to be moved to any empty region at any time.",
        "Take the yellow block to region I and, after that, to region H. As for the red and blue blocks, "
        "they simply need to be moved to any empty region at any time.",
        "The yellow block visits region G first and then region I. The red and blue blocks go to any empty "
        "region at any time you like.",
        "Two things: yellow block on region G, then on region I; the red and blue blocks to any empty region "
        "at any time.",
        "Put the yellow block on region G, and once it is there, put it on region I. The red and blue "
        "blocks, on the other hand, also go to any empty region at any time.",
    ],
}

# Our fresh rounds in the styles h38 found weakest (terse, formal, explanatory), each run once on first
# contact before the reader was changed for it (instance 0): round 1 (24 sentences): 10 gave the written
# spec, 14 were refused, 0 another spec; round 2 (24): 11 / 13 / 0; round 3 (24): 2 / 22 / 0; round 4
# (24): 7 / 17 / 0; round 5 (24): 6 / 18 / 0; round 6 (16, mostly explanatory): 8 / 8 / 0. After all the
# class fixes: 15 / 9 / 0, 19 / 5 / 0, 19 / 5 / 0, 21 / 3 / 0, 18 / 6 / 0 and 14 / 2 / 0. Still refused:
# reasons and asides ("because ...", "since ...", "to keep things tidy,", "has to wait:", "what I need is
# simple:", "stack nothing:", "has two destinations in order:", "we are trying to clear this side",
# "think of regions H, I and J as slots"), statements of the start ("all of the blocks start on one
# side", "the blocks currently sit on one side"), places defined in one sentence and used as "there" in
# the next, telegraphic chains without a preposition ("Yellow: I, then G", "Yellow -> I -> G", "G, H, I:
# one block each", "Blue block: not to be touched before red block", "red and blue blocks anywhere
# empty"), "respectively", an exchange said as "where the other one started" or "take the blue block's
# spot". The test asserts that each is read right or refused, never misread.
H43_ROUNDS: dict[int, list[str]] = {
    1: [
        "Blocks: all three to the opposite side. Order: red, then blue.",
        "It is requested that the three blocks be transferred to the opposite side, the red block being "
        "placed prior to the blue block.",
        "The goal is to have all three blocks on the opposite side; because the blue block may only be "
        "placed once the red block is there, place red first.",
        "Objective: relocate the three blocks to the opposite side. Constraint: the red block is placed "
        "before the blue block.",
        "Kindly arrange for all three blocks to be moved to the opposite side, with the red block placed "
        "ahead of the blue block.",
        "Since the blocks start on one side, they all have to go across to the opposite side; place the red "
        "one there before the blue one.",
        "Opposite side: all blocks. Red precedes blue.",
        "The arms are required to transfer every block to the opposite side, and the red block is to be "
        "placed before the blue block.",
        "What I need is simple: the three blocks should all end up on the opposite side, and the red one has "
        "to be put there before the blue one.",
        "Transfer: 3 blocks -> opposite side. Red before blue.",
        "The desired outcome is that the three blocks rest on the opposite side, with the red block having "
        "been placed before the blue block.",
        "All of the blocks start on one side of the table. Your job is to get them to the opposite side, and "
        "the red block must be placed before the blue one.",
        "Three blocks, all to the opposite side; red goes down before blue.",
        "Please be advised that all three blocks are to be moved to the opposite side, and that the red "
        "block must be placed before the blue block.",
        "We are trying to clear this side of the table. Take every block over to the opposite side, and make "
        "sure red lands there before blue does.",
        "The blocks currently sit on one side, and they need to be moved to the opposite side. Please place "
        "the red block before the blue block.",
        "For this task, transfer all three blocks to the opposite side; the red one first, then the blue "
        "one.",
    ],
    2: [
        "Three blocks to H, I, J; one per region.",
        "The three blocks are to be placed in regions H, I and J respectively one per region, no region "
        "receiving more than one object.",
        "We need the three blocks to end up in the goal regions H, I and J. Since a region can only hold one "
        "object, each block gets its own region.",
        "Blocks into H, I, J. One object per region.",
        "Each of the three blocks is to be deposited in one of the goal regions H, I and J, and no goal "
        "region may contain more than one object.",
        "The three blocks belong in regions H, I and J. A region can hold just one object, so put one block "
        "in each.",
        "Blocks to regions H/I/J, max one per region.",
        "The three blocks shall occupy regions H, I and J, no region holding more than a single object.",
        "Please fill the goal regions H, I and J with the three blocks; because every goal region fits only "
        "one object, the blocks will end up in different regions.",
        "Place 3 blocks into H, I, J (single object per region).",
        "Regions H, I and J are to receive the three blocks, each region accommodating exactly one object.",
        "The goal regions are H, I and J. Move the three blocks there; note that a goal region can only hold "
        "one object.",
        "H, I and J get one block each.",
        "The three blocks shall be positioned in regions H, I and J, it being understood that each goal "
        "region can only hold one object.",
        "Think of regions H, I and J as three slots that each take one object: put the three blocks into "
        "those regions.",
        "Since each goal region can only be placed with one object, put the three blocks into regions H, I "
        "and J, one per region.",
        "The blocks are to be spread over regions H, I and J, and no two blocks may share a region.",
    ],
    3: [
        "Pillars to E, F, G. Nothing on other regions.",
        "The three pillars shall be relocated to regions E, F and G, which are adjacent to arms a and b; "
        "objects shall not be placed on any region other than the target regions.",
        "The pillars need to go to the area near arms a and b, that is regions E, F and G, and because the "
        "other labelled regions are off limits, never put an object on an area other than the target region.",
        "Three pillars to regions E, F, G. No other region may be used.",
        "All three pillars are to be transferred to the placement area on the side of arm a and arm b, "
        "namely regions E, F and G. Placing an object on any area other than the target region is "
        "prohibited.",
        "Move the pillars to E, F and G, the regions on the side of arm a and arm b. Keep in mind that no "
        "object may ever be put on an area other than the target region.",
        "Pillars → E, F, G. Keep H, I, J empty.",
        "The three pillars are to be conveyed to regions E, F and G, located on the side of arm a and arm b. "
        "At no time may an object be placed on an area other than the target region.",
        "The pillars should go to the placement area by arm a and arm b, i.e. regions E, F and G. The other "
        "regions are not to be used for anything, so do not drop any object on an area other than the target "
        "region.",
        "Move pillars to E/F/G; no placements outside the target regions.",
        "The three pillars must be relocated to the placement area beside arm a and arm b, consisting of "
        "regions E, F and G; placing objects anywhere other than the target region is not permitted.",
        "Here is the task: the three pillars have to end up in regions E, F and G, on the side of arm a and "
        "arm b. While doing this, no object may be placed on an area other than the target region.",
        "Pillars: E, F and G. Other regions: never.",
        "The three pillars should be moved to the placement area at the side of arm a and arm b, being "
        "regions E, F and G, and no object should be placed on an area other than the target region.",
        "The pillars belong on arm a and arm b's side, in regions E, F and G. Since the other regions must "
        "stay free, no object may be placed on an area other than the target region.",
        "The pillars have to be moved over to regions E, F and G, which are next to arm a and arm b. Objects "
        "can only be placed on the target regions.",
        "Bring the three pillars to regions E, F and G. To keep things tidy, no object may be placed on an "
        "area other than the target region.",
    ],
    4: [
        "Three blocks to the opposite regions. Blue untouched until red is touched. Last: yellow back to G.",
        "The three blocks shall be transferred to the opposite regions. No arm shall touch the blue block "
        "before the red block has been touched. Upon completion, the yellow block shall be returned to "
        "region G.",
        "First the three blocks go over to the opposite regions. The blue block has to wait: no arm may "
        "touch it until some arm has touched the red block. When that is done, the yellow block goes back to "
        "region G, where it started.",
        "Three blocks: opposite regions. Blue block: not to be touched before red block. Then yellow back to "
        "region G.",
        "The three blocks are to be moved into the opposite regions, provided that no arm touches the blue "
        "block until the red block has been touched. Subsequently, the yellow block is to be returned to "
        "region G.",
        "Start by moving the three blocks to the opposite regions. There is one restriction: the blue block "
        "must not be picked up by any arm before the red block has been picked up. Once that is finished, "
        "move the yellow block back to region G.",
        "Opposite regions for all three blocks; red must be touched before blue; yellow returns to G at the "
        "end.",
        "All three blocks must be delivered to the opposite regions. The blue block may not be grasped by "
        "any arm prior to the red block being grasped. Once the above is complete, the yellow block must be "
        "placed back on region G.",
        "You will move the three blocks to the opposite regions. Be careful about one thing: the blue block "
        "must stay untouched until an arm has touched the red block. At the very end, the yellow block goes "
        "back to region G.",
        "Blocks to the opposite regions. Touch red before blue. Afterwards, yellow back to region G.",
        "It is necessary to transfer the three blocks into the opposite regions, whereby the blue block "
        "shall not be touched until the red block has been touched; thereafter the yellow block shall be "
        "placed back on region G.",
        "Move the three blocks across to the opposite regions. There is a rule about touching: the arms must "
        "leave the blue block alone until one of them has touched the red block. Once everything is done, "
        "put the yellow block back on region G.",
        "Opposite regions: three blocks. Blue only after red has been touched. Yellow: back to G last.",
        "Transfer the three blocks into the opposite regions under the condition that no arm touches the "
        "blue block before an arm touches the red block; upon finishing, return the yellow block to region "
        "G.",
        "Here's what should happen. The three blocks travel to the opposite regions. The arms can only touch "
        "the blue block after the red block has been touched. After all of that, the yellow block is put "
        "back on region G.",
        "First, transfer the three blocks into the opposite regions. While doing so, the blue block may only "
        "be touched after the red block has been touched. Finally, put the yellow block back on region G.",
        "The three blocks go to the opposite regions, with the constraint that an arm may touch the blue "
        "block only once the red block has been touched. When everything else is finished, return the yellow "
        "block to region G.",
    ],
    5: [
        "Swap red and blue, red first. Yellow to the opposite side, any time.",
        "The positions of the red block and the blue block shall be exchanged, with the red block placed "
        "before the blue block; the yellow block shall be moved to the opposite side at any time.",
        "The red and blue blocks should trade places, and since the red one goes down first, place it before "
        "the blue one. The yellow block just needs to reach the opposite side at some point.",
        "Exchange red and blue; red placed first. Yellow: opposite side, any time.",
        "The red block and the blue block are to exchange positions, the red block to be placed before the "
        "blue block. The yellow block is to be moved to the opposite side at any time.",
        "Red and blue need to swap places. Because red must be placed before blue, start with red. The "
        "yellow block can go to the opposite side whenever convenient.",
        "Red and blue swap positions (red placed first); yellow to the opposite side whenever.",
        "The red block and the blue block shall exchange their positions, the red block being placed first, "
        "while the yellow block shall be transferred to the opposite side at an arbitrary time.",
        "I want red and blue to end up where the other one started, and red should be placed before blue. "
        "Whenever it suits you, also move the yellow block to the opposite side.",
        "Swap red/blue positions, red placed first; yellow -> opposite side at any time.",
        "It is required that the red block and the blue block exchange positions, the red block being placed "
        "before the blue block, and that the yellow block be moved to the opposite side at any time.",
        "The red and blue blocks should end up swapped. Put the red one down first, then the blue one. The "
        "yellow block also has to go to the opposite side, but it does not matter when.",
        "Red <-> blue (red first). Yellow to the opposite side, any time.",
        "Interchange the positions of the red and blue blocks, placing red before blue; additionally, "
        "transfer the yellow block to the opposite side at any time.",
        "The red block should take the blue block's spot and the blue block the red block's spot, with red "
        "being placed first. The yellow block goes across to the opposite side at any time.",
        "The red block and the blue block trade places, and the red block is placed first. In addition, the "
        "yellow block is moved to the opposite side whenever you like.",
        "To swap the red and blue blocks, place the red block before the blue block. The yellow block, on "
        "the other hand, can go to the opposite side at any time.",
    ],
    6: [
        "Three blocks to G, H, I, one each. Red before blue.",
        "The three objects shall be placed separately on regions G, H and I, the red block being placed "
        "before the blue block.",
        "Put the three blocks on regions G, H and I, one block per region; the order matters only for red "
        "and blue: red has to be placed before blue.",
        "G, H, I: one block each. Red before blue.",
        "The three blocks are to be placed separately in regions G, H and I, and the red block must be "
        "placed prior to the blue block.",
        "Distribute the three blocks over regions G, H and I so that each region gets one block. The red "
        "block has to go down before the blue block.",
        "Regions G, H, I get the three blocks, one each; red placed before blue.",
        "The three blocks shall be placed separately in regions G, H and I, where the red block is required "
        "to be placed before the blue block.",
        "Spread the three blocks across regions G, H and I, one per region. The only ordering rule is that "
        "the red block is placed earlier than the blue block.",
        "3 blocks -> G, H, I separately. Red before blue.",
        "The three blocks are to be distributed separately over regions G, H and I, the placement of the red "
        "block preceding that of the blue block.",
        "Each of the three blocks needs its own region among G, H and I. When placing them, do the red block "
        "before the blue block.",
        "G, H, I - one block in each; red before blue.",
        "The three blocks are to be placed individually on regions G, H and I, whereby the red block is to "
        "be placed before the blue block.",
        "Use regions G, H and I for the three blocks, one block per region, and make sure the red block is "
        "down before the blue block.",
        "The three blocks go separately to regions G, H and I. As for the order, the red block is placed "
        "before the blue block.",
        "Regions G, H and I should end up with one block each, and the red block must be placed before the "
        "blue block.",
    ],
    7: [
        "All three to I, one after another, red before blue. F, G, H stay empty meanwhile.",
        "The three objects shall be placed on region I one after another, the red block before the blue "
        "block; during this period no object shall be placed on regions F, G or H.",
        "Region I should receive the three blocks one after another. Red has to come before blue, and while "
        "this happens, regions F, G and H must stay empty.",
        "Three blocks onto region I in turn; red before blue; no objects on F, G, H in the meantime.",
        "The three objects are to be placed on region I one after another, with the red block preceding the "
        "blue block; no object may be placed on regions F, G or H during this period.",
        "Put each of the three blocks on region I in turn. The red block must come before the blue block, "
        "and until then nothing should be put on region F, G or H.",
        "Region I: all three blocks, one after another, red before blue; F, G, H off limits.",
        "The three blocks shall be placed on region I in succession, the red block prior to the blue block, "
        "and regions F, G and H shall receive no object during this period.",
        "Stack nothing: put the three blocks on region I one at a time, red before blue, and keep regions F, "
        "G and H free the whole time.",
        "3 objects -> region I one after another (red before blue); F/G/H: nothing during this period.",
        "The three objects shall be deposited on region I one after another, the red block ahead of the blue "
        "block, and no object shall be placed on regions F, G and H throughout.",
        "Put the three blocks onto region I, one after the other. Red must go before blue. For as long as "
        "this takes, regions F, G and H must not receive any object.",
        "Region I gets the three blocks in turn, red before blue, with F, G and H kept empty meanwhile.",
        "Successively place the three objects on region I, the red block preceding the blue block, while "
        "ensuring that no object is placed on region F, G or H during this period.",
        "All three blocks need to visit region I, one after another. Red comes before blue. Meanwhile "
        "nothing may be put on regions F, G and H.",
        "All three blocks have to be placed on region I one after another, red before blue. While this is "
        "going on, nothing can be put on regions F, G and H.",
        "The three objects are placed on region I one after another; the red block is placed before the blue "
        "block, and in the meantime regions F, G and H stay empty.",
    ],
    8: [
        "Yellow: I, then G. Red and blue: any empty region, any time.",
        "The yellow block shall first be placed on region I and subsequently on region G; the red and blue "
        "blocks shall be moved to any empty region at any time.",
        "The yellow block makes two stops: first region I, then region G. The red and blue blocks only need "
        "to get to any empty region, whenever you like.",
        "Yellow block to region I, then to region G. Red and blue blocks to any empty region at any time.",
        "The yellow block is to be placed on region I first and on region G thereafter; the red and blue "
        "blocks are to be moved to any empty region at any time.",
        "Take the yellow block to region I and, after that, to region G. As for the red and blue blocks, "
        "they simply need to be moved to any empty region at any time.",
        "Yellow → I → G. Red, blue → any empty region, any time.",
        "The yellow block shall be moved to region I and subsequently to region G, whereas the red and blue "
        "blocks shall be moved to any empty region at any time.",
        "The yellow block visits region I first and then region G. Meanwhile, at any time you like, the red "
        "and blue blocks have to be moved to any empty region.",
        "Yellow block: region I, then region G. Red and blue blocks: any empty region, at any time.",
        "The yellow block shall be placed first on region I and then on region G; the red block and the blue "
        "block shall each be moved to any empty region at any time.",
        "The yellow block has two destinations in order: region I and then region G. The red and blue blocks "
        "just have to reach any empty region at some point.",
        "Yellow block on I, then on G; red and blue blocks anywhere empty, any time.",
        "The yellow block is to be positioned first on region I and subsequently on region G, and the red "
        "and blue blocks are to be relocated to any empty region at any time.",
        "Two things: the yellow block goes to region I and after that to region G; and the red and blue "
        "blocks go to any empty region, at any time.",
        "The yellow block is first placed on region I and then on region G. The red and blue blocks, on the "
        "other hand, go to any empty region at any time.",
        "Move the yellow block to region I, and once it is there, move it on to region G. At any time, also "
        "move the red and blue blocks to any empty region.",
    ],
}

# Written by the lead in session 9 after h43 had started (batch 8) and never shown to any helper. First
# contact, on main with h38's rules: 15 gave the written spec, 1 was refused ("In the end, after all of
# this, put ..."), 0 another spec; after h43's rules the same 15 / 1 / 0. The lead then read stacked
# closing markers ("in the end, after all of this", "finally, after all of that") as one; that sentence
# is read now and is no longer held out.
LEAD_SESSION9_BATCH8: dict[int, list[str]] = {
    1: [
        "Get the three blocks over to the opposite side. The red one should be put there before the blue "
        "one.",
        "Transfer all the three blocks into the opposite regions; the red block is to be placed before "
        "the blue block.",
    ],
    2: [
        "Put three blocks in the goal regions H, I and J, and each goal region can hold only one object.",
        "The three blocks need to go into region H, region I and region J, one object in each goal "
        "region.",
    ],
    3: [
        "Move the three pillars to the placement area (regions E, F, G) beside arm a and arm b; objects "
        "can't be placed anywhere other than the target region.",
        "Please move the three pillars to region E, F and G. No object should be placed on an area other "
        "than the target region.",
    ],
    4: [
        "Move all three blocks to the opposite regions. The blue block can't be touched by a robot arm "
        "until a robot arm has touched the red block. After all of these, place the yellow block back to "
        "region G.",
        "Transfer three blocks into the opposite regions, and the robot arms cannot touch the blue block "
        "until one of them has touched the red block. In the end, after all of this, put the yellow "
        "block back to region G.",
    ],
    5: [
        "Exchange the positions of the red and blue blocks, placing the red block before the blue block, "
        "and at any time move the yellow block into the opposite side.",
        "Swap the red block and the blue block. The red block should be placed before the blue block. "
        "Also, at any time, put the yellow block to the opposite side.",
    ],
    6: [
        "Please place the three blocks separately on region G, region H and region I. The red block "
        "should be placed before the blue block.",
        "Put the three objects to regions G, H and I separately; place the red block before the blue "
        "block.",
    ],
    7: [
        "Put the three blocks on region I one after another. During this period, no objects can be "
        "placed on regions F, G and H. Place the red block before the blue block.",
        "The red block should be placed before the blue block. The three objects should be placed to "
        "region I one after another, and during this period no object can be placed on region F, G or H.",
    ],
    8: [
        "First place the yellow block to region I, then place the yellow block to region G. At any time, "
        "move the red and blue blocks to any empty region.",
        "Put the yellow block on region I, then on region G, and at any time move the red block and the "
        "blue block to any empty region.",
    ],
}


# Stacked closing markers (the lead's fix above): variants that give the written spec, and near misses.
STACKED_MARKERS: dict[int, list[str]] = {
    4: [
        "Move the three blocks to the opposite regions; no arm may touch the blue block until the red block "
        "has been touched. Finally, after all of that, place the yellow block back to region G.",
        "Move the three blocks to the opposite regions; no arm may touch the blue block until the red block "
        "has been touched. Then, once all of this is done, place the yellow block back to region G.",
    ],
}
STACKED_MARKER_NEAR_MISSES: dict[int, list[str]] = {
    4: [
        "Move the three blocks to the opposite regions; no arm may touch the blue block until the red block "
        "has been touched. In the end, after all of this, place the yellow block back to region H.",
        "Move the three blocks to the opposite regions. In the end, after all of this, place the yellow "
        "block back to region G.",
    ],
}

# Written by the lead in session 9 after every rule of the session was in (batch 9) and run once on the
# final reader, never shown to anyone who wrote rules: 15 gave the written spec, 1 was refused by name
# ("regions F, G and H can't have any object placed on them"), 0 another spec. Left as it is: held out.
# Session 10 (h47): the refused sentence is read now (a prohibition with "them" naming its own regions).
LEAD_SESSION9_BATCH9: dict[int, list[str]] = {
    1: [
        "Please move the three blocks to the opposite side; place the red block before you place the "
        "blue block.",
        "Red block before blue block: bring all three blocks to the opposite regions.",
    ],
    2: [
        "Move the three blocks into region H, region I and region J. Each goal region may contain only "
        "one object.",
        "Please place the three blocks in the three goal regions H, I and J, with just one object in "
        "each goal region.",
    ],
    3: [
        "Please transfer the three pillars to the placement area (regions E, F and G) at the side of arm "
        "a and arm b. Do not put objects on any area other than the target region.",
        "Move the three pillars to region E, F and G. Objects must not be placed on any area other than "
        "the target region.",
    ],
    4: [
        "Please move the three blocks to the opposite regions. Until one of the robot arms has touched "
        "the red block, the blue block must not be touched. After all of this, place the yellow block "
        "back on region G.",
        "Transfer the three blocks into the opposite regions, making sure no arm touches the blue block "
        "until an arm has touched the red block. After that is all done, return the yellow block to "
        "region G.",
    ],
    5: [
        "Swap the positions of the red block and the blue block; the red block should be placed before "
        "the blue block. Also move the yellow block to the opposite side at any time.",
        "Exchange the positions of the red and blue blocks, putting the red block down before the blue "
        "block. The yellow block should go to the opposite side at any time.",
    ],
    6: [
        "Please put the three blocks separately into regions G, H and I, and place the red block before "
        "the blue block.",
        "Place the red block before the blue block, and place the three blocks separately on region G, "
        "region H and region I.",
    ],
    7: [
        "Place the three blocks on region I one after another, and place the red block before the blue "
        "block. No objects may be placed on regions F, G and H during this period.",
        "Please put the three objects to region I one after another. During this period, regions F, G "
        "and H can't have any object placed on them. The red block should be placed before the blue "
        "block.",
    ],
    8: [
        "Put the yellow block on region I first and then on region G. Also, at any time, move the red "
        "block and the blue block to any empty region.",
        "Please move the red and the blue block to any empty region at any time, and place the yellow "
        "block first on region I, then on region G.",
    ],
}
