"""Large instances: 5-9 base tasks for 10 robots, built from the benchmark's own tasks.

For a floor plan with several benchmark instances, the base tasks of all its (feasible) instances
are pooled into one instruction on one world (the union of their ALFRED trials), tasks the world
cannot provide are dropped, the first k are kept with their `before` relations plus a few random
extra orderings (seeded), and the 10 robots start at the first instance's first init_pos draw.
Each instance is planned with oracle specs in both objectives and checked with the goal checker.

    python scripts/bench_planner_large.py [--timeout 300] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import sys
from collections import Counter

from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.suites.alfred.ground_truth import load_gt
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world
from nl2hltl2plan.worlds.starts import start_cells
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.world import sliced_type

SCENES = ["FloorPlan7", "FloorPlan310", "FloorPlan427", "FloorPlan19", "FloorPlan322", "FloorPlan8",
          "FloorPlan27"]
SIZES = [5, 6, 7, 8, 9]


def pooled_instance(scene: str, k: int, seed: int) -> GTInstance | None:
    insts = [g for g in load_gt() if g.scene == scene and g.feasible]
    tasks, before, trials = [], [], []
    for n, g in enumerate(insts):
        ren = {t.id: f"T{n}{t.id}" for t in g.tasks}
        tasks += [t.model_copy(update={"id": ren[t.id]}) for t in g.tasks]
        before += [(ren[a], ren[b]) for a, b in g.before]
        trials += [t for t in g.source_trials if t not in trials]
    draft = GTInstance(id=f"{scene}.pooled", scene=scene, tasks=tasks, before=before, source_trials=trials,
                       init_pos=insts[0].init_pos)
    world = build_benchmark_world(draft)
    ok, used = [], Counter()
    for t in tasks:  # tasks the world can do, each with objects of its own (distinct instances)
        types = [sliced_type(o) if t.sliced else o for o in t.object]
        short = len(types) == 1 and used[types[0]] + t.count > len(world.instances(types[0]))
        if t.missing(world) or short:
            continue
        ok.append(t)
        used[types[0]] += t.count
    if len(ok) < k:
        return None
    keep = ok[:k]
    ids = {t.id for t in keep}
    rel = [(a, b) for a, b in before if a in ids and b in ids]
    rng = random.Random(seed)
    order = [t.id for t in keep]
    for _ in range(2 if k >= 2 else 0):  # a couple of extra orderings, consistent with the list order
        i, j = sorted(rng.sample(range(k), 2))
        if (order[i], order[j]) not in rel:
            rel.append((order[i], order[j]))
    return GTInstance(id=f"{scene}.pooled{k}", scene=scene, n_base=k, tasks=keep, before=rel,
                      source_trials=trials, init_pos=insts[0].init_pos)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--robots", type=int, default=10)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    rows = []
    head = (f"{'instance':<24} {'tasks':>5} {'leaves':>6} {'actions':>7} {'objective':>9} {'status':>8} "
            f"{'time s':>7} {'travel m':>8} {'steps':>5} {'robots used':>11} {'bound':>6} {'check':>6}")
    print(head)
    print("-" * len(head))
    for seed, scene in enumerate(SCENES):
        for k in SIZES:
            gt = pooled_instance(scene, k, seed)
            if gt is None:
                continue
            world = build_benchmark_world(gt)
            if benchmark_issues(world, gt):
                continue
            spec = oracle_spec(gt, world).spec
            starts = start_cells(world, args.robots, gt=gt)
            actions = sum(len(spec.leaf_actions(n) or []) for n in spec.leaves)
            for objective in ("min", "minmax"):
                r = plan(world, spec, starts, objective=objective, timeout_s=args.timeout)
                ok = r.solved and check(r.execution, gt).success
                used = len({e.robot for e in r.events})
                row = {"instance": gt.id, "tasks": k, "leaves": len(spec.leaves), "actions": actions,
                       "objective": objective, "status": r.status, "time_s": round(r.plan_time_s, 3),
                       "travel_m": r.travel_m, "steps": r.steps, "robots_used": used,
                       "bound": None if r.bound is None else round(r.bound, 3), "success": ok,
                       "before": [list(p) for p in gt.before]}
                rows.append(row)
                print(f"{gt.id:<24} {k:>5} {len(spec.leaves):>6} {actions:>7} {objective:>9} {r.status:>8} "
                      f"{r.plan_time_s:>7.2f} {r.travel_m if r.travel_m is not None else '-':>8} "
                      f"{r.steps if r.steps is not None else '-':>5} {used:>11} "
                      f"{'-' if r.bound is None else f'{r.bound:.2f}':>6} {'ok' if ok else 'FAIL':>6}",
                      flush=True)
    times = [r["time_s"] for r in rows]
    print("-" * len(head))
    print(f"{len(rows)} runs, {sum(r['success'] for r in rows)} solved and checked; planning time s: "
          f"median {statistics.median(times):.2f}, max {max(times):.2f}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(rows, fh, indent=1)
    return 0 if all(r["success"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
