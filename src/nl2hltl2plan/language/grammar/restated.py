"""Requests restated around their places or end states (issue 28), rewritten onto the plain "put X on Y"
before the grammar's rules. Each rule rewrites only words whose object and place phrases the scene's
lexicon names (`find_mentions`), so a sentence about anything else is left as it is:

- "the yellow one": "one" stands for the head noun of the nearest earlier noun phrase in the same role
  (a place after a place word, an object otherwise), kept only when "yellow plate" names something;
- a header before a colon that counts the placements listed after it ("Place three fruits: the green
  apple on the pink plate, ...") keeps only its verb, when the count, if it says one, is the number of
  placements listed in that sentence;
- a topic header ("Start with the yellow plate: put the green apple on it.", "Then the blue plate: the
  carrot and the red apple, any order"): "it" in the clause is the topic; a clause of objects alone is
  put on the topic; the order word stays ("start with" is "first");
- the place as subject: "(the) yellow plate (has to) get(s) the green apple" is "put the green apple on
  the yellow plate", and in the same sentence ", the blue plate the red apple" is one more;
- a place's need: "the bin needs X, Y and Z" (or "could use") is "put X, Y and Z on the bin", and "the
  sink needs X and the fridge needs Y" two such clauses, when the place is a receptacle and each listed
  thing ends in a name the lexicon knows ("the sink needs a scrub" and "the table needs the mug moved off
  it" stay as said: h291);
- "load / fill / stock the yellow plate with X and Y" is "put X and Y on the yellow plate";
- a record "Blue plate: carrot." (or "Carrot: blue plate.") is "put the carrot on the blue plate" when
  exactly one side is a receptacle;
- the place fronted: "onto the blue plate goes the green apple", "on the pink plate put the green apple,
  on the yellow plate the orange", "for the blue plate the carrot";
- goals stated as a passive or an end state: "needs to be placed", "must be put", "ends up", "should
  sit", "lands", "is to go", "should be left" before a place are "goes" (which `supply_put` reads), "X is to
  be thrown away" is "take X and throw it out", "make sure X is on Y" is "X goes on Y",
  "I want to see X on Y" is "I want X on Y", an opening "By the end," is dropped (no earlier task);
- an ordered clause about what goes where: "before anything goes on the blue plate" is "before you put
  anything on the blue plate", "only after that should X be placed on Y" is "after that, put X on Y".
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import categories
from nl2hltl2plan.language.grounding import MOVABLE_RECEPTACLES, RECEPTACLES, Mention, find_mentions

_PLACE = r"(?:on|onto|in|into|inside)"
_NP = r"(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,2}?"  # a short noun phrase; checked against the lexicon
_ORDER = r"(?:(?:start|begin)\s+with|first(?:ly)?|then|next|after\s+that|finally|lastly)"
NUMBER_WORDS = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6}
_CLAUSE_START = r"(?:^|(?<=[.;!?])\s+)"

_ONE = re.compile(r"\b(?P<det>the|a)\s+(?P<adj>[a-z]+)\s+one\b(?!\s+(?:of|after|by)\b)", re.I)
_COUNTED_HEADER = re.compile(
    rf"{_CLAUSE_START}(?:(?P<verb>place|put|set|move|arrange|lay)\s+)?"
    r"(?:(?P<count>two|three|four|five|six|\d)|these|the\s+following)\s+[a-z]+(?:\s+[a-z]+){0,3}?\s*:\s*",
    re.I,
)
# a topic before a colon: "the yellow plate: ...", and a fixed place named bare or by its back or top
# ("armchair: 2 newspapers and 2 cards", "back of the toilet: a sponge", users_h300, h315)
_TOPIC_HEADER = re.compile(
    rf"{_CLAUSE_START}(?:(?P<order>{_ORDER})\s*,?\s+)?(?P<part>(?:the\s+)?(?:back|top)\s+of\s+)?"
    r"(?P<topic>(?:the\s+)?[a-z]+(?:\s+[a-z]+){0,2}?)\s*:\s*(?P<clause>[^.;!?:]+)",
    re.I,
)
# the count that may open a list of things after a topic ("armchair: 2 newspapers and 2 cards")
_COUNT_LEAD = re.compile(r"^\s*(?:\d+|two|three|four|five|six)\s+(?=[a-z])", re.I)
_GETS = r"(?:(?:should|must|will|has\s+to|have\s+to|needs?\s+to)\s+(?:get|receive)|gets|receives)"
_SUBJECT_PLACE = re.compile(
    rf"(?:{_CLAUSE_START}|(?<=,)\s*(?:and\s+)?|\s+and\s+)(?P<place>(?:the\s+)?[a-z]+(?:\s+[a-z]+)?)\s+{_GETS}\s+"
    r"(?P<objs>(?:the|a|an)\s+[^,.;!?]+?)"
    r"(?=\s+(?:before|after|until|once|when|then|first)\b|\s*[,.;!?]|\s+and\s+the\s+[a-z]+(?:\s+[a-z]+)?\s+"
    rf"{_GETS}|$)",
    re.I,
)
_NEEDS = r"(?:needs|could\s+use)"
_PLACE_NEEDS = re.compile(
    r"(?:^|(?<=[.;:!?,])|(?<=\band)|(?<=\bthen)|(?<=\bso)|(?<=\bok)|(?<=\balso))(?P<sp>\s*)"
    rf"(?P<place>the\s+[a-z]+(?:\s+[a-z]+)?)\s+{_NEEDS}\s+"
    r"(?P<objs>(?:the|a|an|one|two|three|four|\d+)\s+[^.;:!?]+?)"
    r"(?=\s*[.;:!?]|\s*,\s*(?:and\s+)?(?:then\s+)?the\s+[a-z]+(?:\s+[a-z]+)?\s+"
    rf"{_NEEDS}\b|\s+and\s+(?:then\s+)?the\s+[a-z]+(?:\s+[a-z]+)?\s+{_NEEDS}\b|"
    r"\s*,?\s+(?:and\s+)?(?:then|before|after|once|when|too|as\s+well|first|last)\b|\s*,\s*(?:thx|thanks|pls|please)\b|$)",
    re.I,
)
_LIST_SPLIT = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+", re.I)
# ", the blue plate the red apple" after a place-as-subject clause: two noun phrases side by side
_PLACE_OBJECT_PAIR = re.compile(
    rf"(?P<join>,\s*(?:and\s+)?|\s+and\s+)(?P<place>{_NP})\s+(?P<obj>{_NP})(?=\s*[,.;!?]|\s+and\s|$)", re.I
)
_FRONTED_PLACE = re.compile(
    rf"(?P<lead>{_CLAUSE_START}|,\s*(?:and\s+)?|\s+and\s+)(?P<order>{_ORDER}\s*,?\s+)?"
    rf"(?P<prep>{_PLACE}|for)\s+(?P<place>the\s+[a-z]+(?:\s+[a-z]+)??)\s*[,:]?\s+(?P<order2>first\s+)?"
    r"(?:(?:goes|go|put|place|set|lay)\s+)?(?P<objs>(?:the|a|an)\s+[^,.;!?]+?)"
    r"(?=\s*[,.;!?]|\s+(?:in\s+any|in\s+whatever|in\s+either)\b|\s+and\s+(?:on|onto|in|into|for)\s+the\b|$)",
    re.I,
)
_PASSIVE_GOAL = re.compile(
    r"\s+(?:(?:needs?|has|have|is|are)\s+to\s+be\s+(?:placed|put|set|moved|laid|dropped|left|kept|stored)|"
    r"(?:must|should|will|shall|can)\s+be\s+(?:placed|put|set|moved|laid|dropped|left|kept|stored)|"
    r"(?:is|are|needs?|has|have)\s+to\s+go|"
    r"(?:(?:should|must|has\s+to|have\s+to|needs?\s+to|will)\s+)?(?:ends?\s+up|sits?|rests?|lands?)|"
    r"(?:should|must|has\s+to|have\s+to|needs?\s+to|will)\s+(?:end\s+up|sit|rest|land)|"
    r"(?:should|must|has\s+to|have\s+to|needs?\s+to|will)\s+be\s+(?:sitting|resting|lying|standing))\s+"
    rf"(?={_PLACE}\s)",
    re.I,
)
# a decree's passive that takes a thing and lays it down ("two cell phones shall be taken from the shelves and
# laid upon the desk", paper_h301): "take two cell phones from the shelves and put them on the desk"
_TAKEN_AND_LAID = re.compile(
    r"(?P<lead>^|(?<=[.;!?:,])\s*|\s+and\s+)(?P<np>(?:the|a|an|one|two|three|both)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s+"
    r"(?:shall|must|will|should|is\s+to|are\s+to|(?:needs?|has|have)\s+to)\s+be\s+"
    r"(?:taken|removed|lifted|brought|moved|carried|fetched)\s+"
    r"(?P<src>(?:from|off|out\s+of)\s+(?:the|a|an|its|their)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s+and\s+(?:be\s+)?"
    r"(?:laid|placed|put|set|left|stored|dropped)\s+(?P<prep>upon|atop|on|onto|in|into|inside)\s+(?=(?:the|a|an)\s)",
    re.I,
)
# "the spray bottle on the counter is to be thrown away" (h223): the thing, up to its landmark, thrown away
_THROWN = re.compile(
    r"(?P<lead>(?:^|(?<=[.;!?:])\s*|,\s*(?:and\s+)?|\s+and\s+))(?P<np>(?:the|a|an|two|both)\s+[^,.;!?]+?)\s+"
    r"(?:(?:needs?|has|have|is|are)\s+to\s+be|(?:must|should|will|shall|can)\s+be)\s+"
    r"(?:thrown|tossed|binned|chucked)\s+(?:away|out)\b",
    re.I,
)
_MAKE_SURE = re.compile(r"\b(?:make\s+sure|ensure|see\s+to\s+it)(?:\s+that)?\s+(?P<rest>[^.;!?]+)", re.I)
_IS_ON = re.compile(rf"\s+(?:is|are)\s+(?={_PLACE}\s)", re.I)
_WANT_TO_SEE = re.compile(r"\b((?:I|we)(?:'d|\s+would)?\s+(?:like|want|love|need))\s+to\s+see\b", re.I)
_END_STATE_OPENER = re.compile(
    r"^\s*(?:by|at|in)\s+the\s+end|^\s*(?:when|once)\s+you(?:'re|\s+are)\s+(?:finished|done)", re.I
)
_CLAUSE_GOES = re.compile(
    r"\b(?P<rel>before|after|until|once|when)\s+"
    r"(?P<objs>(?:the|a|an)\s+[^,.;!?]+?|anything|everything|any\s+of\s+them)"
    rf"\s+(?:goes|go|is\s+put|are\s+put|gets?\s+put|lands?)\s+(?P<prep>{_PLACE})\s+(?=the\s)",
    re.I,
)
# "Blue plate: carrot." / "Carrot: blue plate." records, one placement each
_RECORD = re.compile(
    rf"{_CLAUSE_START}(?P<a>(?:the\s+)?[a-z]+(?:\s+[a-z]+)?)\s*:\s*(?P<b>(?:the\s+)?[a-z]+(?:\s+[a-z]+)?)"
    r"\s*(?=[.;]|$)",
    re.I,
)
# "load the yellow plate with the green apple and the orange": the things go on the place
_LOAD_WITH = re.compile(
    r"\b(?:load|fill|stock)\s+(?P<place>the\s+[a-z]+(?:\s+[a-z]+)?)\s+with\s+(?P<objs>(?:the|a|an)\s+[^,.;!?]+?)"
    r"(?=\s+(?:first|then|next|before|after|once|when)\b|\s*[,.;!?]|$)",
    re.I,
)
_ALTERNATIVES = re.compile(r"\s+or\s+(?=(?:the|a|an)\s)", re.I)  # "the carrot or the red apple"
_INVERTED_AFTER = re.compile(
    r"\b(?:only\s+)?(?P<rel>after\s+(?:that|this)|then|afterwards)\s*,?\s+(?:should|must|can|may|will)\s+"
    rf"(?P<objs>(?:the|a|an)\s+[^,.;!?]+?)\s+(?:be\s+(?:placed|put|set|moved)|go)\s+(?={_PLACE}\s)",
    re.I,
)

# "the lotion and the tissues both go on the tank", "a bowl, a pan and a pot each go in the sink": after a
# list of things "both" / "each" / "all" counts nothing of its own (each thing is a task of its own) (h216)
_EACH_OF_LIST = re.compile(
    rf"{_CLAUSE_START}(?P<objs>(?:the|a|an)\s+[^.;!?]*?\band\s+(?:the|a|an)\s+[^.;!?]+?)\s+(?:both|each|all)\s+"
    rf"(?=(?:go|belong|(?:need|have)\s+to\s+go|should\s+go)\s+{_PLACE}\s)",
    re.I,
)

# "wash the ladle and put it in a drawer, and the two spatulas go in a drawer as well": a placing said with
# "goes" after a task's clause is a request of its own ("and put the two spatulas in a drawer"); left
# verbless, its counted things were read as a second object of the clause before (h216)
_AND_GOES = re.compile(
    r",\s*and\s+(?P<np>(?:the|a|an|two|both|three)\s+[^,.;!?]+?)\s+(?:goes|go|belongs?|should\s+go)\s+"
    rf"(?={_PLACE}\s)",
    re.I,
)
_TASK_VERB = frozenset({"verb_any", "verb_clean_place", "verb_heat_place", "verb_cool_place"})


def _and_put(text: str, m: re.Match[str]) -> str:
    """ ", and put X " where a task verb comes before in the sentence and X names a thing; else as said."""
    start = max(text.rfind(c, 0, m.start()) for c in ".;!?\n") + 1
    verbs = any(categories(w) & _TASK_VERB for w in re.findall(r"[a-z]+", text[start : m.start()].lower()))
    named = any(not x.entry.generic for x in find_mentions(m["np"]))
    return f", and put {m['np']} " if verbs and named else m[0]


def restated(text: str) -> str:
    """The text with the restated requests above written as plain placements."""
    text = _AND_GOES.sub(lambda m: _and_put(text, m), text)
    text = _EACH_OF_LIST.sub(lambda m: m[0][: m.end("objs") - m.start()] + " ", text)
    text = _ONE.sub(lambda m: _one_named(text, m), text)
    text = _COUNTED_HEADER.sub(lambda m: _without_header(text, m), text)
    text = _TOPIC_HEADER.sub(_topic_clause, text)
    text = _subject_places(text)
    text = _PLACE_NEEDS.sub(_needs_put, text)
    text = _FRONTED_PLACE.sub(_fronted, text)
    text = _LOAD_WITH.sub(_loaded, text)
    text = _RECORD.sub(_record_put, text)
    text = _WANT_TO_SEE.sub(r"\1", text)
    text = _MAKE_SURE.sub(lambda m: _IS_ON.sub(lambda i: _goes(m["rest"], i), m["rest"]), text)
    text = _PASSIVE_GOAL.sub(lambda m: _goes(text, m), _TAKEN_AND_LAID.sub(_taken_and_laid, text))
    text = _THROWN.sub(_thrown, text)
    text = _CLAUSE_GOES.sub(_you_put, text)
    text = _INVERTED_AFTER.sub(_after_then_put, text)
    opener = _END_STATE_OPENER.match(text)
    if opener and text[opener.end() :].lstrip().startswith(","):
        text = text[opener.end() :].lstrip(" ,")
    return text


def _taken_and_laid(m: re.Match[str]) -> str:
    """ "X shall be taken from A and laid upon B" -> "take X from A and put it (them) on B" (see above)."""
    counted = re.match(r"(?:one|two|three|both)\s+", m["np"], re.I)
    if not _is_named(m["np"][counted.end() :] if counted else m["np"]):
        return m[0]
    them = "them" if counted and counted[0].strip().lower() != "one" else "it"
    prep = "on" if m["prep"].lower() in ("upon", "atop") else m["prep"]
    return f"{m['lead']}take {m['np']} {m['src']} and put {them} {prep} "


def _is_named(phrase: str, whole: bool = False) -> bool:
    """Does the phrase start with (or, with `whole`, consist of) a name the lexicon knows?"""
    phrase = phrase.strip()
    found = find_mentions(phrase)
    if not found:
        return False
    head = found[0]
    if whole:
        alone = len(found) == 1 and phrase[head.char_end :].strip() == ""
        return alone and _det_only(phrase[: head.char_start])
    return _det_only(phrase[: head.char_start])


def _det_only(words: str) -> bool:
    return re.fullmatch(r"\s*(?:(?:the|a|an)\s+)?", words, re.I) is not None


def _in_place_role(text: str, at: int) -> bool:
    return re.search(rf"\b{_PLACE}\s+(?:the\s+|a\s+)?$", text[:at], re.I) is not None


def _one_named(text: str, m: re.Match[str]) -> str:
    """ "the yellow one" -> "the yellow plate" from the nearest earlier noun phrase in the same role."""
    role = _in_place_role(text, m.start())
    earlier: list[Mention] = [
        x for x in find_mentions(text[: m.start()]) if _in_place_role(text, x.char_start) == role
    ]
    if not earlier:
        return m[0]
    candidate = f"{m['adj']} {earlier[-1].surface.split()[-1]}"
    return f"{m['det']} {candidate}" if _is_named(candidate, whole=True) else m[0]


def count_fits(count: str | None, listed: int) -> bool:
    """A heading's count ("four things need plates:", "3 moves:"; a word or digits) is the number of things
    listed after it; a heading without one fits any list."""
    return not count or (NUMBER_WORDS.get(count.lower()) or int(count)) == listed


def _without_header(text: str, m: re.Match[str]) -> str:
    """The header's verb alone when the count fits the placements listed in its sentence."""
    sentence = re.split(r"[.;!?]", text[m.end() :], maxsplit=1)[0]
    placements = re.findall(rf"\b{_PLACE}\s+the\s+", sentence, re.I)
    if not count_fits(m["count"], len(placements)):
        return m[0]
    if len(placements) < 2 or not _is_named(sentence):
        return m[0]
    lead = m[0][: len(m[0]) - len(m[0].lstrip())]
    return f"{lead}{m['verb'] or 'put'} "


