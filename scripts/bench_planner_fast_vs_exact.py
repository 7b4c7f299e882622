"""Fast vs exact mode on the benchmark's oracle scenarios (summed cost; 1-2 base tasks by default,
`--n-base 3,4` for the larger ones), reproducibly.

Every scenario (instance x team size; start cells from init_pos, first draw) is planned from its
oracle spec in both modes, in this process, one after another. The planner's budgets count
expansions, so the numbers other than times are the same on every run and machine.

    python scripts/bench_planner_fast_vs_exact.py [--n-base 1,2] [--robots 1,2,4] [--limit N]
        [--exact-timeout 120] [--max-nodes 400000] [--jsonl out.jsonl]

Prints per (base tasks, robots): scenarios, exact proven optimal, fast equal to the proven optimum,
summed-cost ratio fast/exact and the worst ratio, fast proven within 5 % (bound <= 1.05), the
proven bounds of both modes (median / max), the planning times and exact's peak search nodes; a
fast plan cheaper than a proven optimum would be a bug and is reported.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
from typing import Any

from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.suites.alfred.ground_truth import load_gt
from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world
from nl2hltl2plan.worlds.starts import start_cells


def run(n_base: list[int], robots: list[int], limit: int | None, exact_timeout: float,
        max_nodes: int, out: str | None) -> list[dict[str, Any]]:
    insts = [g for g in load_gt() if g.n_base in n_base]
    rows = []
    for g in insts[:limit]:
        world = build_benchmark_world(g)
        if benchmark_issues(world, g):
            continue  # infeasible in our worlds (docs/worlds.md)
        spec = oracle_spec(g, world).spec
        for n in robots:
            starts = start_cells(world, n, gt=g)
            row: dict[str, Any] = {"id": g.id, "n_base": g.n_base, "robots": n}
            for mode in ("fast", "exact"):
                r = plan(world, spec, starts, mode=mode, timeout_s=exact_timeout if mode == "exact" else 300,
                         max_nodes=max_nodes)
                row[mode] = {k: getattr(r, k) for k in (
                    "status", "total_cost", "lower_bound", "bound", "proven_optimal", "plan_time_s",
                    "peak_nodes", "memory_mb", "stopped")}
                row[mode]["status"] = str(r.status)
            rows.append(row)
            if out:
                with open(out, "a") as fh:
                    fh.write(json.dumps(row) + "\n")
            print(".", end="", flush=True, file=sys.stderr)
    print(file=sys.stderr)
    return rows


def table(rows: list[dict[str, Any]]) -> list[str]:
    out = ["| base tasks | robots | scenarios | exact proven | fast = optimum "
           "| cost ratio fast/exact (sum, worst) | fast proven within 5 % "
           "| fast bound (median, max) | exact bound (median, max) | fast time s (median, max) "
           "| exact time s (median, max) | exact peak nodes (max) |", "|" + " --- |" * 12]
    groups = sorted({(r["n_base"], r["robots"]) for r in rows})
    for key in [*groups, None]:
        sel = [r for r in rows if key is None or (r["n_base"], r["robots"]) == key]
        solved = [r for r in sel if r["fast"]["status"] == "solved" and r["exact"]["status"] == "solved"]
        proven = [r for r in solved if r["exact"]["proven_optimal"]]
        ratio = [r["fast"]["total_cost"] / r["exact"]["total_cost"]
                 for r in proven if r["exact"]["total_cost"]]
        same = sum(r["fast"]["total_cost"] == r["exact"]["total_cost"] for r in proven)
        summed = (sum(r["fast"]["total_cost"] for r in proven)
                  / max(1, sum(r["exact"]["total_cost"] for r in proven)))
        bounds = [r["fast"]["bound"] for r in solved if r["fast"]["bound"] is not None]
        ebounds = [r["exact"]["bound"] for r in solved if r["exact"]["bound"] is not None]
        within = sum(b <= 1.05 for b in bounds)
        ft = [r["fast"]["plan_time_s"] for r in sel]
        et = [r["exact"]["plan_time_s"] for r in sel]
        label = ("all", "all") if key is None else key
        out.append(
            f"| {label[0]} | {label[1]} | {len(sel)} | {len(proven)}/{len(sel)} | {same}/{len(proven)} "
            f"| {summed:.4f}, {max(ratio, default=1):.3f} | {within}/{len(sel)} "
            f"| {_spread(bounds)} | {_spread(ebounds)} "
            f"| {statistics.median(ft):.2f}, {max(ft):.2f} | {statistics.median(et):.2f}, {max(et):.2f} "
            f"| {max(r['exact']['peak_nodes'] for r in sel)} |")
    bugs = [r["id"] for r in rows if r["exact"]["proven_optimal"] and r["fast"]["status"] == "solved"
            and r["fast"]["total_cost"] < r["exact"]["total_cost"]]
    if bugs:
        out.append("FAST CHEAPER THAN A PROVEN OPTIMUM: " + ", ".join(bugs))
    return out


def _spread(values: list[float]) -> str:
    if not values:
        return "-"
    return f"{statistics.median(values):.3f}, {max(values):.3f}"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n-base", default="1,2", help="base-task counts (default 1,2)")
    ap.add_argument("--robots", default="1,2,4", help="team sizes (default 1,2,4)")
    ap.add_argument("--limit", type=int, default=None, help="first N instances only (default: all)")
    ap.add_argument("--exact-timeout", type=float, default=120.0,
                    help="exact mode's wall-clock last resort (120 s)")
    ap.add_argument("--max-nodes", type=int, default=400_000,
                    help="the planner's memory bound, nodes held at once (deterministic; default 400000)")
    ap.add_argument("--jsonl", default=None, help="also append one JSON line per scenario to this file")
    args = ap.parse_args()
    rows = run([int(x) for x in args.n_base.split(",")], [int(x) for x in args.robots.split(",")], args.limit,
               args.exact_timeout, args.max_nodes, args.jsonl)
    print("\n".join(table(rows)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
