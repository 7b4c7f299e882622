"""The word classes of the four-arm handover worlds' reader (`handover_reading`), as regular
expressions: placing verbs and prepositions, modifiers, negations, touching and dropping verbs, the
"during this period" and "after all of these" phrases, step numbers, and the gerunds read as verbs. The
rewrites that map a writer's variants onto the forms these classes read are in `handover_rewrites`."""

VERB = (
    r"(?:transfer|move|put|place|bring|carry|take|deliver|relocate|shift|get|set|send|return|distribute|"
    r"spread|position|drop|arrange|want|need|lay|deposit|pop|collect|gather|ferry|shuttle|haul|lug)"
)
PREP = r"(?:to|into|onto|on|in|at|towards?|over\s+to|in\s+to|on\s+to|among|across|over)"
MOD = (
    r"(?:separately|separate|individually|one\s+after\s+another|one\s+by\s+one|one\s+at\s+a\s+time|in\s+turn|each|"
    r"all|at\s+any\s+time|any\s+time|whenever|in\s+any\s+order|as\s+well|too|across|over)"
)
GERUND = (
    r"(?:placing|putting|moving|transferring|bringing|carrying|delivering|taking|getting|shifting|laying)"
)
DONE = (
    r"(?:placed|put|moved|transferred|delivered|carried|brought|taken|shifted|relocated|returned|sent|"
    r"arranged|positioned|distributed|spread|done|handled|set|transfer|move|place|bring|carry|deposited|return|"
    r"collected|gathered|ferried|shuttled|hauled|lugged|"
    r"conveyed|returns|belongs?|rests?|travels?|"
    r"dropped|go|goes|going|end\s+up|ends\s+up|land|lands)"
)
# a passive goal's or order's modal: "should", "is to", "can", "has to" ... ("be" follows, optional)
MODAL = (
    r"(?:(?:should|must|shall|will|can|may|could|would|has\s+to|have\s+to|needs?\s+to|ought\s+to|is\s+to|to|"
    r"are\s+to|gets?|is|are|being|having\s+been)\s+)?(?:(?:all|each|both|first|only|also)\s+)?(?:be\s+)?"
)
NEG = (
    r"(?:cannot|can\s+not|can\s+t|must\s+not|mustn\s+t|should\s+not|shouldn\s+t|may\s+not|do\s+not|"
    r"does\s+not|don\s+t|doesn\s+t|(?:is|are)\s+not\s+allowed\s+to|never|not)"
)
# "now" as a scene statement says it, after its verb ("where the red block is at present / sitting at the
# moment / for the time being")
NOW = (
    r"(?:currently|presently|(?:right\s+|just\s+)?now|initially|at\s+first|at\s+the\s+start|at\s+present|"
    r"at\s+(?:the|this)\s+(?:moment|time)|for\s+(?:now|the\s+time\s+being))"
)
SWAP = r"(?:exchang(?:e|ing)|swap(?:ping)?|switch(?:ing)?|interchang(?:e|ing)|trad(?:e|ing))"
SWAPPED = r"(?:swapped|exchanged|switched|interchanged)"
TOUCH = r"(?:touch|pick\s+up|pick|grasp|grab|handle|move|lift)"
TOUCHED = (
    r"(?:touched|picked\s+up|picked|grasped|grabbed|handled|moved|lifted|touches|picks\s+up|grabs|moves)"
)
TOUCHING = r"(?:touching|picking\s+up|picking|grabbing|grasping|handling|lifting|moving)"
DROP = (
    r"(?:placed|put|dropped|set|left|laid|deposited|positioned|moved|brought|carried|transferred|stored|"
    r"place|drop)(?:\s+down)?"  # "place": a non-native passive ("region F can not place any object")
)
# "during this period": a prohibition's scope, the goals of its sentence (else all goals so far); legal
# English says "during such period", "during said period"
PERIOD_WORDS = (
    r"(?:(?:during|in)\s+(?:this|that|such|(?:the\s+)?said|the\s+same)\s+(?:whole\s+|entire\s+)?(?:period|time|stretch|spell)|"
    r"for\s+(?:this|that|the)\s+(?:whole|entire)\s+(?:period|time|stretch|spell)|in\s+the\s+meantime|meanwhile|"
    r"while\s+doing\s+(?:so|this|that|it)|while\s+(?:this|that)\s+(?:happens|is\s+happening|goes\s+on|is\s+going\s+on)|"
    r"during\s+(?:all\s+)?(?:this|that)(?=\s*(?:$|,|;))|at\s+the\s+same\s+time|"
    r"in\s+the\s+process|all\s+the\s+while|the\s+whole\s+time|in\s+the\s+interim|"
    r"throughout(?:\s+(?:this|the|that)\s+(?:process|period|time))?|until\s+then|along\s+the\s+way|in\s+between|"
    # "until you are done", "till done": until the goals are met (a plan ends when its last goal is met)
    r"until\s+(?:(?:you|we|they)\s+(?:are|have\s+finished)\s+)?(?:all\s+)?(?:done|finished)|"
    r"until\s+(?:it|this|that|everything)\s+is\s+(?:done|finished|complete)|"
    r"for\s+as\s+long\s+as\s+(?:this|that|it)\s+takes|for\s+the\s+whole\s+of\s+(?:this|that|the)\s+(?:time|period)|"
    r"while\s+(?:this|that|it)\s+is\s+(?:in\s+progress|under\s+way|ongoing)|"
    r"until\s+the\s+(?:job|task|work|transfer)\s+is\s+(?:done|finished|complete|over)|"
    # "during the whole task", "for the duration of this task", "while you do this", "while this is done"
    r"(?:during|throughout|for)\s+(?:this|that|the)\s+(?:whole\s+|entire\s+)?(?:task|process|job|operation|transfer|game|exercise)|"
    r"for\s+the\s+(?:whole\s+|entire\s+)?duration(?:\s+of\s+(?:this|that|the)\s+(?:task|process|period|job|operation))?|"
    r"while\s+(?:you|we|they|the\s+arms)\s+(?:are\s+)?(?:do|doing|carry\s+out|carrying\s+out|perform|performing)\s+"
    r"(?:this|that|it|so)|while\s+(?:this|that|it)\s+(?:is|gets)\s+(?:being\s+)?done)"
)
PERIOD = rf"(?:\s*,?\s*(?:{PERIOD_WORDS}|at\s+any\s+time|ever|at\s+all))?"
EMPTY = r"(?:empty|free|clear|unoccupied|vacant)"
# the work said before as the other steps: "every other step", "(all) the other / remaining tasks"
OTHER_WORK = (
    r"(?:every\s+other\s+(?:step|stage|phase|part|task|job|move)|(?:all\s+(?:of\s+)?)?(?:the\s+)?(?:other|remaining)\s+"
    r"(?:steps|stages|phases|parts|tasks|jobs|moves))"
)
DONE_STATE = (
    r"(?:done|finished|complete|completed|over|sorted(?:\s+out)?|settled|taken\s+care\s+of|dealt\s+with|out\s+of\s+the\s+way|"
    r"wrapped\s+up)"
    # "done with that"
    rf"(?:\s+with\s+(?:all\s+(?:of\s+)?)?(?:this|these|that|it|everything(?:\s+else)?|them|the\s+above|the\s+rest|{OTHER_WORK}))?"
)
# "as soon as" opens the same clauses as "once" ("as soon as everything else is done, ...")
# "(all) the rest" is the work said before, as "everything else" ("once all the rest is done, ...")
AFTER_ALL = (
    r"(?:(?:once|when|after|as\s+soon\s+as)\s+(?:all\s+(?:of\s+)?)?(?:this|these|that|it|everything(?:\s+else)?|the\s+above|"
    rf"the\s+rest|{OTHER_WORK})(?:\s+all)?\s+"
    rf"(?:is|are|has\s+been|have\s+been)\s+(?:all\s+)?{DONE_STATE}|(?:once|when)\s+{DONE_STATE}|"
    rf"(?:once|when|after|as\s+soon\s+as)\s+(?:you|we)\s+(?:are|have(?:\s+been)?)\s+(?:all\s+)?{DONE_STATE}|"
    # an absolute opener: "with that done", "with all of this sorted", "that done"
    rf"(?:with\s+(?:all\s+(?:of\s+)?)?(?:this|these|that|it|everything(?:\s+else)?|the\s+above|the\s+rest|{OTHER_WORK})|that)"
    rf"(?:\s+all)?\s+{DONE_STATE}(?=\s*,)|"
    r"after\s+(?:all\s+(?:of\s+)?(?:these|this|that|"
    rf"the\s+above)|everything(?:\s+else)?|(?:(?:all\s+)?the\s+rest|{OTHER_WORK})(?=\s*,))|finally|lastly|last\s+of\s+all|at\s+the\s+(?:very\s+)?end|in\s+the\s+end|"
    r"after\s+(?:finish(?:ing)?|complet(?:e|ing)|doing|done)\s+(?:with\s+)?(?:all\s+(?:of\s+)?)?(?:this|these|that|everything|them|"
    rf"the\s+rest|{OTHER_WORK})|"
    r"after\s+(?:finishing|completing)\s+(?:it\s+)?all|after\s+(?:that|this|the)\s+(?:transfer|task|move)|"
    # "when the transfer is complete", "when all finish" (non-native): the work said so far is done
    rf"(?:once|when|after)\s+(?:the|this|that)\s+(?:transfer|task|job|work|moving|transport)\s+(?:is|has\s+been)\s+{DONE_STATE}|"
    r"(?:once|when|after)\s+(?:all|everything)\s+(?:is\s+|are\s+|has\s+|have\s+)?(?:finish(?:ed)?|done|complete(?:d)?)|"
    r"as\s+(?:a|the)\s+(?:final|last)\s+step|to\s+(?:finish|end|conclude|wrap\s+up|close)(?:\s+(?:off|up))?(?=\s*,)|at\s+last|after\s+all(?=\s*,)|(?:up)?on\s+(?:completion|finishing)(?:\s+of\s+(?:this|these|that|the\s+above|all\s+(?:of\s+)?(?:this|these|that)))?)"
)
THEN = (
    r"(?:then|after\s+that|afterwards?|next|subsequently|later|and\s+then|(?:and\s+)?from\s+there|"
    r"after\s+which|thereafter)"
)
# a place named again in other words: "the placement area, which consists of regions E, F and G"
APPOSITION = (
    r"(?:\(|which\s+(?:is|are)\s+made\s+up\s+of|(?:which\s+(?:is|are|lies?|sits?)\s+|that\s+(?:is|are|lies?)\s+)?"
    r"(?:(?:located|situated|lying)\s+)?(?:to|on|at|in)|that\s+is|being|"
    r"which\s+(?:is|are|consists\s+of|comprises|includes|lies|lie)|consisting\s+of|comprising|"
    r"made\s+up\s+of|(?:that\s+is\s+|which\s+is\s+)?(?:formed|made|composed|covered)\s+(?:by|of)|namely|:)"
)
LEAD = r"\s*,?\s*(?:you\s+should\s+|please\s+|we\s+should\s+)?"
# an enumerated step: "Step 2", "Stage two", "Second step", "2)", "(2)", "(b)", "b)" (a list's letters a-d,
# never a region's); the first of them, and the ones after it
STEP_WORD = r"(?:step|stage|phase|part)"
FIRST_STEP = (
    rf"(?:{STEP_WORD}\s+(?:1|one)\b\s*[:,-]?|(?:the\s+)?first\s+(?:{STEP_WORD}|point|thing)\b\s*[:,-]?|1\s*[):-]|"
    r"\(\s*1\s*\)|\(\s*a\s*\)|a\s*\))"
)
LATER_STEP = (
    rf"(?:{STEP_WORD}\s+(?:[2-9]|two|three|four|five)\b\s*[:,-]?|(?:the\s+)?(?:second|third|fourth|fifth|next)\s+"
    rf"(?:{STEP_WORD}|point|thing)\b\s*[:,-]?|[2-9]\s*[):-]|\(\s*[2-9]\s*\)|\(\s*[b-d]\s*\)|[b-d]\s*\))"
)
STEP_NUMBER = rf"\s*(?:{FIRST_STEP}|{LATER_STEP}|{STEP_WORD}\s+\w+\s*[:-]?)?\s*"

