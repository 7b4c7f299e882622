"""Forms of a household (ALFRED) instruction written out as the forms the shared grammar reads, before it
reads (the household reader's `prepared`); each rewrite keeps every word that names a thing, a place or
an action, and applies only where its parts name what it needs:

- a list of things and places with colons (`paired`): "mug: sink; apple: fridge" is "mug -> sink,
  apple -> fridge", which the grammar reads as it reads arrows ("green apple -> blue plate"); each side of
  a colon names one thing or place, so a label ("Task: ...", "Note: ...") is left as it is;
- a thing asked as a topic, then what to do with it (`topic_said`): "The mug? Heat it and put it in the
  sink." is "Heat the mug and put it in the sink." (the question names one thing and nothing else, and the
  sentence after it says "it" or "them"); "The mug in the sink - wash it ..." is "Wash the mug in the sink
  ..." (a thing and where it is, set off by a dash or a colon, before a verb on "it");
- a treatment and a "respectively" list after it (`treated_lists`): "wash the mug and the plate and put
  them in the sink and the cabinet respectively" is "put the washed mug and the washed plate in the sink
  and the cabinet respectively", which `respectively.distributed` writes out pair by pair;
- a story's or a commentator's narration of the robot's actions, as the commands it tells of
  (`household_narration.narrated`, first);
- a list's count written after its things (`counts_before`, h294): "candles x2", "2x spray bottles", "soap
  bars (2)" are "two candles", ... (the count was left unread, and the task took one);
- an instruction continued over two rows or sentences (`continued`): "pick up two books. lay them on the
  dining table" is one task ("pick up ... and lay them ..."): a sentence that only picks a thing up does
  nothing of its own;
- a list item that names its thing first, then what to do (`items_said`, h294): "wrist watch, inspect under
  the floor lamp", "1 cloth - rinse well, then leave in the bathtub", "potato slice, microwave, bin",
  "Two loaves of bread: store in the fridge" are "inspect the wrist watch under the floor lamp", "rinse one
  cloth well and leave it in the bathtub", "microwave the potato slice and put it in the bin", ...; "same"
  or "ditto" after a thing is what the item before it said to do ("item 4 - mobile phone, same");
- "first" said after a thing whose clause goes on ("Put two bottles in the fridge. Heat a slice of bread
  first and throw it in the bin.", `first_remarked`): the task on that thing before every other, said as a
  remark of its own after the sentence ("... throw it in the bin. The slice of bread first."), which
  `grammar.order_remarks` reads (the guide: "X first" orders X against each of the others); inside the
  clause the word was left unread.

>>> paired("mug: sink; apple: fridge")
'mug -> sink, apple -> fridge'
>>> topic_said("The mug? Heat it and put it in the sink.")
'Heat the mug and put it in the sink.'
>>> topic_said("The mug in the sink - wash it and put it in the cabinet.")
'Wash the mug in the sink and put it in the cabinet.'
>>> treated_lists("rinse the mug and the plate and put them in the sink and the cabinet respectively")
'put the rinsed mug and the rinsed plate in the sink and the cabinet respectively'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import stems
from nl2hltl2plan.language.grammar.restated import fixed_place
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS, VERBS
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.household_narration import narrated
from nl2hltl2plan.language.respectively import LIST_ITEMS

_NP = r"(?:(?:the|a|an|my|your|this|that)\s+)?[a-z]+(?:\s+[a-z]+){0,2}"
# "mug: sink" between list separators (a colon that opens a clause, "Task: put ...", has a verb after it,
# and its sides are not one thing and one place)
_PAIR = re.compile(
    rf"(?P<lead>^|[,;]\s*|\b(?:and|then)\s+)(?P<thing>{_NP})\s*:\s*(?P<place>{_NP})"
    r"(?=\s*(?:[,;.!]|\band\b|\bthen\b|$))",
    re.I,
)
_SEPARATOR = re.compile(r"\s*;\s*")
# "The mug?", "what about the mug?", "as for the apple?" opening the text or a sentence
_TOPIC = re.compile(
    rf"(?P<lead>^|(?<=[.!?])\s+)(?:(?:and|what\s+about|how\s+about|as\s+for)\s+)?(?P<np>{_NP})\s*\?\s+"
    r"(?P<next>[^.!?]*\b(?:it|them)\b)",
    re.I,
)
_PRONOUN = re.compile(r"\b(?:it|them)\b", re.I)
# "The apple in the microwave - slice it, ...": a thing and where it is, set off by a dash or a colon, then a
# verb of the grammar on "it" (h261); its place is where it is found, never a step ("put it in the microwave")
_PLACED_TOPIC = re.compile(
    r"(?P<lead>^|(?<=[.!?])\s+)(?P<np>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)\s+"
    r"(?P<where>(?:in|on|inside|from)\s+the\s+[a-z]+(?:\s+[a-z]+)?)\s*(?:\s[-\u2013\u2014]+|:)\s*"
    r"(?P<verb>[a-z]+)\s+(?:it|them)\b",
    re.I,
)


def _participles() -> dict[str, str]:
    """Each treatment verb of the grammar -> the participle the grammar reads as that treatment's state
    ("wash" -> "washed": `word_tables.VERBS` and `STATE_WORDS`, the one table of both); an "-ed" form
    before a bare one ("warmed", not "warm")."""
    out = {}
    for done in sorted(STATE_WORDS, key=lambda w: w.endswith("ed")):  # the "-ed" forms last: they stay
        for verb in stems(done):
            if VERBS.get(verb) == (STATE_WORDS[done], verb):
                out[verb] = done
    return out


PARTICIPLES = _participles()
# a treatment of its things, then a placement of "them" closing with "respectively"
_TREATED = re.compile(
    rf"\b(?P<verb>{'|'.join(PARTICIPLES)})(?:\s+up)?\s+(?P<things>[^.;!?]+?)\s*,?\s+and\s+(?:then\s+)?"
    r"(?P<put>put|place|set|move|leave|store)\s+them\s+(?P<places>[^.;!?]+?,?\s+respectively)\b",
    re.I,
)
_DETERMINER = re.compile(r"^(?P<det>(?:the|a|an|my|your|both|two)\s+)?", re.I)


# a completion clause on every task before it with no comma before the verbless item it orders ("..., and once
# everything else is done 2 keychains on the armchair"): the comma, so that the item is a clause of its own
_REST_DONE_ITEM = re.compile(
    r"\b(?P<done>(?:once|when|after)\s+(?:everything\s+else|all\s+(?:of\s+)?(?:that|else|the\s+rest)|the\s+rest|"
    r"both(?:\s+of\s+(?:them|those))?)(?:'s|\s+is|\s+are|\s+has\s+been|\s+have\s+been)\s+(?:all\s+)?"
    r"(?:done|finished|over|complete|completed))(?=\s+(?:a|an|the|another|one|two|three|four|both|\d+)\s)",
    re.I,
)


def household_forms(text: str) -> str:
    """`text` with each form above written out as the grammar reads it."""
    text = _REST_DONE_ITEM.sub(r"\g<done>,", text)
    text = first_remarked(placed_items(items_said(continued(counts_before(narrated(text))))))
    return treated_lists(topic_said(paired(text)))



def paired(text: str) -> str:
    """Colon pairs of one thing and one place, "mug: sink; apple: fridge", as arrows; else `text`."""
    pairs = list(_PAIR.finditer(text))
    if not pairs or not all(_one_thing(m["thing"]) and _one_thing(m["place"]) for m in pairs):
        return text
    if any(fixed_place(m["thing"]) for m in pairs):  # "armchair: a newspaper": a place heads its things
        return text
    text = _PAIR.sub(lambda m: f"{m['lead']}{m['thing']} -> {m['place']}", text)
    return _SEPARATOR.sub(", ", text)


def topic_said(text: str) -> str:
    """ "The mug? Heat it ..." as "Heat the mug ..."; else `text`."""

    def said(m: re.Match[str]) -> str:
        if not _one_thing(m["np"]):
            return m[0]
        np = m["np"] if _DETERMINER.match(m["np"])["det"] else f"the {m['np']}"  # type: ignore[index]
        rest = _PRONOUN.sub(np.lower(), m["next"], count=1)
        return f"{m['lead']}{rest[0].upper()}{rest[1:]}"

    def placed(m: re.Match[str]) -> str:
        if m["verb"].lower() not in VERBS or not (_one_thing(m["np"]) and _one_thing(m["where"])):
            return m[0]
        return f"{m['lead']}{m['verb'].capitalize()} {m['np'].lower()} {m['where']}"

    return _PLACED_TOPIC.sub(placed, _TOPIC.sub(said, text))


def treated_lists(text: str) -> str:
    """ "wash A and B and put them in X and Y respectively" as "put the washed A and the washed B in X
    and Y respectively"; else `text`."""

    def said(m: re.Match[str]) -> str:
        things = LIST_ITEMS.split(m["things"].strip())
        if len(things) < 2 or not all(_one_thing(t) for t in things):
            return m[0]
        done = PARTICIPLES[m["verb"].lower()]
        treated = [_DETERMINER.sub(lambda d: f"{d['det'] or 'the '}{done} ", t, count=1) for t in things]
        return f"{m['put']} {' and '.join(treated)} {m['places']}"

    return _TREATED.sub(said, text)


