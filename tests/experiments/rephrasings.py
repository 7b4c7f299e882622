"""Four people's rephrasings of each tabletop task (the paper's Q3 user study), written here."""

REPHRASINGS: dict[int, list[str]] = {
    1: [
        "Put the green apple on the blue plate and put the orange on the yellow plate.",
        "Could you move the orange onto the yellow plate and the green apple onto the blue plate?",
        "Please place the green apple in the blue plate. Also place the orange in the yellow plate.",
        "Please place the orange in the yellow plate, and place the green apple in the blue plate too.",
    ],
    2: [
        "Put the green apple on the pink plate, the orange on the yellow plate and the red apple on the "
        "blue plate, in whatever order you like.",
        "In any order, place the red apple in the blue plate, the orange in the yellow plate and the green "
        "apple in the pink plate.",
        "Put the orange in the yellow plate, the red apple in the blue plate and the green apple in the "
        "pink plate. Order does not matter.",
        "Could you put the green apple into the pink plate, the orange into the yellow plate and the red "
        "apple into the blue plate?",
    ],
    3: [
        "Put the carrot on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate and the red apple on the pink plate, in any order.",
        "In any order you like, place the red apple in the pink plate, the green apple in the green plate, "
        "the orange in the yellow plate and the carrot in the blue plate.",
        "Move the carrot to the blue plate, the orange to the yellow plate, the green apple to the green "
        "plate and the red apple to the pink plate.",
        "Please put the orange in the yellow plate, the carrot in the blue plate, the red apple in the pink "
        "plate and the green apple in the green plate. The order is up to you.",
    ],
    4: [
        "First put the green apple and the orange in the yellow plate. After that, put the carrot and the "
        "red apple in the blue plate, in any order.",
        "Start by placing the orange and the green apple in the yellow plate, then place the red apple and "
        "the carrot in the blue plate.",
        "First, place the green apple and the orange in the yellow plate. Then place the carrot and the red "
        "apple in the blue plate.",
        "Place the green apple and the orange in the yellow plate. After both are there, place the carrot "
        "and the red apple in the blue plate in any order.",
    ],
}

# A subordinate clause that states the order ("before placing ...", "once ... are in ..."), once refused
# (read since h61: each object listed in a reference's clause is a task of its own).
HARDER: dict[int, list[str]] = {
    4: ["Before placing the carrot and red apple in the blue plate, place the green apple and orange in the "
        "yellow plate.",
        "Once the green apple and the orange are in the yellow plate, put the carrot and the red apple in "
        "the blue plate."],
}

# Validation rephrasings in the terse and conversational styles (issue 24), written for developing the
# reader's rules for those styles; kept apart from the study's wordings
# (suites/data/tabletop_rephrasings.json), which were not used to write the rules.
STYLES: dict[str, dict[int, list[str]]] = {
    "terse": {
        1: ["Green apple onto blue plate; orange onto yellow plate.",
            "Orange into the yellow plate and green apple into the blue plate.",
            "Green apple goes in the blue plate, orange goes in the yellow plate."],
        2: ["Red apple into blue plate, green apple into pink plate, orange into yellow plate. Any order.",
            "The orange on the yellow plate, the green apple on the pink plate, the red apple on the blue "
            "plate, in any order."],
        3: ["Orange on the yellow plate, carrot on the blue plate, red apple on the pink plate, green apple "
            "on the green plate, any order."],
        4: ["First green apple and orange into the yellow plate, then red apple and carrot into the blue "
            "plate.",
            "Orange and green apple on the yellow plate first. Then carrot and red apple on the blue plate, "
            "any order."],
    },
    "conversational": {
        1: ["I would like you to put the orange in the yellow plate and the green apple in the blue plate.",
            "We need the green apple on the blue plate and the orange on the yellow plate, please.",
            "Hey robot, drop the green apple into the blue plate and the orange into the yellow plate, "
            "thanks!"],
        2: ["I'd love the orange to be in the yellow plate, the red apple in the blue plate and the green "
            "apple in the pink plate, in whatever order.",
            "I need the orange in the yellow plate, the red apple in the blue plate and the green apple in "
            "the pink plate. Order does not matter."],
        3: ["I want the carrot to go on the blue plate, the orange on the yellow plate, the green apple on "
            "the green plate and the red apple on the pink plate. Any order is fine."],
        4: ["Begin with the orange and the green apple on the yellow plate, and after that I'd like the "
            "carrot and the red apple on the blue plate.",
            "Could you start with the green apple and the orange in the yellow plate? When that is done, "
            "the carrot and the red apple go in the blue plate.",
            "Put the carrot and the red apple in the blue plate after you have put the green apple and the "
            "orange in the yellow plate."],
    },
}

# Issue 28 (h57): everyday styles, written before the rules for them. DEV_S11 is for developing the
# rules; VALID_S11 (other voices) is measured once before and once after, never read per sentence between.
# Styles: terse arrow notation, spoken fillers and hedges, goals stated as belonging or need, and a
# trailing free-order remark after an ordered first part.
DEV_S11: dict[int, list[str]] = {
    1: ["green apple -> blue plate, orange -> yellow plate",
        "ok so just put the green apple on the blue plate and, um, the orange on the yellow one",
        "the orange belongs in the yellow plate and the green apple belongs in the blue plate, so please put "
        "them there",
        "two things need plates: the green apple goes on the blue plate and the orange goes on the yellow "
        "plate",
        "uh, could you, like, put the orange on the yellow plate and the green apple on the blue plate?",
        "orange -> yellow plate; green apple -> blue plate"],
    2: ["green apple -> pink plate, orange -> yellow plate, red apple -> blue plate (any order)",
        "each fruit gets its own plate: the green apple goes on the pink plate, the orange on the yellow "
        "plate and the red apple on the blue plate",
        "so, um, the green apple on the pink plate, the orange on the yellow plate and, uh, the red apple on "
        "the blue plate, order doesn't matter",
        "the red apple belongs on the blue plate, the orange belongs on the yellow plate and the green apple "
        "belongs on the pink plate, any order",
        "okay just put the orange on the yellow plate, the green apple on the pink plate and the red apple "
        "on the blue plate, whatever order",
        "red apple -> blue plate; green apple -> pink plate; orange -> yellow plate; any order"],
    3: ["carrot -> blue plate, orange -> yellow plate, green apple -> green plate, red apple -> pink plate "
        "(any order)",
        "four things need plates: the carrot goes on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate",
        "so basically the carrot on the blue plate, the orange on the yellow plate, um, the green apple on "
        "the green plate and the red apple on the pink plate, in any order",
        "the carrot belongs on the blue plate and the orange belongs on the yellow plate; the green apple "
        "belongs on the green plate and the red apple belongs on the pink plate. any order",
        "alright, just put the red apple on the pink plate, the green apple on the green plate, the orange "
        "on the yellow plate and the carrot on the blue plate, order doesn't matter",
        "carrot -> blue plate; orange -> yellow plate; green apple -> green plate; red apple -> pink plate"],
    4: ["first: green apple and orange -> yellow plate. then: carrot and red apple -> blue plate",
        "first the green apple and the orange on the yellow plate, and after that put the carrot and the red "
        "apple on the blue plate, order doesn't matter",
        "ok so first, um, put the green apple and the orange on the yellow plate, and then the carrot and "
        "the red apple on the blue plate",
        "green apple and orange -> yellow plate first, then carrot and red apple -> blue plate (any order)",
        "the green apple and the orange belong in the yellow plate, so put them there first. after that the "
        "carrot and the red apple go in the blue plate, in any order",
        "first put the orange and the green apple on the yellow plate, then the red apple and the carrot on "
        "the blue plate, the order of those two doesn't matter"],
}

VALID_S11: dict[int, list[str]] = {
    1: ["blue plate <- green apple, yellow plate <- orange",
        "hmm, so, the green apple, put it on the blue plate, and the orange on the yellow plate, yeah",
        "the green apple should be on the blue plate and the orange should be on the yellow plate",
        "orange -> yellow plate and green apple -> blue plate please"],
    2: ["orange -> yellow plate, red apple -> blue plate, green apple -> pink plate, in any order",
        "er, just pop the red apple on the blue plate, the green apple on the pink plate and the orange on "
        "the yellow plate, any order is fine",
        "three fruits need plates: the green apple goes to the pink plate, the orange to the yellow plate "
        "and the red apple to the blue plate. any order",
        "the orange belongs on the yellow plate, the red apple on the blue plate and the green apple on the "
        "pink plate; whatever order you like"],
    3: ["orange -> yellow plate; carrot -> blue plate; red apple -> pink plate; green apple -> green plate "
        "(order doesn't matter)",
        "right, um, carrot on the blue plate, orange on the yellow plate, green apple on the green plate and "
        "red apple on the pink plate, any order",
        "every item gets its own plate: the carrot goes on the blue plate, the red apple on the pink plate, "
        "the orange on the yellow plate and the green apple on the green plate",
        "the green apple belongs on the green plate, the carrot on the blue plate, the red apple on the pink "
        "plate and the orange on the yellow plate, in any order"],
    4: ["first: orange and green apple -> yellow plate; then: red apple and carrot -> blue plate",
        "so, uh, start with the green apple and the orange on the yellow plate, and after that, um, the "
        "carrot and the red apple on the blue plate",
        "first the orange and the green apple go on the yellow plate, then put the red apple and the carrot "
        "on the blue plate, the order doesn't matter",
        "the green apple and the orange belong on the yellow plate first; then the carrot and the red apple "
        "belong on the blue plate, any order"],
}

# Issue 28 (h61): validation rephrasings written before the rules for the styles below, in four styles
# that the sets above do not use: a modal passive ("needs to be placed"), take-and-set with a pronoun
# ("take X and set it on ..."), the receptacle fronted ("onto the blue plate goes ..."), and the end state
# ("make sure X ends up on ..."). Measured once before and once after (scripts/tabletop_styles.py --batch
# VALID_H61), never read per sentence between; the expected signature is each task's ground truth.
VALID_H61: dict[int, list[str]] = {
    1: ["The green apple needs to be placed on the blue plate, and the orange needs to be placed on the "
        "yellow plate.",
        "Take the green apple and set it down on the blue plate; take the orange and set it down on the "
        "yellow plate.",
        "Onto the blue plate goes the green apple, and onto the yellow plate goes the orange.",
        "Make sure the green apple ends up on the blue plate and the orange ends up on the yellow plate."],
    2: ["The green apple is to be put on the pink plate, the orange on the yellow plate and the red apple on "
        "the blue plate; the order is your call.",
        "Grab the red apple and lay it on the blue plate, grab the orange and lay it on the yellow plate, "
        "and grab the green apple and lay it on the pink plate, no particular order.",
        "On the pink plate put the green apple, on the yellow plate the orange, and on the blue plate the "
        "red apple, whichever order you prefer.",
        "By the end, the green apple should sit on the pink plate, the orange on the yellow plate and the "
        "red apple on the blue plate; how you order it is up to you."],
    3: ["The carrot must be put on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate. Do them in any sequence.",
        "Pick up the carrot and drop it on the blue plate, pick up the orange and drop it on the yellow "
        "plate, pick up the green apple and drop it on the green plate, pick up the red apple and drop it on "
        "the pink plate; any order is okay.",
        "For the blue plate the carrot, for the yellow plate the orange, for the green plate the green apple "
        "and for the pink plate the red apple; order is free.",
        "When you're finished, I want to see the carrot on the blue plate, the orange on the yellow plate, "
        "the green apple on the green plate and the red apple on the pink plate. Any order."],
    4: ["The green apple and the orange have to be placed on the yellow plate first; only after that should "
        "the carrot and the red apple be placed on the blue plate, in either order.",
        "Take the green apple and the orange and set them on the yellow plate. When both are on it, take the "
        "carrot and the red apple and set them on the blue plate, in either order.",
        "On the yellow plate, first put the green apple and the orange. Next, on the blue plate, put the "
        "carrot and the red apple in any order.",
        "Make sure the green apple and the orange are on the yellow plate before the carrot or the red apple "
        "goes on the blue plate; those last two can go in any order."],
}

# Issue 28 (h61): the classes the reader refused in the lead's sets, with variants, for developing the rules
# (read per sentence): a counted header with a colon list, a topic header whose plate "it" names, "the
# yellow one" for a plate named before, and the receptacle as subject ("the yellow plate gets ...").
DEV_H61: dict[int, list[str]] = {
    1: ["ok so just put the green apple on the blue plate and, um, the orange on the yellow one",
        "Two placements: the green apple on the blue plate and the orange on the yellow plate.",
        "The blue plate gets the green apple and the yellow plate gets the orange.",
        "See to it that the orange sits on the yellow plate and the green apple sits on the blue plate.",
        "In the yellow plate put the orange, and in the blue plate put the green apple.",
        "Onto the yellow plate: the orange. Onto the blue plate: the green apple."],
    2: ["Place three fruits: the green apple on the pink plate, the orange on the yellow plate, the red "
        "apple on the blue plate. Any order works.",
        "put the green apple on the pink plate, the orange on the yellow one and the red apple on the blue "
        "one, any order",
        "The pink plate should get the green apple, the yellow plate the orange and the blue plate the red "
        "apple, in any order.",
        "The red apple has to be put on the blue plate, the green apple on the pink plate and the orange on "
        "the yellow plate, in any order.",
        "We'd like to see the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate, any order."],
    3: ["Put four items on plates: the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate, in any order.",
        "The carrot should be placed on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate, any order.",
        "Onto the blue plate goes the carrot, onto the yellow plate the orange, onto the green plate the "
        "green apple and onto the pink plate the red apple, in any order."],
    4: ["Start with the yellow plate: put the green apple and the orange on it. Then put the carrot and the "
        "red apple on the blue plate in any order.",
        "The yellow plate has to get the green apple and the orange before anything goes on the blue plate; "
        "after that, the carrot and the red apple go on the blue plate in whatever order.",
        "First the yellow plate: the green apple and the orange go on it. Then the blue plate: the carrot "
        "and the red apple, any order.",
        "Ensure the orange and the green apple end up on the yellow plate before the red apple or the carrot "
        "goes on the blue plate.",
        "The orange and the green apple must be placed in the yellow plate first, and only then should the "
        "carrot and the red apple be put in the blue plate."],
}

# Issue 28 (h65): held-out rephrasings in styles the sets above do not use, written before the
# framing-independent tabletop reading (language/tabletop_pairs.py): a colon or "=" notation, the plate
# as the place "for" or "where" an object goes, pairing and matching verbs, "end up"/"land" goals, and the
# plate as the subject of "takes". Measured once before and once after (scripts/tabletop_styles.py --batch
# VALID_H65), never read per sentence between; the expected signature is each task's ground truth.
VALID_H65: dict[int, list[str]] = {
    1: ["green apple: blue plate. orange: yellow plate.",
        "The blue plate is for the green apple and the yellow plate is for the orange.",
        "Match the green apple with the blue plate and the orange with the yellow plate.",
        "I'd like the green apple to end up on the blue plate, and the orange should end up on the yellow "
        "plate."],
    2: ["pink plate = green apple, yellow plate = orange, blue plate = red apple; no particular order",
        "Red apple to the blue plate, green apple to the pink plate, orange to the yellow plate, sequence "
        "doesn't matter.",
        "The pink plate is where the green apple goes, the yellow plate is where the orange goes and the "
        "blue plate is where the red apple goes, in any order.",
        "Could the green apple land on the pink plate, the orange on the yellow plate and the red apple on "
        "the blue plate? Any order."],
    3: ["carrot: blue plate, orange: yellow plate, green apple: green plate, red apple: pink plate. any "
        "order.",
        "Pair the carrot with the blue plate, the orange with the yellow plate, the green apple with the "
        "green plate and the red apple with the pink plate.",
        "The blue plate takes the carrot, the yellow plate takes the orange, the green plate takes the green "
        "apple and the pink plate takes the red apple, in any order.",
        "Let the carrot end up on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, whatever the order."],
    4: ["Yellow plate first: green apple and orange. Once that's done, blue plate: carrot and red apple, "
        "any order.",
        "First the yellow plate takes the green apple and the orange; after that the blue plate takes the "
        "carrot and the red apple, in any order.",
        "To begin, the green apple and the orange should end up on the yellow plate. Once that's done, the "
        "carrot and the red apple should end up on the blue plate, in any order.",
        "First match the green apple and the orange with the yellow plate, then match the carrot and the "
        "red apple with the blue plate."],
}

# Issue 28 (h68): held-out rephrasings written before any h68 rule, in four writers' voices the sets above
# do not use (a non-native speaker, a child, a terse engineer, a long-winded polite person) and framings
# they do not (a goal state or numbered-step record, a "|" list, "I want that X is on Y", a correction
# "no wait", asides, "lastly" inside a free-order list). Measured once before and once at the end
# (scripts/tabletop_styles.py --batch VALID_H68), never read per sentence between; the expected signature
# is each task's ground truth.
VALID_H68: dict[int, list[str]] = {
    1: ["Please you put green apple to blue plate, and orange to yellow plate.",
        "put the green apple on the pink plate. no wait, the blue plate! and the orange on the yellow plate",
        "Goal state: green apple on blue plate, orange on yellow plate.",
        "If it isn't too much trouble, I would be very grateful if you could kindly place the green apple on "
        "the blue plate and, while you are at it, the orange on the yellow plate. Thank you so much!"],
    2: ["Green apple must go in pink plate, orange in yellow plate, red apple in blue plate. Which order, is "
        "not important.",
        "put the green apple on the pink plate and the orange on the yellow plate and the red apple on the "
        "blue plate and you can do it in any order you want",
        "pink plate: green apple | yellow plate: orange | blue plate: red apple. Order: any.",
        "Would you be so kind as to put the green apple onto the pink plate, the orange onto the yellow "
        "plate, and the red apple onto the blue plate? Please feel free to do them in whichever order is "
        "most convenient for you."],
    3: ["I want that carrot is on blue plate, orange is on yellow plate, green apple is on green plate and "
        "red apple is on pink plate. Order you can choose.",
        "the carrot goes on the blue plate. the orange goes on the yellow plate. the green apple goes on the "
        "green plate because they are both green! and the red apple goes on the pink plate.",
        "Carrot to blue plate, orange to yellow plate, green apple to green plate, red apple to pink plate. "
        "No ordering constraints.",
        "Hello! When you have a moment, could you please arrange things for me: the carrot should be placed "
        "on the blue plate, the orange on the yellow plate, the green apple on the green plate and, lastly, "
        "the red apple on the pink plate. The order really doesn't matter to me at all."],
    4: ["First you put green apple and orange in yellow plate. After finish this, you put carrot and red "
        "apple in blue plate, any order is ok.",
        "first the green apple and the orange go on the yellow plate. then when thats done put the carrot "
        "and the red apple on the blue plate. you can do those two any way you want",
        "Step 1: green apple, orange -> yellow plate. Step 2: carrot, red apple -> blue plate. Within each "
        "step, any order.",
        "I'd appreciate it if you could start by putting the green apple and the orange on the yellow plate. "
        "Once you have finished with those, please go ahead and put the carrot and the red apple on the "
        "blue plate, in whichever order you prefer, of course."],
}

# Issue 28 (h68): rephrasings for developing h68's rules (read per sentence), in voices neither VALID_H68
# nor the older sets use: text messages, a teacher's handout, a logistics operator, a formal letter, and
# someone thinking aloud (corrections, asides, afterthoughts). Task 4's first wording is the lead's
# refused example.
DEV_H68: dict[int, list[str]] = {
    1: ["pls green apple on blue plate & orange on yellow plate thx",
        "1) Place the green apple on the blue plate. 2) Place the orange on the yellow plate. You may do "
        "these in any order.",
        "Deliver the green apple to the blue plate and the orange to the yellow plate.",
        "Kindly see that the green apple is put upon the blue plate and the orange upon the yellow plate.",
        "put the orange on the blue plate, sorry, the yellow plate, and the green apple on the blue plate",
        "Final layout: blue plate has the green apple, yellow plate has the orange.",
        "The blue plate is for the green apple; the yellow plate is for the orange."],
    2: ["green apple on pink plate, orange on yellow plate, red apple on blue plate. whatever order u want",
        "Here is what I need: the green apple on the pink plate, the orange on the yellow plate, the red "
        "apple on the blue plate. Any order will do.",
        "Route: green apple to pink plate, orange to yellow plate, red apple to blue plate. Sequence: any.",
        "I should like the green apple to be on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate; the order is of no consequence.",
        "the green apple, which is a bit bruised, goes on the pink plate, the orange on the yellow plate, "
        "and the red apple on the blue plate, any order"],
    3: ["carrot->blue plate, orange->yellow plate, green apple->green plate, red apple->pink plate. any "
        "order ok",
        "Your job is to put each item on its plate: carrot on the blue plate, orange on the yellow plate, "
        "green apple on the green plate, red apple on the pink plate. The order is not important.",
        "Load the blue plate with the carrot, the yellow plate with the orange, the green plate with the "
        "green apple and the pink plate with the red apple, in any sequence.",
        "It would please me greatly if the carrot were set on the blue plate, the orange on the yellow "
        "plate, the green apple on the green plate and the red apple on the pink plate, in whatever order "
        "suits you.",
        "carrot on the blue plate, orange on the yellow plate, green apple on the green plate, oh and red "
        "apple on the pink plate. no particular order"],
    4: ["What I need first is the green apple and the orange on the yellow plate, and after that the carrot "
        "and the red apple on the blue plate, in any order",
        "1st green apple & orange on yellow plate, then carrot & red apple on blue plate (any order)",
        "Phase one: green apple and orange onto the yellow plate. Phase two: carrot and red apple onto the "
        "blue plate, either order.",
        "Would you first see to it that the green apple and the orange are on the yellow plate? Thereafter, "
        "the carrot and the red apple may go on the blue plate, in either order.",
        "Start with the yellow plate, it gets the green apple and the orange. After that, the blue plate "
        "gets the carrot and the red apple, whichever order."],
}

# Issue 28 (h68): a second development batch in five more voices (a chef on the pass, a formal email, a
# programmer's notation, a grandparent on the phone, a coach), written before any h68 rule as well.
DEV2_H68: dict[int, list[str]] = {
    1: ["Green apple, blue plate. Orange, yellow plate. Go!",
        "Dear robot, I am writing to ask that you place the green apple on the blue plate and the orange on "
        "the yellow plate. Best regards.",
        "place(green apple, blue plate); place(orange, yellow plate);",
        "Now dear, the green apple, the nice shiny one, goes on the blue plate, and the orange goes on the "
        "yellow plate, alright?",
        "Alright team, green apple to the blue plate, orange to the yellow plate, let's go!"],
    2: ["Pink plate: green apple. Yellow plate: orange. Blue plate: red apple. Any order, chop chop.",
        "Could you please arrange the following: green apple on the pink plate; orange on the yellow plate; "
        "red apple on the blue plate. The sequence is entirely up to you.",
        "set green apple -> pink plate, orange -> yellow plate, red apple -> blue plate; order: unspecified",
        "Oh and could you be a dear and put the green apple on the pink plate, the orange on the yellow "
        "plate and the red apple on the blue plate? Doesn't matter which you do first.",
        "Three moves, any order: green apple on the pink plate, orange on the yellow plate, red apple on the "
        "blue plate."],
    3: ["Carrot goes blue plate, orange goes yellow plate, green apple goes green plate, red apple goes pink "
        "plate. Order's your choice.",
        "Please find below the placements I need: the carrot on the blue plate, the orange on the yellow "
        "plate, the green apple on the green plate and the red apple on the pink plate. These may be done "
        "in any order.",
        "Postcondition: carrot on blue plate, orange on yellow plate, green apple on green plate, red apple "
        "on pink plate. Ordering: none.",
        "Let me see... the carrot on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate, and, oh yes, the red apple on the pink plate. However you like, dear.",
        "Four placements, no particular order: carrot blue plate, orange yellow plate, green apple green "
        "plate, red apple pink plate."],
    4: ["First course: green apple and orange on the yellow plate. Second course: carrot and red apple on "
        "the blue plate, any order.",
        "Please begin by placing the green apple and the orange on the yellow plate. Subsequently, the "
        "carrot and the red apple should be placed on the blue plate, in any order.",
        "yellow plate <- {green apple, orange}; then blue plate <- {carrot, red apple}",
        "Before you do anything else, pop the green apple and the orange on the yellow plate, dear. When "
        "you've done that, the carrot and the red apple go on the blue plate, whichever way round.",
        "Round one: green apple and orange onto the yellow plate. Round two: carrot and red apple onto the "
        "blue plate. Order within each round is up to you."],
}

# Issue 28 (h68): a third development batch, four more voices (a teenager texting, a lab protocol, a
# voice-assistant transcript with no punctuation, questions about what is possible).
DEV3_H68: dict[int, list[str]] = {
    1: ["yo robot can u like put the green apple on the blue plate and the orange on the yellow plate lol",
        "Procedure: transfer the green apple to the blue plate; transfer the orange to the yellow plate.",
        "okay robot green apple on the blue plate orange on the yellow plate thanks",
        "Is it possible for you to put the green apple on the blue plate and the orange on the yellow "
        "plate?"],
    2: ["green apple on pink plate, orange on yellow plate, red apple on blue plate, idc about the order",
        "Transfer the green apple to the pink plate, the orange to the yellow plate and the red apple to the "
        "blue plate. Order of transfers: arbitrary.",
        "put the green apple on the pink plate the orange on the yellow plate and the red apple on the blue "
        "plate in any order",
        "Can you get the green apple onto the pink plate, the orange onto the yellow plate and the red apple "
        "onto the blue plate? I don't mind the order."],
    3: ["ok so carrot goes on blue plate, orange on yellow plate, green apple on green plate, red apple on "
        "pink plate, whatever order works",
        "Samples and destinations: carrot - blue plate; orange - yellow plate; green apple - green plate; "
        "red apple - pink plate. No order required.",
        "carrot blue plate orange yellow plate green apple green plate red apple pink plate any order",
        "Would it be possible to have the carrot on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate? Any order is fine by me."],
    4: ["first green apple n orange on the yellow plate, then carrot n red apple on the blue plate, order "
        "dont matter for those",
        "Stage 1: transfer the green apple and the orange to the yellow plate. Stage 2: transfer the carrot "
        "and the red apple to the blue plate (order within a stage is arbitrary).",
        "first the green apple and the orange on the yellow plate then the carrot and the red apple on the "
        "blue plate",
        "Can you do the yellow plate first, with the green apple and the orange, and then the blue plate "
        "with the carrot and the red apple, in any order?"],
}

