"""Words of a household (ALFRED) instruction that name a thing by what it is or holds, read with the
floor plan's types before the grammar reads (the household reader's `prepared`; the data and where it
comes from are in household_names.txt):

- a descriptive name of a receptacle ("the island", "the nightstand", "the entertainment center", "the
  vanity") is the first of its types that the floor plan has, written as that type's name; a name whose
  types the floor plan has two or more of, where they differ (`: either`), is refused by name;
- a drink or food named with its container is the container ("a cup of coffee", "heat up coffee in a mug"):
  no floor plan has coffee apart from the mug, so the mug is what is moved, heated or chilled, and the
  reader says so (`Contents.notes`); one named with no container is left for check 1, which refuses it,
  and the refusal asks for the container (`Contents.hint`).

>>> descriptive_names("put the apple on the island", {"DiningTable", "CounterTop"})
'put the apple on the dining table'
>>> said = Contents.read("heat up coffee in a mug and put it in the cabinet")
>>> said.text
'heat up a mug and put it in the cabinet'
>>> said.notes[0]
"'coffee in a mug' is read as the mug: no floor plan has coffee apart from its container"
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cache

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grounding import camel_words, find_mentions, phrase_lines

_PREPOSITIONS = {"in": r"(?:in|into|inside|in\s+to)", "on": r"(?:on|onto|on\s+top\s+of|upon)"}


@dataclass(frozen=True)
class _Name:
    pattern: re.Pattern[str]
    types: tuple[str, ...]
    either: bool


@cache
def _names() -> tuple[_Name, ...]:
    out = []
    for names, fields in phrase_lines("household_names.txt"):
        if fields[0] in ("contents", "holders"):
            continue
        for name in names:
            prep, _, words = name.rpartition(":")
            said = r"\s+".join(map(re.escape, words.split()))
            lead = rf"\b{_PREPOSITIONS[prep]}\s+(?:(?:the|a|an|your|my)\s+)?" if prep else ""
            pattern = re.compile(rf"{lead}(?<![\w-])(?P<name>{said})(?![\w-])", re.I)
            out.append(_Name(pattern, tuple(fields[0].split()), "either" in fields[1:]))
    return tuple(out)


def descriptive_names(text: str, types: set[str]) -> str:
    """`text` with each descriptive name written as the name of the type it is in a floor plan of `types`
    (see the module docstring); raises HTTError naming the types where the name could be several."""
    for name in _names():
        for m in reversed(list(name.pattern.finditer(text))):
            if _inside_longer_name(text, m):
                continue  # "kitchen island": a name of the lexicon's own
            present = [t for t in name.types if t in types]
            if not present:
                continue  # left as it is: the grammar and check 1 read or refuse it
            if name.either and len(present) > 1:
                raise HTTError(f"{m['name']!r} could be the {' or the '.join(present)} here; say which")
            text = text[: m.start("name")] + camel_words(present[0]) + text[m.end("name") :]
    return text


def _inside_longer_name(text: str, m: re.Match[str]) -> bool:
    """Is the match part of a longer name in the lexicon ("kitchen island")?"""
    return any(
        k.char_start < m.start("name") < k.char_end or k.char_start < m.end("name") < k.char_end
        for k in find_mentions(text)
    )


@cache
def _words(kind: str) -> tuple[str, ...]:
    return tuple(
        n for names, fields in phrase_lines("household_names.txt") for n in names if fields[0] == kind
    )


@cache
def _content_patterns() -> tuple[re.Pattern[str], re.Pattern[str], re.Pattern[str]]:
    contents = "|".join(re.escape(w).replace(r"\ ", r"\s+") for w in _words("contents"))
    temperature = r"(?:(?:hot|cold|warm|iced|fresh|some)\s+)?"
    holders = "|".join(re.escape(w).replace(r"\ ", r"\s+") for w in _words("holders"))
    holder = rf"(?:a|an|the|one|your|my)\s+(?:[a-z]+\s+)?(?:{holders})s?\b"
    of = re.compile(rf"(?P<holder>{holder})\s+of\s+{temperature}(?P<content>{contents})\b", re.I)
    # after a treatment only: "put the juice in a glass" is pouring it there
    treated_in = re.compile(
        rf"(?P<verb>\b(?:heat|warm|reheat|microwave|cool|chill|refrigerate)(?:\s+up)?\s+)(?:the\s+)?{temperature}"
        rf"(?P<content>{contents})\s+in\s+(?P<holder>{holder})",
        re.I,
    )
    alone = re.compile(rf"\b(?:{contents})\b", re.I)
    return of, treated_in, alone


@dataclass
class Contents:
    """An instruction with its drinks and foods read as their containers, and what the reader says of it."""

    text: str
    notes: list[str] = field(default_factory=list)

    @classmethod
    def read(cls, text: str) -> Contents:
        of, treated_in, _ = _content_patterns()
        said = cls(text)
        said.text = of.sub(said._holder, treated_in.sub(said._holder, text))
        return said

    def _holder(self, m: re.Match[str]) -> str:
        named = find_mentions(m["holder"])
        if len(named) != 1:  # "a red glass" is one thing; "the fridge cup" is not said so
            return m[0]
        said = m[0][len(m.groupdict().get("verb") or "") :]
        content = " ".join(m["content"].lower().split())
        where = f"no floor plan has {content} apart from its container"
        self.notes.append(f"{said!r} is read as the {named[0].surface}: {where}")
        return f"{m.groupdict().get('verb') or ''}{m['holder']}"

    @staticmethod
    def hint(text: str) -> str | None:
        """What a refusal adds where the text names a drink or food with no container."""
        named = _content_patterns()[2].search(text)
        if named is None:
            return None
        content = named[0].lower()
        return f"no floor plan has {content!r} apart from its container: name it ('a mug of {content}')"
