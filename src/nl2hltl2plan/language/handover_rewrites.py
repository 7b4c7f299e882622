"""The rewrites of the four-arm handover worlds' reader (`handover_phrases.normalise` applies them): each
maps a writer's variant (a synonym, a British form, an abbreviation, a polite or legal turn) onto the form
the patterns of `handover_words` read, and changes no meaning (typos are mended before, by
`handover_typos`). The table is data; the code that applies it is in `handover_phrases`."""

from nl2hltl2plan.language.handover_words import (
    AFTER_ALL,
    DONE_STATE,
    DROP,
    EMPTY,
    FIRST_STEP,
    GERUND_VERBS,
    LATER_STEP,
    NEG,
    NEGATED_GERUNDS,
    PERIOD_WORDS,
    SET_OFF_FOR,
    STEP_NUMBER,
    STEP_WORD,
    SWAP,
    TOUCH,
    VERB,
    WAY_IDIOM,
)

# a heading's label of a rule ("Rule:", "Constraint:")
_RULE_LABEL = (
    r"(?:(?:sequence|sequencing|order|ordering|timing|safety|placement|additional|extra|main|key|special)\s+)?"
    r"(?:order|ordering|sequence|constraints?|rules?|requirements?|restrictions?|conditions?|caution|warning|"
    r"important|nb|notice|attention|reminder|"
    # a note's label: it asks for attention and says nothing itself ("Careful: ...", "Please note: ...")
    r"(?:be\s+)?careful|(?:please\s+)?note|heads\s+up|remember|do\s+not\s+forget|tip|fyi|ps)"
)
# an intensifier before a word of necessity adds no meaning ("it is very important that ...")
_INTENSIFIER = r"(?:(?:very|really|extremely|absolutely|vitally|critically|most|quite)\s+)?"

# a region said to be free, and a goal on it after a comma ("region g is free, put the yellow block there")
_FREED = (
    rf"(?:region\s+)?(?P<r>[e-j])\s+(?:is|has\s+been|becomes|gets)\s+(?:{EMPTY}|vacated|available|freed(?:\s+up)?)"
    r"\s*,\s*(?P<goal>[^,;]*?)\s+(?:there|on\s+it|in\s+it|to\s+it)\b"
)

# a negative phrase that opens a prohibition with its subject after the verb, the auxiliaries it takes, its
# subject (any object: "no" takes the article's place), and "nowhere but"'s region letters
_NEG_OPEN = (
    r"(?:under\s+no\s+circumstances|on\s+no\s+account|in\s+no\s+case|at\s+no\s+(?:time|point|stage|moment)|"
    r"not\s+once|never)"
)
_AUX = r"(?P<aux>may|can|should|must|shall|will|could|is|are)"
_THING = r"(?:object|block|pillar|cube|item|piece)s?"
_ANY_THING = rf"(?:(?:an?|any)\s+)?(?P<thing>{_THING})"
_BUT = r"(?:but|except|other\s+than|apart\s+from|besides)"
_LETTERS = (
    r"(?:regions?\s+)?[e-j](?:\s*,\s*(?:region\s+)?[e-j])*(?:\s*,?\s*(?:and|or)\s+(?:region\s+)?[e-j])?"
)