# Issue 28 (h74): held-out rephrasings written before any h74 rule, in voices the sets above do not use (a
# contract's "shall", a game master's quest, a checklist on separate lines, radio talk, a parent to a
# child, a "let's"/"we're going to" plan, an exam's task sheet, priority labels, a future-tense briefing)
# and framings they do not (a numbered list headed "in this order", "whichever you fancy first", "either
# one first", "Constraint: none on the order"). Measured once before and once at the end
# (scripts/tabletop_styles.py --batch VALID_H74), never read per sentence between; the expected signature
# is each task's ground truth.
VALID_H74: dict[int, list[str]] = {
    1: ["Plating instructions: green apple on the blue plate, orange on the yellow plate.",
        "The robot shall place the green apple on the blue plate and shall place the orange on the yellow "
        "plate.",
        "Robot, this is base. Green apple to blue plate, orange to yellow plate. Over.",
        "Okay sweetie, can you put the green apple on the blue plate for me, and the orange on the yellow "
        "plate? Good job!",
        "- [ ] green apple on blue plate\n- [ ] orange on yellow plate"],
    2: ["The robot shall place the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate. The sequence of placement is at the robot's discretion.",
        "Your quest, brave robot: deliver the green apple to the pink plate, the orange to the yellow plate "
        "and the red apple to the blue plate, in an order of your choosing.",
        "To do (any order):\n- green apple -> pink plate\n- orange -> yellow plate\n"
        "- red apple -> blue plate",
        "Let's get the green apple onto the pink plate, the orange onto the yellow plate and the red apple "
        "onto the blue plate. No need to follow any particular order.",
        "Be a love and put the red apple on the blue plate, the orange on the yellow plate and the green "
        "apple on the pink plate, whichever you fancy first."],
    3: ["Base to robot: carrot to blue plate, orange to yellow plate, green apple to green plate, red apple "
        "to pink plate. Order at your discretion. Over.",
        "Task: move the carrot to the blue plate, the orange to the yellow plate, the green apple to the "
        "green plate and the red apple to the pink plate. Constraint: none on the order.",
        "Arrange the carrot on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate and the red apple on the pink plate, in no set order.",
        "We're going to put the carrot on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate. Any sequence works for me.",
        "You will put the carrot on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, in whichever order you see fit."],
    4: ["Priority 1: green apple and orange on the yellow plate. Priority 2: carrot and red apple on the "
        "blue plate. Within a priority, any order.",
        "The robot shall first place the green apple and the orange on the yellow plate and shall thereafter "
        "place the carrot and the red apple on the blue plate, in either order.",
        "Your first quest: bring the green apple and the orange to the yellow plate. Your second quest: "
        "bring the carrot and the red apple to the blue plate.",
        "Sweetie, the yellow plate comes first: the green apple and the orange go on it. Only when that's "
        "done do the carrot and the red apple go on the blue plate, either one first.",
        "Do in this order:\n1. green apple and orange -> yellow plate\n"
        "2. carrot and red apple -> blue plate"],
}

# Issue 28 (h79): held-out rephrasings written before any h79 rule, in voices the sets above do not use (a
# roommate's sticky note, a museum curator, a stage manager, a nurse's handover, a quiz, a spreadsheet
# pasted as text, a shop-floor supervisor, someone asking on a forum) and framings they do not (a dash list
# after "sort these", a casual opener before a question, "Y gets X", a table of rows, "none of these
# depends on another", "the order within each pair does not matter", "only once ... already"). Measured
# once on first contact and once at the end (scripts/tabletop_styles.py --batch VALID_H79), never read per
# sentence between; the expected signature is each task's ground truth.
VALID_H79: dict[int, list[str]] = {
    1: ["hey, whenever you're free could you sort out the plates - green apple goes to the blue one, orange "
        "to the yellow one",
        "Blue plate <- green apple\nYellow plate <- orange",
        "Note for the robot: the green apple belongs on the blue plate; the orange belongs on the yellow "
        "plate. Cheers!",
        "What should end up where? The green apple on the blue plate, and the orange on the yellow plate.",
        "The green apple should be moved onto the blue plate by you, and the orange onto the yellow plate."],
    2: ["hiya! mind doing me a favour? green apple onto the pink plate, orange onto the yellow plate, red "
        "apple onto the blue plate. do them however you like",
        "Item | Plate\ngreen apple | pink plate\norange | yellow plate\nred apple | blue plate\n(order: "
        "doesn't matter)",
        "The pink plate gets the green apple, the yellow plate gets the orange, and the blue plate gets the "
        "red apple. It makes no difference which one you do first.",
        "I'd like three things done, in no particular sequence - the red apple placed on the blue plate, the "
        "orange placed on the yellow plate, the green apple placed on the pink plate.",
        "Sort these out for me please - green apple: pink plate - orange: yellow plate - red apple: blue "
        "plate. The order in which you do them is irrelevant."],
    3: ["Curator's note: carrot to be displayed on the blue plate, orange on the yellow plate, green apple "
        "on the green plate, red apple on the pink plate. Installation order is unimportant.",
        "hey so when you get a chance, could you pop the carrot on the blue plate, the orange on the yellow "
        "plate, the green apple on the green plate and the red apple on the pink plate? no rush, any order",
        "Each plate gets one thing: blue plate the carrot, yellow plate the orange, green plate the green "
        "apple, pink plate the red apple. Sequence is totally up to you.",
        "Can the carrot go on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate and the red apple on the pink plate? You're free to do them in any order you like.",
        "The carrot is to be placed on the blue plate. The orange is to be placed on the yellow plate. The "
        "green apple is to be placed on the green plate. The red apple is to be placed on the pink plate. "
        "None of these depends on another."],
    4: ["Two rounds. Round A: the green apple and the orange onto the yellow plate. Round B, only after "
        "round A: the carrot and the red apple onto the blue plate; the order within each round does not "
        "matter.",
        "hey, when you get a sec, could you load the yellow plate with the green apple and the orange first, "
        "and after that load the blue plate with the carrot and the red apple? whichever order inside each.",
        "The yellow plate needs the green apple and the orange before the blue plate gets anything; the "
        "blue plate then gets the carrot and the red apple, in either order.",
        "Sequence matters here: green apple and orange go onto the yellow plate to begin with, and the "
        "carrot and red apple onto the blue plate afterwards. Within each pair, do whatever.",
        "Put the carrot and the red apple on the blue plate, but only once the green apple and the orange "
        "are already on the yellow plate."],
}

# Issue 28 (h79): rephrasings for developing h79's form-independent reading (read per sentence): the three
# shapes the lead's closing note named (a list with a colon or dash per pair after "sort these", a casual
# opener, an explicit freedom statement), h74's "I want that X is on Y" past the third pair, and forms the
# reading is to take whatever their framing: questions, passives, "Y gets X", tables, notes.
DEV_H79: dict[int, list[str]] = {
    1: ["Please sort these: - green apple: blue plate - orange: yellow plate",
        "hey, when you get a sec, could you put the green apple on the blue plate and the orange on the "
        "yellow plate?",
        "The green apple is to be put on the blue plate by the robot, and the orange on the yellow plate.",
        "blue plate gets green apple, yellow plate gets orange",
        "green apple | blue plate\norange | yellow plate",
        "Reminder: green apple on the blue plate, orange on the yellow plate. Thanks!",
        "Would you mind putting the orange on the yellow plate and the green apple on the blue plate?"],
    2: ["Please sort these: - green apple: pink plate - orange: yellow plate - red apple: blue plate. The "
        "order within each pair does not matter.",
        "hey, when you get a sec, could you put the green apple on the pink plate, the orange on the yellow "
        "plate and the red apple on the blue plate? the order does not matter",
        "Organise these for me - green apple - pink plate, orange - yellow plate, red apple - blue plate. "
        "Doesn't matter which comes first.",
        "The green apple gets placed on the pink plate, the orange on the yellow plate, the red apple on the "
        "blue plate. You can pick the order.",
        "pink plate: green apple\nyellow plate: orange\nblue plate: red apple\nany order is fine"],
    3: ["I want that carrot is on blue plate, orange is on yellow plate, green apple is on green plate and "
        "red apple is on pink plate.",
        "Please sort these: - carrot: blue plate - orange: yellow plate - green apple: green plate - red "
        "apple: pink plate",
        "hey, when you get a sec, could you do the carrot on the blue plate, the orange on the yellow plate, "
        "the green apple on the green plate and the red apple on the pink plate? order doesn't matter",
        "The blue plate gets the carrot, the yellow plate the orange, the green plate the green apple and "
        "the pink plate the red apple. The order in which you do this is irrelevant.",
        "Everything should be on its plate: carrot on blue, well, on the blue plate, orange on the yellow "
        "plate, green apple on the green plate, red apple on the pink plate. Any order."],
    4: ["Please sort these: - green apple: yellow plate - orange: yellow plate. Then: - carrot: blue plate "
        "- red apple: blue plate. The order within each pair does not matter.",
        "hey, when you get a sec, could you first put the green apple and the orange on the yellow plate, "
        "then the carrot and the red apple on the blue plate? the order within each pair doesn't matter",
        "The green apple and the orange go on the yellow plate first; the carrot and the red apple go on the "
        "blue plate after that. Within each pair the order is up to you.",
        "Yellow plate first (green apple, orange), then blue plate (carrot, red apple), any order inside "
        "each."],
}

# Issue 28 (h79): a second development batch over more forms: plates by colour alone, a "finally" step,
# questions and answers, a forum post, "X precedes Y", texting abbreviations, "sort" with names.
DEV2_H79: dict[int, list[str]] = {
    1: ["green apple -> blue, orange -> yellow",
        "Where does the green apple go? On the blue plate. And the orange? On the yellow plate.",
        "pls put green apple on blue plate n orange on yellow plate thx",
        "Hi all, first post here. I need my robot to put the green apple on the blue plate and the orange "
        "on the yellow plate. Thanks in advance!",
        "Sort the green apple onto the blue plate and the orange onto the yellow plate.",
        "Put the green apple on the blue plate and the orange on the yellow."],
    2: ["Item | Plate\ngreen apple | pink\norange | yellow\nred apple | blue\nany order",
        "Could you sort these out for me? green apple to the pink plate, orange to the yellow plate, red "
        "apple to the blue plate. Which one goes first is up to you.",
        "The pink plate gets the green apple, the yellow plate gets the orange, and the blue plate gets the "
        "red apple. It does not matter which one you start with.",
        "green apple - pink plate\norange - yellow plate\nred apple - blue plate\n(no particular order)"],
    3: ["hey! when you have a minute, carrot on blue, orange on yellow, green apple on green, red apple on "
        "pink. whatever order",
        "Would it be possible to put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate? The order is completely up to you.",
        "None of these depend on each other: carrot on the blue plate, orange on the yellow plate, green "
        "apple on the green plate, red apple on the pink plate."],
    4: ["First the green apple and the orange on the yellow plate, and finally the carrot and the red apple "
        "on the blue plate. The order within each pair does not matter.",
        "Green apple and orange onto the yellow plate must precede carrot and red apple onto the blue plate.",
        "yellow plate: green apple, orange (first)\nblue plate: carrot, red apple (after that)",
        "hey, when you get a sec: green apple and orange on the yellow plate first, then carrot and red "
        "apple on the blue plate, any order within each pair"],
}

# Issue 28 (h79): a third development batch: openers and headings of other kinds, freedom said in other
# words, and the order said of plates rather than of objects ("once the yellow plate is done").
DEV3_H79: dict[int, list[str]] = {
    1: ["hey there! quick favour: green apple on the blue plate and orange on the yellow plate",
        "Here's the plan: the green apple goes to the blue plate, the orange goes to the yellow plate.",
        "so, um, if you could, the green apple on the blue plate and the orange on the yellow plate",
        "whenever you can, green apple to blue plate and orange to yellow plate, ta"],
    2: ["Feel free to do them in any order: green apple on pink plate, orange on yellow plate, red apple "
        "on blue plate.",
        "green apple on the pink plate, orange on the yellow plate, red apple on the blue plate. I don't "
        "mind which goes first.",
        "TODO: green apple -> pink plate; orange -> yellow plate; red apple -> blue plate. Order isn't "
        "important.",
        "Can you make it so the green apple is on the pink plate, the orange is on the yellow plate and the "
        "red apple is on the blue plate? Doesn't matter what order."],
    3: ["carrot on the blue plate, orange on the yellow plate, green apple on the green plate, red apple "
        "on the pink plate - the order's up to you",
        "Instructions: carrot to blue plate, orange to yellow plate, green apple to green plate, red apple "
        "to pink plate. No specific order needed.",
        "at some point today, could you put the carrot on the blue plate, the orange on the yellow plate, "
        "the green apple on the green plate and the red apple on the pink plate? any sequence is fine"],
    4: ["Do the yellow plate before the blue plate: green apple and orange on the yellow plate, carrot "
        "and red apple on the blue plate.",
        "Start with the yellow plate (green apple and orange), then do the blue plate (carrot and red "
        "apple). Within each plate the order is free.",
        "Green apple and orange on the yellow plate. Once the yellow plate is done, carrot and red apple on "
        "the blue plate, in either order.",
        "hey, when you get a sec: yellow plate gets green apple and orange first, blue plate gets carrot and "
        "red apple after, any order within each"],
}

# Issue 28 (h79): a fourth development batch: the three shapes the lead named, combined and varied (line
# breaks, no commas, "+" for "and", a heading that asks a question).
DEV4_H79: dict[int, list[str]] = {
    1: ["Could you please sort these for me: green apple - blue plate; orange - yellow plate",
        "Hey when you get a sec could you put the green apple on the blue plate and the orange on the "
        "yellow plate"],
    2: ["Please sort these:\n- green apple: pink plate\n- orange: yellow plate\n- red apple: blue plate",
        "hey, when you get a sec, could you sort these? - green apple: pink plate - orange: yellow plate - "
        "red apple: blue plate (order doesn't matter)"],
    3: ["Hey! When you get a chance could you sort the plates: carrot goes on blue, orange on yellow, "
        "green apple on green, red apple on pink. Order doesn't matter.",
        "sort these please: carrot -> blue plate, orange -> yellow plate, green apple -> green plate, red "
        "apple -> pink plate. the order does not matter"],
    4: ["Please sort these: first - green apple: yellow plate, orange: yellow plate; then - carrot: blue "
        "plate, red apple: blue plate. The order within each pair does not matter.",
        "hey when you get a sec could you first do the yellow plate (green apple + orange) and then the "
        "blue plate (carrot + red apple)? order within each pair does not matter",
        "hey, when you get a sec, could you put the green apple and the orange on the yellow plate, and "
        "once that's done the carrot and red apple on the blue plate? the order within each pair does not "
        "matter"],
}

# Issue 28 (h79): a fifth development batch, fifteen sentences written at once in as many voices (a
# briefing, a forum post, "respectively", idioms: "first things first", "once that's sorted").
DEV5_H79: dict[int, list[str]] = {
    1: [
        "OK robot, here's the deal: the green apple belongs with the blue plate and the orange belongs "
        "with the yellow plate.",
        "Just so you know what I want: green apple -> blue plate and orange -> yellow plate, cheers",
        "The green apple should be on the blue plate and the orange on the yellow plate when you're "
        "finished.",
        "Assign the green apple to the blue plate and the orange to the yellow plate.",
        "Get the green apple onto the blue plate, and get the orange onto the yellow plate, in whichever "
        "order."],
    2: [
        "pink plate <- green apple, yellow plate <- orange, blue plate <- red apple; order irrelevant",
        "Could the red apple go on the blue plate, the green apple on the pink plate and the orange on "
        "the yellow plate? Any order you want is fine by me.",
        "I'd like you to sort the fruit: the green apple goes on the pink plate, the orange goes on the "
        "yellow plate and the red apple goes on the blue plate. Sequence doesn't matter."],
    3: [
        "The carrot, the orange, the green apple and the red apple go on the blue, yellow, green and pink"
        " plates respectively, in any order.",
        "hey, quick one: carrot on blue plate, orange on yellow plate, green apple on green plate, red "
        "apple on pink plate. any order's fine",
        "Here's what needs doing, in no set order: carrot on the blue plate; orange on the yellow plate; "
        "green apple on the green plate; red apple on the pink plate."],
    4: [
        "First things first: green apple and orange on the yellow plate. After that's sorted, carrot and "
        "red apple on the blue plate, any order.",
        "To start, the yellow plate gets the green apple and the orange. Then the blue plate gets the "
        "carrot and the red apple. Within each plate, the order doesn't matter.",
        "Load the yellow plate first - green apple and orange - and then the blue plate - carrot and red "
        "apple. Either order within each.",
        "Green apple and orange onto the yellow plate, then, and only then, carrot and red apple onto the"
        " blue plate."],
}

# Issue 28 (h83): held-out rephrasings, written and committed before any h83 rule, in voices no older batch
# uses (a parent to a child, a voice transcript with fillers, a bullet list with arrows, an e-mail with a
# subject and a sign-off, a text message with abbreviations, a recipe, "X lives on Y", "the plate is for X",
# phases, "don't touch ... until ...", "fill the plate with ..."); measured once on first contact and once at
# the end (scripts/tabletop_styles.py --batch VALID_H83), never read per sentence between.
VALID_H83: dict[int, list[str]] = {
    1: ["Don't forget: green apple on the blue plate and orange on the yellow plate.",
        "ok so um put the green apple on the blue plate and uh the orange on the yellow plate",
        "Could we have the green apple on the blue plate and the orange on the yellow plate, please?",
        "\u2022 green apple \u2192 blue plate\n\u2022 orange \u2192 yellow plate",
        "Kiddo, the green apple lives on the blue plate and the orange lives on the yellow plate, can you "
        "fix that?"],
    2: ["Subject: plates\nHi robot, please move the green apple to the pink plate, the orange to the yellow "
        "plate and the red apple to the blue plate. Do them in whatever order suits you. Best, Sam",
        "Your job: red apple on the blue plate, green apple on the pink plate, orange on the yellow plate; "
        "the sequence is your call.",
        "If you could drop the orange onto the yellow plate, the red apple onto the blue plate and the green "
        "apple onto the pink plate, that'd be great - any order is fine.",
        "green apple \u2192 pink plate, orange \u2192 yellow plate, red apple \u2192 blue plate. order: any",
        "The green apple lives on the pink plate, the orange on the yellow plate and the red apple on the "
        "blue plate. Tidy them up in any order."],
    3: ["Recipe for a tidy table: carrot on the blue plate, orange on the yellow plate, green apple on the "
        "green plate, red apple on the pink plate. Mix up the order as you please.",
        "Quick one: could the carrot land on the blue plate, the orange on the yellow plate, the green apple "
        "on the green plate and the red apple on the pink plate? Any order works.",
        "Four moves, no particular order: carrot onto the blue plate, orange onto the yellow plate, green "
        "apple onto the green plate, red apple onto the pink plate.",
        "The blue plate is for the carrot, the yellow plate is for the orange, the green plate is for the "
        "green apple and the pink plate is for the red apple. Order is not important.",
        "cn u put carrot on blue plate, orange on yellow plate, green apple on green plate, red "
        "apple on pink "
        "plate. any order thx"],
    4: ["Phase one: the green apple and the orange on the yellow plate, either order. Phase two: the carrot "
        "and the red apple on the blue plate, either order.",
        "Don't touch the blue plate until the green apple and the orange are on the yellow plate. Then put "
        "the carrot and the red apple on the blue plate.",
        "The green apple and the orange go on the yellow plate first; only then do the carrot and the red "
        "apple go on the blue plate.",
        "Fill the yellow plate with the green apple and the orange, and when that's done, fill the blue "
        "plate with the carrot and the red apple.",
        "ok first thing green apple and orange onto yellow plate, next carrot and red apple onto blue plate"],
}

# Issue 28 (h83): rephrasings for developing h83's rules (read per sentence): symbols for "goes to", fillers,
# sign-offs and subject lines, "lives on" / "is for", "until", and voices from chat, notes and lists.
DEV_H83: dict[int, list[str]] = {
    1: ["Remember: the orange on the yellow plate and the green apple on the blue plate.",
        "so like, uh, the green apple on the blue plate and the orange on the yellow plate",
        "- orange \u2192 yellow plate\n- green apple \u2192 blue plate",
        "Hi! Please put the green apple on the blue plate and the orange on the yellow plate. Thanks, Jo",
        "The blue plate is for the green apple and the yellow plate is for the orange."],
    2: ["Re: tidying\nPlease put the red apple on the blue plate, the orange on the yellow plate "
        "and the green "
        "apple on the pink plate, any order. Regards, Kim",
        "red apple \u2192 blue plate; orange \u2192 yellow plate; green apple \u2192 pink plate (any order)",
        "u can put the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the "
        "blue plate in any order",
        "Your task: orange on the yellow plate, red apple on the blue plate, green apple on the pink plate. "
        "Any order."],
    3: ["The carrot lives on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate and the red apple on the pink plate; any order.",
        "Could the carrot go onto the blue plate, the orange onto the yellow plate, the green apple onto the "
        "green plate and the red apple onto the pink plate? Any order is fine, thanks!",
        "um carrot on blue plate orange on yellow plate green apple on green plate red apple on pink plate "
        "any order"],
    4: ["Leave the blue plate alone until the green apple and the orange are on the yellow plate; then put "
        "the carrot and the red apple on the blue plate.",
        "Stage one: the green apple and the orange onto the yellow plate. Stage two: the carrot and the red "
        "apple onto the blue plate.",
        "first green apple and orange onto yellow plate, then carrot and red apple onto blue plate",
        "Fill the yellow plate with the orange and the green apple, then fill the blue plate with the red "
        "apple and the carrot."],
}

# Issue 28 (h87): held-out rephrasings, written and committed before any h87 rule, in voices no older batch
# uses (archaic "pray ... upon", a diner's order, JSON, a yoga teacher, a pirate, a chat message with an
# @-mention and an emoji code, a bureaucrat's "hereby", a game-show host, meeting action items, a stand-up
# note, "picture this when you're done", a rhyme, a tutorial, a military objective list) and framings they
# do not ("followed by", "wait until", "move on to", "how you get there is up to you", "in this step");
# measured once on first contact and once at the end (scripts/tabletop_styles.py --batch VALID_H87), never
# read per sentence between.
VALID_H87: dict[int, list[str]] = {
    1: ["Pray, set the green apple upon the blue plate, and the orange upon the yellow plate.",
        "I'll have the green apple on the blue plate and the orange on the yellow plate, thanks.",
        '{"green apple": "blue plate", "orange": "yellow plate"}',
        "Gently lift the green apple and rest it on the blue plate, and gently rest the orange on the "
        "yellow plate. Nice and slow.",
        "Arr, stow the green apple on the blue plate and the orange on the yellow plate, matey!",
        "@robot can you put the green apple on the blue plate and the orange on the yellow plate :pray:"],
    2: ["It is hereby requested that the green apple be placed on the pink plate, the orange on the yellow "
        "plate and the red apple on the blue plate, in no prescribed order.",
        "Tonight's challenge: green apple to the pink plate, orange to the yellow plate, red apple to the "
        "blue plate - tackle them in any order you like!",
        "Action items (unordered): green apple onto pink plate; orange onto yellow plate; red apple onto "
        "blue plate.",
        "Per today's stand-up, the green apple needs to go on the pink plate, the orange on the yellow plate "
        "and the red apple on the blue plate. Feel free to tackle these in any order.",
        "Picture this when you're done: green apple on the pink plate, orange on the yellow plate, red apple "
        "on the blue plate. How you get there is up to you.",
        "Green apple to the pink, orange to the yellow, red apple to the blue - any order, fellow!"],
    3: ["The customer wants the carrot on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate - any order.",
        '{"carrot": "blue plate", "orange": "yellow plate", "green apple": "green plate", "red apple": '
        '"pink plate"}',
        "Pray place the carrot upon the blue plate, the orange upon the yellow, the green apple upon the "
        "green, and the red apple upon the pink; the order thereof is of no import.",
        "In this step, you'll put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate. You can go in any order.",
        "No hurry at all - carrot on the blue plate, orange on the yellow plate, green apple on the green "
        "plate, red apple on the pink plate, in whatever order feels natural.",
        "@robot quick ask :) carrot -> blue plate, orange -> yellow plate, green apple -> green plate, red "
        "apple -> pink plate. order is whatever"],
    4: ["Objective one: green apple and orange onto the yellow plate. Objective two: carrot and red apple "
        "onto the blue plate, in either order.",
        "The green apple and the orange go on the yellow plate, followed by the carrot and the red apple on "
        "the blue plate.",
        "Start off by putting the green apple and the orange on the yellow plate. Once you've finished with "
        "the yellow plate, move on to the blue plate: carrot and red apple, whichever order.",
        "Firstly, set the green apple and the orange upon the yellow plate; thereafter, the carrot and the "
        "red apple upon the blue plate, in whichever order thou wilt.",
        "The carrot and the red apple go on the blue plate, but wait until the green apple and the orange "
        "are on the yellow plate.",
        "First, ye load the yellow plate with the green apple and the orange. Then ye load the blue plate "
        "with the carrot and the red apple, arr!"],
}

# Issue 28 (h87): rephrasings for developing h87's rules (read per sentence), in voices VALID_H87 does not
# use (a film director, a tour guide, a cowboy, a tweet with hashtags, a shouted sign, "do the needful", a
# haiku-like terse voice, a bartender) and the shapes older held-out batches left refused, in other words
# (a question heading, a bracketed "order:" remark on its own line, lettered labels, "before ... gets
# anything", a freedom said with "as you please", a heading with "one", a negated "until", "shall first").
DEV_H87: dict[int, list[str]] = {
    1: ["Action! The green apple goes on the blue plate, the orange on the yellow plate. Cut!",
        "Howdy partner, rustle that green apple onto the blue plate and the orange onto the yellow plate.",
        "PLEASE PLACE THE GREEN APPLE ON THE BLUE PLATE AND THE ORANGE ON THE YELLOW PLATE",
        "Kindly do the needful: green apple on the blue plate, orange on the yellow plate.",
        "Where do things go? Green apple on the blue plate, orange on the yellow plate.",
        "Could I trouble you to put the green apple on the blue plate and the orange on the yellow plate?"],
    2: ["On your left, the pink plate, which will hold the green apple; the yellow plate takes the orange "
        "and the blue plate the red apple. Any order at all.",
        "green apple on pink plate, orange on yellow plate, red apple on blue plate #tidy #anyorder",
        "Fruit | Plate\ngreen apple | pink plate\norange | yellow plate\nred apple | blue plate\n(sequence: "
        "up to you)",
        "Green apple, pink plate; orange, yellow plate; red apple, blue plate. Shuffle the order as you "
        "like.",
        "One more thing: the green apple on the pink plate, the orange on the yellow plate, the red apple on "
        "the blue plate, any order."],
    3: ["Pour me - I mean, place the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate, any order.",
        "What goes where: carrot on the blue plate, orange on the yellow plate, green apple on the green "
        "plate, red apple on the pink plate. Order as you please.",
        "Could you be a sweetheart and put the carrot on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate? Any order.",
        "Four quick ones, any order: carrot onto the blue plate, orange onto the yellow plate, green apple "
        "onto the green plate, red apple onto the pink plate."],
    4: ["Part A: green apple and orange onto the yellow plate. Part B: carrot and red apple onto the blue "
        "plate.",
        "The yellow plate gets the green apple and the orange before the blue plate gets anything; then the "
        "blue plate gets the carrot and the red apple.",
        "Leave the blue plate empty until the green apple and the orange are on the yellow plate, then put "
        "the carrot and the red apple on the blue plate.",
        "The robot shall first place the green apple and the orange on the yellow plate and shall then "
        "place the carrot and the red apple on the blue plate.",
        "Nothing goes on the blue plate until the green apple and the orange are on the yellow plate; after "
        "that, the carrot and the red apple go on the blue plate.",
        "You shall first put the green apple and the orange on the yellow plate, and you shall then put the "
        "carrot and the red apple on the blue plate."],
}

