"""Session 11, second round (h54): spoken and instructor styles (`language.handover_spoken`), each class
with sentences it reads (task id -> sentences that must give the written spec) and near misses in which
the filler, hedge or correction carries a meaning ("just the red block", "maybe the red block before the
blue one?", "you don't have to ...", "on I, uh, on H"): refused by name or another spec, never the written
one."""

READ = {
    1: [
        # hesitations, "basically", "yeah", opening interjections and a closing tag
        "Um, so, just move the three blocks over to the opposite side, okay, and, uh, the red block has to "
        "go before the blue block.",
        "Okay so basically, yeah, move all three blocks to the opposite side, right? Red before blue.",
        # a phrase said again after "i mean", in other words ("block" / "one")
        "Yeah, move all three blocks to the opposite side, okay, and the red block, I mean the red one, goes "
        "down before the blue one.",
        # a closer that adds nothing
        "Move the three blocks to the opposite side and the red block has to be placed before the blue block "
        "and that's all there is to it.",
        # narration: "what we're going to do is", a framed rule ("the one thing to watch is that")
        "Now, what we're going to do is move the three blocks to the opposite side. The one thing to watch "
        "is that the red block has to be placed before the blue block.",
    ],
    2: [
        "Well, basically, the three blocks go on H, I and J, and, you know, only one block per region.",
        # who is spoken to, and when; what the class should notice
        "Alright class, in this exercise the three blocks go to H, I and J, and you'll notice each region "
        "can only hold one block.",
        "Today you're going to place the three blocks on regions H, I and J, one block per region.",
        "Your task today: put the three blocks on H, I and J, and remember, one block per region.",
        # a voice transcript without punctuation
        "so yeah put the uh three blocks on h i and j and you know only one block in each region okay",
        "put like all three blocks on h i and j one per region",
        "So the three blocks go into H, I and J, and you can't double up.",
        "How about you put the three blocks on H, I and J, one each?",
        "In this task you'll put the three blocks on regions H, I and J. Keep in mind that each region can "
        "only hold one block.",
    ],
    3: [
        # "you don't want to ...": a prohibition
        "Move the three pillars to E, F and G, and you don't want to put anything on H, I or J.",
        # a topic taken up by "they"; "oh and"; "while you're doing it"
        "Right so, the pillars, yeah, they need to go over to E, F and G. Oh and don't put anything on H, I "
        "or J while you're doing it, okay?",
        "So basically the pillars need to go to E, F and G, and I guess nothing should go on H, I or J.",
        # a hedge on the whole request, "try not to"
        "I think it would be best if you could move the three pillars to regions E, F and G, and please try "
        "not to put any object on H, I or J.",
    ],
    4: [
        # "you're not allowed to", "once you've done that, you put ..."
        "Your job is to transfer the three blocks to the opposite regions. You're not allowed to touch the "
        "blue block until the red block has been touched. Once you've done that, you put the yellow block "
        "back on region G.",
        "If possible, could you transfer the three blocks to the opposite regions? Please don't touch the "
        "blue block until the red one has been touched, and then maybe put the yellow block back on G "
        "afterwards.",
        # "hands off X until somebody's touched Y", "we're gonna"
        "Alright, move all three blocks over to the opposite regions, but hands off the blue one until "
        "somebody's touched the red one. Then put the yellow block back on G.",
        "Move all three blocks to the opposite regions, hands off the blue block until the red block has "
        "been touched, and then we're gonna put the yellow block back on G.",
        "You need to transfer the three blocks to the opposite regions. You may not touch the blue block "
        "until the red block has been touched. After you have done all of this, you put the yellow block "
        "back on region G.",
    ],
    5: [
        # "can you like swap", a topic taken up by "that one", "just needs to"
        "So, um, can you like swap the red and blue blocks? Red goes first. And the yellow block, that one "
        "just needs to get to the opposite side at some point, whenever.",
        # the time before the subject, "gotta", "doesn't matter when" without "it"
        "Swap red and blue, red first. At some point you also gotta move the yellow block to the opposite "
        "side, doesn't matter when.",
        "Why don't you swap red and blue, red first, and move the yellow block to the opposite side, doesn't "
        "matter when?",
        "Okay so for this one you're gonna swap the red and blue blocks, red goes first, and at some point "
        "you'll also take the yellow block to the opposite side.",
        "Um, I was thinking, could you swap the red and the blue blocks, with red going first, and, er, get "
        "the yellow one to the opposite side whenever?",
        # "what we want is for X to ..."
        "Now what we want is for the red and blue blocks to swap places, and the red one is placed first. "
        "The yellow block also has to end up on the opposite side, and it doesn't matter when.",
    ],
    6: [
        # a hesitation inside a list, a subject said again after "i mean"
        "Place the three objects on G, H and, uh, I, one per region, and the red block, I mean the red "
        "block, goes before the blue block.",
        "What you'll do here is place the three objects on regions G, H and I, one object per region. You "
        "want to place the red block before the blue block.",
        "Here the three objects go to regions G, H and I, each one on its own region. And remember, the red "
        "block has to be placed before the blue block.",
    ],
    7: [
        # a stutter ("the three, uh, the three objects"), a rule said twice after "i mean"
        "Put the three, uh, the three objects on region I one after another, red before blue, and nothing on "
        "F, G or H, I mean nothing on F, G or H during this period.",
        "I'd probably have you put the three objects on region I one after another, red before blue, and "
        "ideally no object should be placed on F, G or H during this period.",
        "Alright so basically all three blocks go onto I, one after the other, red before blue, and yeah, "
        "nothing goes on F, G or H the whole time.",
    ],
    8: [
        # a place said again in more words after "er"
        "First the yellow block goes to I, er, region I, then to region G, and the red and blue blocks go to "
        "any empty region at any time.",
        # "you start by placing", "you also move"
        "You start by placing the yellow block on region I, and then you move it to region G. You also move "
        "the red and blue blocks to any empty region, at any time.",
        "I guess the yellow block should go to region I first and then to region G, and the red and blue "
        "blocks can go to any empty region whenever.",
    ],
}

