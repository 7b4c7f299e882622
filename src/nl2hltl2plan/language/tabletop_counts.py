"""Plates said in number in the tabletop world (issue 28).

Counts said of a plate: "two for the yellow plate", "the yellow plate's two", "the yellow plate gets two
things". Such a count says how many placements go on that plate; the pairs reading
(`tabletop_pairs.read_pairs`) takes it out of the words it reads and keeps the reading only where the
placements it pairs on that plate are that many (else the count is not understood: refused).

The count stands beside the plate with nothing but a noun for things between ("two things for", "two
for", "'s two", "gets two (things)"); a count beside an object's name ("two green apples") is another
matter, left to the plural and count rules.

A clause that counts the placements and names nothing ("- those four placements, that's all", "Four
placements in all.", "just those three, that's it") says how many there are in all: it is read where the
reading pairs that many (`total_counts_read`), refused otherwise.

"The plates" with no colour or count before it ("Grocery list for the plates:", "brought to you by
plates") are, in this world, the plates that the reading pairs things with, each of which it has by name
(`plates_said_alone`).

>>> import re
>>> plate = re.compile(r"\\b(?:yellow|blue) plate\\b")
>>> plate_counts_read("two for the yellow plate (green apple, orange)", plate)
('for the yellow plate (green apple, orange)', [('yellow plate', 2)])
>>> plate_counts_read("the yellow plate's two go before the blue plate's two", plate)
('the yellow plate go before the blue plate', [('yellow plate', 2), ('blue plate', 2)])
"""

from __future__ import annotations

import re
from collections.abc import Callable

_COUNTS = {"one": 1, "two": 2, "three": 3, "four": 4}
_COUNT = r"(?P<count>one|two|three|four)"
_THINGS = r"(?:\s+(?:things?|items?|objects?|fruits?|pieces?|ones|placements?))?"
_GETS = r"(?:gets|takes|holds|receives|has)"


def plate_counts_read(text: str, plate: re.Pattern[str]) -> tuple[str, list[tuple[str, int]]]:
    """`text` without the counts said of a plate (see the module docstring), and each as (the plate in
    words, the count); `plate` finds a plate's name."""
    claims: list[tuple[str, int]] = []
    name = rf"(?P<plate>{plate.pattern})"

    def taken(kept: str) -> Callable[[re.Match[str]], str]:
        def read(m: re.Match[str]) -> str:
            claims.append((" ".join(m["plate"].split()), _COUNTS[m["count"]]))
            return m.expand(kept)

        return read

    text = re.sub(rf"\b{_COUNT}{_THINGS}\s+(?=(?:for|on|onto|to)\s+(?:the\s+)?{name})", taken(""), text)
    text = re.sub(rf"{name}'s\s+{_COUNT}{_THINGS}\b", taken(r"\g<plate>"), text)  # PLATE's two
    gets = rf"{name}\s+(?P<gets>{_GETS})\s+{_COUNT}{_THINGS}\b(?:\s*,)?"  # PLATE gets two things, ...
    return re.sub(gets, taken(r"\g<plate> \g<gets>"), text), claims


_CLOSING_COUNT = re.compile(
    r"(?:^|(?<=[.;!?:,-]))\s*(?:(?:and\s+)?(?:just|only)\s+)?(?:(?:those|these|the)\s+)?"
    rf"{_COUNT}{_THINGS}(?:\s+(?:in\s+(?:all|total)|altogether|all\s+told|total))?"
    r"(?:\s*,?\s*(?:that's|that\s+is|thats)\s+(?:all|it)|\s*,?\s*nothing\s+(?:more|else))?\s*(?=[.;!?]|$)"
)


def total_counts_read(text: str) -> tuple[str, list[int]]:
    """`text` without the clauses that count the placements in all (see the module docstring), and each
    count they say."""
    counts = [_COUNTS[m["count"]] for m in _CLOSING_COUNT.finditer(text)]
    return _CLOSING_COUNT.sub(" ", text), counts


def plates_said_alone(text: str, kinds: dict[str, bool]) -> str:
    """`text` without "plates" said with no colour or count before it (see the module docstring); `kinds`:
    each name in words -> is it a plate."""
    modifiers = {w for name, plate in kinds.items() if plate for w in name.split()[:-1]}

    def dropped(m: re.Match[str]) -> str:
        counted = m["before"] in modifiers or m["before"] in _COUNTED_BY or m["before"].isdigit()
        return m[0] if counted else m["before"]

    return re.sub(r"\b(?P<before>[\w']+)\s+plates\b", dropped, text)


_COUNTED_BY = frozenset("one two three four five both all many several some few these those".split())