# Issue 28 (h87): a second development batch, sixteen sentences written at once in voices no batch uses (a
# sports coach's play call, a flight attendant, a librarian, a kindergarten song, a ship's captain, a
# hurried parent, a game tutorial, a scientist's notebook, a sceptic, a poet, a customer complaint, a
# magician), measured before any rule for them.
DEV2_H87: dict[int, list[str]] = {
    1: ["Ladies and gentlemen, please ensure the green apple is stowed on the blue plate and the orange on "
        "the yellow plate.",
        "Shh, quietly now: the green apple to the blue plate, the orange to the yellow plate.",
        "Green apple, find your blue plate! Orange, find your yellow plate!",
        "Helm, set the green apple on the blue plate and the orange on the yellow plate. Make it so."],
    2: ["Okay, quick, quick: green apple on the pink plate, orange on the yellow plate, red apple on the "
        "blue plate - I don't care how, just do it.",
        "Tutorial: drag the green apple to the pink plate, the orange to the yellow plate and the red apple "
        "to the blue plate. You can do these in any order.",
        "Observation plan: green apple placed on pink plate; orange placed on yellow plate; red apple placed "
        "on blue plate. Order randomised.",
        "I bet you can't put the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate. Any order, go on."],
    3: ["The carrot for the blue plate, the orange for the yellow plate, the green apple for the green plate "
        "and the red apple for the pink plate - in any order.",
        "My complaint: the carrot is not on the blue plate. Put the carrot on the blue plate, the orange "
        "on the yellow plate, the green apple on the green plate and the red apple on the pink plate, any "
        "order.",
        "And for my next trick: carrot onto the blue plate, orange onto the yellow plate, green apple onto "
        "the green plate, red apple onto the pink plate, in any order whatsoever.",
        "Here's a little job for you: put the carrot on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate. Any order is grand."],
    4: ["Play one: green apple and orange to the yellow plate. Play two: carrot and red apple to the blue "
        "plate.",
        "Green apple and orange on the yellow plate - that's the first job. The second job: carrot and red "
        "apple on the blue plate, any order.",
        "Right, so before you go near the blue plate, put the green apple and the orange on the yellow "
        "plate. Then the carrot and the red apple go on the blue plate.",
        "The yellow plate is first in line: it gets the green apple and the orange. The blue plate is next: "
        "it gets the carrot and the red apple."],
}

# Issue 28 (h87): a third development batch, sixteen sentences written at once after the rules above, in
# voices no batch uses (a text adventure, a drill sergeant, a court order, an HR memo, a wedding planner, a
# DJ, "TL;DR", a dog trainer, a mechanic, a fortune teller), measured once before any rule for them.
DEV3_H87: dict[int, list[str]] = {
    1: ["> put green apple on blue plate\n> put orange on yellow plate",
        "Listen up! Green apple, blue plate. Orange, yellow plate. Move it!",
        "The court hereby orders that the green apple be placed on the blue plate and the orange on the "
        "yellow plate.",
        "TL;DR: green apple on the blue plate, orange on the yellow plate."],
    2: ["Memo to all robots: please place the green apple on the pink plate, the orange on the yellow plate "
        "and the red apple on the blue plate. Sequence at your discretion.",
        "For the big day we need the green apple on the pink plate, the orange on the yellow plate and the "
        "red apple on the blue plate - any order, darling.",
        "Spin it! Green apple to the pink plate, orange to the yellow plate, red apple to the blue plate, "
        "mix it up any order!",
        "Good robot! Now pop the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate. Any order. Good job!"],
    3: ["Job card: carrot - blue plate, orange - yellow plate, green apple - green plate, red apple - pink "
        "plate. Order not critical.",
        "I see the carrot on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate and the red apple on the pink plate in your future - make it happen, in any order.",
        "FYI we want the carrot on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate. Order irrelevant.",
        "Please, in no special order: carrot to the blue plate, orange to the yellow plate, green apple to "
        "the green plate, red apple to the pink plate."],
    4: ["> put green apple on yellow plate\n> put orange on yellow plate\n> wait\n> put carrot on blue plate"
        "\n> put red apple on blue plate",
        "Listen up! First the green apple and the orange go on the yellow plate. Then, and only then, the "
        "carrot and the red apple go on the blue plate!",
        "Memo: priority goes to the yellow plate (green apple, orange); the blue plate (carrot, red apple) "
        "follows.",
        "Load the yellow plate with the green apple and the orange; once it's loaded, load the blue plate "
        "with the carrot and the red apple."],
}

# Issue 28 (h90): held-out rephrasings written and committed before any h90 rule, in voices no batch above
# uses (a telegram, a text with "pls"/"thx", a carnival barker, an inverted "on X, the Y", a spy briefing, a
# recipe card, a sports commentator, a teacher's homework, a self-answered question list, teen slang, a
# grandmother's letter, a news headline, a programmer's mapping, a station announcement, a hurried
# "before I head out", a project plan's phases, a video game's levels, a house rule, a "must be ... before
# ... touches", a chef, "do X and then Y"). Measured on first contact without --per-sentence and once at
# the end; the expected signature is each task's ground truth.
VALID_H90: dict[int, list[str]] = {
    1: ["GREEN APPLE TO BLUE PLATE STOP ORANGE TO YELLOW PLATE STOP",
        "pls put green apple on blue plate n orange on yellow plate thx",
        "Step right up! The green apple lands on the blue plate and the orange lands on the yellow plate!",
        "On the blue plate, the green apple; on the yellow plate, the orange.",
        "Your mission, should you choose to accept it: the green apple on the blue plate, the orange on the "
        "yellow plate."],
    2: ["Recipe: 1 green apple, on the pink plate. 1 orange, on the yellow plate. 1 red apple, on the blue "
        "plate. Assemble in any order.",
        "And the green apple goes on the pink plate! The orange to the yellow plate! The red apple to the "
        "blue plate! Any order, folks, it's all legal!",
        "Homework for today: put the green apple on the pink plate, the orange on the yellow plate, and the "
        "red apple on the blue plate. Do them in whatever order suits you.",
        "Green apple? Pink plate. Orange? Yellow plate. Red apple? Blue plate. Order? Doesn't matter.",
        "no cap, just yeet the green apple onto the pink plate, the orange onto the yellow plate and the red "
        "apple onto the blue plate, order doesn't matter fr"],
    3: ["Dearest robot, would you be so kind as to set the carrot on the blue plate, the orange on the "
        "yellow plate, the green apple on the green plate and the red apple on the pink plate? In any order "
        "you wish. With love, Grandma",
        "Breaking: carrot heads to blue plate, orange to yellow plate, green apple to green plate, red apple "
        "to pink plate; order left open.",
        "Mapping (order-free): carrot => blue plate; orange => yellow plate; green apple => green plate; red "
        "apple => pink plate",
        "Attention please: the carrot is to be placed on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate. Order of placement: "
        "unrestricted.",
        "Quick favour before I head out: carrot on the blue plate, orange on the yellow plate, green apple "
        "on the green plate, red apple on the pink plate. Do them in any sequence."],
    4: ["Phase 1 (do this before anything else): green apple and orange on the yellow plate. Phase 2: "
        "carrot and red apple on the blue plate, order within the phase is free.",
        "Level 1: green apple and orange onto the yellow plate. Level 2: carrot and red apple onto the blue "
        "plate. Don't start level 2 before level 1 is cleared.",
        "House rule: the yellow plate is filled first (green apple, orange), and only then does anything go "
        "on the blue plate (carrot, red apple).",
        "The green apple and the orange must be on the yellow plate before the carrot or the red apple "
        "touches the blue plate.",
        "Chef says: yellow plate first, with the green apple and the orange; when the yellow plate is done, "
        "the blue plate gets the carrot and the red apple.",
        "Do the yellow plate (green apple, orange) and then the blue plate (carrot, red apple); within a "
        "plate, any order."],
}

# Issue 28 (h90): rephrasings for developing h90's rules (read per sentence): the shapes VALID_H87 and
# VALID_H79 left refused, in other words (an end state described "when you're done", a freedom said as "of
# no consequence" / "your call", "when you're done with PLATE, go on to PLATE", a positive "wait / hold off
# until", a label that refers back to an earlier label), in voices no batch uses (an interior designer, a
# lab protocol, a babysitter's note, a referee, a librarian's checklist, a surveyor).
DEV_H90: dict[int, list[str]] = {
    1: ["Here's how the table should look at the end: green apple on the blue plate, orange on the yellow "
        "plate. How you get there is your call.",
        "Design brief: the green apple rests on the blue plate and the orange rests on the yellow plate."],
    2: ["When you're finished, the table should look like this: green apple on the pink plate, orange on "
        "the yellow plate, red apple on the blue plate. The route there is up to you.",
        "Place the green apple on the pink plate, the orange on the yellow plate and the red apple on the "
        "blue plate; the sequence is of no consequence.",
        "Put the green apple on the pink plate, the orange on the yellow plate and the red apple on the blue "
        "plate. Which one comes first is of no importance."],
    3: ["End state: carrot on the blue plate, orange on the yellow plate, green apple on the green plate, "
        "red apple on the pink plate. The order of the moves is your call.",
        "Set the carrot upon the blue plate, the orange upon the yellow, the green apple upon the green and "
        "the red apple upon the pink; the order is of no importance."],
    4: ["Begin by putting the green apple and the orange on the yellow plate. When you're done with the "
        "yellow plate, go on to the blue plate: carrot and red apple, either order.",
        "Put the carrot and the red apple on the blue plate, but hold off until the green apple and the "
        "orange are on the yellow plate.",
        "Put the carrot and the red apple on the blue plate, but wait until the green apple and the orange "
        "are already on the yellow plate.",
        "Step one: the green apple and the orange onto the yellow plate. Step two, only after step one: the "
        "carrot and the red apple onto the blue plate.",
        "Batch one: green apple and orange on the yellow plate. Batch two, after batch one: carrot and red "
        "apple on the blue plate.",
        "Fill the yellow plate with the green apple and the orange. Once you're through with the yellow "
        "plate, move on to the blue plate and fill it with the carrot and the red apple."],
}

# Issue 28 (h90): a second development batch, written at once after the rules for DEV_H90, in voices no
# batch uses ("Simon says", a weather report, an auctioneer, a cooking show, a robot's log, a sign in a
# shop, a coach at half-time, a detective, a wedding toast, a sailor's log, a quiz master, a mum's voice
# note), measured once before any rule for it.
DEV2_H90: dict[int, list[str]] = {
    1: ["Simon says: green apple on the blue plate, orange on the yellow plate.",
        "Today's forecast: a green apple landing on the blue plate and an orange settling on the yellow "
        "plate.",
        "Log entry: task received - green apple to the blue plate, orange to the yellow plate.",
        "Voice note from mum: love, can you pop the green apple on the blue plate and the orange on the "
        "yellow plate? Ta."],
    2: ["Going once, going twice: green apple to the pink plate, orange to the yellow plate, red apple to "
        "the blue plate - in any order!",
        "Today on the show we plate the green apple on the pink plate, the orange on the yellow plate and "
        "the red apple on the blue plate; plate them in any order.",
        "Elementary: the green apple belongs on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate. Which you place first is immaterial.",
        "Captain's log: the green apple goes on the pink plate, the orange on the yellow plate, the red "
        "apple on the blue plate. Order unimportant."],
    3: ["Sign: please put the carrot on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate. Any order.",
        "Half-time talk: carrot to the blue plate, orange to the yellow plate, green apple to the green "
        "plate, red apple to the pink plate. Do it in the order that suits you.",
        "Raise a glass and put the carrot on the blue plate, the orange on the yellow plate, the green apple "
        "on the green plate and the red apple on the pink plate - the order is entirely yours.",
        "For ten points: carrot on the blue plate, orange on the yellow plate, green apple on the green "
        "plate, red apple on the pink plate, in any order you choose."],
    4: ["Simon says: first the green apple and the orange on the yellow plate, and only then the carrot and "
        "the red apple on the blue plate.",
        "Once the yellow plate holds the green apple and the orange, the blue plate can take the carrot and "
        "the red apple.",
        "Yellow plate before blue plate: the green apple and the orange go on the yellow one, the carrot and "
        "the red apple on the blue one.",
        "Get the green apple and the orange onto the yellow plate; only when you're done with the yellow "
        "plate should the carrot and the red apple go onto the blue plate."],
}

# Issue 28 (h90): a third development batch, written at once after the rules for DEV_H90 and DEV2_H90 and
# before any rule for it, in voices no batch uses (a pilot's checklist, an audio guide, a herald, a
# concierge, a commit message, a gardener, a horoscope, a nurse at rounds), measured once before any rule.
DEV3_H90: dict[int, list[str]] = {
    1: ["Checklist: green apple - blue plate, check. Orange - yellow plate, check.",
        "Hear ye, hear ye: the green apple shall go upon the blue plate, the orange upon the yellow plate!",
        "fix: move green apple to blue plate; move orange to yellow plate",
        "As your concierge I'd suggest the green apple on the blue plate and the orange on the yellow "
        "plate."],
    2: ["Press play. The green apple goes to the pink plate, the orange to the yellow plate and the red "
        "apple to the blue plate. The order is yours to choose.",
        "Plant the green apple in the pink plate, the orange in the yellow plate and the red apple in the "
        "blue plate; it makes no odds which goes first.",
        "Your stars today: green apple on the pink plate, orange on the yellow plate, red apple on the blue "
        "plate. Any order brings luck.",
        "Rounds: green apple onto the pink plate, orange onto the yellow plate, red apple onto the blue "
        "plate, no set sequence."],
    3: ["Checklist, any order: carrot - blue plate; orange - yellow plate; green apple - green plate; red "
        "apple - pink plate.",
        "Hear ye: carrot upon the blue plate, orange upon the yellow plate, green apple upon the green "
        "plate, red apple upon the pink plate, in what order thou wilt.",
        "feat: put carrot on blue plate, orange on yellow plate, green apple on green plate, red apple on "
        "pink plate (order-independent)",
        "I'd recommend the carrot on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, in whichever order is easiest."],
    4: ["Checklist: 1. green apple and orange - yellow plate. 2. carrot and red apple - blue plate.",
        "Hear ye: first the green apple and the orange upon the yellow plate, and thereafter the carrot and "
        "the red apple upon the blue plate!",
        "Plant the green apple and the orange in the yellow plate first; when you're done with the yellow "
        "plate, plant the carrot and the red apple in the blue plate.",
        "The yellow plate's turn comes first: green apple and orange. Then it's the blue plate's turn: "
        "carrot and red apple."],
}

# Issue 28 (h94): held-out rephrasings written and committed before any h94 rule (and before reading
# VALID_H90's refusals per sentence), in voices no batch above uses (a two-line text message, a child's
# excited voice, a YAML list, a passive-aggressive note, a very polite British request, a checkbox to-do
# list, a question series, a non-native speaker, a manager delegating, a "what you'll need" card, a long
# rambling message, a counted heading, a numbered plan with lettered sub-steps, a kids' party host, a
# recipe card with a yield line). Measured on first contact without --per-sentence and once at the end;
# the expected signature is each task's ground truth.
VALID_H94: dict[int, list[str]] = {
    1: ["hey r u free?\ngreen apple on the blue plate n orange on the yellow plate plz",
        "Robot can you pleeease put the green apple on the blue plate?? And the orange on the yellow "
        "plate!! Thank you robot!!",
        "placements:\n  - green apple: blue plate\n  - orange: yellow plate",
        "As I've asked twice already, the green apple goes on the blue plate and the orange goes on the "
        "yellow plate.",
        "Would you mind terribly popping the green apple onto the blue plate and the orange onto the yellow "
        "plate?",
        "[ ] green apple -> blue plate\n[ ] orange -> yellow plate"],
    2: ["Can you put the green apple on the pink plate? The orange on the yellow plate? The red apple on "
        "the blue plate? Any order's fine.",
        "Please to put green apple in pink plate, orange in yellow plate and red apple in blue plate. Which "
        "one first is not important.",
        "I need you to own this one: green apple onto the pink plate, orange onto the yellow plate, red "
        "apple onto the blue plate. Sequence is your call.",
        "What you'll need: green apple, orange, red apple. Put the green apple on the pink plate, the orange "
        "on the yellow plate and the red apple on the blue plate. Note: no particular order required.",
        "So I was thinking about lunch and honestly it'd help a lot if the fruit got sorted out, nothing "
        "fancy, the green apple should go on the pink plate, the orange on the yellow plate, and oh yeah "
        "the red apple on the blue plate, I don't care what order you do them in as long as they all end up "
        "where they belong.",
        "Three little jobs for you, in no order at all: green apple on the pink plate, orange on the yellow "
        "plate, red apple on the blue plate."],
    3: ["Hi! Okay so I've got a bit of a weird request, hope that's fine. I'm setting the table for a kids' "
        "party and every plate has a colour, right, so I want the carrot on the blue plate, the orange on "
        "the yellow plate, then the green apple on the green plate (makes sense, right?) and finally the "
        "red apple on the pink plate. Honestly the order doesn't matter at all, I just want it to look "
        "nice. Thanks so much!",
        "Plan:\n1. carrot - blue plate\n2. orange - yellow plate\n3. green apple - green plate\n4. red apple "
        "- pink plate\n(the numbers are just for reference, do them in any order)",
        "You must put carrot into blue plate, orange into yellow plate, green apple into green plate, red "
        "apple into pink plate. Order is free.",
        "ok robot here is the game: the carrot goes on the blue plate and the orange goes on the yellow "
        "plate and the green apple goes on the green plate and the red apple goes on the pink plate and you "
        "can do them in any order you want",
        "plates pls: carrot blue, orange yellow, green apple green, red apple pink\nany order",
        "Can you do me a favour? Would you put the carrot on the blue plate, the orange on the yellow plate, "
        "the green apple on the green plate and the red apple on the pink plate? In any order?"],
    4: ["1. Yellow plate:\n   a) green apple\n   b) orange\n2. Blue plate, once step 1 is finished:\n   a) "
        "carrot\n   b) red apple\nThe letters within a step can be done in any order.",
        "Firstly you put green apple and orange on yellow plate. After finish this, you put carrot and red "
        "apple on blue plate, any order is ok.",
        "yellow plate first: green apple + orange\nthen blue plate: carrot + red apple",
        "Okay so here's the thing, I need the yellow plate done first, meaning the green apple and the "
        "orange go on it, and it's only once that's done that you should start on the blue plate, which "
        "gets the carrot and the red apple, and for each plate I really don't mind which of the two goes "
        "first.",
        "Could you put the green apple and the orange on the yellow plate first? And after that, the carrot "
        "and the red apple on the blue plate? Either order within each pair.",
        "first the green apple and the orange go on the yellow plate!! and THEN the carrot and the red apple "
        "go on the blue plate!!",
        "Makes: one tidy table\nStep 1: Lay the green apple and the orange on the yellow plate.\nStep 2: "
        "When that's done, lay the carrot and the red apple on the blue plate."],
}

# Issue 28 (h94): rephrasings for developing h94's rules (read per sentence), written at once in voices no
# batch above uses (spoken dictation, a surfer, a waiter, a therapist, a movie trailer, a grocery list, a
# hotel card, a scout leader, a philosopher, a worksheet, a telemarketer, a Slack thread) and with what
# makes a voice hard to read: chit-chat sentences, counts in headings and closing remarks, references by
# count, questions in a row, "then ... finally" inside a free-order list, sub-steps.
DEV_H94: dict[int, list[str]] = {
    1: ["Hope your day is going well! Green apple on the blue plate, orange on the yellow plate. Cheers.",
        "dude just chuck the green apple on the blue plate and the orange on the yellow plate, easy",
        "Two placements, that's all: the green apple on the blue plate and the orange on the yellow plate.",
        "Grocery list for the plates:\ngreen apple (blue plate)\norange (yellow plate)",
        "Our housekeeping team kindly asks that the green apple be set on the blue plate and the orange on "
        "the yellow plate.",
        "Put the green apple on the blue plate. Put the orange on the yellow plate. Those two placements, "
        "that's all."],
    2: ["Okay scouts, listen up! Green apple goes on the pink plate. Orange goes on the yellow plate. Red "
        "apple goes on the blue plate. Do them in any order you like.",
        "What is an order, really? Put the green apple on the pink plate, the orange on the yellow plate and "
        "the red apple on the blue plate, in any order.",
        "Is the green apple on the pink plate yet? No? Please put it there, and the orange on the yellow "
        "plate and the red apple on the blue plate too, any order.",
        "Exercise 3: place the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate. You may work in any order.",
        "green apple on the pink plate comma orange on the yellow plate comma red apple on the blue plate "
        "period any order period",
        "Put the green apple on the pink plate, then the orange on the yellow plate, and finally the red "
        "apple on the blue plate - honestly any order works."],
    3: ["Four placements, any order: carrot on the blue plate, orange on the yellow plate, green apple on "
        "the green plate, red apple on the pink plate.",
        "How are you feeling today? When you're ready, place the carrot on the blue plate, the orange on the "
        "yellow plate, the green apple on the green plate and the red apple on the pink plate, in any order.",
        "In a world where every plate has its fruit... the carrot takes the blue plate, the orange the "
        "yellow plate, the green apple the green plate, and the red apple the pink plate. Any order.",
        "Can I interest you in putting the carrot on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate? In any order, of course.",
        "+1 to the plan: carrot on the blue plate, orange on the yellow plate, green apple on the green "
        "plate, red apple on the pink plate. order doesn't matter",
        "Carrot on the blue plate, orange on the yellow plate, green apple on the green plate, red apple on "
        "the pink plate. Four placements in all, any order."],
    4: ["The yellow plate's two come before the blue plate's two: green apple and orange on the yellow "
        "plate, then carrot and red apple on the blue plate.",
        "Two for the yellow plate first (green apple, orange), then two for the blue plate (carrot, red "
        "apple).",
        "Step 1: yellow plate\n - green apple\n - orange\nStep 2: blue plate\n - carrot\n - red apple",
        "May I suggest starting with the green apple and the orange on the yellow plate, and only after "
        "that the carrot and the red apple on the blue plate?",
        "Is the yellow plate done? Then the blue plate. Yellow plate: green apple and orange. Blue plate: "
        "carrot and red apple.",
        "green apple and orange on the yellow plate first, carrot and red apple on the blue plate second"],
}

# Issue 28 (h94): a second development batch, written at once after the line-break rule and before any
# other h94 rule, in voices no batch uses (a Spanish speaker's "the plate blue", snake_case identifiers,
# unicode arrows and ticks, a support agent, a voice assistant's wake word, a tired parent, a quiz of
# yes/no questions, a tourist's phrasebook, a Reddit post, a teacher counting aloud).
DEV2_H94: dict[int, list[str]] = {
    1: ["Please put the green apple in the plate blue and the orange in the plate yellow.",
        "green_apple → blue_plate\norange → yellow_plate",
        "✔ green apple on blue plate ✔ orange on yellow plate",
        "Thanks for reaching out! To resolve this, kindly place the green apple on the blue plate and the "
        "orange on the yellow plate."],
    2: ["Hey Google, put the green apple on the pink plate, the orange on the yellow plate and the red apple "
        "on the blue plate, any order.",
        "ugh ok. green apple, pink plate. orange, yellow plate. red apple, blue plate. whatever order.",
        "Can the green apple go on the pink plate? Can the orange go on the yellow plate? Can the red apple "
        "go on the blue plate? Yes to all three, in any order.",
        "I would like: the green apple → pink plate, the orange → yellow plate, the red apple → blue plate. "
        "Order is not important, thank you."],
    3: ["TIL robots can do this: carrot on the blue plate, orange on the yellow plate, green apple on the "
        "green plate, red apple on the pink plate. Any order pls.",
        "One, the carrot on the blue plate; two, the orange on the yellow plate; three, the green apple on "
        "the green plate; four, the red apple on the pink plate. Any order!",
        "Put the carrot in the plate blue, the orange in the plate yellow, the green apple in the plate "
        "green and the red apple in the plate pink, the order is free.",
        "carrot/blue plate, orange/yellow plate, green apple/green plate, red apple/pink plate - no order"],
    4: ["First, green apple and orange → yellow plate. After, carrot and red apple → blue plate.",
        "Please, first you put the green apple and the orange in the plate yellow, and after you put the "
        "carrot and the red apple in the plate blue.",
        "Can you fill the yellow plate first with the green apple and the orange? Then fill the blue plate "
        "with the carrot and the red apple.",
        "ugh ok. yellow plate first: green apple, orange. blue plate after: carrot, red apple."],
}

