"""Words of a household (ALFRED) instruction that name a thing by what it is or holds, read with the
floor plan's types before the grammar reads (the household reader's `prepared`; the data and where it
comes from are in household_names.txt, the drinks and food in content_words.txt):

- a descriptive name of a receptacle ("the island", "the nightstand", "the entertainment center", "the
  vanity") is the first of its types that the floor plan has, written as that type's name; a name whose
  types the floor plan has two or more of, where they differ (`: either`), is refused by name, or left as
  said (`: as said`); one whose first present type is marked `=Type` is left as said too;
- a drink or food ("a cup of coffee", "heat up some coffee") is left for check 1, which names it: no floor
  plan has coffee apart from its container, and a plan that heats the cup cannot check that it holds
  coffee; the refusal says so and asks for the container alone (`contents_hint`).

>>> descriptive_names("put the apple on the island", {"DiningTable", "CounterTop"})
'put the apple on the dining table'
>>> contents_hint("heat up coffee in a mug")
'no floor plan has coffee apart from its container: to act on the container, name it alone'
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import DRINK_FOOD, phrase_category
from nl2hltl2plan.language.grounding import camel_words, find_mentions, phrase_lines

_PREPOSITIONS = {"in": r"(?:in|into|inside|in\s+to)", "on": r"(?:on|onto|on\s+top\s+of|upon)"}


@dataclass(frozen=True)
class _Name:
    pattern: re.Pattern[str]
    types: tuple[str, ...]
    either: bool
    as_said: bool  # two or more of its types in the floor plan: left as said, not refused


@cache
def _names() -> tuple[_Name, ...]:
    out = []
    for names, fields in phrase_lines("household_names.txt"):
        for name in names:
            prep, _, words = name.rpartition(":")
            said = r"\s+".join(map(re.escape, words.split()))
            lead = rf"\b{_PREPOSITIONS[prep]}\s+(?:(?:the|a|an|your|my)\s+)?" if prep else ""
            pattern = re.compile(rf"{lead}(?<![\w-])(?P<name>{said})(?![\w-])", re.I)
            flags = fields[1:]
            out.append(_Name(pattern, tuple(fields[0].split()), "either" in flags, "as said" in flags))
    return tuple(out)


def descriptive_names(text: str, types: set[str]) -> str:
    """`text` with each descriptive name written as the name of the type it is in a floor plan of `types`
    (see the module docstring); raises HTTError naming the types where the name could be several."""
    return _renamed(text, types)[0]


def descriptive_name_notes(text: str, types: set[str]) -> list[str]:
    """What `descriptive_names` changed, said as a result's assumptions: no word is read as another thing
    silently ("read 'kettle' as 'watering can'": a living room's kettle-shaped watering can).

    >>> descriptive_name_notes("put the apple on the island", {"DiningTable", "CounterTop"})
    ["read 'island' as 'dining table'"]
    """
    return [f"read {said!r} as {name!r}" for said, name in _renamed(text, types)[1]]


def _renamed(text: str, types: set[str]) -> tuple[str, list[tuple[str, str]]]:
    """`descriptive_names`, and each (name said, type name written) that changed a word."""
    changed: list[tuple[str, str]] = []
    for name in _names():
        for m in reversed(list(name.pattern.finditer(text))):
            if _inside_longer_name(text, m):
                continue  # "kitchen island": a name of the lexicon's own
            present = [t for t in name.types if t.lstrip("=") in types]
            if not present or present[0].startswith("="):
                continue  # left as said: the grammar and check 1 read or refuse it ("=": as the lexicon does)
            if name.as_said and len(present) > 1:
                continue
            if name.either and len(present) > 1:
                raise HTTError(f"{m['name']!r} could be the {' or the '.join(present)} here; say which")
            written = camel_words(present[0])
            if written != m["name"].lower():
                changed.insert(0, (m["name"], written))
            text = text[: m.start("name")] + written + text[m.end("name") :]
    return text, changed


def _inside_longer_name(text: str, m: re.Match[str]) -> bool:
    """Is the match part of a longer name in the lexicon ("kitchen island")?"""
    return any(
        k.char_start < m.start("name") < k.char_end or k.char_start < m.end("name") < k.char_end
        for k in find_mentions(text)
    )


@cache
def _contents() -> re.Pattern[str]:  # the one list of drinks and food, check 1's too (content_words.txt)
    return re.compile(rf"\b(?:{phrase_category(DRINK_FOOD)})\b", re.I)


def contents_hint(text: str) -> str | None:
    """What a refusal adds where the text names a drink or food, which no floor plan has apart from its
    container (the plan cannot check that the mug holds coffee, so "coffee" stays unread, never dropped)."""
    named = _contents().search(text)
    if named is None:
        return None
    content = " ".join(named[0].lower().split())
    return f"no floor plan has {content} apart from its container: to act on the container, name it alone"
