"""The order said in a remark of its own, after or before the tasks (issue 28): "Start with the towel.",
"Save the mug for last.", "Books first, mug last.", "The first two in any order, the cloth last.", "The
washing last.", "Start with the spray bottle; the rest in any order.".

A sentence is such a remark when every part of it (split at commas, semicolons and ", but") is one of the
patterns of `order_remarks.txt`; each part gives one relation (kind, a, b) that `remark_edges` maps to the
tasks it names. A sentence with any other part is left to the rules (`sentences.read_sentences`)."""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

from nl2hltl2plan.language.content_words import free_order_phrase
from nl2hltl2plan.language.grammar import word_tables as G

# a thing that names a task: one to four words, no verb (but a treatment's "-ing") and no preposition, so
# that "put the mug in the sink first" is a clause, never a remark
_THING = r"(?:[a-z][a-z']*(?:\s+[a-z][a-z']*){0,3}?)"
_NOT_IN_THING = frozenset(
    "in on into onto to from under at by with for till until then and or it them you your i we is are be not "
    "don't can wait save leave keep may might could should must will would either any whichever each every "
    "neither step steps order only just right but which what matter doesn't does else rest others everything "
    "anything".split()
)
# every other task ("Everything else before the apple", "The lamp ones can wait until the rest is done")
_REST = (
    r"(?:the\s+rest|(?:everything|anything)\s+else|(?:all\s+)?the\s+others|the\s+other\s+(?:ones|two|three)|"
    r"all\s+of\s+them|all\s+that|both(?:\s+of\s+them)?)"
)
_DONE = r"(?:is|are|has\s+been|have\s+been)\s+(?:done|finished|complete|completed|over)"
# the treatments whose verb may open a remark ("Rinse the soap before anything else.")
_TREATING = frozenset({"clean", "heat", "cool"})
# (and "and" before a last thing that closes the sentence: "The bread comes first and the apple last", h261)
_PARTS = re.compile(
    r"\s*(?:,\s*(?:but|and)\s+|,|;|\s+but\s+|\s+and\s+(?=(?:the\s+)?[a-z]+(?:\s+[a-z]+){0,2}\s+last$))\s*",
    re.I,
)

# sentences that only say the order is free (no task, no constraint): a free-order clause ("the order is up
# to you"; content_words.free_order_phrase) in a sentence that opens with no verb ("Any order." alone does
# not say what it frees, and is left to the rules)
NO_ORDER_SENTENCE = re.compile(rf"\b{free_order_phrase('clause')}\b", re.I)
# "Do the fork first.", "The mug last.", "Start with the fork.": the task of one named object before (after)
# every other task; "the" may be left out before tasks named so ("Counter ones first"), "go" said (h190)
FIRST_LAST_SENTENCE = re.compile(
    r"^(?:(?:please\s+)?(?:do|handle|deal\s+with)\s+)?"
    r"(?P<a>(?:the|that|this)\s+[a-z][a-z\s]*?|[a-z]+(?:\s+[a-z]+)?\s+(?:ones?|jobs?|tasks?))\s+"
    r"(?:(?:go|goes|come|comes|should\s+(?:go|come)|get\s+done|gets\s+done)\s+)?"
    r"(?P<rel>first|last)(?:\s*,?\s*(?:please|though))?$"
    r"|^(?:please\s+)?(?:start|begin)\s+with\s+(?P<start>(?:the|that|this)\s+[a-z][a-z\s]*?)(?:\s*,?\s*please)?$",
    re.I,
)
# "A should be placed before B" with bare noun phrases: a relation between tasks named by their objects
REL_SENTENCE = re.compile(
    r"^(?P<a>.+?)\s+(?:should|must|has\s+to|needs?\s+to|is\s+to)\s+(?:be\s+)?(?:placed|put|moved|done|handled|"
    r"transferred|delivered|completed|finished)\s+(?P<rel>before|after)\s+(?P<b>.+)$",
    re.I,
)

Relation = tuple[str, str, str]  # (kind, a, b); "free": a is "first" / "last", b the count


@cache
def _patterns() -> list[tuple[str, re.Pattern[str]]]:
    out = []
    for line in Path(__file__).with_name("order_remarks.txt").read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        kind, pattern = line.split(":", 1)
        body = pattern.strip().replace("{x}", rf"(?P<x>{_THING})").replace("{y}", rf"(?P<y>{_THING})")
        body = body.replace("{v}", r"(?P<v>[a-z]+(?:\s+up)?)").replace("{rest}", _REST)
        body = body.replace("{done}", _DONE)
        out.append((kind.strip(), re.compile(rf"^{body}$", re.I)))
    return out