# Issue 28 (h94): a third development batch, written at once after the rules for DEV_H94 and DEV2_H94 and
# measured before any rule for it, in voices no batch uses (a sommelier, a tired student, a museum
# placard, an IKEA-style pictogram legend, an air-traffic controller, a knitting pattern, a car's voice
# assistant, a camp counsellor, a baker, a lifeguard, a lawyer's letter, a podcast host).
DEV3_H94: dict[int, list[str]] = {
    1: ["For this pairing I'd suggest the green apple with the blue plate, and the orange with the yellow "
        "plate.",
        "cant think rn. green apple blue plate. orange yellow plate. ty",
        "Legend: green apple = blue plate, orange = yellow plate.",
        "Robot one, cleared to place the green apple on the blue plate and the orange on the yellow plate."],
    2: ["Row 1: green apple onto pink plate. Row 2: orange onto yellow plate. Row 3: red apple onto blue "
        "plate. Rows may be worked in any order.",
        "Okay campers! Green apple, you're on the pink plate. Orange, yellow plate. Red apple, blue plate. "
        "Go in any order!",
        "Could you put the green apple on the pink plate? And the orange on the yellow plate? And the red "
        "apple on the blue plate? Order doesn't matter.",
        "Further to our conversation, please arrange for the green apple to be placed on the pink plate, "
        "the orange on the yellow plate and the red apple on the blue plate, in no particular order."],
    3: ["Bake-off rules: carrot on the blue plate, orange on the yellow plate, green apple on the green "
        "plate, red apple on the pink plate. No set order.",
        "Navigate to: carrot - blue plate; orange - yellow plate; green apple - green plate; red apple - "
        "pink plate. Any order.",
        "Today's episode is brought to you by plates! Carrot on the blue plate, orange on the yellow plate, "
        "green apple on the green plate, red apple on the pink plate, in any order.",
        "Everyone out of the pool and onto their plates: carrot on blue, orange on yellow, green apple on "
        "green, red apple on pink. Whatever order."],
    4: ["Pattern: yellow plate (green apple, orange). Repeat with blue plate (carrot, red apple) once the "
        "yellow plate is complete.",
        "Green apple and orange on the yellow plate to start; carrot and red apple on the blue plate to "
        "finish.",
        "The yellow plate comes first with the green apple and the orange, and the blue plate comes second "
        "with the carrot and the red apple.",
        "First up: the green apple and the orange on the yellow plate. Next up: the carrot and the red apple "
        "on the blue plate."],
}

# Issue 28 (h94): a fourth development batch, written at once after every h94 rule and measured once
# before any rule for it (a check of how far the rules carry), in voices no batch uses (a crossword clue
# setter, a football coach's whiteboard, a nervous first-day intern, a dentist, a medieval scribe's list,
# a shopping app's push notification, a hiker's checklist, a stage whisper).
DEV4_H94: dict[int, list[str]] = {
    1: ["Um, sorry to bother you, I think the green apple should go on the blue plate? And the orange on "
        "the yellow plate, if that's okay.",
        "Whiteboard:\nGREEN APPLE -> BLUE PLATE\nORANGE -> YELLOW PLATE",
        "Item the first: the green apple upon the blue plate. Item the second: the orange upon the yellow "
        "plate.",
        "Reminder: green apple on the blue plate, orange on the yellow plate."],
    2: ["Open wide! Green apple on the pink plate, orange on the yellow plate, red apple on the blue plate, "
        "in any order.",
        "Packing list (any order):\n- green apple: pink plate\n- orange: yellow plate\n- red apple: blue "
        "plate",
        "psst... green apple, pink plate... orange, yellow plate... red apple, blue plate... any order...",
        "The green apple wants the pink plate, the orange wants the yellow plate, the red apple wants the "
        "blue plate; do them in any order."],
    3: ["Your order is ready to be plated: carrot on the blue plate, orange on the yellow plate, green "
        "apple on the green plate, red apple on the pink plate. Any order.",
        "Blue plate: carrot\nYellow plate: orange\nGreen plate: green apple\nPink plate: red apple\nOrder: "
        "any",
        "All four, any order: the carrot to the blue plate, the orange to the yellow plate, the green apple "
        "to the green plate and the red apple to the pink plate.",
        "Could I ask you to put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate? Whichever order suits."],
    4: ["Play one: green apple and orange to the yellow plate. Play two: carrot and red apple to the blue "
        "plate. Run them in that order.",
        "Um, first the green apple and the orange on the yellow plate, I think? Then the carrot and the red "
        "apple on the blue plate.",
        "Yellow plate\n- green apple\n- orange\nthen blue plate\n- carrot\n- red apple",
        "When the green apple and the orange are both on the yellow plate, the carrot and the red apple can "
        "go on the blue plate, either first."],
}

# h96's held-out batch: written and committed before any h96 rule, in voices no older batch uses (a game
# master, a telegram with STOP, a voice that gives the reason for each step, a greeting and sign-off, a
# hurried voice with ellipses, a shopping-list voice, a pirate).
VALID_H96: dict[int, list[str]] = {
    1: ["Quest for the brave robot: deliver the green apple to the blue plate and the orange to the yellow "
        "plate. Complete both to win!",
        "GREEN APPLE TO BLUE PLATE STOP ORANGE TO YELLOW PLATE STOP",
        "Put the green apple on the blue plate, because green and blue look nice together, and put the "
        "orange on the yellow plate, since they're both warm colours.",
        "Hi there! Please put the green apple on the blue plate and the orange on the yellow plate. Thanks "
        "so much, Sam",
        "quick... green apple on the blue plate... orange on the yellow one... go!",
        "Need on the table: blue plate with a green apple, yellow plate with an orange."],
    2: ["Your mission, should you choose to accept it: red apple to the blue plate, orange to the yellow "
        "plate, green apple to the pink plate. Tackle them in any order you like.",
        "PUT GREEN APPLE ON PINK PLATE STOP ORANGE ON YELLOW PLATE STOP RED APPLE ON BLUE PLATE STOP ANY "
        "ORDER STOP",
        "The green apple goes on the pink plate so the colours contrast, the orange on the yellow plate to "
        "match, and the red apple on the blue plate; the order doesn't matter since none of them depend on "
        "each other.",
        "Good morning! Could you place the green apple on the pink plate, the orange on the yellow plate "
        "and the red apple on the blue plate? Any order is fine. Cheers, Alex",
        "ok ok ok... red apple, blue plate... green apple, pink plate... orange, yellow plate... whatever "
        "order, just hurry",
        "Ahoy! Drop the green apple on the pink plate, the orange on the yellow plate and the red apple on "
        "the blue plate, any order ye please."],
    3: ["Level three, adventurer! Four treasures, four plates: the carrot goes to the blue plate, the "
        "orange to the yellow plate, the green apple to the green plate, the red apple to the pink plate. "
        "Any order wins.",
        "CARROT BLUE PLATE STOP ORANGE YELLOW PLATE STOP GREEN APPLE GREEN PLATE STOP RED APPLE PINK PLATE "
        "STOP ORDER UNIMPORTANT STOP",
        "Put the carrot on the blue plate so it stands out, the orange on the yellow plate so it blends in, "
        "the green apple on the green plate and the red apple on the pink plate for the same reason; do "
        "them in whatever order is easiest.",
        "Hey robot, hope you're well! The carrot should go on the blue plate, the orange on the yellow "
        "plate, the green apple on the green plate and the red apple on the pink plate, in no special "
        "order. Thanks a bunch!",
        "carrot... blue plate. orange... yellow plate. green apple... green plate. red apple... pink plate. "
        "any order, quick!",
        "Blue plate: 1 carrot. Yellow plate: 1 orange. Green plate: 1 green apple. Pink plate: 1 red apple. "
        "Any order."],
    4: ["Round one: bring the green apple and the orange to the yellow plate. Round two, which unlocks "
        "after round one: the carrot and the red apple to the blue plate.",
        "GREEN APPLE AND ORANGE TO YELLOW PLATE FIRST STOP THEN CARROT AND RED APPLE TO BLUE PLATE STOP",
        "Put the green apple and the orange on the yellow plate first, because the blue plate is still "
        "being cleaned; after that, put the carrot and the red apple on the blue plate.",
        "Hello! First, please put the green apple and the orange on the yellow plate. When that's done, put "
        "the carrot and the red apple on the blue plate. Many thanks, Jo",
        "yellow plate first... green apple, orange... then blue plate... carrot, red apple... thanks!!",
        "Arr, first stow the green apple and the orange on the yellow plate, matey, then the carrot and the "
        "red apple on the blue plate!"],
}

# h96's development batches: written for developing the rules and read per sentence.
DEV_H96: dict[int, list[str]] = {
    1: ["Objective unlocked: green apple onto the blue plate, orange onto the yellow plate. Good luck!",
        "BLUE PLATE GREEN APPLE STOP YELLOW PLATE ORANGE STOP THANKS STOP",
        "Dear robot, kindly put the green apple on the blue plate and the orange on the yellow plate. Best "
        "regards, Mia",
        "hmm... the green apple on the blue plate... and the orange... on the yellow plate, yeah",
        "Put the orange on the yellow plate because it matches, and the green apple on the blue plate "
        "because there's room there."],
    2: ["Hi! The orange goes on the yellow plate, the red apple on the blue plate and the green apple on "
        "the pink plate, any order. Thanks, Lee",
        "RED APPLE BLUE PLATE STOP GREEN APPLE PINK PLATE STOP ORANGE YELLOW PLATE STOP",
        "Shopping list for the plates: pink plate - green apple, yellow plate - orange, blue plate - red "
        "apple. Any order.",
        "right... orange, yellow plate... red apple, blue plate... green apple, pink plate... in any order",
        "Avast! The red apple to the blue plate, the orange to the yellow plate and the green apple to the "
        "pink plate, in any order, me hearty."],
    3: ["Greetings, traveller! Place the carrot on the blue plate, the orange on the yellow plate, the "
        "green apple on the green plate and the red apple on the pink plate, in any order. Farewell!",
        "CARROT TO BLUE PLATE STOP ORANGE TO YELLOW PLATE STOP GREEN APPLE TO GREEN PLATE STOP RED APPLE "
        "TO PINK PLATE STOP",
        "The carrot goes on the blue plate, the orange on the yellow plate, the green apple on the green "
        "plate, and the red apple on the pink plate, each to its own colour so it's easy to check; the "
        "order doesn't matter.",
        "quick quick... carrot blue plate... orange yellow plate... green apple green plate... red apple "
        "pink plate... any order"],
    4: ["Hey! Start with the green apple and the orange on the yellow plate. When that's done, the carrot "
        "and the red apple on the blue plate. Thanks, Kim",
        "YELLOW PLATE FIRST GREEN APPLE AND ORANGE STOP BLUE PLATE NEXT CARROT AND RED APPLE STOP",
        "First put the green apple and the orange on the yellow plate, since those are needed first; then "
        "put the carrot and the red apple on the blue plate.",
        "Chapter one: the green apple and the orange on the yellow plate. Chapter two, only after chapter "
        "one: the carrot and the red apple on the blue plate.",
        "ok... green apple and orange on the yellow plate first... then carrot and red apple on the blue "
        "plate... go go go"],
}

# written after the rules for DEV_H96 and measured before any rule for it (how far those rules carry)
DEV2_H96: dict[int, list[str]] = {
    1: ["Ladies and gentlemen, the green apple will now be placed on the blue plate and the orange on the "
        "yellow plate. Thank you for flying with us.",
        "Voicemail: hey it's me, um, could you pop the green apple on the blue plate and the orange on the "
        "yellow plate, okay, talk soon, bye",
        "The robot shall place the green apple on the blue plate and the orange on the yellow plate.",
        "green apple -> blue plate 🍏 orange -> yellow plate 🍊 thx!!"],
    2: ["Alright team, huddle up! Green apple to the pink plate, orange to the yellow plate, red apple to "
        "the blue plate. Any order, let's go!",
        "To whom it may concern: please place the green apple on the pink plate, the orange on the yellow "
        "plate and the red apple on the blue plate, in any order. Yours faithfully, the kitchen",
        "Three little jobs, dear: the green apple on the pink plate, the orange on the yellow plate, the red "
        "apple on the blue plate. Whatever order, love. Gran x",
        "#tidy green apple on pink plate, orange on yellow plate, red apple on blue plate #anyorder"],
    3: ["Attention please: carrot to the blue plate, orange to the yellow plate, green apple to the green "
        "plate and red apple to the pink plate. The order is up to you. Thank you.",
        "So, like, the carrot goes on the blue plate, and the orange on the yellow plate, and the green "
        "apple on the green plate, and the red apple on the pink plate, whatever order, it's fine.",
        "The robot shall place the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate, in any order.",
        "Coach here. Carrot, blue plate. Orange, yellow plate. Green apple, green plate. Red apple, pink "
        "plate. Any order. Go!"],
    4: ["Alright team: the green apple and the orange go on the yellow plate first. Then the carrot and the "
        "red apple on the blue plate. Let's go!",
        "Dear robot, first the green apple and the orange onto the yellow plate, please; afterwards the "
        "carrot and the red apple onto the blue plate. Yours, Pat",
        "The robot shall first place the green apple and the orange on the yellow plate and shall then "
        "place the carrot and the red apple on the blue plate.",
        "ugh fine... green apple and orange on the yellow plate first... then carrot and red apple on the "
        "blue plate... happy now?"],
}

# written after the rules for DEV_H96 and DEV2_H96 and measured before any rule for it
DEV3_H96: dict[int, list[str]] = {
    1: ["Protocol: transfer the green apple to the blue plate; transfer the orange to the yellow plate. End "
        "of protocol.",
        "Dear diary, today I asked the robot to put the green apple on the blue plate and the orange on the "
        "yellow plate.",
        "Listen up, soldier! Green apple on the blue plate! Orange on the yellow plate! Move it!",
        "Once upon a time the green apple went to the blue plate and the orange went to the yellow plate. "
        "The end."],
    2: ["Thanks for calling! Today we'll be placing the green apple on the pink plate, the orange on the "
        "yellow plate and the red apple on the blue plate, in any order. Have a nice day!",
        "Forecast: green apple on the pink plate, orange on the yellow plate, red apple on the blue plate, "
        "order unimportant.",
        "I reckon the green apple suits the pink plate, the orange the yellow plate and the red apple the "
        "blue plate, so put them there, any order.",
        "Right, I'm off to work. Put the green apple on the pink plate, the orange on the yellow plate and "
        "the red apple on the blue plate, any order. See you later!"],
    3: ["Lab steps (order not important): carrot to blue plate; orange to yellow plate; green apple to "
        "green plate; red apple to pink plate.",
        "It's a big day, so put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate, in any order.",
        "My friend, the carrot belongs on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate. Do them in any order.",
        "CARROT > BLUE PLATE STOP ORANGE > YELLOW PLATE STOP GREEN APPLE > GREEN PLATE STOP RED APPLE > PINK "
        "PLATE STOP ANY ORDER STOP"],
    4: ["Listen up, soldier! Green apple and orange on the yellow plate first! Then carrot and red apple on "
        "the blue plate! Move it!",
        "Protocol: step one, the green apple and the orange to the yellow plate; step two, the carrot and "
        "the red apple to the blue plate.",
        "Right, I'm off. Green apple and orange on the yellow plate first, then carrot and red apple on the "
        "blue plate. See you tonight!",
        "It's a big day... green apple and orange on the yellow plate... then carrot and red apple on the "
        "blue plate... that's all, thanks!"],
}

# written after every rule above, in VALID_H96's voices (new sentences), measured before any rule for it
DEV4_H96: dict[int, list[str]] = {
    1: ["New quest! Carry the green apple to the blue plate and the orange to the yellow plate, brave robot.",
        "ORANGE ON YELLOW PLATE STOP GREEN APPLE ON BLUE PLATE STOP",
        "Put the orange on the yellow plate, since it's the same colour, and the green apple on the blue "
        "plate.",
        "Hello robot! Place the green apple on the blue plate and the orange on the yellow plate. Kind "
        "regards, Tom",
        "hurry... orange, yellow plate... green apple, blue plate... done!",
        "Today's list: green apple for the blue plate, orange for the yellow plate."],
    2: ["Side quest: red apple to the blue plate, green apple to the pink plate, orange to the yellow plate. "
        "Any order, hero.",
        "GREEN APPLE PINK PLATE STOP RED APPLE BLUE PLATE STOP ORANGE YELLOW PLATE STOP ANY ORDER STOP",
        "The orange goes on the yellow plate because it's yellow too, the red apple on the blue plate and "
        "the green apple on the pink plate, in any order.",
        "Hiya! Green apple on the pink plate, orange on the yellow plate, red apple on the blue plate, any "
        "order. Ta, Jess",
        "no time... green apple pink plate... orange yellow plate... red apple blue plate... any order",
        "Yo ho! The orange on the yellow plate, the red apple on the blue plate, the green apple on the pink "
        "plate, any order, savvy?"],
    3: ["Boss fight! Carrot to the blue plate, orange to the yellow plate, green apple to the green plate, "
        "red apple to the pink plate, any order. Go, hero!",
        "RED APPLE TO PINK PLATE STOP CARROT TO BLUE PLATE STOP ORANGE TO YELLOW PLATE STOP GREEN APPLE TO "
        "GREEN PLATE STOP",
        "Put the green apple on the green plate since they match, the carrot on the blue plate, the orange "
        "on the yellow plate and the red apple on the pink plate, in any order.",
        "Morning! Carrot on the blue plate, orange on the yellow plate, green apple on the green plate, red "
        "apple on the pink plate, whichever order. Cheers, Ben",
        "fast... carrot on the blue plate... orange on the yellow plate... green apple on the green "
        "plate... red apple on the pink plate... any order",
        "Shopping list for the plates: blue plate - carrot, yellow plate - orange, green plate - green "
        "apple, pink plate - red apple. Any order."],
    4: ["Level one: the green apple and the orange on the yellow plate. Level two: the carrot and the red "
        "apple on the blue plate. Good luck, hero!",
        "FIRST GREEN APPLE AND ORANGE ON YELLOW PLATE STOP AFTER THAT CARROT AND RED APPLE ON BLUE PLATE "
        "STOP",
        "First the green apple and the orange on the yellow plate, because they're for now, then the "
        "carrot and the red apple on the blue plate.",
        "Hi! First the green apple and the orange on the yellow plate, then the carrot and the red apple on "
        "the blue plate. Thanks, Lou",
        "quick quick... green apple and orange on the yellow plate... after that... carrot and red apple on "
        "the blue plate...",
        "Ahoy! First, the green apple and the orange on the yellow plate, then the carrot and the red apple "
        "on the blue plate, me hearties!"],
}

# h99's held-out batch: written at the same time as DEV_H99 and committed before any h99 rule, in voices no
# older batch uses (a Gherkin test scenario, a user story, a ticket with labelled fields such as "Goal -" and
# "Condition -", a chat log with names and times, typing with typos and abbreviations, a record of labelled
# fields, a robot-and-user dialogue, the order said by ordinals, a correction with "sorry, I mean").
# Measured on first contact and at the end without --per-sentence; never read per sentence between.
VALID_H99: dict[int, list[str]] = {
    1: ["Scenario: fruit sorting. When the robot is done, the green apple is on the blue plate and the "
        "orange is on the yellow plate.",
        "As a busy parent, I want the orange on the yellow plate and the green apple on the blue plate so "
        "that the kids can grab them.",
        "Goal - the green apple on the blue plate and the orange on the yellow plate\nCondition - n/a",
        "[18:40] Priya: could you put the orange on the yellow plate\n[18:41] Priya: oh and the green apple "
        "on the blue one",
        "plz put the grren apple on the blue plate & the orange on the yelow plate ty",
        "Object: orange. Destination: yellow plate.\nObject: green apple. Destination: blue plate."],
    2: ["Scenario: three plates\nWhen the robot tidies the table\nThen the orange is on the yellow plate\n"
        "And the red apple is on the blue plate\nAnd the green apple is on the pink plate",
        "As a guest I'd like the green apple on the pink plate, the red apple on the blue plate and the "
        "orange on the yellow plate; any order works for me.",
        "Goal - red apple on the blue plate, orange on the yellow plate, green apple on the pink plate.\n"
        "Condition - none. Order - whatever.",
        "Robot: What shall I do?\nUser: Put the green apple on the pink plate, the orange on the yellow "
        "plate and the red apple on the blue plate.\nRobot: Any particular order?\nUser: No.",
        "put the green apple on the yellow plate - sorry, I mean the pink plate - the orange on the yellow "
        "plate and the red apple on the blue plate, in any order",
        "put the orange on the yelow plate, the red aple on the blue plate and the green apple on the pinc "
        "plate, any order"],
    3: ["Item: red apple | Plate: pink\nItem: carrot | Plate: blue\nItem: green apple | Plate: green\nItem: "
        "orange | Plate: yellow\nOrder: none",
        "As the person who sets the table, I want the carrot on the blue plate, the orange on the yellow "
        "plate, the green apple on the green plate and the red apple on the pink plate, in no particular "
        "order.",
        "[07:55] Leo: carrot -> blue plate\n[07:55] Leo: orange -> yellow plate\n[07:56] Leo: green apple -> "
        "green plate\n[07:56] Leo: red apple -> pink plate\n[07:56] Leo: any order",
        "Then the carrot must be on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, whatever the order.",
        "Goal: carrot on blue, orange on yellow, green apple on green, red apple on pink.\nConditions: "
        "none.\nPriority: normal.",
        "Put the carrot on the plate that is blue, the orange on the plate that is yellow, the green apple "
        "on the green one and the red apple on the pink one, in any order."],
    4: ["The first job is to put the green apple and the orange on the yellow plate. The second job, after "
        "the first one, is to put the carrot and the red apple on the blue plate.",
        "Step 1 - the green apple and the orange on the yellow plate\nStep 2 - the carrot and the red apple "
        "on the blue plate\nCondition - step 2 only after step 1",
        "Scenario: two rounds. When the green apple and the orange are on the yellow plate, then the robot "
        "puts the carrot and the red apple on the blue plate.",
        "[12:01] Mo: green apple and orange on the yellow plate first\n[12:02] Mo: after that carrot and red "
        "apple on the blue plate",
        "put the green apple and orange on the yelow plate frist, than the carrot and red apple on the blue "
        "plate",
        "Robot: Where do I start?\nUser: With the green apple and the orange on the yellow plate.\nRobot: "
        "And then?\nUser: Then the carrot and the red apple on the blue plate."],
}

# h99's development batch: written at the same time as VALID_H99, in its voices, for developing the rules
# (read per sentence).
DEV_H99: dict[int, list[str]] = {
    1: ["Scenario: tidy the table. Given the robot is at its start, when I say go, then the green apple is "
        "on the blue plate and the orange is on the yellow plate.",
        "As a hungry user, I want the green apple on the blue plate and the orange on the yellow plate, so "
        "that I can find them.",
        "Goal - put the green apple on the blue plate and the orange on the yellow plate. Condition - none.",
        "[09:14] Dana: hey can u put the green apple on the blue plate\n[09:14] Dana: and the orange on the "
        "yellow one pls",
        "pls put teh green aple on the blu plate and the orange on the yelow plate thx",
        "Object: green apple. Target: blue plate.\nObject: orange. Target: yellow plate."],
    2: ["Given three fruits and three plates\nWhen the robot tidies up\nThen the green apple is on the pink "
        "plate\nAnd the orange is on the yellow plate\nAnd the red apple is on the blue plate\nIn any order",
        "As a host I want the red apple on the blue plate, the orange on the yellow plate and the green "
        "apple on the pink plate. Order is not important to me.",
        "Goal - place the green apple on the pink plate, the orange on the yellow plate and the red apple on "
        "the blue plate\nOrder - any\nDeadline - none",
        "Robot: What do you need?\nMe: The green apple on the pink plate, the orange on the yellow plate and "
        "the red apple on the blue plate.\nRobot: In which order?\nMe: Doesn't matter.",
        "Put the green apple on the blue plate, sorry, I mean the pink plate, the orange on the yellow plate "
        "and the red apple on the blue plate, any order.",
        "put the red appel on the blue plate, the orange on the yelow plate and the grean apple on the pink "
        "plate, any order"],
    3: ["Item: carrot | Plate: blue\nItem: orange | Plate: yellow\nItem: green apple | Plate: green\nItem: "
        "red apple | Plate: pink\nOrder: any",
        "As a tidy person, I'd like the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate and the red apple on the pink plate, in any order, so that the table "
        "looks neat.",
        "Sam: carrot on the blue plate\nSam: orange on the yellow plate\nSam: green apple on the green "
        "plate\nSam: red apple on the pink plate\nSam: any order is fine",
        "Then the carrot should be on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, regardless of order.",
        "Goal: carrot to the blue plate, orange to the yellow plate, green apple to the green plate, red "
        "apple to the pink plate. Constraints: none. Priority: low.",
        "Put the carrot on the plate that's blue, the orange on the plate that's yellow, the green apple on "
        "the green one and the red apple on the pink one, any order."],
    4: ["The first thing to do is put the green apple and the orange on the yellow plate. The second thing, "
        "once that's done, is to put the carrot and the red apple on the blue plate.",
        "Step 1 - green apple and orange on the yellow plate\nStep 2 - carrot and red apple on the blue "
        "plate\nCondition - step 2 only after step 1",
        "Scenario: two rounds. When the robot has put the green apple and the orange on the yellow plate, "
        "then it puts the carrot and the red apple on the blue plate.",
        "[10:02] Kai: first the green apple and the orange on the yellow plate\n[10:03] Kai: after that the "
        "carrot and the red apple go on the blue plate",
        "frist put the green apple and orange on the yelow plate, than the carrot and red apple on the blue "
        "plate",
        "As the chef, I want the green apple and the orange on the yellow plate before anything goes on the "
        "blue plate, and then the carrot and the red apple on the blue plate."],
}

# h99's second development batch, written after the rules for DEV_H99 and measured before any rule for it,
# in voices no batch uses (dictation with spoken punctuation, Markdown headings and bold, a commit message, a
# checklist with emoji numbers, a voice assistant addressed by name, "X's for the Y plate").
DEV2_H99: dict[int, list[str]] = {
    1: ["put the green apple on the blue plate comma and the orange on the yellow plate period",
        "## Todo\n- **green apple** → *blue plate*\n- **orange** → *yellow plate*",
        "feat: move green apple to blue plate and orange to yellow plate",
        "The green apple's for the blue plate and the orange's for the yellow plate."],
    2: ["pls:\n1️⃣ green apple ➡️ pink plate\n2️⃣ orange ➡️ yellow plate\n3️⃣ red apple ➡️ blue plate\norder "
        "doesn't matter",
        "Put the green apple on the pink plate comma the orange on the yellow plate comma and the red apple "
        "on the blue plate period any order period",
        "## Plates\n**Pink:** green apple\n**Yellow:** orange\n**Blue:** red apple",
        "chore: sort fruit (green apple -> pink plate, orange -> yellow plate, red apple -> blue plate), any "
        "order"],
    3: ["Siri, put the carrot on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate in any order",
        "- [ ] carrot: blue plate\n- [ ] orange: yellow plate\n- [ ] green apple: green plate\n- [ ] red "
        "apple: pink plate\n(any order)",
        "The carrot's for the blue plate, the orange's for the yellow plate, the green apple's for the green "
        "plate and the red apple's for the pink plate; no particular order.",
        "carrot on blue plate, orange on yellow plate, green apple on green plate, red apple on pink plate - "
        "each one independent of the others"],
    4: ["### Phase A\ngreen apple + orange → yellow plate\n### Phase B (after A)\ncarrot + red apple → blue "
        "plate",
        "put the green apple and the orange on the yellow plate period once that's done put the carrot and "
        "the red apple on the blue plate period",
        "Please do the yellow plate before the blue one: green apple and orange on yellow, carrot and red "
        "apple on blue.",
        "Green apple and orange go on the yellow plate. Don't start on the blue plate (carrot and red apple) "
        "until then."],
}

