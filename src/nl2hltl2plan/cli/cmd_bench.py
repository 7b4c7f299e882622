"""`nl2hltl2plan bench alfred (--oracle | --llm offline|local|openai) --robots 1,2,4 --out DIR`

Runs every selected benchmark instance (ALFRED, ../shared/data/benchmark, or --gt FILE with the same
schema) for every team size: with --llm, the whole pipeline (language stage -> hierarchical spec ->
planner -> simulator -> goal checker); with --oracle, from the spec a perfect translator would give.
Writes DIR/scenarios.jsonl (one JSON line per scenario, appended as it finishes; a rerun resumes
unless --fresh), DIR/language.jsonl (--llm: one record per instruction), DIR/summary.json and
DIR/report.md with plots, and prints a table in the layout of the paper's Table I.
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
    source.add_argument(
        "--llm",
        choices=["offline", "local", "openai"],
        default=None,
        help="run the language stage with this backend (the whole pipeline)",
    )
    p.add_argument(
        "--gt",
        type=Path,
        default=None,
        help="ground-truth JSONL with the schema of alfred_test50_gt.jsonl (default: that file)",
    )
    llm = p.add_argument_group("LLM backend for --llm local|openai (environment: NL2HLTL2PLAN_LLM_*)")
    llm.add_argument("--base-url", default=None, help="OpenAI-compatible endpoint")
    llm.add_argument("--model", default=None, help="model name")
    llm.add_argument("--api-key", default=None, help="API key (better: NL2HLTL2PLAN_LLM_API_KEY)")
    llm.add_argument("--gguf", default=None, help="GGUF file for --llm local (default: SmolLM2 test model)")
    llm.add_argument("--cache", default=None, help="answer cache folder, or 'off'")
    p.add_argument("--robots", type=_ints, default=[1, 2, 4], help="team sizes, e.g. 1,2,4 (default)")
    p.add_argument("--n-base", type=_ints, default=None, help="base-task counts to include (default: all)")
    p.add_argument("--limit", type=int, default=None, help="first N instances only (after --n-base)")
    p.add_argument("--draw", type=int, default=0, help="init_pos draw for the start cells (default 0)")
    p.add_argument("--workers", type=int, default=None, help="parallel worker processes (default: CPU cores)")
    p.add_argument("--objective", choices=["min", "minmax"], default="min")
    p.add_argument("--mode", choices=["fast", "exact"], default="fast")
    p.add_argument("--timeout", type=float, default=300.0, help="planner time limit per scenario in s (300)")
    p.add_argument("--fresh", action="store_true", help="start over instead of resuming DIR/scenarios.jsonl")
    p.add_argument("--quiet", action="store_true", help="no progress display")
    p.add_argument("--json", action="store_true", help="print summary.json instead of the table")
    p.add_argument("--out", type=Path, required=True, help="output folder")
    p.set_defaults(func=run, source_group=source)


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.evaluation.alfred import alfred_scenarios, load_gt_file, oracle_job, preload
    from nl2hltl2plan.evaluation.report import format_table
    from nl2hltl2plan.evaluation.report_md import (
        failures_markdown,
        machine_description,
        table1_markdown,
        write_report,
    )
    from nl2hltl2plan.evaluation.runner import run_scenarios

    if not args.oracle and not args.llm:
        raise PlanningError(
            "choose where the specs come from: --oracle (perfect translations) or --llm BACKEND"
        )
    if args.limit is not None and args.limit < 1:
        raise PlanningError("--limit must be at least 1")
    preload()
    gts = load_gt_file(args.gt)
    scenarios = alfred_scenarios(args.robots, args.n_base, args.limit, args.draw, gts=list(gts.values()))
    if not scenarios:
        raise PlanningError("no benchmark instance matches --n-base/--limit")
    workers = args.workers or os.cpu_count() or 1
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    if args.fresh:
        for name in ("scenarios.jsonl", "language.jsonl"):
            (out / name).unlink(missing_ok=True)
    planner = {"objective": args.objective, "mode": args.mode, "timeout_s": args.timeout}
    if args.oracle:
        job = oracle_job(gts=gts, **planner)
        source = "oracle specs"
    else:
        job = _language_job(args, gts, scenarios, out, planner)
        source = f"language backend {args.llm}"

    with _Progress(len(scenarios), "planning", args.quiet) as bar:
        rows = run_scenarios(
            scenarios,
            job,
            out / "scenarios.jsonl",
            workers=workers,
            hard_timeout_s=args.timeout + 60.0,
            resume=True,
            progress=bar.row,
        )
    command = " ".join(["nl2hltl2plan", *sys.argv[1:]]) if sys.argv else ""
    title = (
        f"ALFRED benchmark, {source}, objective {args.objective}, mode {args.mode} "
        f"({len(rows)} scenarios, {workers} workers)"
    )
    summary = write_report(rows, out, title, command, machine_description())
    summary["command"] = command
    summary["settings"] = {
        "source": "oracle" if args.oracle else args.llm,
        "gt": str(args.gt or "default"),
        **planner,
        "robots": args.robots,
        "n_base": args.n_base,
        "limit": args.limit,
        "draw": args.draw,
        "workers": workers,
    }
    (out / "summary.json").write_text(json.dumps(summary, indent=2))
    if args.json:
        print(json.dumps(summary, indent=2))
    elif args.oracle:
        print(format_table(summary, title))
    else:
        t = summary["plan_time_s"]
        print(f"{title}\n\n{table1_markdown(summary)}\n\nfailures by first failing stage:\n"
              f"{failures_markdown(summary)}\n\nplanning time s: median {t['median']}, p95 {t['p95']}, "
              f"max {t['max']}")
    if not args.json:
        print(f"wrote {out / 'report.md'}, {out / 'summary.json'} and {out / 'scenarios.jsonl'}")
    return 0


def _language_job(args: argparse.Namespace, gts: dict, scenarios: list, out: Path, planner: dict) -> Any:
    """Phase 1 in this process (an LLM is asked once per instruction), phase 2 in the workers."""
    from nl2hltl2plan.evaluation.language_bench import language_job, translate_instances
    from nl2hltl2plan.language.llm.settings import LLMSettings
    from nl2hltl2plan.language.pipeline import open_client

    settings = LLMSettings.from_env(
        base_url=args.base_url, model=args.model, api_key=args.api_key, gguf=args.gguf, cache_dir=args.cache
    )
    ids = list(dict.fromkeys(s.instance for s in scenarios))
    with (
        open_client(args.llm, settings) as client,
        _Progress(len(ids), f"language ({args.llm})", args.quiet) as bar,
    ):
        records = translate_instances(
            [gts[i] for i in ids],
            args.llm,
            client,
            out / "language.jsonl",
            progress=lambda _gt: bar.advance(),
        )
    return language_job(records, gts, **planner)


class _Progress:
    """A rich progress bar on stderr (nothing with --quiet)."""

    def __init__(self, total: int, label: str, quiet: bool):
        self.quiet = quiet
        self.total = total
        self.label = label

    def __enter__(self) -> _Progress:
        if not self.quiet:
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

            self.bar = Progress(
                TextColumn("{task.description}"),
                BarColumn(),
                MofNCompleteColumn(),
                TimeElapsedColumn(),
                transient=False,
            )
            self.bar.start()
            self.task = self.bar.add_task(self.label, total=self.total)
        return self

    def advance(self) -> None:
        if not self.quiet:
            self.bar.advance(self.task)

    def row(self, row: dict, done: int, total: int) -> None:
        if not self.quiet:
            verdict = "success" if row.get("success") else row.get("status", "?")
            self.bar.update(
                self.task, completed=done, total=total, description=f"{self.label} (last: {verdict})"
            )

    def __exit__(self, *exc: object) -> None:
        if not self.quiet:
            self.bar.stop()
