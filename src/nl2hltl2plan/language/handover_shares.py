"""A region set said once and then shared out among the blocks (issue 24, h157): "put the red block on
one of regions G, H and I, the blue block on another of them, and the yellow block on the remaining one",
and the anonymous count "put one block on region H, another block on region I and the last block on region
J". Both say that the blocks end one per region on those regions, in no order, as "put the red, blue and
yellow blocks on regions G, H and I, one block per region" says; `handover_phrases.normalise` rewrites them
so on the lower-cased, punctuation-spaced sentence.

Only where each block of the list is named once and their count is the count of regions. A "then" (or any
other word) between the clauses is an order or more than a sharing: the sentence is left as it is, to be
read or refused by the other rules.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.handover_scene import COLOUR, LETTER

_BLOCK = rf"the\s+{COLOUR}\s+(?:block|pillar|object|cube)"
_VERB = r"(?:(?:put|place|move|set)\s+)?"
_GOES = r"(?:\s+(?:goes|should\s+go|must\s+go|can\s+go|is\s+put|should\s+be\s+put|should\s+be\s+placed))?"
_ON = r"\s+(?:on|onto|to|in|into)\s+"
_LETTERS = r"[e-j](?:\s*(?:,|\band\b|\bor\b)\s*[e-j])+"
_JOIN = r"\s*(?:,\s*)?(?:and\s+)?"

_NAMED = re.compile(
    rf"\b{_VERB}(?P<first>{_BLOCK}){_GOES}{_ON}one\s+of\s+(?:the\s+)?(?:regions\s+)?(?P<list>{_LETTERS})"
    rf"(?P<more>(?:{_JOIN}{_VERB}{_BLOCK}{_GOES}{_ON}(?:another|a\s+second|a\s+different)\s+(?:one\s+)?of\s+"
    rf"(?:them|those|these))+)"
    rf"{_JOIN}{_VERB}(?P<last>{_BLOCK}){_GOES}{_ON}the\s+(?:remaining|last|leftover)\s+(?:one|region)\b"
)

_ANY = r"(?:block|object|pillar|one)"
_AT = rf"{_ON}(?:region\s+)?(?P<{{name}}>[e-j])\b"
_COUNTED = re.compile(
    rf"\b{_VERB}one\s+(?:block|object|pillar){_GOES}{_AT.format(name='r1')}"
    rf"(?P<more>(?:{_JOIN}{_VERB}another\s+{_ANY}{_GOES}{_ON}(?:region\s+)?[e-j]\b)*)"
    rf"{_JOIN}{_VERB}the\s+(?:last|remaining|third|final)\s+{_ANY}{_GOES}{_AT.format(name='rl')}"
)
_COUNTS = {2: "two", 3: "three"}


def shared_out(text: str) -> str:
    """`text` with each region set shared out among the blocks said as one goal of the group."""
    return _COUNTED.sub(_counted, _NAMED.sub(_named, text))


def _named(found: re.Match[str]) -> str:
    blocks = [found["first"], *re.findall(_BLOCK, found["more"]), found["last"]]
    blocks = [" ".join(b.split()) for b in blocks]
    letters = re.findall(LETTER, found["list"])
    if len(set(blocks)) != len(blocks) or len(set(letters)) != len(blocks):
        return found[0]
    group = " , ".join(blocks[:-1]) + " and " + blocks[-1]
    return f"put {group} on regions {_listed(letters)} , one block per region"


def _counted(found: re.Match[str]) -> str:
    letters = [found["r1"], *re.findall(rf"{_ON}(?:region\s+)?([e-j])\b", found["more"]), found["rl"]]
    if len(set(letters)) != len(letters) or len(letters) not in _COUNTS:
        return found[0]
    return f"put the {_COUNTS[len(letters)]} blocks on regions {_listed(letters)} , one block per region"


def _listed(letters: list[str]) -> str:
    return " , ".join(letters[:-1]) + " and " + letters[-1]
