"""A "... respectively" list pairs its things with its places in turn (`distributed`), before the household
grammar reads: "put the mug and the apple in the sink and the fridge respectively" is "put the mug in the
sink and put the apple in the fridge". A place may keep its own preposition ("on the sofa and in the box,
respectively"). Lists of different lengths are refused by name. "Wash A and B and put them in X and Y
respectively" reaches here as "put the washed A and the washed B in X and Y respectively"
(`household_forms.treated_lists`); a clause of another shape is left as it is, and the grammar and check 1
refuse or name it.

>>> distributed("put the mug and the apple in the sink and the fridge respectively")
'put the mug in the sink and put the apple in the fridge'
>>> distributed("put the mug in the sink")
'put the mug in the sink'
"""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.prepositions import ONE_PLACE, preposition_pattern

_PREP = preposition_pattern(ONE_PLACE)  # the grammar's prepositions of one place each (`prepositions`)
# a clause's verb, its things, a preposition and its places, closing with "respectively"
_LIST = re.compile(
    rf"(?P<verb>\b[a-z]+)\s+(?P<things>[^.;!?]+?)\s+(?P<prep>{_PREP})\s+(?P<places>[^.;!?]+?)"
    r",?\s+respectively\b",
    re.I,
)
LIST_ITEMS = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+", re.I)
_OWN_PREP = re.compile(rf"^{_PREP}\s", re.I)


def distributed(text: str) -> str:
    """`text` with each "... respectively" list written out as one clause per pair (see the module
    docstring); raises HTTError where the two lists differ in length."""
    return _LIST.sub(_pairs, text)


def _pairs(m: re.Match[str]) -> str:
    things, places = LIST_ITEMS.split(m["things"].strip()), LIST_ITEMS.split(m["places"].strip())
    if not all(_names_one(t) for t in things) or not all(_names_one(_OWN_PREP.sub("", p)) for p in places):
        return m[0]  # not a list of things and places: left for the grammar and check 1
    if len(things) != len(places) or len(things) < 2:
        raise HTTError(
            f"'respectively' pairs {len(things)} things with {len(places)} places in {m[0]!r}: "
            "name one place for each thing"
        )
    verb = m["verb"]
    return " and ".join(
        f"{verb} {t} {p}" if _OWN_PREP.match(p) else f"{verb} {t} {m['prep']} {p}"
        for t, p in zip(things, places, strict=True)
    )


def _names_one(item: str) -> bool:
    """Does the item name exactly one thing ("the mug", "a slice of bread"), and nothing else?"""
    return len(find_mentions(item)) == 1
