"""Do two `bench alfred --oracle` runs give identical plans? (The planner's budgets are counted in
expansions, so they should, on any machine load.)

    python scripts/bench_planner_same_plans.py RUN_A RUN_B

Compares, scenario by scenario, the status, the costs and the planned events (time, robot, atom,
task, objects); prints the differences and the planning-time statistics of both runs.
"""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path
from typing import Any

FIELDS = ("status", "total_cost", "steps", "cost", "lower_bound", "proven_optimal", "events")


def rows(folder: str) -> dict[str, dict[str, Any]]:
    lines = (Path(folder) / "scenarios.jsonl").read_text().splitlines()
    return {r["key"]: r for r in map(json.loads, lines)}


def times(run: dict[str, dict[str, Any]]) -> str:
    ts = sorted(r["plan_time_s"] for r in run.values() if r.get("status") == "solved")
    p95 = ts[min(len(ts) - 1, int(0.95 * len(ts)))]
    return (f"solved {len(ts)}; plan time s median {statistics.median(ts):.3f}, p95 {p95:.3f}, "
            f"max {ts[-1]:.3f}")


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    a, b = rows(sys.argv[1]), rows(sys.argv[2])
    keys = sorted(set(a) | set(b))
    differ = [k for k in keys if k not in a or k not in b
              or any(a[k].get(f) != b[k].get(f) for f in FIELDS)]
    print(f"scenarios: {len(keys)}; identical status, costs and plans: {len(keys) - len(differ)}")
    for k in differ:
        fields = [f for f in FIELDS if k in a and k in b and a[k].get(f) != b[k].get(f)]
        print(f"  differs: {k}: {', '.join(fields) or 'missing in one run'}")
    print(f"run A: {times(a)}")
    print(f"run B: {times(b)}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
