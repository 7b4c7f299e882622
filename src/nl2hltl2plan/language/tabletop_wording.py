"""The tabletop reading's wording rules (issue 28): what a tabletop instruction says besides its object
and plate names, read before `tabletop_pairs` pairs them.

- statements: a clause that says where something is or was ("the carrot is on the blue plate", "the
  blue plate had the carrot") is a task only under a wish or goal said before it in its sentence ("make
  sure", "I want", "should", "Final layout:", "once"); `stated_not_asked` finds the first one that is not;
- free-order remarks ("in any order", "the order is of no consequence", "whichever way round"): read,
  then removed; they leave the order inside each group free (the groups keep theirs);
- corrections: "the blue plate, sorry, the yellow plate" keeps the second name, "no wait" too;
- plurals: "the apples" / "both apples" name every object the world has with that head noun, when the
  count, if one is said, is theirs;
- "lastly" / "finally" beside a remark that frees the whole list only mark its last item (step labels and
  list numbers are `tabletop_steps`');
- politeness that carries nothing: "it would please me if", "I would be grateful if you could", "let me
  see", "chop chop", "go ahead and";
- clauses that name no object or plate (courtesy, list headings, freedom statements), read by what their
  words are rather than by a list of phrasings (`tabletop_remarks.remarks_read`);
- what the world's closed vocabulary settles: a plate said by its colour alone, "on it" (the plate named
  before), "respectively", a question about where an object goes joined with the plate that answers it,
  and a tidying verb before an object ("sort the carrot onto ...") as placing it (a state clause under a
  wish is asked for however far from the wish: `statements.asked_before`, which check 1 shares).
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from nl2hltl2plan.language.content_words import free_order_remarks
from nl2hltl2plan.language.courtesy import courtesy_pattern
from nl2hltl2plan.language.grounding import sentence_start
from nl2hltl2plan.language.handover_words import SET_OFF_FOR, WAY_IDIOM
from nl2hltl2plan.language.spelling import english_lemmas
from nl2hltl2plan.language.statements import WHERE_VERB, asked_before
from nl2hltl2plan.language.tabletop_remarks import FREE_ORDER, TIDY_VERB, remarks_read
from nl2hltl2plan.language.tabletop_waits import plate_waits_read

# ---- statements ---------------------------------------------------------------------------------------
# where it is: on or in a place, or "fine where it is" / "good as it is" / "fine there"
_LOCATIVE = (
    r"(?:\s+(?:on|in|onto|into|upon|inside|at)\b|\s+(?:fine|ok|okay|good|alright|all\s+right)\s+"
    r"(?:where\s+(?:it|they)\s+(?:is|are)|as\s+(?:it|they)\s+(?:is|are)|there)\b)"
)
_HOLDS = r"\s+(?:has|had|holds|held|contains|contained|carries|carried)\s+(?=(?:the|a|an|both|two)\b)"
# "please" before a state clause asks for it too ("please, the carrot is on the blue plate"); the wishes
# (the polite frames below among them: "it would please me if X were on Y" is "i want X were on Y"), goals
# and references are `statements`'
_PLEASE = re.compile(r"\bplease\b")


def stated_not_asked(text: str, names: Iterable[str]) -> str | None:
    """The first clause of `text` that states where a named thing is, was or has been put with no wish or
    goal before it in its sentence ("the carrot is on the blue plate, please put ..."); None when there is
    none. `names`: the world's object and plate names, in words ("blue plate")."""
    lowered = polite_frames(text.lower())
    mention = mention_pattern(names).pattern.removesuffix(r"\b")
    state = re.compile(
        rf"{mention}(?:\s+(?:both|all|too|also))?{WHERE_VERB}{_LOCATIVE}|{mention}{_HOLDS}"
    )
    for m in state.finditer(lowered):
        if not asked_before(lowered, m.start()) and not _PLEASE.search(
            lowered, sentence_start(lowered, m.start()), m.start()
        ):
            clause_end = re.compile(r"[,.;!?]|$").search(lowered, m.end())
            return lowered[m.start() : clause_end.start() if clause_end else None].strip()
    return None


