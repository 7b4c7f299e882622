"""Negations said in other words, written as the "don't" / "do not" the negation reader reads (`negations`),
before the household grammar reads: "Instead of putting the mug in the sink, put it ..." (`instead_said`) and
a treatment not to be done, "... without washing it", "..., no need to wash it" (`untreated_said`)."""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import categories, stems
from nl2hltl2plan.language.grounding import find_mentions

# "Instead of putting the mug in the sink, put it in the fridge": the grammar read "in the sink" as
# washing (clean_place Mug -> Fridge, exit 0); said as the negation it is: "don't put the mug in ...". h208
_INSTEAD_OF_DOING = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?:instead\s+of|rather\s+than)\s+(?P<verb>[a-z]+ing)\b(?=[^.;!?,]*,\s*\w)", re.I
)


def instead_said(text: str) -> str:
    """`text` with a sentence that opens "instead of / rather than" and an action word ending in -ing said as
    "don't" and the action (the household reader's `as_read`); any other opening stays as said.

    >>> instead_said("Instead of putting the mug in the sink, put it in the fridge.")
    "don't put the mug in the sink, put it in the fridge."
    """

    def negated(m: re.Match[str]) -> str:
        verb = _verb_said(m["verb"])
        lead = m[0][: len(m[0]) - len(m[0].lstrip())]
        return f"{lead}don't {verb}" if verb else m[0]

    text = _SET_OFF_NOT_WANTED.sub(lambda m: f" {m['rest'].strip()} instead of {m['np']}", text)
    return _PLACE_NOT_WANTED.sub(" instead of ", _INSTEAD_OF_DOING.sub(negated, text))


# "put the book on the desk rather than on the bed" / "instead of on the bed" / "in place of the bed": the
# grammar took the place not wanted as the task's (place Book -> Bed, exit 0, h297); said as "instead of the
# bed", which it reads as the contrast it is. Inside a sentence only: a sentence that opens so is a swap
# (`negations.exclusions_unread`) or an action not to do (`_INSTEAD_OF_DOING`).
_PLACE_NOT_WANTED = re.compile(
    r"(?<![.;!?,])\s+(?:rather\s+than|instead\s+of|in\s+place\s+of)\s+(?:on|in|into|onto|inside|to)\s+(?=(?:the|a|an)\s)"
    r"|(?<![.;!?,])\s+in\s+place\s+of\s+(?=(?:the|a|an)\s)"
    # (and "rather than the pencil" with no preposition: the thing or place not wanted, h299)
    # ("rather than the black one" stays as said: `vague_words` names it in the user's words)
    r"|(?<![.;!?,])\s+rather\s+than\s+(?=(?:the|a|an|my|your)\s)(?!\w+\s+\w+\s+ones?\b)",
    re.I,
)
# "put the mug, rather than the pot, in the sink": the thing not wanted set off by commas, which the grammar
# read as a second thing to put there (place Pot too, exit 0, h299); said after the place, as the contrast
_SET_OFF_NOT_WANTED = re.compile(
    r"\s*,\s*(?:rather\s+than|instead\s+of|in\s+place\s+of)\s+"
    r"(?P<np>(?:the|a|an|my|your)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s*,\s*(?P<rest>[^.;!?,]+)",
    re.I,
)


def _verb_said(word: str) -> str | None:
    """The one verb an -ing form says ("putting": "put"); the -ing form itself is a verb too (`categories`
    stems it)."""
    said = word.lower()
    verbs = [v for v in sorted(stems(said) - {said}) if any(c.startswith("verb_") for c in categories(v))]
    return verbs[0] if len(verbs) == 1 else None


# "Put the mug in the sink without washing it / , no need to wash it / , you don't need to wash it": a
# treatment not to do, which the grammar left unread (refused); said as the ban it is, on the one thing of
# its one-clause sentence: ". Do not wash the mug."
_UNTREATED = re.compile(
    r"(?P<clause>(?:^|(?<=[.;!?]))[^.;!?,]+?)\s*(?:,\s*|\s+)(?:(?:there's\s+)?no\s+need\s+to|(?:you\s+)?"
    r"(?:don't|do\s+not)\s+(?:need|have)\s+to|without)\s+(?P<verb>[a-z]+)\s+(?:it|them)(?:\s+first)?(?=\s*(?:[.;!?]|$))",
    re.I,
)
_TREATMENTS = frozenset({"verb_heat_place", "verb_cool_place", "verb_clean_place", "verb_sliced"})


def untreated_said(text: str) -> str:
    """`text` with a treatment said not to be done to the one thing its sentence names as a ban of its own
    (the household reader's `as_read`); a sentence of more clauses or things stays as said.

    >>> untreated_said("Put the mug in the sink without washing it.")
    'Put the mug in the sink. Do not wash the mug.'
    """

    def banned(m: re.Match[str]) -> str:
        verb = _verb_said(m["verb"]) if m["verb"].lower().endswith("ing") else m["verb"].lower()
        named = [n for n in find_mentions(m["clause"].lower()) if not n.entry.generic]
        if not verb or not categories(verb) & _TREATMENTS or len(named) != 2 or " and " in m["clause"]:
            return m[0]
        return f"{m['clause']}. Do not {verb} the {named[0].surface}"

    return _UNTREATED.sub(banned, text)


# "keep your hands off the vases", "hands off the watch", "stay away from the candles": a ban on touching the
# thing said with no negation word, which no rule read (trust_h311dev: the key chain put in the box at exit 0,
# the ban dropped); said as the "don't touch" it is, where the lexicon names the one thing
_HANDS_OFF = re.compile(
    r"(?P<lead>^|(?<=[.;!?,])\s*|(?<=\band\s)|(?<=\bbut\s)|(?<=\bplease\s))(?:(?:keep|take|get)\s+your\s+hands\s+"
    r"off|hands\s+off|(?:stay|keep)\s+away\s+from)(?:\s+of)?\s+(?P<x>(?:the|a|an|both|all\s+the|my|your)\s+[a-z]+"
    r"(?:\s+[a-z]+)?)(?=\s*(?:[.;!?,]|$|(?:and|but|then|while|please)\b))",
    re.I,
)


def untouched_said(text: str) -> str:
    """`text` with a ban on touching a thing said without a negation word as "don't touch" the thing (the
    household reader's `as_read`), where the lexicon names exactly the words after it.

    >>> untouched_said("Put the key chain in the box but keep your hands off the vases.")
    "Put the key chain in the box but don't touch the vases."
    """

    def banned(m: re.Match[str]) -> str:
        return f"{m['lead']}don't touch {m['x']}" if names_one_thing(m["x"]) else m[0]

    return _HANDS_OFF.sub(banned, text)


def names_one_thing(phrase: str) -> bool:
    """Whether the lexicon names exactly one thing in `phrase`, and nothing follows it ("the vases"; not
    "the vases and the mug", not "the mug of the day"): the object a ban said without "don't" is about.

    >>> names_one_thing("the vases"), names_one_thing("the mug and the cup")
    (True, False)
    """
    named = find_mentions(phrase.lower())
    return len(named) == 1 and not phrase.lower()[named[0].char_end :].strip()
