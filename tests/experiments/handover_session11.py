"""Session 11 (h51): the clause reader (`language.handover_clauses`: scene, target, need and question
statements) and the word-table forms added with it, each with sentences it reads (task id -> sentences that
must give the written spec) and near misses that change one meaning (another block, region or order, a
constraint or marker left out, a scene the world contradicts): refused by name or another spec, never the
written one."""

READ = {
    1: [
        # a need, then a command that restates it ("carry them across": no other place, the same blocks)
        "We need the blocks on the other side, so carry all three of them across, and the red block has to "
        "arrive before the blue one.",
        "The blocks belong on the opposite side, so move all three of them there; red before blue.",
        # "there" in the next sentence: the place a block may go to that the sentence before named last
        "The blocks belong on the opposite side. Move them there, red before blue.",
        # a bare "opposite" after the blocks (terse)
        "Transfer all blocks opposite, red ahead of blue.",
        # (h47's dev, refused until this round: now read as a need and its restatement)
        "The blocks belong on the opposite side, so move all three of them there. Place the red block "
        "before the blue block so that the order is right.",
        # non-native: "red block placing is before blue block"
        "Three block must transfer into opposite side, and red block placing is before blue block.",
        # a rule's label after a comma in a compressed heading
        "Goal: all blocks to the opposite side, constraint: red before blue.",
    ],
    2: [
        # a target statement, then the goal over "them" (the same regions), and the one-block rule
        "Regions H, I and J are the targets and each can only hold one object, so the three blocks should "
        "end up spread over them, one in each.",
        "Put the three blocks on H, I and J. Only one block may occupy a region.",
        "Goal: blocks on H, I and J, constraint: one block per region.",
    ],
    3: [
        # a scene statement that holds (the pillars start on H, I and J), a descriptive place ("the
        # placement area formed by ..."), "them" naming the one group of the sentence before, a goal
        # given again in a later sentence ("move them there": read once), "along the way"
        "The pillars sit on H, I and J but belong in the placement area formed by regions E, F and G. Move "
        "them there, and don't set any of them down on a region that isn't a target along the way.",
        # a relative scene clause, "take ... and bring them", framing ("what I would like you to do is")
        "What I would like you to do is to take the three pillars, which are standing on regions H, I and J "
        "at the moment, and bring them over to regions E, F and G; while you are doing that, please make "
        "sure that none of the objects is ever put down on regions H, I or J.",
        # "they" naming the one group of the sentence before; "nothing may ever be placed"
        "The three pillars are on H, I and J right now; they belong on E, F and G. Never place an object on "
        "H, I or J.",
        "The pillars are currently on H, I and J. They should end up on E, F and G, and nothing may ever be "
        "placed on H, I or J.",
    ],
    4: [
        # completion markers as step separators
        "The blue block may only be touched once the red one has been touched. All three blocks need to go "
        "to the opposite regions; when the transfer is complete, the yellow block goes back to G, where the "
        "red block is now.",
        "Please transfer the three blocks to opposite regions. Robot arm not touch blue block until red "
        "block is touched by some arm. When all finish, yellow block go back region G.",
        "What needs to happen is that all three blocks get transferred to the regions on the opposite side, "
        "but there is one condition, namely that neither arm is allowed to touch the blue block until one "
        "of them has touched the red block; and then, once all of that has been finished, the yellow block "
        "should be put back on region G, where the red block is sitting right now.",
        # a completion marker as a heading; "until red is" (the participle left out)
        "- blocks to the opposite regions\n- do not touch blue before red\n- when the transfer is done: "
        "yellow back to G",
        "Task: blocks to the opposite regions. Rule: blue is not touched until red is. Afterwards: yellow "
        "back on G.",
    ],
    5: [
        "Swap: red and blue blocks (red first).\nYellow block: opposite side, any time.",
        "Red block and blue block change their place each other, red block is place first. Yellow block "
        "put in opposite side, when is not important.",
        "I would like the red block and the blue block to trade places with each other, and it is important "
        "that the red block is placed first, before the blue block; in addition to that, the yellow block "
        "should be moved to the opposite side, and it does not matter at what point that happens.",
        # a sentence that goes on from the one before ("And ...")
        "Please, could you exchange the red block and the blue block? The red one must be placed first. And "
        "the yellow block to the opposite side whenever.",
    ],
    6: [
        "Could you put the three blocks on regions G, H and I, a separate region for each, and make sure "
        "the red one is placed before the blue one?",
        "I'd like you to arrange the three blocks so that regions G, H and I each end up holding one of "
        "them, with the red block being put down at some point before the blue block is put down.",
    ],
    7: [
        "Would you put the three blocks on region I one after the other, red before blue? And could you "
        "keep regions F, G and H clear until you're done?",
        "Target: region I, all three blocks, one after another.\nOrder: red, then blue.\nMeanwhile: nothing "
        "on F, G or H.",
        "Blocks onto I in turn, red before blue. F, G, H off limits till done.",
        # a target statement: "region I is the drop point", "use region I as a drop-off"
        "Region I is the drop point, so place the three blocks there one after another, red before blue; "
        "because regions F, G and H must stay clear meanwhile, put nothing on them.",
        "Use region I as a drop-off: one after another, put the three blocks on region I, red before blue. "
        "Regions F, G and H must stay empty the whole time.",
    ],
    8: [
        # a question with its modal before the subject
        "Can you move the yellow block to region I first and then on to region G? And whenever you like, "
        "could the red and blue blocks each go to an empty region?",
        "Yellow to I, then G. Red, blue: any empty region, any order.",
        "Yellow block firstly to region I, after to region G. Red and blue block, to any empty region, time "
        "is free.",
    ],
}

