"""Choose fast mode's stall stop (`api.FAST_STALL_WORK`, `STALL_SHARE`, `STALL_NEAR`) on valid_seen scenarios.

Plans the valid_seen 3-4 task scenarios of `planner_validation.py` in fast mode with the stall stop
off, recording its first plan's cost, when the A*'s proven bound rose (in units of heuristic work)
and when it found a cheaper plan; then replays each candidate (min work, share, near: the stop waits
while the plan is within `near` objective units of its bound) on the recordings: where would it have
stopped, which proofs (within 5 %) and which later cheaper plans would it have lost, and how much A*
work would it have spent. Never reads the evaluation set.

    python scripts/planner_stall_replay.py [--instances 20] [--robots 1,2,4]
        [--min-work 20000,50000,100000] [--shares 0.5,0.667,0.75] [--nears 0,1,2,3]
        [--jsonl runs.jsonl | --replay runs.jsonl]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_tables import append_jsonl  # noqa: E402
from planner_validation import scenarios  # noqa: E402

from nl2hltl2plan.errors import Nl2Hltl2PlanError  # noqa: E402
from nl2hltl2plan.planning import oracle_spec, plan, search  # noqa: E402
from nl2hltl2plan.worlds.starts import start_cells  # noqa: E402


class Recorder:
    """Hooks on the A*: the work at each rise of its proven bound and at each cheaper plan."""

    def __init__(self) -> None:
        self.searcher: search.Searcher | None = None
        self.start = 0
        self.rises: list[tuple[int, int]] = []
        self.plans: list[tuple[int, float]] = []
        self.first_cost: float | None = None  # the incumbent the A* starts with
        self.work = 0

    def install(self) -> None:
        lower_bound, awa, found = search._lower_bound, search.Searcher.awa, search.Searcher.found
        rec = self

        def lower_bound_spy(heap: Any) -> int | None:
            value = lower_bound(heap)
            if rec.searcher is not None and value is not None and (not rec.rises or value > rec.rises[-1][1]):
                rec.rises.append((rec.searcher.h.work - rec.start, value))
            return value

        def awa_spy(self: search.Searcher, *args: Any, **kwargs: Any) -> Any:
            rec.searcher, rec.start, rec.rises, rec.plans = self, self.h.work, [], []
            incumbent = args[1] if len(args) > 1 else kwargs.get("incumbent")
            rec.first_cost = None if incumbent is None else float(self.cost(incumbent))
            try:
                return awa(self, *args, **kwargs)
            finally:
                rec.work, rec.searcher = self.h.work - rec.start, None

        def found_spy(self: search.Searcher, node: Any) -> None:
            if rec.searcher is self:
                rec.plans.append((self.h.work - rec.start, float(self.cost(node))))
            found(self, node)

        search._lower_bound = lower_bound_spy  # type: ignore[assignment]
        search.Searcher.awa = awa_spy  # type: ignore[method-assign]
        search.Searcher.found = found_spy  # type: ignore[method-assign]


def record(instances: int, robots: list[int], out: str | None) -> list[dict[str, Any]]:
    rec = Recorder()
    rec.install()
    runs = []
    for gt, world in scenarios(instances, 0):
        spec = oracle_spec(gt, world).spec
        for k in robots:
            try:
                # the stall stop off: every run keeps its whole budget
                r = plan(world, spec, start_cells(world, k), timeout_s=300, fast_stall_work=None)
            except Nl2Hltl2PlanError:
                continue
            if not r.solved or r.bound is None:
                continue
            runs.append({"id": gt.id, "robots": k, "bound": r.bound, "stopped": str(r.stopped),
                         "work": rec.work, "rises": rec.rises, "plans": rec.plans,
                         "first_cost": rec.first_cost})
            append_jsonl(out, runs[-1])
            print(".", end="", flush=True, file=sys.stderr)
    print(file=sys.stderr)
    return runs


def stop_at(run: dict[str, Any], min_work: int, share: float, near: float) -> float:
    """The work at which the stall stop would have ended this run (its own end if never). Its plan's
    distance to the bound only shrinks as the search goes (the bound rises, the plan gets cheaper),
    so once it is within `near` the stall stop never fires."""
    rises = run["rises"] or [(0, 0)]
    for i, (work, bound) in enumerate(rises):
        following = rises[i + 1][0] if i + 1 < len(rises) else float("inf")
        stop = max(min_work, work / (1 - share))  # spent - last_rise >= share * spent
        if stop < following:
            cost = min([run["first_cost"]] + [c for w, c in run["plans"] if w <= stop])
            return min(stop, run["work"]) if cost - bound > near else run["work"]
    return run["work"]


def replay(runs: list[dict[str, Any]], min_works: list[int], shares: list[float],
           nears: list[float]) -> list[str]:
    total = sum(r["work"] for r in runs)
    proven = sum(r["bound"] <= 1.05 for r in runs)
    out = [f"{len(runs)} runs, {proven} proven within 5 %, A* work {total:,} units without the stall stop",
           "", "| min work | share | near | A* work | proofs lost | cheaper plans lost |", "|" + " --- |" * 6]
    for min_work in min_works:
        for share in shares:
            for near in nears:
                stops = [stop_at(r, min_work, share, near) for r in runs]
                cut = [s < r["work"] for r, s in zip(runs, stops, strict=True)]
                lost = [f"{r['id']} x {r['robots']}" for r, c in zip(runs, cut, strict=True)
                        if c and r["bound"] <= 1.05 and r["stopped"] != "budget"]
                later = [f"{r['id']} x {r['robots']}" for r, s in zip(runs, stops, strict=True)
                         if any(w > s for w, _ in r["plans"])]
                out.append(f"| {min_work:,} | {share:.3g} | {near:g} | {int(sum(stops)):,} | {len(lost)} "
                           f"{', '.join(lost)} | {len(later)} {', '.join(later)} |")
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--instances", type=int, default=20)
    ap.add_argument("--robots", default="1,2,4")
    ap.add_argument("--min-work", default="20000,50000,100000")
    ap.add_argument("--shares", default="0.5,0.667,0.75")
    ap.add_argument("--nears", default="0,1,2,3",
                    help="objective units: the stop waits while the plan is this close to its bound")
    ap.add_argument("--jsonl", default=None, help="also append the recorded runs here")
    ap.add_argument("--replay", default=None, help="replay the runs recorded here, not plan")
    args = ap.parse_args()
    if args.replay:
        runs = [json.loads(line) for line in Path(args.replay).read_text().splitlines() if line.strip()]
    else:
        runs = record(args.instances, [int(x) for x in args.robots.split(",")], args.jsonl)
    floats = [[float(x) for x in arg.split(",")] for arg in (args.min_work, args.shares, args.nears)]
    print("\n".join(replay(runs, [int(x) for x in floats[0]], floats[1], floats[2])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
