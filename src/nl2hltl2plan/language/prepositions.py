"""The prepositions of a place, as the readers outside the grammar match them: taken from the grammar's one
list (`grammar.word_tables.PREPOSITIONS`, its destination and landmark sets), never written again; and
which preposition a place phrase of a tokenized text has (`preposition_before`, for check 1); and whether a
place is named as a source, where a thing is taken from (`source_at`, `a_source`: check 1, the grammar's
"put it back" and the learned readers ask this one test), or as where a thing goes (`goes_to`, check 1).

>>> import re
>>> bool(re.fullmatch(preposition_pattern(ONE_PLACE), "on  top of"))
True
>>> "between" in ONE_PLACE, "next to" in PLACE_OR_LANDMARK
(False, True)
>>> [a_source(t, t.index("shelf")) for t in ("take it out of the shelf", "the second from the top shelf")]
[True, False]
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from pathlib import Path

from nl2hltl2plan.language.content_words import DETERMINERS, LOCATIVE, categories
from nl2hltl2plan.language.grammar.word_tables import DEST_PREPS, NEAR_PREPS, PREPOSITIONS
from nl2hltl2plan.language.grounding import tokens

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


# where a place phrase opens a destination (check 1: "from the counter to the table")
DESTINATION = frozenset({"to", "into", "onto"})


def preposition_before(toks: list[tuple[str, int, int]], start: int, preps: frozenset[str]) -> int:
    """The index of the preposition before the phrase whose first word is at `start`, over up to four
    determiners or plain words; else of the word where the scan stopped (-1 at the start): at a destination's
    ("from the counter to the table": "to"), at "and" / "or" before a phrase with its own determiner ("the
    apple from the counter and the egg"; "from the sink and table" shares the "from")."""
    i = start - 1
    while i >= 0 and start - i <= 4 and toks[i][0] not in preps:
        if _to_a_destination(toks, i) or (toks[i][0] not in DETERMINERS and categories(toks[i][0])):
            break
        if toks[i][0] in ("and", "or") and i < start - 1:
            break
        i -= 1
    return i


def _to_a_destination(toks: list[tuple[str, int, int]], i: int) -> bool:
    """ "to" / "into" / "onto" at `i` opens a destination, unless it ends "next to", "close to", "up to"."""
    return toks[i][0] in DESTINATION and (i == 0 or toks[i - 1][0] not in LOCATIVE | {"close", "up"})


# the first word of a source's prepositions: "from (under) the bed", "out of the fridge", "off (of) the
# counter"
SOURCE = frozenset({"from", "off", "out"})
# "the second from the top shelf": which shelf, no source
_ORDINALS = frozenset({"first", "second", "third", "fourth", "last", "2nd", "3rd"})


def source_at(text: str, toks: list[tuple[str, int, int]], start: int, relative: bool = False) -> bool:
    """Is the place phrase whose first word is token `start` of `text` (tokenized as `toks`) where a thing is
    taken from: its prepositions (`preposition_before`, never over punctuation) open with "from", "out" or
    "off", not after an ordinal ("the second from the top shelf")?"""
    i = preposition_before(toks, start, LOCATIVE)
    if i < 0 or toks[i][0] not in LOCATIVE or re.search(r"[,;:.!?]", text[toks[i][2] : toks[start][1]]):
        return False
    while i > 0 and toks[i - 1][0] in LOCATIVE | {"out"}:
        i -= 1  # "from under the bed", "out of", "off of"
    said_from = toks[i][0] in SOURCE and (i == 0 or toks[i - 1][0] not in _ORDINALS)
    return said_from or (relative and _where_it_is(toks, i))


# with `relative` (check 1, `accounting`): "the plate thats in the microwave", "the mug that is under the
# coffee maker" (paper_h301), a relative clause that says where the thing is now, as "from" does (not for
# the learned models' data labels, `learned.faithful`, which a change here would move)
_RELATIVE = frozenset({"that", "which", "thats", "that's", "which's"})
_IS = frozenset({"is", "are", "'s", "s"})


def _where_it_is(toks: list[tuple[str, int, int]], i: int) -> bool:
    j = i - 1 if i > 0 and toks[i - 1][0] in {"sitting", "lying", "standing", "now"} else i
    j = j - 1 if j > 0 and toks[j - 1][0] in _IS else j
    return j > 0 and toks[j - 1][0] in _RELATIVE


def a_source(text: str, start: int) -> bool:
    """`source_at` of the place whose name begins at character `start` of `text` ("from the sink")."""
    toks = tokens(text)
    at = next((k for k, t in enumerate(toks) if t[1] == start), None)
    return at is not None and source_at(text, toks, at)


_GOING_LINES = (Path(__file__).parent / "going_words.txt").read_text().splitlines()
_GOING = frozenset(w for line in _GOING_LINES if not line.startswith("#") for w in line.split())


def goes_to(toks: list[tuple[str, int, int]], i: int) -> bool:
    """Is the preposition at `i` said right after "put it" ("put it in the microwave") or after a verb that
    says where its subject goes ("a potato slice goes in the fridge"; not "the mug that sits on the
    shelf")? Its place is a destination, never where something is (h273: a rewrite that carried the
    sentence before's verb over "A potato slice goes in the fridge" made it one object, and check 1 took
    the fridge for where the slice is)."""
    if i >= 2 and toks[i - 1][0] in ("it", "them") and "verb_any" in categories(toks[i - 2][0]):
        return True
    relative = i >= 2 and toks[i - 2][0] in ("that", "which")
    return i >= 1 and toks[i - 1][0] in _GOING and not relative
