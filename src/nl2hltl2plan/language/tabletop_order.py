"""The order words of the tabletop world's pairs reading (`tabletop_pairs.read_pairs`), and where they may
stand (issue 28).

The pairs reading cuts a text into ordered groups at its "then"s (`THEN`) and marks the first group by a
"first" (`FIRST`, `FIRST_CLOSING`). An order word that stands elsewhere in its clause is first put before
the clause: a clause that waits for placements it states ("Once the green apple and the orange are on
the yellow plate, ...": those placements first, `reference_fronted`), a "then" or "first" closing its
clause ("the carrot goes on the blue plate after that", "... on the yellow plate to start; ... to
finish": `trailing_then_fronted`), and one after the clause's named subject ("the blue plate then gets
...", "the blue plate comes second with ...": `then_after_subject_fronted`).
"""

from __future__ import annotations

import re

_DONE = r"(?:done|finished|complete[d]?)"
_THAT = r"(?:that|this|those|these|them|it)"
# where one ordered group ends and the next begins: "then", "after that", "After," (opening its clause,
# nothing after it in the clause), "once that's done", "when you've done that", "subsequently", "next"
# (not "next to"); "only if they are (already) there" as "only when"
_THERE = r"(?:there|on\s+it|in\s+it|on\s+there|in\s+place|placed|down|(?:in|on)(?=\s*(?:[,.;:!?]|$)))"
THEN = re.compile(
    r"\b(?:only\s+)?(?:then,?\s+and\s+only\s+then|(?:and\s+)?then|after\s+(?:that|this|those|these|which)|"
    r"afterwards?|(?<![a-z]\s)(?<![a-z])after(?=\s*[,:])|thereafter|subsequently|"
    r"next(?!\s+to\b)|second(?:ly)?|(?:and\s+)?(?:finally|lastly)|"
    rf"(?:once|when|after|as\s+soon\s+as|(?<=only\s)if)\s+(?:{_THAT}(?:'s|s|\s+is|\s+are|'re)\s+{_DONE}|"
    rf"(?:they|both|{_THAT}|(?:both|all|the\s+two)\s+of\s+them|the\s+two)(?:'re|'s|\s+are|\s+is)\s+(?:both\s+|all\s+)?"
    rf"(?:already\s+)?{_THERE}|"
    rf"you(?:'ve|\s+have|'re|\s+are)\s+{_DONE}(?:\s+(?:with\s+)?{_THAT})?|{_DONE}))\b"
)
# how the first group is marked: "first" / "to begin" / "start with" / "before anything else" before its
# first name ("What I need first is ..."), or "first" closing it or its heading ("yellow plate first: ...")
FIRST = re.compile(
    r"\b(?:first(?:ly)?|to\s+(?:begin|start)|(?:start|begin)(?:\s+off)?(?:\s+(?:with|by))?|"
    r"before\s+(?:you\s+do\s+)?anything\s+else)\b"
)
# "A before B" inside a clause (not "Before B, A", not "before that")
BEFORE = re.compile(
    r"(?<=[a-z])\s+before\s+(?!(?:that|this|those|these|it|which|then|anything|everything)\b)"
)
FIRST_CLOSING = re.compile(r"\bfirst\b(?=\W*$|\s*:)")

# where a clause stands in the whole ("... to start", "... to finish", closing it), which a reading with no
# order leaves unused ("To start, ..." opens the first step instead)
PLACE_IN_THE_WHOLE = re.compile(
    r"(?<=[a-z]\s)to\s+(?:start|begin|finish|end|close|wrap\s+up)\b(?=\s*(?:[,.;:!?]|$))"
)

# "once the green apple and the orange are on the yellow plate, ...": a placement the rest waits for
_REFERENCE_FIRST = re.compile(
    r"^\W*(?:only\s+)?(?:once|when|after|as\s+soon\s+as)\s+(?P<clause>[^,.;:!?]+?)\s*"
    r"(?:,\s*(?:then\s+)?|\s+then\s+)"
)
_STATE_WORDS = frozenset(
    "the and both all is are 's 're has have been already on in onto into sitting placed".split()
)
_BOTH = re.compile(r"\b(?:both|all)\b")
_STATE_VERBS = re.compile(r"\b(?:is|are|has|have|been|already|sitting|placed)\b|'s\b|'re\b")

