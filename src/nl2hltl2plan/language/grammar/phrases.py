"""Noun phrases: the word lists and `parse_np`, which the later steps share."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cache, lru_cache

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grounding import (
    LAMPS,
    MOVABLE_RECEPTACLES,
    RECEPTACLES,
    Entry,
    camel_words,
    find_mentions,
)

_WORD = re.compile(r"[A-Za-z0-9]+(?:'[A-Za-z]+)?|,")
DETERMINERS = {
    "the",
    "a",
    "an",
    "some",
    "any",
    "one",
    "another",
    "other",
    "each",
    "every",
    "this",
    "that",
    "these",
    "those",
    "its",
    "their",
    "my",
    "your",
    "his",
    "her",
    "our",
    "all",
    "both",
    "two",
    "three",
    "four",
    "five",
    "single",
    "couple",
    "pair",
    "set",
    "of",
    "several",
}
COLOURS = {
    "red",
    "blue",
    "green",
    "yellow",
    "pink",
    "purple",
    "white",
    "black",
    "grey",
    "gray",
    "brown",
    "multi-colored",
    "multicolored",
    "colored",
    "coloured",
    "multi",
    "orange-colored",
}
FILLER = {
    "left",
    "right",
    "upper",
    "lower",
    "top",
    "bottom",
    "back",
    "front",
    "side",
    "edge",
    "end",
    "center",
    "centre",
    "middle",
    "seat",
    "lid",
    "surface",
    "corner",
    "open",
    "empty",
    "full",
    "opened",
    "closed",
    "new",
    "old",
    "small",
    "large",
    "big",
    "little",
    "left-most",
    "leftmost",
    "rightmost",
    "same",
    "most",
    "nearest",
    "closest",
    "first",
    "second",
    "third",
    "last",
    "other",
    "kitchen",
    "living",
    "room",
    "part",
    "area",
    "spot",
    "place",
    "inside",
}


@dataclass
class NP:
    """A noun phrase: its words, the lexicon entry of its head, and what its modifiers say."""

    text: str
    entry: Entry | None = None
    head: str = ""  # words naming the thing when no lexicon entry fits ("green apple", "region h")
    plural: bool = False
    count: int = 1
    pronoun: bool = False
    states: set[str] = field(default_factory=set)
    sliced: bool = False
    generic: bool = False
    water: bool = False
    # "three things: the egg ...": a count before a colon counts what the heading names, not the head
    heading_count: bool = False

    @property
    def empty(self) -> bool:
        return self.entry is None and not self.head and not self.pronoun

    @property
    def key(self) -> str:
        if self.entry is not None:
            return self.entry.canonical
        return self.head

    def is_lamp(self) -> bool:
        return self.entry is not None and set(self.entry.types) <= LAMPS | {"LightSwitch"}

    def is_receptacle(self) -> bool:
        return self.entry is not None and any(t in RECEPTACLES for t in self.entry.types)

    def is_movable_receptacle(self) -> bool:
        return self.entry is not None and self.entry.canonical in MOVABLE_RECEPTACLES


def tokens(text: str) -> list[tuple[str, int, int]]:
    """(lower-case word or comma, start, end) for each word of `text`."""
    return list(_tokens(text))


@lru_cache(maxsize=4096)  # the clauses' noun phrases are read again by each reading of the instruction
def _tokens(text: str) -> tuple[tuple[str, int, int], ...]:
    return tuple((m.group(0).lower(), m.start(), m.end()) for m in _WORD.finditer(text))


# ----- noun phrases ----------------------------------------------------------------------------------
# a word after a compound's last noun that makes it the place for that thing ("the mug location")
_SPOT = re.compile(r"\s*(?:location|spot|place|area|holder|slot|position)s?\b", re.I)


def parse_np(text: str) -> NP:
    """A noun phrase: its head (a lexicon entry, else its own words), pronoun, states, slices, count."""
    np = NP(text=text.strip())
    words = [w for w, _, _ in tokens(text) if w != ","]
    if not words:
        return np
    mentions = find_mentions(text)
    # pronoun ("it", "them", "the same one")
    words = [w for w in words if w not in G.PARTICLES]
    content = [w for w in words if w not in DETERMINERS and w not in G.PRONOUNS]
    if not content or (
        all(w in G.PRONOUNS | DETERMINERS for w in words) and any(w in G.PRONOUNS for w in words)
    ):
        np.pronoun = any(w in G.PRONOUNS for w in words) or not content
    # "put a fork in the mug, move both to the counter": a bare "both" names the things already said
    # (the fork and the mug), not a second fork
    _read_modifiers(np, [w for w in words if w != "both"] if not content else words)
    if ":" in text:
        heading = [w for w, _, _ in tokens(text.rsplit(":", 1)[0])]
        np.heading_count = any(w.isdigit() or G.NUMBERS.get(w, 0) > 1 for w in heading)
    real = [m for m in mentions if not m.entry.generic]
    if real:
        # the head is the first mention unless it is followed by "of" + another ("bar of soap" is one entry)
        m = real[0]
        for nxt in real[1:]:  # a compound names its last noun: "a glass bowl" is a bowl
            if text[m.char_end : nxt.char_start].strip() or nxt.entry.phrase == "container":
                break  # but "a soap container" holds soap: the soap's
            if _SPOT.match(text[nxt.char_end :]):
                break  # "the coffee maker mug spot" is a spot of the coffee maker, for a mug
            m = nxt
        np.entry, np.plural = m.entry, m.plural
        surface = text[m.char_start : m.char_end].lower()
        one_of = words[:2] == ["one", "of"]  # "one of the pots": one
        if m.plural and surface != "keys" and not surface.startswith("set of") and not one_of:
            # "keys" and "a set of keychains" are one key chain; "the keychains" are two
            np.count = max(np.count, 2)
    elif mentions:
        np.generic = True
        np.plural = mentions[0].plural
    if not np.entry and not np.pronoun:
        _read_own_head(np, words, content)
    return np


def _read_modifiers(np: NP, words: list[str]) -> None:
    """State words (washed, heated, sliced), slice nouns, water, numbers."""
    for w in words:
        if w in G.STATE_WORDS:
            st = G.STATE_WORDS[w]
            if st == "slice":
                np.sliced = True
            else:
                np.states.add(st)
        if w in G.SLICE_NOUNS:
            np.sliced = True
        if w in G.WATER_WORDS:
            np.water = True
        number = int(w) if w.isdigit() else G.NUMBERS.get(w, 0)
        if number > 1:  # "three mugs", "3 mugs": check 1 holds the count to what the scene has
            np.count = max(np.count, number)
    if "toast" in words:
        np.sliced = True


def _read_own_head(np: NP, words: list[str], content: list[str]) -> None:
    """No lexicon entry: the content words name the thing ("green apple", "region h"); "-s" marks plural."""
    head = [
        w
        for w in content
        if w not in G.STATE_WORDS and w not in G.SLICE_NOUNS and w not in FILLER and w not in G.WATER_WORDS
    ]
    if np.generic:
        head = []
    np.head = " ".join(head)
    if (
        np.head
        and not np.generic
        and words[-1].endswith("s")
        and not words[-1].endswith("ss")
        and len(head) == 1
    ):
        np.plural = True
        np.count = max(np.count, 2)


# ----- clauses and frames ------------------------------------------------------------------------------
def match_prep(words: list[str], i: int) -> tuple[str, int] | None:
    """The preposition starting at word `i` (the first of `grammar.PREPOSITIONS` that fits) and its length."""
    for p in _prepositions_from(words[i]) if i < len(words) else ():
        if tuple(words[i : i + len(p)]) == p:
            return " ".join(p), len(p)
    return None


@cache  # asked of every word of every clause: only the prepositions that start with the word are tried
def _prepositions_from(word: str) -> tuple[tuple[str, ...], ...]:
    return tuple(p for p in G.PREPOSITIONS if p[0] == word)


def one_of_each_under_a_shared_plural(nps: list[NP | None]) -> None:
    """ "the salt and pepper shakers": a plural whose head noun the thing listed before it leaves out names
    one of each (a salt shaker and a pepper shaker), not two pepper shakers."""
    for prev, np in zip(nps, nps[1:], strict=False):
        if prev is None or np is None or prev.entry is None or np.entry is None or not np.plural:
            continue
        head = camel_words(np.entry.canonical).lower().split()[-1]  # "shaker"
        said = camel_words(prev.entry.canonical).lower()
        if said != camel_words(np.entry.canonical).lower() and said.endswith(f" {head}"):
            if head not in prev.text.lower() and np.count == 2:
                np.count = 1