NEAR_MISSES = {
    1: [
        # the restating command names other blocks: which goal is meant?
        "We need the blocks on the other side, so carry the red block across, and the red block has to "
        "arrive before the blue one.",
        "Transfer all blocks opposite, blue ahead of red.",
        "Goal: all blocks to the opposite side, constraint: blue before red.",
        "The blocks belong on the opposite side. Move them there, blue before red.",
        "Three block must transfer into opposite side, and blue block placing is before red block.",
        # the restating command names another place
        "We need the blocks on the other side, so carry them to region H; red before blue.",
        "The blocks belong on the opposite side, so move all three of them there. Place the blue block "
        "before the red block so that the order is right.",
    ],
    2: [
        # the target statement names other regions than the goal
        "Regions G, H and I are the targets, so the three blocks should end up spread over regions H, I "
        "and J, one in each.",
    ],
    3: [
        # a scene statement the world contradicts (the pillars start on H, I and J)
        "The pillars sit on E, F and G but belong in regions H, I and J. Move them there.",
        "The pillars sit on E, F and G now. Move them to regions E, F and G.",
        "Take the three pillars, which are standing on regions E, F and G at the moment, and bring them "
        "over to regions E, F and G.",
        # the second verb moves other blocks than the first picks up
        "Take the red block and bring the three pillars over to regions E, F and G.",
        "The pillars are currently on E, F and G. They should end up on E, F and G, and nothing may ever be "
        "placed on H, I or J.",
        # a goal given again, the second time one by one: which holds?
        "The pillars belong in regions E, F and G. Move them there one by one.",
        # the prohibition left out
        "The pillars sit on H, I and J but belong in the placement area formed by regions E, F and G. Move "
        "them there.",
    ],
    4: [
        # the completion marker left out: yellow is no longer after the transfer
        "The blue block may only be touched once the red one has been touched. All three blocks need to go "
        "to the opposite regions; the yellow block goes back to G, where the red block is now.",
        "Please transfer the three blocks to opposite regions. Robot arm not touch red block until blue "
        "block is touched by some arm. When all finish, yellow block go back region G.",
        "Task: blocks to the opposite regions. Rule: red is not touched until blue is. Afterwards: yellow "
        "back on G.",
    ],
    5: [
        "Swap: red and blue blocks (blue first).\nYellow block: opposite side, any time.",
        "Red block and blue block change their place each other, blue block is place first. Yellow block "
        "put in opposite side, when is not important.",
    ],
    6: [
        "Could you put the three blocks on regions G and H, a separate region for each, and make sure the "
        "red one is placed before the blue one?",
        "I'd like you to arrange the red block so that regions G, H and I each end up holding one of them, "
        "with the red block being put down at some point before the blue block is put down.",
        "I'd like you to arrange the three blocks so that regions G, H and I each end up holding one of "
        "them, with the red block being put down at some point after the blue block is put down.",
    ],
    7: [
        # a region left out of the prohibition, another target
        "Would you put the three blocks on region I one after the other, red before blue? And could you "
        "keep regions F and G clear until you're done?",
        "Target: region H, all three blocks, one after another.\nOrder: red, then blue.\nMeanwhile: nothing "
        "on F, G or I.",
        "Blocks onto I in turn, red before blue. F, G off limits till done.",
        # the target statement names another region than the goal: refused, not dropped
        "Region H is the drop point, so place the three blocks on region I one after another, red before "
        "blue; put nothing on regions F, G and H meanwhile.",
        "Use region I as a drop-off: one after another, put the three blocks on region I, blue before red. "
        "Regions F, G and H must stay empty the whole time.",
    ],
    8: [
        "Could the red and blue blocks each go to region H? Can you move the yellow block to region I first "
        "and then on to region G?",
        "Yellow block firstly to region G, after to region I. Red and blue block, to any empty region, time "
        "is free.",
        "Yellow to I, then G. Red: any empty region, any order.",
    ],
}