# a number's or ordinal's place in turn ("two", "second"): here and in the step labels (`tabletop_steps`)
NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "first": 1, "second": 2, "third": 3, "fourth": 4}

# ---- free-order remarks ---------------------------------------------------------------------------------
_FREE_ORDER = FREE_ORDER  # the shared list (free_order.txt), anywhere in the text (`tabletop_remarks`)
# under a remark that frees the whole list, "lastly" / "finally" only mark its last item ("..., and, lastly,
# the red apple on the pink plate. The order doesn't matter.")
_LAST_LISTED = re.compile(r"\b(?:lastly|finally)\b\s*,?")


# a free-order remark about the last group alone: "those last two can go in any order"
_LAST_GROUP_FREE = re.compile(
    r"\b(?:and\s+)?(?:those|these|the)\s+(?:last\s+)?(?P<n>two|three|four)(?:\s+ones)?\s+(?:can|may|could)\s+"
    r"(?:go|be\s+(?:done|placed|put))\s+in\s+(?:any|either|whatever)\s+order\b"
)


def last_group_free(text: str) -> tuple[str, int | None]:
    """`text` without a free-order remark about its last group, and how many things the remark names."""
    m = _LAST_GROUP_FREE.search(text)
    if m is None:
        return text, None
    return text[: m.start()] + " " + text[m.end() :], NUMBER_WORDS[m["n"]]


def free_order(text: str) -> tuple[str, list[str]]:
    """`text` (lowercased) without its free-order remarks, and the remarks."""
    return _FREE_ORDER.sub(" ", text), [m[0] for m in _FREE_ORDER.finditer(text)]


def frees_every_step(remarks: list[str]) -> bool:
    """Does one of the remarks free the whole list, not only the order inside each step?"""
    # a per-group remark ("within each step, any order"; `free_order_remarks`) leaves the steps' own order
    return any(not r.per_group for said in remarks for r in free_order_remarks(said.replace(",", " ")))


def last_item_unmarked(text: str) -> str:
    """`text` without "lastly" / "finally", for a list whose order a remark frees."""
    return _LAST_LISTED.sub(" ", text)


# ---- corrections, plurals, politeness ---------------------------------------------------------------------
_CORRECTION = re.compile(
    r"^[\s,.;:!\-]*(?:(?:no|sorry|wait|oops|whoops|actually|rather|or\s+rather|i\s+mean[t]?|make\s+that|"
    r"correction|scratch\s+that|my\s+mistake|my\s+bad)\b[\s,.;:!\-]*)+(?:the\s+|a\s+|an\s+)?$"
)


def _polite(kind: str) -> str:
    """The phrases of one kind of `courtesy.txt`, as one regular expression."""
    return courtesy_pattern(kind)


_POLITE = re.compile(rf"\b(?:{_polite('wish')}|{_polite('state_wish')})\b")  # "it would please me if"
_FILLER = re.compile(rf"^\W*{_polite('opening')}\b|\b{_polite('filler')}\b")  # carry nothing
_REPLY = re.compile(rf"^\W*(?:{_polite('reply')}\s*[!.,]+\s*)+")  # "No problem! ...": an agent's answer
# a letter's frame: a subject line ("Subject: plates", "Re: tidying") that names nothing and says no order
# and a sign-off ("Best, Sam", "Thanks,\nJo") closing the text: neither is part of the request
# (its line break is gone by then: it ends where the letter's first sentence begins, with a capital)
_HEADER_LINE = re.compile(r"^\s*(?i:subject|re|fwd?|topic|title)\s*:(?P<words>[^.:;!?]*?)\s+(?=[A-Z])")
_SIGN_OFF = re.compile(rf"(?<=[.!?\n])\s*(?i:{_polite('sign_off')})\s*,?\s*(?P<name>[A-Z][a-z]+)\W*$")
_SAYS_ORDER = re.compile(
    r"\b(?:order|sequence|first|then|before|after|until|next|last|not|no|never)\b|n't|\d"
)
# "don't forget (to)": a reminder, which asks as "please" asks (not a negation)
_REMINDER = re.compile(rf"\b{_polite('reminder')}\b")
# "if you could X, that would be great": a polite frame around a request, not a condition
_IF_YOU_COULD = re.compile(
    rf"(?:^|(?<=[.!?]\s))(?P<pre>\W*){_polite('request')}\b(?P<body>[^.;!?]*?),?\s*\b{_polite('thanks')}\b"
)
_THE_FOLLOWING = re.compile(r"\b(?:the\s+)?following(?=\s*:)")  # a list's heading: "arrange the following:"
# an aside that only describes the thing before it: "the green apple, the nice shiny one, goes ..."
_APPOSITION = re.compile(r",\s*the\s+(?P<words>(?:[a-z]+\s+){1,3})one\s*,")
_ORDINALS = {"1st": "first", "2nd": "second", "3rd": "third", "4th": "fourth"}
# "pair" as the verb of a placement ("pair the carrot with the blue plate"), not the count "a pair of"
_PAIR_VERB = re.compile(r"\bpair(?:\s+up)?(?=\s+(?:the|a|an)\s)")