# "only when STATE should / must / can SUBJECT ...": the subject after its modal, as English puts it after a
# fronted "only" clause
_INVERTED_MODAL = r"(?P<aux>should|must|can|may|will|shall|could)"


def inverted_condition_read(text: str, pattern: re.Pattern[str]) -> str:
    """An opening "only when STATE" with its subject after the modal ("Only when both A and B are on P
    should C go on Q") in the usual order ("only when both A and B are on P, C should go on Q"), which
    `reference_fronted` reads; the text as it is where no named subject follows the modal."""
    named = rf"(?:the\s+)?{pattern.pattern}"
    inverted = re.compile(
        r"^(?P<lead>\W*only\s+(?:once|when|after|as\s+soon\s+as)\s+(?P<clause>[^,.;:!?]+?))\s+"
        rf"{_INVERTED_MODAL}\s+(?P<subject>{named}(?:\s*(?:,|,?\s+and)\s+{named})*)\s+(?=[a-z])"
    )
    return inverted.sub(r"\g<lead>, \g<subject> \g<aux> ", text, count=1)


# a wait on the things placed before, said with their plate: "..., only if both of them are on the yellow
# plate", "once all of them are in the pink plate"
_WAIT_ON_PLATE = re.compile(
    r"\b(?P<wait>(?:only\s+)?(?:once|when|after|as\s+soon\s+as|(?<=only\s)if)\s+(?:they|both|all)(?:\s+of\s+them)?"
    r"(?:'re|\s+are)\s+(?:both\s+|all\s+)?(?:already\s+)?)(?:on|in|onto|into)\s+(?P<plate>[a-z][a-z ]*?)"
    r"(?:\s+already)?(?=\s*(?:[,.;:!?\n]|$))"
)


def plate_wait_read(text: str, pattern: re.Pattern[str]) -> str:
    """A wait on the things placed before said with their plate ("put C and D on the blue plate only if both
    of them are on the yellow plate") as the wait without it ("... only if both are there", a closing
    `THEN`), where every plate named before the wait's own clause is that plate; the text as it is
    otherwise (a plate that nothing was put on before, or placements on other plates too)."""

    def there(m: re.Match[str]) -> str:
        plate = _name(re.sub(r"^the\s+", "", m["plate"]))
        if not pattern.fullmatch(plate) or not plate.endswith("plate"):
            return m[0]
        named = [_name(f) for f in pattern.findall(text, 0, m.start()) if _name(f).endswith("plate")]
        if len(named) < 2 or named[-1] == plate or any(p != plate for p in named[:-1]):
            return m[0]
        return f"{m['wait']}there"

    return _WAIT_ON_PLATE.sub(there, text)


def reference_fronted(text: str, pattern: re.Pattern[str]) -> str:
    """A text that opens with a clause waiting for placements it states ("Once the green apple and the
    orange are in the yellow plate, put ...") as those placements first and the rest then; the text as
    it is otherwise (a clause with any other word, or none stating where a named object is)."""
    m = _REFERENCE_FIRST.match(text)
    if m is None:
        return text
    names = [_name(f) for f in pattern.findall(m["clause"])]
    words = set(re.findall(r"[a-z']+", pattern.sub(" ", m["clause"])))
    stated = _STATE_VERBS.search(pattern.sub(" ", m["clause"]))
    if not names or not names[-1].endswith("plate") or not words <= _STATE_WORDS or stated is None:
        return text
    placed = _STATE_VERBS.sub(" ", _BOTH.sub(" ", m["clause"]))  # "both A and B are on P": A and B on P
    return f"first {placed}, then {text[m.end() :]}"


