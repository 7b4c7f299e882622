"""Headings that count what follows in the tabletop world (issue 28): "Two things: ...", "Three jobs to
do: ...", "Two stages. Stage one: ... Stage two: ...", "4 placements -". `headings.counted_headings` finds
them, alike in every world; this module holds the tabletop reader to them, so that a count is read where
the reading keeps it and refused by name where it does not, never dropped:

- a count of stages (steps, parts, phases, rounds) is the number of labelled steps or list numbers after
  it: the heading is dropped where they are as many (`stage_headings_read`, before the labels are read as
  "first" / "then"), and the instruction refused where they are not or where none follows;
- a count of things (tasks, jobs, placements, moves, items) is the number of placements the reading
  makes: the pairs reading takes the heading out of the words it reads and checks its count
  (`task_headings_read`); any other reading is checked by `task_headings_unread`.

>>> stage_headings_read("Two stages. Stage one: A on P. Stage two: B on Q.")
'Stage one: A on P. Stage two: B on Q.'
>>> task_headings_read("Two things: A on P; B on Q.")
('A on P; B on Q.', [2])
"""

from __future__ import annotations

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.headings import counted_headings
from nl2hltl2plan.language.tabletop_steps import labelled_steps


def stage_headings_read(text: str) -> str:
    """`text` without its headings that count stages, each checked against the labelled steps after it;
    HTTError naming the heading where their number is another or none follows."""
    headings = [h for h in counted_headings(text) if h.stages]
    for h in reversed(headings):
        text = text[: h.span[0]] + text[h.span[1] :]
    steps = labelled_steps(text) if headings else 0
    for h in headings:
        if h.number != steps:
            said = f"{steps} labelled steps follow" if steps else "no labelled steps follow (Step 1: ...)"
            raise HTTError(f"'{h.phrase}' counts {h.number} stages, but {said}: say the stages it counts")
    return " ".join(text.split()) if headings else text


def task_headings_read(text: str) -> tuple[str, list[int]]:
    """`text` without its headings that count things, closed by a colon, dash or stop, and each count
    (which the pairs reading checks against the placements it makes)."""
    headings = [h for h in counted_headings(text) if not h.stages and not text[: h.span[1]].endswith(",")]
    for h in reversed(headings):
        text = text[: h.span[0]] + text[h.span[1] :]
    return (" ".join(text.split()), [h.number for h in headings]) if headings else (text, [])


def task_headings_unread(text: str, placements: int) -> list[tuple[str, str]]:
    """Each heading of `text` that counts things other than the `placements` a reading makes, with why."""
    return [
        (h.phrase, f"it counts {h.number}, and the reading makes {placements} placements")
        for h in counted_headings(text)
        if not h.stages and h.number != placements
    ]