def _topic_clause(m: re.Match[str]) -> str:
    """ "Start with the yellow plate: put the green apple on it" -> "First put the green apple on the
    yellow plate"; a clause of objects alone is put on the topic."""
    topic, clause = m["topic"], m["clause"]
    if not _is_named(topic, whole=True):
        return m[0]
    if m["part"] or not re.match(r"the\s", topic, re.I):  # only a fixed place: "mug: sink" is a record
        if not fixed_place(topic):
            return m[0]
        part = re.sub(r"^(?!the\s)", "the ", m["part"].lower()) if m["part"] else ""
        topic = part + "the " + re.sub(r"^the\s+", "", topic, flags=re.I)
    lead = m[0][: len(m[0]) - len(m[0].lstrip())]
    order = (m["order"] or "").lower()
    order = "first " if order.startswith(("start", "begin")) else (f"{order}, " if order else "")
    pronoun = re.search(r"\b(?:it|them)\b", clause, re.I)
    if pronoun:
        body = clause[: pronoun.start()] + _lower_article(topic) + clause[pronoun.end() :]
    else:
        objs, rest = re.match(r"([^,]*)(.*)", clause).groups()  # type: ignore[union-attr]
        if not _is_named(_COUNT_LEAD.sub("", objs)) or re.search(rf"\b{_PLACE}\b", objs, re.I):
            return m[0]
        body = f"put {objs.strip()} on {_lower_article(topic)}{rest}"
    return f"{lead}{order}{body}"


