"""Pieces of a sliceable thing said without "slice" (issue 28, h276): "a round of tomato", "a sliver of
apple", "the heel of the loaf", "a potato slab" are slices, and are written so for the readers; "a leaf of
lettuce", "a bit of bread", "the end of the loaf" may be no slice, and check 1 refuses them by name
(`vague_words`). Before, all of them were read as the whole thing at exit 0. The words are in
piece_words.txt.

>>> slices_said("Chill a round of tomato and put it on the table.")
'Chill a slice of tomato and put it on the table.'
>>> slices_said("Put the round tomato on the table.")
'Put the round tomato on the table.'
"""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

from nl2hltl2plan.language.content_words import Unread
from nl2hltl2plan.language.grounding import SLICEABLE, find_mentions

_FILE = Path(__file__).with_name("piece_words.txt")
_CUT = SLICEABLE - {"Egg"}  # an egg is cracked, not cut into pieces
UNSURE_PIECE = "a part that may be no slice: say 'a slice of' or the whole thing"


@lru_cache(maxsize=1)
def _words() -> dict[str, tuple[str, ...]]:
    out: dict[str, tuple[str, ...]] = {}
    for line in _FILE.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            kind, words = line.split(":", 1)
            out[kind.strip()] = tuple(words.split())
    return out


def _alternation(*kinds: str) -> str:
    return "|".join(w for k in kinds for w in _words()[k])


@lru_cache(maxsize=1)
def _patterns() -> tuple[re.Pattern[str], re.Pattern[str], re.Pattern[str]]:
    det = r"(?:(?:the|an?|this|that)\s+)?"
    of = re.compile(rf"\b(?P<w>{_alternation('slice', 'slice_of_bread')})(?P<s>s)?\s+of\s+{det}", re.I)
    # "a tomato round", not "the apple round the corner"
    not_after = r"(?!\s+(?:the|a|an|to|about|of)\b)"
    after = re.compile(rf"\s+(?P<w>{_alternation('slice')})(?P<s>s)?\b{not_after}", re.I)
    unsure = re.compile(rf"\b(?:(?:a|an|one|the)\s+)?(?:{_alternation('unsure')})s?\s+of\s+{det}", re.I)
    return of, after, unsure


def _cut(text: str, at: int, bread_only: bool) -> int | None:
    """Where the one sliceable thing named at `at` ends, or None."""
    named = next((x for x in find_mentions(text) if x.char_start == at), None)
    if named is None or named.entry.generic:
        return None
    types = set(named.entry.types) & _CUT
    if not types or (bread_only and types != {"Bread"}):
        return None
    return named.char_end


def slices_said(text: str) -> str:
    """`text` with each piece word that names a slice of a sliceable thing written "slice"."""
    of, after, _ = _patterns()
    for m in reversed(list(of.finditer(text))):
        if _cut(text, m.end(), m["w"].lower() in _words()["slice_of_bread"]) is not None:
            text = text[: m.start("w")] + "slice" + text[m.end("w") :]
    for x in reversed(find_mentions(text)):
        compound = after.match(text, x.char_end)  # "a tomato round"
        if compound and not x.entry.generic and set(x.entry.types) & _CUT and len(set(x.entry.types)) == 1:
            text = text[: compound.start("w")] + "slice" + text[compound.end("w") :]
    return text


def unsure_pieces(lowered: str) -> list[Unread]:
    """Check 1's refusals of a part that may be no slice ("a leaf of lettuce"), said of a sliceable thing,
    and of a slice of a thing no knife cuts into slices ("a slice of egg": read as a cracked egg at exit
    0)."""
    _, _, unsure = _patterns()
    out = []
    for m in unsure.finditer(lowered):
        end = _cut(lowered, m.end(), bread_only=False)
        if end is not None:
            out.append(Unread(lowered[m.start() : end], "count", UNSURE_PIECE))
    for x in find_mentions(lowered):
        if set(x.entry.types) <= SLICEABLE - _CUT and (
            _SLICE_BEFORE.search(lowered[max(0, x.char_start - 24) : x.char_start])
            or _SLICE_AFTER.match(lowered, x.char_end)
        ):
            out.append(Unread(x.surface, "object", NO_SLICES))
    return out


NO_SLICES = "no knife cuts it into slices (an egg is cracked): no base task takes a slice of it"
_SLICE_WORD = r"(?:slices?|pieces?|wedges?|chunks?|bits?)"
_SLICE_BEFORE = re.compile(
    rf"\b(?:{_SLICE_WORD}\s+of|slice|cut|chop)(?:\s+up)?\s+(?:the\s+|an?\s+|that\s+)?$"
)
_SLICE_AFTER = re.compile(rf"\s+{_SLICE_WORD}\b")
