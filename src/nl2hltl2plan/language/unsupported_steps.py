"""Steps of an instruction that no base task does, judged in word accounting (`accounting.account`):
a slice or treatment said after the placing ("put the tomato in the fridge, then slice it"), closing
after a placing ("... and close it"), returning a thing to where it was ("bring it back"), repeating a
task ("three times") and leaving things out ("leave one out").

>>> from nl2hltl2plan.language.task_specs import BaseTaskSpec
>>> [u.words for u in returns_and_repeats("move the laptop to the sofa and then bring it back")]
['back']
"""

from __future__ import annotations

import re

from nl2hltl2plan.domain.task_kinds import APPLIANCE
from nl2hltl2plan.language.content_words import Unread, categories
from nl2hltl2plan.language.grounding import Mention, sentence_start
from nl2hltl2plan.language.negations import NO_CONSTRAINT
from nl2hltl2plan.language.parse_usage import ParseUsage

# "bring it back", "then back again": to where it was, which no base task names; "three times"
_RETURN = re.compile(r"\bback(?: again)?\b(?=\s*(?:$|[.,;!?)]|(?:and|then|again|afterwards|later|here)\b))")
_LEFT_OUT = re.compile(r"\bleave (?:\w+ ){0,3}out\b(?! of)")  # "leave one out": an exception, as "except one"
_SOURCE = re.compile(r"\b(?:from|out of|off)\b")
_TIMES = re.compile(
    r"\b(?:\d+|two|three|four|five|six|seven|eight|nine|ten|several|many|multiple|a few) times\b"
)


def returns_and_repeats(instruction: str) -> list[Unread]:
    """ "Back" with no place after it names one only where the sentence said where the thing came from
    ("wash the cloth from the cabinet, put it back")."""
    lowered = instruction.lower()
    out = [
        Unread(m.group(0), "place", "no base task returns a thing to where it was: name the place")
        for m in _RETURN.finditer(lowered)
        if not _SOURCE.search(lowered, sentence_start(instruction, m.start()), m.start())
    ]
    out += [Unread(m.group(0), "negation", NO_CONSTRAINT) for m in _LEFT_OUT.finditer(lowered)]
    return out + [
        Unread(m.group(0), "count", "no base task is done more than once: say each time as its own task")
        for m in _TIMES.finditer(lowered)
    ]


_THEN_VERB = re.compile(
    r"\b(?:then|afterwards|after that|next|later|before)\s*,?\s+(?:you\s+)?(?:can\s+)?([a-z]+)"
)


def treated_after_placing(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """A task's slice or treatment comes before its placing; "put the tomato in the fridge, then slice
    it" says the opposite, so a sliced tomato in the fridge is not what it asks."""
    out = []
    lowered = instruction.lower()
    for t in parse.tasks:
        wanted = {f"verb_{t.kind}"} | ({"verb_sliced"} if t.sliced else set())
        places = set(t.receptacle or ()) - {APPLIANCE.get(t.kind, "")}
        at = lowered.find(t.text.lower()) if t.text else -1  # the task's own words, else the whole text
        start, end = (at, at + len(t.text)) if at >= 0 else (0, len(lowered))
        placed = [m.char_end for m in mentions if set(m.entry.types) & places and start <= m.char_start < end]
        sentence_end = next((k for k in range(end, len(lowered)) if lowered[k] in ".;!?"), len(lowered))
        for then in _THEN_VERB.finditer(lowered, start, sentence_end):
            if not (placed and then.start() > max(placed) and categories(then.group(1)) & wanted):
                continue
            after = lowered[then.end() : then.end() + 40]
            if _PRONOUN.match(after) or any(
                m.char_start >= then.end()
                and set(m.entry.types) & set(t.object)
                and m.char_start < then.end() + 40
                for m in mentions
            ):
                out.append(
                    Unread(then.group(0), "order", f"task {t.id}'s treatment comes before its placing")
                )
    return out


_PRONOUN = re.compile(r"\s+(?:it|them|this|that|these|those)\b")


def closed_after_placing(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """A placing task leaves its receptacle open: "put the knife in the drawer and close it" is not done
    unless a task closes it."""
    places = {r for t in parse.tasks for r in t.receptacle or ()}
    first = min((m.char_end for m in mentions if set(m.entry.types) & places), default=None)
    if first is None or "closed" in parse.states:
        return []
    return [
        Unread(shut.group(0), "action", "no base task closes it: the plan leaves it open")
        for shut in _CLOSE.finditer(instruction.lower(), first)
    ]


_CLOSE = re.compile(r"\b(?:close|shut)\b(?! (?:to|by)\b)")