# h104's held-out batch: written at the same time as DEV_H104 and committed before any h104 rule, in voices
# no older batch uses (a table of delimited values with a header row, "is to be" duties, "it would be great
# if you could", a collective noun that names the things listed after "as follows", labelled fields one per
# line, "don't start ... until then", Markdown parts). Measured on first contact and at the end only.
VALID_H104: dict[int, list[str]] = {
    1: ["food;plate\norange;yellow\ngreen apple;blue",
        "The orange is to be set on the yellow plate, and the green apple is to be set on the blue plate.",
        "It would be great if you could put the orange on the yellow plate and the green apple on the blue "
        "plate.",
        "Please arrange the fruit as follows: orange on the yellow plate, green apple on the blue plate."],
    2: ["Item: red apple\nPlate: blue plate\n\nItem: green apple\nPlate: pink plate\n\nItem: orange\nPlate: "
        "yellow plate",
        "The green apple is to be on the pink plate, the red apple on the blue plate and the orange on the "
        "yellow plate, in whatever order.",
        "Place the fruit as follows: red apple in the blue plate, green apple in the pink plate, orange in "
        "the yellow plate. Any order.",
        "fruit | plate\ngreen apple | pink\norange | yellow\nred apple | blue"],
    3: ["If you could put the carrot on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate, in any order, that would be great.",
        "Object: carrot\nDestination: blue plate\nObject: orange\nDestination: yellow plate\nObject: green "
        "apple\nDestination: green plate\nObject: red apple\nDestination: pink plate",
        "Put the food as follows: the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate, the red apple on the pink plate.",
        "The red apple is to be placed on the pink plate, the green apple on the green plate, the orange on "
        "the yellow plate and the carrot on the blue plate."],
    4: ["Put the green apple and the orange on the yellow plate. Do not start putting the carrot and the red "
        "apple on the blue plate until then.",
        "### Part 1\ngreen apple and orange on the yellow plate\n### Part 2 (after part 1)\ncarrot and red "
        "apple on the blue plate",
        "It would be great if you could first put the green apple and the orange on the yellow plate, and "
        "after that the carrot and the red apple on the blue plate.",
        "The green apple and the orange are to be placed on the yellow plate; once they are, the carrot and "
        "the red apple are to be placed on the blue plate."],
}

# h104's development batch: written at the same time as VALID_H104, in its voices, read per sentence.
DEV_H104: dict[int, list[str]] = {
    1: ["fruit,plate\ngreen apple,blue\norange,yellow",
        "The green apple is to be placed on the blue plate and the orange is to be placed on the yellow "
        "plate.",
        "If you could put the green apple on the blue plate and the orange on the yellow plate, that would "
        "be great.",
        "Sort the fruit as follows: the green apple onto the blue plate, the orange onto the yellow plate."],
    2: ["object,destination\ngreen apple,pink plate\norange,yellow plate\nred apple,blue plate\n(any order)",
        "The red apple is to go on the blue plate, the orange is to go on the yellow plate and the green "
        "apple is to go on the pink plate; the order is not important.",
        "If you could get the green apple onto the pink plate, the orange onto the yellow plate and the red "
        "apple onto the blue plate in any order, that would be lovely.",
        "Object: green apple\nTarget: pink plate\n\nObject: orange\nTarget: yellow plate\n\nObject: red "
        "apple\nTarget: blue plate\n\nOrder: any"],
    3: ["Arrange the food as follows, in any order: carrot on the blue plate, orange on the yellow plate, "
        "green apple on the green plate, red apple on the pink plate.",
        "item,plate\ncarrot,blue\norange,yellow\ngreen apple,green\nred apple,pink",
        "The carrot is to be put on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, in no set order.",
        "Thing: carrot. Where: blue plate.\nThing: orange. Where: yellow plate.\nThing: green apple. Where: "
        "green plate.\nThing: red apple. Where: pink plate."],
    4: ["Put the green apple and the orange on the yellow plate. Don't put the carrot and the red apple on "
        "the blue plate until then.",
        "If you could do the green apple and the orange on the yellow plate first and then the carrot and "
        "the red apple on the blue plate, that would be great.",
        "### Step A\nthe green apple and the orange on the yellow plate\n### Step B (after A)\nthe carrot "
        "and the red apple on the blue plate",
        "The green apple and the orange are to be placed on the yellow plate first; only then are the carrot "
        "and the red apple to be placed on the blue plate."],
}

# h106's held-out batch: written at the same time as DEV_H106 and committed before any h106 rule, in the
# four classes the lead's held-out set left refused (a methods-section passive with "respectively", a
# "Method:" recipe with numbered or labelled steps, "each item is to be placed on its plate: ..." with a
# freedom said as "arbitrary" or "whatever is easiest", a support agent's "Sure!" / "Of course!" voice).
# Measured on first contact and at the end only; never read per sentence between.
VALID_H106: dict[int, list[str]] = {
    1: ["The green apple and the orange are to be set on the blue and yellow plates respectively.",
        "Method:\n1. Place the orange onto the yellow plate.\n2. Place the green apple onto the blue plate.\n"
        "The two steps may be done in either order.",
        "Each fruit is to be placed on its plate: the orange on the yellow one and the green apple on the "
        "blue one, in arbitrary order.",
        "Sure thing! Please put the orange on the yellow plate and the green apple on the blue plate."],
    2: ["The red apple, the green apple and the orange are to be placed on the blue, pink and yellow plates "
        "respectively, in any order.",
        "Method (order free): green apple onto pink plate, red apple onto blue plate, orange onto yellow "
        "plate.",
        "Every fruit is to go on its own plate: the green apple on the pink one, the orange on the yellow "
        "one and the red apple on the blue one, in whatever order is simplest.",
        "Of course! Please place the red apple on the blue plate, the orange on the yellow plate and the "
        "green apple on the pink plate, in any order you find convenient."],
    3: ["The carrot, the orange, the green apple and the red apple should be placed on the blue, yellow, "
        "green and pink plates respectively; the order is not prescribed.",
        "Method:\nStep 1 - carrot onto the blue plate.\nStep 2 - orange onto the yellow plate.\nStep 3 - "
        "green apple onto the green plate.\nStep 4 - red apple onto the pink plate.\nThese steps may be "
        "carried out in any order.",
        "Each item is to be placed on its plate, in arbitrary order: the red apple on the pink one, the "
        "carrot on the blue one, the green apple on the green one and the orange on the yellow one.",
        "Absolutely! Just put the carrot on the blue plate, the orange on the yellow plate, the green apple "
        "on the green plate and the red apple on the pink plate, whichever order is easiest for you."],
    4: ["The green apple and the orange are first to be placed on the yellow plate, after which the carrot "
        "and the red apple are to be placed on the blue plate.",
        "Method: Step 1 - the green apple and the orange onto the yellow plate (any order). Step 2 - the "
        "carrot and the red apple onto the blue plate (any order).",
        "Each item is to be placed on its plate: first the green apple and the orange on the yellow one, and "
        "only after those two the carrot and the red apple on the blue one.",
        "No problem! Please begin with the orange and the green apple on the yellow plate, and when both are "
        "on it, move the red apple and the carrot to the blue plate."],
}

# h106's development batch: written at the same time as VALID_H106, in its four classes, read per sentence.
DEV_H106: dict[int, list[str]] = {
    1: ["The green apple and the orange are to be placed on the blue and yellow plates respectively, in no "
        "prescribed order.",
        "Method: 1. Green apple onto the blue plate. 2. Orange onto the yellow plate. Either step may come "
        "first.",
        "Method (any order): orange on yellow plate, green apple on blue plate.",
        "Each item is to be placed on its plate: the green apple on the blue one, the orange on the yellow "
        "one.",
        "Sure! Put the green apple on the blue plate and the orange on the yellow plate.",
        "No problem! Please place the orange on the yellow plate and the green apple on the blue plate, in "
        "arbitrary order."],
    2: ["The green apple, the orange and the red apple are to be placed on the pink, yellow and blue plates "
        "respectively, in no prescribed order.",
        "Method: Step 1 - red apple onto the blue plate. Step 2 - green apple onto the pink plate. Step 3 - "
        "orange onto the yellow plate. The steps may be done in any order.",
        "Each item is to be placed on its plate: the green apple on the pink one, the orange on the yellow "
        "one, the red apple on the blue one, in whatever order is easiest.",
        "Of course! Please put the orange on the yellow plate, the green apple on the pink plate and the red "
        "apple on the blue plate, in any order.",
        "Method (any order): green apple on pink plate, orange on yellow plate, red apple on blue plate.",
        "The orange, the red apple and the green apple were placed on the yellow, blue and pink plates, "
        "respectively, in arbitrary order."],
    3: ["The carrot, the orange, the green apple and the red apple are to be placed on the blue, yellow, "
        "green and pink plates respectively, in no prescribed order.",
        "Method (any order): carrot on blue plate, orange on yellow plate, green apple on green plate, red "
        "apple on pink plate.",
        "Method: 1. Carrot onto the blue plate. 2. Orange onto the yellow plate. 3. Green apple onto the "
        "green plate. 4. Red apple onto the pink plate. Any step may come first.",
        "Each item is to be placed on its plate in arbitrary order: the carrot on the blue one, the orange "
        "on the yellow one, the green apple on the green one and the red apple on the pink one.",
        "Sure! Just place the red apple on the pink plate, the green apple on the green plate, the orange on "
        "the yellow plate and the carrot on the blue plate, in whatever order is easiest.",
        "No problem! The carrot goes on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate; any order works."],
    4: ["Method: Step 1 - the green apple and the orange onto the yellow plate (any order). Step 2 - the "
        "carrot and the red apple onto the blue plate (any order).",
        "Of course! Please start with the green apple and the orange on the yellow plate, and once both are "
        "there, put the carrot and the red apple on the blue plate.",
        "The green apple and the orange are to be placed on the yellow plate first, and the carrot and the "
        "red apple on the blue plate after them.",
        "Method: 1. Green apple and orange onto the yellow plate. 2. Carrot and red apple onto the blue "
        "plate.",
        "Sure! First the orange and the green apple go on the yellow plate, then the red apple and the "
        "carrot go on the blue plate.",
        "Each item is to be placed on its plate: first the green apple and the orange on the yellow one, "
        "then the carrot and the red apple on the blue one."],
}

# h106's second development batch: written after the rules for DEV_H106 and measured before any rule for it
# (how far those rules carry), in the same four classes with other words.
DEV2_H106: dict[int, list[str]] = {
    1: ["The orange and the green apple go to the yellow and blue plates, respectively.",
        "Method:\n- orange onto the yellow plate\n- green apple onto the blue plate\n(steps in any order)",
        "All items are to be placed on their respective plates: the green apple on the blue one and the "
        "orange on the yellow one.",
        "Certainly! Could you put the green apple on the blue plate and the orange on the yellow plate?"],
    2: ["Place the green apple, the orange and the red apple onto the pink, yellow and blue plates "
        "respectively.",
        "Method: 1) red apple onto the blue plate; 2) orange onto the yellow plate; 3) green apple onto the "
        "pink plate. The order of the steps is arbitrary.",
        "Every item goes on its own plate, in whatever order is most convenient: the orange on the yellow "
        "one, the red apple on the blue one and the green apple on the pink one.",
        "Happy to help! Put the red apple on the blue plate, the green apple on the pink plate and the "
        "orange on the yellow plate, in an arbitrary order."],
    3: ["The red apple, the green apple, the orange and the carrot must be put onto the pink, green, yellow "
        "and blue plates respectively, order not prescribed.",
        "Method (steps may be performed in any order): carrot onto blue plate; orange onto yellow plate; "
        "green apple onto green plate; red apple onto pink plate.",
        "Each object is to be placed on its plate in any sequence: the orange on the yellow one, the carrot "
        "on the blue one, the red apple on the pink one, the green apple on the green one.",
        "No worries! The red apple on the pink plate, the carrot on the blue plate, the orange on the "
        "yellow plate and the green apple on the green plate, whichever order is easiest."],
    4: ["The green apple and the orange are to be placed on the yellow plate; only after that are the "
        "carrot and the red apple to be placed on the blue plate.",
        "Method:\nStep 1 - green apple and orange onto the yellow plate (either order).\nStep 2 - carrot and "
        "red apple onto the blue plate (either order).",
        "Each item is to be placed on its plate: the green apple and the orange on the yellow one first, and "
        "the carrot and the red apple on the blue one after them.",
        "Of course! Start by putting the green apple and the orange on the yellow plate. Once both are "
        "there, put the carrot and the red apple on the blue plate."],
}

# h106's third development batch: written after the rules for DEV2_H106 and measured before any rule for it,
# in the same four classes with more variation (a methods section's "were to be", a recipe with lettered
# steps, "its designated plate", an agent's longer reply).
DEV3_H106: dict[int, list[str]] = {
    1: ["The green apple and the orange were to be placed on the blue and yellow plates respectively.",
        "Method: a) green apple onto blue plate; b) orange onto yellow plate. Steps a and b may be done in "
        "either order.",
        "Each item is to be placed on its designated plate: green apple - blue plate, orange - yellow plate.",
        "Sure, happy to help! Just put the orange on the yellow plate and the green apple on the blue "
        "plate."],
    2: ["The green apple, the orange and the red apple are to be transferred to the pink, yellow and blue "
        "plates respectively; no order is prescribed.",
        "Method (in no particular order):\n1. Red apple onto the blue plate.\n2. Orange onto the yellow "
        "plate.\n3. Green apple onto the pink plate.",
        "Each of the three fruits is to be placed on its plate, in arbitrary order: the green apple on the "
        "pink one, the orange on the yellow one, the red apple on the blue one.",
        "No problem at all! The green apple goes on the pink plate, the red apple on the blue plate and the "
        "orange on the yellow plate. Any order is fine."],
    3: ["The carrot, the orange, the green apple and the red apple are respectively to be placed on the "
        "blue, yellow, green and pink plates, in arbitrary order.",
        "Method: Step 1 - carrot onto the blue plate. Step 2 - orange onto the yellow plate. Step 3 - green "
        "apple onto the green plate. Step 4 - red apple onto the pink plate. The steps may be carried out "
        "in any order.",
        "Each item is to be placed on its own plate in whatever order is easiest: the carrot on the blue "
        "plate, the orange on the yellow plate, the green apple on the green plate and the red apple on "
        "the pink plate.",
        "Of course! Please put the carrot on the blue plate, the orange on the yellow plate, the green apple "
        "on the green plate and the red apple on the pink plate, in whatever order works for you."],
    4: ["The green apple and the orange are to be placed on the yellow plate, and only then the carrot and "
        "the red apple on the blue plate.",
        "Method: Step 1 - green apple and orange onto the yellow plate. Step 2 - carrot and red apple onto "
        "the blue plate.",
        "Each item is to be placed on its plate: the green apple and the orange on the yellow plate before "
        "the carrot and the red apple on the blue plate.",
        "Absolutely! First, please put the orange and the green apple on the yellow plate; once they are "
        "both there, put the red apple and the carrot on the blue plate."],
}

# h106's fourth development batch: written after every rule above and measured before any rule for it, in
# the same four classes said by other voices (a lab notebook's "were placed" asked as a duty, a recipe card's
# "Method" with its steps on lines, a form's "its matching plate", a chat agent's longer answer).
DEV4_H106: dict[int, list[str]] = {
    1: ["Procedure: the green apple and the orange are to be placed onto the blue and the yellow plate, "
        "respectively.",
        "Method\n1. Green apple onto the blue plate.\n2. Orange onto the yellow plate.\nDo the steps in "
        "any order.",
        "Each fruit should be put on its matching plate: the green apple on the blue plate and the orange on "
        "the yellow plate.",
        "Sure, no problem! Please pop the green apple on the blue plate and the orange on the yellow plate."],
    2: ["Respectively, the green apple, the orange and the red apple go on the pink, yellow and blue plates.",
        "Method (any order):\n- green apple on pink plate\n- orange on yellow plate\n- red apple on blue "
        "plate",
        "Each item is to be placed on its plate, in whatever order is easiest for you: the green apple on "
        "the pink plate, the orange on the yellow plate and the red apple on the blue plate.",
        "Of course! Please put the green apple on the pink plate, the orange on the yellow plate and the red "
        "apple on the blue plate. The order doesn't matter."],
    3: ["The carrot, orange, green apple and red apple should go onto the blue, yellow, green and pink "
        "plates respectively (in arbitrary order).",
        "Method: Step 1 - the carrot onto the blue plate. Step 2 - the orange onto the yellow plate. Step 3 "
        "- the green apple onto the green plate. Step 4 - the red apple onto the pink plate. Any step may "
        "be done first.",
        "Each item goes on its plate, in arbitrary order: carrot on blue, orange on yellow, green apple on "
        "green, red apple on pink.",
        "No problem! Please put the red apple on the pink plate, the green apple on the green plate, the "
        "orange on the yellow plate and the carrot on the blue plate, in whatever order is easiest."],
    4: ["The green apple and the orange are first to be placed on the yellow plate; the carrot and the red "
        "apple are then to be placed on the blue plate.",
        "Method: Step 1 - the orange and the green apple onto the yellow plate. Step 2 - the red apple and "
        "the carrot onto the blue plate (any order within each step).",
        "Each item is to be placed on its plate: the green apple and the orange on the yellow one, and once "
        "both are there, the carrot and the red apple on the blue one.",
        "Sure! Please start with the green apple and the orange on the yellow plate, and once both are "
        "there, put the carrot and the red apple on the blue plate."],
}

# h109's held-out batch (issue 28): written together with DEV_H109 and committed before any rule, in the
# classes h106 left refused: casual chat ("n", "&", "+" for "and", "u", "dont care what order", greetings
# and sign-offs around the request), "in any order you find convenient", "only after those two", and
# "when both are on it, move ..." after an agent's reply. Scored only at the end.
VALID_H109: dict[int, list[str]] = {
    1: ["hey, can u put the green apple on the blue plate n the orange on the yellow plate? thx!",
        "Hi there, please put the orange on the yellow plate & the green apple on the blue plate. Cheers, "
        "Tom",
        "green apple on blue plate + orange on yellow plate, dont care which order",
        "Hello! Could you put the green apple on the blue plate and the orange on the yellow plate, in any "
        "order you find convenient? Many thanks."],
    2: ["hi! put the red apple on the blue plate, the orange on the yellow plate n the green apple on the "
        "pink plate. dont care what order u do it in. thanks!",
        "Good morning, please place the green apple on the pink plate, the red apple on the blue plate & the "
        "orange on the yellow plate, in whatever order you find convenient. Best, Sam",
        "can u put green apple on pink plate + red apple on blue plate + orange on yellow plate? any order "
        "is fine",
        "Hey, the orange goes on the yellow plate, the green apple on the pink plate and the red apple on "
        "the blue plate, in any order you find easiest. Ta!"],
    3: ["hiya, carrot on the blue plate, orange on the yellow plate, green apple on the green plate n red "
        "apple on the pink plate, dont care about the order. cheers",
        "Hello, could u please place the red apple on the pink plate & the green apple on the green plate & "
        "the orange on the yellow plate & the carrot on the blue plate? Thank you!",
        "Hi! Please put the carrot on the blue plate, the orange on the yellow plate, the green apple on the "
        "green plate and the red apple on the pink plate, in any order you find convenient. Thanks, Mia",
        "ok so: red apple on pink plate + green apple on green plate + carrot on blue plate + orange on "
        "yellow plate. order doesnt matter to me. thx"],
    4: ["Hey! Please put the orange and the green apple on the yellow plate first. Once both are on there, "
        "put the red apple and the carrot on the blue plate. Cheers, Ana",
        "hey can u put the orange n the green apple on the yellow plate first, then the red apple n the "
        "carrot on the blue plate? cheers",
        "Sure thing! Start with the green apple and the orange on the yellow plate, and when both are on it, "
        "move the carrot and the red apple to the blue plate.",
        "First the green apple and the orange go on the yellow plate, and only after those two, the red "
        "apple and the carrot go on the blue plate."],
}

# h109's development batch: written at the same time as VALID_H109, in its classes, read per sentence.
DEV_H109: dict[int, list[str]] = {
    1: ["hey, green apple on the blue plate n orange on the yellow plate pls",
        "Hi, please put the green apple on the blue plate and the orange on the yellow plate. Thanks!",
        "can u put the orange on the yellow plate & the green apple on the blue plate? dont care what "
        "order. Cheers, Ana",
        "orange on yellow plate + green apple on blue plate, in any order you find convenient",
        "Hello! Put the green apple on the blue plate and the orange on the yellow plate please. Thank you "
        "so much!",
        "No problem! Put the orange on the yellow plate and the green apple on the blue plate, in whatever "
        "order you find easiest."],
    2: ["hi, put the green apple on the pink plate, the orange on the yellow plate n the red apple on the "
        "blue plate. thx",
        "red apple on blue plate + green apple on pink plate + orange on yellow plate, dont care what order",
        "Hey! Could u place the orange on the yellow plate & the red apple on the blue plate & the green "
        "apple on the pink plate? Thanks, Ben",
        "Please put the green apple on the pink plate, the orange on the yellow plate and the red apple on "
        "the blue plate, in any order you find convenient.",
        "Good evening, the red apple goes on the blue plate, the green apple on the pink plate and the "
        "orange on the yellow plate. any order u like. Cheers!",
        "hiya, u can do it in any order: green apple on pink plate, red apple on blue plate, orange on "
        "yellow plate. ta"],
    3: ["hey, carrot on blue plate, orange on yellow plate, green apple on green plate & red apple on pink "
        "plate. dont care what order. thx!",
        "Hi! Could u put the red apple on the pink plate, the green apple on the green plate, the orange on "
        "the yellow plate n the carrot on the blue plate? Thanks!",
        "carrot on the blue plate + orange on the yellow plate + green apple on the green plate + red apple "
        "on the pink plate pls",
        "Hello, please place the carrot on the blue plate, the orange on the yellow plate, the green apple "
        "on the green plate and the red apple on the pink plate, in any order you find convenient. "
        "Regards, Kim",
        "Of course! Put the orange on the yellow plate, the carrot on the blue plate, the red apple on the "
        "pink plate and the green apple on the green plate, dont care which order.",
        "hi there, u can go in any order: red apple on pink plate, carrot on blue plate, green apple on "
        "green plate, orange on yellow plate. cheers, Jo"],
    4: ["Hi, please put the green apple and the orange on the yellow plate first. After both are on it, put "
        "the carrot and the red apple on the blue plate. Thanks!",
        "hey put the green apple n the orange on the yellow plate first, then the carrot n the red apple on "
        "the blue plate. thx",
        "No problem! Please start with the green apple and the orange on the yellow plate, and when both "
        "are on it, move the carrot and the red apple to the blue plate.",
        "Put the orange and the green apple on the yellow plate, and only after those two, put the carrot "
        "and the red apple on the blue plate.",
        "green apple + orange on the yellow plate first, then carrot + red apple on the blue plate",
        "Hello! First the green apple & the orange on the yellow plate. When both are on it, the red apple "
        "& the carrot on the blue plate please. Thanks, Sam"],
}

# h109's second development batch: written after the rules for DEV_H109 and measured before any rule for it
# (how far those rules carry), in the same classes with other words.
DEV2_H109: dict[int, list[str]] = {
    1: ["yo, pls put green apple on the blue plate n orange on the yellow plate, ty",
        "Morning! Could u pop the orange onto the yellow plate & the green apple onto the blue plate? Much "
        "appreciated.",
        "Hey there! Green apple on the blue plate + orange on the yellow plate, whatever order u find "
        "easiest. Thanks a lot!",
        "Sure thing! Orange to the yellow plate and green apple to the blue plate, in any order you find "
        "handy."],
    2: ["hello again, can u move the red apple to the blue plate, the green apple to the pink plate n the "
        "orange to the yellow plate? thanks in advance",
        "Hi team, green apple on the pink plate & red apple on the blue plate & orange on the yellow plate. "
        "Dont care what order. Best, Lee",
        "Of course! Please put the orange on the yellow plate, the green apple on the pink plate and the red "
        "apple on the blue plate in whichever order you find simplest.",
        "hey! red apple on blue plate + orange on yellow plate + green apple on pink plate. u choose the "
        "order. cheers"],
    3: ["Good afternoon! Please put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate & the red apple on the pink plate. Kind regards, Jo",
        "hi, can u put red apple on pink plate, green apple on green plate, orange on yellow plate n carrot "
        "on blue plate? dont care about order. thx",
        "Absolutely! The carrot goes on the blue plate, the orange on the yellow plate, the green apple on "
        "the green plate and the red apple on the pink plate, in any order you find most convenient.",
        "hey there, carrot + orange + green apple + red apple on the blue, yellow, green and pink plates "
        "respectively. thanks!"],
    4: ["Hi! Please put the green apple and the orange on the yellow plate first. Once they are both on it, "
        "put the carrot and the red apple on the blue plate. Cheers!",
        "hey, green apple n orange on the yellow plate first, then carrot n red apple on the blue plate pls. "
        "ty",
        "No worries! First the orange & the green apple on the yellow plate; when both are on it, the carrot "
        "& the red apple on the blue plate.",
        "Put the green apple and the orange on the yellow plate, then, only after those two, put the red "
        "apple and the carrot on the blue plate. Thanks, Sam"],
}

# h113's held-out batch (session 20): the words every world shares, greetings, forms of address and thanks
# from the one list (courtesy.txt) and chat shorthand ("n", "&", "u", "w/") read by the shared spelling
# step, with "respectively" and landmark-free prepositions; written with DEV_H113 and scored once at the end.
VALID_H113: dict[int, list[str]] = {
    1: ["Hey everyone! Put the green apple on the blue plate n the orange on the yellow plate. Much "
        "appreciated!",
        "yo robot, can u put the orange onto the yellow plate & the green apple onto the blue plate? ty"],
    2: ["Hiya folks, the green apple, the orange and the red apple go on the pink, yellow and blue plates "
        "respectively, in any order. Best, Sam",
        "Greetings team! red apple on the blue plate + orange on the yellow plate + green apple on the pink "
        "plate, any order u like. Thanks a bunch!"],
    3: ["Hello crew, please put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate n the red apple on the pink plate, in any order. Thanks in advance!"],
    4: ["Hey buddy, put the green apple n the orange on the yellow plate first, then the carrot & the red "
        "apple on the blue plate. Many thanks!"],
}

