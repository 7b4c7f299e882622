"""Experiment: does the tiled LP bound (`planning/lp_bound.py`) raise the root bound and prove more?

On valid_seen scenarios (`planner_validation.scenarios`, 3-4 base tasks) x robots, the root's bound
with and without the LP, and fast mode's proven bound and time with and without it.

    python scripts/bench_planner_lp.py [--instances 20] [--robots 1,2,4]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from planner_validation import scenarios  # noqa: E402

from nl2hltl2plan.planning import heuristic, oracle_spec, plan  # noqa: E402
from nl2hltl2plan.planning.model import build_problem, required_leaves  # noqa: E402
from nl2hltl2plan.planning.navigation import Navigator  # noqa: E402
from nl2hltl2plan.planning.state import Expander  # noqa: E402
from nl2hltl2plan.worlds.starts import start_cells  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--instances", type=int, default=20)
    ap.add_argument("--robots", default="1,2,4")
    args = ap.parse_args()
    raised = runs = 0
    proofs = {False: 0, True: 0}
    times = {False: 0.0, True: 0.0}
    for gt, world in scenarios(args.instances, 0):
        spec = oracle_spec(gt, world).spec
        for k in (int(x) for x in args.robots.split(",")):
            problem = build_problem(world, spec, start_cells(world, k))
            x = Expander(problem, Navigator(world))
            required = {problem.leaf_index[n] for n in required_leaves(problem)}
            roots = []
            for tiled in (False, True):
                h = heuristic.Heuristic(x, required, makespan=False)
                h.tiled_root = tiled
                roots.append(h.evaluate(x.root())[0])
            finals = []
            for tiled in (False, True):
                heuristic.Heuristic.tiled_root = tiled  # the class default the planner's heuristic reads
                t0 = time.process_time()
                r = plan(world, spec, start_cells(world, k), timeout_s=120)
                times[tiled] += time.process_time() - t0
                proofs[tiled] += bool(r.solved and r.bound is not None and r.bound <= 1.05)
                finals.append(f"{r.lower_bound:g}/{r.model_cost:g}")
            runs += 1
            raised += roots[1] > roots[0]
            print(f"{gt.id} x {k}: root {roots[0]} -> {roots[1]}; fast lb/cost {finals[0]} -> {finals[1]}",
                  flush=True)
    print(f"root bound raised in {raised} of {runs}; proven within 5 %: {proofs[False]} without, "
          f"{proofs[True]} with; CPU s {times[False]:.1f} without, {times[True]:.1f} with")
    return 0


if __name__ == "__main__":
    sys.exit(main())
