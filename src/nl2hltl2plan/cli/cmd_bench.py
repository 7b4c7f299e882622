"""`nl2hltl2plan bench alfred --oracle --robots 1,2,4 [--n-base 1,2,3,4] [--limit N] [--workers K] --out DIR`

Plans every selected benchmark instance (ALFRED, ../shared/data/benchmark) for every team size,
from the spec a perfect translator would give (--oracle), executes each plan in the simulator and
judges it with the goal checker. Writes DIR/scenarios.jsonl (one JSON line per scenario; an
interrupted run resumes where it stopped unless --fresh) and DIR/summary.json, and prints a table
in the layout of the paper's Table I with the paper's numbers beside ours.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import PlanningError


def _ints(text: str) -> list[int]:
    try:
        values = [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected comma-separated integers, got {text!r}") from None
    if not values or any(v < 1 for v in values):
        raise argparse.ArgumentTypeError(f"expected positive integers, got {text!r}")
    return values


def register(sub: Any) -> None:
    p = sub.add_parser(
        "bench",
        help="benchmark the pipeline on ALFRED instances (Table I)",
        description=__doc__.split("\n\n")[1],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("suite", choices=["alfred"], help="benchmark suite")
    source = p.add_mutually_exclusive_group()
    source.add_argument("--oracle", action="store_true", help="plan from oracle specs (a perfect translator)")
    p.add_argument("--robots", type=_ints, default=[1, 2, 4], help="team sizes, e.g. 1,2,4 (default)")
    p.add_argument("--n-base", type=_ints, default=None, help="base-task counts to include (default: all)")
    p.add_argument("--limit", type=int, default=None, help="first N instances only (after --n-base)")
    p.add_argument("--draw", type=int, default=0, help="init_pos draw for the start cells (default 0)")
    p.add_argument("--workers", type=int, default=None, help="parallel worker processes (default: CPU cores)")
    p.add_argument("--objective", choices=["min", "minmax"], default="min")
    p.add_argument("--mode", choices=["fast", "exact"], default="fast")
    p.add_argument("--timeout", type=float, default=300.0, help="planner time limit per scenario in s (300)")
    p.add_argument("--fresh", action="store_true", help="start over instead of resuming DIR/scenarios.jsonl")
    p.add_argument("--quiet", action="store_true", help="no progress lines")
    p.add_argument("--out", type=Path, required=True, help="output folder")
    p.set_defaults(func=run, source_group=source)


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.evaluation.alfred import alfred_scenarios, oracle_job, preload
    from nl2hltl2plan.evaluation.report import format_table, summarize
    from nl2hltl2plan.evaluation.runner import run_scenarios

    if not args.oracle:
        raise PlanningError("choose where the specs come from: --oracle (perfect translations)")
    if args.limit is not None and args.limit < 1:
        raise PlanningError("--limit must be at least 1")
    preload()
    scenarios = alfred_scenarios(args.robots, args.n_base, args.limit, args.draw)
    if not scenarios:
        raise PlanningError("no benchmark instance matches --n-base/--limit")
    workers = args.workers or os.cpu_count() or 1
    out: Path = args.out
    job = oracle_job(objective=args.objective, mode=args.mode, timeout_s=args.timeout)

    def progress(row: dict, done: int, total: int) -> None:
        if args.quiet:
            return
        verdict = "ok" if row.get("success") else row.get("status", "?")
        t = row.get("plan_time_s")
        print(f"[{done}/{total}] {row['key']}: {verdict}" + (f" ({t:.2f} s)" if t is not None else ""),
              file=sys.stderr, flush=True)

    rows = run_scenarios(scenarios, job, out / "scenarios.jsonl", workers=workers,
                         hard_timeout_s=args.timeout + 60.0, resume=not args.fresh, progress=progress)
    summary = summarize(rows)
    summary["command"] = " ".join(["nl2hltl2plan", *sys.argv[1:]]) if sys.argv else ""
    summary["settings"] = {"objective": args.objective, "mode": args.mode, "timeout_s": args.timeout,
                           "robots": args.robots, "n_base": args.n_base, "limit": args.limit,
                           "draw": args.draw, "workers": workers}
    (out / "summary.json").write_text(json.dumps(summary, indent=2))
    title = (f"ALFRED benchmark, oracle specs, objective {args.objective}, mode {args.mode} "
             f"({len(rows)} scenarios, {workers} workers)")
    print(format_table(summary, title))
    print(f"wrote {out / 'summary.json'} and {out / 'scenarios.jsonl'}")
    return 0