def polite_frames(text: str) -> str:
    """A polite frame as what it asks: around a request ("I'd be grateful if you could put X on Y")
    "please", around a state ("it would please me if X were on Y", "I'd appreciate it if X went on Y") the
    wish "i want" (a wish of `state_words.txt`), so that the state clause is read as a goal whatever verb
    says where the thing is (`statements.WHERE_VERB`: "were", "went", "ended up", "sat")."""
    return _POLITE.sub(_wish_word, text)


def _wish_word(frame: re.Match[str]) -> str:
    return "please" if _FRAME_ASKS_YOU.search(frame.group(0)) else "i want"


# "... if you could", "be so kind as to": a request follows
_FRAME_ASKS_YOU = re.compile(r"\b(?:you\s+(?:could|would|can|will)|to)$")


def plain_words(text: str, kinds: dict[str, bool], heads: dict[str, list[str]]) -> str:
    """The lowercased text with ordinals spelt out, politeness that carries nothing removed (an agent's
    reply opening the text, "Sure! ...", too), the verb "pair" read as "match", "make it so" as "make
    sure", clauses that name nothing read (`remarks_read`), a tidying verb before an object as "put",
    plates said by colour named, questions joined with their answers, corrections applied and plurals
    named. `kinds`: each object or plate name (in words) -> is it a plate; `heads`: a head noun that
    several objects share ("apple") -> their names."""
    text = plate_waits_read(_REPLY.sub("", _letter_frame_dropped(text, kinds).lower()), kinds)
    text = end_state_heading_read(text, kinds)
    text = re.sub(r"\b(1st|2nd|3rd|4th)\b", lambda m: _ORDINALS[m[1]], text)
    text = _IF_YOU_COULD.sub(r"\g<pre>please\g<body>", _REMINDER.sub("please", text))
    text = _THE_FOLLOWING.sub("these", _FILLER.sub(" ", polite_frames(text)))
    text = remarks_read(text, mention_pattern(kinds), frozenset(w for name in kinds for w in name.split()))
    text = _PAIR_VERB.sub("match", text).replace("+", " and ")
    text = _BY_THE_END.sub("", _FIRST_THINGS.sub("first", text))
    text = _UNSAID_DONE.sub(r"\g<when> that is done", _DONE_WORDS.sub(r"\g<that> is done", text))
    text = re.sub(r"\b(?:make|have|get)\s+it\s+so(?:\s+that)?\b", "make sure", text)  # the same goal
    text = _own_plate_dropped(_tidied_as_put(text, kinds), kinds)
    text = answers_joined(plates_by_colour(respectively_paired(text, kinds), kinds), kinds)
    text = _moving_on_read(_plate_referred(text, kinds), kinds)
    text = _APPOSITION.sub(lambda m: m[0] if _names_a_word(m["words"], kinds) else ",", text)
    text = corrected(text, kinds)
    return _plurals_named(text, kinds, heads)


