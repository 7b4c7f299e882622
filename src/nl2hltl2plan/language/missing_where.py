"""A refusal for a type the world lacks, with the words it came from (h280, issue 23): "no Mirror (for
'mirrors' in 'Check your mirrors and off you go') in tabletop". Apart from `missing_types`, which imports no
language module so that `grounding` may ask it."""

from __future__ import annotations

import re

from nl2hltl2plan.domain.task_kinds import camel_words
from nl2hltl2plan.language.grounding import find_mentions, sentence_start

_NO_TYPE = re.compile(r"^no ([A-Z][A-Za-z]+)(?= in )")
_SENTENCE_BREAK = re.compile(r"[.;!?]")


def named_where(refused: Exception, instruction: str) -> Exception:
    """A refusal for a type the world lacks ("no Mirror in tabletop", issue 23) with the words it came
    from, where the word differs from the type's name or the instruction says more than one sentence:
    "no Mirror (for 'mirrors' in 'Check your mirrors and off you go') in tabletop". A user who never
    asked for a mirror sees which of their sentences was read as one."""
    said = str(refused)
    m = _NO_TYPE.match(said)
    if m is None:
        return refused
    for x in find_mentions(instruction):
        if x.entry.canonical != m[1] and m[1] not in x.entry.types:
            continue
        start = sentence_start(instruction, x.char_start)
        after = _SENTENCE_BREAK.search(instruction, x.char_end)
        sentence = " ".join(instruction[start : after.start() if after else None].split())
        alone = sentence == " ".join(instruction.split()).rstrip(".!?")
        if alone and (x.surface.lower() == camel_words(m[1]) or repr(x.surface) in said):
            return refused  # "put the statue in the fridge": one sentence, its word named as said
        return type(refused)(f"no {m[1]} (for {x.surface!r} in {sentence!r}){said[m.end() :]}")
    return refused
