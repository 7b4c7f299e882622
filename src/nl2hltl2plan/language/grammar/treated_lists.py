"""A treatment said once for several things, said as an outcome, or said after its thing (issue 28,
paper_h189 and paper_h204dev.txt), rewritten onto the imperatives the grammar reads. Each rule rewrites
only where every thing is a name the scene's lexicon knows (`find_mentions`) and the verb or participle
is one of the grammar's treatments (`word_tables`: clean, heat, cool), so anything else is left as it is:

- a treatment heading a list: "Chill these in the fridge and then put them away: a potato slice in the
  bin, an egg in the microwave" is "chill a potato slice and put it in the bin, chill an egg and put it in
  the microwave" (a list says no order); a place said in the heading ("... and set them on the table: a
  potato slice and a plate") is every item's place;
- a treatment and a placement said as an outcome: "make sure the pan gets washed and left on the counter"
  is "wash the pan and put it on the counter", and so is each "and (that) X gets washed and left on Y" of a
  text that says "make sure"; a closing "once both are done" of such a clause is said before it;
- an item with participles: "a cup heated in the microwave and left on the shelf", "the pot chilled and
  put in a cabinet" is "a heated cup on the shelf", "the chilled pot in a cabinet" (the verbless items of
  `verbless_items.py`);
- a name and its place after a treatment and a placement of a thing: "rinse out a bowl and leave it on the
  counter and a green glass in the cupboard" is "..., and rinse a green glass and leave it in the cupboard";
- a thing named before its steps: "Next, a slice of potato: heat it up and drop it in the sink" is "Next,
  heat up a slice of potato and drop it in the sink";
- one verb over a list, each thing's place after it: "Heat an egg and a plate. The egg goes on the side
  table, the plate on the counter." and "Wash a knife and a mug, one at a time, then put the knife in a
  drawer and the mug on the coffee machine" are "heat an egg and put it on the side table, heat a plate and
  put it on the counter" (no order: a list says none); every thing of the list takes one place, and each
  place names one thing of it by its words ("the slice" of "a potato slice"), else the text stays; "one at
  a time" after such a list ("..., one at a time, and put each of them on the counter") says nothing more;
  "microwave a slice, then drop the slice in the sink" drops that slice ("then drop it");
- the same where each thing has a treatment of its own (h247): "Chill a mug and wash a plate - the mug goes
  on the coffee maker, the plate in the microwave" (after a stop, colon, semicolon, question mark, dash or
  "then"; "the former" / "the latter" of two things; "plate on the shelf" without its article), or one place
  for all ("..., and put both on the counter"); "Heat two mugs: one goes on A, the other in B" is "heat a mug
  and put it on A, heat another mug and put it in B".
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.grammar.word_tables import VERB_PAST, VERBS
from nl2hltl2plan.language.grounding import find_mentions

_STATE = {"clean": "washed", "heat": "heated", "cool": "chilled"}  # the state word a treatment leaves
# a treatment verb's particle ("heat up", "wipe down"; `treatments_said` too)
PARTICLE = r"(?:\s+(?:up|down|off|out))?"
_APPLIANCE = r"(?:\s+(?:in|inside)\s+(?:the|a)\s+(?:microwave|fridge|refrigerator|sink|oven))?"
_PREP = r"(?P<prep>in|into|on|onto|inside)"
_PLACED = r"(?:left|put|set|placed|dropped|stored|kept|returned)(?:\s+back)?"
_NP = r"(?:a|an|the|another|one|this|that|my|your)\s+[a-z]+(?:\s+[a-z]+){0,3}?"
# an item's name: no word of a list or a place inside it ("the sink and a cup heated" is two phrases)
_WORD = r"(?!(?:and|or|then|in|into|on|onto|inside|with)\b)[a-z]+"
_ITEM_NP = rf"(?:a|an|the|another|one|this|that|my|your)\s+{_WORD}(?:\s+{_WORD}){{0,3}}?"
_THESE = r"(?:these|them|all\s+of\s+these|each\s+of\s+these|all\s+these|the\s+following)"
_AWAY = r"(?:away|back|where\s+I\s+say|where\s+they\s+go|where\s+I\s+tell\s+you)"
# a gap between items; one that says "then" keeps its order ("the egg in the fridge, then the apple in the
# bin": read before as a chilled egg and an apple only put, at exit 0, h205)
_ITEM_GAP = re.compile(
    r"\s*,\s*(?:and\s+)?(?P<then>then\s+)?|\s+and\s+(?P<and_then>then\s+)?(?=(?:a|an|the|another|one)\s)|"
    r"\s+(?P<bare_then>then)\s+(?=(?:a|an|the|another|one)\s)",
    re.I,
)
_ITEM_PLACE = re.compile(rf"^(?P<np>{_NP})\s+{_PREP}\s+(?P<place>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)$", re.I)
_SLICE = re.compile(r"(?:\s+slices?)?\s*", re.I)
# "wash the pan and put it on the counter once both are done": the reference said first, where the grammar
# reads it ("once both are done, wash the pan ..."); only in a text where an outcome was rewritten
_ONCE_DONE = re.compile(
    r"(?P<lead>^|[.;!?]\s+|,\s+and\s+)(?P<clause>[a-z][^.;!?,]*?)\s+(?P<once>once\s+(?:that's|that\s+is|both\s+are|"
    r"those\s+are|they're|they\s+are|it's|it\s+is)\s+done)(?=\s*(?:[.;!?]|$))",
    re.I,
)
_TOO = re.compile(r"\s+(?:too|as\s+well|also)\s*$", re.I)
# between the items of a list each said with its own treatment ("wash a tomato and heat a potato")
_EACH_GAP = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+", re.I)
# where a list whose places are said after it may begin: a sentence, a request's "please" / "could you", or
# after a comma ("After you've done that, heat a tomato slice and an apple - the slice goes in ...")
_AFTER_LEAD = (
    r"(?P<lead>(?:^|(?<=[.;!?])\s+|(?<=,)\s+)"
    r"(?:(?:then|next|now|also|first|please|pls|(?:could|can|would)\s+you(?:\s+please)?)\s*,?\s+)?)"
)
# the end of the list and the places said after it: a stop, colon, semicolon, question mark, dash or "then"
_PLACES_AFTER = (
    r"(?:[.:;?]|\s+-+\s+|,?\s+(?:and\s+)?then\b|,)\s*(?:then\s*,?\s+)?(?:and\s+(?=put|place|set|leave))?"
    r"(?:(?:put|place|set|leave)\s+)?(?P<places>[^.;!?]+)"
)


def _treatments(table: dict[str, tuple[str, str]]) -> str:
    words = sorted((w for w, (cls, _) in table.items() if cls in _STATE), key=len, reverse=True)
    return "|".join(re.escape(w) for w in words)


@lru_cache(maxsize=1)
def _patterns() -> tuple[re.Pattern[str], ...]:
    verbs, past = _treatments(VERBS), _treatments(VERB_PAST)
    heading = re.compile(
        rf"(?P<lead>(?:^|(?<=[.;!?])\s+)(?:(?:after\s+that|then|next|now|also|first)\s*,?\s+)?)"
        rf"(?P<verb>{verbs}){PARTICLE}\s+{_THESE}{PARTICLE}{_APPLIANCE}\s*,?\s+"
        rf"(?:and\s+|then\s+|and\s+then\s+|before\s+)(?:put|putting|set|setting|place|placing)\s+them\s+"
        rf"(?:{_AWAY}|{_PREP}\s+(?P<place>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?))\s*:\s*(?P<items>[^.;!?]+)",
        re.I,
    )
    outcome = re.compile(
        rf"(?P<lead>\b(?:make\s+sure|ensure)(?:\s+that)?\s+|,?\s+and\s+(?:that\s+)?)(?P<np>{_NP}"
        rf"(?:\s+and\s+{_NP})?)\s+(?P<gets>gets|get|is|are)\s+(?P<part>{past}){PARTICLE}{_APPLIANCE}\s+and\s+"
        rf"(?:{_PLACED}|ends?\s+up|goes|go)\s+{_PREP}\s+",
        re.I,
    )
    item = re.compile(
        rf"\b(?P<np>{_ITEM_NP})\s+(?P<part>{past}){PARTICLE}{_APPLIANCE}\s+and\s+(?:then\s+)?{_PLACED}\s+{_PREP}\s+",
        re.I,
    )
    named_first = re.compile(
        rf"(?P<lead>(?:^|(?<=[.;!?])\s+)(?:(?:next|now|then|first|finally|after\s+that)\s*,?\s+)?)"
        rf"(?P<np>(?:a|an|the)\s+[a-z]+(?:\s+[a-z]+){{0,3}}?)\s*:\s*(?P<verb>{verbs}|put|place|set)"
        rf"\s+it(?P<particle>{PARTICLE})\b",
        re.I,
    )
    shared = re.compile(
        rf"\b(?P<steps>(?P<verb>{verbs}){PARTICLE}\s+{_NP}\s+and\s+(?P<put>put|leave|set|place|drop)\s+it\s+"
        rf"(?:in|into|on|onto|inside)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)\s+and\s+(?P<np>{_NP})\s+{_PREP}\s+"
        rf"(?P<place>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)(?=\s*(?:[.;!?]|$))",
        re.I,
    )
    placed_after = re.compile(
        rf"{_AFTER_LEAD}(?P<verb>{verbs}|put|move){PARTICLE}(?:\s+away)?\s+"
        rf"(?P<items>{_ITEM_NP}(?:\s*,\s*{_ITEM_NP})*\s*,?\s+and\s+{_ITEM_NP})(?:\s+away)?{_APPLIANCE}(?:\s*,?\s*one\s+at\s+a\s+time)?\s*{_PLACES_AFTER}",
        re.I,
    )
    # "Heat a tomato, an egg and a potato in the microwave, one at a time, and put each of them on the
    # counter": each thing on its own says no order and no other task (h239)
    one_at_a_time = re.compile(
        rf"(?P<list>\b(?:{verbs}){PARTICLE}\s+{_ITEM_NP}(?:\s*,\s*{_ITEM_NP})*\s*,?\s+and\s+{_ITEM_NP}"
        rf"{_APPLIANCE})\s*,\s*one\s+at\s+a\s+time\s*(?=,)",
        re.I,
    )
    # "Cut a potato and microwave a slice, then drop the slice in the sink": the slice just treated is "it"
    slice_again = re.compile(
        rf"(?P<head>\b(?:{verbs}){PARTICLE}\s+(?:a|one)\s+slice{_APPLIANCE}\s*,?\s+(?:and\s+)?(?:then\s+)?"
        r"(?:put|drop|place|set|leave|throw|toss|move)\s+)the\s+slice\b",
        re.I,
    )
    return heading, outcome, item, named_first, shared, placed_after, one_at_a_time, slice_again


@lru_cache(maxsize=1)
def _apart_patterns() -> tuple[re.Pattern[str], re.Pattern[str]]:
    """The lists of things each given its place after them (h247)."""
    verbs = _treatments(VERBS)
    # "Chill a mug and wash a plate: the mug goes on ..., the plate in ...", "..., and put both on the
    # counter": each thing with a treatment of its own, its place said after the list (h247)
    each = rf"(?:{verbs}){PARTICLE}\s+{_ITEM_NP}"
    each_placed_after = re.compile(
        rf"{_AFTER_LEAD}(?P<items>{each}(?:(?:\s*,\s*(?:and\s+)?|\s+and\s+){each})+){_APPLIANCE}\s*"
        rf"{_PLACES_AFTER}",
        re.I,
    )
    # "Heat two mugs: one goes on the coffee maker, the other in a cabinet": each treated, each its place
    at = r"(?:in|into|on|onto|inside|under)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,3}?"
    two_apart = re.compile(
        rf"{_AFTER_LEAD}(?P<verb>{verbs}){PARTICLE}\s+(?:two|2)\s+(?P<things>[a-z]+(?:\s+[a-z]+){{0,3}}?)"
        rf"{_APPLIANCE}\s*(?:[.:;]|\s+-+\s+|,)\s*(?:the\s+)?one\s+(?:(?:goes|go)\s+)?(?P<p1>{at})\s*[,;]?\s+"
        r"(?:and\s+)?the\s+other(?:\s+(?!(?:in|into|on|onto|inside|under)\b)[a-z]+){0,2}\s+(?:(?:goes|go)\s+)?"
        rf"(?P<p2>{at})(?=\s*(?:[.;!?]|$))",
        re.I,
    )
    return each_placed_after, two_apart


def treated_lists(text: str) -> str:
    """The text with the treatments above rewritten (see the module docstring)."""
    heading, outcome, item, named_first, shared, placed_after, one_at_a_time, slice_again = _patterns()
    each_placed_after, two_apart = _apart_patterns()
    text = slice_again.sub(r"\g<head>it", text)
    text = _CUT_FIRST.sub(_cut_first, text)
    text = placed_after.sub(_placed_after, text)
    text = each_placed_after.sub(_placed_after, text)
    text = two_apart.sub(_two_apart, text)
    text = one_at_a_time.sub(lambda m: m["list"] if _names_things(m["list"], most=9) else m[0], text)
    text = shared.sub(_steps_shared, text)
    text = heading.sub(_distributed, text)
    if re.search(r"\b(?:make\s+sure|ensure)\b", text, re.I) and (said := outcome.sub(_outcome, text)) != text:
        text = _ONCE_DONE.sub(_once_first, said)
    text = item.sub(_item, text)
    return named_first.sub(_named_first, text)


# "Slice the bread and the lettuce. I want a cold slice of the bread on the table and ...": a sentence that
# only slices things whose slices the later text names ("a slice of the bread", "a lettuce slice"), each of
# them a task that takes a slice and so includes the slicing (ANNOTATION_GUIDE: `sliced`); said as its own
# task it would slice a second time
_CUT_FIRST = re.compile(
    r"(?P<lead>^|(?<=[.;!?])\s+)(?:first\s*,?\s+)?(?:slice|cut)(?:\s+up)?\s+(?P<things>[^.;!?,]+?)\s*[.;!]\s*(?=\S)",
    re.I,
)


def _cut_first(m: re.Match[str]) -> str:
    """The slicing sentence dropped where each thing it slices is named again as a slice after it."""
    parts = [p.strip() for p in _ITEM_GAP.sub("\0", m["things"]).split("\0")]
    rest = m.string[m.end() :]
    if not parts or not all(_names_things(p) for p in parts):
        return m[0]
    for part in parts:
        name = re.escape(find_mentions(part)[-1].surface)
        said = rf"\b(?:slices?|pieces?)\s+of\s+(?:the\s+)?{name}\b|\b{name}\s+(?:slices?|pieces?)\b"
        if not re.search(said, rest, re.I):
            return m[0]
    return m["lead"]


def _names_things(phrase: str, most: int = 1) -> bool:
    """Does the phrase end on a name the lexicon knows ("an apple slice": a slice of it), with at most `most`
    names in it?"""
    found = find_mentions(phrase)
    return 0 < len(found) <= most and _SLICE.fullmatch(phrase[found[-1].char_end :]) is not None


def _distributed(m: re.Match[str]) -> str:
    """The heading's treatment and placement written for each item of its list; the text as it was where
    an item is not a name with its place (or a bare name, where the heading said the place)."""
    verb, shared = m["verb"].lower(), m["place"]
    items = _TOO.sub("", m["items"].strip())
    thens = [any(g.groups()) for g in _ITEM_GAP.finditer(items)]
    said = []
    for part in _ITEM_GAP.sub("\0", items).split("\0"):
        found = _ITEM_PLACE.match(part.strip())
        if found and not shared and _names_things(found["np"]) and _names_things(found["place"]):
            said.append(f"{verb} {found['np']} and put it {found['prep'].lower()} {found['place']}")
        elif shared and not found and _names_things(part.strip()):
            said.append(f"{verb} {part.strip()} and put it {m['prep'].lower()} {shared}")
        else:
            return m[0]
    if len(said) < 2:
        return m[0]
    if any(thens):  # "A, then B": each step after its "then", the others with a comma (no order)
        steps = zip(thens, said[1:], strict=True)
        joined = said[0] + "".join((", then " if t else ", ") + x for t, x in steps)
        return m["lead"] + (joined if m["lead"].strip() else _capital(joined))
    lead = m["lead"]
    return lead + (", ".join(said[:-1]) + " and " + said[-1] if lead.strip() else _capital(", ".join(said)))


def _capital(text: str) -> str:
    return text[:1].upper() + text[1:]


def _steps_shared(m: re.Match[str]) -> str:
    """ "rinse a bowl and leave it on the counter and a glass in the cupboard": the glass is rinsed and left
    too."""
    if not (_names_things(m["np"]) and _names_things(m["place"])):
        return m[0]
    return f"{m['steps']}, and {m['verb']} {m['np']} and {m['put']} it {m['prep'].lower()} {m['place']}"


def _outcome(m: re.Match[str]) -> str:
    """ "make sure the pan gets washed and left on the" -> "wash the pan and put it on the"."""
    verb = VERB_PAST[m["part"].lower()][1]
    if not _names_things(m["np"], most=2):
        return m[0]
    it = "them" if m["gets"].lower() in ("get", "are") else "it"
    lead = ", and " if m["lead"].lstrip().startswith((",", "and")) else ""
    return f"{lead}{verb} {m['np']} and put {it} {m['prep'].lower()} "


def _once_first(m: re.Match[str]) -> str:
    once = m["once"] if m["lead"].strip(" ,").lower() == "and" else _capital(m["once"].lower())
    return f"{m['lead']}{once}, {m['clause'][:1].lower()}{m['clause'][1:]}"


def _item(m: re.Match[str]) -> str:
    """ "a cup heated in the microwave and left on the" -> "a heated cup on the"."""
    det, _, noun = m["np"].partition(" ")
    if not _names_things(m["np"]):
        return m[0]
    return f"{det} {_STATE[VERB_PAST[m['part'].lower()][0]]} {noun} {m['prep'].lower()} "


def _named_first(m: re.Match[str]) -> str:
    """ "Next, a slice of potato: heat it up" -> "Next, heat up a slice of potato"."""
    if not _names_things(m["np"]):
        return m[0]
    verb = m["verb"] if m["lead"].strip() else _capital(m["verb"].lower())
    return f"{m['lead']}{verb}{m['particle']} {m['np']}"


_PREP_AT = r"(?P<prep>in|into|on|onto|inside|under)"
_PLACE_NP = r"(?P<place>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,6})"
# a thing and its place; the article may be left out ("plate on the shelf, mug on the coffee maker"), but a
# pronoun or "both" names no one thing of the list
_PLACE_ITEM = re.compile(
    r"^(?P<np>(?!(?:both|them|it|all|each|one|these|those)\b)(?:(?:the|a|an)\s+)?[a-z]+(?:\s+[a-z]+){0,3}?)\s+"
    rf"(?:(?:goes|go|belongs?)\s+(?:back\s+)?)?{_PREP_AT}\s+{_PLACE_NP}$",
    re.I,
)
# one place for every thing of a list each treated on its own ("..., and put both on the counter", "leave
# them both on the side table"; h231's "put both slices on the white table")
_ALL_THERE = re.compile(
    rf"^(?:both(?:\s+of\s+them|\s+[a-z]+s)?|them(?:\s+both)?)\s+{_PREP_AT}\s+{_PLACE_NP}$",
    re.I,
)
# a place named by a landmark beside it ("the counter by the coffee maker") names two things
_LANDMARK = re.compile(r"\b(?:by|near|beside|next\s+to|left\s+of|right\s+of|under|above)\s+(?:the|a)\b", re.I)
_PLACE_GAP = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+(?=(?:the|a|an)\s)", re.I)
_NOT_NAMING = frozenset({"the", "a", "an", "of", "piece", "slice"})
# "Chill a plate and a potato, then put the former in the cabinet and the latter on the table"
_FORMER_LATTER = {"the former": 0, "the latter": 1}


def _a_place(place: str) -> bool:
    return _names_things(place, most=2 if _LANDMARK.search(place) else 1)


def _placed_after(m: re.Match[str]) -> str:
    """ "Heat an egg and a plate. The egg goes on the table, the plate on the counter" -> "heat an egg and
    put it on the table, heat a plate and put it on the counter"; the same where each thing has a treatment
    of its own ("Chill a mug and wash a plate: ...", or one place for both: "..., and put both on the
    counter"); the text as it was unless each thing has exactly one place and each place one thing."""
    said = _said_items(m)
    if said is None or len(said) < 2 or not all(_names_things(i) for _, i in said):
        return m[0]
    places = _TOO.sub("", m["places"].strip())
    shared = _ALL_THERE.match(places) if "verb" not in m.groupdict() else None
    if shared is not None and _a_place(shared["place"]):
        there = f"{shared['prep'].lower()} {shared['place']}"
        where: dict[int, str] | None = dict.fromkeys(range(len(said)), there)
    else:
        where = _places_of(places, [i for _, i in said])
    if where is None:
        return m[0]
    steps = [f"put {i} {where[k]}" if v in {"put", "move"} else f"{v} {i} and put it {where[k]}"
             for k, (v, i) in enumerate(said)]
    joined = ", ".join(steps)  # as `_distributed` writes a list: no order
    after_comma = m.string[: m.start()].rstrip().endswith(",")
    return m["lead"] + (joined if after_comma or m["lead"].strip() else _capital(joined))


def _said_items(m: re.Match[str]) -> list[tuple[str, str]] | None:
    """Each thing of the list with its treatment verb: the list's one verb, or each item's own."""
    if "verb" in m.groupdict():
        verb = m["verb"].lower()
        return [(verb, i.strip()) for i in _ITEM_GAP.sub("\0", m["items"]).split("\0")]
    out = []
    for part in _EACH_GAP.split(m["items"]):
        said = re.match(rf"^(?P<v>[a-z]+){PARTICLE}\s+(?P<np>.+)$", part.strip(), re.I)
        if said is None or _base_verb(said["v"]) is None:
            return None
        out.append((said["v"].lower(), said["np"]))
    return out


def _places_of(places: str, items: list[str]) -> dict[int, str] | None:
    """Each item's place, by the list of "the X (goes) in P" said after it; None unless each item has one."""
    where: dict[int, str] = {}
    waiting: list[str] = []  # "the plate and the pan go on the counter": both take the place
    for part in _PLACE_GAP.sub("\0", places).split("\0"):
        said = _PLACE_ITEM.match(part.strip())
        if said is None and re.fullmatch(r"(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?", part.strip(), re.I):
            waiting.append(part.strip())
            continue
        if said is None or not _a_place(said["place"]):
            return None
        for np in [*waiting, said["np"]]:
            hit = [k for k, i in enumerate(items) if _same_thing(np, i)]
            if np.lower() in _FORMER_LATTER and len(items) == 2:
                hit = [_FORMER_LATTER[np.lower()]]
            if len(hit) != 1 or hit[0] in where:
                return None
            where[hit[0]] = f"{said['prep'].lower()} {said['place']}"
        waiting = []
    return None if waiting or len(where) != len(items) else where


def _two_apart(m: re.Match[str]) -> str:
    """ "Heat two mugs: one goes on A, the other in B" -> "heat a mug and put it on A, heat another mug and
    put it in B"; the text as it was unless the words name one kind of thing, several of it, and each place
    names one thing."""
    found = find_mentions(m["things"])
    places = [m[k].split(None, 1)[1] for k in ("p1", "p2")]
    if len(found) != 1 or not found[0].plural or not all(_a_place(p) for p in places):
        return m[0]
    name, verb = found[0].entry.phrase, m["verb"].lower()
    one = f"{'an' if name[:1] in 'aeiou' else 'a'} {name}"
    joined = f"{verb} {one} and put it {m['p1']}, {verb} another {name} and put it {m['p2']}"
    after_comma = m.string[: m.start()].rstrip().endswith(",")
    return m["lead"] + (joined if after_comma or m["lead"].strip() else _capital(joined))


def _base_verb(word: str) -> str | None:
    found = VERBS.get(word.lower())
    return found[1] if found and found[0] in _STATE else None


def _same_thing(np: str, item: str) -> bool:
    """Does a place's thing name that item of the list by its words ("the slice" of "a potato slice", "the
    bread" of "a slice of bread")?"""
    said = set(np.lower().split()) - _NOT_NAMING
    named = set(item.lower().split())
    return (said <= named and bool(said)) or (np.lower().split()[-1] == "slice" and "slice" in named)