# the subject and "do" inverted after a time clause: "only once both are in do the carrot and the apple go
# ..." is "once both are in, the carrot and the apple go ..."
_DO_INVERTED = re.compile(
    r"\b((?:only\s+)?(?:once|after|when)\b[^.,;:]*?)\s+do\s+(?=the\b[^.,;:]*?\b(?:go|goes)\b)", re.I
)


def moving_idioms_read(text: str, kinds: dict[str, bool]) -> str:
    """`text` with the idioms of moving said as "goes (to)" (`handover_words.WAY_IDIOM`, `SET_OFF_FOR`): "the
    orange makes its way into the yellow plate", "the carrot sets off for the blue plate"; a thing sent
    to a plate by a participle as "goes" (`assigned_read`); and "do" after a time clause put back
    (`_DO_INVERTED`). `kinds`: each name in words -> is it a plate."""
    text = re.sub(WAY_IDIOM, "goes ", re.sub(SET_OFF_FOR, "goes to", text, flags=re.I), flags=re.I)
    return _DO_INVERTED.sub(r"\1, ", assigned_read(text, kinds))


# verbs whose participle before "to" keeps a thing from its plate or holds it ("is barred from / kept to"):
# never read as its going there
_HELD_BACK = frozenset(
    "keep ban forbid prohibit bar restrict deny lock limit confine hold stick chain tie".split()
)


def assigned_read(text: str, kinds: dict[str, bool]) -> str:
    """`text` with a thing sent to a plate by a verb's passive or progressive said as "goes" (h262): "the
    green apple is allocated to the pink plate", "green apple posted to the blue plate", "the orange is
    moving into the yellow plate". The world's one action is placing, so a participle right between a
    thing and "to" / "into" / "onto" and a plate says where it goes; "in" / "on" (a state: "is kept on"),
    "not" between, and a verb that holds a thing back (`_HELD_BACK`) are left.

    >>> assigned_read("The orange is allocated to the pink plate.", {"orange": False, "pink plate": True})
    'The orange goes to the pink plate.'
    """
    if all(kinds.values()) or not any(kinds.values()):
        return text
    things = kind_pattern(kinds, plates=False).pattern
    plates = kind_pattern(kinds, plates=True).pattern
    sent = re.compile(
        rf"(?P<thing>{things})\s+(?:(?:is|are|gets|get|was|were|being)\s+)?(?P<verb>[a-z]+(?:ed|en|ing))\s+"
        rf"(?P<to>into|onto|to)\s+(?=(?:the\s+)?{plates})",
        re.IGNORECASE,
    )

    def goes(m: re.Match[str]) -> str:
        lemmas = english_lemmas(m["verb"].lower()).get("VERB", ())
        if not lemmas or any(lemma in _HELD_BACK for lemma in lemmas):
            return m[0]
        return f"{m['thing']} goes {m['to']} "

    return sent.sub(goes, text)


def _letter_frame_dropped(text: str, kinds: dict[str, bool]) -> str:
    """`text` without a subject line that names nothing and says no order, and without a sign-off whose
    name is no object or plate (the case of the name is read: before lowercasing)."""
    header = _HEADER_LINE.match(text)
    words = header["words"].lower() if header else ""
    if header and not mention_pattern(kinds).search(words) and not _SAYS_ORDER.search(words):
        text = text[header.end() :]
    sign_off = _SIGN_OFF.search(text)
    if sign_off and not any(sign_off["name"].lower() in name.split() for name in kinds):
        text = text[: sign_off.start()]
    return text


# a heading that describes the end state the list after it shows ("Here's how the table should look at the
# end:", "Picture this when you're done:", "End state:"): words of the end, of a picture, and nothing else
_END_WORDS = frozenset("end final finally finished done through result outcome afterwards".split())
_PICTURE_WORDS = frozenset("look looks picture imagine state layout setup arrangement see".split())
_END_FRAME_WORDS = _END_WORDS | _PICTURE_WORDS | frozenset(
    "here's here is how what the table it everything things should must will would to like this at in by "
    "when once you're youre you are you've have i i'd we we'd want like".split()
)
_HEADING = re.compile(r"^(?P<words>[^:.;!?\n]+):")


