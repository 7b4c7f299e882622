"""The prepositions of a place, as the readers outside the grammar match them: taken from the grammar's one
list (`grammar.word_tables.PREPOSITIONS`, its destination and landmark sets), never written again.

>>> import re
>>> bool(re.fullmatch(preposition_pattern(ONE_PLACE), "on  top of"))
True
>>> "between" in ONE_PLACE, "next to" in PLACE_OR_LANDMARK
(False, True)
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from nl2hltl2plan.language.grammar.word_tables import DEST_PREPS, NEAR_PREPS, PREPOSITIONS

# where a thing is put, one place to each: the grammar's destinations but the two that take two places
# ("between the sink and the stove") and the parser's own "then to"
ONE_PLACE = frozenset(DEST_PREPS - {"between", "in between", "among", "then to"})
# where a thing is put or stands: a question's gap ("what goes next to the sink?") and a correction's place
# ("in the sink, no wait, next to it") may name a landmark too
PLACE_OR_LANDMARK = ONE_PLACE | frozenset(NEAR_PREPS)


def preposition_pattern(words: Iterable[str]) -> str:
    """`words` (prepositions of `PREPOSITIONS`) as one regular expression, the longest first, any spaces
    between a preposition's words (no context, no flags)."""
    said = set(words)
    unknown = said - {" ".join(p) for p in PREPOSITIONS}
    if unknown:
        raise ValueError(f"not prepositions of grammar.word_tables: {sorted(unknown)}")
    ordered = sorted(said, key=lambda p: (-len(p), p))
    return "(?:" + "|".join(r"\s+".join(map(re.escape, p.split())) for p in ordered) + ")"
