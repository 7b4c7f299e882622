"""One side of `bench_planner_ab.py`: plans the jobs it reads on stdin with the planner on ITS OWN
PYTHONPATH (this tree or an older commit's), one JSON line out per job.

A job: {"gt": <a GTInstance as JSON>, "starts": [[r, c], ...]}. The world and the oracle spec are built
by the side's own code (`build_benchmark_world`, `oracle_spec`, which both releases have), so each
side plans what its own release would plan. Only calls that every release since 8daad2e has are used.
"""

from __future__ import annotations

import json
import resource
import sys
import time
from typing import Any


def _robot_and_atom(event: Any) -> list[Any]:
    """[robot, atom] of a planner event: a typed `PlanEvent` today, a dict in 8daad2e."""
    if isinstance(event, dict):
        return [event["robot"], event["atom"]]
    return [event.robot, event.atom]


def run(job: dict) -> dict:
    from nl2hltl2plan.planning import oracle_spec, plan

    try:
        from nl2hltl2plan.worlds.floor_plans import build_benchmark_world
    except ImportError:  # releases before the issue-26 moves (8daad2e) named the module worlds.alfred
        from nl2hltl2plan.worlds.alfred import build_benchmark_world  # type: ignore[no-redef]

    world = build_benchmark_world(job["gt"])
    spec = oracle_spec(job["gt"], world).spec
    starts = [tuple(c) for c in job["starts"]]
    wall, cpu = time.perf_counter(), time.process_time()
    r = plan(world, spec, starts, timeout_s=job.get("timeout", 300.0))
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    return {"status": str(r.status), "total_cost": r.total_cost, "bound": r.bound,
            "proven_optimal": bool(r.proven_optimal), "wall_s": wall, "cpu_s": cpu,
            "events": [_robot_and_atom(e) for e in r.events],
            "max_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def main() -> int:
    for line in sys.stdin:
        try:
            out = run(json.loads(line))
        except Exception as exc:  # reported to the driver, which names the scenario
            out = {"status": "crashed", "reason": f"{type(exc).__name__}: {exc}"}
        print(json.dumps(out), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
