"""Actions the system has no word for (issue 23): "put the pillow on the sofa and fluff it", "... and
polish them". A word that opens a command (at the text's or a clause's start, or after "and", "then",
"please") and is followed by its object ("it", "them", a determiner) is the command's verb. When English
knows that word but none of the project's word tables does (the lexicon, `content_words.txt`, the order
and politeness lists), no base task does what it says: it is unread, and the instruction is refused,
never read as the commands around it.

Not judged: prepositions ("behind the mug"), words in -ly ("gently the ...") and in -ing ("containing a
knife": a participle describes a thing), and words English does not know (the spelling rule's business).

>>> [u.words for u in unknown_verbs("put the pillow on the sofa and fluff it")]
['fluff']
>>> unknown_verbs("put the pillow on the sofa and then put it back")
[]
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import DETERMINERS, LOCATIVE, Unread, categories
from nl2hltl2plan.language.grounding import tokens
from nl2hltl2plan.language.spelling import english_word, known_word

_COMMAND_START = frozenset("and then please pls also now next first finally lastly".split())
_OBJECT_START = frozenset(DETERMINERS - {"of"} | {"it", "them", "some", "both", "all", "each", "every"})
_PREPOSITIONS = LOCATIVE | {
    "to", "into", "onto", "upon", "toward", "towards", "past", "through", "via", "outside", "around",
    "beside", "besides", "within", "over", "up", "down", "out", "for", "like", "than", "as",
}  # fmt: skip
# words that open a clause without naming its action: conjunctions, pronouns, auxiliaries and the verbs
# whose object the action follows ("let it cool", "use the knife to slice ...", "have the mug in the sink")
_NO_ACTION = frozenset(
    "but or nor yet so plus except including especially even only just too either neither whether while "
    "where when which what who how why there here you we they he she i let have has had use need want like "
    "try help be is are was were do does did can could will would should must may might shall".split()
)
_CLAUSE_BREAK = re.compile(r"[,.;:!?()]|\s[-–—]\s")
REASON = "no base task does this: an action the system has no word for"


def unknown_verbs(instruction: str) -> list[Unread]:
    """The verbs of commands in `instruction` that English knows and no word table of the project does."""
    toks = tokens(instruction)
    out = []
    for i, (word, start, _) in enumerate(toks[:-1]):
        opens = i == 0 or toks[i - 1][0] in _COMMAND_START or _CLAUSE_BREAK.search(
            instruction[toks[i - 1][2] : start]
        )
        if opens and toks[i + 1][0] in _OBJECT_START and _unknown_action(word):
            out.append(Unread(word, "action", REASON))
    return out


def _unknown_action(word: str) -> bool:
    if len(word) < 3 or word in DETERMINERS | _PREPOSITIONS | _NO_ACTION:
        return False
    if word.endswith(("ly", "ing", "'s")):  # an adverb, a participle, a possessive
        return False
    return not known_word(word) and not categories(word) and english_word(word)