def _one_thing(phrase: str) -> bool:
    """Does the phrase name exactly one thing or place of the lexicon ("the mug", "coffee machine")?"""
    named = find_mentions(phrase)
    return len(named) == 1 and not named[0].entry.generic


# --- h294 (issue 28): a list's counts, rows continued, and items that name their thing first

_COUNT_NAMES = {str(n): w for n, w in enumerate("zero one two three four five six".split())}
# "candles x2", "spray bottles ×2", "soap bars (2)" after a list's separator; "2x candles" before the things
_COUNT_AFTER = re.compile(
    r"(?P<lead>^|[,;:.!?]\s*|\s[-\u2013\u2014]+\s*|->\s*|\band\s+)(?P<things>[a-z][a-z ]*?[a-z])"
    r"(?:\s+[x\u00d7]\s*(?P<n>[1-6])|\s*\(\s*(?P<m>[1-6])\s*\))(?=\s*(?:[-\u2013\u2014,;:.!?]|->|$))",
    re.I,
)
_COUNT_FIRST = re.compile(r"\b(?P<n>[1-6])\s*[x\u00d7]\s+(?=[a-z])", re.I)


def counts_before(text: str) -> str:
    """A count written after the things it counts (or as "2x") as the count word before them."""

    def said(m: re.Match[str]) -> str:
        things = _DETERMINER.sub("", m["things"], count=1)
        named = find_mentions(things.lower())  # "put the CD in the box 2. ...": a step's number, no count
        if len(named) != 1 or not _names_only(things, named[0].char_start, named[0].char_end):
            return m[0]
        return f"{m['lead']}{_COUNT_NAMES[m['n'] or m['m']]} {things}"

    return _COUNT_FIRST.sub(lambda m: f"{_COUNT_NAMES[m['n']]} ", _COUNT_AFTER.sub(said, text))