def fixed_place(phrase: str) -> bool:
    """Does the phrase name a place that stays where it is (a receptacle no one carries: "armchair")?"""
    found = find_mentions(phrase)
    fixed = RECEPTACLES - MOVABLE_RECEPTACLES
    return bool(found) and all(t in fixed for t in found[0].entry.types)


def _subject_places(text: str) -> str:
    """ "the yellow plate gets X, the blue plate Y" -> "put X on the yellow plate, put Y on the blue
    plate"."""
    found = [
        m
        for m in _SUBJECT_PLACE.finditer(text)
        if _is_named(m["place"], whole=True) and _is_named(m["objs"])
    ]
    out, pos = [], 0
    for k, m in enumerate(found):
        lead = m[0][: m.start("place") - m.start()]  # "and " or the space before the clause
        out.append(f"{text[pos : m.start()]}{lead}put {m['objs']} on {_lower_article(m['place'])}")
        sentence_end = re.search(r"[.;!?]|$", text[m.end() :])
        end = m.end() + (sentence_end.start() if sentence_end else 0)
        end = min(end, found[k + 1].start()) if k + 1 < len(found) else end
        out.append(_PLACE_OBJECT_PAIR.sub(_pair_put, text[m.end() : end]))
        pos = end
    return "".join(out) + text[pos:]


