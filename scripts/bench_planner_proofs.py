"""What the planner proved on an oracle benchmark run: per (base tasks, robots), the share proven
optimal and proven within 5 % (bound <= 1.05), the proven bound (median / max) and the planning
time, read from the run's scenarios.jsonl (`nl2hltl2plan bench alfred --oracle -o DIR`).

    python scripts/bench_planner_proofs.py DIR [--n-base 3,4] [--out table.md]

Prints a Markdown table (solved scenarios only; the last row pools the selected ones).
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_tables import emit  # noqa: E402


def load(run: str) -> list[dict[str, Any]]:
    path = Path(run) / "scenarios.jsonl"
    if not path.is_file():
        raise SystemExit(f"error: no scenarios.jsonl in {run}")
    rows: dict[str, dict[str, Any]] = {}
    for line in path.read_text().splitlines():
        if line.strip():
            row = json.loads(line)
            rows[row["key"]] = row  # a resumed run: the last line of a scenario counts
    return [r for r in rows.values() if r["status"] == "solved"]


def table(rows: list[dict[str, Any]], n_base: list[int] | None) -> list[str]:
    if n_base:
        rows = [r for r in rows if r["n_base"] in n_base]
    out = ["| base tasks | robots | solved | proven optimal | proven within 5 % | bound (median, max) "
           "| time s (median, p95, max) |", "|" + " --- |" * 7]
    groups = sorted({(r["n_base"], r["robots"]) for r in rows})
    for key in [*groups, None]:
        sel = [r for r in rows if key is None or (r["n_base"], r["robots"]) == key]
        if not sel:
            continue
        bounds = [r["bound"] if r["bound"] is not None else 1.0 if r["proven_optimal"] else float("inf")
                  for r in sel]
        times = [r["plan_time_s"] for r in sel]
        label = ("all", "all") if key is None else key
        out.append(
            f"| {label[0]} | {label[1]} | {len(sel)} | {sum(bool(r['proven_optimal']) for r in sel)} "
            f"| {sum(b <= 1.05 for b in bounds)} ({100 * sum(b <= 1.05 for b in bounds) / len(sel):.0f} %) "
            f"| {statistics.median(bounds):.3f}, {max(bounds):.3f} "
            f"| {statistics.median(times):.2f}, {_p95(times):.2f}, {max(times):.2f} |")
    return out


def _p95(values: list[float]) -> float:
    """The 95th percentile (the value below which 95 % of the runs fall; inclusive method)."""
    if len(values) < 2:
        return values[0]
    return statistics.quantiles(values, n=20, method="inclusive")[18]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="an oracle benchmark output folder")
    ap.add_argument("--n-base", default=None, help="base-task counts to keep (default: all)")
    ap.add_argument("--out", default=None, help="also write the table here (with command, commit, machine)")
    args = ap.parse_args()
    n_base = [int(x) for x in args.n_base.split(",")] if args.n_base else None
    emit(table(load(args.run), n_base), args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
