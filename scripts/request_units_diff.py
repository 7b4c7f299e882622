"""Which committed lines the request-unit classifier changes, and how they read with it and without it
(issue 28, h287; `language/learned/request_units.py`).

    python scripts/request_units_diff.py [--sets A,B] [--out FILE]

A line can change only where the household reader's text (`as_read`) differs with
NL2HLTL2PLAN_REQUEST_UNITS=1, so each such line of every committed set (trust and styles; never the
session's held-out sets) is read twice through `trust_sets.read_line`, off and on. Prints the table per set
(lines, changed, converted and wrong off -> on) and every line whose outcome or detail differs.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from trust_sets import STYLES, TRUST, load, read_line  # noqa: E402

from nl2hltl2plan.config.reading_settings import REQUEST_UNITS_ENV as ON_ENV  # noqa: E402
from nl2hltl2plan.errors import Nl2Hltl2PlanError  # noqa: E402
from nl2hltl2plan.language.world_readers import _HouseholdReader  # noqa: E402

HELD = ("h284", "h285", "h286")  # this session's held-out sets: never read here


def committed_sets() -> list[str]:
    names = sorted(p.stem for p in TRUST.glob("*.jsonl")) + sorted(p.stem for p in STYLES.glob("*.txt"))
    return [n for n in names if not any(h in n for h in HELD)]


def _as_read(text: str, on: bool) -> tuple[str, list[str]]:
    os.environ[ON_ENV] = "1" if on else "0"
    reader = _HouseholdReader(None)  # type: ignore[arg-type]  # as_read reads no world
    try:
        return reader.as_read([text]), reader.frames
    except Nl2Hltl2PlanError as exc:  # refused before any frame is read: the same either way
        return str(exc), []


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--sets", default=None)
    p.add_argument("--out", type=Path, default=None)
    args = p.parse_args()
    names = args.sets.split(",") if args.sets else committed_sets()
    rows, totals = [], [0, 0, 0, 0, 0, 0]
    print("| set | lines | text changed | converted off -> on | wrong off -> on |")
    print("| --- | --- | --- | --- | --- |")
    for name in names:
        gts = load(name)
        changed = [gt for gt in gts if _as_read(gt.instruction, True) != _as_read(gt.instruction, False)]
        conv, wrong = [0, 0], [0, 0]
        for gt in changed:
            said = []
            for k, on in enumerate((False, True)):
                os.environ[ON_ENV] = "1" if on else "0"
                what, why, assumed = read_line(gt)
                said.append((what, why[:200], assumed))
                conv[k] += what == "converted"
                wrong[k] += what == "wrong"
            if said[0][:2] != said[1][:2]:
                rows.append({"set": name, "id": gt.id, "text": gt.instruction, "off": said[0][:2],
                             "on": said[1][:2], "dropped": _as_read(gt.instruction, True)[1]})
        totals = [a + b for a, b in zip(totals, [len(gts), len(changed), *conv, *wrong], strict=True)]
        if changed:
            moved = f"{conv[0]} -> {conv[1]} | {wrong[0]} -> {wrong[1]}"
            print(f"| {name} | {len(gts)} | {len(changed)} | {moved} |")
    n, n_changed, c0, c1, w0, w1 = totals
    print(f"| all {len(names)} sets | {n} | {n_changed} | {c0} -> {c1} | {w0} -> {w1} |")
    for r in rows:
        print(json.dumps(r))
    if args.out:
        args.out.write_text("".join(json.dumps(r) + "\n" for r in rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