# "would you mind moving ...": a request, read as the verb
GERUND_VERBS = {
    "moving": "move",
    "transferring": "transfer",
    "bringing": "bring",
    "carrying": "carry",
    "taking": "take",
    "swapping": "swap",
    "exchanging": "exchange",
}
# "avoid placing", "refrain from touching", "without putting": a negated verb
NEGATED_GERUNDS = {
    "placing": "place",
    "putting": "put",
    "dropping": "drop",
    "setting": "set",
    "touching": "touch",
    "grabbing": "grab",
    "picking up": "pick up",
}

# idioms of moving, said of the thing moved ("makes its way to", "find their way onto", "heads on over to",
# "moseys on back to": "back" is kept, it says the place the thing left; "sets off for", "are headed for",
# h296): every reader reads them as "goes to" / "goes" (a verb's tense and number change nothing a task needs)
SET_OFF_FOR = (
    r"\b(?:(?:sets?|setting|heads?|heading)\s+off|(?:is|are)\s+(?:headed|heading))\s+(?:for|towards?)\b"
)
# a voice's steps of a dance or a stroll, said of the thing moved ("the yellow block dances to region I",
# "promenade over to", "sashay off to"; h296)
_STEPS = (
    r"danc(?:es?|ing)|promenad(?:es?|ing)|sashay(?:s|ing)?|waltz(?:es|ing)?|glid(?:es?|ing)|hops?|hopping|"
    r"strolls?|strolling|trots?|trotting|ambl(?:es?|ing)|saunter(?:s|ing)?"
)
WAY_IDIOM = (
    r"\b(?:(?:makes?|making|made|finds?|finding|found|wends?|wending)\s+(?:its|their)\s+way|heads?|heading|"
    rf"moseys?|moseying|cross(?:es)?|crossing|{_STEPS})(?:\s+(?:on|over|off|along|across))*\s+"
    r"(?=(?:back\s+)?(?:to|towards?|into|onto)\b)"
)