def _needs_put(m: re.Match[str]) -> str:
    """ "the bin needs X and Y" -> "put X and Y on the bin" when the bin is a receptacle and each listed
    thing ends in a name ("a chilled lettuce", "two glass bottles"); else as said."""
    place = find_mentions(m["place"])
    if not (_is_named(m["place"], whole=True) and set(place[0].entry.types) & RECEPTACLES):
        return m[0]
    for item in _LIST_SPLIT.split(m["objs"].strip()):
        found = find_mentions(item)
        if not found or found[-1].char_end != len(item) or found[-1].entry.generic:
            return m[0]
    return f"{m['sp']}put {m['objs']} on {_lower_article(m['place'])}"


def _pair_put(p: re.Match[str]) -> str:
    """ ", the blue plate the red apple" after a place-as-subject clause: "put the red apple on ..."."""
    if _is_named(p["place"], whole=True) and _is_named(p["obj"], whole=True):
        return f"{p['join']}put {p['obj']} on {_lower_article(p['place'])}"
    return p[0]


def _fronted(m: re.Match[str]) -> str:
    """ "on the pink plate put the green apple" -> "put the green apple on the pink plate"."""
    if not (_is_named(m["place"], whole=True) and _is_named(m["objs"])):
        return m[0]
    prep = "on" if m["prep"].lower() == "for" else m["prep"].lower()
    order = (m["order"] or m["order2"] or "").strip(" ,")
    return f"{m['lead']}{order + ' ' if order else ''}put {m['objs']} {prep} {_lower_article(m['place'])}"


