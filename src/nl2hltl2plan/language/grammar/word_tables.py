"""Word tables of the offline parser: verbs, prepositions, temporal markers, state words.

Everything here is plain data (regular expressions and sets); `parser.py` applies it.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language import grounding
from nl2hltl2plan.language.content_words import phrase_list_pattern, word_categories
from nl2hltl2plan.language.courtesy import courtesy_pattern

# ----- verbs ---------------------------------------------------------------------------------------
# class: place (move something somewhere), pick (take hold), clean/heat/cool/slice (change state),
# fill (fill with water: the object is rinsed in the sink), light (switch a lamp), examine (look at),
# trash (throw away: destination garbage can), other (open/close...: no task of its own).
_VERBS: dict[str, tuple[str, ...]] = {
    "place": (
        "put",
        "place",
        "move",
        "set",
        "bring",
        "carry",
        "transfer",
        "deliver",
        "store",
        "stash",
        "leave",
        "return",
        "position",
        "lay",
        "stick",
        "insert",
        "hang",
        "load",
        "relocate",
        "secure",
        "drop",
        "stack",
        "arrange",
        "slide",
        "deposit",
        "locate",
        "shift",
        "send",
        "keep",
        "tuck", "stow",
        "serve",
        # casual moving verbs check 1 knows (`verb_any`): without them the grammar read "pop the tomato in
        # the fridge and then the pan in the sink" as nothing (a verb left out after it needs a verb here)
        "pop",
        "plop",
        "plonk",
        "shove",
        "pack",  # "pack the remote in the cardboard box"
        "transport",
    ),
    "pick": (
        "pick",
        "grab",
        "retrieve",
        "gather",
        "collect",
        "take",
        "get",
        "hold",
        "lift",
        "obtain",
        "acquire",
        "fetch",
        "find",
        "locate",
        "remove",
        "use",
        "holding",
        "carrying",
    ),
    "clean": ("wash", "rinse", "clean", "scrub", "wet", "cleanse", "moisten"),
    "heat": ("heat", "warm", "cook", "microwave", "bake", "toast", "boil", "reheat", "nuke", "zap"),
    "cool": ("chill", "cool", "refrigerate", "freeze", "frost"),
    "slice": ("slice", "cut", "chop", "dice", "section"),
    "fill": ("fill",),
    "light": ("turn", "switch", "lit", "light", "toggle", "power", "illuminate"),
    "examine": (
        "examine",
        "inspect",
        "view",
        "check",
        "see",
        "study",
        "observe",
        "read",
        "look",
        "glance",
        "scan",
        "investigate",
        "analyze",
        "analyse",
    ),
    "trash": ("throw", "toss", "discard", "dispose", "trash", "bin", "chuck", "dump"),
    "other": (
        "open",
        "close",
        "shut",
        "exchange",
        "swap",
        "empty",
        "finish",
        "complete",
        "do",
        "make",
        "go",
        "walk",
        "head",
    ),
}


_PLACING = word_categories("placing_verbs.txt")  # the placing verbs kept in a word file (h278)
_VERBS["place"] += tuple(sorted(_PLACING["place"]))
_DOUBLED = frozenset("put set get cut sit shut swap drop chop pop plop stop dump".split())
_DOUBLED |= _PLACING["doubled"]


def _gerund(v: str) -> str:
    if v.endswith("ing"):
        return v
    if v in _DOUBLED:
        return v + v[-1] + "ing"
    if v in {"lit"}:
        return "lighting"
    if v.endswith("e") and not v.endswith(("ee", "ye")):
        return v[:-1] + "ing"
    return v + "ing"


# "only after you've thrown the bottle in the bin": the participle of a task a reference states
_IRREGULAR_PAST = {
    "take": "taken", "throw": "thrown", "hold": "held", "get": "got", "bring": "brought", "find": "found"
}  # fmt: skip


def _past(v: str) -> str:
    if v in {"put", "set", "cut", "lit", "shut", "read"}:
        return v
    if v in _IRREGULAR_PAST:
        return _IRREGULAR_PAST[v]
    if v.endswith("e"):
        return v + "d"
    if v.endswith("y") and v[-2] not in "aeiou":
        return v[:-1] + "ied"
    if v in {"drop", "chop", "stop", "swap", "plop", "pop"} | _PLACING["doubled"]:
        return v + v[-1] + "ed"
    return v + "ed"


VERBS: dict[str, tuple[str, str]] = {}  # surface -> (class, base)
for _cls, _words in _VERBS.items():
    for _w in _words:
        for _form in {_w, _gerund(_w), _w + "s", _w + "es"}:
            VERBS.setdefault(_form, (_cls, _w))
VERB_PAST: dict[str, tuple[str, str]] = {}  # "placing the statue" refs use gerunds; "the box is examined"
for _cls, _words in _VERBS.items():
    for _w in _words:
        VERB_PAST.setdefault(_past(_w), (_cls, _w))

# words that start a new clause when they follow one of these (then a verb must come next)
CLAUSE_JOINERS = {
    "and",
    "then",
    "to",
    "plus",
    "also",
    "while",
    "or",
    "before",
    "after",
    "as",
    "so",
    "in",
    "order",
    "first",
    "next",
    "finally",
    "lastly",
    "afterwards",
    "afterward",
    "subsequently",
}
SEQ_JOINERS = {
    "then": "then",
    "next": "then",
    "afterwards": "then",
    "afterward": "then",
    "subsequently": "then",
    "first": "first",
    "finally": "finally",
    "lastly": "finally",
    "after": "after",
    "before": "before",
}

# ----- prepositions ----------------------------------------------------------------------------------
# multi-word prepositions first (matched on token sequences)
PREPOSITIONS: list[tuple[str, ...]] = sorted(
    [
        tuple(p.split())
        for p in (
            "on top of",
            "in front of",
            "next to",
            "close to",
            "closest to",
            "nearest to",
            "closer to",
            "out of",
            "inside of",
            "on to",
            "in to",
            "along with",
            "together with",
            "away from",
            "by the light of",
            "under the light of",
            "in the light of",
            "with the light of",
            "using the light of",
            "under light of",
            "by light of",
            "in light of",
            "near to",
            "closest to",
            "nearest to",
            "closer to",
            "to the left of",
            "to the right of",
            "in between",
            "all the way to",
            "back into",
            "back onto",
            "back on",
            "back in",
            "back to",
            "down on",
            "down onto",
            "down in",
            "over to",
            "up to",
            "off of",
            "on the top of",
            "to",
            "into",
            "onto",
            "in",
            "on",
            "inside",
            "at",
            "from",
            "off",
            "under",
            "underneath",
            "below",
            "beneath",
            "above",
            "over",
            "near",
            "by",
            "beside",
            "besides",
            "behind",
            "between",
            "against",
            "through",
            "toward",
            "towards",
            "with",
            "containing",
            "holding",
            "using",
            "within",
            "across",
            "around",
            "for",
            "among",
            "upon",
            "via",
            "without",
            "filled with",
            "full of",
        )
    ],
    key=len,
    reverse=True,
)
DEST_PREPS = {
    "then to",  # set by the parser: a further destination after a stop
    "to",
    "into",
    "onto",
    "in",
    "on",
    "inside",
    "at",
    "on top of",
    "inside of",
    "on to",
    "in to",
    "within",
    "upon",
    "back into",
    "back onto",
    "back on",
    "back in",
    "back to",
    "down on",
    "down onto",
    "down in",
    "over to",
    "up to",
    "all the way to",
    "on the top of",
    "under",
    "underneath",
    "below",
    "beneath",
    "in between",
    "between",
    "among",
}
NEAR_PREPS = {  # a place after these is a landmark: "the cabinet closest to the stove" (the stove says which)
    *"near by beside besides against behind above over across around toward towards".split(),
    *("next to", "close to", "closest to", "nearest to", "closer to", "near to", "in front of"),
    *("to the left of", "to the right of"),
}
WITH_PREPS = {"with", "containing", "holding", "along with", "together with", "filled with", "full of"}
LIGHT_PREPS = {
    "by the light of",
    "under the light of",
    "in the light of",
    "with the light of",
    "using the light of",
    "under light of",
    "by light of",
    "in light of",
    "using",
}
PARTICLES = {"up", "down", "away", "back", "around", "aside"}  # skipped after a verb and inside noun phrases

# ----- state words (adjectives and participles in noun phrases) --------------------------------------
STATE_WORDS: dict[str, str] = {"filled": "clean"}  # "a filled kettle": at the sink, as check 1 reads "fill"
for _w in ("washed", "rinsed", "clean", "cleaned", "wet", "scrubbed", "cleansed", "moist", "damp", "soaked"):
    STATE_WORDS[_w] = "clean"
for _w in (
    "heated",
    "warm",
    "warmed",
    "cooked",
    "hot",
    "microwaved",
    "baked",
    "toasted",
    "boiled",
    "reheated",
    "nuked",
):
    STATE_WORDS[_w] = "heat"
for _w in ("chilled", "cold", "cooled", "refrigerated", "frozen", "cool", "iced"):
    STATE_WORDS[_w] = "cool"
for _w in ("sliced", "cut", "chopped", "diced"):
    STATE_WORDS[_w] = "slice"
# what AI2-THOR can slice; a knife listed with one of them is the tool that sliced it ("a slice of tomato
# and a knife in the trash"), as in ALFRED's slicing tasks, whose goal is the slice
SLICEABLE = grounding.SLICEABLE
KNIVES = {"Knife", "ButterKnife"}
SLICE_NOUNS = {
    "slice", "slices", "piece", "pieces", "wedge", "wedges", "chunk", "chunks", "bit", "bits", "section",
    "sections",
}  # fmt: skip
WATER_WORDS = {"water"}

# counts
NUMBERS = {
    "one": 1,
    "a": 1,
    "an": 1,
    "single": 1,
    "two": 2,
    "both": 2,
    "pair": 2,
    "couple": 2,
    "three": 3,
    "four": 4,
    "five": 5,
    "several": 2,
    "all": 2,
}
PRONOUNS = {"it", "them", "this", "that", "these", "those", "they", "one", "same", "its"}

# ----- temporal markers ------------------------------------------------------------------------------
_F = re.IGNORECASE
THEN, FINALLY, FIRST, FREE, BEFORE_PREV, AFTER_ALL, AFTER_REF, BEFORE_REF, NOCONSTRAINT = (
    "then",
    "finally",
    "first",
    "free",
    "before_prev",
    "after_all",
    "after_ref",
    "before_ref",
    "none",
)
IN_ORDER = "in_order"  # "..., in that order": the sentence's tasks in the order they are named
IN_REVERSE = "in_reverse"  # "..., in reverse order": the sentence's tasks last named first
# "whenever convenient", "at whatever point suits you", "at your convenience": a free task
WHENEVER = (
    r"whenever(?:\s+(?:convenient|possible|you\s+(?:like|want|wish|can)|it\s+suits\s+you|you\s+get\s+(?:a|the)\s+chance))?|"
    r"at\s+(?:any|whatever|some)\s+point(?:\s+(?:that\s+)?(?:suits\s+you|you\s+like|you\s+want|works\s+for\s+you))?|"
    r"at\s+your\s+(?:convenience|leisure)"
)
_DONE = (
    r"(?:done|finished|finish|complete|completed|over|through|in\s+place|handled|taken\s+care\s+of|"
    r"out\s+of\s+the\s+way)"
)
# the words that open a reference the task comes after ("after X, Y", "right after X, Y", "once X, Y");
# `subordinate.after_ref` splits such a reference from its task
# ("having put the mug, Y": a perfect participle, not "having a mug in hand")
AFTER_OPENER = (
    r"(?:(?:only|right|just|immediately)\s+)?"
    r"(?:after|once|when|following|upon|having(?!\s+(?:a|an|the|some|no|to)\b))\s+"
)
LEADING: list[tuple[re.Pattern[str], str]] = [
    (
        re.compile(
            r"^(?:and\s+)?(?:then|next|afterwards?|after\s+that(?!')|after\s+this(?!')|after\s+which|subsequently|"
            r"later(?:\s+on)?|following\s+(?:that|this)|thereafter|followed\s+by|"
            r"(?:with\s+)?(?:that|this)\s+(?:done|finished|completed|out\s+of\s+the\s+way)|"
            r"having\s+(?:done|finished|completed)\s+(?:that|this|so)|"
            r"(?:second|third|fourth|fifth)(?:ly)?(?=\s*[,:])|"
            rf"(?:once|when|after)\s+(?:(?:that|this|it|you)(?:'s|'re)?)?\s*(?:is\s+|are\s+|have\s+|has\s+)?{_DONE}"
            # not before an object: "after you finish the mug, ..." is a reference, not "then"
            r"(?:\s+(?:with\s+)?(?:that|this|it|so)\b)?(?!\s+(?:with|the|a|an|my|your|all|every|each|both|any)\b)|"
            r"after\s+(?:doing|finishing|completing)\s+(?:that|this|it))\b\s*[,:]?\s*",
            _F,
        ),
        THEN,
    ),
    (
        re.compile(
            r"^(?:finally|lastly|last(?:\s+of\s+all)?|in\s+the\s+end|at\s+the\s+end|to\s+finish(?:\s+up)?|eventually|"
            r"to\s+(?:wrap\s+(?:it\s+|things\s+|everything\s+)?up|conclude|end|close(?:\s+out)?)|"
            r"as\s+(?:a|the)\s+(?:final|last)\s+(?:step|thing|task|job))\b\s*[,:]?\s*",
            _F,
        ),
        FINALLY,
    ),
    (re.compile(r"^(?:finish|end|wrap\s+(?:things\s+)?up|conclude)\s+(?:up\s+)?(?:by|with)\s+", _F), FINALLY),
    # "The last thing: Y" (`order_scope.txt`'s `last`), before a colon or comma ("the last thing I need": no)
    (re.compile(rf"^{phrase_list_pattern('order_scope.txt', 'last')}\s*[:,]\s*", _F), FINALLY),
    (
        re.compile(
            r"^(?:first(?:ly)?(?:\s+of\s+all)?|to\s+(?:begin|start)(?:\s+with)?|initially|before\s+anything\s+else)"
            r"\b\s*[,:]?\s*",
            _F,
        ),
        FIRST,
    ),
    (re.compile(r"^(?:begin|start)\s+(?:by|with)\s+", _F), FIRST),
    (
        re.compile(
            # "Any time you like, heat a slice": that task free
            r"^(?:in\s+any\s+order|(?:at\s+any\s+time|any\s*time)(?:\s+(?:you\s+(?:like|want|wish)|that\s+suits(?:\s+you)?))?|"
            r"at\s+whatever\s+time|simultaneously|meanwhile|"
            r"in\s+the\s+meantime|in\s+no\s+(?:particular|specific|set)\s+order|in\s+whatever\s+order|"
            rf"at\s+the\s+same\s+time|in\s+parallel|independently|concurrently|{WHENEVER})\b\s*[,:]?\s*",
            _F,
        ),
        FREE,
    ),
    (
        re.compile(
            r"^(?:(?:prior|previous)\s+to\s+(?:that|this)|(?:before|ahead\s+of)\s+(?:that|this|doing\s+(?:that|this|so))|"
            r"beforehand)\b\s*[,:]?\s*",
            _F,
        ),
        BEFORE_PREV,
    ),
    (
        re.compile(
            r"^(?:after|once|when|following|upon)\s+(?:completing|finishing|doing|all|these|those|"
            r"the\s+previous(?!\s+(?:task|step|job|one|thing)\b)|the\s+above|both|everything|each|every)\b[^,]*,\s*",
            _F,
        ),
        AFTER_ALL,
    ),
    (re.compile(r"^(?:while|during|as)\b[^,]*,\s*", _F), NOCONSTRAINT),
    (re.compile(rf"^{AFTER_OPENER}(?P<ref>[^,]+),\s*", _F), AFTER_REF),
    (re.compile(r"^(?:just\s+)?(?:before|prior\s+to|ahead\s+of)\s+(?P<ref>[^,]+),\s*", _F), BEFORE_REF),
    (
        re.compile(
            r"^(?:please|let'?s|let\s+us|now|next\s+up|you\s+should|you\s+must|we\s+need\s+to|"
            r"you(?:'ll|\s+will|'d|\s+would)?\s+(?:want|need|have)\s+to|you'?ve\s+got\s+to|"
            r"(?:can|could|would|will)\s+(?:the|a)\s+robots?|"
            r"i\s+want\s+you\s+to|can\s+you|could\s+you|would\s+you|will\s+you|kindly|go\s+and|also|additionally|"
            r"in\s+addition|separately|moreover|furthermore|besides(?=\s*,)|on\s+top\s+of\s+(?:that|this)(?=\s*,)|"
            r"alright|all\s+right|ok(?:ay)?|(?:thanks|thank\s+you|cheers)(?=\s*(?:[,!]|$))|and)\b\s*[,:]?\s*",
            _F,
        ),
        "",
    ),
    (re.compile(r"^to\s+(?=[a-z])", _F), ""),
    # "Your first job: X, Y, the order is up to you": a heading of the list, no order of its own
    (re.compile(r"^(?:your|the)\s+first\s+(?:job|task|chore|errand)\s*:\s*", _F), ""),
]
_FREE_T = (
    rf"(?:at\s+any\s+time|at\s+whatever\s+time|in\s+any\s+order|any\s+order|in\s+any\s+sequence|anytime|any\s+time|"
    rf"{WHENEVER}|"
    r"in\s+whatever\s+order(?:\s+you\s+(?:like|want|prefer))?|whatever\s+order\s+(?:works|is\s+fine)|in\s+no\s+(?:particular|specific|set)\s+order|"
    r"(?:the\s+)?order\s+is\s+(?:up\s+to\s+you|your\s+call|yours\s+to\s+choose)|in\s+parallel|simultaneously|concurrently|"
    r"independently|at\s+your\s+(?:convenience|leisure))"
)
TRAILING: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"\s*,?\s*(?:(?:in\s+(?:the\s+)?)?reversed?(?:\s+order)?|backwards)\s*$", _F), IN_REVERSE),
    # a closing courtesy: ", cheers", ", thanks!", ", thank you" (`courtesy.txt`'s closing thanks)
    (re.compile(rf"\s*,?\s*(?:{courtesy_pattern('closing')}|please)\s*$", _F), ""),
    (re.compile(rf"\s*,?\s*(?:also\s+)?{_FREE_T}\s*$", _F), FREE),
    (
        re.compile(
            rf"\s*,?\s*(?:this\s+)?(?:can|may|could)\s+(?:be\s+)?(?:done|performed|completed|happen)\s+{_FREE_T}"
            r"\s*$",
            _F,
        ),
        FREE,
    ),
    (
        re.compile(
            r"\s*,?\s*(?:(?:this\s+)?(?:should|must|has\s+to|have\s+to|needs?\s+to|can\s+only|is\s+to)\s+be\s+"
            r"(?:done|completed|performed|finished|placed|put|moved|carried\s+out)\s+)?(?:but\s+)?"
            r"(?:(?:only|right|just|immediately)\s+)?"
            r"(?P<rel>after|before|(?:ahead\s+of|prior\s+to)(?=\s+(?!turning|switching)\w+ing\b)|once|"
            # "when both are finished" closing the sentence (h234), never before a clause of its own ("and
            # then, only when both are there, put the carrot ...": the carrot is no reference)
            r"when(?=\s+(?:\w+ing|the)\b|\s+both\s+(?:of\s+th[a-z]+\s+)?(?:are|have)\b[^,;]*$))\s+(?P<ref>(?:\w+ing\b|the\s|you\s|having\s|all\s|every|each|both\s+"
            r"(?=(?:[a-z]+\s+){1,2}(?:jobs?|ones|tasks?|chores)\b|(?:of\s+th[a-z]+\s+)?(?:are|have)\s)|finishing|completing).+)$",
            _F,
        ),
        "ref",
    ),
    (
        re.compile(
            r"\s*,?\s*(?:first|at\s+first|to\s+begin\s+with|to\s+start\s+with|before\s+anything\s+else)\s*$",
            _F,
        ),
        FIRST,
    ),
    (re.compile(r"\s*,?\s*(?:afterwards?|after\s+that|next|then|later|thereafter|after)\s*$", _F), THEN),
    (re.compile(r"\s*,?\s*(?:last|lastly|finally|at\s+the\s+end|in\s+the\s+end)\s*$", _F), FINALLY),
    (
        re.compile(
            r"\s*,?\s*(?:(?:strictly|exactly|precisely)\s+)?(?:in\s+(?:(?:strictly|exactly|precisely)\s+)?"
            r"(?:that|this|the\s+same|the\s+given|the\s+listed)\s+(?:exact\s+)?(?:order|sequence)|"
            r"in\s+the\s+order\s+(?:given|listed|stated|named)|(?:from\s+)?top\s+to\s+bottom)(?:\s*,?\s*please)?\s*$",
            _F,
        ),
        IN_ORDER,
    ),
]
# A reference to tasks by position, not by object ("once done with the first tasks", "after the previous
# task", "when everything else is finished"): every earlier task, or (a singular "previous/last task") the
# one just before, or (a singular ordinal, "the first task") that one.
_TASK_NOUN = r"(?:tasks?|steps?|jobs?|things?|chores?|actions?|ones?|parts?|errands?)"
GENERIC_REF = re.compile(
    r"^(?:(?:all|each|every|both)\s+(?:of\s+)?)?(?:the|these|those|your|my|our)?\s*"
    r"(?P<which>first|previous|above|earlier|prior|preceding|other|former|initial|last|second|third|fourth)?\s*"
    r"(?:(?:two|three|four|few|couple\s+of)\s+)?"
    rf"(?P<noun>{_TASK_NOUN})(?:\s+(?:above|before|so\s+far|mentioned|listed))?"
    r"(?:\s+(?:is|are|have\s+been|has\s+been)\s+(?:done|finished|complete|completed|over))?$"
    r"|^(?:everything|all)(?:\s+(?:else|of\s+(?:that|this|those|these|the\s+above)|above|that|this|before|so\s+far|"
    r"(?:listed|mentioned|named|stated|given)(?:\s+(?:above|before|so\s+far))?))?"
    r"(?:\s+(?:is|are|has\s+been)\s+(?:done|finished|complete|completed|over))?$"
    r"|^the\s+(?:rest|above)(?:\s+(?:is|are|has\s+been)\s+(?:done|finished|complete|completed|over))?$"
    r"|^any\s+of\s+(?:that|this|those|these|the\s+above)$",  # "before any of that": before every task said
    _F,
)
# a closing "when the rest is done" / "once everything else is done": every task but the clause it closes
THE_REST_DONE = re.compile(r"^(?:the\s+rest|(?:everything|all)\s+else)\b", _F)
ORDINALS = {"first": 0, "second": 1, "third": 2, "fourth": 3}