# one meaning away from a read sentence: the filler, hedge or correction carries it
NEAR_MISSES = {
    1: [
        "Just the red block goes to the opposite side, yeah, red before blue.",  # "just": only
        "So basically move all three blocks to the opposite side. The red one, uh, the blue one goes down "
        "first.",  # a correction after a hesitation: not the first wording
        "Move all three blocks to the opposite side, and, um, you don't have to put the red block before the "
        "blue block.",  # no order asked for
        "I think all three blocks go to the opposite side, red before blue, but I'm not sure.",
        "Maybe the red block before the blue block? Move all three blocks to the opposite side.",
        "Move all three blocks to the opposite side, and the red block, I mean the blue one, goes down "
        "before the blue one.",
        "You'll move all three blocks to the opposite side, and you'll place the blue block, sorry, the red "
        "block before the blue block.",
        "Okay, move all three blocks to the opposite side, and, uh, not yet the red block.",
    ],
    2: [
        "So the three blocks go into H, I and J, and you can double up.",  # not the one-block rule
        "Okay everyone, you'll see the three blocks on H, I and J.",  # a scene, not a goal
    ],
    3: [
        # a permission is not read as a command by the narration rules ("you may", "you get to")
        "Move the three pillars to E, F and G, and you may put objects on H, I or J.",
        "Move the three pillars to E, F and G; you get to put objects on H, I or J.",
        "So basically the pillars need to go to E, F and G, and I think nothing should go on H or I, not "
        "sure about J.",
        # "oh, and never ...": the rule after "oh" is kept (here on the target regions: no plan)
        "Right so, the pillars need to go over to E, F and G. Oh, and never put anything on E, F or G.",
    ],
    4: [
        # "hands off" without "until": never touched (no plan), not the guard
        "Move all three blocks over to the opposite regions. Hands off the blue one. Then put the yellow "
        "block back on G.",
        "Move all three blocks over to the opposite regions, hands off the red one until somebody's touched "
        "the blue one, then put the yellow block back on G.",
    ],
    6: [
        "Place the three objects on G, H and I, I mean H, I and J, one per region, red before blue.",
        "Place the three objects on G, H and, uh, J, one per region, and the red block goes before the blue "
        "block.",
    ],
    8: [
        "Put the yellow block on region I, I mean region H, then on region G, and move the red and blue "
        "blocks to any empty region at any time.",
        "First put the yellow block on I, uh, on H, then on G, and the red and blue blocks go to any empty "
        "region at any time.",
        "Okay so, um, first the yellow block goes on I, then on G, and, uh, just the red block goes to any "
        "empty region whenever.",
        "You start by placing the yellow block on region I, and then you move it to region G. You also move "
        "the red block to any empty region, at any time.",
    ],
}

# a correction that says something else is refused as a correction, quoting it
CORRECTIONS_REFUSED = {
    # a correction that opens a sentence corrects the sentence before: never read as one more step
    8: [
        "Put the yellow block on I, then on G. No wait, put it on H. The red and blue blocks go to any empty "
        "region at any time.",
        "Put the yellow block on I. Sorry, put it on H, then on G. The red and blue blocks go to any empty "
        "region at any time.",
        "Put the yellow block on region I, sorry, region H, then on region G, and the red and blue blocks to "
        "any empty region at any time.",
    ],
    1: ["Move all three blocks to the opposite side, I mean the blue block, and red before blue."],
    6: ["Place the three objects on G, H and I, I mean H, I and J, one per region, red before blue."],
}
