"""Session 10 (h47): our rephrasings by style (`handover_styles_session10.json`: `dev`, `dev2`, and the
`validation` batch measured once at the end) and near misses of the forms added for them. Each near miss
changes one meaning of a sentence the reader now reads (another block or region, the order reversed, a
constraint or "at any time" left out, a count): it must be refused or give another spec."""

import json
from pathlib import Path

STYLES = json.loads((Path(__file__).parent / "handover_styles_session10.json").read_text())

# Development sentences still refused on purpose (each by name): statements of the scene or of a purpose
# that name a place or a relation the reader does not model, an "after" that may mean "then", a block whose
# goal is left to an ellipsis, and "stack" (a list of fragments, "- three blocks" over "- regions H, I and J",
# is read since h114 as the blocks and their place: test_handover_fourteenth_round.py).
STILL_REFUSED = {
    "To clear this side of the table, move all three blocks to the opposite side; the red block has to be "
    "placed before the blue block.",
    "The red block is holding the blue one in place, so no arm may touch the blue block until the red "
    "block has been touched. Move all three blocks to the opposite regions, and once that is done, put the "
    "yellow block back on region G, where the red block is now.",
    "The yellow block needs to pass through region I, so put it on region I first and then on region G. "
    "The red and blue blocks can go to any empty region at any time, since their order does not matter.",
    "Please first put yellow block to region I, after put yellow block to region G, and the red and blue "
    "block move to any empty region any time.",
    "We have three goal regions, H, I and J, and three blocks, so put the three blocks in regions H, I and "
    "J with one block per region.",
    "The pillars are in the way on the far side, so bring the three pillars to regions E, F and G, and "
    "don't put any object on a region other than the targets.",
    "Move the three blocks to the opposite regions, but leave the blue block alone until the red block has "
    "been picked up, because the red one has to be handled first. Once everything has been moved, put the "
    "yellow block back on region G.",
    "Move the three blocks to the opposite regions. The blue block must stay untouched until the red block "
    "has been touched, because the red one is picked up first. After all of that is done, put the yellow "
    "block back on region G.",
    "The red and blue blocks are in the wrong places, so exchange their positions, with the red block "
    "placed before the blue block. Because the yellow block's timing doesn't matter, move it to the "
    "opposite side at any time.",
    "The yellow block goes to region I first and then on to region G; this is the only ordering. The red "
    "and blue blocks go to any empty region at any time.",
    "The red block is to be moved to the opposite side before the blue block, and the yellow block is to "
    "be moved there as well.",
    # dev4: statements of purpose or of the scene ("on top of the plan", "each other's spots", "a drop-off",
    # "two stops", "reserved")
    "We want the pillars back at regions E, F and G. While moving them, keep every other region empty, "
    "because those regions are reserved.",
    "First move the three blocks to the opposite regions; note that the blue block cannot be touched until "
    "the red one has been, since the red block is on top of the plan. When everything is over there, bring "
    "the yellow block back to region G.",
    "To get the red and blue blocks into each other's spots, swap them, red before blue. The yellow block "
    "should just go to the opposite side at some point, whenever it is convenient.",
    "Use region I as a drop-off: one after another, put the three blocks on region I, red before blue. "
    "Regions F, G and H must stay empty the whole time, since they are blocked.",
    "The yellow block has two stops: region I and then region G. The other two blocks, red and blue, just "
    "need to go to any empty region at any time.",
    # dev5: reasons that carry what is not modelled ("should arrive first", "handled first", "has to wait",
    # "has priority", "visit region I before region G")
    "The red block should arrive first, so move the red block to the opposite side before the blue block, "
    "and bring the yellow block over too.",
    "Exchange the positions of the red block and the blue block, placing red first since blue has to wait "
    "for it. It doesn't matter when the yellow block goes to the opposite side.",
    "Because the red block has priority, put it down before the blue block; the three blocks go separately "
    "to regions G, H and I.",
    "Since the yellow block must visit region I before region G, put it on region I first, then on region "
    "G. Red and blue can go to any empty region at any time.",
    # dev7: "their" across sentences (refused on purpose, as "swap them" is)
    "The red block has to be placed before the blue block. Swap their positions. The yellow block goes to "
    "the opposite side at any time.",
    # dev8: "that way nothing is stacked" (a negation, so not dropped as framing), "stack"
    "Every goal region takes a single block, so place the three blocks in regions H, I and J, one per "
    "region; that way nothing is stacked.",
    "Stack the three blocks nowhere but region I, one after another, red before blue, and put nothing on "
    "regions F, G and H meanwhile.",
    # dev9: "there is no order for them" (a statement about an order, not read)
    "Put the yellow block on region I, then on region G. Move the red and blue blocks to any empty region "
    "at any time; there is no order for them.",
    # dev10 (h50): reasons that state the scene or a purpose ("belong on", "knocking over"), a goal said
    # twice ("visit region I before it ends at region G, so take it to I first"), and headings whose
    # subject is left to the goal ("Timing: yellow at any time", "Target regions: G, H and I")
    "To avoid knocking the blue block over, don't touch it until the red block has been touched. Move "
    "the three blocks to the opposite regions, and when they are all there, bring the yellow block "
    "back to region G.",
    "The yellow block has to visit region I before it ends at region G, so take it to I first and "
    "then to G. The red and blue blocks just need to be in some empty region, at any time.",
    "Goal: red and blue blocks swapped, yellow block on the opposite side. Order: red before blue. "
    "Timing: yellow at any time.",
    "Target regions: G, H and I, one block each. Order: red block first, then blue block.",
}