def end_state_heading_read(text: str, kinds: dict[str, bool]) -> str:
    """`text` (lowercased) with a heading that opens it and describes the end state ("when you're done,
    the table should look like this:") read as "final layout:", a goal's heading that asks for the states
    listed after it; the text as it is otherwise (a "when you're done" before a request opens a step)."""
    heading = _HEADING.match(text)
    if heading is None or mention_pattern(kinds).search(heading["words"]):
        return text
    words = set(re.findall(r"[a-z']+", heading["words"]))
    if words <= _END_FRAME_WORDS and words & _END_WORDS and words & _PICTURE_WORDS:
        return "final layout:" + text[heading.end() :]
    return text


# "... when you're finished.": the end state, not an order ("when you're done, put ..." opens a step)
_BY_THE_END = re.compile(
    r",?\s*\b(?:when|once|by\s+the\s+time)\s+you(?:'re|\s+are|'ve|\s+have)\s+(?:all\s+)?(?:done|finished|through)"
    r"(?=\s*(?:[.;!?]|$))"
)
# "once that's sorted / taken care of / out of the way": a step done (said as "done", which check 1 knows);
# "(all) set" and "down" only where they end the clause ("when that's all set, ..."; not "set on the plate")
_DONE_WORDS = re.compile(
    r"\b(?P<that>that|this|those|these|it|they)(?:'s|s|\s+is|\s+are|'re)\s+(?:sorted|handled|through|over|"
    r"taken\s+care\s+of|out\s+of\s+the\s+way|loaded|filled|full|ready|"
    r"(?:all\s+)?(?:set|down)(?=\s*(?:[,.;:!?]|$)))\b"
)
# a non-native speaker's end of a step, with no subject or a bare verb: "when is finish(ed)", "after finish
# this", "once finishing all" (that is done); only where it ends its clause ("after finishing the orange, ..."
# names a task, and stays)
_UNSAID_DONE = re.compile(
    r"\b(?P<when>when|once|after)\s+(?:(?:it\s+)?is\s+finish(?:ed)?|(?:to\s+)?finish(?:ing)?\s+"
    r"(?:this|that|it|all)(?:\s+of\s+(?:this|that|it))?)(?=\s*(?:[,.;:!?]|$))"
)
_FIRST_THINGS = re.compile(r"\bfirst\s+things\s+first\b")


# "Each item is to be placed on its plate: ...": the plate of each, which the list after the heading names
_OWN_PLATE = re.compile(
    r"^(?P<head>[^:.;!?]*?)\s+(?:on|onto|in|into|to)\s+(?:its|their)\s+(?:own\s+|respective\s+|proper\s+)?"
    r"plates?\b(?=[^:.;!?]*:)"
)


def _own_plate_dropped(text: str, kinds: dict[str, bool]) -> str:
    """`text` without "on its plate" in a heading that names nothing ("each item is to be placed on its
    plate: the carrot on the blue plate, ..."): each thing's plate is the one the list gives it."""
    m = _OWN_PLATE.match(text)
    return m["head"] + text[m.end() :] if m and not mention_pattern(kinds).search(m["head"]) else text


def _tidied_as_put(text: str, kinds: dict[str, bool]) -> str:
    """ "sort the green apple onto the blue plate": a verb of tidying before a named object is the one
    action of this world, placing it."""
    objects = kind_pattern(kinds, plates=False).pattern
    return re.sub(rf"\b{TIDY_VERB}(?:\s+(?:out|up))?(?=\s+(?:the\s+)?{objects})", "put", text)


_RESPECTIVELY_WORDS = frozenset(
    "the and go goes put place move set on onto in into to should must plates please belong belongs be "
    "placed moved shall transfer transferred bring brought".split()
)
# a duty said in the passive ("are to be placed", "is to be set"): a request here, never a state
_TO_BE = re.compile(r"\b(?:is|are)\s+to\s+be\b")


