"""Choose fast mode's search budgets on planning scenarios that are NOT the evaluation set.

The scenarios come from ALFRED's valid_seen split: the text-faithful compositions of the language
validation (`suites.alfred.learned_validation`: 1-4 base tasks from one floor plan, fixed seed), turned into
ground-truth-like instances (their own trials place the objects, the world's default start cells),
keeping the 3- and 4-task ones the world can do. Neither `benchmark/alfred_test50_gt.jsonl` nor an
excluded trial is read. Each candidate budget (A* expansions / generated successors) plans every
scenario in fast mode; the table gives the share proven optimal and proven within 5 % and the
planning time.

The rule, fixed before measuring: the largest candidate whose p95 planning time is <= 5 s (the
project's p95 target); if none, the smallest. `planning/api.py`'s FAST_EXPANSIONS / FAST_GENERATED
/ FAST_WORK hold the chosen one.

    python scripts/planner_validation.py [--instances 30] [--robots 1,2,4]
        [--budgets 300/5000,1000/10000,3000/30000]   # expansions / generated [/ work]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.learned.faithful import compose_faithful
from nl2hltl2plan.planning import api, oracle_spec, plan
from nl2hltl2plan.suites.alfred.learned_validation import faithful_split
from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world
from nl2hltl2plan.worlds.starts import start_cells
from nl2hltl2plan.worlds.tasks import BaseTask, GTInstance
from nl2hltl2plan.worlds.world import World


def scenarios(n: int, seed: int, sizes: tuple[int, ...] = (3, 4)) -> list[tuple[GTInstance, World]]:
    """The first `n` feasible valid_seen compositions with `sizes` base tasks (3 and 4), with their
    worlds."""
    comps = compose_faithful(list(faithful_split("valid_seen")), 8 * n, seed)
    out: list[tuple[GTInstance, World]] = []
    for i, c in enumerate(comps):
        if len(c.tasks) not in sizes:
            continue
        gt = GTInstance(id=f"{c.scene}#v{i}", scene=c.scene, n_base=len(c.tasks),
                        tasks=[BaseTask.model_validate(t.model_dump()) for t in c.tasks],
                        before=c.before, source_trials=sorted(set(c.trials)))
        try:
            world = build_benchmark_world(gt)
        except Nl2Hltl2PlanError:
            continue
        if benchmark_issues(world, gt):
            continue
        out.append((gt, world))
        if len(out) == n:
            break
    return out


def measure(cases: list[tuple[GTInstance, World]], robots: list[int], expansions: int,
            generated: int, work: int) -> dict[str, float]:
    api.FAST_GENERATED = generated  # the generated-successor budget that goes with `fast_expansions`
    times: list[float] = []
    bounds: list[float] = []
    for gt, world in cases:
        spec = oracle_spec(gt, world).spec
        for k in robots:
            t0 = time.perf_counter()
            r = plan(world, spec, start_cells(world, k), fast_expansions=expansions, fast_work=work,
                     timeout_s=120)
            times.append(time.perf_counter() - t0)
            if r.solved:
                bounds.append(r.bound)
    q = statistics.quantiles(times, n=20, method="inclusive")
    return {"runs": len(times), "solved": len(bounds), "optimal": sum(b <= 1.0 + 1e-9 for b in bounds),
            "within5": sum(b <= 1.05 for b in bounds), "median": statistics.median(times),
            "p95": q[18], "max": max(times)}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--instances", type=int, default=30)
    ap.add_argument("--robots", default="1,2,4")
    ap.add_argument("--budgets", default="300/5000,1000/10000,3000/30000")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    robots = [int(x) for x in args.robots.split(",")]
    budgets = [(*(int(v) for v in b.split("/")), api.FAST_WORK)[:3] for b in args.budgets.split(",")]
    cases = scenarios(args.instances, args.seed)
    n3 = sum(gt.n_base == 3 for gt, _ in cases)
    n4 = len(cases) - n3
    print(f"{len(cases)} valid_seen scenarios ({n3} with 3 tasks, {n4} with 4) x robots {robots}")
    print("| budget (expansions / generated / work) | runs | solved | proven optimal | proven within 5 % "
          "| time s (median, p95, max) |\n| --- | --- | --- | --- | --- | --- |")
    chosen = budgets[0]
    for exp, gen, work in budgets:
        m = measure(cases, robots, exp, gen, work)
        print(f"| {exp} / {gen} / {work} | {m['runs']} | {m['solved']} | {m['optimal']} "
              f"({m['optimal'] / m['runs']:.0%}) | {m['within5']} ({m['within5'] / m['runs']:.0%}) "
              f"| {m['median']:.2f}, {m['p95']:.2f}, {m['max']:.2f} |", flush=True)
        if m["p95"] <= 5.0:
            chosen = (exp, gen, work)
    print(f"chosen by the rule (largest with p95 <= 5 s): {' / '.join(map(str, chosen))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
