"""Misspelt names of things: "tomatoe", "microwve", "coffe table" read as the lexicon's words (issue 28).

One rule, used by the grammar (through `grammar.everyday`) and by check 1 (which reads the same rewritten
text, so a misspelt name the reading does not use is named, never passed over): a word of five letters
or more that the lexicon does not know is the lexicon word it is closest to (difflib ratio >= 0.85, or
two neighbouring letters swapped; one best match) when English does not know it either. The English
test (pyspellchecker's frequency list) keeps real words that look like names as they are: "ridge" is
not the fridge, "dressed" not the dresser, "status" not the statue. The list loads only when a word
passes the first test.
"""

from __future__ import annotations

import difflib
import re
from functools import cache, lru_cache

from nl2hltl2plan.language.grounding import lexicon

CUTOFF = 0.85  # one letter off in a five-letter word (4/5 matched is 0.8: "plate"/"place" stay apart)
_WORD = re.compile(r"[A-Za-z]{5,}")


@cache
def _name_words() -> tuple[str, ...]:
    """Every word of the lexicon's phrases in their singular form ("coffee", "table", "microwave")."""
    words = {w for key, (_, plural) in lexicon().items() if not plural for w in key}
    return tuple(sorted(w for w in words if len(w) >= 4))


@cache
def _known_words() -> frozenset[str]:
    """Every word the lexicon knows in any form (plurals included): these are never respelt."""
    return frozenset(w for key in lexicon() for w in key)


@cache
def _english():  # type: ignore[no-untyped-def]  # pyspellchecker has no type hints
    from spellchecker import SpellChecker

    return SpellChecker(distance=1)


@lru_cache(maxsize=4096)
def spelt_name(word: str) -> str | None:
    """The lexicon word that `word` misspells, or None (a known word, a real English word, too short,
    or no single closest name)."""
    low = word.lower()
    if len(low) < 5 or low in _known_words():
        return None
    scored = sorted(((_score(low, w), w) for w in _close(low)), reverse=True)
    if not scored or (len(scored) > 1 and scored[1][0] == scored[0][0]):
        return None
    if low in _english():
        return None
    return scored[0][1]


def _close(low: str) -> list[str]:
    """Names within the cutoff, and names two swapped neighbouring letters away ("kettel": difflib
    scores a swap as two edits)."""
    swapped = {low[:i] + low[i + 1] + low[i] + low[i + 2 :] for i in range(len(low) - 1)}
    names = _name_words()
    return sorted({*difflib.get_close_matches(low, names, n=3, cutoff=CUTOFF), *(swapped & set(names))})


def _score(low: str, name: str) -> float:
    """How close: a swap of neighbours counts as one letter off."""
    differ = len(low) == len(name) and sum(a != b for a, b in zip(low, name, strict=True))
    if differ == 2 and sorted(low) == sorted(name):
        return 1 - 1 / len(name)
    return difflib.SequenceMatcher(None, low, name).ratio()


def respelt(text: str) -> str:
    """`text` with each misspelt name written as the lexicon writes it (a capital kept)."""

    def fix(m: re.Match[str]) -> str:
        name = spelt_name(m[0])
        if name is None:
            return m[0]
        return name.capitalize() if m[0][0].isupper() else name

    return _WORD.sub(fix, text)