def respectively_paired(text: str, kinds: dict[str, bool]) -> str:
    """ "the carrot and the orange go on the blue and yellow plates respectively" -> "put the carrot on
    the blue plate, the orange on the yellow plate": the n-th object with the n-th plate, where the
    clause names as many objects as plates (by colour or in full) and nothing else but placing words."""
    objects = kind_pattern(kinds, plates=False).pattern
    colours = {n.split()[0]: n for n, plate in kinds.items() if plate and len(n.split()) == 2}
    plate = rf"\b(?:{'|'.join(map(re.escape, colours))})(?:\s+plate)?\b"

    def paired(m: re.Match[str]) -> str:
        said = re.findall(rf"{objects}|{plate}", m["clause"])
        things = [_name(w) for w in said if _name(w) in kinds and not kinds[_name(w)]]
        plates = [colours[_name(w).split()[0]] for w in said if _name(w) not in things]
        rest = set(re.findall(r"[a-z']+", re.sub(rf"{objects}|{plate}|{_TO_BE.pattern}", " ", m["clause"])))
        one_each = len(things) == len(plates) > 1 and [_name(w) for w in said[: len(things)]] == things
        if not one_each or not rest <= _RESPECTIVELY_WORDS:
            return m[0]
        return "put " + ", ".join(f"the {o} on the {p}" for o, p in zip(things, plates, strict=True))

    # "Respectively, A and B go on ..." and "A and B are respectively to be placed on the blue and yellow
    # plates": the word closes its clause
    opening = r"(?:^|(?<=[.;!?]\s))respectively\s*,?\s+(?P<clause>[^.;:!?]+)"
    text = re.sub(opening, r"\g<clause> respectively", text)
    said_after = rf"(?:\s*,?\s*(?:{plate}|\b(?:{'|'.join(sorted(_RESPECTIVELY_WORDS | {'is', 'are'}))})\b))+"
    text = re.sub(rf"\s+respectively(?P<after>{said_after})", r"\g<after> respectively", text)
    return re.sub(r"(?P<clause>[^.;:!?]*?),?\s+respectively\b", paired, text)


# "fill it with X": only a plate is filled here
_FILL_IT = re.compile(r"\b(?P<verb>fill|load|stack)\s+(?:it|that\s+(?:plate|one))(?:\s+up)?\s+with\b")
# "once you're done / through with the yellow plate": the step on that plate; "move on to the blue plate":
# the next step's plate
_DONE_WITH = re.compile(
    r"\b(?:when|once|after)\s+you(?:'re|\s+are|'ve|\s+have)\s+(?:all\s+)?(?:done|finished|through)\s+with\s+"
    r"(?:the\s+)?(?P<plate>[a-z]+\s+plate)\b"
)
# "when the yellow plate is done": the same, said of the plate
_PLATE_DONE = re.compile(
    r"\b(?:when|once|after)\s+(?:the\s+)?(?P<plate>[a-z]+\s+plate)(?:'s|\s+is|\s+has\s+been)\s+"
    r"(?:all\s+)?(?:done|finished|full|complete|completed)\b"
)
_MOVE_ON = re.compile(
    r"\b(?:move|go|head|proceed)\s+on\s+to\s+(?:the\s+)?(?P<plate>[a-z]+\s+plate)(?P<and>\s+and\b)?"
)


def _moving_on_read(text: str, kinds: dict[str, bool]) -> str:
    """ "once you're done with the yellow plate, move on to the blue plate: carrot and red apple" -> "once
    that is done, the blue plate: carrot and red apple" ("when the yellow plate is done" too): done with the
    plate named last before it (the
    step just said), then the next plate ("move on to the blue plate and fill it with ..." -> "fill the
    blue plate with ..."); left where the plate done with is not the one named last."""
    plates = kind_pattern(kinds, plates=True)

    def done(m: re.Match[str]) -> str:
        before = [_name(p) for p in plates.findall(text, 0, m.start()) if _name(p) in kinds]
        return "once that is done" if before and before[-1] == _name(m["plate"]) else m[0]

    text = _PLATE_DONE.sub(done, _DONE_WITH.sub(done, text))
    return _MOVE_ON.sub(lambda m: "" if m["and"] else f"the {_name(m['plate'])}", text)


