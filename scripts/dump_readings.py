"""Every instruction of the committed sets read by `translate`, as JSON lines: a change meant to leave the
reading alone (a speed-up) is checked by a byte comparison of the dumps before and after.

    python scripts/dump_readings.py OUT.jsonl [--rows DIR] [--full 200] [--times TIMES.json]

The corpus: tests/language/data/styles/*.txt, the trust sets (tests/language/data/trust/*.jsonl) and, with
`--rows DIR`, the rows `scripts/language_failures.py --save-rows DIR` kept (its default sets). Each line is
one reading with `build=False, actions="none"` (the whole `LanguageResult`, or the error's class and
text); a seeded sample of `--full` instructions is read again with the full build (recipes and the
hierarchical spec). Prints the CPU time per instruction (median and mean) of each text's first reading,
the others hitting the readers' memos; `--times` keeps the per-instruction times.
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import time
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parent))
from trust_sets import STYLES, TRUST, parse_line, world_of  # noqa: E402


def corpus(rows: Path | None) -> list[tuple[str, str, str]]:
    """(key, scene, instruction) of every committed instruction, in a fixed order."""
    out = []
    for f in sorted(STYLES.glob("*.txt")):
        said = [ln for ln in f.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
        for k, ln in enumerate(said, 1):
            r = parse_line(ln, f.stem, k)
            out.append((f"styles.{f.stem}.{k}", r["scene"], r["instruction"]))
    for f in sorted(TRUST.glob("*.jsonl")):
        for k, ln in enumerate(f.read_text().splitlines()):
            if ln.strip():
                r = json.loads(ln)
                out.append((f"trust.{f.stem}.{k}", r["scene"], r["instruction"]))
    for f in sorted(rows.glob("*.json")) if rows else []:
        for k, r in enumerate(json.loads(f.read_text())):
            out.append((f"rows.{f.stem}.{k}", r["scene"], r["instruction"]))
    return out



def reading(scene: str, text: str, full: bool) -> dict[str, Any]:
    """The reading as JSON (the spec's JSON too with the full build), or the error's class and text."""
    try:
        if not full:
            return translate(text, world_of(scene), build=False, actions="none").model_dump(mode="json")
        res = translate(text, world_of(scene))
        spec = res.spec.to_json(indent=None) if res.spec is not None else None
        return res.model_dump(mode="json") | {"spec": spec}
    except Nl2Hltl2PlanError as exc:
        return {"error": f"{type(exc).__name__}: {exc}"}


def _line(row: dict[str, Any]) -> str:
    return json.dumps(row, sort_keys=True) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/dump_readings.py")
    ap.add_argument("out", type=Path)
    ap.add_argument("--rows", type=Path, default=None, help="language_failures.py --save-rows DIR")
    ap.add_argument("--full", type=int, default=200, help="how many to read again with the full build")
    ap.add_argument("--times", type=Path, default=None, help="write each first reading's CPU seconds")
    args = ap.parse_args()
    items = corpus(args.rows)
    for _, scene, _ in items:
        world_of(scene)  # worlds loaded before the clock runs
    reading("FloorPlan1", "put the apple in the fridge", False)  # models and word files loaded
    sample = set(random.Random(7).sample(range(len(items)), min(args.full, len(items))))
    times, seen = [], set()
    with args.out.open("w") as fh:
        for k, (key, scene, text) in enumerate(items):
            start = time.process_time()
            res = reading(scene, text, False)
            if (scene, text) not in seen:  # a text read before hits the memos: not a first reading
                times.append(time.process_time() - start)
            seen.add((scene, text))
            fh.write(_line({"key": key, "scene": scene, "text": text, "res": res}))
            if k in sample:
                fh.write(_line({"key": f"{key}.full", "res": reading(scene, text, True)}))
    times.sort()
    n = len(times)
    median, mean = 1000 * times[n // 2], 1000 * sum(times) / n
    print(f"{n} first readings: median {median:.2f} ms, mean {mean:.2f} ms CPU")
    if args.times:
        args.times.write_text(json.dumps(times))
    return 0


if __name__ == "__main__":
    sys.exit(main())