def _a_thing(words: str | None) -> bool:
    """May these words name a task's thing (no verb, no preposition: a clause is no remark)?"""
    said = (words or "").lower().split()
    return bool(said) and not any(
        w in _NOT_IN_THING or (w in G.VERBS and not w.endswith("ing")) or w in ("first", "last") for w in said
    )


def _part(part: str) -> Relation | None:
    for kind, pattern in _patterns():
        if not (m := pattern.match(part)):
            continue
        said = m.groupdict()
        if kind == "free":
            return kind, said["pos"].lower(), said["n"].lower()
        if kind == "rest":
            return kind, "", ""
        verb = said.get("v")
        if verb is not None and G.VERBS.get(verb.split()[0].lower(), ("",))[0] not in _TREATING:
            continue  # "put the mug first" is a clause (no thing is named by a place verb alone)
        if _a_thing(said.get("x")) and (kind != "before" or _a_thing(said.get("y"))):
            return kind, f"{verb} {said['x']}" if verb else said["x"], said.get("y") or ""
    return None


def order_remark(sentence: str, before: str | None = None) -> list[Relation] | None:
    """The relations of a sentence that only says the order of tasks named elsewhere, free ones last (they
    are checked against the edges the others give); None where any part says something else. `before`: the
    text before the sentence, where a thing said to be done at any time must be named (`_read`).

    >>> order_remark("Soap bottles first, toilet paper last")
    [('first', 'Soap bottles', ''), ('last', 'toilet paper', '')]
    >>> order_remark("Put the mug in the sink first") is None
    True
    """
    read = _read(sentence, before)  # a plain "X first" of `remarks_said_plainly` reads as it was written
    return None if read is None else sorted((r for r, _ in read), key=lambda r: r[0] == "free")


def _read(sentence: str, before: str | None = None) -> list[tuple[Relation, str]] | None:
    """Each part of a remark sentence with its relation, in the order said; None: no remark. "The CD
    whenever." where no CD is named `before` is no remark: it is the task before, for the CD (`repeats`)."""
    sentence = _CLOSING_COURTESY.sub("", sentence)  # "mug first and egg last pls": the parts read without it
    parts = [p.strip(" .!") for p in _PARTS.split(sentence.strip(" .!")) if p.strip(" .!")]
    read = [(_part(p), p) for p in parts if not _COURTESY.match(p)]
    if not read or any(r is None for r, _ in read):
        return None
    if len(read) > 1 and all(r[0] == "rest" for r, _ in read if r is not None):
        return None
    if before is not None and any(r[0] == "any" and not _named_before(r[1], before) for r, _ in read if r):
        return None
    return [(r, p) for r, p in read if r is not None]


_NAMING = frozenset("the a an that this one ones job jobs task tasks stuff".split())


def _named_before(thing: str, before: str) -> bool:
    """Is a word of `thing` (its name, not "the" / "ones") in the text before, a plural's stem too?"""
    words = [w for w in thing.lower().split() if w not in _NAMING]
    return any(re.search(rf"\b{re.escape(w[:-1] if w.endswith('s') else w)}", before, re.I) for w in words)


_SENTENCE = re.compile(r"[^.;!?]+[.;!?]*\s*")
_COURTESY = re.compile(r"^(?:please|thanks|thank\s+you|cheers)$", re.I)
# a courtesy word closing a remark sentence (h278): with it, "and" before its last part was no part break
_CLOSING_COURTESY = re.compile(r"\s*,?\s*\b(?:please|pls|plz|thanks|thx|ta|cheers)\s*[.!]*\s*$", re.I)


# "A and put B after everything else" / "after the rest" / "once both are done": the clause the closing
# reference ends is B alone (each clause of the sentence took it, a cycle); not "wash the mug and put it away
# ..." (one task)
_LAST_CLAUSE_ELSE = re.compile(
    r",?\s+and\s+(?=(?P<verb>[a-z]+)\s+(?!it\b|them\b|that\b|this\b)[^.;!?,]*?\s+(?:before|after|once|when)\s+"
    r"(?:(?:anything|everything)\s+else|the\s+rest|both(?:\s+of\s+th[a-z]+)?\s+(?:are|have\s+been)\s+[a-z]+)"
    r"\s*(?:[.;!?]|$))",
    re.I,
)