# Rewrites applied to the lower-cased sentence before any phrase is read: each maps a variant onto the
# form the patterns read and changes no meaning ("prior to" -> "before", "whilst" -> "while").
REWRITES: tuple[tuple[str, str], ...] = (
    (  # (also after a step said first: "after all of these, the plan is to put ...")
        r"(^|,)\s*(?:your|the|my|our)\s+(?:job|task|goal|mission|assignment|plan)\s*(?:is\s+to\b|:)",
        r"\1 please",
    ),
    (r"(?<=s)'(?=\s|$)", ""),  # the blocks' positions -> the blocks positions
    # "first X, and finally Y" with nothing between: a pair of steps, as "first X, and then Y" (the last of
    # all the goals only where more than one goal comes before it)
    (r"\bfirst\b([^,.;:]*),\s*(?:and\s+)?(?:finally|lastly)\b", r"first\1, and then"),
    (r"\bwhilst\b", "while"),
    # "..., at any step" after labelled steps: at any point of them, as "at any time" says
    (r"\b(?:at|during|in)\s+any\s+(?:step|stage)\b", "at any time"),
    # "once region G is free, put the yellow block back there": the world lets a block down only on a free
    # region, so waiting for the goal's own region to be free is what any plan does ("if" stays: a condition)
    (
        rf"\b(?P<done>(?:once|when|after)\s+(?:everything|all\s+(?:of\s+)?(?:this|that|these|it)|this|that|it)\s+"
        rf"(?:is|are|has\s+been|have\s+been)\s+{DONE_STATE})\s+and\s+{_FREED}",
        r"\g<done>, \g<goal> on region \g<r>",
    ),
    (rf"\b(?:once|when|as\s+soon\s+as)\s+{_FREED}", r"\g<goal> on region \g<r>"),
    # "only touch the blue block once the red one has been touched": a touch rule said as a permission
    (
        rf"\bonly\s+({TOUCH})\s+([^,;]+?)\s+(?:once|after|when)\s+(?=(?:the\s+)?(?:red|blue|yellow)\b)",
        r"do not \1 \2 until ",
    ),
    # "never put one anywhere else": "one" after a negated placing verb is any block, not a count of one
    (
        rf"\b({NEG})\s+({VERB}|set|leave|drop)\s+one\b(?=\s+(?:anywhere|elsewhere|outside|on|onto|in|into|down)\b)",
        r"\1 \2 any block",
    ),
    # before "it" is read as a block: "while you're at it" is the period of the goals
    (r"\bwhile\s+(?:you|we)\s+are\s+at\s+it\b", "meanwhile"),
    (r"\bamongst\b", "among"),
    (r"\bunless\s+and\s+until\b", "until"),  # legal English
    (r"\blet\s*'?\s*s\b|\blet\s+us\b|\bgo\s+ahead\s+and\b", "please"),
    (
        r"\b(?:whenever\s+(?:you\s+(?:like|want|wish|please|can)|(?:is\s+|s\s+)?convenient|possible|(?:it\s+)?suits(?:\s+you)?)|"
        r"at\s+(?:any|whatever)\s+(?:point(?:\s+in\s+time)?|moment|stage)|(?:at\s+)?any\s+time\s+you\s+(?:like|want))\b",
        "at any time",
    ),
    (r"\bat\s+any\s+time\s+that\s+(?:works|suits)(?:\s+(?:for\s+)?you)?\b", "at any time"),
    # "when you get a chance", "whenever you have a moment": the time is the writer's to leave free
    (
        r"\b(?:when|whenever)\s+(?:you|they|the\s+arms)\s+(?:get|have|find)\s+(?:a|the)\s+(?:chance|moment|minute)\b",
        "at any time",
    ),
    # "you two," "you both,": the arms addressed at a clause's start, set off by a comma
    (r"(^|,)\s*you\s+(?:two|both|all|guys|lot)\s*,", r"\1 "),
    (
        r"\b(?:sequentially|in\s+sequence|successively|in\s+succession|consecutively|one\s+after\s+the\s+other)\b",
        "one after another",
    ),
    (r"\b(?:earlier\s+than|prior\s+to|ahead\s+of|in\s+advance\s+of|sooner\s+than)\b", "before"),
    (r"\blater\s+than\b", "after"),
    (r"\buntil\s+after\b", "until"),
    (r"\b(?:i|we)\s*would\s+like\b", "want"),
    # framing that announces a rule: "there is one ordering requirement:", "with the rule that"
    (
        r"\bthere\s+(?:is|are)\s+(?:one|a|an|another|two|some)\s+(?:\w+\s+)?(?:requirement|restriction|constraint|"
        r"condition|rule)s?(?:\s+(?:about|on|for|regarding)\s+\w+)?\s*(?::|,\s*namely(?:\s+that)?\b)",
        " ",
    ),
    (r"\s*,?\s*\bwith\s+the\s+(?:rule|condition|constraint|requirement|restriction)\s+that\b", ","),
    (r"\bin\s+addition(?:\s+to\s+(?:that|this))?\b", " "),
    # a heading, also after a step's number: "Rule: ...", "2) Constraint: ...", "Goals:"
    (rf"^({STEP_NUMBER}){_RULE_LABEL}\s*:", r"\1"),
    # a completion marker as a heading: "when the transfer is done: yellow back to G"
    (rf"^\s*({AFTER_ALL})\s*:", r"\1 ,"),
    # "only" before a completion clause stresses it: "only after every other step is over, put ..." (after)
    (rf"(^|,)\s*only\s+(?=(?:{AFTER_ALL}))", r"\1 "),
    # a rule's label after a comma, in a compressed heading: "Goal: ..., constraint: red before blue"
    (rf",\s*{_RULE_LABEL}\s*:", ","),
    (rf"^({STEP_NUMBER})(?:objectives?|goals?|tasks?|aims?|missions?|instructions?)\s*:", r"\1 please"),
    # casual openers: "ok so ..." (a closer, "... pls", "thanks", is a courtesy word: `handover_registers`)
    (r"^\s*(?:(?:ok(?:ay)?|alright|right|so|well|hi|hello|hey)\b\s*,?\s*)+", " "),
    (r"\b(?:till|til)\b", "until"),
    (r"\b([a-z]+)\s+s\s+been\b", r"\1 has been"),  # "till red's been touched"
    (r"\b(?:any\s+)?(?:stuff|things)\b(?=\s+(?:on|in|onto|into)\b)", "anything"),
    # a prohibition opened by a negative phrase, its subject after the verb ("at no point during this period
    # is an object placed on F", "never may a block be put on H"): said in the usual order, its "during this
    # period" at the end ("no object is placed on F during this period")
    (
        rf"^(?P<neg>\s*{_NEG_OPEN})\s*,?\s*(?P<period>{PERIOD_WORDS})\s*,?\s+(?P<rest>(?={_AUX}\s+{_ANY_THING}\s).*?)"
        r"\s*[.!]?\s*$",
        r"\g<neg> \g<rest> \g<period>",
    ),
    (
        rf"(^|[,;]\s*|\band\s+){_NEG_OPEN}\s+{_AUX}\s+{_ANY_THING}(?=\s+(?:be|{DROP}|on|in)\b)",
        r"\1no \g<thing> \g<aux>",
    ),
    # "nowhere but E, F or G may a pillar be put down", "a pillar may be put down nowhere except E, F or G":
    # never on a region other than those
    (
        rf"(^|[,;]\s*|\band\s+)nowhere\s+{_BUT}\s+(?:(?:on|in)\s+)?(?P<places>{_LETTERS})\s*,?\s+{_AUX}\s+"
        rf"{_ANY_THING}\s+be\s+(?P<verb>{DROP})\b",
        r"\1no \g<thing> \g<aux> be \g<verb> on a region other than \g<places>",
    ),
    (
        rf"(^|[,;]\s*|\band\s+)(?:an?|any)\s+(?P<thing>{_THING})\s+{_AUX}\s+be\s+(?P<verb>{DROP})\s+nowhere\s+"
        rf"{_BUT}\s+(?:(?:on|in)\s+)?(?P<places>{_LETTERS})",
        r"\1no \g<thing> \g<aux> be \g<verb> on a region other than \g<places>",
    ),
    (
        r"\b(?:under\s+no\s+circumstances|on\s+no\s+account|at\s+no\s+(?:time|point|stage|moment))\s+"
        r"(?=(?:place|put|drop|set|touch|move)\b)",
        "never ",
    ),
    # a prohibition said as a field: "not allowed (meanwhile): any object on regions F, G and H"
    (
        rf"^\s*(?:not\s+allowed|forbidden|prohibited|disallowed)(\s+{PERIOD_WORDS})?\s*:\s*(?:placing\s+|putting\s+)?"
        r"(?:any|an?)\s+(objects?|blocks?|pillars?|items?|pieces?)\s+(?=(?:on|onto|in|into)\b)",
        r"no \2 may be placed \1 ",
    ),
    # a prohibition said as a command with "no": "place no object on F during such period"
    (
        r"\b(?:place|put|set|drop|placing|putting|setting|dropping)\s+(no\s+(?:objects?|blocks?|pillars?|items?|pieces?)|"
        r"nothing)\b",
        r"\1 may be placed",
    ),
    (r"\bat\s+some\s+(?:point|time)\s+(?=before|after)\b", ""),  # "put down at some point before ...": before
    # "at no point will they place ...": the inverted "never"
    (
        r"\bat\s+no\s+(?:point|time|stage|moment)\s+(?:will|shall|should|may|can|must)\s+(?:they|we|you|the\s+arms)\s+"
        r"(?=(?:place|put|drop|set|touch|move)\b)",
        "never ",
    ),
    (r"\bat\s+(?:some|whatever|whichever)\s+(?:point|time|moment|stage)\b", "at any time"),
    # a hedge of time opening a sentence or after "will", or ending a one-clause sentence, orders nothing
    # (after a goal, "..., and eventually put it on G", it may mean "then": unread); "later on" only before
    # an order that says what it follows ("later on, once that is done") or "also" (an added step)
    (r"(^\s*|\bwill\s+(?:also\s+)?)(?:eventually|sooner\s+or\s+later|in\s+due\s+course)\b\s*,?", r"\1 "),
    (r"^((?:(?!\band\b|\bthen\b)[^,;])*?)\s*\b(?:eventually|sooner\s+or\s+later|in\s+due\s+course)$", r"\1"),
    (r"\blater\s+on\s*,?\s*(?=(?:once|when|after)\b|(?:(?:we|they|the\s+arms)\s+will\s+)?also\b)", " "),
    # the one-block rule said of each region: "no more than one block shall be placed on each of said regions"
    (
        r"\b(?:(?:no|not)\s+more\s+than|at\s+most)\s+one\s+(block|object|pillar|item)\s+(?:shall|may|can|should|must|will|"
        r"is\s+to)\s+be\s+(?:placed|put|set)\s+(?:on|in|onto)\s+each(?:\s+of\s+(?:said|such|those|these|the)\s+regions|"
        r"\s+(?:such\s+|said\s+)?region)\b",
        r"one \1 per region",
    ),
    # a causative before a block: "have the red block land before the blue block" (as "make ...")
    (r"(^|,|\band)\s*have\s+(?=(?:the\s+)?(?:red|blue|yellow|three|all|both)\b)", r"\1 "),
    (r"\s*,\s*go\s*$", " "),  # a coach's start signal after the goal: "three blocks, opposite side, go!"
    # "one block per region, no more": the count's "no more" restates it
    (
        r"\b((?:one|a\s+single)\s+(?:block|object|pillar|item)\s+(?:per|to\s+a|in\s+each|on\s+each|for\s+each)\s+"
        r"(?:region|area|cell|spot))\s*,?\s*(?:and\s+)?no\s+more\b",
        r"\1",
    ),
    (r"\bnowhere\s+(?=else\b|other\s+than\b|except\b|but\b)", "not anywhere "),  # "..., and nowhere else"
    (r"\bnothing\s+else\b", "nothing"),
    (r"\bno\s+other\s+(?=(?:blocks?|objects?|items?|cubes?|pillars?|pieces?)\b)", "no "),
    (r"\bthe\s+(?:last|final)\s+step\s+is\s+to\b", "finally"),
    (r"^\s*(?:the\s+)?(?:last|final)\s+step\s*:", "finally ,"),  # "Last step: yellow back on G"
    (r"\s*,?\s*\b(?:tho|though)\s*$", " "),  # "red has to go before blue tho"
    (r"\bthe\s+first\s+step\s+is\s+to\b", "first"),
    (r"\bthe\s+(?:next|second)\s+step\s+is\s+to\b", "then"),
    (
        r"\bthe\s+first\s+(?:block|object|one)\s+(?:to\s+be\s+placed|placed|to\s+go)\s+(?:must|should|has\s+to|will)\s+be\s+"
        r"(?:the\s+)?(red|blue|yellow)(?:\s+(?:block|one))?",
        r"\1 first",
    ),
    (r"\b(?:any|either|one)\s+of\s+(?=(?:the\s+)?(?:(?:goal|target)\s+)?(?:regions?|areas?|zones?)\b)", ""),
    (r"\barrange\s+for\b", " "),  # "arrange for the blocks to be moved to ..."
    # "red <-> blue": an exchange; "pillars -> E, F, G": a goal
    (
        r"\b([a-z]+(?:\s+(?:block|one))?)\s*(?:<\s*-\s*>|↔)\s*([a-z]+(?:\s+(?:block|one))?)\b",
        r"swap \1 with \2",
    ),
    # a chain of arrows is a sequence of stops: "yellow -> I -> G"
    (r"\s*(?:→|->|=>)\s*([e-j])\s*(?:→|->|=>)\s*", r" to \1 , then to "),
    (r"\s*(?:→|->|=>)\s*", " to "),
    # abbreviations: "b4", "1st", "opp. side" (the full stop of "opp." is kept from ending the sentence)
    (r"\bb4\b", "before"),
    # "<rule> as you move X ...": the rule holds while you do it ("as" of time before "you" and a verb)
    (rf"\bas\s+you\s+(?={VERB}\b)", "while you "),
    (r"\bcan\s+happen\s+(?=at\s+any\s+time\b)", ""),  # "moving yellow ... can happen at any time"
    # texting: "2" for "to" before a place or an arm ("2 the opposite side", "2 regions e , f n g", "next 2
    # arms"; a count of regions names as many letters), "n" for "and", "1" for "one" as a pronoun
    (
        r"\b2\s+(?=(?:the|any|opposite|arms?|region\s+[e-j]|regions\s+[e-j]\s*(?:,|and|n)\s*[e-j]\s*(?:,|and|n)\s*[e-j]|[e-j])\b)",
        "to ",
    ),
    (r"(?<=[a-z,])\s+n\s+(?=[a-z])", " and "),
    (r"\bmv\b", "move"),
    # an order with its subject after the verb: "before the blue block goes the red block"
    (
        r"(^|,|;|\band\b)\s*before\s+((?:the\s+)?(?:red|blue|yellow)(?:\s+block)?)\s+(?:goes|comes)\s+"
        r"((?:the\s+)?(?:red|blue|yellow)(?:\s+block)?)\b",
        r"\1 \3 goes before \2",
    ),
    (r"\s+k\s*(?=(?:please\s*)?$)", " "),  # "... k thx": ok, a closer
    (r"\b1\s+(?=after\s+(?:another|the\s+other)\b)", "one "),
    (r"\b(red|blue|yellow|the)\s+1\b", r"\1 one"),
    (r"\b1\s*st\b", "first"),
    (r"\bopp\b\.?", "opposite"),
    (r"\b(?:please\s+)?(?:be\s+advised|be\s+aware|note)\s+that\b", " "),
    (r"\s*,?\s*\bit\s+being\s+understood\s+that\b", ","),
    (
        r"^\s*here\s*(?:s|is)\s+what\s+(?:should|must|has\s+to|needs\s+to|will)\s+(?:happen|be\s+done)\s*:?\s*$",
        " ",
    ),
    (r"^\s*(?:two|three|a\s+few)\s+things\s*:", " "),
    (r"\b(?:somebody|someone|anybody|anyone)\b", "an arm"),  # "until somebody has touched the red block"
    # narrative verbs of moving: "makes a stop at I", "moves on to G", "takes the blue block's place"
    (r"\b(?:makes?|making)\s+a\s+stop\s+(?:at|on|in)\b", "goes to"),
    (SET_OFF_FOR, "goes to"),  # idioms of moving (`handover_words`): "heads (on over) to", "makes its way to"
    (WAY_IDIOM, "goes "),
    (
        r"\b(?:takes?|gets?|occup(?:y|ies))\s+(?=(?:the\s+)?(?:red|blue|yellow)\s+(?:block\s+|one\s+)?s\s+"
        r"(?:place|position|spot)\b)",
        "goes to ",
    ),
    # framing that announces the task: "what needs to happen is ..."
    (r"^\s*what\s+(?:needs|has)\s+to\s+(?:happen|be\s+done)\s+is\s+(?:that\s+)?", " "),
    # a heading verb that names an exchange: "Swap: red and blue blocks"
    (r"^\s*(swap|exchange|switch)\s*:\s*(?:(?:swap|exchange|switch)\b)?", r"\1 "),
    # a heading that gives the period of what follows: "Meanwhile: nothing on F, G or H"
    (rf"^\s*({PERIOD_WORDS})\s*:\s*(.+)$", r"\2 \1"),
    (r"(?<!\bin\s)\bany\s+order\b", "in any order"),
    # the state asked for, said as where the blocks end up: "the blocks should end up spread over H, I and J"
    (r"\bend\s+up\s+(?=(?:spread|distributed|split|placed|put)\b)", "be "),
    # non-native: "yellow block go back region G", "firstly",
    # "after to region G" (after, then a preposition: afterwards)
    (r"\b(go|goes|come|comes|put|move|return)\s+back\s+(?=regions?\b)", r"\1 back to "),
    (r"\bfirstly\b", "first"),
    (r",\s*after\s+(?=(?:to|on|onto|in|into)\s)", ", then "),
    (r"\s*,?\s*\bon\s+the\s+other\s+hand\b\s*,?", " "),
    (r"^\s*then\s+again\s*,", " "),  # "Then again, ...": "on the other hand", not a step
    (r"^\s*as\s+(?:for|to|regards)\s+(?:the\s+)?(?:order|ordering|sequence)\s*,", " "),
    (r"\b(?:once|when|after)\s+it\s+(?:is|gets|has\s+been\s+placed)\s+there\s*,", " then "),
    (r"\b(?<!to\s)(?<!on\s)(?<!in\s)anywhere\s+(?:empty|free)\b", "to any empty region"),
    # "use regions G, H and I for the three blocks": put them there
    (
        r"\buse\s+(regions?\s+[e-j](?:\s*(?:,|and|or)\s*(?:region\s+)?[e-j])*)\s+for\s+"
        r"(the\s+(?:three\s+)?(?:blocks|objects|pillars))\b",
        r"put \2 in \1",
    ),
    (r"\s*,?\s*\bwhereas\b", ", and"),
    (r"\s*,?\s*\bwhereby\b", ","),
    (rf"^\s*({VERB})\s*:", r"\1"),  # "Transfer: 3 blocks -> opposite side"
    (r"\bthe\s+(?:desired\s+)?(?:outcome|result|end\s+state)\s+(?:is|should\s+be)\s+that\b", " "),
    (rf"\bit\s+is\s+{_INTENSIFIER}(?:necessary|required|essential|important)\s+to\b", "please"),
    # a prohibition, before its "it" is read as a block: "it is forbidden to place any object on F"
    (r"\bit\s+is\s+(?:forbidden|prohibited|not\s+allowed|not\s+permitted)\s+to\b", "do not"),
    (r"\bno\s+placements?\s+(?=outside|on|in|onto|anywhere)", "nothing placed "),
    (
        r"\s*,?\s*(?:and\s+|but\s+)?it\s+does\s+not\s+matter\s+(?:when|at\s+what\s+(?:point|time|moment)|at\s+which\s+point)"
        r"(?:\s+(?:that|this|it)\s+(?:happens|is\s+done))?",
        " at any time",
    ),
    # non-native: "when is not important", "time is free": the timing is free
    (
        r"\s*,\s*(?:the\s+)?(?:when|time|timing)\s+(?:is\s+)?(?:not\s+important|free|does\s+not\s+matter)\s*(?=,|$)",
        " at any time",
    ),
    # "..., no restrictions on when": the timing is free (read once where "at any time" comes just before it)
    (
        r"(\bat\s+any\s+time\s*)?,\s*(?:with\s+)?no\s+(?:restrictions?|constraints?|limits?)\s+on\s+"
        r"(?:when|the\s+timing|timing|the\s+time)\s*(?=,|$)",
        " at any time",
    ),
    (r"^\s*when\s+(?:placing|putting|moving)\s+(?:them|the\s+blocks)\s*,", " "),
    (r"\b(?:needs?|gets?|has|have|takes?)\s+(?=its\s+own\s+(?:region|area|spot|place)\b)", "goes in "),
    (r"\breach(?:es)?\s+(?=(?:the|any|an?|regions?|[e-j])\b)", "go to "),
    (rf"\b(?:also|too)\s+(?=(?:has|have|needs?|must|should|shall|will|can|may|{VERB})\b)", ""),
    (r"\bat\s+(?:an?\s+)?(?:arbitrary|unspecified|any\s+given)\s+(?:time|point|moment)\b", "at any time"),
    (r"\b(?:is|are)\s+(?:required|obliged|supposed|expected)\s+to\b", "must"),
    (r"\bvisits?\b", "goes to"),
    # the doer named formally: "the agent shall transfer ...", "the system must move ..."
    (
        rf"^\s*(?:the\s+)?(?:agent|agents|system|robot\s+system|planner|team|robot\s+team|operator)\s+"
        rf"(?:must|should|will|shall|needs?\s+to|has\s+to|is\s+to|are\s+to)\s+(?={VERB}\b|exchange|swap|fill)",
        "please ",
    ),
    # one modal for obligation: "is to be / has to be / needs to be / ought to be placed" -> "must be placed"
    (r"\b(?:is|are|has|have|needs?|ought)\s+to\s+be\b", "must be"),
    # "is left alone", "stays left alone": untouched (said of a block; "leave X alone until" is read as it is)
    (r"\b(is|are|be|gets?|stays?|remains?)\s+left\s+alone\b", r"\1 left untouched"),
    # "must stay / remain untouched", "is to be left untouched": not touched
    (
        r"\b(?:must\s+|should\s+|shall\s+|will\s+)?(?:stay|remain|be\s+left|be\s+kept)\s+untouched\b",
        "must not be touched",
    ),
    (r"\bone\s+after\s+(?:one|other)\b", "one after another"),
    (r"\bwont\b", "will not"),
    (r"\b(do|does|can|should|must|is|are)nt\b", r"\1 not"),  # "dont", "shouldnt" without the apostrophe
    (r"\bcant\b", "can not"),  # "can't" without the apostrophe ("can" + "nt" is "cannt")
    # who asks: "the operator requires that the blocks be moved ..."; "please do the following:"
    (
        r"^\s*(?:the\s+)?(?:operator|user|client|customer|supervisor|lab|team|we|i)\s+(?:require|request|ask|want)s?\s+"
        r"that\b",
        " ",
    ),
    (
        r"^\s*(?:please\s+)?(?:(?:the\s+)?(?:arms|robots)\s+(?:should|must|will|need\s+to|have\s+to)\s+)?"
        r"(?:do|carry\s+out|perform|follow)\s+(?:the\s+following|these\s+steps)(?:\s+steps)?\s*:?",
        " ",
    ),
    (r"(?<=[a-z])\s*\+\s*(?=[a-z])", " and "),  # "red + blue"
    # "while moving them, ...": the period of the goals
    (
        r"\bwhile\s+(?:you\s+(?:are\s+)?)?(?:moving|placing|transferring|carrying|bringing|doing)\s+"
        r"(?:them|it|this|that|so|the\s+(?:blocks|pillars|objects))\b",
        "meanwhile",
    ),
    # reasons that say nothing but that the order or the timing was meant
    (
        r"\s*,?\s*\b(?:(?:as|since|because)\s+(?:(?:the\s+)?order\s+(?:matters|is\s+important)(?:\s+here)?|that\s+is\s+the\s+"
        r"order\s+(?:we|i)\s+(?:need|want))|so\s+that\s+the\s+order\s+is\s+(?:right|correct|kept|respected))\b",
        " ",
    ),
    (
        r"\s*,?\s*\b(?:as|since|because)\s+(?:their|its|the)\s+timing\s+(?:is\s+free|does\s+not\s+matter|is\s+up\s+to\s+you)\b",
        " in any order",
    ),
    (
        r"\b(blocks|pillars|objects|cubes|items)\s*\(\s*(two|three|four|\d)\s*\)",
        r"\2 \1",
    ),  # "pillars (three)"
    # non-native: "the blue block is not allow to touch": not to be touched (a block is the subject: not "the
    # arm is not allowed to touch the blue block")
    (
        r"(?:(?<=block\s)|(?<=blocks\s)|(?<=red\s)|(?<=blue\s)|(?<=yellow\s)|(?<=object\s)|(?<=pillar\s))"
        r"(?:is|are)\s+not\s+allow(?:ed)?\s+to\s+(?:be\s+)?(?:touch(?:ed)?|grab(?:bed)?|pick(?:ed)?\s+up|lift(?:ed)?)\b",
        "must not be touched",
    ),
    (r"\bchange\s+(?=(?:the\s+)?(?:positions?|places?)\s+of\b)", "exchange "),
    (r"\b(that|it|there|what|here)\s+s\b", r"\1 is"),  # "a region that's not a target"
    # "..., than place ...": a typo ("than" is never comparative between a comma and a verb)
    (r"(?<=,)\s*than\s+(?=(?:place|put|move|transfer|bring|take)\b)", " then "),
    (
        r"^\s*(?:with\s+(?:that|this)(?:\s+(?:rule|constraint|condition|requirement)|\s+in\s+mind)?|that\s+said|"
        r"having\s+said\s+that)\s*,",
        " ",
    ),
    (r"\band\s+(?:because|since)\s+", "and "),
    # a rule's label with its period: "Restriction for the duration: F, G and H remain empty"
    (rf"^\s*{_RULE_LABEL}\s+({PERIOD_WORDS})\s*:\s*(.+)$", r"\2 \1"),
    # a reason clause: read as a clause of the instruction ("because regions F, G and H must stay clear, ...")
    (rf"^({STEP_NUMBER})(?:because|since)\s+", r"\1 "),
    (r"\s*,\s*(?:because|since)\s+", ", and "),
    (r"\s*,\s*so\s+(?!that\b|as\b|long\b|far\b|on\b)", ", "),
    (r"\s*,?\s*(?:since|because|as)\s+(?:the|their)\s+order\s+does\s+not\s+matter\b", " in any order"),
    # a rule announced: "the only ordering rule is that ...", "be careful about one thing:"
    (
        r"\b(?:the|one|an?|another)\s+(?:only\s+)?(?:other\s+)?(?:ordering\s+|order\s+)?"
        r"(?:rule|constraint|requirement|restriction|condition)\s+is\s+(?:that\b|:)",
        " ",
    ),
    (r"\b(?:be\s+careful|pay\s+attention)\s+(?:about|to)\s+(?:one|this|the\s+following)\s+thing\s*:", " "),
    # "the blocks shall occupy regions H, I and J": go there (not "occupy R with the blocks")
    (
        r"\b((?:blocks|pillars|objects|cubes|items)\s+(?:(?:shall|should|must|will|are\s+to|need\s+to|have\s+to)\s+)?)"
        r"occupy\s+(?=(?:the\s+)?(?:(?:goal|target)\s+)?regions?\b)",
        r"\1go to ",
    ),
    # "they simply need to be moved", "the yellow block only has to reach ..."
    (
        r"\b(?:simply|merely|just|only)\s+(?=(?:needs?|ha(?:s|ve))\s+to\b)|\b(?:simply|merely|just)\s+(?=must\b)",
        "",
    ),
    # "to region I and, after that, to region G"
    (r"(?:\s+and)?\s*,\s*(?:after\s+that|afterwards?|subsequently|thereafter)\s*,", ", then"),
    (
        r"\b(?:plan|find|give|compute)\s+(?:a\s+)?(?:solution|plan)\s+(?:that|which)\s+(move|put|place|transfer|bring)s\b",
        r"\1",
    ),
    # framing that asks for the plan of a task: "plan how to move ...", "find a way to move ..."
    (
        r"^\s*(?:please\s*,?\s*)?(?:(?:plan|figure\s+out|work\s+out|find\s+out|determine|decide|show\s+(?:me|us)|"
        r"tell\s+(?:me|us))\s+how\s+to|(?:find|devise|come\s+up\s+with|work\s+out|make|create|produce|generate|"
        r"write)\s+(?:a|the)\s+(?:way|plan|schedule|sequence\s+of\s+actions)\s+(?:to|for\s+the\s+arms\s+to))\b",
        "please",
    ),
    (r"\b(?:manipulators|grippers|end\s+effectors|robotic\s+arms)\b", "arms"),
    (r"\b(?:manipulator|gripper|end\s+effector|robotic\s+arm)\b", "arm"),
    (r"\bin\s+(?:an|the|such\s+an)\s+order\s+(?:where|in\s+which|that|such\s+that)\b", ","),
    (r"\s*,?\s*\bsubject\s+to\s+the\s+(?:constraint|condition|rule|requirement)\s+that\b", ","),
    # "under no circumstances should an object be put on R": an object should never be put on R ("at no point
    # is an object to be put on R": an object is never to be put on R)
    (
        r"\b(?:under\s+no\s+circumstances|at\s+no\s+(?:time|point))\s+(should|may|can|must|shall|is|are)\s+"
        r"(an?\s+\w+|any\s+\w+|objects|blocks|nothing|anything)\s+(to\s+)?be\b",
        r"\2 \1 never \3be",
    ),
    # "at no point may a region hold two blocks": no region may hold two blocks
    (
        r"\b(?:under\s+no\s+circumstances|at\s+no\s+(?:time|point))\s+(should|may|can|must|shall|will)\s+"
        r"(?:an?|any)\s+(region|area|zone)\s+(?=(?:hold|contain|receive|get|take|have)\b)",
        r"no \2 \1 ",
    ),
    (r"\bpreceding\b", "before"),
    (r"\b(?<!the\s)following\b", "after"),
    # where the blocks start adds nothing to where they go: "from their current regions"
    (
        r"\bfrom\s+(?:their|its|the)\s+(?:current|present|starting|initial|original)\s+"
        r"(?:regions?|positions?|places?|locations?|spots?|sides?)\b",
        " ",
    ),
    (
        rf"\bit\s+is\s+(?:hereby\s+)?{_INTENSIFIER}(?:required|necessary|important|essential|requested|desired|"
        r"expected|mandatory|imperative|agreed|understood|stipulated|ordered|directed)\s+that\b",
        " ",
    ),
    # legal English goes on with "and that" after "it is agreed that X": the second requirement is its own
    (r"(?<=,)\s*and\s+that\s+(?=(?:the|each|every|no|all|both|any)\b)", " and "),
    # "the goal is to have the blocks on ...": the state asked for, as a goal
    (r"\b(please|to)\s+have\s+(?=(?:the|all|both|each|every)\b)", r"\1 get "),
    # a numbered step: the first, or one after the step before
    # (a comma after it, so that a step without a verb reads as "First, yellow block to I")
    (rf"^\s*{FIRST_STEP}\s*", "first , "),
    (rf"^\s*{LATER_STEP}\s*", "then , "),
    # a later step inside the sentence: "first step, put yellow on I, second step, put it on G"
    (
        rf",\s*(?:{STEP_WORD}\s+(?:[2-9]|two|three|four|five)|(?:second|third|next)\s+{STEP_WORD})\b\s*[:,-]?",
        ", then , ",
    ),
    (r"^\s*(?:second(?:ly)?|third(?:ly)?|fourth(?:ly)?)\s*[:,]", "then "),
    (r"^\s*(first|then)\s*,?\s*\1\b\s*,?", r"\1 "),  # "2) Then move it ...": the step's "then" said twice
    (r"\b(finally|lastly|then|next|afterwards|first)\s*:", r"\1 ,"),  # "Finally: yellow -> G"
    # a reminder of a prohibition is the prohibition: "remember not to put ...", "be sure not to touch ..."
    (r"\b(?:remember|be\s+(?:sure|careful|certain)|make\s+sure|take\s+care)\s+not\s+to\b", "do not"),
    (
        r"\b(?:(?:remember|be\s+(?:sure|careful)|make\s+sure|do\s+not\s+forget|note|(?:keep|bear)\s+in\s+mind|be\s+aware|know)\s+"
        r"(?:to|that)|(?:verify|check|confirm)\s+that|(?:keep|bear)\s+in\s+mind)\b",
        " ",
    ),
    (r"\bprecedes?\b", "comes before"),
    # (not "as follows" nor an imperative "Follow me ...": a refusal would name "comes after", never said)
    (r"(?<!\bas\s)(?<!^)(?<!^\s)\bfollows?\b", "comes after"),
    (
        r"\b(?:nobody|no\s+one|none\s+of\s+the\s+(?:robot\s+)?arms|neither\s+(?:of\s+the\s+)?(?:robot\s+)?arms?)\b",
        "no arm",
    ),
    # "the red and blue blocks are in the wrong places, so swap them": the scene said as the swap it asks for
    (
        rf"^\s*((?:the\s+)?[a-z]+\s+and\s+(?:the\s+)?[a-z]+\s+(?:blocks|cubes|pieces|ones))\s+(?:are|were)\s+in\s+"
        rf"(?:the\s+wrong|each\s+other\s*s?)\s+(?:places|spots|positions)\s*,\s*(?:so\s+)?({SWAP})\s+(?:them|their\s+positions)\b",
        r"\2 \1",
    ),
    # "after all these done" (non-native, without "are")
    (r"\b(after\s+all\s+(?:of\s+)?(?:these|this|that))\s+done\b", r"\1 are done"),
    # "..., never more than one block per region": the world's rule
    (r"\bnever\s+more\s+than\s+(?=one\b)", "no more than "),
    # "please note the red block goes first": a rule, as "note:" is
    (r"^\s*(?:please\s+)?note\s+(?:that\s+)?(?=the\b)", " "),
    (r"\b(has|have|needs?)\s+to\s+get\s+to\b", r"\1 to go to"),  # "the yellow block has to get to ..."
    # "each of regions H, I and J can only hold one block, so put the three blocks into them": the world's
    # one-block rule, and the regions named for the goal that follows
    (
        r"^\s*each\s+of\s+(?:the\s+)?(regions\s+[e-j](?:\s*,\s*[e-j])*\s*,?\s*and\s+[e-j])\s+"
        r"(?:(?:can|should|may|must|will|shall)\s+)?(?:only\s+)?(?:hold|take|contain|get|end\s+up\s+with)\s+"
        r"(?:only\s+|exactly\s+)?(?:one|a\s+single)\s+(?:block|object)\s*,\s*(?:so\s+)?"
        r"(.*?)\b(?:those\s+regions|them)\b",
        r"\2 \1 , one block per region ",
    ),
    # "regions H, I and J each get one block: put the three blocks there": the regions said first, as the
    # subject of the world's one-block rule, then the goal that puts the blocks "there" (read only with
    # "each", which makes the count one per region)
    (
        r"^\s*(regions\s+[e-j](?:\s*,\s*[e-j])*\s*,?\s*and\s+[e-j])\s+(?:each\s+(?:gets?|takes?|receives?|holds?)\s+"
        r"(?:only\s+|exactly\s+)?(?:one|a\s+single)\s+(?:block|object)|(?:gets?|takes?|receives?|holds?)\s+"
        r"(?:only\s+|exactly\s+)?(?:one|a\s+single)\s+(?:block|object)\s+each)\s*:\s*(.*?)\s+there\b",
        r"\2 on \1 , one block per region ",
    ),
    # a reason that says again that the places kept empty must stay so: "keep regions F, G and H empty in
    # the meantime, as they must stay clear"
    (
        r"(\b(?:empty|clear|free|nothing)\b[^,]*),\s*(?:as|since|because)\s+they\s+(?:must|have\s+to|need\s+to)\s+"
        r"(?:stay|remain|be\s+kept)\s+(?:empty|clear|free)\s*$",
        r"\1",
    ),
    # a heading that forbids places: "Forbidden meanwhile: regions F, G and H"
    (
        rf"^\s*(?:forbidden|prohibited|off\s+limits|keep\s+(?:empty|clear|free))\s*({PERIOD_WORDS})?\s*:\s*"
        r"(?=(?:the\s+)?(?:regions?\s+)?[e-j]\b)",
        r"\1 , nothing on ",
    ),
    # "regions H, I and J are reserved, so never put any object on them": the reason said as the rule it
    # gives, read only where a prohibition on them follows
    (
        rf"\b(?:are|is)\s+(?:reserved|in\s+use|off\s+limits|blocked)\b(?=\s*(?:{PERIOD_WORDS})?\s*,\s*"
        r"(?:do\s+not|never|put\s+nothing|place\s+nothing|nothing)\b[^,]*?\b(?:on|in|onto|into)\s+them\s*$)",
        "must stay empty",
    ),
    # "put one block each into regions H, I and J": one block in each of them
    (
        r"\bone\s+(block|object|cube|pillar|piece|item)\s+each\s+(?:in|into|on|onto|to)\s+(?=(?:the\s+)?regions\b)",
        r"one \1 in each of ",
    ),
    (
        r"\bdo\s+not\s+let\s+(?:any\s+|an?\s+|the\s+)?(?:robot\s+)?(?:arms?|robots?)\s+",
        "no arm may ",
    ),
    # "don't let any object be placed on F", "never let the blue block be touched": the object's own
    # prohibition, as "no object should be placed on F" and "the blue block should not be touched"
    (
        r"\b(?:do\s+not|never)\s+let\s+(?:any|an?)\s+(object|block|pillar|cube|item)s?\s+be\b",
        r"no \1 should be",
    ),
    (r"\b(?:do\s+not|never)\s+let\s+anything\s+be\b", "nothing should be"),
    (
        r"\b(?:do\s+not|never)\s+let\s+(the\s+(?:(?:red|blue|yellow)\s+)?(?:block|pillar|object|cube)s?)\s+be\b",
        r"\1 should not be",
    ),
    # "the regions across from where they are now": the opposite side
    (
        r"\b(?:the\s+)?(?:regions?|areas?|side|zones?)\s+across\s+from\s+(?:where\s+(?:they|it|the\s+blocks?)\s+"
        r"(?:are|is|start|started|were|was|lie|sit)(?:\s+(?:now|currently|at\s+first))?|it|them)\b",
        "the opposite side",
    ),
    # "put it on I before putting it on G": the steps in order
    (
        r"\s*,?\s*\bbefore\s+(?:placing|putting|moving|bringing|transferring|taking|carrying|setting)\b",
        ", then put",
    ),
)
REWRITES += tuple(
    (rf"\b(?:avoid|refrain\s+from)\s+{gerund}\b", f"do not {verb}")
    for gerund, verb in NEGATED_GERUNDS.items()
)
REWRITES += tuple(
    # a negated modal before a gerund (non-native): "the arm cannot touching the blue block"
    (rf"\b(cannot|must\s+not|should\s+not|do\s+not)\s+{gerund}\b", rf"\1 {verb}")
    for gerund, verb in (GERUND_VERBS | NEGATED_GERUNDS).items()
)
REWRITES += tuple(
    (rf"\s*,?\s*\b(?:without\s+(?:ever\s+)?|never\s+){gerund}\b", f" and never {verb}")
    for gerund, verb in NEGATED_GERUNDS.items()
    if verb not in ("touch", "grab", "pick up")  # "without touching X before Y" is a touch rule
)
