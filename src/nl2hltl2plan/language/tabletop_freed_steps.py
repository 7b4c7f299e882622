"""Runs of numbered tabletop steps that a remark after the last step frees by number (issue 24's
rephrasings): "Step 1: A. Step 2: B. Step 3: C. Step 4: D. Steps 1 and 2 may happen in any order, and so may
steps 3 and 4." (or "The first two steps can be done in either order, and so can the last two") is "Step 1:
A and B, in any order. Step 2: C and D, in any order." Each run is two or more steps in turn, and the steps
keep their order otherwise. A remark that names every step by number, a step that is not there,
overlapping runs, or a remark anywhere but after the last step leave the text as it is; the tabletop
reader then refuses a remark that still names steps by number (`steps_named`).
"""

from __future__ import annotations

import re

_STEP = re.compile(
    r"(?:^|(?<=[.;!?]))\s*(?:step\s+(?P<n>[1-6])\s*[:.)\-]|(?P<d>[1-6])[.)])\s+", re.IGNORECASE
)
_COUNT = {"two": 2, "three": 3}


def _run(i: int) -> str:
    return (
        rf"(?:steps\s+(?P<lo{i}>[1-6])\s+(?:and|&|(?P<to{i}>to|through))\s+(?P<hi{i}>[1-6])|the\s+(?P<end{i}>first|last)\s+"
        rf"(?P<count{i}>two|three)(?:\s+steps)?)"
    )


_MAY = r"(?:(?:may|can|could)\s+(?:happen|be\s+done|go|come)\s+)?"
_FREE = rf"(?:the\s+)?{{run}}\s+{_MAY}in\s+(?:any|either)\s+order"
_ALSO = r"\s*,?\s*(?:and\s+)?so\s+(?:may|can|could)\s+{run}"
_REMARKS = re.compile(
    rf"(?<=[.;!?])\s*{_FREE.format(run=_run(1))}(?:{_ALSO.format(run=_run(2))}|\s*[.;]\s*"
    rf"{_FREE.format(run=_run(3))})?\s*[.!]?\s*$",
    re.IGNORECASE,
)


def _span(m: re.Match[str], i: int, steps: int) -> tuple[int, int] | None:
    if m[f"lo{i}"]:  # "steps 2 and 3" names two steps in turn, "steps 1 to 3" a run ("steps 1 and 3": none)
        lo, hi = int(m[f"lo{i}"]), int(m[f"hi{i}"])
        return (lo, hi) if hi == lo + 1 or m[f"to{i}"] else (0, 0)
    if m[f"end{i}"]:
        count = _COUNT[m[f"count{i}"].lower()]
        return (1, count) if m[f"end{i}"].lower() == "first" else (steps - count + 1, steps)
    return None


def runs_freed(text: str) -> str:
    """`text` with the runs of steps its closing remark frees said as one step each (see the module's
    docstring); else `text` as it is."""
    marks = list(_STEP.finditer(text))
    if len(marks) < 3 or [int(m["n"] or m["d"]) for m in marks] != list(range(1, len(marks) + 1)):
        return text
    remark = _REMARKS.search(text, marks[-1].end())
    if remark is None:
        return text
    runs = [s for s in (_span(remark, i, len(marks)) for i in (1, 2, 3)) if s is not None]
    freed = [n for lo, hi in runs for n in range(lo, hi + 1)]
    if any(lo >= hi or lo < 1 or hi > len(marks) for lo, hi in runs) or len(set(freed)) != len(freed):
        return text
    if (1, len(marks)) in runs:  # every step by number: refused by name (`steps_named`), as check 1 would
        return text
    ends = [m.start() for m in marks[1:]] + [remark.start()]
    steps = [text[m.end() : end].strip().rstrip(".;,!").strip() for m, end in zip(marks, ends, strict=True)]
    said: list[str] = []
    n = 1
    while n <= len(steps):
        run = next(((lo, hi) for lo, hi in runs if lo == n), None)
        if run is None:
            said.append(steps[n - 1])
            n += 1
            continue
        group = steps[run[0] - 1 : run[1]]
        said.append(", ".join(group[:-1]) + f" and {group[-1]}, in any order")
        n = run[1] + 1
    start = text[: marks[0].start()]
    return start + " ".join(f"Step {i}: {s}." for i, s in enumerate(said, 1))


# steps named by number ("steps 1 and 4", "the last two steps") still in the text once `runs_freed` has read
# the runs it can: a remark that frees steps no rule reads, refused rather than read as freeing the list
_NAMED = re.compile(
    r"\b(?:steps\s+[1-6](?:\s*(?:,|and|&|to|through)\s*[1-6])+|the\s+(?:first|last)\s+(?:two|three)\s+steps)\b",
    re.IGNORECASE,
)


def steps_named(text: str) -> str | None:
    """The steps a remark of `text` names by number, or None."""
    m = _NAMED.search(text)
    return m[0] if m else None