# a sentence that only picks things up, then one that places "it" or "them": one task over two sentences
_PICKED_ONLY = re.compile(
    r"(?P<pick>\b(?:pick\s+up|grab|take|get|collect|fetch)\s+[^.!?;:]+?)\s*[.;]\s+"
    r"(?P<verb>[a-z]+)\s+(?P<pron>it|them)\b",
    re.I,
)


def continued(text: str) -> str:
    """ "pick up two books. lay them on the table" as "pick up two books and lay them on the table"."""

    def said(m: re.Match[str]) -> str:
        if VERBS.get(m["verb"].lower(), ("",))[0] not in _DOING:
            return m[0]
        return f"{m['pick']} and {m['verb']} {m['pron']}"

    return _PICKED_ONLY.sub(said, text)


# an item of a list: its thing, a dash, a colon or a comma, then what to do with it; items end at a
# semicolon or a sentence's end, and a heading's colon opens the first
_ITEM = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?;:]))\s*)(?P<thing>[A-Za-z0-9][A-Za-z0-9' ]*?)\s*(?:\s[-\u2013\u2014]+(?=\s)|,|:)"
    r"(?=\s*(?P<rest>[^.!?;:]+?)\s*(?:[.!?;]|$))"
)
_SAME = re.compile(r"^(?:the\s+)?(?:same|ditto|likewise)(?:\s+again|\s+as\s+above)?$", re.I)
_ORDINAL_THING = re.compile(r"^(?:2nd|second)\s+", re.I)
_TREATING = frozenset({"clean", "cool", "heat"})
_DOING = _TREATING | {"place", "examine", "trash"}


def items_said(text: str) -> str:
    """List items that name their thing first ("rag - wash, into the tub") as clauses that open with
    their verb ("wash the rag and put it into the tub"); "same" / "ditto" repeats the item before."""
    before: list[str] = []  # what the item before said to do

    def said(m: re.Match[str]) -> str:
        thing, parts = m["thing"].strip(), [p.strip() for p in m["rest"].split(",") if p.strip()]
        if _SAME.match(m["rest"].strip()) and before:
            parts = before
        named = find_mentions(thing.lower())
        if len(named) != 1 or named[0].entry.generic or not parts or not _opens_doing(parts[0]):
            return m[0]
        if not _names_only(thing, named[0].char_start, named[0].char_end):
            return m[0]
        before[:] = parts
        thing = _ORDINAL_THING.sub("another ", thing)
        if not (_DETERMINER.match(thing)["det"] or re.match(r"\d|another\b", thing, re.I)):  # type: ignore[index]
            thing = f"the {thing}"
        thing = re.sub(r"^1\s+", "one ", thing)
        clauses = [_clause(p, thing if k == 0 else "it") for k, p in enumerate(parts)]
        if any(c is None for c in clauses):
            return m[0]
        return f"{m['lead']}{' and '.join(c for c in clauses if c)}"  # the whole item, its rest included

    out, pos = [], 0
    for m in _ITEM.finditer(text):  # the rest is a lookahead: a heading ("Kitchen pattern:") is passed over
        if m.start() < pos:
            continue
        if (item := said(m)) != m[0]:
            out.append(text[pos : m.start()] + item)
            pos = m.end("rest")
    return "".join(out) + text[pos:]


# what may follow an item's verb: nothing, a place's preposition or a manner ("rinse well, then ..."); a
# verb with its own object opens a clause of its own ("Ahead of the newspaper, put two keys in the safe")
_AFTER_VERB = frozenset("in into on onto to under inside beneath well thoroughly off up out".split())
# the words of a thing's phrase besides its name: a count, a determiner or a describing word, never an order,
# a time or a person ("Before you examine the basketball, put ...", "Right after, heat an egg ...")
_PIECES = frozenset({"slice", "slices"})  # "potato slice": the piece, not the verb
_NOT_IN_ITEM = frozenset(
    "before after ahead first then once when while begin start by finally next meanwhile until having done "
    "you i we please whenever as soon if right is are be and or needs need has have".split()
)


def _opens_doing(part: str) -> bool:
    """Whether the part opens with a verb that treats, places or examines a thing and takes no object of its
    own ("rinse well", "store in the fridge", "examine under the lamp", "chill")."""
    words = re.sub(r"^then\s+", "", part, flags=re.I).split()
    verb = VERBS.get(words[0].lower()) if words else None
    return verb is not None and verb[0] in _DOING and (len(words) < 2 or words[1].lower() in _AFTER_VERB)


def _names_only(thing: str, start: int, end: int) -> bool:
    """Whether an item's thing ("wrist watch", "1 cloth", "2nd mug") is a name with at most a count, a
    determiner or describing words before it: no verb, preposition, order or person outside the name."""
    said = thing.lower()
    rest = (said[:start] + " " + said[end:]).split()
    return len(said.split()) <= 5 and not any(
        (w in VERBS and w not in _PIECES) or w in _NOT_IN_ITEM or w in _AFTER_VERB - {"well"} for w in rest
    )


def _clause(part: str, thing: str) -> str | None:
    """One part of an item as a clause on `thing`: a verb ("rinse well": "rinse the cloth well"), a place
    after a preposition ("into the tub": "put it into the tub"), a bare place ("bin": "put it in the
    bin"), or the lamp said to be on ("lamp on": kept); None where the part is none of these."""
    part = re.sub(r"^then\s+", "", part, flags=re.I)
    words = part.split()
    first = words[0].lower()
    # a bare "bin" is the place ("potato slice, microwave, bin"), though "bin it" throws a thing away
    if first in VERBS and VERBS[first][0] in _DOING and not (len(words) == 1 and VERBS[first][0] == "trash"):
        return " ".join([words[0], thing, *words[1:]])
    if re.match(r"(?:lamp|light)\s+(?:on|switched\s+on)$", part, re.I):
        return ""
    places = find_mentions(" ".join(words[1:]).lower())
    if first in {"in", "into", "to", "onto", "on", "under", "inside"} and places:
        # "then to the bin": "put it to the bin" is no English the grammar reads
        return f"put {thing} {'in' if first == 'to' else first} {' '.join(words[1:])}"
    if _one_thing(part) and not _DETERMINER.match(part)["det"]:  # type: ignore[index]
        return f"put {thing} in the {part}"
    return None


# a sentence that is one verbless placement, "two vases onto the black desk.", "a third vase into the safe.":
# the grammar supplies its "put", but a list of such sentences lost the first one's order ("Work the rows in
# order" ordered only the later rows); said with its verb, each is read as a sentence of its own
_PLACED_ITEM = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?;:]))\s*)(?P<thing>(?:one|two|three|four|\d|a|an|the|another)\s+[a-z ]+?)\s+"
    r"(?P<rest>(?:into|onto|in|on|to)\s+[^.!?;:,]+?)(?=\s*(?:[.!?;]|$))",
    re.I,
)


