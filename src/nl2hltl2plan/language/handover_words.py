"""The word classes of the four-arm handover worlds' reader (`handover_reading`), as regular
expressions: placing verbs and prepositions, modifiers, negations, touching and dropping verbs, the
"during this period" and "after all of these" phrases, and the polite lead-ins the reader skips."""

VERB = r"(?:transfer|move|put|place|bring|carry|take|deliver|relocate|shift|get|set|send|return)"
PREP = r"(?:to|into|onto|on|in|at|towards?|over\s+to|in\s+to|on\s+to)"
MOD = (
    r"(?:separately|individually|one\s+after\s+another|one\s+by\s+one|one\s+at\s+a\s+time|in\s+turn|each|"
    r"all|at\s+any\s+time|any\s+time|whenever|as\s+well|too|across|over)"
)
GERUND = r"(?:placing|putting|moving|transferring|bringing|carrying|delivering)"
DONE = r"(?:placed|put|moved|transferred|delivered|carried|brought|done|handled|go|goes)"
NEG = (
    r"(?:cannot|can\s+not|can\s+t|must\s+not|mustn\s+t|should\s+not|shouldn\s+t|may\s+not|do\s+not|"
    r"does\s+not|don\s+t|doesn\s+t|(?:is|are)\s+not\s+allowed\s+to|never|not)"
)
TOUCH = r"(?:touch|pick\s+up|pick|grasp|grab|handle|move|lift)"
TOUCHED = (
    r"(?:touched|picked\s+up|picked|grasped|grabbed|handled|moved|lifted|touches|picks\s+up|grabs|moves)"
)
DROP = r"(?:placed|put|dropped|set|left|laid)"
PERIOD = (
    r"(?:\s*,?\s*(?:during\s+this\s+(?:period|time)|in\s+the\s+meantime|meanwhile|while\s+doing\s+(?:so|this)|"
    r"until\s+then|throughout|at\s+any\s+time|ever|at\s+all))?"
)
AFTER_ALL = (
    r"(?:after\s+all\s+(?:of\s+)?(?:these|this|that|the\s+above)|after\s+all\s+that|once\s+(?:all\s+)?"
    r"(?:this|these|that)\s+(?:is|are|has\s+been|have\s+been)\s+done|when\s+(?:all\s+)?(?:this|these|that)\s+"
    r"(?:is|are)\s+done|finally|lastly|at\s+the\s+end|in\s+the\s+end)"
)
LEAD = r"\s*,?\s*(?:you\s+should\s+|please\s+|we\s+should\s+)?"