_CLAUSE_END = re.compile(r"[,.;!?\n]")
# a closing "then" said as a wait on what was placed before ("only when both are there")
_WAITS = re.compile(r"(?:only\s+)?(?:once|when|if|after|as\s+soon\s+as)\b")
# a "then" that closes its clause: "the carrot goes on the blue plate after that.", "... after them.", "...
# red apple after,", or a heading: "blue plate after: carrot, red apple"
# a clause closed by where it stands in the whole: "... on the yellow plate to start; ... to finish"
_TO_START = r"to\s+(?:start|begin)(?:\s+with)?|at\s+first"
_TO_FINISH = r"to\s+(?:finish|end|close|wrap\s+up)|at\s+the\s+end|in\s+the\s+end"
_TRAILING_THEN = re.compile(
    rf"(?:(?P<first>\b(?:first|{_TO_START})\b)|{THEN.pattern}|\b(?:after(?:\s+them)?|later|last|{_TO_FINISH})\b)"
    r"(?=\s*(?:[,.;:!?\n]|$))"
)

# what may stand between a comma and a "then" that closes the clause before the comma
_SET_OFF = re.compile(r"\s*(?:but\s+|and\s+)?")

# the verbs a "then" may stand before in "the blue plate then gets ...", "the carrot then goes ..."
_SUBJECT_VERB = r"(?:gets?|goes|go|takes?|receives?|holds?|should|must|can|will|may|needs?|has|have|is|are)"


def then_after_subject_fronted(text: str, pattern: re.Pattern[str]) -> str:
    """A "then" between a clause's named subject and its verb put before the clause ("; the blue plate then
    gets the carrot" -> "; then the blue plate gets the carrot"), so that it cuts the groups where the
    clause starts; not before another name ("the carrot then the orange" orders the two). So is a "second",
    "next" or "last" after the subject's "comes" ("the blue plate comes second with ..."), and a "first" or
    "then" inside a passive duty ("the carrot and the red apple are then to be placed on ...")."""
    subject = rf"(?P<subject>(?:the\s+)?{pattern.pattern})"
    start = r"(?P<start>(?:^|[,.;:!?])\s*(?:and\s+)?)"
    text = re.sub(
        rf"{start}(?:then\s+)?{subject}\s+then\s+(?={_SUBJECT_VERB}\b)", r"\g<start>then \g<subject> ", text
    )
    # in a duty said in the passive: "the carrot and the red apple are then to be placed on ..."
    named = rf"(?:the\s+)?{pattern.pattern}"
    subjects = rf"(?P<subject>{named}(?:\s*(?:,|,?\s+and)\s+{named})*)"
    text = re.sub(
        rf"{start}{subjects}\s+(?P<be>is|are)\s+(?P<when>first|then|next|afterwards)\s+(?=to\s+be\b)",
        lambda m: f"{m['start']}{'first' if m['when'] == 'first' else 'then'} {m['subject']} {m['be']} ",
        text,
    )
    # the same said by where the subject comes: "..., and the blue plate comes second with the carrot"
    return re.sub(
        rf"{start}{subject}\s+(?P<verb>comes|goes|is)\s+(?:second|next|after(?:wards)?|later|last)\b",
        r"\g<start>then \g<subject> \g<verb>",
        text,
    )


def heading_colon_put_back(text: str, pattern: re.Pattern[str]) -> str:
    """A plate, an order word and an object name opening a clause as a heading with its colon left out
    ("blue plate next carrot and red apple" -> "blue plate next: carrot and red apple"), which
    `trailing_then_fronted` then reads as the headings it reads."""
    start = r"(?P<start>(?:^|[,.;:!?])\s*(?:and\s+)?)"
    heading = re.compile(
        rf"{start}(?P<plate>(?:the\s+)?{pattern.pattern})\s+(?P<when>first|next|then|second|last|after\s+that)"
        rf"\s+(?=(?:the\s+)?(?P<named>{pattern.pattern}))"
    )

    def put_back(m: re.Match[str]) -> str:
        plates = _name(m["plate"]).endswith("plate") and not _name(m["named"]).endswith("plate")
        return f"{m['start']}{m['plate']} {m['when']}: " if plates else m[0]

    return heading.sub(put_back, text)