# found with dev12 (written after the clause reader): a scene statement that opens with its time, the
# exchange said as the state it leaves, a record of labelled lines, a heading whose colon ends the line
READ_DEV12 = {
    1: ["hey, can you get all 3 blocks to the opposite side? red has to go before blue tho"],
    2: ["Blocks: red, blue, yellow\nTargets: H, I, J\nRule: one block per region"],
    3: [
        "Right now the pillars stand on H, I and J; they need to go back to E, F and G. Nothing should be "
        "put on H, I or J while this is going on.",
        "1) Pillars to E, F, G.\n2) Never use H, I or J in between.",
    ],
    4: [
        "- Transfer: three blocks to the opposite regions\n- Constraint: no touching blue until red has been "
        "touched\n- Last step: yellow back on G"
    ],
    5: [
        "The red and blue blocks should end up in each other's starting positions, with red placed first. "
        "The yellow block needs to reach the opposite side too, whenever.",
        "Exchange: red <-> blue, red placed first\nYellow: to the opposite side, at any time",
    ],
    6: ["Place the blocks on:\n- G, H and I (one each)\nOrder: red before blue"],
    8: [
        "The yellow block needs to go to I and after that to G. The red and blue blocks simply need to be "
        "moved to some empty region, at whatever time.",
        "Step 1: yellow -> I\nStep 2: yellow -> G\nAlso: red and blue -> any empty region, whenever",
    ],
}

NEAR_MISSES_DEV12 = {
    2: ["Blocks: red, blue\nTargets: H, I, J\nRule: one block per region"],
    3: [
        "Right now the pillars stand on E, F and G; they need to go back to E, F and G. Nothing should be "
        "put on H, I or J while this is going on.",
        "1) Pillars to E, F, G.\n2) Never use H or J in between.",
    ],
    4: [
        "- Transfer: three blocks to the opposite regions\n- Constraint: no touching blue until red has been "
        "touched\n- Yellow back on G",
        "Put the red block on the opposite side. Put the blue block there too. Put the yellow block there "
        "too. Do not touch blue before red; after all of that, put yellow back on G.",
    ],
    5: [
        "The red and yellow blocks should end up in each other's starting positions, with red placed first. "
        "The blue block needs to reach the opposite side too, whenever.",
    ],
    6: ["Place the blocks on:\n- G, H and J (one each)\nOrder: red before blue"],
    8: [
        "Step 1: yellow -> G\nStep 2: yellow -> I\nAlso: red and blue -> any empty region, whenever",
        # "there" for other blocks than the sentence before moved: the same region, or each its own? refused
        "The red block goes to any empty region. Put the blue block there too. Yellow to I, then G.",
    ],
}

# found with dev13 (narrative, abbreviated, needs and passives)
READ_DEV13 = {
    1: [
        "Here's the idea: the three blocks go across to the opposite side, the red one arriving before the "
        "blue one.",
        "Move all 3 blocks -> opp. side (red before blue).",
    ],
    2: [
        "The blocks are going to H, I and J. Since each region only has room for one, every block gets a "
        "region of its own.",
        "Regions H, I and J need to be filled with the three blocks, one block in each.",
    ],
    4: [
        "First the three blocks travel to the opposite regions, and the blue block stays untouched until "
        "somebody has touched the red block. After that transfer, the yellow block returns to region G.",
        "Blocks -> opposite regions; don't touch blue b4 red; then yellow -> G.",
    ],
    5: [
        "The red block takes the blue block's place and the blue block takes the red block's place, red "
        "going first. Meanwhile the yellow block heads to the opposite side at some point.",
        "Swap red & blue (red 1st); yellow -> opposite side anytime.",
    ],
    6: [
        "The three blocks need to be placed on regions G, H and I, a different region each, and the red "
        "block needs to be placed before the blue block."
    ],
    7: [
        "The three blocks are dropped on region I, one after the other, red ahead of blue; for the whole "
        "task, regions F, G and H receive nothing."
    ],
    8: [
        "The yellow block makes a stop at region I and then moves on to region G, while the red and blue "
        "blocks each go to an empty region at any point.",
        "Yellow -> I -> G. Red & blue -> any empty region, anytime.",
    ],
}

NEAR_MISSES_DEV13 = {
    1: [
        "Here's the idea: the three blocks go across to the opposite side, the blue one arriving before the "
        "red one."
    ],
    2: ["Regions H and I need to be filled with the three blocks, one block in each."],
    4: [
        "First the three blocks travel to the opposite regions, and the red block stays untouched until "
        "somebody has touched the blue block. After that transfer, the yellow block returns to region G.",
        "Blocks -> opposite regions; don't touch blue b4 red; yellow -> G.",
    ],
    5: [
        "The red block takes the blue block's place and the blue block takes the red block's place, blue "
        "going first. Meanwhile the yellow block heads to the opposite side at some point.",
        "The red block takes the blue block's place. Meanwhile the yellow block heads to the opposite side "
        "at some point.",
    ],
    7: [
        "The three blocks are dropped on region I, one after the other, red ahead of blue; for the whole "
        "task, regions F and G receive nothing."
    ],
    8: [
        "Yellow -> G -> I. Red & blue -> any empty region, anytime.",
        "The yellow block makes a stop at region G and then moves on to region I, while the red and blue "
        "blocks each go to an empty region at any point.",
    ],
}

# the same steps said out of the text's order: refused by name (the tree follows the text), never read
# without the order
OUT_OF_ORDER = {
    8: [
        "Finally: yellow to G. First: yellow to I. Red and blue to any empty region at any time.",
        "Finally, put the yellow block on G. First, put the yellow block on I. Move red and blue to any "
        "empty region at any time.",
        "Put the yellow block on G at the end. First put it on I. Move red and blue to any empty region "
        "at any time.",
    ],
}
