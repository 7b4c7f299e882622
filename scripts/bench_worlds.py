"""Measure world loading, execution and checking speed (the numbers in docs/worlds.md).

    python scripts/bench_worlds.py [--json]

Builds all 120 ALFRED floor plans and all 200 benchmark worlds from ../shared/data, then times the
executor and the checker on the one-robot greedy plans of the feasible benchmark instances.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from collections import Counter


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print JSON")
    args = parser.parse_args(argv)

    from nl2hltl2plan.errors import Nl2Hltl2PlanError
    from nl2hltl2plan.suites.alfred.ground_truth import load_gt
    from nl2hltl2plan.worlds import check, execute
    from nl2hltl2plan.worlds.floor_plans import (
        alfred_data,
        benchmark_issues,
        build_benchmark_world,
        floor_plans,
        load_floor_plan,
    )
    from nl2hltl2plan.worlds.scripted import sequential_plan
    from nl2hltl2plan.worlds.starts import start_cells

    try:
        t0 = time.perf_counter()
        alfred_data()
        t_parse = time.perf_counter() - t0

        t0 = time.perf_counter()
        fp_worlds = [load_floor_plan(fp) for fp in floor_plans()]
        t_fp = time.perf_counter() - t0

        gts = load_gt()
        t0 = time.perf_counter()
        bench = [(g, build_benchmark_world(g)) for g in gts]
        t_bench = time.perf_counter() - t0
    except Nl2Hltl2PlanError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2

    plans = []
    for g, w in bench:
        if not benchmark_issues(w, g):
            plans.append((g, w, sequential_plan(w, g.tasks, g.before, start=start_cells(w, 1, gt=g)[0])))
    exec_ms, check_ms, steps, ok = [], [], [], 0
    for g, w, p in plans:
        t0 = time.perf_counter()
        for _ in range(10):
            ex = execute(w, p)
        exec_ms.append((time.perf_counter() - t0) * 100)
        t0 = time.perf_counter()
        res = check(ex, g)
        check_ms.append((time.perf_counter() - t0) * 1000)
        steps.append(sum(len(r.steps) for r in p.robots))
        ok += res.success
    per_100 = [ms / s * 100 for ms, s in zip(exec_ms, steps, strict=True)]

    unplaced = Counter(t for w in fp_worlds for t in w.unplaced)
    sizes = [(w.shape[0], w.shape[1]) for w in fp_worlds]
    out = {
        "parse_trials_s": round(t_parse, 2),
        "build_120_floor_plans_s": round(t_fp, 2),
        "build_200_benchmark_worlds_s": round(t_bench, 2),
        "grid_rows_range": [min(s[0] for s in sizes), max(s[0] for s in sizes)],
        "grid_cols_range": [min(s[1] for s in sizes), max(s[1] for s in sizes)],
        "free_cells_range": [min(len(w.cells) for w in fp_worlds), max(len(w.cells) for w in fp_worlds)],
        "objects_per_benchmark_world_median": statistics.median(
            sum(o.present for o in w.objects.values()) for _, w in bench
        ),
        "floor_plans_with_unreachable_objects": sum(1 for w in fp_worlds if w.unreachable),
        "floor_plans_disconnected": [w.name for w in fp_worlds if len(w.components) > 1],
        "unplaced_types_in_floor_plans": dict(unplaced.most_common()),
        "greedy_plans": len(plans),
        "greedy_plans_passing_checker": ok,
        "plan_steps_median": statistics.median(steps),
        "plan_steps_max": max(steps),
        "execute_ms_median": round(statistics.median(exec_ms), 3),
        "execute_ms_max": round(max(exec_ms), 3),
        "execute_ms_per_100_steps_median": round(statistics.median(per_100), 3),
        "check_ms_median": round(statistics.median(check_ms), 3),
        "check_ms_max": round(max(check_ms), 3),
    }
    if args.json:
        print(json.dumps(out, indent=2))
    else:
        for k, v in out.items():
            print(f"{k:40} {v}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