def trailing_then_fronted(text: str, pattern: re.Pattern[str]) -> str:
    """A "then" or "first" that closes its clause put before it ("the carrot goes on the blue plate after
    that" -> "then the carrot goes on the blue plate"), where the clause names one plate (so that its
    placements are one step: "A on P and B on Q after that" does not say whether B alone comes after)
    and, for a "then", something is named before it."""
    for m in reversed(list(_TRAILING_THEN.finditer(text))):
        ends = list(_CLAUSE_END.finditer(text, 0, m.start()))
        start = ends[-1].end() if ends else 0
        clause = text[start : m.start()]
        if _SET_OFF.fullmatch(clause) and ends and ends[-1][0] == ",":
            # set off by a comma ("..., (but) only when both are there"): it closes the clause before it
            # (back over a free-order remark set off by commas too, "..., in any order, only when both are
            # there": `free_order` took the remark out before and left its commas)
            k = len(ends) - 1
            while k > 0 and ends[k - 1][0] == ",":
                if not _SET_OFF.fullmatch(text[ends[k - 1].end() : ends[k].start()]):
                    break
                k -= 1
            start = ends[k - 1].end() if k > 0 else 0
            clause = text[start : ends[-1].start()]
        plates = {_name(f) for f in pattern.findall(clause) if _name(f).endswith("plate")}
        marked = THEN.search(clause) or FIRST.search(clause)
        if len(plates) == 1 and THEN.match(clause.strip()) and _WAITS.match(m[0]):
            # "then C on Q, only when both are there": the condition says the "then" again
            text = f"{text[: m.start()]}{text[m.end() :]}"
            continue
        if len(plates) != 1 or marked or not (m["first"] or pattern.search(text, 0, start)):
            continue
        text = f"{text[:start]} {'first' if m['first'] else 'then'} {clause.strip()}{text[m.end() :]}"
    return text


def _name(found: str) -> str:
    return " ".join(found.split())


# "The first thing to do is (to) put ...", "The second job, after the first one, is to put ...": a step's
# turn said by an ordinal noun; the turn is the ordinal ("First, put ...", "Second, put ...")
_ORDINAL_THING = re.compile(
    r"\b(?:the\s+|my\s+|your\s+)?(?P<turn>first|second|third|fourth|next|last|final)\s+(?:thing|job|task|"
    r"step|chore|bit|part|errand)(?:\s+(?:to\s+do|(?:I\s+need\s+)?(?:you\s+)?to\s+do|you\s+(?:should\s+)?do))?"
    r"(?P<aside>\s*,\s*(?:once|when|after)\s+[^,.;:!?]{1,40}?,)?\s+is\s+(?:to\s+)?(?=[a-z])",
    re.IGNORECASE,
)


def ordinal_things_read(text: str, pattern: re.Pattern[str]) -> str:
    """`text` with each "the first / second / next thing (to do) is (to)" as its ordinal ("First, put ...");
    an aside between them that names nothing ("once that's done", "after the first one") only restates the
    turn and goes; one that names a thing or plate keeps the text as it is (what it waits for is read
    elsewhere or refused).

    >>> ordinal_things_read("The first thing to do is put A. The second job, after the first one, is B.",
    ...                     re.compile(r"\\b[AB]\\b"))
    'First, put A. Second, B.'
    """

    def read(m: re.Match[str]) -> str:
        if m["aside"] and pattern.search(m["aside"]):
            return m[0]
        turn = m["turn"].lower()
        return f"{turn.capitalize() if m[0][:1].isupper() else turn}, "

    return _ORDINAL_THING.sub(read, text)


# the robot named as the one who places, in the third person (a test scenario's or a specification's voice:
# "When the robot has put A on P, then it puts B on Q"): the one asked, as "you"; "it" only where the robot
# is named before it, and only before a verb of placing (a thing "goes", it never "puts")
_PLACES = r"(?:put|place|move|set|bring|take|carry|drop)"
_ROBOT_DOES = re.compile(
    rf"\b(?P<who>the\s+robot|it)\s+(?:(?P<has>has|will|shall)\s+)?(?P<verb>{_PLACES}(?:s|d|ed)?|moved|brought|"
    r"took|taken|carried)\b",
    re.IGNORECASE,
)


