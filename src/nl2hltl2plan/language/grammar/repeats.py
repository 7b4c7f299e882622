"""A sentence that asks for the task before it again, for another thing (issue 23): "Wash the mug and put
it on the counter. The cup too." is "... Wash the cup and put it on the counter." The fragment forms
(`REPEAT_FRAGMENT`): "The cup too.", "And the egg as well.", "Same for the bowl.", "Do the same with the
tomato.", "Also the pencil.".

The task before is repeated only where its sentence is one plain task: a task verb opening it (or "turn on"
with a lamp), one thing it acts on (singular, after a verb: "holding the book"), places after prepositions,
and otherwise only task verbs, "and", "it", "while", "back" and the words between a determiner and its
thing; a source ("from the shelf") is the first thing's and is not copied. The fragment says nothing but
its things and their describing words ("The white teapot too." is repeated, "The tomato in the microwave
too." stays). Said inside the sentence of its task with no order word ("X, and do the same with the Y"),
the copy is written in its place, in the same sentence, so the sentence's order word ("Then ...") covers
both; so are copies for a list ("... with a pillow and a clock") and a counted copy after a counted placing
("put two candles on the tank and do the same with two bars of soap"). "Do the same with the bowl, but put
that one in the cabinet" is the task before for the bowl with that place, and "the same for X and then Y"
two repeats, Y after X.
Any other fragment stays as written, and check 1 names it unless a task does the whole of the task before
for the thing it names (`unsupported_steps.repeats_for_another`).

>>> repeated_for_another("Wash the mug and put it on the counter. The cup too.")
'Wash the mug and put it on the counter. Wash the cup and put it on the counter.'
>>> repeated_for_another("Put the mug in the sink after the apple is in the fridge. The cup too.")
'Put the mug in the sink after the apple is in the fridge. The cup too.'
>>> repeated_for_another("Put the apple in the fridge. The tomato in the microwave too.")
'Put the apple in the fridge. The tomato in the microwave too.'
>>> repeated_for_another("Then turn on the lamp while holding the book, and do the same with the box.")
'Then turn on the lamp while holding the book, and turn on the lamp while holding the box.'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import DETERMINERS, categories
from nl2hltl2plan.language.grounding import SLICEABLE, Mention, find_mentions, tokens

_DET = r"(?:the|a|an|my|your|his|her|their|our|this|that|these|those)"
# a word of a noun phrase: no preposition, joiner or verb ("the tomato in the microwave too" says a place)
_W = r"(?!(?:in|into|on|onto|inside|to|at|under|near|by|from|with|and|then|too|also|as|is|are|goes)\b)[a-z]+"
_NP = rf"{_DET}\s+{_W}(?:\s+{_W}){{0,2}}"
_NPS = rf"{_NP}(?:\s*,?\s*(?:and\s+)?{_NP})*"
REPEAT_FRAGMENT = re.compile(
    r"^\s*(?:(?:and|also|plus)\s+)*"
    rf"(?:(?:please\s+)?(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s+{_NPS}"
    rf"|{_NPS}\s*,?\s+(?:too|as\s+well|also)"
    rf"|(?:and|also|plus)\s+{_NPS})"
    r"\s*(?:,?\s*(?:too|as\s+well|also|please))?\s*$",
    re.I,
)
_SENTENCE = re.compile(r"[^.;!?\n]+[.;!?\n]*")
# "Then do the same with the cup.", "After that, the cup too.": the repeat comes after the task before; the
# connective stays before the task written out (the order the words say)
_ORDER_LEAD = re.compile(
    r"^\s*(?:(?:and\s+)?then|after\s+that|afterwards|next|once\s+(?:that's|that\s+is)\s+done"
    r"|once\s+you(?:'ve|\s+have)\s+done\s+that)\s*,?\s+",
    re.I,
)
# "X, and then do the same with the cup": the repeat said inside the sentence of its task is a sentence
_SAME_INSIDE = re.compile(
    r"(?:,\s*(?:and\s+)?|\s+and\s+)(?P<conn>then|after\s+that|once\s+(?:that's|that\s+is)\s+done"
    r"|once\s+you(?:'ve|\s+have)\s+done\s+that)(?=\s*,?\s+(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s)",
    re.I,
)
# "put two candles on the tank, and do the same with two bars of soap": a counted thing for a counted one
_COUNT = r"(?:two|three|four)"
_COUNTED_TASK = re.compile(
    rf"^(?P<verb>[a-z]+)\s+(?:the\s+)?{_COUNT}\s+(?P<thing>[a-z]+(?:\s+[a-z]+){{0,3}}?)\s+"
    r"(?:from\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?\s+)?"  # where they are now ("from the bed", h238)
    r"(?P<place>(?:in|into|on|onto|inside|under|to)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,3})$",
    re.I,
)
# "X, and do the same with the cup" (no order word): the copy is written where the fragment is
_SAME_AND = re.compile(
    rf"(?P<join>,\s*and\s+|\s+and\s+)(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s+"
    rf"(?P<np>{_NPS}|{_COUNT}\s+{_W}(?:\s+{_W}){{0,3}})"
    r"(?=\s*(?:[,.;!?]|$))",
    re.I,
)
# "do the same with the bowl, but put that one in the cabinet", "... only put that in the tub": the task
# before for the bowl, with this place instead of its own
_SAME_ELSEWHERE = re.compile(
    rf"^(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s+(?P<np>{_NP})\s*,?\s*(?:but|only|except)\s+"
    r"(?:that\s+)?(?:(?:put|place|set|leave|move|drop|throw|toss|hang|lay|take)\s+(?:it|(?:that|this)(?:\s+[a-z]+)?)"
    r"|(?:it|(?:that|this)(?:\s+one)?)\s+goes)\s+"
    r"(?P<place>(?:in|into|on|onto|inside|under)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,3}?)"
    r"\s*(?:instead)?\s*$",
    re.I,
)
# the prepositions that open a destination (not "of", "by": "the back of the toilet", "by the light of")
_TO_PREPS = {"in", "into", "on", "onto", "inside", "to", "under", "at", "near"}
# the words before a place's determiner ("in the sink", "by the light of the lamp"); "look at" opens a thing
_PLACE_PREPS = {"in", "into", "on", "onto", "inside", "to", "at", "under", "by", "of", "near"}
# the words a plain one-task sentence may hold besides its thing and its place
_PLAIN = DETERMINERS | {"and", "it", "please", "then", "light", "while", "you", "back", "from", "up"}
_PLAIN |= _PLACE_PREPS
# a fragment sentence ("The cup too.") repeats a sentence of one thing and one place only (and a source, not
# copied), its words these:
# check 1 judges the text with the copy written out, and a copy of a longer sentence shares its verbs with
# the sentence, which would hide a reading that gives the cup another task (test_repeats_for_another.py)
_PLAIN_ONE = DETERMINERS | {"and", "it", "please", "in", "into", "on", "onto", "inside", "to", "then"}
# "look at the vase by the light of the lamp", "pick up the egg from the sink"
_PLAIN_ONE |= {"at", "under", "by", "light", "of", "up", "from"}
_FRAGMENT_WORDS = DETERMINERS | set("and also plus please do same thing for with to too as well".split())
_TASK_VERBS = frozenset(
    {"verb_any", "verb_clean_place", "verb_heat_place", "verb_cool_place", "verb_sliced"}
    | {"verb_examine_in_light"}
)
_OPENING = _TASK_VERBS | {"verb_switch"}  # "turn on the lamp while holding the book"
# "warm X in the microwave and toss it in Y", "chill X in the fridge ...": the appliance is passed on the way;
# not "wash X in the sink and put it on Y", whose fragment check 1 names (test_repeats_for_another.py)
_TREATING = frozenset({"verb_heat_place", "verb_cool_place"})
_APPLIANCES = frozenset({"Microwave", "Fridge"})
_SLICED_SAID = SLICEABLE - {"Egg"}  # a slice of bread, of a tomato; an egg is cracked, never "a slice of egg"


# "do the same for a book and then a cushion", "... with the statue, and then with a plate": two repeats, the
# second after the first
_SAME_THEN = re.compile(
    rf"(?P<head>\b(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s+{_NP})\s*,?\s+(?:and\s+)?then\s+"
    rf"(?:(?:for|with|to)\s+)?(?P<np>{_NP})"
    r"(?=\s*(?:[.;!?]|$))",
    re.I,
)


# "..., and so does the cup", "the same goes for the cup", "likewise the cup", "ditto for the cup": "do the
# same with the cup" (h216); "likewise X, and likewise Y" is one list ("do the same with X and Y")
_SAME_SAID = re.compile(
    rf"\b(?:so\s+(?:does|do)|(?:the\s+)?same\s+goes\s+for|likewise(?:\s+(?:for|with))?|ditto\s+(?:for|with)"
    rf"|repeat(?:\s+(?:it|that|this|the\s+same))?\s+(?:with|for))\s+(?={_DET}\s)",
    re.I,
)
# "Do the same with a pencil after that.": the order word said last opens the sentence ("After that do the
# same with a pencil."), as `_ORDER_LEAD` reads it (h237)
_ORDER_LAST = re.compile(
    r"(?P<lead>^|[.;!?]\s+)(?P<frag>(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s+[^.;!?,]+?)"
    r"\s*,?\s+(?P<conn>after\s+that|afterwards)(?=\s*(?:[.;!?]|$))",
    re.I,
)
# "do a potato slice the same way (but put it on the table)": "do the same with a potato slice" (h237)
_SAME_WAY = re.compile(rf"\bdo\s+(?P<np>{_NP})\s+(?:the\s+same\s+way|likewise|the\s+same)\b", re.I)
# after a placing said with "goes" ("the cup and the pot both go on the table, and so does the knife"):
# the things after it go there too ("..., and the knife goes on the table")
_GOES_SO = re.compile(
    r"\b(?P<verb>goes|go|belongs?)\s+(?P<place>(?:in|into|on|onto|inside|under)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)"
    r"\s*,?\s+and\s+(?:so\s+(?:does|do)|(?:the\s+)?same\s+goes\s+for|likewise)\s+"
    r"(?P<np>(?:the|a|an|two|three|four|\d+)\s+[^,.;!?]+?)(?=\s*(?:[,.;!?]|$))",
    re.I,
)
_LIKEWISE_AGAIN = re.compile(rf"(?<=\blikewise\s)(?P<np>{_NP})\s*,?\s+and\s+likewise\s+(?={_DET}\s)", re.I)
# "X, and the cup too" / "..., and a slice of potato as well" / "..., plus the cup" inside the sentence of a
# plain task: "do the same with" said at the end (h216); a place after the thing ("and the cup in the sink
# too") is no repeat, but where it is now is ("and the keys from the nightstand too": the source, h238)
_TOO_AND = re.compile(
    rf"(?:(?P<join>,\s*and\s+|\s+and\s+)(?P<np>{_NPS}|{_COUNT}\s+{_W}(?:\s+{_W}){{0,3}})"
    rf"(?:\s+(?:from|off)\s+{_NP})?\s*,?\s+(?:too|as\s+well)"
    rf"|(?P<plus>,\s*(?:and\s+)?plus\s+)(?P<np2>{_NPS}|{_COUNT}\s+{_W}(?:\s+{_W}){{0,3}}))(?=\s*(?:[,.;!?]|$))",
    re.I,
)
# "heat a mug and put it on the counter, and one more for the shelf" / "..., then another one on the shelf":
# the task before for a second thing of its type, at this place ("and heat another mug and put it on the
# shelf"); the task before one plain clause (`_ONE_TASK`)
_ONE_MORE = re.compile(
    r"(?P<join>,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+)(?:one\s+more|another(?:\s+one)?)\s+"
    r"(?P<prep>for|on|in|into|onto|inside|to)\s+(?P<place>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)(?=\s*(?:[,.;!?]|$))",
    re.I,
)
_ONE_TASK = re.compile(
    r"^(?P<verb>[a-z]+)\s+(?:the|a|an)\s+(?P<thing>[a-z]+(?:\s+[a-z]+)?)"
    r"(?P<put>\s+and\s+[a-z]+\s+it)?\s+(?P<prep>in|into|on|onto|inside|to)\s+(?P<at>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,2})$",
    re.I,
)


def repeated_for_another(text: str) -> str:
    """Each fragment sentence that repeats a plain one-task sentence for other things, written out."""
    text = _GOES_SO.sub(_goes_there_too, text)
    text = _LIKEWISE_AGAIN.sub(lambda m: f"{m['np']} and ", text)
    text = _SAME_SAID.sub("do the same with ", text)
    text = _SAME_WAY.sub(lambda m: f"do the same with {m['np']}", text)
    text = _SAME_THEN.sub(lambda m: f"{m['head']}. Then do the same with {m['np']}", text)
    out: list[str] = []
    task = ""  # the last sentence that is not a fragment
    # that sentence follows another task's after ";" ("heat an egg ...; heat a cup .... Then do the same
    # with the mug."): which task is repeated is not said, so the fragment stays as said (h246)
    shared = semicolon = False
    written = False  # the sentence split off by `_SAME_INSIDE` is kept only where its repeat is written out
    inline = _SAME_AND.sub(lambda m: _copy_inside(text, m), text)
    inline = _TOO_AND.sub(lambda m: _copy_inside(inline, m), inline)
    inline = _ONE_MORE.sub(lambda m: _one_more(inline, m), inline)
    written = inline != text
    for s in _SENTENCE.finditer(_SAME_INSIDE.sub(lambda m: ". " + m["conn"].capitalize(), inline)):
        body = s.group(0)
        core = body.rstrip(" .;!?\n")
        said = _ORDER_LEAD.match(core)
        fragment = core[said.end() :] if said else core
        if task and not shared and REPEAT_FRAGMENT.match(fragment):
            things = [m for m in find_mentions(fragment) if not m.entry.generic]
            copies = [c for c in (_with_thing(task, m, words=_phrase(fragment, m)) for m in things) if c]
            # after an order word, one thing only ("then the cup and the bowl": their own order unsaid)
            one = not said or len(things) == 1
            if things and len(copies) == len(things) and _only_things(fragment, things) and one:
                lead = core[: len(core) - len(core.lstrip())]
                copies = [c[:1].upper() + c[1:] for c in copies]  # the task's order word is not copied
                if said:  # "Then put the cup on the counter."
                    lead, copies = said.group(0), [c[:1].lower() + c[1:] for c in copies]
                out.append(lead + ". ".join(copies) + body[len(core) :])
                written = True
                continue
        elsewhere = _elsewhere(task, fragment) if task and not shared else None
        if elsewhere:  # "Then do the same with the bowl, but put that one in the cabinet."
            lead = said.group(0) if said else core[: len(core) - len(core.lstrip())]
            said_as = elsewhere if said else elsewhere[:1].upper() + elsewhere[1:]
            out.append(lead + said_as + body[len(core) :])
            written = True
            continue
        if not REPEAT_FRAGMENT.match(fragment):
            # its order word stays with it ("After that, look at X. Then the Y too."), its question not
            shared = bool(task) and semicolon
            task = _ASKED.sub("", fragment.strip())
        semicolon = body.rstrip().endswith(";")
        out.append(body)
    return "".join(out) if written else text


def order_word_first(text: str) -> str:
    """ "Do the same with a pencil after that." -> "After that do the same with a pencil." (before the lamp
    phrases and the repeats read it)."""
    def first(m: re.Match[str]) -> str:
        return f"{m['lead']}{m['conn'].capitalize()} {m['frag'][:1].lower()}{m['frag'][1:]}"

    return _ORDER_LAST.sub(first, text)


def _goes_there_too(m: re.Match[str]) -> str:
    """ "go on the table, and so does the knife" -> "go on the table, and the knife goes on the table"."""
    return f"{m[0][: m.end('place') - m.start()]}, and {m['np']} {_go(m['np'])} {m['place']}"


def _go(things: str) -> str:
    """ "goes" after one thing, "go" after a list or a count ("the 2 pump bottles and 2 bars of soap")."""
    return "go" if re.search(r"\band\b|^(?:two|three|four|\d+)\b|s$", things.strip(), re.I) else "goes"


# a request's opening question, which the task copied for another thing does not repeat
_ASKED = re.compile(r"^(?:(?:can|could|would|will)\s+(?:you|u)\s+)?(?:please\s+)?(?=[a-z])", re.I)


def _one_more(text: str, m: re.Match[str]) -> str:
    """ ", and one more for the shelf" after "heat a mug and put it on the counter": ", and heat another mug
    and put it on the shelf", where the clause before is one plain task of one thing; else as said."""
    start = max(text.rfind(c, 0, m.start()) for c in ".;!?\n") + 1
    clause = text[start : m.start()].strip()
    said = _ORDER_LEAD.match(clause)
    task = _ONE_TASK.match(clause[said.end() :] if said else clause)
    if not task or not categories(task["verb"].lower()) & _TASK_VERBS:
        return m[0]
    named = [x for x in find_mentions(task["thing"]) if not x.entry.generic]
    placing = "verb_any" in categories(task["verb"].lower())  # "put a mug on", not "heat a mug and put it"
    if len(named) != 1 or named[0].plural or (not task["put"]) != placing:
        return m[0]
    prep = task["prep"] if m["prep"].lower() == "for" else m["prep"]
    place = f"{prep} {m['place']}"
    verb = task["verb"].lower()
    again = f"{verb} another {task['thing']}{task['put'] or ''} {place}"
    return f"{m['join']}{again}"


