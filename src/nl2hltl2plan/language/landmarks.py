"""Landmarks for check 1 (`accounting`): places named only to say where something goes *near*.

"Put the mug next to the microwave" names no destination: the microwave is a landmark. A reading that
puts the mug *in* the microwave (a model's guess, or a heating task its appliance seems to name) uses
the word for something the text does not say, so check 1 names it. "Put the mug on the counter next to
the microwave" is fine: the counter is the destination, the microwave where on it.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from pathlib import Path

from nl2hltl2plan.language.content_words import (
    DETERMINERS,
    ROOM_WORDS,
    Unread,
    categories,
    stems,
    verb_places,
)
from nl2hltl2plan.language.courtesy import courtesy_pattern
from nl2hltl2plan.language.grounding import RECEPTACLES, Mention, alfred_lookup, find_mentions
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.statements import says_where

# the words before a place that make it a landmark ("next to", "beside", "to the left of")
NEAR_WORDS = frozenset("near beside besides by next between behind against".split())
_NEAR_TWO = {
    ("next", "to"), ("close", "to"), ("closest", "to"), ("nearest", "to"), ("closer", "to"), ("near", "to"),
}  # fmt: skip
# a word before a bare "left"/"right" (no article) that makes the side a part of the place: "on the front left
# of the stove", "at left of"
_PART_BEFORE_SIDE = frozenset("on in at onto into upon front back far top bottom upper lower".split())


def near_word_before(toks: list[tuple[str, int, int]], start: int) -> bool:
    """Is the place whose first word is at `start` introduced by a word of nearness ("next to the", "by
    a", "in front of the", "to the left of the")?"""
    j = start - 1
    while j >= 0 and toks[j][0] in DETERMINERS:
        j -= 1
    if j < 0:
        return False
    if toks[j][0] in NEAR_WORDS - {"next"}:  # "next" alone is an order word: only "next to" is nearness
        return True
    if "of" in (w for w, _, _ in toks[j + 1 : start]):  # "of" is a determiner: it was passed over
        return _side_of(toks, j)
    return j >= 1 and (toks[j - 1][0], toks[j][0]) in _NEAR_TWO


def _side_of(toks: list[tuple[str, int, int]], j: int) -> bool:
    """Does the word at `j`, before "of", say a place beside the next one: "in front of", "(to the) left
    of", "to the right side of"? A side said with "on"/"in"/"at" is a part of that place ("on the left
    side of the stove", "at the front of the sink", "on the back of the toilet"): ALFRED's annotators
    put things there, on it (results/language/h184.md)."""
    if toks[j][0] == "front":
        return j >= 1 and toks[j - 1][0] == "in"
    if toks[j][0] == "side" and j >= 1:
        j -= 1
    if toks[j][0] not in ("left", "right"):
        return False
    j -= 1
    if j >= 0 and toks[j][0] == "the":
        j -= 1
        return j >= 0 and toks[j][0] == "to"
    return j < 0 or toks[j][0] not in _PART_BEFORE_SIDE  # "the drawer left of the sink"


# a posture's place may be a landmark too: "the apple sitting next to the bread", "lying by the sink"
_WHERE_PREPOSITIONS = frozenset({"on", "in", "at", "inside", "atop", "upon"}) | NEAR_WORDS


def posture_at(instruction: str, toks: list[tuple[str, int, int]], i: int) -> bool:
    """Is word `i` a posture before a place's preposition ("sitting on", "lying in", "sitting next to"):
    where a thing is (check 1 reads no action there)?"""
    nxt = toks[i + 1] if i + 1 < len(toks) else None
    return nxt is not None and nxt[0] in _WHERE_PREPOSITIONS and says_where(instruction, nxt[1])


# the verbs that treat a thing where it is taken to (a sink, a fridge, a microwave), never put it anywhere
_TREATMENTS = frozenset({"verb_clean_place", "verb_cool_place", "verb_heat_place"})


def of_a_treated_thing(toks: list[tuple[str, int, int]], m: Mention, clause: tuple[int, int]) -> bool:
    """Does the place `m` say where a thing is, in a clause (character span `clause`) whose verb treats
    it or throws it away and where no other verb puts anything ("wash the fork next to the coffee machine",
    "throw the apple by the microwave away")? The treatment's own place (the sink, the fridge, the
    trash) is said by the verb; a place said with "on" is where a treated thing is ("chill the tomato on
    the counter"), unless it is a thing to carry ("heat the apple on the plate") or the thing is thrown
    ("throw the apple on the counter" may say where it lands)."""
    start = pair_start(toks, m.start)
    said = [w for w, s, _ in toks[:start] if clause[0] <= s]
    treats = any(categories(w) & _TREATMENTS for w in said)
    thrown = [w for w in said if any(verb_places().get(f) == "GarbageCan" for f in stems(w))]
    if any("verb_any" in categories(w) for w in said if w not in thrown) or not (treats or thrown):
        return False
    if near_word_before(toks, start):
        return True
    j = start - 1
    while j >= 0 and toks[j][0] in DETERMINERS:
        j -= 1
    return treats and j > 0 and toks[j][0] in ("on", "upon") and not carried(m)


_PLACING = frozenset({"in", "on", "into", "onto", "inside"})


def listed_landmark(text: str, toks: list[tuple[str, int, int]], m: Mention, mentions: list[Mention]) -> bool:
    """Is the landmark `m` ("by the sink") said of an item of a list whose every later item has a landmark
    too and whose last one the destination: "put the mug by the sink and the bowl next to the stove in the
    cabinet"? Said alike of every item, each landmark tells which thing; the one place said with "in"/"on"
    is where they all go. With one item plain ("the mug by the sink and the bowl in the cabinet") where the
    mug goes is not said: that stays unread."""
    if not near_word_before(toks, m.start):
        return False
    later = sorted((o for o in mentions if o.start >= m.end), key=lambda o: o.start)
    at, k = m.end, 0
    while k + 1 < len(later) and at < len(toks) and _joined(text, toks, at):
        thing, mark = later[k], later[k + 1]
        between = [w for w, _, _ in toks[at : thing.start]]
        if any("verb_any" in categories(w) for w in between) or not near_word_before(toks, mark.start):
            return False
        at, k = mark.end, k + 2
        if k < len(later) and at < len(toks) and toks[at][0] in _PLACING and later[k].start <= at + 3:
            return True
    return False


def _joined(text: str, toks: list[tuple[str, int, int]], at: int) -> bool:
    """Does another item of a list start at word `at`: after "and", or after a comma (not a token)?"""
    return toks[at][0] == "and" or (at > 0 and "," in text[toks[at - 1][2] : toks[at][1]])


def landmark_destinations(
    mentions: list[Mention], toks: list[tuple[str, int, int]], parse: ParseUsage
) -> list[Unread]:
    """Destinations (receptacle slots) that the instruction names only as landmarks (a verb that names
    the place, "refrigerate the bread", names it as a destination)."""
    in_mention = {i for m in mentions for i in range(m.start, m.end)}
    places = verb_places()
    by_verb = {
        places[f]
        for i, (w, _, _) in enumerate(toks)
        if i not in in_mention and not _attributive(toks, i, in_mention)
        for f in stems(w)
        if f in places
    }
    out = []
    for task_id, role, types in parse.slots():
        if role != "receptacle" or types & by_verb:
            continue
        naming = [m for m in mentions if types & set(m.entry.types) or m.entry.canonical in types]
        if naming and all(near_word_before(toks, m.start) for m in naming):
            m = naming[0]
            out.append(
                Unread(
                    m.surface,
                    "place",
                    f"named only as a landmark, not as where task {task_id} puts it: say where (in, on ...)",
                )
            )
    return out


def _attributive(toks: list[tuple[str, int, int]], i: int, in_mention: set[int]) -> bool:
    """Is the word at `i` said of a thing ("a warmed apple", "clean sliced tomato") rather than done to it?
    Such a word names the treatment, never where the thing goes: "put a warmed apple in front of the
    microwave" leaves the destination unsaid."""
    after = toks[i + 1][0] if i + 1 < len(toks) else ""
    return (i > 0 and toks[i - 1][0] in DETERMINERS - {"of"}) or i + 1 in in_mention or after == "sliced"


def carried(m: Mention) -> bool:
    """A thing named after "with" that is no place ("a pan with a tomato slice in it", "a knife with an
    apple"): something the task moves too, never only where something is ("the dresser with the
    television" is a landmark: no robot moves a television). Without ALFRED's facts: what is no receptacle."""
    look = alfred_lookup()
    if look is None:
        return RECEPTACLES.isdisjoint(m.entry.types)
    return any((a := look(t)) is not None and a.pickupable for t in m.entry.types)


def on_the_place(toks: list[tuple[str, int, int]], at: int, m: Mention, places: list[Mention]) -> bool:
    """ "the side table with the pen on it": after "with" (at `at`), a thing said to be on or in the place
    named just before, a place no robot moves; the thing only says which place it is ("a plate with an
    apple on it" is a plate to move)."""
    before = [o for o in places if o.end == at and not carried(o)]
    after = [w for w, _, _ in toks[m.end : m.end + 2]]
    if not before:
        return False
    if after in (["on", "it"], ["in", "it"], ["on", "top"]):
        return True
    # "the end table with the statue": a thing that marks places (`marker_things.txt`), said definite right
    # after a place no robot moves, says which place it is, as "on it" does; "with the statue too" moves it
    marks = set(m.entry.types) <= MARKER_THINGS and toks[at + 1][0] == "the" and m.start <= at + 3
    return marks and (not after or after[0] not in _MOVED_WITH)


_MOVED_WITH = frozenset({"too", "also", "as", "in", "together", "both"})
_MARKERS = Path(__file__).with_name("marker_things.txt").read_text().splitlines()
MARKER_THINGS = frozenset(w.strip() for w in _MARKERS if w[:1].isalpha())


def pair_start(toks: list[tuple[str, int, int]], start: int) -> int:
    """For the place whose first word is at `start`: the first word of the place before it when the two
    are joined as "between the sink and the stove"; else `start`."""
    j = start - 1
    while j >= 0 and toks[j][0] in DETERMINERS:
        j -= 1
    if j < 2 or toks[j][0] != "and":
        return start
    k = j - 1
    while k >= 0 and j - k <= 4 and toks[k][0] not in ("between", ",", "and"):
        k -= 1
    if k < 0 or toks[k][0] != "between":
        return start
    first = k + 1
    while first < j - 1 and toks[first][0] in DETERMINERS:
        first += 1
    return first


# A plain place said inside a subject or a wish's object ("the soaps in the sink belong in the tub", "I'd like
# the keys on the table put in the box") says where the thing is now, as "from" does: the destination is the
# place after the verb. Places said with a word of nearness are landmarks already and stay as they are.
_WHERE_NOW = re.compile(
    r"\b(?:on|in|inside|atop|upon|at)\s+(?=(?:the|a|an|one\s+of\s+the|its|their|your|my|our)\s)", re.I
)
_PHRASE_END = re.compile(
    r"\b(?:on|in|inside|atop|upon|at|by|near|beside|next|between|behind|under|from|with|and|or)\b|"
    r"[,;.!?]|\s[-\u2013\u2014]\s",
    re.I,
)
# where a subject starts: after a clause's punctuation or joiner ("..., and the book on the bed goes ..."),
# never at "and from", which goes on a list of sources ("the spatulas from the sink and from the table go")
_CLAUSE_START = re.compile(
    r"[.;:!?,]\s*|\s[-\u2013\u2014]\s|\b(?:and|then|also|but|so|plus|oh)\s+(?!from\s)", re.I
)
# a landmark said with a word of nearness ("the apple next to the sink should go in the fridge")
_NEAR_SAID = re.compile(
    r"\b(?:next\s+to|close\s+to|beside|by|near|between|behind|in\s+front\s+of)\s+(?:the|a|an|two)\s", re.I
)
# a part of the room, or the room, after a subject's place: "the book on the armchair in the corner"
_ROOM_PART_LAST = re.compile(
    r"\s(?:in|on|at)\s+the\s+(?:corner|middle|back|front|left|right|end|"
    + "|".join(r"\s+".join(w.split()) for w in ROOM_WORDS)
    + r")\s*$",
    re.I,
)
# a wish's participle before the destination: "I'd like X put in D"
_PARTICIPLE = (
    r"\s+(?:put|placed|moved|set|left|taken|brought)(?:\s+(?:it|them))?\s+(?=(?:in|into|on|onto|inside|to)\s)"
)
_THING_FIRST = r"(?=(?:the|a|an|both|two|three|\d+|all|my|your|one|those|these)\b)"


def places_as_sources(phrase: str) -> str:
    """The noun phrase with each plain place in it said as a source: "the soaps from the sink"."""
    out, pos = [], 0
    for m in _WHERE_NOW.finditer(phrase):
        end = _PHRASE_END.search(phrase, m.end())
        if find_mentions(phrase[m.end() : end.start() if end else len(phrase)]):
            out.append(phrase[pos : m.start()] + "from ")
            pos = m.end()
    return "".join(out) + phrase[pos:]


def subject_sources(
    text: str, verb: re.Pattern[str], names_object_before: Callable[[str, int], bool], near_too: bool = True
) -> str:
    """The text with the places of each subject before a verb of going (`verb`: "goes", "belongs",
    "should go" ...) said as sources and the request's verb said: "the book on the armchair goes on the
    table" -> "put the book from the armchair on the table". A subject is the clause's words before the
    verb, a name last or a part of the room after it ("the book on the armchair in the corner").
    `near_too=False`: a subject whose only place is said with a word of nearness is left as it is."""
    out = text
    for m in reversed(list(verb.finditer(text))):
        start = max((c.end() for c in _CLAUSE_START.finditer(text, 0, m.start())), default=0)
        said = text[start : m.start()]
        room_part = _ROOM_PART_LAST.search(said) and find_mentions(said)
        if not (names_object_before(text, m.start()) or room_part):
            continue
        subject = places_as_sources(said)
        # a clause of a subject and its place only ("the book on the bed goes on the desk") is a request
        near = near_too and _NEAR_SAID.search(subject)
        if (subject != said or near) and re.match(_THING_FIRST, subject, re.I):
            out = out[:start] + "put " + subject + " " + out[m.end() :].lstrip()
        elif subject != said:
            out = out[:start] + subject + out[m.start() :]
    return out


# A source split over the things of a plural, or said of one of them, before where they go: "both spatulas,
# the one next to the wine bottle and the one by the toaster, go in a drawer", "two bars of soap: one's in
# the sink and the other's on the counter. Both go in the drawer", "the other knife, the one under the
# microwave, in a cup". Each piece says where a thing is now: read as sources, "both spatulas from next to
# the wine bottle and from by the toaster go in a drawer". Pieces with no destination after them ("put the
# two mugs, one in the sink and the other on the counter") say where each goes and are left as they are.
_PLAIN_AT = r"on\s+top\s+of|inside|on|in|at|atop|upon|from|off(?:\s+of)?|out\s+of"
_NEAR_AT = (
    r"next\s+to|close\s+to|by|near|beside|between|behind|under|underneath|beneath|below|above|in\s+front\s+of"
)
_ONE_AT = (
    r"(?:the\s+)?(?:one|other(?:\s+one)?|first|second|another)(?:'s|\s+is|\s+that's|\s+that\s+is|\s+which\s+is|"
    r"\s+sitting|\s+lying)?\s+(?:(?P<plain{n}>" + _PLAIN_AT + r")|(?P<near{n}>" + _NEAR_AT + r"))\s+"
    r"(?P<place{n}>(?:the|a|an|its|their|your|my)\s[^,;:.!?]*?)"
)
# a destination after the pieces: a verb of going or a place's preposition; or "Both go ..." after a stop
_GOES_ON = r"(?=(?:go|goes|belong|belongs|should|need|needs|must|have|has|are|in|into|on|onto|to|inside)\b)"
_THEN_THEY = r"\.\s+(?:both(?:\s+of\s+them)?|they(?:\s+both)?)\s+" + _GOES_ON
_SPLIT_SOURCE = re.compile(
    r"(?:,|:|\s[-\u2013\u2014])\s*"
    + _ONE_AT.format(n=1)
    + r"(?:\s+and\s+"
    + _ONE_AT.format(n=2)
    + r")?(?:,\s*"
    + _GOES_ON
    + r"|"
    + _THEN_THEY
    + ")",
    re.I,
)


# a room opening a sentence says where all its things are: "In the bedroom, the two CDs ... go on the dresser"
_ROOM_OPENER = re.compile(
    r"(?:^|(?<=[.;!?]\s))\s*(?:in|inside|at)\s+the\s+(?:"
    + "|".join(r"\s+".join(w.split()) for w in ROOM_WORDS)
    + r")\s*,\s*(?P<first>\w)",
    re.I,
)


# a posture said of a thing with a plain place says where it is now, as "from" does: "the knife lying in the
# sink on a plate" (with a word of nearness it is a landmark already, `posture_at`); never after "leave" or
# "keep", or a wish or "be" ("I want the apple sitting on the plate", "it should be resting on the plate": an
# end state), or of "it" ("leave it lying on the bed" says where it goes)
_POSTURE_IN = re.compile(
    r"(?<!\bit)(?<!\bthem)\s+(?:that's\s+|that\s+is\s+|which\s+is\s+)?"
    r"(?:sitting|lying|laying|located|standing|resting|kept|stored)\s+(?:in|on|inside|at|atop)\s+"
    r"(?=(?:the|a|an|its|their|your|my)\s)",
    re.I,
)
_KEPT_AS = re.compile(  # the wish verbs are the wish readers' (`courtesy.txt`'s `wish_verb`), a person's too
    rf"\b(?:leave|leaving|left|keep|keeping|have|let|see|be|{courtesy_pattern('wish_verb')}s?)\b[^,.;!?]*$",
    re.I,
)


def where_things_are(text: str) -> str:
    """The text with each split source and posture (above) said as sources of the thing before it, and a room
    that opens a sentence left out."""
    text = _ROOM_OPENER.sub(lambda m: m["first"].upper(), text)
    text = _POSTURE_IN.sub(lambda m: m[0] if _KEPT_AS.search(text, 0, m.start()) else " from ", text)

    def said(m: re.Match[str], n: int) -> str:
        near = m[f"near{n}"]
        return ("from " + near.lower() + " " if near else "from ") + m[f"place{n}"]

    def sources(m: re.Match[str]) -> str:
        if m["place2"] is None and not re.match(r"[,:]\s*the\s+one\b", m[0], re.I):
            return m[0]  # one piece alone is "the one ...": "two mugs, one in the sink, ..." is not a source
        both = said(m, 1) + (" and " + said(m, 2) if m["place2"] is not None else "")
        return " " + both + " "

    return _SPLIT_SOURCE.sub(sources, text)


def wished_put(text: str, wish: re.Pattern[str]) -> str:
    """ "I'd like the keys on the coffee table put in the open box": a wish's object before its participle
    is the thing, every plain place in it where the thing is -> "put the keys from the coffee table in the
    open box". A wish with a verb after it ("I'd like you to put ...") is left as it is."""
    said = re.compile(wish.pattern + _THING_FIRST + r"(?P<thing>[^.;!?,]*?)" + _PARTICIPLE, wish.flags)

    def put(m: re.Match[str]) -> str:
        return "put " + places_as_sources(m["thing"]) + " " if find_mentions(m["thing"]) else m[0]

    return said.sub(put, text)


# "put away the mug in the sink": the one place after "put away X" where things are left out, not stored
# (`left_out_places.txt`): where the mug is now (put away from the sink), or where it goes? (h206, read as
# the sink, at exit 0); "put away the mug in the cabinet", "put the mug away in the sink" stay the grammar's
_NAMED = r"(?:the|a|an|my|your)\s+[a-z]+(?:\s+(?!(?:and|then|please|in|on|into|onto|inside)\b)[a-z]+)?"
_PUT_AWAY_IN = re.compile(
    rf"\b(?:put|place|set)\s+away\s+(?P<thing>{_NAMED})\s+(?:in|on|into|onto|inside)\s+(?P<place>{_NAMED})"
    r"\s*(?=[.,;!?]|$|\s+(?:and|then|please)\b)",
    re.I,
)
_LEFT_OUT = frozenset(
    w
    for line in (Path(__file__).parent / "left_out_places.txt").read_text().splitlines()
    if not line.startswith("#")
    for w in line.split()
)


def put_away_unread(text: str) -> list[Unread]:
    """ "put away X in P" where P is a place where things are left out: named unread, as no reading can tell
    whether P is where X is or where it goes.

    >>> [u.words for u in put_away_unread("Put away the mug in the sink. Put away the cup in the cabinet.")]
    ['Put away the mug in the sink']
    """
    out = []
    for m in _PUT_AWAY_IN.finditer(text):
        named = find_mentions(m["place"].lower())
        if len(named) == 1 and set(named[0].entry.types) <= _LEFT_OUT:
            why = f"is {m['place']} where {m['thing']} is, or where it goes? say where to put it away"
            out.append(Unread(m[0].strip(), "place", why))
    return out


# "the bowl (that) the mug is in", "the shelf the vase is next to": a relative clause that leaves its
# preposition at its end (nothing named after it) says where the thing before it is; its subject is a
# landmark, never a destination or a second task (h227's leftover, h236)
_STRANDED_WHERE = re.compile(
    r"\s+(?:is|are|'s|sits|was)\s+(?:(?:sitting|lying|standing|now|already)\s+)?"
    r"(?:next\s+to|close\s+to|in|on|by|beside|near|inside|at|under|behind)"
    r"(?=\s*(?:[,.;!?]|$|(?:in|into|on|onto|to|and|then|please)\b))",
    re.I,
)
_AFTER_A_NAME = re.compile(r"\s+(?:(?:that|which)\s+)?(?:the|a|an|my|your|our)\s+$", re.I)


def relative_subject(instruction: str, m: Mention, mentions: list[Mention]) -> bool:
    """Is `m` the subject of such a relative clause, right after another thing's name?"""
    before = [x for x in mentions if x.char_end <= m.char_start]
    return bool(
        before
        and _AFTER_A_NAME.fullmatch(instruction, before[-1].char_end, m.char_start)
        and _STRANDED_WHERE.match(instruction, m.char_end)
    )


# A thing's place said as a sentence of its own, then the thing as "it" (users_h271's C2): "my phone is on
# the desk, can you bring it to the bed", "there's an apple on the counter. chill it ..." is "take the phone
# from the desk, ... bring it ...", whose place the grammar reads as a source; only where the next clause
# opens (after a request) with one of the grammar's verbs and "it" / "them" (not "put the pen in it")
_STATED_PLACE = re.compile(
    r"(?:^|(?<=[.!?]\s))(?:(?P<there>there(?:'s|\s+is|\s+are)\s+)(?P<det>a|an|the|my|your|two)|(?P<det2>the|my|your|a|an|two))"
    r"\s+(?P<thing>[a-z]+(?:\s+[a-z]+){0,2}?)\s+(?(there)|(?:is|are|'s)\s+)"
    r"(?P<place>(?:on|in|inside|by|near|next\s+to|under)\s+(?:the|my|your)\s+[a-z]+(?:\s+[a-z]+)?)"
    r"(?P<sep>\s*[,.;]\s*|\s+(?:and|so)\s+)"
    r"(?=(?:(?:can|could|would)\s+(?:you|u)\s+|please\s+|pls\s+)?(?P<verb>[a-z]+)\s+(?:it|them)\b)",
    re.I,
)


def places_stated(text: str, verbs: Collection[str]) -> str:
    """The text with each thing whose place is said as a sentence before "VERB it" said with its place
    only (see `_STATED_PLACE`); `verbs`: the grammar's verbs. A phrase naming no one thing is left."""

    def topic(m: re.Match[str]) -> str:
        if m["verb"].lower() not in verbs or len(find_mentions(m["thing"])) != 1:
            return m[0]
        place = re.sub(r"^(?:on|in|inside)\b", "from", m["place"], flags=re.I)
        det = "two" if (m["det"] or m["det2"]).lower() == "two" else "the"
        return f"take {det} {m['thing']} {place}, "

    return _STATED_PLACE.sub(topic, text)
