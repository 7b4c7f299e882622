"""Check 1: a container that the text never says holds anything (issue 23).

A place-in-container reading puts a thing into a container and the container somewhere. The text must say
the container holds the thing: the container named after "in", "into" or "inside" ("put the egg in the
bowl"), named with what it holds ("the pan with the tomato in it", "a mug containing a pencil"), or
referred to as "it" in such a phrase ("take a pan, put the tomato in it, ..."), or named next to the thing
with no other thing between (ALFRED's "put box and keys on the chair", "move the spoon to the pan", "the
fork with the cup"). Otherwise the reading has
invented the containing: "put the tomato in the fridge and the pan in the sink" once read (learned
re-read, exit 0) as the tomato in the pan and the pan in the fridge, the sink dropped, because "the pan in
the sink" also reads as where the pan is.

>>> from nl2hltl2plan.language.grounding import find_mentions
>>> text = "put the tomato in the fridge and the pan in the sink"
>>> said_as_container(text, [m for m in find_mentions(text) if m.surface == "pan"])
False
>>> text = "put the tomato in a pan and put the pan in the fridge"
>>> said_as_container(text, [m for m in find_mentions(text) if m.surface == "pan"])
True
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import cache
from pathlib import Path

from nl2hltl2plan.language.content_words import Unread
from nl2hltl2plan.language.grounding import Mention
from nl2hltl2plan.language.parse_usage import ParseUsage

# the words a container's name may follow when it is said to hold something, with up to two words between
# ("in the small bowl", "into a clean mug", "on a plate")
_INTO_BEFORE = re.compile(r"\b(?:in|into|inside|within|in\s+to|on|onto)\s+(?:\S+\s+){0,2}$", re.IGNORECASE)
# the words after a container's name that say what it holds ("the pan with the tomato", "a mug holding ...")
_HOLDING_AFTER = re.compile(
    r"^\s*(?:with|containing|holding|carrying|(?:that|which)(?:'s|\s+is|\s+has|\s+holds|\s+contains))\b",
    re.IGNORECASE,
)
# "put the tomato in it", "take a dish to the table to put the tissue box on it": a container said by a
# pronoun
_INTO_IT = re.compile(r"\b(?:in|into|inside|on|onto)\s+(?:it|them)\b", re.IGNORECASE)


def said_as_container(
    instruction: str, said: Sequence[Mention], held: Sequence[Mention] = (), every: Sequence[Mention] = ()
) -> bool:
    """Is one of the mentions `said` (of a container's type) said to hold something? `held`: the mentions
    of the thing it holds; `every`: all mentions of the text (`_next_to`)."""
    if said and _INTO_IT.search(instruction):
        return True
    return any(
        _INTO_BEFORE.search(instruction[: m.char_start])
        or _HOLDING_AFTER.match(instruction[m.char_end :])
        or any(_next_to(instruction, m, h, every) for h in held)
        for m in said
    )


def _next_to(instruction: str, container: Mention, thing: Mention, every: Sequence[Mention]) -> bool:
    """Are the container and the thing named next to each other: at most four words between, no other
    thing and no sentence end?"""
    first, second = sorted((container, thing), key=lambda m: m.char_start)
    start, end = first.char_end, second.char_start
    between = instruction[start:end]
    other = any(start <= m.char_start < end for m in every)
    return not other and len(between.split()) <= 4 and re.search(r"[.;!?]", between) is None


def unsaid_containers(instruction: str, mentions: Sequence[Mention], parse: ParseUsage) -> list[Unread]:
    """An `Unread` for each container of a place-in-container task that the text never says holds anything
    (see the module docstring); a container not named at all is `unfilled_slots`' or the noun check's."""
    out: list[Unread] = []
    for task in parse.tasks:
        types = set(task.container or []) if task.kind == "place_in_container" else set()
        said = [m for m in mentions if types & set(m.entry.types)]
        held = [m for m in mentions if set(task.object) & set(m.entry.types)]
        if said and not said_as_container(instruction, said, held, mentions):
            why = f"a thing is put in the {said[0].surface}, which the text never says holds anything"
            out.append(Unread(said[0].surface, "object", why))
    return out


@cache
def _vessels() -> frozenset[str]:
    lines = Path(__file__).with_name("measure_vessels.txt").read_text(encoding="utf-8").splitlines()
    return frozenset(w for line in lines if not line.startswith("#") for w in line.split())


def held_content(vessel_said: Mention, content: Mention) -> bool:
    """Whether "VESSEL of CONTENT" names two things: a vessel of measure_vessels.txt and what it holds, of
    types the vessel's name never has ("a glass of wine", "a bowl of apples"; not "two bottles of lotion").

    >>> from nl2hltl2plan.language.grounding import find_mentions
    >>> held_content(*find_mentions("a glass of wine")), held_content(*find_mentions("a mug of cups"))
    (True, False)
    """
    said = vessel_said.surface.lower().split()[-1]
    return said in _vessels() and not set(vessel_said.entry.types) & set(content.entry.types)


def vessel(word: str) -> bool:
    """Whether `word` (lower case) names a vessel of measure_vessels.txt: what follows its "of" is held in
    it ("a glass of wine"), never where something is."""
    return word in _vessels()