def _copy_inside(text: str, m: re.Match[str]) -> str:
    """ "Then turn on the lamp while holding the book, and do the same with the box": the clause before
    (its order word left out; or its last comma-separated part) written out for the box, where it is one
    plain task; the words as they were otherwise."""
    np, join = m["np"] or m.groupdict().get("np2") or "", m["join"] or ", and "
    things = [x for x in find_mentions(np) if not x.entry.generic]
    start = max(text.rfind(c, 0, m.start()) for c in ".;!?\n") + 1
    clause = _ASKED.sub("", text[start : m.start()].strip())  # "can you hold X ..., and do the same with Y"
    said = _ORDER_LEAD.match(clause)
    last = re.sub(r"^(?:and|then)\s+", "", clause.split(",")[-1].strip())
    tasks = [clause[said.end() :] if said else clause, last]
    for task in tasks:
        copies = [c for c in (_with_thing(task.strip(), x, True, words=_phrase(np, x)) for x in things) if c]
        if copies and len(copies) == len(things):  # "..., and do the same with a pillow and a clock"
            return join + ", and ".join(c[:1].lower() + c[1:] for c in copies)
        if len(things) != 1:
            continue
        counted = _COUNTED_TASK.match(task.strip())
        if counted and _one_thing(counted["thing"]):  # ("move two books to the dresser, and the keys too")
            return f"{join}{counted['verb'].lower()} {np} {counted['place']}"
        if not re.match(_COUNT, np, re.I):
            continue
        # "move the clock to the dresser, and two pencils too": a counted placing of its own (h216)
        one = _ONE_TASK.match(task.strip())
        if one and not one["put"] and "verb_any" in categories(one["verb"].lower()):
            return f"{join}{one['verb'].lower()} {np} {one['prep']} {one['at']}"
    return m[0]


