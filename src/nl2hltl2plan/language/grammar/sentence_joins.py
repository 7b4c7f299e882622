"""Two sentences that say one task: a treatment, then where the treated thing goes.

"Heat the egg in the microwave. Then put it in the fridge." and "... heat it up in the microwave; when it's
warm, put it in the fridge." are one heat-and-place task, as the same words joined by a comma are; an LLM
that rewrites ALFRED's step-by-step annotations into one paragraph (the paper's test set, issue 28) splits
them so. The rules read each sentence on its own, and "it" at the start of a sentence names nothing. The
join is made only where the first sentence treats a thing and places nothing, and the second places "it"
(after "then" or "when it's warm", the treatment's end, or nothing): the "it" can only be the treated thing.
`sentences.normalize` applies `joined_treatments`.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.grammar import word_tables as G

_TREATMENTS = frozenset({"clean", "heat", "cool"})
_PLACING = frozenset({"place", "trash"})
_DONE_STATE = r"(?:warm|hot|heated|cooked|cold|chilled|cool|cooled|clean|washed|rinsed|done|ready)"
# the sentence that follows: an order word or the treatment's end, then a placing of "it"
_THEN_PLACE_IT = re.compile(
    rf"^\s*(?:(?:(?:and\s+)?then|after\s+that|afterwards|next|(?:when|once)\s+it(?:'s|\s+is)\s+{_DONE_STATE})"
    r"\s*,?\s+)?(?=(?:put|place|set|leave|move|bring|take|drop|throw|toss|store|lay|return)\s+it\b)",
    re.I,
)
_NOT_A_STEP = frozenset({"not", "don't", "never", "without", "if", "unless", "no"})
_SENTENCE_END = re.compile(r"\s*[.;]\s+")


def _treats_only(sentence: str) -> bool:
    """The sentence has a treating verb and no placing one ("grab the egg and heat it in the microwave"),
    and no negation or condition ("don't heat the egg", "if it is cold, heat it": no step to go on from)."""
    words = re.findall(r"[a-z']+", sentence.lower())
    classes = {G.VERBS[w][0] for w in words if w in G.VERBS}
    return bool(classes & _TREATMENTS) and not classes & _PLACING and not _NOT_A_STEP & set(words)


def joined_treatments(text: str) -> str:
    """Each "S1. Then put it ..." where S1 only treats a thing, written as "S1, then put it ..."."""
    parts = _SENTENCE_END.split(text)
    if len(parts) < 2:
        return text
    out = [parts[0]]
    ends = _SENTENCE_END.findall(text)
    for end, part in zip(ends, parts[1:], strict=True):
        m = _THEN_PLACE_IT.match(part)
        if m and _treats_only(out[-1]):
            rest = part[m.end() :]
            out[-1] += ", then " + rest[:1].lower() + rest[1:]
        else:
            out[-1] += end
            out.append(part)
    return "".join(out)
