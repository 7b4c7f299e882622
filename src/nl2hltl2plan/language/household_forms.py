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
  and the cabinet respectively", which `respectively.distributed` writes out pair by pair;
- a story's or a commentator's narration of the robot's actions (`narrated`): "Once upon a time, a little
  robot put a pen in a bowl and carried the bowl to the desk." is "put a pen in a bowl and carry the bowl
  to the desk." The message is the request, and the robot it tells of is its listener (docs/language.md,
  "Narration"); only a verb the grammar reads is said in its base form, and only where the robot ("it")
  is its subject or it goes on the robot's list of actions ("..., and laid it on the shelf").

>>> paired("mug: sink; apple: fridge")
'mug -> sink, apple -> fridge'
>>> topic_said("The mug? Heat it and put it in the sink.")
'Heat the mug and put it in the sink.'
>>> topic_said("The mug in the sink - wash it and put it in the cabinet.")
'Wash the mug in the sink and put it in the cabinet.'
>>> treated_lists("rinse the mug and the plate and put them in the sink and the cabinet respectively")
'put the rinsed mug and the rinsed plate in the sink and the cabinet respectively'
>>> narrated("Once upon a time, a little robot put a pen in a bowl and carried the bowl to the desk.")
'put a pen in a bowl and carry the bowl to the desk.'
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import NamedTuple

from nl2hltl2plan.language.content_words import phrase_list_pattern, stems, word_categories
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS, VERBS
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.respectively import LIST_ITEMS
from nl2hltl2plan.language.spelling import english_lemmas

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
    return treated_lists(topic_said(paired(narrated(text))))


class _Narration(NamedTuple):
    teller: re.Pattern[str]  # the robot as a verb's subject ("a little robot tiptoed", "the robot takes")
    subject: re.Pattern[str]  # the robot or "it" as the subject of a verb before its object
    on_list: re.Pattern[str]  # a verb on the doer's list after "and", "then", a comma, before its object
    opening: re.Pattern[str]  # a story's opening ("Once upon a time, ...")
    asking: frozenset[str]  # a word before the doer that makes it no narration ("could the robot put")
    tutor: re.Pattern[str]  # a tutorial's "then we hold ...", "now I take ..." (a verb in its base form)


@lru_cache(maxsize=1)
def _narration() -> _Narration:
    w = word_categories("narration_words.txt")
    doer = rf"(?:a|an|the|our|my|this|that|its|your)\s+(?:[a-z]+\s+){{0,2}}?(?:{'|'.join(sorted(w['doer']))})"
    between = rf"(?P<between>(?:{'|'.join(sorted(w['between']))})\s+)?"
    # (what the robot is about to do: "our robot is going to take ...", "the robot will put ...")
    between += r"(?:(?:is|are)\s+(?:going\s+to|gonna|about\s+to)\s+|will\s+|['’]ll\s+)?"
    pronoun = "|".join(sorted(w["pronoun"]))
    thing = r"(?=(?:\s+(?:up|down|on|off|out|away|back))?\s+(?:the|a|an|one|two|three|some|both|another|its|"
    thing += r"his|her|it|them|that|this|those|\d+)\b)"
    lead = r"(?P<lead>(?:\band|\bthen|,|\blast|\bfinally|\bnext)\s+(?:(?:then|last\s+of\s+all|finally)\s+)?)"
    opening = phrase_list_pattern("narration_words.txt", "opening")
    tutor_after = "|".join(sorted(w["tutor_after"]))
    return _Narration(
        re.compile(rf"(?i)\b{doer}\s+{between}(?P<verb>[a-z]+)\b"),
        re.compile(rf"(?i)\b(?:{doer}|{pronoun})\s+{between}(?P<verb>[a-z]+)\b{thing}"),
        re.compile(rf"(?i){lead}(?P<verb>[a-z]+)\b{thing}"),
        re.compile(rf"(?i)(?:^|(?<=[.!?])\s+)(?:and\s+)?(?:{opening}\b\s*,?\s*)+"),
        w["asking"],
        re.compile(rf"(?i)\b(?P<lead>(?:{tutor_after})\s+)(?:{'|'.join(sorted(w['tutor']))})\s+(?P<verb>[a-z]+)\b{thing}"),
    )


def _action(verb: str) -> str | None:
    """The base form of a narrated verb of a task the grammar reads ("carried" -> "carry", "takes" ->
    "take", "put" -> "put"), or None (a verb of no task: "slept", "lived"; a word of no verb)."""
    word = verb.lower()
    for base in (word, *english_lemmas(word).get("VERB", ())):
        if VERBS.get(base, ("other",))[0] != "other" and VERBS[base][1] == base:
            return base
    return None


def _finite(verb: str) -> bool:
    """Whether a word after the robot may be a verb's past or present tense: "tiptoed", "takes", "put"."""
    word = verb.lower()
    return _action(word) is not None or any(lemma != word for lemma in english_lemmas(word).get("VERB", ()))


def _told(text: str, m: re.Match[str]) -> bool:
    """Whether the doer of `m` tells of an action, not one asked for ("could the robot put ...") or set as
    a time or a condition ("after it washed ...")."""
    before = re.findall(r"[a-z]+", text[: m.start()].lower())[-1:]
    return not set(before) & _narration().asking


def _past(verb: str) -> bool:
    """Whether a word after "it" is the past tense of a task's verb ("it washed a bar of soap"): a story
    that tells of its robot as "it" alone ("The little robot tiptoed in." is dropped as frame first)."""
    word = verb.lower()
    return _action(word) is not None and word not in VERBS and not word.endswith("s")


def _tutored(m: re.Match[str]) -> str:
    """A tutorial's "then we hold ..." as "then hold ..." (only a verb's base form: "I took" is a report)."""
    return m["lead"] + m["verb"] if _action(m["verb"]) == m["verb"].lower() else m[0]


def narrated(text: str) -> str:
    """A narration of the robot's actions ("a robot put ... and carried ...", "the robot takes ..., sets it
    down ...") and a tutorial's own steps ("then we hold ...") as the commands they tell of; else `text`. A
    message is a narration when the robot (a noun phrase ending in "robot") is the subject of a verb in its
    past or present tense ("tiptoed", "takes")."""
    n = _narration()
    text = n.tutor.sub(_tutored, text)
    told = any(_finite(m["verb"]) and _told(text, m) for m in n.teller.finditer(text))
    if not (told or any(_past(m["verb"]) and _told(text, m) for m in n.subject.finditer(text))):
        return text

    def said(m: re.Match[str]) -> str:
        base = _action(m["verb"])
        return m[0] if base is None or not _told(text, m) else (m["between"] or "") + base

    def listed(m: re.Match[str]) -> str:
        base = _action(m["verb"])
        return m[0] if base is None else m["lead"] + base

    return n.on_list.sub(listed, n.subject.sub(said, n.opening.sub(" ", text))).strip()


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
