"""Labelled lines, read alike by every world's reader: `translate` applies `unlabelled` to each line of an
instruction before any reader or backend reads it.

- A one-word label and a dash open a sentence as a colon does ("Goal - ...", "Condition — ..."); not after
  a step's number ("1 - move ...", "two - put ...").
- A labelled sentence whose value asks nothing ("Condition - none", "Notes: n/a", "Constraints: nothing";
  the labels are `empty_label` in content_words.txt, the values `empty_value`) is dropped; another label
  keeps its value, which the readers read ("Ordering: none" frees an order, "Other regions: nothing" says
  where nothing goes).
- Any other label stays for the readers, which read its value ("Task: put ...") or refuse it by name
  ("Note: the fridge is cold").
- Questions and answers ("Q: Where does the mug go? A: In the sink. Q: And the apple? A: The fridge.
  Q: Order? A: Mug first.") become the instruction they state (`answered`): each answer fills its
  question's gap, a follow-up ("And the apple?") asks the question before it again, and an answer about
  the order orders the tasks or frees the order. A question or answer the frames do not cover, or an
  answer that says nothing certain, is refused by name; nothing is guessed.

>>> unlabelled("Goal - put the apple in the fridge. Condition - none.")
'Goal: put the apple in the fridge.'
>>> unlabelled("Notes: n/a")
''
>>> unlabelled("1 - put the mug in the sink. Ordering: none")
'1 - put the mug in the sink. Ordering: none'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import phrase_category, shared_words
from nl2hltl2plan.language.questions import answered

__all__ = ["answered", "unlabelled"]

_NUMBER_WORDS = frozenset("one two three four five six seven eight nine ten i ii iii iv v".split())
_START = r"(?P<start>^|(?<=[.!?;])\s+)"
_DASH_LABEL = re.compile(rf"{_START}(?P<label>[A-Za-z]+)(?:\s*[—–]\s*|\s+-+\s+)")
# a label of up to three words, a colon, and a value that asks nothing, to the sentence's end
_EMPTY = re.compile(
    rf"{_START}(?P<label>[A-Za-z]+(?:\s+[A-Za-z]+){{0,2}})\s*:\s*(?:{phrase_category('empty_value')})\s*"
    r"(?:[.!?;]+|$)",
    re.I,
)


def unlabelled(line: str) -> str:
    """`line` with its labels' dashes as colons and its labelled sentences that ask nothing dropped."""
    line = _DASH_LABEL.sub(_as_colon, line)
    return " ".join(_EMPTY.sub(_dropped, line).split())


def _as_colon(m: re.Match[str]) -> str:
    if m["label"].lower() in _NUMBER_WORDS:
        return m[0]
    return f"{m['start']}{m['label']}: "


def _dropped(m: re.Match[str]) -> str:
    labels = set(re.findall(r"[a-z]+", m["label"].lower()))
    return m["start"] if labels <= _EMPTY_LABELS else m[0]


_EMPTY_LABELS = shared_words("empty_label")
