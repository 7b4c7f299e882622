"""A return with no place after it, said after the place a thing is taken from: "wash the cloth from the
cabinet, put it back", "take the egg out of the fridge, cook it and return it", "grab the mug off the
counter, rinse it, put it back where it was". No base task returns a thing to "where it was", but the
sentence named that place: the return is read as a placing there ("put it back in the cabinet") before the
grammar reads the text. With no source before it, or two different ones ("the egg out of the fridge and
the mug from the sink, put them back"), the text is left as written and check 1 names "back".

>>> put_back_where_taken("wash the cloth from the cabinet, put it back")
'wash the cloth from the cabinet, put it back in the cabinet'
>>> put_back_where_taken("put the mug in the sink, then put it back")
'put the mug in the sink, then put it back'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.grounding import find_mentions, sentence_start

# A place named right after "from" / "out of" / "off" (a determiner and one word may come between) is
# where the object is taken from, never its destination ("the second from the bottom shelf" is a place).
_SOURCE = re.compile(
    r"(?<!second\s)(?<!third\s)(?<!fourth\s)\b(?:from|out\s+of|off(?:\s+of)?)\s+"
    r"(?:(?:the|a|an|your|its|that|this)\s+)?(?:[a-z-]+\s+)?$",
    re.I,
)
# "put it back", "return it", "put it back where it was", "put them back in their place": a return whose
# place is not said (what follows ends the clause or is a connective, never "in the fridge")
_PUT_BACK = re.compile(
    r"\b(?:(?:put|place|set|stick|bring|take)\s+(?:(?P<pron>it|them)\s+)?back|return\s+(?P<rpron>it|them))"
    r"(?:\s+(?:(?:to\s+)?where\s+(?:it|they)\s+(?:was|were|came\s+from|belongs?)|"
    r"(?:in|into|on|to)\s+(?:its|their)\s+(?:original\s+)?(?:place|spot)s?))?"
    r"(?=\s*(?:$|[.,;!?)]|(?:and|then|afterwards|again|after|once|when|please)\b))",
    re.I,
)


def a_source(text: str, start: int) -> bool:
    """Whether the place named at `start` of `text` is where a thing is taken from ("from the sink")."""
    return bool(_SOURCE.search(text[:start]))


def put_back_where_taken(text: str) -> str:
    """`text` with each return whose place is unsaid put back in the one place its sentence named as a
    source before it (module doc)."""
    out, last = [], 0
    for m in _PUT_BACK.finditer(text):
        said = text[sentence_start(text, m.start()) : m.start()]
        sources = {x.entry.canonical: x.surface for x in find_mentions(said) if a_source(said, x.char_start)}
        if len(sources) != 1:
            continue
        pron = m.group("pron") or m.group("rpron") or "it"
        out += [text[last : m.start()], f"put {pron} back in the {next(iter(sources.values()))}"]
        last = m.end()
    return "".join(out) + text[last:]