def _loaded(m: re.Match[str]) -> str:
    """ "load the yellow plate with X and Y" -> "put X and Y on the yellow plate"."""
    if not (_is_named(m["place"], whole=True) and _is_named(m["objs"])):
        return m[0]
    return f"put {m['objs']} on {m['place']}"


def _record_put(m: re.Match[str]) -> str:
    """ "Blue plate: carrot." -> "put the carrot on blue plate.": the side that is a receptacle is the
    place, when exactly one side is (a mug holds things too: "Mug: sink." is left)."""
    if not (_is_named(m["a"], whole=True) and _is_named(m["b"], whole=True)):
        return m[0]
    holds = [not RECEPTACLES.isdisjoint(find_mentions(side)[0].entry.types) for side in (m["a"], m["b"])]
    if holds.count(True) != 1:
        return m[0]
    place, thing = (m["a"], m["b"]) if holds[0] else (m["b"], m["a"])
    lead = m[0][: len(m[0]) - len(m[0].lstrip())]
    return f"{lead}put {_with_article(thing)} on {_with_article(place)}"


def _with_article(phrase: str) -> str:
    return phrase if re.match(r"(?:the|a|an)\s", phrase, re.I) else f"the {phrase.lower()}"


def _lower_article(phrase: str) -> str:
    """ "The blue plate" moved inside a sentence: "the blue plate"."""
    return re.sub(r"^(The|A|An)\b", lambda a: a[0].lower(), phrase)