def placed_items(text: str) -> str:
    """Sentences that are one verbless placement with "put" before them; else `text`."""

    def said(m: re.Match[str]) -> str:
        thing = re.sub(r"^(?:one|two|three|four|\d|a|an|the|another)\s+", "", m["thing"], flags=re.I)
        named = find_mentions(thing.lower())
        place = re.sub(r"^\w+\s+", "", m["rest"])  # one place, no list after it ("on the dresser and ...")
        # "The plate needs to be washed and put in ...", "The plate stays on the shelf": a verb after the name
        if len(named) != 1 or thing[named[0].char_end :].strip() or not _names_only(
            thing, named[0].char_start, named[0].char_end
        ):
            return m[0]
        if not re.match(r"(?:the|a|an|my|your)\s", place, re.I) or not _one_thing(place):
            return m[0]
        return f"{m['lead']}put {m['thing']} {m['rest']}"

    return _PLACED_ITEM.sub(said, text)


# "Heat a slice of bread first and throw it in the bin": a thing, "first", and its clause going on with "it";
# "Heat the tomato first, then put it on the counter" orders the task's own steps ("First X, then Y"), and
# is left as it is
_FIRST_INSIDE = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?;]))\s*)(?P<verb>[A-Za-z]+)\s+(?P<np>(?:the|a|an|one|two|another)\s+[a-z]+"
    r"(?:\s+[a-z]+){0,3}?)\s+first\s+(?P<join>and)\s+(?P<rest>[a-z]+\s+(?:it|them)\b[^.!?;]*)"
    r"(?P<end>[.!?;]|$)",
    re.I,
)


def first_remarked(text: str) -> str:
    """ "V X first and V2 it ..." as "V X and V2 it .... The X first." (see the module docstring)."""

    def said(m: re.Match[str]) -> str:
        if m["verb"].lower() not in VERBS or not _one_thing(m["np"]):
            return m[0]
        the = re.sub(r"^(?:a|an|one|another)\s+", "the ", m["np"], flags=re.I)
        end = m["end"] if m["end"] and m["end"] in ".!?" else "."
        remark = f"{the[0].upper()}{the[1:]} first{end}"
        return f"{m['lead']}{m['verb']} {m['np']} {m['join']} {m['rest']}{end} {remark}"

    return _FIRST_INSIDE.sub(said, text)