def _one_thing(words: str) -> bool:
    """Do the words name one thing of the scene's kinds and nothing else ("bars of soap")?"""
    named = [x for x in find_mentions(words) if not x.entry.generic]
    return len(named) == 1 and named[0].surface.lower() == words.lower().strip()


def _elsewhere(task: str, fragment: str) -> str | None:
    """ "do the same with the bowl, but put that one in the cabinet" after a plain one-task sentence: that
    sentence for the bowl, its last place replaced by this one (lower case); None where it is no such pair."""
    m = _SAME_ELSEWHERE.match(fragment.strip())
    things = [x for x in find_mentions(m["np"]) if not x.entry.generic] if m else []
    words = _phrase(m["np"], things[0]) if m and len(things) == 1 else ""  # "a slice of lettuce" whole
    copy = _with_thing(task, things[0], True, True, words) if m and len(things) == 1 else None
    if not copy or not m:
        return None
    toks = tokens(copy)
    places = [x for x in find_mentions(copy) if not x.entry.generic and _role(x, toks) == "place"]
    preps = [i for i in range(_det_at(places[-1], toks)) if toks[i][0] in _TO_PREPS] if places else []
    if not preps:
        return None
    copy = copy[: toks[preps[-1]][1]] + m["place"] + copy[places[-1].char_end :]
    return copy[:1].lower() + copy[1:]