def _thrown(m: re.Match[str]) -> str:
    """ "the X on the counter is to be thrown away" -> "take the X on the counter and throw it out"."""
    return f"{m['lead']}take {m['np']} and throw it out" if _is_named(m["np"]) else m[0]


def _goes(text: str, m: re.Match[str]) -> str:
    """ " goes " where an object is named right before the goal's verb ("the tomato slice" too)."""
    before = find_mentions(text[: m.start()])
    named = before and re.fullmatch(r"(?:\s+slices?)?", text[before[-1].char_end : m.start()], re.I)
    return " goes " if named else m[0]


def _after_then_put(m: re.Match[str]) -> str:
    """ "only after that should X be placed on Y" -> "after that, put X on Y"."""
    return f"{m['rel']}, put {m['objs']} " if _is_named(m["objs"]) else m[0]


def _you_put(m: re.Match[str]) -> str:
    """ "before anything goes on Y" -> "before you put anything on Y"; "before X or Z goes on Y" waits for
    both, so it is "before you put X and Z on Y" ("after X or Z" is left: which one is not said)."""
    objs = m["objs"]
    if re.match(r"(?:the|a|an)\s", objs, re.I) and not _is_named(objs):
        return m[0]
    if _ALTERNATIVES.search(objs):
        if m["rel"].lower() not in {"before", "until"}:
            return m[0]
        objs = _ALTERNATIVES.sub(" and ", objs)
    return f"{m['rel']} you put {objs} {m['prep']} "
