"""The final report: grammar vs the default (learned) offline backend on test50, run once, and speed.

    python -m nl2hltl2plan.suites.alfred.learned_report test50   # the final report only, never for tuning
    python -m nl2hltl2plan.suites.alfred.learned_report speed [--split valid_unseen]

Choices are made on the text-faithful validation (`suites.alfred.learned_validation`); test50 is the
benchmark table
(`suites.alfred.conversion.table`) for both backends. `speed` times the default backend on validation
instructions (model load, median and max per instruction).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from typing import Any

from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.inference import load_model
from nl2hltl2plan.suites.alfred.conversion import (
    evaluate,
    grammar_generator,
    learned_generator,
    load_benchmark,
    table,
)


def speed(rows: list[dict[str, Any]]) -> str:
    t0 = time.monotonic()
    load_model.cache_clear()
    load_model()
    load_s = time.monotonic() - t0
    gen = learned_generator()
    ms = []
    for r in rows:
        types = scene_types(r["scene"])
        t = time.perf_counter()
        gen(r["instruction"], types, r["scene"])
        ms.append(1000 * (time.perf_counter() - t))
    med = statistics.median(ms)
    return f"model load {load_s:.2f} s; median {med:.1f} ms per instruction (max {max(ms):.0f})"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m nl2hltl2plan.suites.alfred.learned_report")
    ap.add_argument("what", choices=["test50", "speed"])
    ap.add_argument("--split", default="valid_unseen", choices=["valid_seen", "valid_unseen"])
    args = ap.parse_args(argv)
    if args.what == "speed":
        from nl2hltl2plan.suites.alfred.learned_validation import validation_rows

        rows = validation_rows(args.split)
        print(f"{args.split}: {len(rows)} instructions; {speed(rows)}")
        return 0
    rows = load_benchmark()
    print(f"test50: {len(rows)} instructions")
    print("grammar:")
    print(table(evaluate(rows, grammar_generator)))
    print("offline (default: grammar + learned model):")
    print(table(evaluate(rows, learned_generator())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