def _only_things(fragment: str, things: list[Mention]) -> bool:
    """The fragment says nothing but its things ("the tomato in the microwave too" says a place)."""
    toks = tokens(fragment)
    # a thing's describing words, between its determiner and it ("the white teapot"), are its own
    in_thing = {i for m in things for i in range(_own_words_start(m, toks), m.end)}
    return all(i in in_thing or w in _FRAGMENT_WORDS for i, (w, _, _) in enumerate(tokens(fragment)))


def _own_words_start(m: Mention, toks: list[tuple[str, int, int]]) -> int:
    """Where a thing's own words start: after its determiner ("the white teapot"), or at the thing."""
    at = _det_at(m, toks)
    return at + 1 if at >= 0 else m.start


def _phrase(text: str, m: Mention) -> str:
    """The words of `m`'s noun phrase after its determiner ("slice of potato" of "a slice of potato")."""
    toks, i = tokens(text), m.start
    while i > 0 and _slice_word(toks, i - 1):
        i -= 1
    return text[toks[i][1] : m.char_end]


def _sliced(words: str) -> bool:
    return any("verb_sliced" in categories(w) for w in re.findall(r"[a-z]+", words.lower()))


def _with_thing(
    sentence: str, thing: Mention, inside: bool = False, container: bool = False, words: str = ""
) -> str | None:
    """`sentence` with its thing replaced by `thing` (by `words`, its words after the determiner: "slice of
    potato") and its source left out, where it is a plain one-task sentence (None else); for a fragment
    sentence (not `inside`), one of one thing and one place. With `container`, a place named again as a
    thing ("put a vase in a box and set the box on the table") is the container, still a place."""
    words = words or thing.surface
    if thing.plural:
        return None
    toks = tokens(sentence)
    named = [m for m in find_mentions(sentence) if not m.entry.generic and not _light_of(m, toks)]
    if named and named[0].start == 0 and categories(toks[0][0]) & _OPENING:
        named = named[1:]  # "Microwave an egg ...": the verb, not the appliance
    roles = [_role(m, toks) for m in named]
    if container:
        held = [m.entry.types for m, role in zip(named, roles, strict=True) if role == "place"]
        roles = [
            "place" if role == "thing" and k and m.entry.types in held else role
            for k, (m, role) in enumerate(zip(named, roles, strict=True))
        ]
    firsts = [m for m, role in zip(named, roles, strict=True) if role == "thing"]
    if None in roles or len(firsts) != 1 or "place" not in roles or len(toks) < 3 or firsts[0].plural:
        return None
    own = sentence[toks[_det_at(firsts[0], toks) + 1][1] : firsts[0].char_end]
    if firsts[0].entry.types[0] == thing.entry.types[0] and _sliced(own) == _sliced(words):
        return None  # "the mug ... Same for the coffee mug": one type, the atoms cannot tell them apart
    if not categories(toks[0][0]) & _OPENING:
        return None
    said = {i for m in named for i in range(_det_at(m, toks) + 1, m.end)}  # a thing and the words before it
    plain, opening = (_PLAIN, _OPENING) if inside else (_PLAIN_ONE, _TASK_VERBS)
    # no word between a determiner and its thing but a slice's ("a slice of tomato")
    direct = all(all(_slice_word(toks, j) for j in range(_det_at(m, toks) + 1, m.start)) for m in named)
    kept = [m for m, role in zip(named, roles, strict=True) if role != "source"]  # "from the sink": left out
    if categories(toks[0][0]) & _TREATING and len(kept) == 3:
        kept = [m for m in kept if not (m is not kept[-1] and set(m.entry.types) & _APPLIANCES)]
    if not inside and (len(kept) != 2 or kept[0] is not firsts[0] or not direct):
        return None
    for i, (word, _, _) in enumerate(toks):
        if i not in said and word not in plain and not categories(word) & opening:
            return None
    # the thing (with the words between its determiner and it) replaced, a source ("from the shelf") left out
    # "a slice of bread ... repeat with a pot": a pot is no slice, the slice words go with the bread (h237)
    whole = _sliced(words) or not set(thing.entry.types) & _SLICED_SAID
    spans = [(toks[_after_det(m, toks, whole)][1], m.char_end, words) for m in firsts]
    sources = [m for m, role in zip(named, roles, strict=True) if role == "source"]
    spans += [(toks[_det_at(m, toks) - 1][1] - 1, m.char_end, "") for m in sources]
    for start, end, new in sorted(spans, reverse=True):
        sentence = sentence[:start] + new + sentence[end:]
    article = "an" if words[:1].lower() in "aeiou" else "a"  # "an egg" copied for "a tomato"
    said_before = rf"\b[Aa]n?(?=\s+{re.escape(words)}\b)"
    return re.sub(said_before, lambda m: m[0][0] + article[1:], sentence, count=1)