_ON_IT = re.compile(
    r"\b(?P<to>on|onto|in|into|to)\s+(?:it|that\s+(?:plate|one)|this\s+(?:plate|one)|the\s+same\s+(?:plate|one))\b"
)


def _plate_referred(text: str, kinds: dict[str, bool]) -> str:
    """ "on it" / "on that plate" / "on the same plate" as the plate named last before it (in this world
    only a plate holds things: "the yellow plate comes first: the green apple and the orange go on it");
    left where no plate is named before it."""
    plates = kind_pattern(kinds, plates=True)

    def referred(m: re.Match[str]) -> str:
        before = [_name(p) for p in plates.findall(text, 0, m.start()) if _name(p) in kinds]
        return f"{m['to']} the {before[-1]}" if before else m[0]

    def filled(m: re.Match[str]) -> str:
        before = [_name(p) for p in plates.findall(text, 0, m.start()) if _name(p) in kinds]
        return f"{m['verb']} the {before[-1]} with" if before else m[0]

    return _ON_IT.sub(referred, _FILL_IT.sub(filled, text))


def plates_by_colour(text: str, kinds: dict[str, bool]) -> str:
    """A plate said by its colour alone ("green apple -> blue", "the orange on the yellow") named in full:
    a colour word of a plate's name that starts no name and is followed by no noun of its own ("the
    green apple", "the blue and yellow plates" are left); "the yellow one" names the plate when no other
    name starts with "yellow" (not "the green one": the green apple or the green plate, but after a word of
    place, "on the green one", the plate)."""
    colours = {n.split()[0]: n for n, plate in kinds.items() if plate and len(n.split()) == 2}
    only_plate = [c for c in colours if sum(n.split()[0] == c for n in kinds) == 1]
    if only_plate:
        one = re.compile(rf"\b(?:the\s+)?(?P<c>{'|'.join(map(re.escape, only_plate))})\s+one\b")
        text = one.sub(lambda m: f"the {colours[m['c']]}", text)
    # "the green apple on the green one": after a word of place, "the green one" is where something goes, a
    # plate, though an object's name starts with "green" too
    after_place = re.compile(
        rf"\b(?P<at>(?:on|onto|upon|in|into|to)\s+)the\s+(?P<c>{'|'.join(map(re.escape, colours))})\s+one\b"
    )
    text = after_place.sub(lambda m: f"{m['at']}the {colours[m['c']]}", text)
    objects = kind_pattern(kinds, plates=False).pattern
    # "on the green and the red apple on the pink": after a word of place, a colour is where something
    # goes, a plate, even before "and" when an object follows ("the green and red apples" elsewhere)
    placed = re.compile(
        rf"\b(?P<at>(?:on|onto|upon|in|into|to)\s+(?:the\s+)?)(?P<c>{'|'.join(map(re.escape, colours))})"
        rf"(?=\s+and\s+(?:the\s+)?{objects})"
    )
    text = placed.sub(lambda m: f"{m['at']}{colours[m['c']]}", text)
    heads = {w for n in kinds for w in n.split()[1:]} | {"one", "ones", "and", "or", "plates", "plated"}
    alone = re.compile(rf"\b(?:{'|'.join(map(re.escape, colours))})\b(?!\s*(?:{'|'.join(sorted(heads))})\b)")
    out, at = [], 0
    for name in [*mention_pattern(kinds).finditer(text), None]:
        end = name.start() if name is not None else len(text)
        out.append(alone.sub(lambda m: colours[m[0]], text[at:end]))
        if name is not None:
            out.append(name[0])
            at = name.end()
    return "".join(out)


# a question that asks where objects go: "where does the green apple go?", "and the orange?", "what about
# the carrot?" (not "where is the carrot?": that asks where it is)
_ASKED_WHERE = re.compile(
    r"^\s*(?:and\s+)?(?:(?:where\s+(?:does|do|should|will|would|must|can)|what\s+about|how\s+about)\s+)?"
    r"(?P<objects>[a-z\s,']+?)(?:\s+(?:go|goes|belong|belongs|end\s+up|land))?\s*\?\s*$"
)


