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
- A heading that counts what follows ("Two things:", "Three jobs to do:", "Two stages.", "4 placements -")
  is found by `counted_headings`, for a world's reader to check against its reading: the things it counts
  are the tasks, the stages the labelled steps ("Stage one: ... Stage two: ..."). It is never dropped
  unchecked.
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
from typing import NamedTuple

from nl2hltl2plan.language.content_words import free_order_phrase, phrase_category, shared_words
from nl2hltl2plan.language.questions import answered

__all__ = ["CountedHeading", "answered", "counted_headings", "note_counts", "unlabelled"]

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


_COUNT_WORDS = {w: i for i, w in enumerate("one two three four five six seven eight nine ten".split(), 1)}
# the nouns a heading counts: the tasks themselves, or the stages (labelled steps) they come in
_TASK_NOUNS = "things?|tasks?|jobs?|placements?|moves?|items?|errands?|chores?|actions?"
_STAGE_NOUNS = "stages?|steps?|parts?|phases?|rounds?|batch(?:es)?"
# "one more thing:", "two last things:": what is added, not how many there are
_NOT_A_TOTAL = "(?:more|other|last|final|further|extra|additional|remaining)"
def _counted(start: str) -> re.Pattern[str]:
    """A heading that counts what follows (its tasks, or the stages they come in), after `start`."""
    return re.compile(
        # "there are", "we have", "today the robot has": who has the things to do is the one asked
        rf"{start}(?:(?:(?:today|now),?\s+)?(?:there\s+are|here\s+are|(?:we|you|i)\s+have|(?:the\s+robot|it)\s+has)\s+)?"
        rf"(?P<phrase>(?P<count>\d|{'|'.join(_COUNT_WORDS)})\s+(?:(?!{_NOT_A_TOTAL}\b)[a-z]+\s+)?(?:(?P<stages>{_STAGE_NOUNS})|{_TASK_NOUNS})"
        r"(?:\s+(?:to\s+(?:do|place|make|carry\s+out)|in\s+(?:all|total)|for\s+(?:you|the\s+robot|today)))?)"
        # "Three jobs, any order:": the order the heading frees is read with the tasks, not counted
        rf"(?:\s*,?\s*{free_order_phrase('whole')})?"
        r"\s*(?P<end>[:.!,]|\s-+\s|\s*[—–])",
        re.I,
    )


_COUNTED = _counted(_START)
# a note's count of its jobs, also after an address or its writer ("Kiddo, three jobs: ...", "Mum here - two
# things: ..."), which the household framing drops with the words before it (`courtesy`): its reader checks
# the tasks counted before a colon (`note_counts`)
_NOTE_COUNT = _counted(r"(?:^|[.!?;,]\s*|\s[-–—]+\s*)")


class CountedHeading(NamedTuple):
    """A heading's count: its words ("two things to do"), its number, and whether it counts stages."""

    phrase: str
    number: int
    stages: bool
    span: tuple[int, int]  # the heading in the text ("There are two stages."), its colon or stop included


def counted_headings(text: str) -> list[CountedHeading]:
    """The headings of `text` that count what follows ("Two things:", "There are two stages.", "3 jobs -"),
    each opening a sentence; the number as said, digits or a word.

    >>> [(h.phrase, h.number, h.stages) for h in counted_headings("Two stages. Stage one: ...")]
    [('Two stages', 2, True)]
    >>> counted_headings("Put two things on the plate. One more thing: ...")
    []
    """
    out = []
    for m in _COUNTED.finditer(text):
        word = m["count"].lower()
        count = int(word) if word.isdigit() else _COUNT_WORDS[word]
        out.append(CountedHeading(m["phrase"], count, m["stages"] is not None, (m.end("start"), m.end())))
    return out


def note_counts(text: str) -> list[CountedHeading]:
    """The counts of a note's jobs said as a heading closed by a colon, at the start, after a sentence, an
    address or a dash: the tasks they count, which a reading must make as many of.

    >>> [(h.phrase, h.number) for h in note_counts("Kiddo, three jobs: put the mug in the sink, ...")]
    [('three jobs', 3)]
    >>> note_counts("One more thing: put the mug in the sink.")
    []
    """
    out = []
    for m in _NOTE_COUNT.finditer(text):
        if m["stages"] or m["end"] != ":":
            continue
        word = m["count"].lower()
        count = int(word) if word.isdigit() else _COUNT_WORDS[word]
        out.append(CountedHeading(m["phrase"], count, False, m.span("phrase")))
    return out