def _after_det(m: Mention, toks: list[tuple[str, int, int]], sliced: bool) -> int:
    """Where the words replaced for a copy start: after the determiner, and after a slice's words unless the
    copy says its own ("a slice of tomato ... Same for an apple": a slice of apple)."""
    at = _det_at(m, toks) + 1
    while not sliced and at < m.start and _slice_word(toks, at):
        at += 1
    return at


def _det_at(m: Mention, toks: list[tuple[str, int, int]]) -> int:
    """The index of the determiner that opens `m`'s noun phrase (the words between are its own); -1: none."""
    for i in range(m.start - 1, 0, -1):
        if _slice_word(toks, i):  # "a slice of tomato", "a sliced apple": the thing's own words
            continue
        if toks[i][0] in DETERMINERS:
            return i
        if toks[i][0] in _PLAIN or categories(toks[i][0]):
            return -1
    return -1


def _slice_word(toks: list[tuple[str, int, int]], i: int) -> bool:
    """Is the i-th word a slice word of a thing ("slice", "sliced") or the "of" after one ("slice of")?"""
    if toks[i][0] == "of":
        return i > 0 and "verb_sliced" in categories(toks[i - 1][0])
    of_next = i + 1 < len(toks) and toks[i + 1][0] == "of"
    return "verb_sliced" in categories(toks[i][0]) and (toks[i][0].endswith("ed") or of_next)


def _role(m: Mention, toks: list[tuple[str, int, int]]) -> str | None:
    """ "thing" (after a verb: "wash the mug", "holding the book", "look at the vase"), "place" (after a
    preposition: "on the shelf", "of the lamp"), "source" ("from the shelf") or None (no determiner)."""
    at = _det_at(m, toks)
    if at < 1:
        return None
    before = toks[at - 1][0]
    if before == "from":
        return "source"
    if before in ("at", "up") and at > 1 and categories(toks[at - 2][0]) & _OPENING:
        return "thing"  # "look at the vase", "pick up the book"
    if before in _PLACE_PREPS:
        return "place"
    return "thing" if categories(before) & _OPENING else None


def _light_of(m: Mention, toks: list[tuple[str, int, int]]) -> bool:
    """"the light of the lamp": the lamp's light, no thing of its own."""
    return m.surface.lower() == "light" and m.end < len(toks) and toks[m.end][0] == "of"
