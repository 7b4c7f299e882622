"""Two `scripts/language_failures.py --outcomes` files compared row by row (before/after, or its two
readers on the same saved rows).

    python scripts/compare_outcomes.py BEFORE.jsonl AFTER.jsonl [--show FROM->TO]

Prints how many rows moved from each class to each other one, and, for rows that left `ok`, what the
new reason is, with the numbers, quoted words and floor plans taken out so that one cause is one line
("'spoons': FloorPlan23 has 6 of them ..." and "... has 8 of them ..." count together).
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter
from pathlib import Path
from typing import Any

_VARIABLE = re.compile(r"'[^']*'|FloorPlan\d+|\d+")


def load(path: Path) -> dict[tuple[str, int], dict[str, Any]]:
    """The rows of an outcomes file by (set, row number)."""
    rows = [json.loads(line) for line in path.read_text().splitlines() if line.strip()]
    return {(r["set"], r["row"]): r for r in rows}


def cause(why: str) -> str:
    """A reason with what varies from row to row taken out (quoted words, floor plans, numbers)."""
    return _VARIABLE.sub("_", why.split(" || ")[0])[:120]


def transitions(
    before: dict[tuple[str, int], dict[str, Any]], after: dict[tuple[str, int], dict[str, Any]]
) -> tuple[Counter[tuple[str, str]], Counter[str]]:
    """(rows per class change, the causes of the rows that were `ok` and are not), over the rows both
    files hold."""
    moved: Counter[tuple[str, str]] = Counter()
    lost: Counter[str] = Counter()
    for key in before.keys() & after.keys():
        a, b = before[key]["class"], after[key]["class"]
        if a != b:
            moved[a, b] += 1
            if a == "ok":
                lost[cause(after[key]["why"])] += 1
    return moved, lost


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/compare_outcomes.py")
    ap.add_argument("before", type=Path)
    ap.add_argument("after", type=Path)
    ap.add_argument("--show", default=None, help="print the rows of one change, e.g. 'ok->error'")
    args = ap.parse_args()
    before, after = load(args.before), load(args.after)
    moved, lost = transitions(before, after)
    print(f"{len(before.keys() & after.keys())} rows in both; {sum(moved.values())} changed class")
    print("| before | after | rows |\n| --- | --- | --- |")
    for (a, b), n in moved.most_common():
        print(f"| {a} | {b} | {n} |")
    if lost:
        print("\n| why a row that converted no longer does | rows |\n| --- | --- |")
        for why, n in lost.most_common():
            print(f"| {why} | {n} |")
    if args.show:
        for key in sorted(before.keys() & after.keys()):
            if f"{before[key]['class']}->{after[key]['class']}" == args.show:
                print(f"{key}: {after[key]['instruction'][:200]!r}\n    {after[key]['why'][:300]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
