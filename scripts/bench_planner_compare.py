"""Compare two `bench alfred --oracle` runs scenario by scenario (e.g. --mode fast against --mode exact).

    python scripts/bench_planner_compare.py FAST_DIR EXACT_DIR

Prints, over the scenarios both solved and the second proved optimal: how often the first found the
same cost, the ratio of the summed costs (before stand-cell refinement: the search model's cost),
the worst ratio, and any scenario where the first is cheaper than a proven optimum (a bug).
"""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path


def rows(folder: str) -> dict[str, dict]:
    out = {}
    for line in (Path(folder) / "scenarios.jsonl").read_text().splitlines():
        row = json.loads(line)
        out[row["key"]] = row
    return out


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    a, b = rows(sys.argv[1]), rows(sys.argv[2])
    both = [k for k in b if k in a and a[k].get("status") == "solved" and b[k].get("status") == "solved"]
    proven = [k for k in both if b[k].get("proven_optimal")]
    if not proven:
        print("no scenario with a proven optimum in the second run")
        return 1
    ratio = [a[k]["model_cost"] / b[k]["model_cost"] for k in proven]
    bugs = [k for k in proven if a[k]["model_cost"] < b[k]["model_cost"]]
    times_b = [b[k]["plan_time_s"] for k in b if b[k].get("plan_time_s") is not None]
    print(f"scenarios solved by both: {len(both)}; proven optimal by the second: {len(proven)}")
    print(f"first run equal to the optimum: {sum(r == 1 for r in ratio)}/{len(proven)}; summed cost ratio "
          f"{sum(a[k]['model_cost'] for k in proven) / sum(b[k]['model_cost'] for k in proven):.4f}; "
          f"mean ratio {statistics.fmean(ratio):.4f}; worst {max(ratio):.3f}")
    print(f"second run planning time s: median {statistics.median(times_b):.3f}, max {max(times_b):.2f}")
    unproven = [k for k in both if not b[k].get("proven_optimal")]
    if unproven:
        print("not proven optimal within the time limit: " + ", ".join(unproven))
    if bugs:
        print("CHEAPER THAN A PROVEN OPTIMUM: " + ", ".join(bugs))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