# h113's development batch: written at the same time as VALID_H113, in its classes, read per sentence.
DEV_H113: dict[int, list[str]] = {
    1: ["Hiya folks! Put the green apple on the blue plate n the orange on the yellow plate. Thanks so "
        "much!",
        "hey mate, could u put the orange on the yellow plate & the green apple on the blue plate? cheers"],
    2: ["Hey everyone, the green apple, the orange and the red apple go on the pink, yellow and blue plates "
        "respectively, in any order. Much appreciated!",
        "Hello team! green apple on the pink plate + red apple on the blue plate + orange on the yellow "
        "plate, any order u like. Thank you!"],
    3: ["Good morning crew, put the carrot on the blue plate, the orange on the yellow plate, the green "
        "apple on the green plate n the red apple on the pink plate, in any order. Many thanks!"],
    4: ["Hi there buddy, put the orange n the green apple on the yellow plate first, then the red apple & "
        "the carrot on the blue plate. Thanks a lot!"],
}

# h132's held-out batch (session 22, issue 28): headings that count the things or stages that follow
# ("Two things:", "Three jobs:", "Two stages. Stage one: ..."), written with DEV_H132 and scored once at the
# end.
VALID_H132: dict[int, list[str]] = {
    1: ["Two tasks: the orange goes on the yellow plate; the green apple goes on the blue plate. Order "
        "doesn't matter.",
        "2 items to place: green apple on the blue plate, orange on the yellow plate."],
    2: ["Three placements: the red apple goes on the blue plate; the green apple goes on the pink plate; "
        "the orange goes on the yellow plate. Any order is fine.",
        "Three things to do, in any order: green apple on the pink plate, orange on the yellow plate, red "
        "apple on the blue plate."],
    3: ["4 jobs: the carrot goes on the blue plate; the orange on the yellow plate; the green apple on the "
        "green plate; the red apple on the pink plate. The sequence does not matter."],
    4: ["Two steps. Step one: the green apple and the orange go on the yellow plate, in either order. Step "
        "two: the carrot and the red apple go on the blue plate, in either order.",
        "There are two stages. Stage 1: put the orange and the green apple on the yellow plate. Stage 2: "
        "put the red apple and the carrot on the blue plate. Within each stage, any order."],
}

# h132's development batch: written at the same time as VALID_H132, in its classes, read per sentence.
DEV_H132: dict[int, list[str]] = {
    1: ["Two things: green apple goes on the blue plate; orange goes on the yellow plate. Sequence is "
        "irrelevant.",
        "Two placements to do: the green apple on the blue plate; the orange on the yellow plate.",
        "2 things: orange on the yellow plate, green apple on the blue plate."],
    2: ["Three jobs: the green apple goes on the pink plate; the orange goes on the yellow plate; the red "
        "apple goes on the blue plate. The order is up to you.",
        "Three things, any order: red apple on the blue plate, orange on the yellow plate, green apple on "
        "the pink plate."],
    3: ["Four placements to do: carrot on the blue plate; orange on the yellow plate; green apple on the "
        "green plate; red apple on the pink plate. Any order.",
        "Four tasks, in no particular order: the carrot on the blue plate, the orange on the yellow plate, "
        "the green apple on the green plate and the red apple on the pink plate."],
    4: ["Two stages. Stage one: put the green apple and the orange on the yellow plate, in any order. Stage "
        "two: put the carrot and the red apple on the blue plate, in any order.",
        "Two parts. Part 1: the green apple and the orange on the yellow plate. Part 2: the carrot and the "
        "red apple on the blue plate. Within each part, any order.",
        "Two steps: Step 1 - green apple and orange onto the yellow plate; Step 2 - carrot and red apple "
        "onto the blue plate. Within each step, any order."],
}

# h138's held-out batch (session 23, issue 28): four voices, each on the four tasks (a non-native
# speaker's article, preposition and verb-form errors; a voice transcript with fillers "okay so", "uh",
# "um"; a checklist pasted from an e-mail with its greeting, "> " quote marks, "[ ]" boxes and sign-off; a
# terse note in mixed case without punctuation), written with DEV_H138 before any rule and scored once at
# the end.
VALID_H138: dict[str, dict[int, list[str]]] = {
    "nonnative": {
        1: ["Place please the green apple on the blue plate, and the orange you place on the "
            "yellow plate."],
        2: ["You must to put green apple on pink plate, orange on yellow plate and red apple "
            "on blue plate. Order of placing is not important."],
        3: ["Carrot must go in the blue plate, orange in the yellow plate, green apple in "
            "the green plate and red apple in the pink plate, order is not matter."],
        4: ["At first put green apple and orange on the yellow plate. After finish this, put "
            "carrot and red apple on the blue plate, order is free."],
    },
    "voice_fillers": {
        1: ["uh okay so the orange goes on the yellow plate and um the green apple on the "
            "blue plate"],
        2: ["okay so um put the red apple on the blue plate, uh, the green apple on the pink "
            "plate and the orange on the yellow plate, whatever order"],
        3: ["um so okay the carrot on the blue plate, uh, the red apple on the pink plate, "
            "the orange on the yellow plate and the green apple on the green plate, um, in any order you "
            "like"],
        4: ["okay so uh start with the green apple and the orange on the yellow plate, um, "
            "and then when that's done the carrot and the red apple on the blue plate, uh, any order"],
    },
    "email_checklist": {
        1: ["Hi Sam,\n\nCould you do these two:\n- put the green apple on the blue plate\n- "
            "put the orange on the yellow plate\n\nThanks!"],
        2: ["> Items (order doesn't matter):\n> - red apple -> blue plate\n> - orange -> "
            "yellow plate\n> - green apple -> pink plate"],
        3: ["Hello team,\n\nTo do, in any order:\n* carrot on the blue plate\n* orange on "
            "the yellow plate\n* green apple on the green plate\n* red apple on the pink plate\n\nRegards"],
        4: ["Hi,\n\nStep 1: green apple and orange onto the yellow plate.\nStep 2: once that "
            "is done, carrot and red apple onto the blue plate, in any order.\n\nThanks"],
    },
    "terse_no_punctuation": {
        1: ["ORANGE to yellow plate GREEN apple to blue plate"],
        2: ["red apple On blue plate green apple On pink plate orange On yellow plate order "
            "free"],
        3: ["carrot BLUE plate, orange YELLOW plate, green apple GREEN plate, red apple PINK "
            "plate - any order"],
        4: ["Green apple + orange in yellow plate 1st THEN carrot + red apple in blue plate "
            "any order"],
    },
}


DEV_H138: dict[str, dict[int, list[str]]] = {
    "nonnative": {
        1: ["Please you put the green apple in blue plate and the orange in yellow plate."],
        2: ["Place green apple in the pink plate, orange in the yellow plate and red apple "
            "in blue plate, the order is free, you can choose."],
        3: ["Put the carrot in blue plate, orange in yellow plate, green apple in green "
            "plate and red apple in pink plate, in which order you want."],
        4: ["First you place the green apple and orange in yellow plate. When is finish, "
            "place the carrot and red apple in blue plate, also in any order."],
    },
    "voice_fillers": {
        1: ["okay so uh put the green apple on the blue plate and um the orange on the "
            "yellow plate"],
        2: ["um okay so the green apple goes on the pink plate, uh, the orange on the yellow "
            "plate and the red apple on the blue plate, like, any order is fine"],
        3: ["okay so uh carrot on the blue plate, orange on the yellow plate, um, green "
            "apple on the green plate and the red apple on the pink plate, in any order"],
        4: ["uh so first put the green apple and the orange on the yellow plate, okay, and "
            "once that's done, um, put the carrot and the red apple on the blue plate, in any order"],
    },
    "email_checklist": {
        1: ["Hi,\n\nTo do:\n- green apple -> blue plate\n- orange -> yellow plate\n\nThanks"],
        2: ["> Please do these, in any order:\n> * green apple on the pink plate\n> * orange "
            "on the yellow plate\n> * red apple on the blue plate"],
        3: ["Hello,\n\nChecklist (any order):\n- [ ] carrot in the blue plate\n- [ ] orange "
            "in the yellow plate\n- [ ] green apple in the green plate\n- [ ] red apple in the pink "
            "plate\n\nCheers"],
        4: ["Hi there,\n\n1. Put the green apple and the orange in the yellow plate.\n2. "
            "After that, put the carrot and the red apple in the blue plate, any order.\n\nBest"],
    },
    "terse_no_punctuation": {
        1: ["GREEN apple to BLUE plate orange to YELLOW plate"],
        2: ["green apple on Pink plate orange on Yellow plate red apple on Blue plate Any "
            "order"],
        3: ["Carrot in BLUE plate orange in YELLOW plate green apple in GREEN plate red "
            "apple in PINK plate order doesnt matter"],
        4: ["green apple and orange in Yellow plate FIRST then carrot and red apple in Blue "
            "plate any order"],
    },
}


# h142's development batch (session 24, issue 28): four voices, each on the four tasks (a hurried
# supervisor's clipped orders, a teacher explaining to a class, a robotics engineer's spec sheet with
# "Goal:" / "Constraint:" / "Step N:" lines, a phone message in lower case without punctuation), written
# with VALID_H142 before any rule and measured on first contact.
DEV_H142: dict[str, dict[int, list[str]]] = {
    "hurried_supervisor": {
        1: ["Quick job: green apple onto the blue plate, orange onto the yellow plate. Go."],
        2: ["No time to waste. Green apple to the pink plate, orange to the yellow plate, red apple to the "
            "blue plate. Any order, just get it done."],
        3: ["Hurry up: carrot in the blue plate, orange in the yellow plate, green apple in the green plate, "
            "red apple in the pink plate. Order doesn't matter."],
        4: ["Listen up. Green apple and orange into the yellow plate first. Once that's done, carrot and red "
            "apple into the blue plate, any order."],
    },
    "teacher": {
        1: ["Let's see what the robot should do here. It places the green apple in the blue plate and the "
            "orange in the yellow plate. Simple, right?"],
        2: ["Today the robot has three things to do. The green apple goes in the pink plate, the orange goes "
            "in the yellow plate, and the red apple goes in the blue plate. Notice that the order is up to "
            "the robot."],
        3: ["Here is the exercise. The carrot belongs in the blue plate, the orange in the yellow plate, the "
            "green apple in the green plate and the red apple in the pink plate. Any order is correct."],
        4: ["Pay attention to the order here. First, the green apple and the orange are placed in the yellow "
            "plate. Only when both are there do the carrot and the red apple go into the blue plate, and "
            "those two can go in any order."],
    },
    "spec_sheet": {
        1: ["Goal: green apple in blue plate.\nGoal: orange in yellow plate.\nOrder: none."],
        2: ["Task list:\n- green apple -> pink plate\n- orange -> yellow plate\n- red apple -> blue plate\n"
            "Constraint: none on order."],
        3: ["Goals: carrot in blue plate; orange in yellow plate; green apple in green plate; red apple in "
            "pink plate.\nOrder: unconstrained."],
        4: ["Step 1: green apple and orange in yellow plate (any order).\nStep 2: carrot and red apple in "
            "blue plate (any order).\nConstraint: step 2 starts after step 1 is done."],
    },
    "phone_lowercase": {
        1: ["put the green apple in the blue plate and the orange in the yellow plate thx"],
        2: ["green apple in pink plate orange in yellow plate red apple in blue plate any order is fine"],
        3: ["can u put carrot in blue plate orange in yellow plate green apple in green plate red apple in "
            "pink plate any order"],
        4: ["1. green apple and orange in yellow plate\n2. carrot and red apple in blue plate any order\n"
            "please keep that sequence"],
    },
}


# h142's held-out batch (session 24, issue 28): the same four voices, each on the four tasks in other
# words (with British and Indian English turns, and a list closed by "Follow that order."), written with
# DEV_H142 before any rule, put aside, and scored once at the end (its counts, not its sentences, were
# also printed on first contact).
VALID_H142: dict[str, dict[int, list[str]]] = {
    "hurried_supervisor": {
        1: ["Orange on the yellow plate, green apple on the blue plate. Sharpish."],
        2: ["Right, three things and be quick about it: red apple in the blue plate, green apple in the pink "
            "plate, orange in the yellow plate. Whatever order."],
        3: ["Get moving: the carrot to the blue plate, the orange to the yellow plate, the green apple to "
            "the "
            "green plate and the red apple to the pink plate, in whatever order suits you."],
        4: ["Green apple and orange to the yellow plate, sharp. When they're in, carrot and red apple to the "
            "blue plate, either order."],
    },
    "teacher": {
        1: ["Now, watch carefully. The robot is asked to put the orange in the yellow plate and the green "
            "apple in the blue plate. The order does not matter here."],
        2: ["In this exercise the robot moves three fruits: the green apple to the pink plate, the orange to "
            "the yellow plate and the red apple to the blue plate. It may choose any order it likes."],
        3: ["Let's go through it together. Four items: the carrot goes in the blue plate, the orange in the "
            "yellow plate, the green apple in the green plate and the red apple in the pink plate. There is "
            "no required order."],
        4: ["Here is the tricky part.\n1. The robot starts with the green apple and the orange, both into "
            "the yellow plate.\n2. It then places the carrot and the red apple into the blue plate, in any "
            "order.\nFollow that order, please."],
    },
    "spec_sheet": {
        1: ["Goal 1: green apple -> blue plate\nGoal 2: orange -> yellow plate\nConstraint: none"],
        2: ["Objective: place 3 items.\n- green apple: pink plate\n- orange: yellow plate\n- red apple: blue "
            "plate\nOrdering: free."],
        3: ["Goal: carrot in blue plate, orange in yellow plate, green apple in green plate, red apple in "
            "pink plate.\nConstraint: any order."],
        4: ["Phase 1: green apple, orange -> yellow plate (either order).\nPhase 2: carrot, red apple -> "
            "blue plate (either order).\nConstraint: phase 2 only after phase 1 is complete."],
    },
    "phone_lowercase": {
        1: ["green apple in blue plate n orange in yellow plate pls"],
        2: ["pls put green apple on pink plate orange on yellow plate red apple on blue plate order up to u"],
        3: ["carrot blue plate orange yellow plate green apple green plate red apple pink plate any order "
            "thx"],
        4: ["first green apple and orange in yellow plate after that carrot and red apple in blue plate any "
            "order kindly do the needful"],
    },
}


# h181's development batch (session 28, issue 24): task 4's wait on both first items said in the two forms
# held-out rephrasings still refused ("..., any order, only when both are there" set off by commas, and
# "only if both of them are in (the yellow plate)"), written with VALID_H181 before any rule and measured
# on first contact.
DEV_H181: dict[str, dict[int, list[str]]] = {
    "comma_only_when": {
        4: ["Put the green apple and the orange in the yellow plate, in any order. Put the carrot and the "
            "red apple in the blue plate, in any order, only when both are there.",
            "Green apple and orange into the yellow plate, either order. Carrot and red apple into the blue "
            "plate, either order, but only once both are there.",
            "Put the green apple and the orange in the yellow plate in any order, and then, only when both "
            "are there, put the carrot and the red apple in the blue plate in any order."],
    },
    "only_if_both_in": {
        4: ["Put the green apple and the orange on the yellow plate. Put the carrot and the red apple on the "
            "blue plate only if both of them are on the yellow plate.",
            "Put the green apple and the orange in the yellow plate. The carrot and the red apple go in the "
            "blue plate only if both of them are in.",
            "Put the green apple and the orange in the yellow plate, in any order; then the carrot and the "
            "red apple go in the blue plate, any order, only if both are in."],
    },
}


# h181's held-out batch (session 28, issue 24): the same two forms in voices no batch used (a grandparent's
# letter, a stage manager, a safety officer, a commentator, a fridge note, a polite question, a non-native
# speaker, a mentor), written with DEV_H181 and committed before any rule, put aside and scored once at the
# end.
VALID_H181: dict[str, dict[int, list[str]]] = {
    "grandparent_letter": {
        4: ["Dear robot, please put the green apple and the orange in the yellow plate, in any order. Then "
            "put the carrot and the red apple in the blue plate, in any order, only when both are there. "
            "Love, Grandma."],
    },
    "stage_manager": {
        4: ["Places, please. Green apple and orange to the yellow plate. Carrot and red apple to the blue "
            "plate, either order, only once both are there. Thank you."],
    },
    "safety_officer": {
        4: ["Put the green apple and the orange into the yellow plate, in any order. Safety rule: the carrot "
            "and the red apple go into the blue plate only if both of them are in the yellow plate already."],
    },
    "commentator": {
        4: ["The green apple and the orange go into the yellow plate, any order, and then, only when both "
            "are there, the carrot and the red apple go into the blue plate, any order!"],
    },
    "fridge_note": {
        4: ["Note: green apple + orange -> yellow plate (any order). Carrot + red apple -> blue plate (any "
            "order), but only when both are there."],
    },
    "polite_question": {
        4: ["Could you put the green apple and the orange in the yellow plate, in either order, and, only "
            "once both are there, the carrot and the red apple in the blue plate, in either order?"],
    },
    "non_native": {
        4: ["Put green apple and orange in yellow plate any order. Carrot and red apple put in blue plate "
            "only if both of them are in."],
    },
    "mentor": {
        4: ["Start with the green apple and the orange in the yellow plate. The carrot and the red apple can "
            "go in the blue plate, in whichever order, but only if both of them are in."],
    },
}


# h210's held-out batch (session 30, issues 28 and 24): four rephrasings of each of the paper's four tabletop
# tasks, one per voice (a text message, a teacher to a class, a terse checklist, a chatty long-winded
# request), written without reading the reader's code or trying any line, committed before any scoring and
# scored once, unchanged (results/experiments/h210.md). The expected reading of each line is its task's
# ground truth (suites/tabletop/tabletop_tasks.json):
#   1: green apple -> blue plate, orange -> yellow plate; no order
#   2: green apple -> pink plate, orange -> yellow plate, red apple -> blue plate; no order
#   3: carrot -> blue plate, orange -> yellow plate, green apple -> green plate, red apple -> pink plate;
#      no order
#   4: green apple and orange -> yellow plate, each before carrot and red apple -> blue plate; no order within
#      either pair
HELD_H210: dict[str, dict[int, list[str]]] = {
    "text_message": {
        1: ["hey can u put the green apple in the blue plate n the orange in the yellow plate? thx"],
        2: ["pls put green apple in pink plate, orange in yellow plate, red apple in blue plate. any "
            "order is fine"],
        3: ["can u do carrot on the blue plate, orange on the yellow plate, green apple on the green "
            "plate and red apple on the pink plate? order doesnt matter"],
        4: ["first green apple + orange in the yellow plate, then carrot + red apple in the blue plate. "
            "order within each pair doesnt matter"],
    },
    "teacher_to_class": {
        1: ["Okay class, listen carefully: the green apple goes into the blue plate, and the orange goes "
            "into the yellow plate. That's all there is to it."],
        2: ["Alright everyone, here is today's exercise. The green apple belongs in the pink plate, the "
            "orange in the yellow plate and the red apple in the blue plate. You may do them in whatever "
            "order you like."],
        3: ["Class, pay attention, please. The carrot goes in the blue plate, the orange in the yellow "
            "plate, the green apple in the green plate and the red apple in the pink plate. You can place "
            "them in any order."],
        4: ["Okay everyone, this one has two stages. Stage one: the green apple and the orange go into "
            "the yellow plate. Stage two, only when both of those are in: the carrot and the red apple go "
            "into the blue plate, in either order."],
    },
    "terse_checklist": {
        1: ["To do:\n- green apple -> blue plate\n- orange -> yellow plate"],
        2: ["Checklist (any order):\n[ ] green apple -> pink plate\n[ ] orange -> yellow plate\n[ ] red "
            "apple -> blue plate"],
        3: ["- carrot: blue plate\n- orange: yellow plate\n- green apple: green plate\n- red apple: pink "
            "plate\nOrder: any."],
        4: ["Step 1 (any order):\n- green apple -> yellow plate\n- orange -> yellow plate\nStep 2, after "
            "step 1 (any order):\n- carrot -> blue plate\n- red apple -> blue plate"],
    },
    "chatty_long_winded": {
        1: ["So I was thinking, if it's not too much trouble, could you take the green apple and pop it "
            "in the blue plate, and the orange, that one can go in the yellow plate. No rush at all, "
            "whenever you get to it."],
        2: ["Okay so here's what I need, and honestly it doesn't matter which one you start with: the "
            "green apple should end up in the pink plate, the orange in the yellow plate, and the red "
            "apple in the blue plate. Thanks a bunch, you're a star."],
        3: ["Right, so, I've got a bit of a tidy-up for you if you don't mind. The carrot, could you put "
            "that in the blue plate? And the orange wants to go in the yellow plate, the green apple in "
            "the green plate, and the red apple in the pink plate, though honestly you can do them in any "
            "order you fancy, it's all the same to me."],
        4: ["Okay, so what I'd love is for you to start off with the green apple and the orange, both of "
            "those into the yellow plate, doesn't matter which goes first. Once you've got them both in "
            "there, it's the carrot and the red apple's turn, and they go into the blue plate, again in "
            "whichever order suits you. Thanks ever so much!"],
    },
}


# h220's held-out batch (session 30, issues 24 and 28): the frames of new voices around the paper's four
# tabletop tasks (a crew briefing, a quiz night): a group addressed ("crew", "everybody", "folks", "ladies
# and gentlemen"), a label naming the document ("Task card 2:", "Round 1:", "Question 3."), chatty asides
# and sign-offs, a chatty remark that frees the order, and stage labels that carry task 4's order ("phase
# two, only after both of those are in:", "Part B, after part A:"). Written with DEV_H220 and committed
# before any rule changed, put aside and scored once at the end.
VALID_H220: dict[str, dict[int, list[str]]] = {
    "crew_briefing": {
        1: ["All right, crew, put the orange on the yellow plate and the green apple on the blue plate. Easy "
            "does it, crew."],
        2: ["Task card 2: put the red apple on the blue plate, the green apple on the pink plate and the "
            "orange on the yellow plate. Begin with whichever you like."],
        3: ["Listen up, everybody. The carrot goes on the blue plate, the orange on the yellow plate, the "
            "green apple on the green plate and the red apple on the pink plate. Doesn't matter where you "
            "start."],
        4: ["Crew, phase one: the green apple and the orange go in the yellow plate. Phase two, only after "
            "both of those are in: the carrot and the red apple go in the blue plate, either order."],
    },
    "quiz_night": {
        1: ["Round 1: the green apple on the blue plate and the orange on the yellow plate. Can you do it, "
            "folks?"],
        2: ["Ladies and gentlemen, the green apple goes in the pink plate, the orange in the yellow plate "
            "and the red apple in the blue plate. Any one of them can come first. Best of luck!"],
        3: ["Question 3. Put the carrot in the blue plate, the orange in the yellow plate, the green apple "
            "in the green plate and the red apple in the pink plate, in any order you fancy, everyone."],
        4: ["Everyone, part A: put the green apple and the orange in the yellow plate. Part B, after part "
            "A: put the carrot and the red apple in the blue plate."],
    },
}


# h220's development batch (session 30, issues 24 and 28), written with VALID_H220: a tour guide, a coach,
# a label naming the document and a chatty voice around the paper's four tabletop tasks, with chatty remarks
# that free the order and stage or step labels that carry task 4's order; measured on first contact before
# the reader was changed for it.
DEV_H220: dict[str, dict[int, list[str]]] = {
    "tour_guide": {
        1: ["Ladies and gentlemen, put the green apple on the blue plate and the orange on the yellow plate. "
            "Thank you for your cooperation."],
        2: ["Everyone, put the green apple on the pink plate, the orange on the yellow plate and the red "
            "apple on the blue plate. Start wherever you like."],
        3: ["Folks, the carrot goes on the blue plate, the orange on the yellow plate, the green apple on "
            "the green plate and the red apple on the pink plate. It doesn't matter which one you start "
            "with."],
        4: ["Ladies and gentlemen, put the green apple and the orange in the yellow plate first. Stage two, "
            "only when both of those are in: the carrot and the red apple go into the blue plate, in either "
            "order."],
    },
    "coach": {
        1: ["Alright team, green apple on the blue plate, orange on the yellow plate. Nice and steady, "
            "team."],
        2: ["Class, put the orange on the yellow plate, the red apple on the blue plate and the green apple "
            "on the pink plate, class. Whichever comes first is fine."],
        3: ["Crew, put the red apple on the pink plate, the green apple on the green plate, the orange on "
            "the yellow plate and the carrot on the blue plate. Start wherever you like, crew. Good luck!"],
        4: ["Team, stage one: the green apple and the orange go into the yellow plate. Stage two, once both "
            "of those are in: the carrot and the red apple go into the blue plate. Good luck!"],
    },
    "document_label": {
        1: ["Puzzle #1: put the green apple on the blue plate and the orange on the yellow plate. Can you "
            "solve it?"],
        2: ["Exercise 2. Put the green apple in the pink plate, the orange in the yellow plate and the red "
            "apple in the blue plate, in any order."],
        3: ["Object of the game: the carrot in the blue plate, the orange in the yellow plate, the green "
            "apple in the green plate and the red apple in the pink plate. Whichever comes first is fine."],
        4: ["Rules of play: Step 1: put the green apple and the orange in the yellow plate. Step 2, after "
            "step 1: put the carrot and the red apple in the blue plate."],
    },
    "chatty": {
        1: ["What I'd love is for you to put the green apple on the blue plate and the orange on the yellow "
            "plate. It's going to be perfect."],
        2: ["Put the green apple on the pink plate, the orange on the yellow plate and the red apple on the "
            "blue plate. It's all the same to me which goes first."],
        3: ["Okay, so, nice and steady: the carrot on the blue plate, the orange on the yellow plate, the "
            "green apple on the green plate and the red apple on the pink plate. Start wherever you like. "
            "Thank you for your cooperation!"],
        4: ["What I'd love is for you to put the green apple and the orange in the yellow plate. Stage two, "
            "only when both are in: the carrot and the red apple in the blue plate. Good luck!"],
    },
}


