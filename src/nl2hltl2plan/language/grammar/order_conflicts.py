"""Order words that contradict the sequence they stand in (issue 23, h207): "First A, first B", "First A,
then first B", "A, then B, but first C, and finally D". The relations step reads the first "first" and the
"then"s, and dropped the other "first" unread (a wrong order at exit 0); these name it instead."""

from __future__ import annotations

import re

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.draft_tasks import Unit

# "first" opening a clause ("first of all" is one "first"; "the first drawer" opens none)
_OPENING_FIRST = re.compile(r"(?:^|[,.;:!?]\s*|\b(?:and|then|but)\s+)first\b(?!\s+of\s+all\b)", re.I)


def first_said_unread(units: list[Unit], text: str) -> str | None:
    """Why a "first" cannot be read, if so: it opens two clauses, or a list's "but first" marks a clause
    after others of its sentence ("A, then B, but first C, and finally D": the elided-verb list keeps C's
    marker; before which of A and B? `_first_edges` reads a "first" that opens its sentence only)."""
    said = len(_OPENING_FIRST.findall(text))
    if said > 1:
        return f"'first' said of {said} steps"
    for k, u in enumerate(units):
        said_before = any(v.sentence == u.sentence for v in units[:k])
        if u.joiner == "first" and said_before and any(kind == G.FIRST for kind, _ in u.markers):
            return "'first' (no step of the sentence is read as first)"
    return None
