"""Forms of a household (ALFRED) instruction written out as the forms the shared grammar reads, before it
reads (the household reader's `prepared`); each rewrite keeps every word that names a thing, a place or
an action, and applies only where its parts name what it needs:

- a list of things and places with colons (`paired`): "mug: sink; apple: fridge" is "mug -> sink,
  apple -> fridge", which the grammar reads as it reads arrows ("green apple -> blue plate"); each side of
  a colon names one thing or place, so a label ("Task: ...", "Note: ...") is left as it is;
- a thing asked as a topic, then what to do with it (`topic_said`): "The mug? Heat it and put it in the
  sink." is "Heat the mug and put it in the sink." (the question names one thing and nothing else, and the
  sentence after it says "it" or "them"); "The mug in the sink - wash it ..." is "Wash the mug in the sink
  ..." (a thing and where it is, set off by a dash or a colon, before a verb on "it");
- a treatment and a "respectively" list after it (`treated_lists`): "wash the mug and the plate and put
  them in the sink and the cabinet respectively" is "put the washed mug and the washed plate in the sink
  and the cabinet respectively", which `respectively.distributed` writes out pair by pair.

>>> paired("mug: sink; apple: fridge")
'mug -> sink, apple -> fridge'
>>> topic_said("The mug? Heat it and put it in the sink.")
'Heat the mug and put it in the sink.'
>>> topic_said("The mug in the sink - wash it and put it in the cabinet.")
'Wash the mug in the sink and put it in the cabinet.'
>>> treated_lists("rinse the mug and the plate and put them in the sink and the cabinet respectively")
'put the rinsed mug and the rinsed plate in the sink and the cabinet respectively'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import stems
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS, VERBS
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.respectively import LIST_ITEMS

_NP = r"(?:(?:the|a|an|my|your|this|that)\s+)?[a-z]+(?:\s+[a-z]+){0,2}"
# "mug: sink" between list separators (a colon that opens a clause, "Task: put ...", has a verb after it,
# and its sides are not one thing and one place)
_PAIR = re.compile(
    rf"(?P<lead>^|[,;]\s*|\b(?:and|then)\s+)(?P<thing>{_NP})\s*:\s*(?P<place>{_NP})"
    r"(?=\s*(?:[,;.!]|\band\b|\bthen\b|$))",
    re.I,
)
_SEPARATOR = re.compile(r"\s*;\s*")
# "The mug?", "what about the mug?", "as for the apple?" opening the text or a sentence
_TOPIC = re.compile(
    rf"(?P<lead>^|(?<=[.!?])\s+)(?:(?:and|what\s+about|how\s+about|as\s+for)\s+)?(?P<np>{_NP})\s*\?\s+"
    r"(?P<next>[^.!?]*\b(?:it|them)\b)",
    re.I,
)
_PRONOUN = re.compile(r"\b(?:it|them)\b", re.I)
# "The apple in the microwave - slice it, ...": a thing and where it is, set off by a dash or a colon, then a
# verb of the grammar on "it" (h261); its place is where it is found, never a step ("put it in the microwave")
_PLACED_TOPIC = re.compile(
    r"(?P<lead>^|(?<=[.!?])\s+)(?P<np>(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)\s+"
    r"(?P<where>(?:in|on|inside|from)\s+the\s+[a-z]+(?:\s+[a-z]+)?)\s*(?:\s[-\u2013\u2014]+|:)\s*"
    r"(?P<verb>[a-z]+)\s+(?:it|them)\b",
    re.I,
)


def _participles() -> dict[str, str]:
    """Each treatment verb of the grammar -> the participle the grammar reads as that treatment's state
    ("wash" -> "washed": `word_tables.VERBS` and `STATE_WORDS`, the one table of both); an "-ed" form
    before a bare one ("warmed", not "warm")."""
    out = {}
    for done in sorted(STATE_WORDS, key=lambda w: w.endswith("ed")):  # the "-ed" forms last: they stay
        for verb in stems(done):
            if VERBS.get(verb) == (STATE_WORDS[done], verb):
                out[verb] = done
    return out


PARTICIPLES = _participles()
# a treatment of its things, then a placement of "them" closing with "respectively"
_TREATED = re.compile(
    rf"\b(?P<verb>{'|'.join(PARTICIPLES)})(?:\s+up)?\s+(?P<things>[^.;!?]+?)\s*,?\s+and\s+(?:then\s+)?"
    r"(?P<put>put|place|set|move|leave|store)\s+them\s+(?P<places>[^.;!?]+?,?\s+respectively)\b",
    re.I,
)
_DETERMINER = re.compile(r"^(?P<det>(?:the|a|an|my|your|both|two)\s+)?", re.I)


def household_forms(text: str) -> str:
    """`text` with each form above written out as the grammar reads it."""
    return treated_lists(topic_said(paired(text)))


def paired(text: str) -> str:
    """Colon pairs of one thing and one place, "mug: sink; apple: fridge", as arrows; else `text`."""
    pairs = list(_PAIR.finditer(text))
    if not pairs or not all(_one_thing(m["thing"]) and _one_thing(m["place"]) for m in pairs):
        return text
    text = _PAIR.sub(lambda m: f"{m['lead']}{m['thing']} -> {m['place']}", text)
    return _SEPARATOR.sub(", ", text)


def topic_said(text: str) -> str:
    """ "The mug? Heat it ..." as "Heat the mug ..."; else `text`."""

    def said(m: re.Match[str]) -> str:
        if not _one_thing(m["np"]):
            return m[0]
        np = m["np"] if _DETERMINER.match(m["np"])["det"] else f"the {m['np']}"  # type: ignore[index]
        rest = _PRONOUN.sub(np.lower(), m["next"], count=1)
        return f"{m['lead']}{rest[0].upper()}{rest[1:]}"

    def placed(m: re.Match[str]) -> str:
        if m["verb"].lower() not in VERBS or not (_one_thing(m["np"]) and _one_thing(m["where"])):
            return m[0]
        return f"{m['lead']}{m['verb'].capitalize()} {m['np'].lower()} {m['where']}"

    return _PLACED_TOPIC.sub(placed, _TOPIC.sub(said, text))


def treated_lists(text: str) -> str:
    """ "wash A and B and put them in X and Y respectively" as "put the washed A and the washed B in X
    and Y respectively"; else `text`."""

    def said(m: re.Match[str]) -> str:
        things = LIST_ITEMS.split(m["things"].strip())
        if len(things) < 2 or not all(_one_thing(t) for t in things):
            return m[0]
        done = PARTICIPLES[m["verb"].lower()]
        treated = [_DETERMINER.sub(lambda d: f"{d['det'] or 'the '}{done} ", t, count=1) for t in things]
        return f"{m['put']} {' and '.join(treated)} {m['places']}"

    return _TREATED.sub(said, text)


def _one_thing(phrase: str) -> bool:
    """Does the phrase name exactly one thing or place of the lexicon ("the mug", "coffee machine")?"""
    named = find_mentions(phrase)
    return len(named) == 1 and not named[0].entry.generic
