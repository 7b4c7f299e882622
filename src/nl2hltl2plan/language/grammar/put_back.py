"""A return with no place after it, said after the place a thing is taken from: "wash the cloth from the
cabinet, put it back", "take the egg out of the fridge, cook it and return it", "grab the mug off the
counter, rinse it, put it back where it was". No base task returns a thing to "where it was", but the
sentence named that place: the return is read as a placing there ("put it back in the cabinet") before the
grammar reads the text. Things taken each from its own place and returned right away ("take the apple from
the counter and the egg out of the fridge and put them back") each go back to theirs. With no source before
it, or sources the return cannot pair with its things ("the egg out of the fridge and the mug from the
sink, wash them and put them back"), the text is left as written and check 1 names "back".

>>> put_back_where_taken("wash the cloth from the cabinet, put it back")
'wash the cloth from the cabinet, put it back in the cabinet'
>>> put_back_where_taken("put the mug in the sink, then put it back")
'put the mug in the sink, then put it back'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language import prepositions  # a module: prepositions imports the grammar's word tables
from nl2hltl2plan.language.grounding import find_mentions, sentence_start

# "where it was", "in its usual place", "to their home": the place a return goes back to, left unsaid (the
# one pattern of it: here, and check 1's `unsupported_steps`)
WHERE_IT_WAS = (
    r"(?:\s+(?:to\s+)?where\s+(?:it|they)\s+(?:was|were|came\s+from|belongs?)|"
    r"\s+(?:in|into|on|to)\s+(?:its|their)\s+(?:original\s+|usual\s+)?(?:place|spot|home)s?)?"
)
# "put it back", "return it", "put it back where it was", "put them back in their place": a return whose
# place is not said (what follows ends the clause or is a connective, never "in the fridge")
_PUT_BACK = re.compile(
    r"\b(?:(?:put|place|set|stick|bring|take)\s+(?:(?P<pron>it|them)\s+)?back|return\s+(?P<rpron>it|them))"
    + WHERE_IT_WAS
    + r"(?=\s*(?:$|[.,;!?)]|(?:and|then|afterwards|again|after|once|when|please)\b))",
    re.I,
)


# where things belong, said as a statement right before a return ("the remotes live on the armchair, please
# put them back", "my keys go in the box. put them back"): the return goes to that place, said once
BELONGS_THEN_BACK = re.compile(
    r"\b(?P<np>(?:the|my|your|our|all\s+the|both)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s+"
    r"(?:live|lives|belong|belongs|go|goes)\s+(?P<place>(?:on|in|into|onto)\s+(?:the|my|your|our)\s+"
    r"[a-z]+(?:\s+[a-z]+){0,2}?)\s*[,.;]\s*(?:so\s+)?(?P<please>please\s+)?"
    r"(?:(?:put|place|set|bring|take)\s+(?:them|it)\s+back|return\s+(?:them|it))" + WHERE_IT_WAS
    + r"(?=\s*(?:$|[.,;!?)]|(?:and|then|please)\b))",
    re.I,
)


def back_where_belongs(text: str) -> str:
    """`text` with each return right after a statement of where its things belong said as one placing there
    (read before the grammar's normalizing, which writes "the X goes in Y" as a placing of its own).

    >>> back_where_belongs("the remotes live on the armchair, please put them back")
    'please put the remotes back on the armchair'
    """
    return BELONGS_THEN_BACK.sub(lambda m: f"{m['please'] or ''}put {m['np']} back {m['place']}", text)


def put_back_where_taken(text: str) -> str:
    """`text` with each return whose place is unsaid put back in the one place its sentence named as a
    source before it (module doc)."""
    out, last = [], 0
    for m in _PUT_BACK.finditer(text):
        said = text[sentence_start(text, m.start()) : m.start()]
        named = find_mentions(said)
        sources = {x.entry.canonical: x.surface for x in named if prepositions.a_source(said, x.char_start)}
        if len(sources) != 1:
            them = len(sources) > 1 and (m.group("pron") or m.group("rpron")) == "them"
            each = _TAKEN.search(said) if them else None
            if each is not None and (back := _each_back(each.group("body"))):
                out += [text[last : sentence_start(text, m.start()) + each.start()], back]
                last = m.end()
            continue
        pron = m.group("pron") or m.group("rpron") or "it"
        out += [text[last : m.start()], f"put {pron} back in the {next(iter(sources.values()))}"]
        last = m.end()
    text = "".join(out) + text[last:]
    # the grammar's normalizing gathers "take X from A and Y from B and put them back" as "put X from A and
    # Y from B back"
    return _GATHERED.sub(lambda g: _each_back(g.group("body")) or g.group(0), text)


# things taken each from its own place, then returned: "take the apple from the counter and the egg out of the
# fridge and put them back" (the sentence before the return), "put the apple from the counter and the egg
# out of the fridge back" (as the grammar's normalizing gathers it)
_TAKEN = re.compile(
    r"\b(?:take|get|grab|fetch|remove|pick\s+up)\s+(?P<body>(?:the|your|that|this)\s.*?)\s*,?\s*(?:and\s+)?"
    r"(?:then\s+)?$",
    re.I,
)
_GATHERED = re.compile(
    r"\b(?:put|place|set|bring|take)\s+(?P<body>(?:the|your|that|this)\s[^.;!?]*?)\s+back\b"
    r"(?=\s*(?:$|[.,;!?)]|(?:and|then)\b))",
    re.I,
)
# nothing but a source's prepositions and a determiner between a thing and its place
_FROM = re.compile(r"\s+(?:[a-z]+\s+){1,2}(?:the|your|its|that|this)\s+", re.I)
_AND = re.compile(r"\s*(?:,\s*)?(?:and\s+)?(?:the|your|that|this)\s+", re.I)


def _each_back(body: str) -> str | None:
    """Each thing of `body` put back in its own source, where `body` is only "the X from the A and the Y
    out of the B ..." (two or more things, each from its own place); None otherwise."""
    found = find_mentions(body)
    if len(found) % 2 or len(found) < 4:
        return None
    pairs = list(zip(found[::2], found[1::2], strict=True))
    ends = [0] + [p.char_end for _, p in pairs[:-1]]
    if pairs[-1][1].char_end != len(body) or len({t.entry.canonical for t, _ in pairs}) != len(pairs):
        return None
    if not all(_AND.fullmatch(body[e : t.char_start]) for e, (t, _) in zip(ends, pairs, strict=True)):
        return None
    gaps = [(body[t.char_end : p.char_start], p.char_start) for t, p in pairs]
    if not all(_FROM.fullmatch(gap) and prepositions.a_source(body, at) for gap, at in gaps):
        return None
    return " and ".join(f"put the {t.surface} back in the {p.surface}" for t, p in pairs)