NEAR_MISSES_S10: dict[int, list[str]] = {
    1: [
        "Can you get the three cubes to the opposite side? Make sure the blue cube is placed before the "
        "red cube.",
        "To keep things simple, move all three blocks to the opposite side, and because the blue block "
        "must be there first, place it before the red block.",
        "Blue goes before red. With that rule, transfer all three blocks to the opposite side.",
        "All three blocks please move to the opposite side, but blue block must first be placed, then red "
        "block.",
        "Move the thee blocks to the opposite sied, and place the blue block bfore the red blok.",
        "Get every block onto the opposite side, but the blue block goes down before the red block does.",
        "The operator requires that the three blocks be transferred to the opposite side; the blue block "
        "is to precede the red block.",
        "Please do the following:\n1. Move all three blocks to the opposite side.\n2. Place the blue block "
        "before the red block.",
        "Move 3 blocks to opposite side, blue before red.",
        "All three blocks should end up on the opposite side. The blue one needs to be there before the "
        "red one, so place blue first.",
        "ok so move all 3 blocks to the opposite side, blue one before the red one pls",
        "The agent shall transfer all three blocks to the opposite side, the blue block being placed prior "
        "to the red block.",
        "The three blocks are to be moved to the opposite side, and the blue block is to be placed before "
        "the red block.",
        "Bring the blocks across to the opposite side, all two of them, and the red one has to get there "
        "before the blue one.",
        "Bring the blocks across to the opposite side, all three of them, and the blue one has to get "
        "there before the red one.",
        "The blue block must be placed before the red block; with that, move all three blocks to the "
        "opposite side.",
    ],
    2: [
        "Pop the three blocks into regions H and I, one apiece.",
        "The blocks should each be placed in one of regions H and I, no two in the same region.",
        "The three blocks are to be distributed over regions H and I, each region receiving exactly one "
        "block.",
        "Instructions:\n1) Put the three blocks in regions H and I.\n2) Put only one block in each region.",
        "There are three goal regions, H, I and J. Put the red and blue blocks into them; since a region "
        "holds only one object, each gets one block.",
        "Put the three block into the region H and I, one region is only for one block.",
        "Regions H and I are to receive the three blocks, one block each.",
        "Regions H, I and J can each hold only one block, so put one of the red and blue blocks in each of "
        "them.",
        "One object per region, regions H, I and J: put the red and blue blocks there.",
        "1) put the three blocks into regions H and I\n2) one block per region",
    ],
    3: [
        "Carry the three pillars across to regions E, F and G, and on no account place an object on region "
        "H.",
        "Move the three pillars to regions E, F and G. Restriction: objects may only be placed on regions "
        "E, F, G and H.",
        "Pillars (two) must go to region E, F, G; any object must not be placed to region H, I, J.",
        "Move the three pilars to regions E, F and G. Dont place any objcet on regions H or I.",
        "Take the three pillars to regions E, F and G and keep regions H and I free of objects until then.",
        "The three pillars shall be returned to the placement area comprising regions E, F and G. At no "
        "point may any object be placed on regions H or I.",
        "The pillars need to be on the side of arm c and arm d, that is regions E, F and G, and since the "
        "other regions must not be used, never put an object on them.",
        "1 - Move the three pillars to regions E, F and G.\n2 - Never place an object on regions H or I.",
        "Pillars to regions E, F only.",
        "Pillars to regions E, F, G.",
        "Please to move the three pillars into region E, F and G. No object to put on region H.",
        "move the pillars over to E, F and G and don't put stuff on region H",
        "The pillars have to go back to the side of arms a and b, regions E, F and G. Because regions H "
        "and I must stay clear, do not place any object on them.",
        "The pillars have to go to regions E, F and G. Do not place any object on them.",
        "Move three pillar to region E, F, G which is at side of arm a and arm b. The object can not put "
        "on region H.",
        "Move the three pillars from H, I and J over to E, F and G, and don't drop anything on a region "
        "that's a target.",
    ],
    4: [
        "Move the three blocks to the opposite regions; for safety, no arm may touch the red block until "
        "the blue block has been touched. Once that is done, put the yellow block back on region G.",
        "The three blocks should be transfer to opposite regions. Blue block must not be touched before "
        "red block was touched. After all, yellow block must be put back to region H.",
        "All blocks are to be transferred to the opposite regions; the red block may only be touched once "
        "the blue block has been touched; finally, the yellow block is to be put back on region G.",
        "Put the three blocks in the opposite regions. Keep your hands off the red block until the blue "
        "block has been touched. When you're all done, move the yellow block back to region G.",
        "Move three block into opposite region, the red block can not be touch until blue block be "
        "touched. At last put yellow block back to region G.",
        "Move three block into opposite region, the blue block can not be touch until red block be "
        "touched. At last put yellow block back to region H.",
        "First: move the three blocks to the opposite regions, but do not touch the blue block until the "
        "red block has been touched.\nSecond: after all of that, put the yellow block back on region H.",
        "Opposite regions for all blocks. No touching red until blue is touched. Then yellow back on G.",
        "Move three blocks to opposite regions. Red block is not allow to touch before blue block is "
        "touched. After finishing all, put yellow block back on region G.",
        "Move three blocks to opposite regions. Blue block is not allow to touch before red block is "
        "touched. After finishing all, put yellow block back on region H.",
        "The three blocks are to be placed on the opposite regions, with the red block not being touched "
        "until the blue block has been touched. The yellow block is then to be returned to region G once "
        "all of this is done.",
        "The three blocks are to be placed on the opposite regions, with the blue block not being touched "
        "until the red block has been touched. The yellow block is then to be returned to region H once "
        "all of this is done.",
        "Move the three blocks to the opposite regions and then put the yellow block back on region H "
        "after all of that. The blue block must not be touched before the red block is touched.",
        "1. Transfer the three blocks to the opposite regions.\n2. Rule: no arm touches the red block "
        "until the blue block has been touched.\n3. Once everything is done, return the yellow block to "
        "region G.",
        "move the blocks to the opposite regions, but don't touch red till blue's been touched. after all "
        "that, yellow goes back on G",
        "The three blocks are to be moved to the opposite regions; the red block is not to be touched "
        "until the blue block has been picked up. After that, the yellow block is to be put back on region "
        "G.",
        "Until the blue block has been touched, the red block must stay untouched. Move the three blocks "
        "to the opposite regions, and after all of that put the yellow block back on region G.",
        "Blocks to opposite regions. Don't touch blue before red. Then yellow back to H.",
        "Transfer three blocks into the opposit regions. The robot arm can't tuch the blue block untill an "
        "arm has touched the red block. After all of thsi, put the yelow block back to region H.",
        "Blocks -> opposite regions; red not touched before blue. Finally: yellow -> G.",
        "Carry the three blocks over to the opposite regions, and don't pick up the red one until the blue "
        "one has been picked up. Once you're done with that, put the yellow block back on G.",
        "Please transfer three block to opposite region. Robot arm can not touch red block until robot arm "
        "touch blue block first. After all these, please put yellow block back in region G.",
    ],
    5: [
        "Switch the red and blue blocks round, blue first; the yellow block can be taken to the opposite "
        "side whenever suits.",
        "Swap the red and blue blocks (blue goes down first) and, whenever you want, move the yellow block "
        "across to the opposite side.",
        "Exchange red block and blue block the positions, first place blue block. Yellow block to opposite "
        "side any time is ok.",
        "Swap the red and blue blocks, placing the blue one frist. Move the yelow block to the opposite "
        "side at any tmie.",
        "Red <-> blue, blue first. Yellow: opposite side, anytime.",
        "Please change the positions of red block and blue block, blue block first place. Yellow block go "
        "to opposite side any time.",
        "The red and blue blocks are to have their positions exchanged, the blue one being placed before "
        "the red one; the yellow block is to be moved to the opposite side at any time.",
        "Goals:\n- swap the red and blue blocks (blue is placed first)\n- yellow block to the opposite "
        "side, at any time",
        "Step 1: swap the red block and the blue block, the red one going first. Step 2: move the yellow "
        "block to the opposite side.",
        "Because the blue block must be placed first, swap the red block and the blue block with blue "
        "going before red. The yellow block only has to reach the opposite side, at any time.",
    ],
    6: [
        "Put the three blocks on regions G, H and J, a different region for each block, placing the red "
        "block before the blue block.",
        "Step one: place the blue block before the red block.\nStep two: put the three blocks separately "
        "in regions G, H and I.",
        "G, H, J: one block each. Red before blue.",
        "The red block must be placed before the blue one, as the order matters here. Put the three blocks "
        "separately on regions G, H and J.",
        "Please place the three blocks separately at region G, H and I, and the blue block place before "
        "the red block.",
        "1) blue before red\n2) the three blocks go separately into regions G, H and I",
        "The red block should be palced before the blue block. Plaese place the three objects seperately "
        "to region G, H and J.",
        "Regions G, H and J are the targets: place the three blocks separately in them, and because red "
        "must come first, place the red block before the blue block.",
        "Red block should be place before blue block, please place three object separate into region G, H, "
        "J.",
    ],
    7: [
        "1. Put the three blocks on region I one after another, red before blue.\n2) Because regions F and G "
        "must stay clear meanwhile, put nothing on them.",
        "Drop the three blocks on region I in turn, red before blue; regions F and G are to stay clear "
        "throughout.",
        "Because region F must stay empty meanwhile, put the three blocks one after another on region I, "
        "red before blue, and put nothing on regions G and J.",
        "While this is being done, nothing may be placed on regions F and H: put the three blocks one "
        "after another on region I, red before blue.",
        "One after another put three blocks to region I, red block before blue block, during this period "
        "do not put object on region F, G.",
        "Place the three blocks one after anohter on region I, the red blcok before the blue block, and "
        "put nothign on regions F and G meanwhile.",
        "The three blocks shall be deposited on region I sequentially, the red block prior to the blue "
        "block, and no object shall be deposited on regions F or G in the interim.",
        "All 3 onto I, one by one. Red, then blue. Keep F, G empty meanwhile.",
        "Three blocks put on region I one after other, red block before blue block, in this time region F "
        "and G no object.",
        "During this whole task, regions F and G must stay empty. Put the three blocks on region I one "
        "after another, red before blue.",
        "The three blocks shall be placed on region I in succession, the red block preceding the blue "
        "block. For the duration of this task, no object shall be placed on regions F, G or J.",
        "Put the three blocks on region I one at a time, red before blue. While you do this, don't put "
        "anything on regions F or G.",
        "Blocks onto I one by one, red before blue. F, G empty meanwhile.",
        "Please put the three objects to region I one after another. During this period, regions F and G "
        "can't have any object placed on them. The red block should be placed before the blue block.",
        "Since F and G have to stay free, put nothing on regions F and G while you place the three blocks "
        "one after another on region I, the red block before the blue block.",
        "Red block should be placed before blue block. Please place three object one after another into "
        "region I, during this period region F, G can not place any object.",
    ],
    8: [
        "Yellow block must be placed to region G first and to region I after. Red and blue blocks must be "
        "moved to any empty region at any time.",
        "Move the yellow block to region G first and to region I after that. Move the red and blue blocks "
        "to empty regions whenever you like.",
        "Step 1 - put the yellow block on region G.\nStep 2 - put the yellow block on region I.\nAlso, at "
        "any time, move the red and blue blocks to any empty region.",
        "Yellow: G then I. Red + blue: any empty region, whenever.",
        "Yellow: I then G. Red: any empty region, whenever.",
        "First yellow block put on region I, then put on region H. Red block and blue block put on any "
        "empty region any time.",
        "The yellow block is first to be placed on region G and then on region I; the red and blue blocks "
        "are to be placed on any empty region at any time.",
        "yellow goes to G then I; red and blue can go anywhere empty whenever",
        "1. Put the yellow block on region I. 2. Put the yellow block on region G. 3. Move the red and "
        "blue blocks to any empty region.",
        "Yellow: G, then I. Red, blue: any empty region, any time.",
        "Yellow: I, then G. Red: any empty region, any time.",
        "1) Move the yellow block to region I.\n2) Then move it to region G.\n3) Move the red and blue "
        "blocks to any empty region.",
        "Please first place the yellow block to region I, than place the yellow block to region H, and "
        "move red and blue blocks to any empty region at any time.",
    ],
}

