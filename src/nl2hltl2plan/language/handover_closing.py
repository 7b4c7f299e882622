"""A closing restriction on what moves, on the handover worlds: "Nothing else moves.", "No other block is
moved.", "..., and leave everything else where it is". It adds a constraint only where a block has no goal
(that block must then stay put, which the spec cannot say as a goal): where every block of the world has a
goal it restates the spec and is read as nothing; where one has none it is refused, by name."""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError

_OTHERS = (
    r"(?:nothing\s+else|no\s+other\s+(?:blocks?|objects?|pillars?|items?|pieces?|ones?)|"
    r"none\s+of\s+the\s+other\s+(?:blocks|objects|pillars|items|pieces|ones)|(?:everything|anything)\s+else)"
)
_STAYS = (
    r"(?:moves?|is\s+moved|are\s+moved|gets?\s+moved|(?:should|must|may|will|can|shall)(?:\s+not)?\s+(?:be\s+)?"
    r"moved?|(?:is|are|gets?)\s+touched|(?:stays?|remains?)\s+(?:put|where\s+(?:it\s+is|they\s+are)))"
)
_NOT_MOVED = (
    rf"(?:{_OTHERS}\s+{_STAYS}|(?:do\s+not|don\s*[’']?\s*t|never)\s+(?:move|touch)\s+(?:anything\s+else|"
    r"any\s+other\s+(?:blocks?|objects?|pillars?|items?|pieces?))|leave\s+(?:everything|anything)\s+else\s+"
    r"(?:alone|where\s+it\s+is|untouched|in\s+place))"
)
# "Nothing else." closing the instruction: no other task, so nothing else moves either
_WHOLE = re.compile(
    rf"(?i)^\s*(?:and\s+|also\s+)?(?:{_NOT_MOVED}|nothing\s+(?:else|more)|no\s+other\s+moves?)\s*[.!]*\s*$"
)
_AT_END = re.compile(rf"(?i)\s*(?:,\s*|\s+)(?:and\s+)?{_NOT_MOVED}\s*[.!]*\s*$")


def closing_said(sentences: list[str]) -> tuple[list[str], list[str]]:
    """The sentences without their closing restrictions on what moves, and those restrictions' words."""
    kept: list[str] = []
    said: list[str] = []
    for sentence in sentences:
        if _WHOLE.match(sentence):
            said.append(sentence.strip())
            continue
        end = _AT_END.search(sentence)
        if end and sentence[: end.start()].strip():
            said.append(end.group(0).strip(" ,"))
            sentence = sentence[: end.start()]
        kept.append(sentence)
    return kept, said


def check_closing(said: list[str], moved: set[str], blocks: list[str]) -> None:
    """Refuse a closing restriction that keeps a block without a goal in place (a constraint the spec does
    not carry); one that restates the spec (every block has a goal) is read as nothing."""
    still = [b for b in blocks if b not in moved]
    if said and still:
        raise HTTError(
            f"'{said[0]}' keeps the {', '.join(b.lower() for b in still)} block in place, which the reader "
            "cannot say as a goal: leave it out or give that block a goal"
        )
