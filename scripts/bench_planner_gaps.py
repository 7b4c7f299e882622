"""Where fast mode's proofs fail on the valid_seen planning scenarios: a loose bound or a poor plan.

Every scenario of `scripts/planner_validation.py` (ALFRED valid_seen compositions of 3-4 base
tasks; never test50) is planned with each team size in fast mode, then in exact mode with a node
limit (`--exact-nodes`: the duplicate table and open list together; a count, so the outcome does not
depend on the machine; `--exact-timeout` is only a last resort). Each run is then one of:

- `proven`: fast mode proved its plan within 5 % (bound <= 1.05);
- `loose bound`: not proven, but exact mode proved an optimum within 5 % of fast mode's plan, so
  only the lower bound was missing;
- `poor plan`: exact mode proved an optimum more than 5 % below fast mode's plan;
- `open`: exact mode proved no optimum within its node limit.

    python scripts/bench_planner_gaps.py [--instances 20] [--robots 1,2,4] [--exact-nodes 150000]
        [--jsonl runs.jsonl] [--from-jsonl runs.jsonl] [--out table.md]

Prints per (base tasks, robots) the counts of each outcome, fast mode's root bound, proven bound and
the optimum summed over the runs with a proven optimum (how much of the gap the search closes and
how much is left), the runs whose root or proven bound exceeds the optimum (a bound that is not
one: there should be none), then one line per run that is not proven.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_tables import add_run_file_arguments, append_jsonl, emit, emit_from_jsonl  # noqa: E402
from planner_validation import scenarios  # noqa: E402

from nl2hltl2plan.planning import oracle_spec, plan  # noqa: E402
from nl2hltl2plan.planning.heuristic import Heuristic  # noqa: E402
from nl2hltl2plan.planning.model import build_problem, required_leaves  # noqa: E402
from nl2hltl2plan.planning.navigation import Navigator  # noqa: E402
from nl2hltl2plan.planning.state import Expander  # noqa: E402
from nl2hltl2plan.worlds.starts import start_cells  # noqa: E402
from nl2hltl2plan.worlds.world import World  # noqa: E402

GAP = 1.05
OUTCOMES = ("proven", "loose bound", "poor plan", "open")


def root_bound(world: World, spec: Any, starts: list) -> int:
    """Fast mode's first lower bound: the full heuristic at the root (before any search)."""
    problem = build_problem(world, spec, starts, None)
    x = Expander(problem, Navigator(world))
    h = Heuristic(x, {problem.leaf_index[n] for n in required_leaves(problem)}, makespan=False)
    root = x.root()
    return root.g + h.evaluate(root)[0]


def outcome(row: dict[str, Any]) -> str:
    if row["bound"] is not None and row["bound"] <= GAP:
        return "proven"
    if row["optimum"] is None:
        return "open"
    return "loose bound" if row["cost"] <= GAP * row["optimum"] else "poor plan"


def measure(n: int, robots: list[int], exact_nodes: int, exact_timeout: float,
            jsonl: str | None) -> list[dict[str, Any]]:
    rows = []
    for gt, world in scenarios(n, 0):
        spec = oracle_spec(gt, world).spec
        for k in robots:
            starts = start_cells(world, k)
            t0 = time.perf_counter()
            fast = plan(world, spec, starts, timeout_s=300)
            fast_s = time.perf_counter() - t0
            if not fast.solved:
                continue
            exact = plan(world, spec, starts, mode="exact", max_nodes=exact_nodes, timeout_s=exact_timeout)
            row = {"id": gt.id, "n_base": gt.n_base, "robots": k, "cost": fast.model_cost,
                   "lower_bound": fast.lower_bound, "bound": fast.bound,
                   "root": root_bound(world, spec, starts), "time_s": round(fast_s, 3),
                   "stopped": str(fast.stopped),
                   "optimum": exact.model_cost if exact.proven_optimal else None,
                   "exact_lower_bound": exact.lower_bound, "exact_stopped": str(exact.stopped)}
            row["outcome"] = outcome(row)
            append_jsonl(jsonl, row)
            print(row, file=sys.stderr, flush=True)
            rows.append(row)
    return rows


def table(rows: list[dict[str, Any]]) -> list[str]:
    out = ["| base tasks | robots | runs | " + " | ".join(OUTCOMES) + " | with an optimum: root bound, "
           "fast's bound, optimum, fast's plan (sums) | a bound above the optimum (a bug) |",
           "|" + " --- |" * (5 + len(OUTCOMES))]
    groups = sorted({(r["n_base"], r["robots"]) for r in rows})
    for key in [*groups, None]:
        sel = [r for r in rows if key is None or (r["n_base"], r["robots"]) == key]
        known = [r for r in sel if r["optimum"] is not None]
        sums = ", ".join(f"{sum(r[f] for r in known):.0f}"
                         for f in ("root", "lower_bound", "optimum", "cost"))
        label = ("all", "all") if key is None else key
        counts = " | ".join(str(sum(r["outcome"] == o for r in sel)) for o in OUTCOMES)
        above = sum(max(r["root"], r["lower_bound"]) > r["optimum"] for r in known)
        out.append(f"| {label[0]} | {label[1]} | {len(sel)} | {counts} | {sums} ({len(known)} runs) "
                   f"| {above} |")
    out += ["", "| scenario | robots | outcome | root bound | fast's bound | optimum (exact) | fast's plan "
            "| fast stopped |", "|" + " --- |" * 8]
    for r in rows:
        if r["outcome"] != "proven":
            opt = f"{r['optimum']:.0f}" if r["optimum"] is not None else f">= {r['exact_lower_bound']:.0f}"
            out.append(f"| {r['id']} | {r['robots']} | {r['outcome']} | {r['root']} | {r['lower_bound']:.0f} "
                       f"| {opt} | {r['cost']:.0f} | {r['stopped']} |")
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--instances", type=int, default=20)
    ap.add_argument("--robots", default="1,2,4")
    ap.add_argument("--exact-nodes", type=int, default=150_000)
    ap.add_argument("--exact-timeout", type=float, default=120.0)
    add_run_file_arguments(ap)
    args = ap.parse_args()
    if emit_from_jsonl(args, table):
        return 0
    robots = [int(k) for k in args.robots.split(",")]
    emit(table(measure(args.instances, robots, args.exact_nodes, args.exact_timeout, args.jsonl)), args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