# A reason that names a region is read, not dropped as framing: without its region the spec would differ
# (also after a step's number); a framing reason after a step's number is dropped.
REASONS_READ: dict[int, list[str]] = {
    7: [
        "1. Put the three blocks on region I one after another, red before blue.\n"
        "2) Because regions F, G and H must stay clear meanwhile, put nothing on them.",
        "1. Put the three blocks on region I one after another, red before blue.\n"
        "2) For safety, put nothing on regions F, G and H meanwhile.",
        "Because region F must stay empty meanwhile, put the three blocks one after another on region I, red "
        "before blue, and put nothing on regions G and H.",
    ],
    3: [
        "To keep things tidy, move the three pillars to regions E, F and G; since regions H, I and J must "
        "stay free, put nothing on them.",
    ],
}

# dev10 (h50): near misses of the forms read for it and for the earlier refusals fixed with it (step
# headings, 'Forbidden meanwhile:', 'would you mind', 'one block each into', 'are reserved, so never ... on
# them', two blocks 'in the wrong places, so swap them', non-native counts and modals, a period first)
NEAR_MISSES_DEV10: dict[int, list[str]] = {
    1: [
        "Transfer the three blocks into the opposite side. The bleu block should be placed before the red "
        "block.",
        "Please move all two block to opposite side, the red block need to be put before blue block.",
    ],
    2: [
        "Each of regions H and I can only hold one block, so put the three blocks into those regions, one in "
        "each.",
        "Each of regions H, I and J can only hold one block, so put the red and blue blocks into them.",
        "Each of regions H, I and J can only hold one block, so put the three blocks into region H.",
        "Can you put one block each into regions H and I?",
        "Can you put one block each into region H?",
        "The three blocks shall be deposited in regions H and I, and no region shall contain more than "
        "one block.",
        "The three blocks shall be deposited in regions H, I and J, and no region shall contain more than "
        "two blocks.",
        "The three blocks should be placed into regions H and I, each region being given one block.",
        "The three blocks should be placed into regions H, I and J, each region being given two blocks.",
    ],
    3: [
        "Would you mind moving the three pillars to regions E and F? Please don't put anything on any "
        "other region.",
        "Would you mind moving the two pillars to regions E, F and G? Please don't put anything on any "
        "other region.",
        "The pillars need to return to regions E, F and G. Regions H and I are reserved, so never put any "
        "object on them.",
        "The pillars need to return to regions E, F and G. Regions H, I and J are reserved, so put an "
        "object on them.",
        "The pillars need to return to regions E, F and G. Regions H, I and J are reserved, so never put "
        "any object on region H.",
        "Task: move the three pillars to regions E, F and G. Forbidden: regions H and I.",
    ],
    4: [
        "Move three blocks into opposite regions. Robot arm cannot touching red block until any robot arm "
        "touch blue block. After all these done, you put yellow block back to region G.",
        "Move three blocks into opposite regions. Robot arm cannot touching blue block until any robot "
        "arm touch red block. After all these done, you put yellow block back to region H.",
        "The blue block may not be touched before the red block has been touched. With that in mind, move "
        "the three blocks to the opposite regions, and finally put the yellow block back on region H.",
        "The blue block may not be touched before the red block has been touched. With that in mind, move "
        "the three blocks to the opposite regions, and put the yellow block back on region G.",
    ],
    5: [
        "The red and yellow blocks are in the wrong places, so swap them, red being placed first. The "
        "yellow block goes to the opposite side at any time.",
        "The red and blue blocks are in the wrong places, so swap them, blue being placed first. The "
        "yellow block goes to the opposite side at any time.",
        "The red and blue blocks are in the right places, so swap them, red being placed first. The "
        "yellow block goes to the opposite side at any time.",
        "The red and blue blocks are not in the wrong places, so swap them, red being placed first. The "
        "yellow block goes to the opposite side at any time.",
        "The red and blue blocks are in each other's places, so move them, red being placed first. The "
        "yellow block goes to the opposite side at any time.",
        "Can you exchange the red block and the blue block, placing the red one first? And could you also "
        "move the yellow block to the opposite side afterwards?",
    ],
    7: [
        "Put the three blocks on region I one after another, red before blue, and keep regions F and G empty "
        "in the meantime, as they must stay clear.",
        "Put the three blocks on region I one after another, red before blue, as they must stay clear.",
        "Goal: all three blocks on region I, one after another. Order: red before blue. Forbidden "
        "meanwhile: regions F and G.",
        "Goal: all three blocks on region I, one after another. Order: blue before red. Forbidden "
        "meanwhile: regions F, G and H.",
        "All three blocks should be collected on region H, one after the other, red before blue. Regions "
        "F, G and I are in use meanwhile, so do not place anything on them.",
        "All three blocks should be collected on region I, one after the other, red before blue. Regions "
        "F, G and H are in use meanwhile, so do not place anything on region F.",
        "1. Put the blocks on region I one after another, the red block before the blue block.\n2. During "
        "this period, place no objects on regions F and G.",
        "1. Put the blocks on region I one after another, the red block before the blue block.\n2. During "
        "this period, place objects on regions F, G and H.",
    ],
    8: [
        "Step 1: yellow block to region G. Step 2: yellow block to region I. Any time: red and blue "
        "blocks to any empty region.",
        "Step 1: yellow block to region I. Step 2: yellow block to region G. Any time: red block to any "
        "empty region.",
        "Step 1: yellow block to region I. Step 2: yellow block to region G. Any time: red and blue "
        "blocks to region H.",
        "Step 1: yellow block to region I. Step 2: yellow block to region G. Step 3: red and blue blocks "
        "to any empty region.",
    ],
}
