"""Scaling: 1-9 base tasks x 1-10 robots, fast mode (and exact where asked), summed cost.

Instances as in bench_planner_large.py: for each floor plan, the base tasks of all its benchmark
instances pooled into one instruction on one world, the first k kept with their `before` relations
plus two seeded extra orderings; robots start at the first instance's init_pos (first draw).

    python scripts/bench_planner_scaling.py [--scenes 3] [--tasks 1-9] [--robots 1,2,4,10]
        [--exact-upto 0] [--exact-timeout 60] [--jsonl out.jsonl] [--from-jsonl out.jsonl] [--out table.md]

Prints per (base tasks, robots): runs, solved and checked, planning time (median / max), proven
optimal share, proven within 5 % (bound <= 1.05), proven bound (median / max), peak search nodes and
their estimated memory.
"""

from __future__ import annotations

import argparse
import resource
import statistics
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_planner_large import SCENES, pooled_instance  # noqa: E402
from bench_tables import add_run_file_arguments, append_jsonl, emit, emit_from_jsonl  # noqa: E402

from nl2hltl2plan.planning import oracle_spec, plan  # noqa: E402
from nl2hltl2plan.worlds.checker import check  # noqa: E402
from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world  # noqa: E402
from nl2hltl2plan.worlds.starts import start_cells  # noqa: E402


def run(scenes: list[str], sizes: list[int], robots: list[int], exact_upto: int,
        exact_timeout: float, out: str | None) -> list[dict[str, Any]]:
    rows = []
    for seed, scene in enumerate(scenes):
        for k in sizes:
            gt = pooled_instance(scene, k, seed)
            if gt is None:
                continue
            world = build_benchmark_world(gt)
            if benchmark_issues(world, gt):
                continue
            spec = oracle_spec(gt, world).spec
            for n in robots:
                modes = ["fast"] + (["exact"] if k <= exact_upto else [])
                for mode in modes:
                    cpu0 = time.process_time()
                    r = plan(world, spec, start_cells(world, n, gt=gt), mode=mode,
                             timeout_s=exact_timeout if mode == "exact" else 300.0)
                    cpu = time.process_time() - cpu0
                    # the process's peak so far: a run's own peak when it is the first (--tasks k-k)
                    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
                    rows.append({
                        "instance": gt.id, "tasks": k, "robots": n, "mode": mode, "status": str(r.status),
                        "success": bool(r.solved and check(r.execution, gt).success), "time_s": r.plan_time_s,
                        "cost": r.total_cost, "bound": r.bound, "proven": r.proven_optimal,
                        "peak_nodes": r.peak_nodes, "memory_mb": r.memory_mb, "stopped": str(r.stopped),
                        "cpu_s": cpu, "rss_mb": rss_mb})
                    append_jsonl(out, rows[-1])
                    print(".", end="", flush=True, file=sys.stderr)
    print(file=sys.stderr)
    return rows


def table(rows: list[dict[str, Any]]) -> list[str]:
    out = ["| mode | base tasks | robots | runs | solved + checked | time s (median, max) | CPU s (max) "
           "| proven optimal | proven within 5 % | bound (median, max) | peak nodes (max) "
           "| search memory MB (max, est.) | process peak RSS MB |",
           "|" + " --- |" * 13]
    for key in sorted({(r["mode"], r["tasks"], r["robots"]) for r in rows}):
        sel = [r for r in rows if (r["mode"], r["tasks"], r["robots"]) == key]
        times = [r["time_s"] for r in sel]
        bounds = [r["bound"] for r in sel if r["bound"] is not None]
        out.append(f"| {key[0]} | {key[1]} | {key[2]} | {len(sel)} | {sum(r['success'] for r in sel)} "
                   f"| {statistics.median(times):.2f}, {max(times):.2f} "
                   f"| {max(r.get('cpu_s', float('nan')) for r in sel):.2f} "
                   f"| {sum(r['proven'] for r in sel)}/{len(sel)} "
                   f"| {sum(b <= 1.05 for b in bounds)}/{len(sel)} "
                   f"| {statistics.median(bounds) if bounds else float('nan'):.3f}, "
                   f"{max(bounds, default=float('nan')):.3f} | {max(r['peak_nodes'] for r in sel)} "
                   f"| {max(r['memory_mb'] for r in sel):.0f} "
                   f"| {max(r.get('rss_mb', float('nan')) for r in sel):.0f} |")
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", type=int, default=3, help="floor plans used (default 3)")
    ap.add_argument("--tasks", default="1-9", help="base-task counts, a range lo-hi (default 1-9)")
    ap.add_argument("--robots", default="1,2,4,10", help="team sizes (default 1,2,4,10)")
    ap.add_argument("--exact-upto", type=int, default=0, help="also run exact mode up to this many tasks (0)")
    ap.add_argument("--exact-timeout", type=float, default=60.0,
                    help="exact mode's wall-clock last resort (60 s)")
    add_run_file_arguments(ap)
    args = ap.parse_args()
    if emit_from_jsonl(args, table):
        return 0
    lo, hi = (int(x) for x in args.tasks.split("-"))
    rows = run(SCENES[: args.scenes], list(range(lo, hi + 1)), [int(x) for x in args.robots.split(",")],
               args.exact_upto, args.exact_timeout, args.jsonl)
    emit(table(rows), args.out)
    return 0 if all(r["success"] for r in rows if r["status"] == "solved") else 1


if __name__ == "__main__":
    sys.exit(main())
