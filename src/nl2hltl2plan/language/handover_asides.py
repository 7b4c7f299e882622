"""Asides in parentheses, read by what their words name (h95, issue 24).

A writer sets a remark off in parentheses wherever it occurs to them: in the middle of a clause ("place the
three objects (one per region) on regions G, H and I"), after a block ("the red block (first)"), or as
emphasis that says nothing new ("all three blocks (every one of them)", "nothing ... (none at all)", "no arm
may touch the blue block (not even briefly)", "(please)"). `read_asides` runs on the lower-cased sentence,
before the registers:

- an aside that only stresses what its clause already says is dropped: a restated group ("all of them",
  "every one of them", "all three", "each of them"), an emphatic negation ("none at all", "not even
  briefly", "not once", "whatsoever") only where its clause is already negated, a courtesy or reminder
  ("please", "remember", "of course", "mind you");
- an aside that interrupts a clause between its objects and their place ("place the three objects (one per
  region) on regions G, H and I", "move the red and blue blocks (at any time) to any empty region") is
  said after the place, set off by a comma, as a remark on the clause is;
- an aside inside a clause before other words of it ("place the red block (first) before the blue block"),
  and a one-word aside anywhere ("on region I (first), then on region G"), is read in its place, as the
  same words without parentheses;
- any other aside (one that ends its clause) is set off by commas, as the same words between commas are.
Its content is still read in each case, and still refused where the reader cannot place it.

An aside that names or describes the thing before it is left as it is, for the readers of such phrases: a
list's marker or a count ("(1)", "(b)", "(three)"), an apposition or a relative clause ("(the ones beside
arms a and b)", "(region E, F, G)", "(where the red block is now)", "(i.e. ...)").

Nothing is dropped that names a block, a place, an order, a time or an arm: those words are not in the
emphatic lists, so such an aside keeps its words and is read (or refused) like any other phrase.
"""

from __future__ import annotations

import re

# an aside in parentheses; never a list's marker or a count ("(1)", "(b)", "(three)") nor an apposition or
# a relative clause ("(the ones ...)", "(region E, F, G)", "(where ...)"): those keep their parentheses
_KEPT = (
    r"(?:\d+|[a-z]|[ivx]+|two|three|four"
    r"|(?:the|its|their|where|which|that|who|namely|i\.?e|e\.?g|regions?)\b[^()]*)"
)
_ASIDE = re.compile(rf"\(\s*(?!{_KEPT}\s*\))([^()]*?)\s*\)")

# a group restated: "all of them", "every one of them", "all three (of them)", "each of them", "both"
_GROUP = re.compile(
    r"(?:all|each|every|both|every\s+single)(?:\s+(?:one|three|two))?(?:\s+of\s+(?:them|those|these|the\s+three))?"
    r"|all\s+three\s+of\s+them|the\s+whole\s+lot|every\s+one"
)
# an emphatic negation: only where its clause already says "no / not / nothing / never / none / cannot"
_NEGATION = re.compile(
    r"(?:none|no(?:thing)?(?:\s+(?:object|block|objects|blocks|item|items))?)\s+(?:at\s+all|whatsoever)"
    r"|not\s+even(?:\s+(?:briefly|once|for\s+a\s+moment|slightly))?|not\s+once|never|at\s+all|whatsoever"
    r"|no\s+exceptions?|not\s+ever"
)
_NEGATED = re.compile(r"\b(?:no|not|nothing|never|none|cannot|can't|mustn't|n't|nobody)\b")
# an arm list alone ("arms a, b", "arm a, arm b"): a landmark, which must agree with the place beside it
_ARM_LIST = re.compile(r"arms?\s+[a-d](?:\s*(?:,|and|&)\s*(?:arm\s+)?[a-d])+|arm\s+[a-d]")
_COURTESY = re.compile(r"(?:please|remember|of\s+course|mind\s+you|note|thanks|thank\s+you)(?:\s*!)?")


def read_asides(text: str) -> str:
    """The sentence with its asides read as the module docstring says."""
    text = _ASIDE.sub(lambda aside: _emphatic(text, aside), text)
    text = _interrupting(text)
    return _ASIDE.sub(r" , \1 , ", text)


def _emphatic(text: str, aside: re.Match[str]) -> str:
    """Nothing for an aside that only stresses its clause, else the aside as it is."""
    words = " ".join(aside[1].split())
    if _GROUP.fullmatch(words) or _COURTESY.fullmatch(words):
        return " "
    if _NEGATION.fullmatch(words) and _NEGATED.search(_clause_before(text, aside.start())):
        return " "
    if _ARM_LIST.fullmatch(words):  # terse: "to E, F, G (arms a, b)" says where, as "next to arms a, b" does
        return f"(next to {words})"
    return aside[0]


def _interrupting(text: str) -> str:
    """Each aside that interrupts its clause said after the clause's place, or read in its place."""
    out, at = [], 0
    for aside in _ASIDE.finditer(text):
        if aside.start() < at:
            continue
        place = _PLACE_AFTER.match(text, aside.end())
        if place:
            out.append(f"{text[at : aside.start()]} {place[0].strip()} , {aside[1]} , ")
            at = place.end()
        elif _CLAUSE_GOES_ON.match(text, aside.end()) or len(aside[1].split()) == 1:
            out.append(f"{text[at : aside.start()]} {aside[1]} ")
            at = aside.end()
    return "".join(out) + text[at:]


# the place a clause's objects go to, right after an aside: "(...) on regions G, H and I", "(...) to any empty
# region", "(...) to the opposite side" (up to the end of the place: a list of region letters included)
_PLACE_AFTER = re.compile(
    r"\s*(?:back\s+)?(?:to|on|onto|into|in|over\s+to)\s+(?:"
    r"regions?\s+[a-j](?:\s*,\s*[a-j])*(?:\s*,?\s*(?:and|or|&)\s+[a-j])?(?![a-z])"
    r"|(?:the\s+)?opposite(?:\s+(?:side|regions?|area|end))?|any\s+(?:empty|free|vacant)\s+regions?)"
)
# more of the clause after the aside (a word, not a comma, a stop or the end)
_CLAUSE_GOES_ON = re.compile(r"\s*[a-z]")


def _clause_before(text: str, end: int) -> str:
    """The words of the aside's clause before it (from the last sentence end, semicolon or new line)."""
    return re.split(r"[.;!?\n]", text[:end])[-1]