def remarks_said_plainly(text: str) -> str:
    """Each order remark written as the plain "X first" / "X last" that the rules and check 1 read ("Save the
    laptop for last." -> "the laptop last."); "the rest in any order" beside a first / last remark says no
    more and goes. Other sentences are kept as written.

    >>> remarks_said_plainly("Put A on B. Start with the spray bottle; the rest in any order.")
    'Put A on B. the spray bottle first; '
    """
    text = _LAST_CLAUSE_ELSE.sub(lambda m: ". " if m["verb"].lower() in G.VERBS else m[0], text)
    text = _DONE_THE_REST.sub(r". That last\g<end>", text)
    text = _SENTENCE.sub(lambda m: _remark_opens(m[0]), text)
    spans = [(m, _read(m[0].rstrip(".;!? "), text[: m.start()])) for m in _SENTENCE.finditer(text)]
    ends = any(r is not None and any(k in ("first", "last") for (k, _, _), _ in r) for _, r in spans)
    out: list[str] = []
    for m, read in spans:
        head, said = "", m[0]
        if read is None and (tail := _tail_remark(said)) is not None:  # "A and B, the latter first."
            head, said, read = tail
        after_clause = out and out[-1].rstrip().endswith(";") and _read(out[-1].rstrip(" ;")) is None
        if read is not None and after_clause:  # "Heat an egg; that one comes first.": a remark of its own
            out[-1] = out[-1].rstrip()[:-1] + ". "
        if read is not None and (ends or any(k != "rest" for (k, _, _), _ in read)):
            body = said.rstrip(".;!? ")
            lead, end = body[: len(body) - len(body.lstrip())], said[len(body) :]
            read = [(r, s) for r, p in read if (s := _plain(r[0], r[1], p))]
            plain = ", ".join(s for _, s in read)
            said = lead + plain + end if plain else ""
        out.append(head + said)
    return "".join(out)


# where a remark said after the tasks of its own sentence begins: a comma or a dash
_TAIL = re.compile(r",\s*|\s+-+\s+")


def _tail_remark(sentence: str) -> tuple[str, str, list[tuple[Relation, str]]] | None:
    """ "Look at A and B under the lamp, the latter first." -> ("Look at A and B under the lamp. ", "the
    latter first.", its relations): the longest tail, after a comma or a dash, that is an order remark
    saying which task is first, last or before another, as a sentence of its own; None where none is."""
    body = sentence.rstrip(".;!? ")
    for m in _TAIL.finditer(body):
        read = _read(body[m.end() :])
        if read is not None and any(k in ("first", "last", "before") for (k, _, _), _ in read):
            return f"{body[: m.start()]}. ", body[m.end() :] + sentence[len(body) :], read
    return None


def _plain(kind: str, a: str, part: str) -> str:
    if kind in ("first", "last"):
        return f"{a} {kind}"
    return "" if kind == "rest" else part


# "Heat an apple and put it in the fridge when you've done the rest.": that sentence's task after every other
_DONE_THE_REST = re.compile(
    r",?\s+(?:when|once|after)\s+you(?:'ve|\s+have)?\s+(?:done|finished|completed)\s+"
    r"(?:the\s+rest|(?:everything|anything)\s+else|(?:all\s+)?the\s+others)(?P<end>\s*[.!?](?:\s|$)|\s*$)",
    re.I,
)
# "Save the kettle for last: wash it and set it on the stove.": a first / last remark that opens its task
_OPENING_REMARK = re.compile(r"^(?P<lead>\s*)(?P<remark>[^:]+?)\s*:\s+(?P<clause>[^:]+?)(?P<end>[.!?]*\s*)$")
_ITS_THING = re.compile(
    r"^(?P<verb>[a-z]+)\s+(?:(?P<it>it|them)\b|(?P<part>(?:a|one)\s+(?:slice|piece))\b(?!\s+of))", re.I
)


def _remark_opens(sentence: str) -> str:
    """ "Save the bread for last: chill a slice and ..." -> "chill a slice of the bread and .... the bread
    last.": the clause, its "it" or "a slice" said of the remark's thing, then the remark; any other
    sentence unchanged."""
    m = _OPENING_REMARK.match(sentence)
    read = _read(m["remark"]) if m else None
    if m is None or read is None or len(read) != 1 or read[0][0][0] not in ("first", "last"):
        return sentence
    (kind, thing, _), _said = read[0]
    def of_thing(t: re.Match[str]) -> str:
        return f"{t['verb']} {thing}" if t["it"] else f"{t['verb']} {t['part']} of {thing}"

    named = _ITS_THING.sub(of_thing, m["clause"], count=1)
    if named == m["clause"] and re.search(r"\b(?:it|them)\b", named, re.I):
        return sentence  # "Start with the fridge: put the egg in it": its "it" is the remark's thing
    return f"{m['lead']}{named}. {thing} {kind}{m['end'] or '.'}"

