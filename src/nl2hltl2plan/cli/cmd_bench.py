"""`nl2hltl2plan bench alfred (--oracle | --llm offline|local|openai) --robots 1,2,4 -o DIR`

Runs every selected benchmark instance (ALFRED, ../shared/data/benchmark, or --gt FILE with the same
schema) for every team size: with --llm, the whole pipeline (language stage -> hierarchical spec ->
planner -> simulator -> goal checker); with --oracle, from the spec a perfect translator would give.
Writes DIR/scenarios.jsonl (one JSON line per scenario, appended as it finishes; a rerun resumes
unless --fresh), DIR/language.jsonl (--llm: one record per instruction), DIR/summary.json and
DIR/report.md with plots, and prints a table in the layout of the paper's Table I.
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from nl2hltl2plan.argtypes import MAX_ROBOTS
from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.cli.options import (
    add_backend_argument,
    add_llm_arguments,
    add_planner_arguments,
    int_in,
    ints_in,
    llm_settings,
    planner_options,
)
from nl2hltl2plan.domain.plurals import PLURALS
from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.io import ensure_writable_dir, write_json
from nl2hltl2plan.suites.ray_engine import ENGINES, run_with_engine
from nl2hltl2plan.suites.runner import Row, Scenario, is_errored

if TYPE_CHECKING:  # the pipeline (scipy, Spot) loads only when a benchmark runs, not for --help
    from nl2hltl2plan.pipeline import PipelineOptions
    from nl2hltl2plan.worlds.tasks import GTInstance

# Each suite module exposes `register(bench_subparsers)`; a module missing from the tree is not offered.
SUITE_MODULES = ["nl2hltl2plan.cli.bench_experiments", "nl2hltl2plan.cli.bench_smartllm"]


def register(sub: Any) -> None:
    bench = sub.add_parser(
        "bench",
        help=COMMANDS["bench"],
        description="Benchmarks; `nl2hltl2plan bench SUITE --help` for each suite.",
    )
    suites = bench.add_subparsers(dest="suite", metavar="SUITE", required=True)
    p = suites.add_parser(
        "alfred",
        help="the paper's AI2-THOR benchmark (Table I)",
        description=__doc__.split("\n\n")[1],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("--oracle", action="store_true", help="plan from oracle specs (a perfect translator)")
    add_backend_argument(source, help_extra=" (runs the whole pipeline)")
    p.add_argument(
        "--gt",
        type=Path,
        default=None,
        help="ground-truth JSONL with the schema of alfred_test50_gt.jsonl (default: that file)",
    )
    p.add_argument(
        "--robots",
        type=ints_in(1, MAX_ROBOTS),
        default=[1, 2, 4],
        help=f"team sizes, 1..{MAX_ROBOTS} (default 1,2,4)",
    )
    p.add_argument(
        "--n-base",
        type=ints_in(1, 100),
        default=None,
        help="base-task counts to include, 1..100 (default: all)",
    )
    p.add_argument(
        "--limit",
        type=int_in(1, 1_000_000),
        default=None,
        help="first N instances only, after --n-base (default: all)",
    )
    p.add_argument(
        "--draw", type=int_in(0, 4), default=0, help="init_pos draw for the start cells, 0..4 (default 0)"
    )
    p.add_argument(
        "--workers",
        type=int_in(1, 256),
        default=None,
        help="parallel worker processes, 1..256 (default: CPU cores)",
    )
    add_planner_arguments(p, timeout_help="planner time limit per scenario")
    p.add_argument(
        "--engine",
        choices=ENGINES,
        default="local",
        help="local: worker processes on this machine; ray: Ray tasks, for runs that outgrow one "
        "machine (pip install 'nl2hltl2plan[ray]') (default: local)",
    )
    p.add_argument(
        "--address",
        default=None,
        help="with --engine ray: join a running Ray cluster HOST:PORT (default: a local Ray)",
    )
    p.add_argument(
        "--plurals",
        choices=PLURALS,
        default="two",
        help="a plural with no number of more things than the task takes: ALFRED's pick-two (two, "
        "default: 66 of 71 such training annotations are pick-two trials, docs/language.md) or "
        "refused (ask)",
    )
    p.add_argument("--fresh", action="store_true", help="start over instead of resuming DIR/scenarios.jsonl")
    p.add_argument("--quiet", action="store_true", help="no progress display")
    p.add_argument("--json", action="store_true", help="print summary.json instead of the table")
    p.add_argument("-o", "--out", type=Path, required=True, help="output folder")
    add_llm_arguments(p)
    p.set_defaults(func=run)
    for name in SUITE_MODULES:
        try:
            module = importlib.import_module(name)
        except ModuleNotFoundError as exc:
            if exc.name == name:
                continue
            raise
        module.register(suites)


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.io import machine_description
    from nl2hltl2plan.pipeline import PipelineOptions
    from nl2hltl2plan.suites.alfred.alfred_bench import alfred_scenarios, oracle_job, preload
    from nl2hltl2plan.suites.alfred.alfred_report import (
        failures_markdown,
        table1_markdown,
        write_report,
    )
    from nl2hltl2plan.suites.alfred.ground_truth import load_gt
    from nl2hltl2plan.suites.rows import rows_of
    from nl2hltl2plan.suites.summaries import format_table

    out: Path = ensure_writable_dir(args.out)
    gts = {g.id: g for g in load_gt(args.gt)}  # a bad --gt file is refused before the data loads
    preload()
    scenarios = alfred_scenarios(args.robots, args.n_base, args.limit, args.draw, gts=list(gts.values()))
    short = sorted({s.instance for s in scenarios if args.draw >= len(gts[s.instance].init_pos)})
    if short:
        raise PlanningError(f"--draw {args.draw} is out of range for {short[0]} ({len(short)} instance(s))")
    if not scenarios:
        raise PlanningError("no benchmark instance matches --n-base/--limit")
    workers = args.workers or os.cpu_count() or 1
    if args.fresh:
        for name in ("scenarios.jsonl", "language.jsonl"):
            (out / name).unlink(missing_ok=True)
    options = PipelineOptions(backend=args.llm or "offline", plurals=args.plurals, **planner_options(args))
    if args.oracle:
        job = oracle_job(options, gts)
        source = "oracle specs"
    else:
        job = _language_job(args, gts, scenarios, out, options)
        source = f"language backend {args.llm}"

    with _Progress(len(scenarios), "planning", args.quiet) as bar:
        rows = run_with_engine(
            args.engine,
            scenarios,
            job,
            out / "scenarios.jsonl",
            address=args.address,
            workers=workers,
            hard_timeout_s=args.timeout + 60.0,
            resume=True,
            progress=bar.row,
        )
    command = " ".join(["nl2hltl2plan", *sys.argv[1:]]) if sys.argv else ""
    plurals = "" if args.oracle else f", plurals {args.plurals}"  # how a bare plural of many is read
    title = (
        f"ALFRED benchmark, {source}{plurals}, objective {args.objective}, mode {args.mode} "
        f"({len(rows)} scenarios, {workers} workers)"
    )
    summary = write_report(rows_of(rows), out, title, command, machine_description())
    summary["command"] = command
    summary["settings"] = {
        "source": "oracle" if args.oracle else args.llm,
        "gt": str(args.gt or "default"),
        **planner_options(args),
        "plurals": args.plurals,
        "robots": args.robots,
        "n_base": args.n_base,
        "limit": args.limit,
        "draw": args.draw,
        "workers": workers,
    }
    write_json(out / "summary.json", summary, "summary file", indent=2)
    if args.json:
        print(json.dumps(summary, indent=2))
    elif args.oracle:
        print(format_table(summary, title))
    else:
        t = summary["plan_time_s"]
        print(
            f"{title}\n\n{table1_markdown(summary)}\n\nfailures by first failing stage:\n"
            f"{failures_markdown(summary)}\n\nplanning time s: median {t['median']}, p95 {t['p95']}, "
            f"max {t['max']}"
        )
    if not args.json:
        print(f"wrote {out / 'report.md'}, {out / 'summary.json'} and {out / 'scenarios.jsonl'}")
    errored = [r for r in rows if is_errored(r)]
    if errored:
        print(
            f"error: {len(errored)} of {len(rows)} scenarios errored (first: {errored[0].get('key')}: "
            f"{errored[0].get('reason')})",
            file=sys.stderr,
        )
        return 1
    return 0


def _language_job(
    args: argparse.Namespace,
    gts: dict[str, GTInstance],
    scenarios: list[Scenario],
    out: Path,
    options: PipelineOptions,
) -> Callable[[Scenario], Row]:
    """Phase 1 in this process (an LLM is asked once per instruction), phase 2 in the workers."""
    from nl2hltl2plan.language.backends import open_client
    from nl2hltl2plan.suites.alfred.alfred_language import language_job, translate_instances

    settings = llm_settings(args)
    ids = list(dict.fromkeys(s.instance for s in scenarios))
    with (
        open_client(args.llm, settings) as client,
        _Progress(len(ids), f"language ({args.llm})", args.quiet) as bar,
    ):
        records = translate_instances(
            [gts[i] for i in ids], options, client, out / "language.jsonl", progress=lambda _gt: bar.advance()
        )
    return language_job(records, gts, options)


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
