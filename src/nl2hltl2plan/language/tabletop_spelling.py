"""Misspelt names and order words in the tabletop world (issue 28): "the grean aple on the pinc plate",
"frist ... , than ...".

The shared respelling (`language.spelling.respelt`) writes a misspelt name as the ALFRED lexicon writes it
and respells an order word only where no other English word is one edit away. The tabletop world has nine
name words and one order form (groups of placements in turn), so it takes the shared respelling's world
option (`spelling.closed_respelt`) with its own words:

- a word of four letters or more that English does not know and that is one edit (a letter more, less or
  changed, or two neighbours swapped) from exactly one word of the world's names is that word ("aple",
  "grean", "pinc", "grren"), and so is two neighbours swapped in a name word, which English may know as a
  rare word ("appel");
- such a word one edit from exactly one order word is that word ("frist", "thne", "befor"); one near two
  order words is left as written, and `misspelt_order_words` names it, so that a reading that passes over
  it is refused (it may say an order);
- "than" that opens a clause (after a comma, "and", or at a sentence's start) is "then": a comparison's
  "than" never stands there ("..., than the carrot on the blue plate").

>>> order_words_spelt("frist the orange on the yellow plate, than the carrot on the blue plate")
'first the orange on the yellow plate, then the carrot on the blue plate'
>>> names_respelt("the grean aple on the pinc plate", {"green apple": False, "pink plate": True})
'the green apple on the pink plate'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.spelling import closed_near, closed_respelt

# the order words of the tabletop reading (groups in turn) that a misspelling may stand for
_ORDER_WORDS = frozenset(
    "first then after afterwards before next once finally lastly second third fourth later start "
    "begin".split()
)
_WORD = re.compile(r"(?<![A-Za-z'])[A-Za-z]{4,}(?![A-Za-z'])")
_CLAUSE_THAN = re.compile(r"(?:(?<=[,;:.!?]\s)|(?<=\band\s)|^)(?P<than>[Tt]han)\b")


def names_respelt(text: str, kinds: dict[str, bool]) -> str:
    """`text` with each misspelling of one of the world's name words written as the world writes it;
    `kinds`: each name in words -> is it a plate."""
    return closed_respelt(text, frozenset(w for name in kinds for w in name.split()))


def order_words_spelt(text: str) -> str:
    """`text` with each misspelt order word written right, and a clause-opening "than" as "then"."""
    spelt = closed_respelt(text, _ORDER_WORDS)
    return _CLAUSE_THAN.sub(lambda m: "Then" if m["than"][0] == "T" else "then", spelt)


def misspelt_order_words(text: str) -> list[str]:
    """The words of `text` that may misspell an order word and were left as written (near two of them):
    the order they may say is not guessed."""
    return [m[0] for m in _WORD.finditer(text) if closed_near(m[0], _ORDER_WORDS)]