def answers_joined(text: str, kinds: dict[str, bool]) -> str:
    """A question that asks where objects go (`_ASKED_WHERE`), answered by the sentence after it that
    names a plate and no object, as one placement: "where does the green apple go? on the blue plate."
    -> "the green apple on the blue plate."."""
    pattern = mention_pattern(kinds)

    def named(words: str) -> set[bool | None]:
        return {kinds.get(_name(f).removesuffix("s")) for f in pattern.findall(words)}

    out: list[str] = []
    for sentence in re.split(r"(?<=[.;!?])(?![.;!?])", text):
        asked = _ASKED_WHERE.match(out[-1]) if out and named(sentence) == {True} else None
        if asked and named(asked["objects"]) == {False} and _only_names(asked["objects"], pattern):
            out[-1] = f" {asked['objects']} {sentence.lstrip()}"
        else:
            out.append(sentence)
    return "".join(out)


def _only_names(words: str, pattern: re.Pattern[str]) -> bool:
    """Are `words` names joined by "the", "a", "and" and commas alone ("the carrot and the orange")?"""
    return not re.sub(r"\b(?:the|and|a|an)\b|[\s,]", "", pattern.sub(" ", words))


def mention_pattern(names: Iterable[str], flags: int = 0) -> re.Pattern[str]:
    """Each name by its words ("green apple"), longest first, with a plural allowed so that a plural is
    seen (and refused) rather than missed."""
    ordered = sorted(names, key=len, reverse=True)
    alternatives = "|".join(r"\s+".join(map(re.escape, n.split())) + "s?" for n in ordered)
    return re.compile(rf"\b(?:{alternatives})\b", flags)


def kind_pattern(kinds: dict[str, bool], plates: bool) -> re.Pattern[str]:
    """`mention_pattern` of the plates (`plates`) or of the other things of `kinds` (name -> a plate?)."""
    return mention_pattern([n for n, plate in kinds.items() if plate == plates])


def corrected(text: str, kinds: dict[str, bool]) -> str:
    """A name followed by a correction marker and a name of the same kind (a plate for a plate, an object
    for an object) is replaced by it: "on the blue plate, sorry, the yellow plate" -> "on the yellow
    plate" (case kept; the names are found in any case)."""
    found = list(mention_pattern(kinds, re.IGNORECASE).finditer(text))
    for first, second in reversed(list(zip(found, found[1:], strict=False))):
        same_kind = kinds.get(_name(first[0].lower())) == kinds.get(_name(second[0].lower()))
        if same_kind and _CORRECTION.match(text[first.end() : second.start()].lower()):
            text = text[: first.start()] + text[second.start() :]
    return text


def _plurals_named(text: str, kinds: dict[str, bool], heads: dict[str, list[str]]) -> str:
    """ "the apples" / "both apples" / "the two apples" -> "the green apple and the red apple" when the
    world has several objects with that head noun and the count, if one is said, is theirs; a plural
    after a modifier ("green apples") or with another count is left (and refused)."""
    if not heads:
        return text
    modifiers = {w for n in kinds for w in n.split()[:-1]}
    counts = {"both": 2, "two": 2, "three": 3, "four": 4}
    plural = re.compile(
        r"\b(?:(?:all\s+(?:of\s+)?)?(?:the\s+)?(?P<count>both|two|three|four)\s+(?:of\s+the\s+)?|"
        rf"all\s+(?:of\s+)?the\s+|the\s+|all\s+)?(?P<head>{'|'.join(map(re.escape, heads))})s\b"
    )

    def named(m: re.Match[str]) -> str:
        before = text[: m.start("head")].split()
        said = counts.get(m["count"] or "")
        if (before and before[-1] in modifiers) or (said is not None and said != len(heads[m["head"]])):
            return m[0]
        return " and ".join(f"the {n}" for n in heads[m["head"]])

    return plural.sub(named, text)


def _names_a_word(words: str, kinds: dict[str, bool]) -> bool:
    """Does an aside use a word of a name ("the green one" could be another thing: it is left)?"""
    return not {w for n in kinds for w in n.split()}.isdisjoint(words.split())


def _name(found: str) -> str:
    return " ".join(found.split())
