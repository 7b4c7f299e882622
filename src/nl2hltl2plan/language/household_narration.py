"""A story's or a commentator's narration of the robot's actions, read as the commands it tells of (h295,
issue 28; the first of the household forms, `household_forms`): "Once upon a time, a little robot put a
pen in a bowl and carried the bowl to the desk." is "put a pen in a bowl and carry the bowl to the desk."
The message is the request, and the robot it tells of is its listener (docs/language.md, "Narration");
only a verb the grammar reads is said in its base form, and only where the robot ("it") is its subject or
it goes on the robot's list of actions ("..., and laid it on the shelf"). A tutorial's own steps in the
present tense after an order word ("then we hold the box under the lamp") are its commands too. The words
are `narration_words.txt`'s.

>>> narrated("Once upon a time, a little robot put a pen in a bowl and carried the bowl to the desk.")
'put a pen in a bowl and carry the bowl to the desk.'
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import NamedTuple

from nl2hltl2plan.language.content_words import phrase_list_pattern, word_categories
from nl2hltl2plan.language.grammar.word_tables import VERBS
from nl2hltl2plan.language.spelling import english_lemmas


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
