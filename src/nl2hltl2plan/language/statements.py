"""Is a clause that says where a thing is ("the carrot is on the blue plate") asked for, or said of a state
that another clause refers to, rather than stated? The one test of it (`asked_before`), with its words in
`state_words.txt`, for check 1 (`accounting`: a place so named is a stop of a task) and the tabletop reader
(`tabletop_wording`: such a clause is a task); and the connectives that refer to a state (`REFERENCE`: "a task
said once is read twice" in `unsupported_steps`, a command after a state in `grammar.order_phrases`).

>>> asked_before("I want that the carrot is on the blue plate", 25)
True
>>> asked_before("I want this. The carrot is on the blue plate", 25)
False
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import phrase_list_pattern
from nl2hltl2plan.language.grounding import sentence_start

# a relative clause that says where a thing is now ("the mug that's on the counter", "which is sitting in"):
# a source, never a destination or a task (`grammar.sentences`, `grammar.everyday`); no context, no flags
RELATIVE_PLACE = (
    r"(?:that|which)(?:'s|\s+is|\s+are)\s+(?:(?:sitting|lying|standing|now)\s+)?(?:on|in|at|inside)"
)
# a connective that refers to a state ("after the apple is in the fridge"), no context and no flags
REFERENCE = phrase_list_pattern("state_words.txt", "reference")
# a wish or goal, or a reference to a state, anywhere before the clause in its sentence
_ASKED = re.compile(rf"\b{phrase_list_pattern('state_words.txt')}\b", re.I)


def asked_before(text: str, at: int) -> bool:
    """Is a wish, a goal or a reference to a state said in the sentence of character `at`, before it?"""
    return _ASKED.search(text, sentence_start(text, at), at) is not None