# h229's held-out batch (session 30, issue 28): task 4 said in labelled stages or steps, arrow bullets,
# and a chatty long-winded voice ("take X and pop it in", "X, that one can go ...", "it's X's turn", "a bit
# of a tidy-up"). Written with DEV_H229 and committed before any rule changed, scored once at the end.
HELD_H229: dict[str, dict[int, list[str]]] = {
    "labelled_steps": {
        1: ["Step 1 (any order):\n-> green apple on the blue plate\n-> orange on the yellow plate"],
        2: ["Stage one, in any order: the green apple into the pink plate, the orange into the yellow "
            "plate, the red apple into the blue plate."],
        3: ["Steps, any order:\n-> carrot on the blue plate\n-> orange on the yellow plate\n-> green apple "
            "on the green plate\n-> red apple on the pink plate"],
        4: ["Stage 1 (either order): the green apple and the orange into the yellow plate.\nStage 2, only "
            "once stage 1 is done: the carrot and the red apple into the blue plate, either order."],
    },
    "chatty_rambling": {
        1: ["Hey, so if you could, take the orange and pop it in the yellow plate, and the green apple, "
            "that one can go in the blue plate. Cheers!"],
        2: ["Right then, a little job for you: the red apple wants to go in the blue plate, the green "
            "apple in the pink plate and the orange in the yellow plate, and honestly whichever you fancy "
            "first is fine."],
        3: ["Okay so, bit of a tidy-up if you don't mind. Take the green apple and pop it in the green "
            "plate, the red apple, that one goes in the pink plate, the carrot in the blue plate and the "
            "orange in the yellow plate. Any order you fancy."],
        4: ["So what I'd really like is the green apple and the orange in the yellow plate first, "
            "whichever goes first. Once they're both in there, it's the carrot's turn and the red apple's "
            "turn, and those go into the blue plate. Thanks a million!"],
    },
}


# h229's development batch (session 30, issue 28), written with HELD_H229: labelled stages and steps (arrow
# bullets, "Stage two, only when both of those are in:") and a chatty voice; measured before rules changed.
DEV_H229: dict[str, dict[int, list[str]]] = {
    "stage_steps": {
        1: ["Step 1, any order:\n-> orange on the yellow plate\n-> green apple on the blue plate"],
        2: ["Stage one (any order):\n-> green apple into the pink plate\n-> orange into the yellow plate\n"
            "-> red apple into the blue plate"],
        3: ["Step 1 (any order): the carrot on the blue plate, the orange on the yellow plate, the green "
            "apple on the green plate and the red apple on the pink plate."],
        4: ["Stage one: the green apple and the orange into the yellow plate, either order. Stage two, only "
            "when both of those are in: the carrot and the red apple into the blue plate."],
    },
    "arrow_stages": {
        1: ["-> green apple on the blue plate\n-> orange on the yellow plate\nAny order."],
        2: ["Step 1 (any order):\n-> orange on the yellow plate\n-> red apple on the blue plate\n-> green "
            "apple on the pink plate"],
        3: ["Stage 1, any order:\n-> red apple on the pink plate\n-> green apple on the green plate\n-> "
            "orange on the yellow plate\n-> carrot on the blue plate"],
        4: ["Step 1 (any order):\n-> green apple on the yellow plate\n-> orange on the yellow plate\nStep 2, "
            "after step 1 (any order):\n-> carrot on the blue plate\n-> red apple on the blue plate"],
    },
    "chatty_voice": {
        1: ["Could you take the green apple and pop it in the blue plate, and the orange, that one can go "
            "in the yellow plate? Thanks!"],
        2: ["So here's the thing: the orange should end up in the yellow plate, the green apple in the "
            "pink plate and the red apple in the blue plate, whichever you start with."],
        3: ["I've got a bit of a tidy-up for you. The carrot goes in the blue plate, the orange in the "
            "yellow plate, the green apple in the green plate and the red apple in the pink plate, in any "
            "order you fancy."],
        4: ["First the green apple and the orange go into the yellow plate, in either order. Once you've "
            "got them both in there, it's the carrot and the red apple's turn, and they go into the blue "
            "plate."],
    },
    "chatty_aside": {
        1: ["Take the orange and pop it in the yellow plate, and the green apple, that one can go in the "
            "blue plate. No rush at all."],
        2: ["Okay so, the red apple, that one can go in the blue plate, the orange in the yellow plate and "
            "the green apple in the pink plate. Any order is fine."],
        3: ["Right, so, take the carrot and pop it in the blue plate, the orange in the yellow plate, the "
            "green apple in the green plate and the red apple in the pink plate. Any order you like."],
        4: ["Start off with the green apple and the orange, both of those into the yellow plate. Once "
            "they're both in, it's the carrot's turn and the red apple's, and they go into the blue "
            "plate."],
    },
}


# h233's held-out batch (session 31, issues 28 and 24): four rephrasings of each of the paper's four tabletop
# tasks, one per voice (a fitness instructor, a nature-documentary narrator, a Southern US drawl, corporate
# jargon), voices no batch above uses; written without reading the reader's code or trying any line,
# committed before any scoring and scored once, unchanged (results/experiments/h233.md). The expected reading
# of each line is its task's ground truth (suites/tabletop/tabletop_tasks.json), as listed above HELD_H210.
HELD_H233: dict[str, dict[int, list[str]]] = {
    "fitness_instructor": {
        1: ["Alright, let's get moving! Green apple into the blue plate, orange into the yellow plate. "
            "Great work, keep it up!"],
        2: ["Okay, warm-up's over! I want the green apple in the pink plate, the orange in the yellow "
            "plate and the red apple in the blue plate. Mix up the order however you like, just keep that "
            "energy up!"],
        3: ["Let's go, let's go! Carrot in the blue plate, orange in the yellow plate, green apple in the "
            "green plate, red apple in the pink plate. Any order, you've got this!"],
        4: ["Two sets today. Set one: the green apple and the orange go in the yellow plate. Set two, once "
            "set one is done: the carrot and the red apple go in the blue plate, any order. Push through!"],
    },
    "nature_documentary": {
        1: ["And here, in its natural habitat, the robot arm gently places the green apple in the blue "
            "plate and the orange in the yellow plate. Truly remarkable."],
        2: ["Watch closely. The green apple must find its way to the pink plate, the orange to the yellow "
            "plate and the red apple to the blue plate. Which comes first? That, the arm decides for "
            "itself."],
        3: ["Here on the open table, four travellers await their new homes: the carrot will settle in the "
            "blue plate, the orange in the yellow plate, the green apple in the green plate and the red "
            "apple in the pink plate. The order in which they arrive is of no importance."],
        4: ["First, the green apple and the orange make their way into the yellow plate, in either order. "
            "Only once both have arrived do the carrot and the red apple set off for the blue plate, again "
            "in either order."],
    },
    "southern_drawl": {
        1: ["Hey there, would y'all mind puttin' the green apple in the blue plate and the orange in the "
            "yellow plate? Much obliged."],
        2: ["Well now, the green apple oughta go in the pink plate, the orange in the yellow plate and the "
            "red apple in the blue plate. Don't matter none which one you do first, darlin'."],
        3: ["Alright y'all, go on and put the carrot in the blue plate, the orange in the yellow plate, "
            "the green apple in the green plate and the red apple in the pink plate. Any order's just fine."],
        4: ["Now first thing, y'all put the green apple and the orange in the yellow plate. Once that's "
            "done, go on ahead and put the carrot and the red apple in the blue plate, whichever order "
            "suits ya."],
    },
    "corporate_jargon": {
        1: ["Quick ask: can we action the green apple into the blue plate and the orange into the yellow "
            "plate? Thanks in advance."],
        2: ["Circling back on the plates: the deliverables are the green apple in the pink plate, the "
            "orange in the yellow plate and the red apple in the blue plate. No dependencies between them, "
            "so sequence them however works for you."],
        3: ["Per our sync, we need the carrot in the blue plate, the orange in the yellow plate, the green "
            "apple in the green plate and the red apple in the pink plate. Order isn't a blocker here."],
        4: ["Phase one is the green apple and the orange into the yellow plate. Phase two kicks off once "
            "phase one has landed: the carrot and the red apple into the blue plate. Within each phase, "
            "sequencing is flexible."],
    },
}


# h235 (session 31, issues 24 and 28): held out. The four tasks in two voices of my own (a stage magician, a
# ward nurse) whose frames are words no frame list holds ("Ta-da!", "Abracadabra!", "Trick number 2:",
# "Ward round, bed 2:", "There we go, poppet.", "Chin up, love."), and a label naming the first object
# ("Carrot trick:"). Written with DEV_H235 and committed before any rule changed, scored once at the end.
VALID_H235: dict[str, dict[int, list[str]]] = {
    "magician": {
        1: ["Ta-da! Put the green apple on the blue plate and the orange on the yellow plate. Abracadabra!"],
        2: ["Trick number 2: put the red apple on the blue plate, the green apple on the pink plate and the "
            "orange on the yellow plate, in any order. Behold!"],
        3: ["Carrot trick: the carrot goes on the blue plate, the orange on the yellow plate, the green "
            "apple "
            "on the green plate and the red apple on the pink plate. Marvellous."],
        4: ["Illusion 4, my lovely assistants: put the green apple and the orange in the yellow plate first, "
            "then the carrot and the red apple in the blue plate, in either order. A round of applause!"],
    },
    "nurse_ward": {
        1: ["Morning, sweetheart. Put the green apple on the blue plate and the orange on the yellow plate. "
            "There we go, poppet."],
        2: ["Ward round, bed 2: put the red apple on the blue plate, the green apple on the pink plate "
            "and the "
            "orange on the yellow plate, any order you like. Lovely, thanks, petal."],
        3: ["Right then, my dears: the carrot goes on the blue plate, the orange on the yellow plate, the "
            "green apple on the green plate and the red apple on the pink plate. Nice and gentle."],
        4: ["Orange and green apple first, pet: both in the yellow plate. Once they're in, the carrot and "
            "the "
            "red apple go in the blue plate, either order. Chin up, love."],
    },
}

# h235 (session 31): the dev batch written with VALID_H235, in voices of my own (a yoga teacher, a camp
# counsellor, a game streamer) and labels that name the object or plate of the sentences under them
# ("Carrot duty:", "Green apple stuff -", "Yellow plate business:"); measured on first contact.
DEV_H235: dict[str, dict[int, list[str]]] = {
    "yoga_teacher": {
        1: ["Breathe in, friends. Put the green apple on the blue plate and the orange on the yellow plate. "
            "Namaste."],
        2: ["Gently now, lovely people: put the red apple on the blue plate, the green apple on the pink "
            "plate "
            "and the orange on the yellow plate, in any order. Breathe out."],
        3: ["Settle in, everybody. The carrot goes on the blue plate, the orange on the yellow plate, the "
            "green "
            "apple on the green plate and the red apple on the pink plate. Beautiful."],
        4: ["Find your centre, friends. Put the green apple and the orange in the yellow plate first. "
            "Then the "
            "carrot and the red apple go into the blue plate, in either order. Wonderful practice."],
    },
    "camp_counsellor": {
        1: ["Campers, gather round! Put the green apple on the blue plate and the orange on the yellow "
            "plate. "
            "Super job, campers!"],
        2: ["Cabin 4, heads up: put the red apple on the blue plate, the green apple on the pink plate "
            "and the "
            "orange on the yellow plate, any order. Let's hustle, bunkmates!"],
        3: ["Morning activity: the carrot goes on the blue plate, the orange on the yellow plate, the green "
            "apple on the green plate and the red apple on the pink plate. High fives, kiddos!"],
        4: ["Okay, buddies, put the green apple and the orange in the yellow plate first. After that, the "
            "carrot and the red apple go into the blue plate, either order. Rock on, buddies!"],
    },
    "game_streamer": {
        1: ["Yo chat, level 1: put the green apple on the blue plate and the orange on the yellow plate. "
            "GG."],
        2: ["What's up, gamers! Put the red apple on the blue plate, the green apple on the pink plate "
            "and the "
            "orange on the yellow plate, whatever order. Let's gooo!"],
        3: ["Speedrun attempt 3: carrot on the blue plate, orange on the yellow plate, green apple on the "
            "green plate, red apple on the pink plate. Clutch!"],
        4: ["Boss fight, squad: the green apple and the orange go in the yellow plate first; once both "
            "are in, "
            "the carrot and the red apple go in the blue plate, either order. Peace out, chat."],
    },
    "object_labels": {
        1: ["Green apple stuff - put the green apple on the blue plate. Orange stuff - put the orange on the "
            "yellow plate."],
        2: ["Apple jobs: put the red apple on the blue plate and the green apple on the pink plate. Orange "
            "job: put the orange on the yellow plate. Any order."],
        3: ["Carrot duty: the carrot goes on the blue plate. Orange duty: the orange goes on the yellow "
            "plate. "
            "Apple duty: the green apple goes on the green plate and the red apple on the pink plate."],
        4: ["Yellow plate business: put the green apple and the orange in the yellow plate first. Blue plate "
            "business: then put the carrot and the red apple in the blue plate, in either order."],
    },
}


# h241's held-out batch (session 31, issues 28 and 24): task 4 said in stages, in voices no batch above uses
# (a play's acts, a game's levels, a relay's legs, a lettered list, batches, a warm-up and a main event,
# "before touching the others" / "only then", bare ordinals, waves). Written with DEV_H241 and committed
# before any rule changed, put aside and scored once at the end.
HELD_H241: dict[str, dict[int, list[str]]] = {
    "theatre": {
        4: ["Act one: the green apple and the orange go into the yellow plate, in whichever order. Act two, "
            "after act one: the carrot and the red apple go into the blue plate."],
    },
    "video_game": {
        4: ["Level 1 - get the orange and the green apple into the yellow plate. Level 2 - once level 1 is "
            "cleared, get the red apple and the carrot into the blue plate. Either order inside a level."],
    },
    "relay": {
        4: ["First leg: green apple and orange into the yellow plate, any order. Second leg: carrot and red "
            "apple into the blue plate, any order."],
    },
    "lettered": {
        4: ["A) the green apple and the orange into the yellow plate (either order)\nB) then the carrot and "
            "the red apple into the blue plate (either order)"],
    },
    "batches": {
        4: ["Do it in two batches. The first batch is the orange and the green apple, into the yellow plate. "
            "The second batch, the carrot and the red apple, goes into the blue plate once the first batch "
            "is in."],
    },
    "warm_up": {
        4: ["Warm-up: pop the green apple and the orange in the yellow plate, whichever first. Main event, "
            "only after the warm-up: the red apple and the carrot in the blue plate."],
    },
    "before_touching": {
        4: ["Get the green apple and the orange into the yellow plate before touching the others. Only then "
            "put the carrot and the red apple into the blue plate, in any order."],
    },
    "ordinals_alone": {
        4: ["Firstly: the green apple and the orange in the yellow plate. Secondly: the carrot and the red "
            "apple in the blue plate. Inside each, any order."],
    },
    "waves": {
        4: ["Wave one, the orange and the green apple into the yellow plate. Wave two, once all of those are "
            "down, the carrot and the red apple into the blue plate."],
    },
}


# h241's development batch (session 31, issues 28 and 24), written with HELD_H241: task 4 said in stages
# ("Phase one ... Phase two, once phase one is done", "Round 1 ... Round 2", "To begin, ... When that's all
# set, ...", "Part A ... then Part B", "the first batch ... the second batch", "warm-up ... main event",
# numbered and lettered lists, "get these done before touching the others", "only then", "once all of those
# are down"); measured on first contact before the reader was changed for it.
DEV_H241: dict[str, dict[int, list[str]]] = {
    "phases": {
        4: ["Phase one: put the green apple and the orange in the yellow plate. Phase two, once phase one is "
            "done: put the carrot and the red apple in the blue plate.",
            "Phase I) green apple and orange into the yellow plate. Phase II) carrot and red apple into the "
            "blue plate."],
    },
    "rounds": {
        4: ["Round 1: green apple and orange into the yellow plate. Round 2: carrot and red apple into the "
            "blue plate. Any order within a round.",
            "Round one, either order: the orange and the green apple into the yellow plate. Round two, "
            "either order: the carrot and the red apple into the blue plate.",
            "In the opening round, put the green apple and the orange in the yellow plate. In the second "
            "round, put the carrot and the red apple in the blue plate."],
    },
    "to_begin": {
        4: ["To begin, the green apple and the orange into the yellow plate, whichever order. When that's "
            "all set, the carrot and the red apple into the blue plate."],
    },
    "parts": {
        4: ["Part A: place the orange and the green apple on the yellow plate. Then Part B: place the red "
            "apple and the carrot on the blue plate.",
            "Stage A: the green apple and the orange to the yellow plate. Stage B: the carrot and the red "
            "apple to the blue plate."],
    },
    "batches": {
        4: ["The first batch is the green apple and the orange, into the yellow plate. The second batch is "
            "the carrot and the red apple, into the blue plate, after the first batch."],
    },
    "warm_up": {
        4: ["Warm-up: the green apple and the orange go in the yellow plate. Main event: the carrot and the "
            "red apple go in the blue plate."],
    },
    "lists": {
        4: ["1. Green apple and orange into the yellow plate, either order.\n2. Carrot and red apple into "
            "the blue plate, either order.",
            "a) the orange and the green apple in the yellow plate\nb) the carrot and the red apple in the "
            "blue plate"],
    },
    "conditions": {
        4: ["Get the green apple and the orange into the yellow plate; get these done before touching the "
            "others. Then the carrot and the red apple go into the blue plate.",
            "Put the green apple and the orange in the yellow plate, any order. Only then put the carrot and "
            "the red apple in the blue plate.",
            "Put the green apple and the orange in the yellow plate. Once all of those are down, put the "
            "carrot and the red apple in the blue plate, either order."],
    },
    "labels": {
        4: ["Step one - orange and green apple into the yellow plate. Step two - red apple and carrot into "
            "the blue plate. Within a step, any order.",
            "First: the green apple and the orange into the yellow plate. Second: the carrot and the red "
            "apple into the blue plate.",
            "Wave 1: green apple and orange into the yellow plate. Wave 2: carrot and red apple into the "
            "blue plate.",
            "Level one: the green apple and the orange onto the yellow plate. Level two, only after level "
            "one: the carrot and the red apple onto the blue plate.",
            "Act 1: the green apple and the orange go in the yellow plate. Act 2: the carrot and the red "
            "apple go in the blue plate."],
    },
}


# h250's held-out batch (session 32, issues 28 and 24): four rephrasings of each of the paper's four tabletop
# tasks, one per voice (an estate agent, a zookeeper at feeding time, an accountant's ledger, a barista),
# voices no batch above uses; written without reading the reader's code or trying any line, committed before
# any scoring and scored once, unchanged (results/experiments/h250.md). The expected reading of each line is
# its task's ground truth (suites/tabletop/tabletop_tasks.json), as listed above HELD_H210.
HELD_H250: dict[str, dict[int, list[str]]] = {
    "estate_agent": {
        1: ["Let me show you the listings. The blue plate is the ideal home for the green apple, and the "
            "yellow plate is move-in ready for the orange, so please move each of them in. A real steal!"],
        2: ["Three properties, three new owners! The green apple is moving into the pink plate, the "
            "orange into the yellow plate and the red apple into the blue plate. Who moves in first is "
            "entirely flexible."],
        3: ["Great news, every plate on this table has a buyer: put the carrot in the blue plate, the "
            "orange in the yellow plate, the green apple in the green plate and the red apple in the pink "
            "plate. The closings can happen in any order."],
        4: ["The yellow plate is first on the market: settle the green apple and the orange in it, either "
            "one first. Only once both have moved in does the blue plate open up, and then the carrot and "
            "the red apple go into it, again in any order. Location, location, location!"],
    },
    "zookeeper": {
        1: ["Feeding time, everyone! The green apple goes to the blue plate and the orange goes to the "
            "yellow plate. Mind your fingers."],
        2: ["Right, team, here's today's feeding chart: green apple in the pink plate, orange in the "
            "yellow plate, red apple in the blue plate. It doesn't matter which one goes out first."],
        3: ["Before the gates open, we need the carrot in the blue plate, the orange in the yellow plate, "
            "the green apple in the green plate and the red apple in the pink plate. Do them in any order "
            "you like, just keep the enclosure tidy."],
        4: ["Morning round first: drop the green apple and the orange into the yellow plate, in either "
            "order. When both of those are in, do the afternoon round: the carrot and the red apple into "
            "the blue plate, again in either order."],
    },
    "accountant_ledger": {
        1: ["Per the ledger, two entries to post: green apple posted to the blue plate, orange posted to "
            "the yellow plate. That balances the books."],
        2: ["Please reconcile the following three items: the green apple is allocated to the pink plate, "
            "the orange to the yellow plate and the red apple to the blue plate. The posting order is "
            "immaterial."],
        3: ["Year-end close, four line items: carrot to the blue plate; orange to the yellow plate; green "
            "apple to the green plate; red apple to the pink plate. Book them in any sequence."],
        4: ["Quarter one: transfer the green apple and the orange into the yellow plate, in either order. "
            "Quarter two opens only after both are booked: transfer the carrot and the red apple into the "
            "blue plate, in either order as well."],
    },
    "barista": {
        1: ["Order up! One green apple on the blue plate and one orange on the yellow plate, please."],
        2: ["Okay, I've got three orders for you: green apple on the pink plate, orange on the yellow "
            "plate, red apple on the blue plate. Serve them in whatever order, they're all for the same "
            "table."],
        3: ["Busy morning! Can you plate these up for me: carrot on the blue plate, orange on the yellow "
            "plate, green apple on the green plate and red apple on the pink plate? They can go out in "
            "any order."],
        4: ["First, the green apple and the orange go on the yellow plate, either one first. Once that "
            "plate's ready, the carrot and the red apple go on the blue plate, in any order. Thanks, "
            "you're a star."],
    },
}


# h245 (session 31, issues 24 and 28): held out. The four tasks in two voices of my own (an air-traffic
# controller, a sports commentator): motion idioms ("make its way onto", "set off for", "find their way
# into"), narration of what the arm does, a single noun or "my ADJ NOUN" addressed, "Right then,", British
# spellings. Written with DEV_H245 and committed before any rule changed, scored once at the end.
HELD_H245: dict[str, dict[int, list[str]]] = {
    "air_traffic_control": {
        1: ["Tower to all arms: the green apple is cleared to make its way onto the blue plate, and the "
            "orange onto the yellow plate. Cheers, captain."],
        2: ["Traffic advisory: the red apple sets off for the blue plate, the green apple for the pink plate "
            "and the orange for the yellow plate, in any order. Safe travels."],
    },
    "sports_commentator": {
        3: ["And the arm gently places the carrot on the blue plate, the orange on the yellow plate, the "
            "green apple on the green plate and the red apple on the pink plate, in no particular order. "
            "Marvellous stuff, my dear friend!"],
        4: ["Right then, folks: first the green apple and the orange find their way into the yellow plate, "
            "then the carrot and the red apple make their way into the blue plate, either order. What a "
            "finish, partner!"],
    },
}

# h245 (session 31): the dev batch written with HELD_H245 (a British foreman, a ranch hand in dialect:
# "y'all", "oughta", "puttin'", "don't matter none", "mosey on into"; goals said as nouns, "the deliverables
# are"); measured on first contact.
DEV_H245: dict[str, dict[int, list[str]]] = {
    "british_foreman": {
        1: ["Right then, mate: pop the green apple on the blue plate and the orange on the yellow plate. "
            "Cheers, guv."],
        2: ["Morning, chief. The deliverables are the red apple on the blue plate, the green apple on the "
            "pink plate and the orange on the yellow plate, any order. Brilliant, keep it up!"],
        3: ["The robot arm gently places the carrot on the blue plate, the orange on the yellow plate, the "
            "green apple on the green plate and the red apple on the pink plate. Smashing, my good man."],
        4: ["Right, lads: the green apple and the orange make their way into the yellow plate first, then the"
            " carrot and the red apple into the blue plate, either order. Marvellous."],
    },
    "ranch_hand": {
        1: ["Howdy, partner. Would y'all mind puttin' the green apple on the blue plate and the orange on the"
            " yellow plate? Much obliged."],
        2: ["The red apple oughta go on the blue plate, the green apple on the pink plate and the orange on "
            "the yellow plate. Don't matter none which goes first, sugar."],
        3: ["Y'all gonna set the carrot on the blue plate, the orange on the yellow plate, the green apple on"
            " the green plate and the red apple on the pink plate, any order's fine. Yeehaw!"],
        4: ["First off, the green apple and the orange mosey on into the yellow plate. Once that's done, the "
            "carrot and the red apple head on over to the blue plate, whichever order suits ya. Happy "
            "trails."],
    },
}


# h262 (session 32, issues 28 and 24): held out. The four tasks in two voices of my own (a pharmacist, a
# postal clerk): a frame clause before a colon, chit-chat, goal verbs of the voice, order freedom in the
# voice's words, task 4's stages by the voice's labels. Committed before any rule changed (with DEV_H262
# still unwritten), scored once at the end.
HELD_H262: dict[str, dict[int, list[str]]] = {
    "pharmacist": {
        1: ["Two prescriptions to fill: green apple to the blue plate, orange to the yellow plate. Take care "
            "now."],
        2: ["Here's the dosage sheet for today: the green apple goes in the pink plate, the orange in the "
            "yellow plate and the red apple in the blue plate. Which one gets dispensed first makes no "
            "difference."],
        3: ["Next patient, please! The carrot is dispensed into the blue plate, the orange into the yellow "
            "plate, the green apple into the green plate and the red apple into the pink plate. Fill them in "
            "any order."],
        4: ["Step one of the regimen: put the green apple and the orange in the yellow plate, either one "
            "first. Once both are in, step two: the carrot and the red apple go in the blue plate, in either "
            "order. Get well soon!"],
    },
    "postal_clerk": {
        1: ["Two parcels going out today: the green apple is addressed to the blue plate and the orange to "
            "the yellow plate. Stamp them in whatever order."],
        2: ["Sorting time! Green apple to the pink plate, orange to the yellow plate, red apple to the blue "
            "plate. It doesn't matter which one ships first."],
        3: ["Four letters in the tray: deliver the carrot to the blue plate, the orange to the yellow plate, "
            "the green apple to the green plate and the red apple to the pink plate. Sort them in any "
            "sequence. Next in line!"],
        4: ["First delivery round: the green apple and the orange go into the yellow plate, in either order. "
            "When both have arrived, second round: the carrot and the red apple into the blue plate, again "
            "in any order."],
    },
}


