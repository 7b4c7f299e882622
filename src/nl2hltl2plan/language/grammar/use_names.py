"""Things named by their use (issue 28): "the thing you cook pasta in" is "the pot", "the table you eat at"
"the dining table", "the towel you dry your hands with" "the hand towel", "the cup for coffee" "the mug"
(`use_names.txt`). Only a use the file lists is rewritten, and only after a determiner and one head word
("the thing", "the towel"): "after you eat" or "once you dry your hands" has no determiner before it and
stays; a use the file does not list stays as written, for the grammar to read or refuse by name.

>>> named_by_use("put the sponge in the thing you cook pasta in and the towel you dry your hands with in it")
'put the sponge in the pot and the hand towel in it'
>>> named_by_use("rinse the cup for coffee, then put the cup for the lemonade away")
'rinse the mug, then put the cup for the lemonade away'
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from functools import lru_cache

from nl2hltl2plan.language.grounding import phrase_lines

_DETERMINER = r"(?P<det>\b(?:the|a|an|that|this|my|your))\s+"
_PREPS = r"(?:\s+(?:in|with|at|on|from|for))?"


def _alternatives(uses: Iterable[str]) -> str:
    return "|".join(re.escape(u).replace(r"\ ", r"\s+") for u in sorted(uses, key=len, reverse=True))


@lru_cache(maxsize=1)
def _patterns() -> tuple[re.Pattern[str], re.Pattern[str], dict[str, str]]:
    table = {use: fields[0] for uses, fields in phrase_lines("use_names.txt") for use in uses}
    relative = _alternatives(u for u in table if not u.startswith("for "))
    with_for = _alternatives(u for u in table if u.startswith("for "))
    clause = re.compile(
        rf"{_DETERMINER}[a-z]+\s+(?:(?:that|which)\s+)?(?:you|we|i|people)\s+(?:use\s+to\s+)?(?P<use>{relative})"
        rf"{_PREPS}(?![\w'])",
        re.I,
    )
    purpose = re.compile(rf"{_DETERMINER}[a-z]+\s+(?P<use>{with_for})(?![\w'])", re.I)
    return clause, purpose, table


def named_by_use(text: str) -> str:
    """The text with each thing named by a listed use written as its lexicon name (see above)."""
    clause, purpose, table = _patterns()

    def name(m: re.Match[str]) -> str:
        return f"{m['det']} {table[' '.join(m['use'].lower().split())]}"

    return purpose.sub(name, clause.sub(name, text))
