"""A formal requirement's possessive places and a result clause that restates the one-block rule,
rewritten onto the forms the handover reader reads (issue 24; `handover_registers.REGISTERS` applies
`REQUIREMENTS` first, to the lower-cased sentence with its punctuation spaced out):

- "the three blocks shall be moved to their opposite regions", "the yellow block ... to its opposite
  region": the opposite side is per block already, so the possessive is "the", but only where it agrees
  with the blocks of its clause ("their" after blocks said in the plural or "each (of)", "its" after one
  block or "each (of)"); a possessive that agrees with no block of its clause stays unread (refused);
- "(away) from their own places to ...", "from its own place to ...": where the blocks start, said
  before where they go, adds nothing; "to their own places" (where they already are) stays unread;
- a result clause that says the one-block rule again: "..., so there's one block on each" (with one
  block on each), "so that every one of those regions gets one" (each of those regions), "so that each
  of those regions ends up holding one object" (each region holds one), "so that each of them ends up
  holding one" right after a list of regions ("them": those regions), "so that each region gets one of
  them" (a region gets one block: "them" are the blocks).
  Any other result clause ("so there's one block on G", "so that region F ends up empty") stays unread
  and is refused by name: it would add a goal.
"""

from __future__ import annotations

import re
from collections.abc import Callable

_NOUN = r"(?:block|object|pillar|item|cube)"
_PLACE = r"(?:place|position|spot|region|location)"
# the blocks of a clause, as its possessive may refer to them
_PLURAL = re.compile(rf"\b(?:{_NOUN}s|both|all\s+three|them|they)\b")
_SINGULAR = re.compile(rf"\b(?:red|blue|yellow)(?:\s+{_NOUN}|\s+one)?\b(?!\s+and\b)(?!\s*,)")
_EACH = re.compile(rf"\beach\s+(?:of|{_NOUN})\b")


def _possessive(match: re.Match[str]) -> str:
    """'their / its' before 'opposite' as 'the', where it agrees with the blocks of its clause."""
    clause = re.split(r"[.;:!?]", match.string[: match.start()])[-1]
    plural = bool(_PLURAL.search(clause))
    each = bool(_EACH.search(clause))
    singular = bool(_SINGULAR.search(clause)) and not plural
    agrees = each or (plural if match.group(1) == "their" else singular)
    return "the " if agrees else match.group(0)


_RULES: tuple[tuple[str, str | Callable[[re.Match[str]], str]], ...] = (
    # where the blocks start, said before where they go
    (rf"\b(?:away\s+)?from\s+(?:its|their)\s+own\s+{_PLACE}s?\s+(?=(?:to|onto|into|on|in)\s)", ""),
    (r"\b(its|their)\s+(?=opposite\b)", _possessive),
    # a result clause of the one-block rule ("so" after a comma is dropped as an interjection before this)
    (
        r"(,|\bso(?:\s+that)?)\s*there\s*(?:is|'?s|will\s+be|ends\s+up\s+being)\s+(?=(?:exactly\s+|only\s+|just\s+)?"
        rf"(?:one|a\s+single)(?:\s+{_NOUN})?\s+(?:on|in)\s+each\b)",
        r"\1 with ",
    ),
    # "every one of those regions gets one": each of them
    (r"\bevery\s+one\s+of\s+(?=(?:the|these|those)\s+(?:region|area|place|spot)s\b)", "each of "),
    # "(so that) each of them ends up holding one" right after a list of regions: "them" are those regions
    (
        r"(?<=\b[e-j])(\s*,?\s*(?:,|\bso(?:\s+that)?)\s*)(?:each|every\s+one|all)\s+of\s+them\s+(?=(?:(?:will|would|should|"
        r"must)\s+)?(?:ends?\s+up\s+(?:holding|having|getting|containing|receiving|with)|holds?|has|have|gets?|"
        r"contains?|receives?)\s+(?:exactly\s+|only\s+|just\s+)?(?:one|a\s+single)\b)",
        r"\1each of those regions ",
    ),
    # "each region gets one of them / of the blocks": a region receives a block, so "them" are the blocks and
    # "one of them" is the "one" read above
    (
        r"\b((?:each|every)\s+(?:of\s+(?:the|these|those)\s+)?(?:region|area|place|spot)s?\s+(?:(?:will|would|should|"
        rf"must)\s+)?(?:gets?|holds?|receives?|has|contains?|takes?)\s+(?:exactly\s+|only\s+|just\s+)?one)\s+of\s+"
        rf"(?:them|the\s+(?:three\s+)?{_NOUN}s)\b",
        r"\1",
    ),
    (
        r"\b((?:each|every)\s+(?:of\s+(?:the|these|those)\s+)?(?:region|area|place|spot)s?)\s+ends?\s+up\s+"
        r"(?:holding|having|getting|containing|receiving)\b",
        r"\1 holds",
    ),
)

REQUIREMENTS = tuple((re.compile(pattern), replacement) for pattern, replacement in _RULES)
