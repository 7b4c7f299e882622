"""Is a clause that says where a thing is ("the carrot is on the blue plate") asked for, or said of a state
that another clause refers to, rather than stated? The one test of it (`asked_before`), with its words in
`state_words.txt`, for check 1 (`accounting`: a place so named is a stop of a task) and the tabletop reader
(`tabletop_wording`: such a clause is a task); a treatment said as done already (`done_already`, check 1);
and the connectives that refer to a state (`REFERENCE`: "a task said once is read twice" in
`unsupported_steps`, a command after a state in `grammar.order_phrases`).

>>> asked_before("I want that the carrot is on the blue plate", 25)
True
>>> asked_before("I want this. The carrot is on the blue plate", 25)
False
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from nl2hltl2plan.language.content_words import Unread, categories, phrase_list_pattern
from nl2hltl2plan.language.grounding import sentence_start
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def _words(kind: str) -> str:
    return phrase_list_pattern("state_words.txt", kind)


# the verb that says where a thing is, was or has been put, and the words that may follow it before the place
# (" is", " has been", " is already sitting"); `WHERE_VERB`, the tabletop reader's, takes "'s" and a placing's
# participle too ("the carrot's on", " was put"): check 1 reads "the mug that's on the counter, put it ..."
# and "were set on" as naming a stop. Each alternative starts with its own space (or "'s", after its noun);
# no flags
_ADVERBS = rf"(?:\s+(?:{_words('where_adverb')}|{_words('posture')}))*"
WHERE_COPULA = rf"\s+{_words('where')}{_ADVERBS}"
WHERE_VERB = (
    rf"(?:'s|\s+{_words('where')})(?:\s+(?:{_words('where_adverb')}|{_words('posture')}|"
    rf"{_words('where_participle')}))*"
)
_WHERE_BEFORE = re.compile(rf"(?:{WHERE_COPULA}|\s+{_words('posture')})\s*$", re.I)
# a relative clause that says where a thing is now ("the mug that's on the counter", "which is sitting in"):
# a source, never a destination or a task (`grammar.sentences`, `grammar.everyday`); no context, no flags
RELATIVE_PLACE = (
    r"(?:that|which)(?:'s|\s+is|\s+are)\s+(?:(?:sitting|lying|standing|now)\s+)?(?:on|in|at|inside)"
)
# a connective that refers to a state ("after the apple is in the fridge"), no context and no flags
REFERENCE = _words("reference")
# a wish or goal, or a reference to a state, anywhere before the clause in its sentence
_ASKED = re.compile(
    rf"\b(?:{_words('wish')}|{REFERENCE})\b", re.I
)


def asked_before(text: str, at: int) -> bool:
    """Is a wish, a goal or a reference to a state said in the sentence of character `at`, before it?"""
    return _ASKED.search(text, sentence_start(text, at), at) is not None


def says_where(text: str, at: int) -> bool:
    """Does the text before character `at` (a place's preposition) end in a verb that says where a thing is
    ("the mug is in", "the mug's already in", "the mug sitting in"; not a placing's participle: "it has been
    put in")?"""
    return _WHERE_BEFORE.search(text, 0, at) is not None


_TREATS = {f"verb_{kind}": kind for kind in ("heat_place", "cool_place", "clean_place")}
_ALREADY = re.compile(r"\balready\s+([a-z]+ed)\b|\b([a-z]+ed)\s*,?\s+already\b", re.I)


def done_already(instruction: str, tasks: Sequence[BaseTaskSpec]) -> list[Unread]:
    """Each treatment said as done already ("mug, washed already -> cabinet", "the already chilled apple")
    that a task does all the same (h273): the reading took a state for a duty (check 1)."""
    kinds = {t.kind for t in tasks}
    out = []
    for m in _ALREADY.finditer(instruction):
        kind = next((_TREATS[c] for c in categories(m[1] or m[2]) if c in _TREATS), None)
        if kind in kinds:
            out.append(Unread(m[0], "action", "said as done already: no task is to do it again"))
    return out