# h262's dev batch (session 32): the same classes in three voices of my own (a waiter, a removals foreman, a
# hotel concierge), looked at and mended against.
DEV_H262: dict[str, dict[int, list[str]]] = {
    "waiter": {
        1: ["Table for two! The green apple is seated at the blue plate and the orange at the yellow plate. "
            "Enjoy your meal."],
        2: ["Here are tonight's specials: green apple on the pink plate, orange on the yellow plate, red "
            "apple on the blue plate. It doesn't matter which one comes out first."],
        3: ["Coming right up! Carrot on the blue plate, orange on the yellow plate, green apple on the green "
            "plate and red apple on the pink plate. Serve them in any order."],
        4: ["Starters first: the green apple and the orange go on the yellow plate, either one first. Once "
            "both are served, the mains: the carrot and the red apple go on the blue plate, in any order."],
    },
    "removals_foreman": {
        1: ["Right, lads, two items on the van list: green apple into the blue plate, orange into the yellow "
            "plate. Mind your backs."],
        2: ["Big job today. The green apple is moving into the pink plate, the orange into the yellow plate "
            "and the red apple into the blue plate. Which one goes in first is up to you."],
        3: ["The inventory says: carrot in the blue plate, orange in the yellow plate, green apple in the "
            "green plate, red apple in the pink plate. Load them in any order."],
        4: ["Ground floor first: move the green apple and the orange into the yellow plate, in either order. "
            "Only once both are in, the carrot and the red apple go into the blue plate, again in either "
            "order. Cheers, lads."],
    },
    "concierge": {
        1: ["Welcome to the hotel! The green apple is booked into the blue plate and the orange into the "
            "yellow plate."],
        2: ["Your itinerary for the day: green apple to the pink plate, orange to the yellow plate, red "
            "apple to the blue plate. The order of the visits is entirely flexible."],
        3: ["Room assignments are ready: carrot in the blue plate, orange in the yellow plate, green apple "
            "in the green plate and red apple in the pink plate. Check them in whatever order."],
        4: ["First, the green apple and the orange check into the yellow plate, either one first. Once that "
            "plate is full, the carrot and the red apple check into the blue plate, in any order. Have a "
            "pleasant stay."],
    },
}


# h267 (session 32, issues 24 and 28): held out. Task 4's two stages in a voice's own labels ("Leg one ...
# leg two", "Bed one / bed two", "Verse one / verse two"), chit-chat praising a person ("You're a gem"),
# an outside event before the list ("Before the train departs, ...") and "It doesn't matter which one boards
# first", in three voices of my own (a train conductor, a gardener, a choir director). Committed before any
# rule changed, scored once at the end, unchanged.
HELD_H267: dict[str, dict[int, list[str]]] = {
    "train_conductor": {
        2: ["Before the train departs, the green apple goes in the pink plate, the orange in the yellow "
            "plate and the red apple in the blue plate. It doesn't matter which one boards first. You're a "
            "gem."],
        4: ["Leg one of the journey: the green apple and the orange go into the yellow plate, in either "
            "order. Once both have boarded, leg two: the carrot and the red apple go into the blue plate, in "
            "either order too."],
    },
    "gardener": {
        1: ["Before the rain comes, put the green apple on the blue plate and the orange on the yellow "
            "plate. You're a lifesaver!"],
        4: ["Bed one: plant the green apple and the orange in the yellow plate, either one first. When both "
            "are in, bed two: the carrot and the red apple in the blue plate, in any order."],
    },
    "choir_director": {
        3: ["Put the carrot on the blue plate, the orange on the yellow plate, the green apple on the green "
            "plate and the red apple on the pink plate. It doesn't matter which one sings first. Bravo, "
            "maestro!"],
        4: ["Verse one: the green apple and the orange go on the yellow plate, in either order. Only after "
            "both are there, verse two: the carrot and the red apple go on the blue plate, in either order."],
    },
}


# h267's dev batch (session 32): the same classes in three voices of my own (a chef, a ship's captain, a
# coach), looked at and mended against.
DEV_H267: dict[str, dict[int, list[str]]] = {
    "chef": {
        1: ["Before service starts, put the green apple on the blue plate and the orange on the yellow "
            "plate. You're a star."],
        2: ["Green apple on the pink plate, orange on the yellow plate, red apple on the blue plate. It "
            "doesn't matter which one ships first."],
        4: ["Morning prep: the green apple and the orange into the yellow plate, either order. When both are "
            "in, evening prep: the carrot and the red apple into the blue plate, in either order.",
            "Course one: the green apple and the orange go on the yellow plate, either one first. Course two,"
            " only after course one: the carrot and the red apple go on the blue plate, in any order."],
    },
    "ship_captain": {
        1: ["Order up! The green apple on the blue plate and the orange on the yellow plate. Thanks, you're "
            "a hero."],
        3: ["Before we dock, the carrot goes on the blue plate, the orange on the yellow plate, the green "
            "apple on the green plate and the red apple on the pink plate. It doesn't matter which one goes "
            "out first. You're a champ."],
        4: ["Phase one of the voyage: put the green apple and the orange in the yellow plate, either one "
            "first. Once both are in, phase two: the carrot and the red apple go in the blue plate, in any "
            "order.",
            "Shift one: the green apple and the orange into the yellow plate, in either order. Shift two: the"
            " carrot and the red apple into the blue plate, in either order."],
    },
    "coach": {
        1: ["Before the whistle blows, the green apple goes to the blue plate and the orange to the yellow "
            "plate."],
        2: ["Green apple to the pink plate, orange to the yellow plate, red apple to the blue plate. It "
            "doesn't matter which one lands first. Great job, champ!"],
        4: ["Round one: the green apple and the orange go in the yellow plate, either order. Once both are "
            "in, round two: the carrot and the red apple go in the blue plate, either order.",
            "Half one: the green apple and the orange onto the yellow plate, in either order. Half two: the "
            "carrot and the red apple onto the blue plate, in either order."],
    },
}


# h270's held-out batch (session 33, issues 28 and 24): four rephrasings of each of the paper's four tabletop
# tasks, one per voice (a driving instructor, a hairdresser, a casino croupier, a tennis umpire), voices no
# batch above uses; written without reading the reader's code or trying any line, committed before any
# scoring and scored once, unchanged (results/experiments/h270.md). The expected reading of each line is its
# task's ground truth (suites/tabletop/tabletop_tasks.json), as listed above HELD_H210.
HELD_H270: dict[str, dict[int, list[str]]] = {
    "driving_instructor": {
        1: ["Right, hands at ten and two, nice and steady. Move the green apple onto the blue plate and "
            "the orange onto the yellow plate. Check your mirrors and off you go."],
        2: ["Today's route has three stops: the green apple pulls into the pink plate, the orange into "
            "the yellow plate and the red apple into the blue plate. Take the stops in whatever order "
            "feels comfortable."],
        3: ["Last lesson before your test. Park the carrot in the blue plate, the orange in the yellow "
            "plate, the green apple in the green plate and the red apple in the pink plate. You pick the "
            "order, just keep it smooth."],
        4: ["Two junctions on this drive. At the first one, the green apple and the orange go into the "
            "yellow plate, either one first. Don't pull off towards the second until both are in; there "
            "the carrot and the red apple go into the blue plate, in any order. Well driven."],
    },
    "hairdresser": {
        1: ["Sit back and relax, love. All I need is the green apple on the blue plate and the orange on "
            "the yellow plate. Looking gorgeous!"],
        2: ["Three to do before lunch: the green apple into the pink plate, the orange into the yellow "
            "plate, the red apple into the blue plate. Whoever goes first, I'm not fussed."],
        3: ["Busy Saturday in the salon! Pop the carrot in the blue plate, the orange in the yellow "
            "plate, the green apple in the green plate and the red apple in the pink plate. Do them in "
            "any order, sweetie."],
        4: ["Wash before cut, you know how it goes. So the green apple and the orange go in the yellow "
            "plate first, whichever of the two you like. Only when they're both in there do the carrot "
            "and the red apple go in the blue plate, again in any order."],
    },
    "croupier": {
        1: ["Place your bets, please. The green apple goes on the blue plate and the orange goes on the "
            "yellow plate. No more bets."],
        2: ["Three chips to place at this table: red apple onto the blue plate, green apple onto the "
            "pink plate, orange onto the yellow plate. Place them in any order, the house doesn't mind."],
        3: ["New shoe, new deal. Deal the carrot onto the blue plate, the orange onto the yellow plate, "
            "the green apple onto the green plate and the red apple onto the pink plate, in any order you "
            "please. Good luck at the table."],
        4: ["First round: the green apple and the orange land in the yellow plate, in either order. Once "
            "both are down, second round: the carrot and the red apple land in the blue plate, the order "
            "again up to you. Rien ne va plus."],
    },
    "tennis_umpire": {
        1: ["Quiet, please. Orange to the yellow plate, green apple to the blue plate. Play."],
        2: ["New balls, please. The green apple goes into the pink plate, the orange into the yellow "
            "plate and the red apple into the blue plate; the order of play is your choice."],
        3: ["Time. The carrot into the blue plate, the orange into the yellow plate, the green apple into "
            "the green plate and the red apple into the pink plate. No order is called, so take them "
            "however you like."],
        4: ["First set: the orange and the green apple into the yellow plate, in whichever order. The second "
            "set starts only after both of those are in: the carrot and the red apple into the blue "
            "plate, either order again. Thank you, players."],
    },
}


# h280's batches (session 33, issues 28 and 24): the classes HELD_H270 left (any order said the voice's way,
# a voice's sentence around the goals, placing verbs and stage labels of the voice), four rephrasings of
# each of the paper's four tabletop tasks, one per voice, voices no batch above uses. HELD_H280 (a bus
# driver, a cinema usher, a cab driver) was written with DEV_H280 (a dog groomer, a pit-crew chief, a
# postman) and committed before any rule changed; it is scored once at the end, unchanged
# (results/experiments/h280.md). Each line's expected reading is its task's ground truth, as listed above
# HELD_H210.
DEV_H280: dict[str, dict[int, list[str]]] = {
    "dog_groomer": {
        1: ["Next pup on the table! The green apple onto the blue plate and the orange onto the yellow "
            "plate. Whichever you start with, I'm not bothered."],
        2: ["Three to brush out today: green apple into the pink plate, orange into the yellow plate, red "
            "apple into the blue plate. The order of grooming is your call."],
        3: ["Bath time for four. Carrot in the blue plate, orange in the yellow plate, green apple in the "
            "green plate, red apple in the pink plate. I don't mind which goes first."],
        4: ["Two stations. The green apple and the orange go into the yellow plate first, either one. When "
            "both are in, the carrot and the red apple go into the blue plate, any order."],
    },
    "pit_crew_chief": {
        1: ["Box, box! Green apple onto the blue plate, orange onto the yellow plate, in any order. Go go "
            "go!"],
        2: ["Pit stop plan: the green apple into the pink plate, the orange into the yellow plate and the "
            "red apple into the blue plate. The sequence is up to you, nobody minds."],
        3: ["Full service. Carrot onto the blue plate, orange onto the yellow plate, green apple onto the "
            "green plate, red apple onto the pink plate. Do them however you like."],
        4: ["Two phases. Phase one: the green apple and the orange into the yellow plate, in either order. "
            "Phase two, only once both are in: the carrot and the red apple into the blue plate, in either "
            "order."],
    },
    "postman": {
        1: ["Morning delivery. The green apple goes on the blue plate, the orange goes on the yellow plate. "
            "No particular order, I'm not fussy."],
        2: ["Three parcels on my round: the green apple to the pink plate, the orange to the yellow plate, "
            "the red apple to the blue plate. Any order is fine by me."],
        3: ["Big round today. Carrot to the blue plate, orange to the yellow plate, green apple to the green "
            "plate and red apple to the pink plate; the order of the round is your choice."],
        4: ["First street: the green apple and the orange to the yellow plate, in any order. Only after both "
            "are delivered, the carrot and the red apple to the blue plate, in any order."],
    },
}
HELD_H280: dict[str, dict[int, list[str]]] = {
    "bus_driver": {
        1: ["Hold tight, please. The green apple onto the blue plate and the orange onto the yellow plate. "
            "Whoever gets off first, I'm not bothered."],
        2: ["Three stops on this route: the green apple into the pink plate, the orange into the yellow "
            "plate, the red apple into the blue plate. The order of the stops is your choice."],
        3: ["Last bus tonight. Carrot into the blue plate, orange into the yellow plate, green apple into "
            "the green plate and red apple into the pink plate, in any order, the driver doesn't mind."],
        4: ["Two stages on this route. First the green apple and the orange go into the yellow plate, in "
            "either order. Only once both are in, the carrot and the red apple go into the blue plate, in "
            "either order."],
    },
    "cinema_usher": {
        1: ["Tickets, please. The green apple goes on the blue plate and the orange goes on the yellow "
            "plate. Whichever goes first, I'm not fussy."],
        2: ["Three seats to fill: green apple in the pink plate, orange in the yellow plate, red apple in "
            "the blue plate. Seat them in whatever order you like."],
        3: ["Full house tonight. The carrot in the blue plate, the orange in the yellow plate, the green "
            "apple in the green plate and the red apple in the pink plate. Nobody minds the order."],
        4: ["Two rows. The green apple and the orange into the yellow plate first, either one first. When "
            "both are seated, the carrot and the red apple into the blue plate, again in any order."],
    },
    "cab_driver": {
        1: ["Where to, guv? Green apple to the blue plate, orange to the yellow plate. The order of the "
            "drops is your call."],
        2: ["Three drop-offs: the green apple to the pink plate, the orange to the yellow plate and the red "
            "apple to the blue plate. I don't mind which comes first."],
        3: ["Busy night on the meter. Carrot to the blue plate, orange to the yellow plate, green apple to "
            "the green plate, red apple to the pink plate; any order, I'm not fussed."],
        4: ["First fare: the green apple and the orange to the yellow plate, in either order. Once both are "
            "dropped, the carrot and the red apple to the blue plate, in either order."],
    },
}


# h286's held-out batch (session 34, issues 28 and 24): four rephrasings of each of the paper's four tabletop
# tasks, one per voice (a plumber, a cricket captain, an archivist, a sheriff), voices no batch above uses;
# written without reading the reader's code or trying any line, committed before any scoring and scored once,
# unchanged (results/experiments/h286.md). The expected reading of each line is its task's ground truth
# (suites/tabletop/tabletop_tasks.json), as listed above HELD_H210.
HELD_H286: dict[str, dict[int, list[str]]] = {
    "plumber": {
        1: ["Right, I've had a look and it's a simple job. The green apple goes in the blue plate and the "
            "orange goes in the yellow plate. Shouldn't take more than ten minutes."],
        2: ["Three fittings to sort today: the green apple into the pink plate, the orange into the yellow "
            "plate and the red apple into the blue plate. Which one you fit first makes no odds to me."],
        3: ["Full refit on this one, mate. The carrot in the blue plate, the orange in the yellow plate, "
            "the green apple in the green plate and the red apple in the pink plate. Tackle them in any "
            "order, it all drains the same in the end."],
        4: ["Same as any bathroom: pipes before tiles. So first the green apple and the orange go in the "
            "yellow plate, either one first. Once those two are both in, the carrot and the red apple go "
            "in the blue plate, in whatever order."],
    },
    "cricket_captain": {
        1: ["Right lads, field's set. Green apple goes to the blue plate, orange goes to the yellow plate. "
            "Let's get them all out before tea."],
        2: ["Three fielders to put in position: the green apple in the pink plate, the orange in the "
            "yellow plate, the red apple in the blue plate. The batting order doesn't matter here, take "
            "them as you like."],
        3: ["Four overs left, everyone. Carrot onto the blue plate, orange onto the yellow plate, green "
            "apple onto the green plate, red apple onto the pink plate. No set order, the captain's happy "
            "either way."],
        4: ["Two innings today. First innings: the orange and the green apple into the yellow plate, "
            "whichever goes first. The second innings doesn't start till both of them are in: then the "
            "carrot and the red apple into the blue plate, in either order. Well played."],
    },
    "archivist": {
        1: ["For the catalogue, please: the green apple is to be filed in the blue plate and the orange in "
            "the yellow plate. Kindly keep your voice down in the reading room."],
        2: ["Three items to shelve: the green apple in the pink plate, the orange in the yellow plate, the "
            "red apple in the blue plate. They may be shelved in any sequence; nothing here is indexed by "
            "order."],
        3: ["A new accession of four items. The carrot belongs in the blue plate, the orange in the yellow "
            "plate, the green apple in the green plate and the red apple in the pink plate. The order of "
            "filing is of no consequence."],
        4: ["This collection is processed in two batches. Batch one: the orange and the green apple are to "
            "go into the yellow plate, in either order. Batch two, which waits until batch one is "
            "complete: the carrot and the red apple go into the blue plate, again in either order."],
    },
    "sheriff": {
        1: ["Listen up, partner. That green apple's headed for the blue plate, and the orange for the "
            "yellow plate. Now git."],
        2: ["Three outlaws to round up: green apple into the pink plate, orange into the yellow plate, red "
            "apple into the blue plate. Don't matter none which you catch first."],
        3: ["This here town's got four jobs for you, deputy. Carrot on the blue plate, orange on the "
            "yellow plate, green apple on the green plate and red apple on the pink plate, any which way "
            "you like."],
        4: ["Here's how we play it, deputy. The green apple and the orange get put in the yellow plate "
            "first, whichever you reckon. Nobody touches the carrot or the red apple till those two are "
            "in; then the carrot and the red apple go in the blue plate, any order you like."],
    },
}


# h296's batches (session 34, issue 28): two rephrasings of each of the paper's four tabletop tasks per batch,
# one per voice, in voices no batch above uses (dev: a postwoman, a stagehand; held: a cobbler, a lumberjack),
# with a person's ease as the order's freedom, a voice's verb in "is to be ... in", and task 4's second stage
# said as a wait; written together and committed before any rule of that round; HELD_H296 is scored once,
# unchanged, at the end (results/experiments/h296.md). Truths: each task's ground truth, as above HELD_H210.
DEV_H296: dict[str, dict[int, list[str]]] = {
    "postwoman": {
        1: ["Morning! Two deliveries on my round. The green apple is to be posted in the blue plate and the "
            "orange in the yellow plate."],
        2: ["Three parcels for this street: the green apple to the pink plate, the orange to the yellow "
            "plate, the red apple to the blue plate. The sorting office is happy either way about the "
            "order."],
        3: ["Big sack today. The carrot goes in the blue plate, the orange in the yellow plate, the green "
            "apple in the green plate and the red apple in the pink plate. No fixed order, the depot's fine "
            "either way."],
        4: ["Two rounds today. Round one: the green apple and the orange go in the yellow plate, either one "
            "first. Round two doesn't start till both of those are in: then the carrot and the red apple go "
            "in the blue plate, any order."],
    },
    "stagehand": {
        1: ["Scene change, quick. The green apple is to be set in the blue plate and the orange in the "
            "yellow plate. Curtain up in five."],
        2: ["Three props to place: green apple in the pink plate, orange in the yellow plate, red apple in "
            "the blue plate. The director's easy either way on the order."],
        3: ["Props for act two: the carrot onto the blue plate, the orange onto the yellow plate, the green "
            "apple onto the green plate, the red apple onto the pink plate. Any order, the stage manager "
            "doesn't mind."],
        4: ["Act one: the green apple and the orange into the yellow plate, whichever first. Nobody touches "
            "the carrot or the red apple until those two are in. Then the carrot and the red apple into the "
            "blue plate, in any order."],
    },
}
HELD_H296: dict[str, dict[int, list[str]]] = {
    "cobbler": {
        1: ["The green apple is to be stitched into the blue plate, and the orange into the yellow plate. "
            "Good as new."],
        2: ["Three pairs to mend: the green apple into the pink plate, the orange into the yellow plate, the "
            "red apple into the blue plate. The customer's happy either way on order."],
        3: ["Carrot in the blue plate, orange in the yellow plate, green apple in the green plate, red apple "
            "in the pink plate. No particular order, the shop's fine either way."],
        4: ["Soles first: put the green apple and the orange in the yellow plate, either one first. Heels "
            "don't start till both are in: then the carrot and the red apple go in the blue plate, in any "
            "order."],
    },
    "lumberjack": {
        1: ["Timber! The green apple is to be hauled to the blue plate and the orange to the yellow plate."],
        2: ["Three logs to shift: the green apple to the pink plate, the orange to the yellow plate, the red "
            "apple to the blue plate. Foreman's happy whichever way you go."],
        3: ["The carrot goes on the blue plate, the orange on the yellow plate, the green apple on the green "
            "plate and the red apple on the pink plate. Whatever order suits, the crew's easy either way."],
        4: ["First load: the green apple and the orange into the yellow plate, whichever goes first. The "
            "second load waits till both of them are in; then the carrot and the red apple into the blue "
            "plate, either order."],
    },
}


# h302's held-out batch (session 35, issues 28 and 24): four rephrasings of each of the paper's four tabletop
# tasks, one per voice (a vicar, a firefighter, a jazz bandleader, a veterinarian), voices no batch above
# uses; written without reading the reader's code or trying any line, committed before any scoring and scored
# once, unchanged (results/experiments/h302.md). The expected reading of each line is its task's ground truth
# (suites/tabletop/tabletop_tasks.json), as listed above HELD_H210.
HELD_H302: dict[str, dict[int, list[str]]] = {
    "vicar": {
        1: ["Bless you for lending a hand. Would you kindly place the green apple in the blue plate, and the "
            "orange in the yellow plate? Peace be with you."],
        2: ["Three small offerings for the harvest festival: the green apple to the pink plate, the orange "
            "to the yellow plate and the red apple to the blue plate. The order is not a matter of doctrine; "
            "do them as you see fit."],
        3: ["Let us begin. The carrot is to rest in the blue plate, the orange in the yellow plate, the "
            "green apple in the green plate and the red apple in the pink plate. You may attend to them in "
            "whatever order seems right to you."],
        4: ["There is a proper order to this, as to all things. Firstly, the green apple and the orange go "
            "into the yellow plate, whichever of the two you prefer to begin with. Only when both are "
            "settled there should the carrot and the red apple be laid in the blue plate, again in no "
            "particular order. Amen."],
    },
    "firefighter": {
        1: ["Okay, we're on scene. Get the green apple onto the blue plate and the orange onto the yellow "
            "plate. Stay low and stay safe."],
        2: ["Three casualties to move: the green apple goes to the pink plate, the orange to the yellow "
            "plate, the red apple to the blue plate. Triage order doesn't matter on this shout, just get "
            "them all there."],
        3: ["Full turnout for this one, watch. Carrot on the blue plate, orange on the yellow plate, green "
            "apple on the green plate, red apple on the pink plate. Work them in any order you see fit. "
            "Helmets on."],
        4: ["Here's the plan of attack. First the green apple and the orange go in the yellow plate, in any "
            "order. Once both are in, and not before, the carrot and the red apple go in the blue plate, "
            "whichever first. Go!"],
    },
    "jazz_bandleader": {
        1: ["Hey cats, easy groove on this one: the green apple in the blue plate, the orange in the yellow "
            "plate. Dig it?"],
        2: ["Okay, a three-bar tune. Green apple into the pink plate, orange into the yellow plate, red "
            "apple into the blue plate. Improvise the order, anything goes."],
        3: ["Take it from the top, band. Carrot to the blue plate, orange to the yellow plate, green apple "
            "to the green plate and red apple to the pink plate. Play them in whatever order swings for "
            "you."],
        4: ["This number has two choruses. In the first, the green apple and the orange go into the yellow "
            "plate, and you can lead with either one. The second chorus only kicks in once both of those are "
            "in: the carrot and the red apple into the blue plate, in whatever order grooves. Nice and "
            "cool."],
    },
    "veterinarian": {
        1: ["Let's get this sorted before the next appointment. Please put the green apple in the blue plate "
            "and the orange in the yellow plate. Gently does it."],
        2: ["Three patients on the list this morning: the green apple is for the pink plate, the orange for "
            "the yellow plate and the red apple for the blue plate. See them in any order you like."],
        3: ["Busy clinic today. The carrot needs to go on the blue plate, the orange on the yellow plate, "
            "the green apple on the green plate and the red apple on the pink plate. It makes no difference "
            "to me which you do first."],
        4: ["First up are the green apple and the orange: into the yellow plate they go, either one first. "
            "After that, and only after that, the carrot and the red apple go into the blue plate, in "
            "whatever order. Who's a good boy, then?"],
    },
}


# h308's batches (session 35, issue 28): two voices per batch, the four tabletop tasks each, in voices no
# batch above uses (dev: a thatcher, a scaffolder; held: a milliner, a tiler), with the order's freedom said
# as "whichever order" / "either one first" (task 4 inside a stage), a lone stage label, and chat with the
# system's words ('look', 'let's get going'); written together, HELD_H308 committed before any rule and
# scored once, unchanged, at the end (results/experiments/h308.md). Truths: as above HELD_H210.
DEV_H308: dict[str, dict[int, list[str]]] = {
    "thatcher": {
        1: ["Weather's fine, let's get going. The green apple goes on the blue plate and the orange on the "
            "yellow plate."],
        2: ["The green apple into the pink plate, the orange into the yellow plate, the red apple into the "
            "blue plate, in whichever order suits."],
        3: ["Carrot on the blue plate, orange on the yellow plate, green apple on the green plate, red apple "
            "on the pink plate. Whichever one first, no matter."],
        4: ["First round: the green apple and the orange onto the yellow plate, either one first. Then the "
            "carrot and the red apple onto the blue plate, in any order."],
    },
    "scaffolder": {
        1: ["Hard hats on. Green apple to the blue plate, orange to the yellow plate."],
        2: ["Three poles to put up: green apple in the pink plate, orange in the yellow plate, red apple in "
            "the blue plate. Either one first."],
        3: ["Put the carrot in the blue plate, the orange in the yellow plate, the green apple in the green "
            "plate and the red apple in the pink plate, in whichever order."],
        4: ["Stage one: the green apple and the orange into the yellow plate, in whichever order. Once both "
            "are in, the carrot and the red apple into the blue plate, either one first."],
    },
}
HELD_H308: dict[str, dict[int, list[str]]] = {
    "milliner": {
        1: ["Try this on for size. The green apple goes in the blue plate and the orange in the yellow "
            "plate."],
        2: ["Three hats on the stand today: the green apple to the pink plate, the orange to the yellow "
            "plate, the red apple to the blue plate, in whichever order."],
        3: ["Put the carrot in the blue plate, the orange in the yellow plate, the green apple in the green "
            "plate and the red apple in the pink plate. Take them in whichever order you fancy. A perfect "
            "fit."],
        4: ["First fitting: the green apple and the orange go in the yellow plate, in whichever order. When "
            "both are in, the carrot and the red apple go in the blue plate, either one first."],
    },
    "tiler": {
        1: ["Grout's mixed, have a look. Green apple into the blue plate, orange into the yellow plate."],
        2: ["Green apple in the pink plate, orange in the yellow plate, red apple in the blue plate. Lay "
            "them in any order you like."],
        3: ["Four tiles to set: carrot on the blue plate, orange on the yellow plate, green apple on the "
            "green plate, red apple on the pink plate, whichever first."],
        4: ["Stage one: the green apple and the orange into the yellow plate, either one first. Stage two "
            "waits till those are set: the carrot and the red apple into the blue plate, any order."],
    },
}