def robot_addressed(text: str) -> str:
    """`text` with "the robot puts / has put / will put" (and "it puts" after the robot is named) said to the
    one asked ("you put", "you have put").

    >>> robot_addressed("When the robot has put A on P, then it puts B on Q.")
    'When you have put A on P, then you put B on Q.'
    """
    named = re.search(r"\bthe\s+robot\b", text, re.IGNORECASE)
    if named is None:
        return text

    def said(m: re.Match[str]) -> str:
        if m["who"].lower() == "it" and m.start() < named.end():
            return m[0]
        has = {"has": "have ", "will": "will ", "shall": "will "}.get((m["has"] or "").lower(), "")
        verb = m["verb"] if has else re.sub(r"(?<=[a-z])s$", "", m["verb"])
        return f"{'You' if m[0][0].isupper() else 'you'} {has}{verb}"

    return _ROBOT_DOES.sub(said, text)


# a step's turn said by a clause that looks back on the step before ("Having done that,", "That done,", "Once
# you've got that sorted,", "Thereafter,"), or by the last step's "end / finish with" after a first step's
# "begin / start with" ("Begin with A and end with B"; not "end up with": an end state)
_LOOKS_BACK = re.compile(
    rf"\b(?:having\s+done\s+{_THAT}|{_THAT}\s+done|with\s+{_THAT}\s+(?:done|out\s+of\s+the\s+way)|"
    rf"(?:once|when|after)\s+you(?:'ve|\s+have)\s+got\s+{_THAT}\s+(?:sorted(?:\s+out)?|{_DONE})|thereafter)\b"
    r"(?=\s*,)",
    re.IGNORECASE,
)
_BEGIN_WITH = re.compile(r"\b(?:begin|start)(?:\s+off)?\s+with\b", re.IGNORECASE)
_END_WITH = re.compile(r"\b(?:and\s+)?(?:end|finish)(?:\s+off)?\s+with\b", re.IGNORECASE)


# "A and B on P before touching the others. C and D on Q." (or "...; get these done before moving on to the
# rest."): what was just said comes first, and what is said after it, the others, then; read as "first"
# only where words follow that name the others (else the clause is left, to be refused)
_BEFORE_THE_REST = re.compile(
    r"\s*(?:[;,]\s*(?:and\s+)?(?:get|have)\s+(?:these|those|them|this|that|both)(?:\s+(?:both|all))?\s+"
    r"(?:done|sorted|finished|in)\s+)?\s*\bbefore\s+(?:touching|starting\s+on|moving\s+on\s+to|getting\s+to|"
    r"doing|handling)\s+(?:the\s+others|the\s+rest|anything\s+else)(?=\s*[.;!?]\s*\w)",
    re.IGNORECASE,
)


# an end-state opener with no comma before the wish it opens ("By the end I want X on Y", "In the end we'd
# like ..."): the comma the reader takes it with ("by the end, I want ..."), so the wish reads as the goal
_END_OPENER = re.compile(
    r"\b((?:by|at|in)\s+the\s+end)\s+(?=(?:i|we)(?:'d|\s+would)?\s+(?:want|like|need|wish|expect|hope)\b)",
    re.IGNORECASE,
)


def end_opener_read(text: str) -> str:
    """`text` with a comma after an end-state opener before its wish.

    >>> end_opener_read("By the end I want A on B.")
    'By the end, I want A on B.'
    """
    return _END_OPENER.sub(r"\1, ", text)


def turn_phrases_read(text: str) -> str:
    """`text` with each clause that looks back on the step before as "then", one that puts what was said
    before the rest (`_BEFORE_THE_REST`) as "first", and an "end / finish with" after a "begin / start
    with" as "then".

    >>> turn_phrases_read("Begin with A and end with B. Having done that, C.")
    'Begin with A then B. then, C.'
    """
    text = _LOOKS_BACK.sub("then", _BEFORE_THE_REST.sub(" first", text))
    first = _BEGIN_WITH.search(text)
    if first is not None:
        text = text[: first.end()] + _END_WITH.sub(" then", text[first.end() :])
    return re.sub(r"\s+then\b", " then", text)
