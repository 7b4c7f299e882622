"""This release against an earlier one, on the same scenarios, run alternately (A B B A A B ...).

Each side is a worker process (`planner_ab_worker.py`) with its own PYTHONPATH: A = this tree's
src/, B = the src/ of another checkout (make one with `git worktree add --detach ../h29-base 8daad2e`).
Both plan every scenario in fast mode with their defaults; per scenario the time ratio A/B (wall and
CPU), the cost ratio and both proven bounds are recorded. Ratios measured alternately on one machine
stay valid on a loaded machine; the absolute seconds do not.

Scenarios: valid_seen compositions (`planner_validation.scenarios`: 1-4 base tasks, their own
trials' objects, the world's default starts) x `--robots`, and, with `--pooled`, the pooled
FloorPlan7 instruction of `bench_planner_large.py` with its first k base tasks x `--pooled-robots`.

    python scripts/bench_planner_ab.py --base ../h29-base [--valid 12] [--robots 1,2,4]
        [--pooled 5-9] [--pooled-robots 4,10] [--fresh] [--jsonl out.jsonl] [--from-jsonl out.jsonl]
        [--out table.md]

`--fresh` starts a new worker per run (its peak memory is then the run's own).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_planner_large import pooled_instance  # noqa: E402
from bench_tables import add_run_file_arguments, append_jsonl, emit, emit_from_jsonl  # noqa: E402
from planner_validation import scenarios  # noqa: E402

from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world  # noqa: E402
from nl2hltl2plan.worlds.starts import start_cells  # noqa: E402

HERE = Path(__file__).resolve().parent
WORKER = HERE / "planner_ab_worker.py"


class Side:
    """A worker process planning with the code under `src`."""

    def __init__(self, name: str, src: Path, fresh: bool):
        self.name, self.src, self.fresh = name, src, fresh
        self.proc: subprocess.Popen[str] | None = None

    def run(self, job: dict[str, Any]) -> dict[str, Any]:
        if self.proc is None:
            env = dict(os.environ, PYTHONPATH=str(self.src), PYTHONHASHSEED="0")
            self.proc = subprocess.Popen([sys.executable, str(WORKER)], stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, text=True, env=env)
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(json.dumps(job) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if self.fresh:
            self.close()
        return json.loads(line) if line else {"status": "crashed", "reason": "worker died"}

    def close(self) -> None:
        if self.proc is not None:
            assert self.proc.stdin is not None
            self.proc.stdin.close()
            self.proc.wait(timeout=60)
            self.proc = None


def jobs(n_valid: int, robots: list[int], pooled: list[int],
         pooled_robots: list[int]) -> list[dict[str, Any]]:
    out = []
    for gt, world in scenarios(n_valid, 0, sizes=(1, 2, 3, 4)):
        for k in robots:
            out.append({"id": gt.id, "tasks": gt.n_base, "robots": k, "gt": gt.model_dump(mode="json"),
                        "starts": [list(c) for c in start_cells(world, k)]})
    for k in pooled:
        gt = pooled_instance("FloorPlan7", k, 0)
        if gt is None:
            continue
        world = build_benchmark_world(gt)
        if benchmark_issues(world, gt):
            continue
        for n in pooled_robots:
            out.append({"id": gt.id, "tasks": k, "robots": n, "gt": gt.model_dump(mode="json"),
                        "starts": [list(c) for c in start_cells(world, n, gt=gt)]})
    return out


def measure(todo: list[dict[str, Any]], a: Side, b: Side, out: str | None) -> list[dict[str, Any]]:
    rows = []
    for i, job in enumerate(todo):
        order = (a, b) if i % 2 == 0 else (b, a)  # A B, then B A: neither side always runs first
        got = {side.name: side.run(job) for side in order}
        row = {k: job[k] for k in ("id", "tasks", "robots")} | {"A": got["A"], "B": got["B"]}
        rows.append(row)
        append_jsonl(out, row)
        ra, rb = got["A"], got["B"]
        print(f"{job['id']:<40} {job['tasks']} x {job['robots']:>2}: A {ra.get('wall_s', 0):7.2f} s "
              f"cost {ra.get('total_cost')} | B {rb.get('wall_s', 0):7.2f} s cost {rb.get('total_cost')}",
              file=sys.stderr, flush=True)
    return rows


def _ratios(sel: list[dict[str, Any]], field: str) -> list[float]:
    return [r["A"][field] / r["B"][field] for r in sel if r["B"].get(field)]


def _solved(r: dict[str, Any]) -> bool:
    return r["A"].get("status") == "solved" and r["B"].get("status") == "solved"


def table(rows: list[dict[str, Any]]) -> list[str]:
    out = ["| base tasks | robots | runs | time ratio A/B (median, max) | CPU ratio A/B (median, max) "
           "| cost A vs B (lower, equal, higher) | cost ratio A/B (sum) | A within 5 % | B within 5 % "
           "| A time s (median, max) | B time s (median, max) |", "|" + " --- |" * 11]
    groups = sorted({(r["tasks"], r["robots"]) for r in rows}) + [("all", "all")]
    for key in groups:
        sel = [r for r in rows if key == ("all", "all") or (r["tasks"], r["robots"]) == key]
        both = [r for r in sel if _solved(r)]
        t, c = _ratios(both, "wall_s"), _ratios(both, "cpu_s")
        ca = [r["A"]["total_cost"] for r in both]
        cb = [r["B"]["total_cost"] for r in both]
        pairs = list(zip(ca, cb, strict=True))
        cmp = (sum(x < y for x, y in pairs), sum(x == y for x, y in pairs), sum(x > y for x, y in pairs))

        def within(side: str, sel: list[dict[str, Any]] = both) -> str:
            return f"{sum((r[side].get('bound') or 9) <= 1.05 for r in sel)}/{len(sel)}"

        def times(side: str, sel: list[dict[str, Any]] = both) -> str:
            ts = [r[side]["wall_s"] for r in sel]
            return f"{statistics.median(ts):.2f}, {max(ts):.2f}" if ts else "-"

        out.append(f"| {key[0]} | {key[1]} | {len(sel)} | "
                   + (f"{statistics.median(t):.2f}, {max(t):.2f} | "
                      f"{statistics.median(c):.2f}, {max(c):.2f} | " if t else "- | - | ")
                   + f"{cmp[0]}, {cmp[1]}, {cmp[2]} | {sum(ca) / max(1, sum(cb)):.3f} | {within('A')} "
                   f"| {within('B')} | {times('A')} | {times('B')} |")
    unsolved = [f"{r['id']} x {r['robots']}: A {r['A'].get('status')}, B {r['B'].get('status')}"
                for r in rows if not _solved(r)]
    if unsolved:
        out.append("")
        out.append("not solved by both (left out of the ratios): " + "; ".join(unsolved))
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--base", default=None, help="the other checkout (its src/ is side B)")
    ap.add_argument("--valid", type=int, default=12, help="valid_seen scenarios, 1-4 base tasks (12)")
    ap.add_argument("--robots", default="1,2,4")
    ap.add_argument("--pooled", default="", help="pooled FloorPlan7 sizes, a range lo-hi (none)")
    ap.add_argument("--pooled-robots", default="4,10")
    ap.add_argument("--fresh", action="store_true", help="a new worker process per run")
    add_run_file_arguments(ap, unit="scenario")
    args = ap.parse_args()
    if emit_from_jsonl(args, table):
        return 0
    if not args.base or not (Path(args.base) / "src" / "nl2hltl2plan").is_dir():
        print(f"error: --base must be a checkout with src/nl2hltl2plan, got {args.base!r}", file=sys.stderr)
        return 2
    pooled = []
    if args.pooled:
        lo, hi = (int(x) for x in args.pooled.split("-"))
        pooled = list(range(lo, hi + 1))
    todo = jobs(args.valid, [int(x) for x in args.robots.split(",") if x], pooled,
                [int(x) for x in args.pooled_robots.split(",")])
    a = Side("A", HERE.parent / "src", args.fresh)
    b = Side("B", Path(args.base).resolve() / "src", args.fresh)
    try:
        rows = measure(todo, a, b, args.jsonl)
    finally:
        a.close()
        b.close()
    emit(table(rows), args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
