"""`bench tabletop` and `bench handover`: the paper's tabletop (Table II) and handover (Table III) studies.

    nl2hltl2plan bench tabletop --out DIR [--instances 25] [--seed S] [--baseline llm]
    nl2hltl2plan bench handover --out DIR [--instances 10] [--seed S]

Both write DIR/summary.json, DIR/report.md (the paper's table with its numbers beside ours) and a
picture, and print the table. The LLM-as-planner baseline runs only when an LLM is configured
(NL2HLTL2PLAN_LLM_*, or --base-url/--api-key); otherwise the report says it was not run.
`register(bench_subparsers)` adds both to a `bench` sub-command; without that wiring, run
`python -m nl2hltl2plan.cli.bench_experiments tabletop --out DIR`.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from nl2hltl2plan.argtypes import int_in, seed
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.backends import BACKENDS
from nl2hltl2plan.language.llm.llm_options import add_llm_arguments, llm_settings

MAX_INSTANCES = 1000  # the paper runs 25 (tabletop) and 10 (handover); each takes a planner call


def register(sub: Any) -> None:
    """Add `tabletop` and `handover` parsers to a subparsers object."""
    studies = (
        ("tabletop", "the paper's tabletop study (Table II)", 25, "the object layouts", run_tabletop, None),
        (
            "handover",
            "the paper's four-arm handover study (Table III)",
            10,
            "block placements and arm poses",
            run_handover,
            _handover_arguments,
        ),
    )
    for name, title, instances, seeded, func, own_arguments in studies:
        p = sub.add_parser(name, help=title)
        p.add_argument("-o", "--out", type=Path, required=True, help="output folder")
        p.add_argument(
            "--instances",
            type=int_in(1, MAX_INSTANCES),
            default=instances,
            help=f"seeded instances per task, 1..{MAX_INSTANCES} (default {instances})",
        )
        p.add_argument("--seed", type=seed, default=0, help=f"seed of {seeded}, 0..2^32-1 (default 0)")
        p.add_argument(
            "--baseline",
            choices=["auto", "llm", "none"],
            default="auto",
            help="LLM-as-planner baseline: auto (default; when an LLM is configured), llm, none",
        )
        add_llm_arguments(p)
        if own_arguments is not None:
            own_arguments(p)
        p.set_defaults(func=func)


def _handover_arguments(p: argparse.ArgumentParser) -> None:
    """The handover study's own options: a language backend instead of the written specs, and a budget."""
    p.add_argument(
        "--llm",
        choices=BACKENDS,
        default=None,
        help="plan each instance from this language backend's spec of the instruction (the whole "
        "pipeline) instead of the written spec; rows say language_equal",
    )
    p.add_argument(
        "--expansions",
        type=int_in(1, 10_000_000),  # bounded: a budget, not a way to run forever
        default=None,  # the planner's own (planning.coop.MAX_EXPANSIONS), read when the bench runs
        help="planner budget per instance in expansions (deterministic; default: the cooperative "
        "planner's own, planning.coop.MAX_EXPANSIONS)",
    )


@contextlib.contextmanager
def _llm_client(args: argparse.Namespace) -> Iterator[Any]:
    """The project's LLM client when the baseline should run, else None."""
    from nl2hltl2plan.language.llm.client import LLMClient

    if args.baseline == "none":
        yield None
        return
    settings = llm_settings(args)
    if not settings.configured:
        if args.baseline == "llm":
            raise Nl2Hltl2PlanError("--baseline llm needs an LLM: set NL2HLTL2PLAN_LLM_BASE_URL / _API_KEY")
        print("note: no LLM configured: the LLM-as-planner baseline is not run", file=sys.stderr)
        yield None
        return
    yield LLMClient(settings)


def run_tabletop(args: argparse.Namespace) -> int:
    from nl2hltl2plan.suites.tabletop.tabletop_bench import run_bench

    with _llm_client(args) as client:
        summary = run_bench(args.out, instances=args.instances, seed=args.seed, client=client)
    print((args.out / "report.md").read_text())
    print(f"wrote {args.out / 'summary.json'} ({len(summary['tasks'])} tasks)", file=sys.stderr)
    return _errored_exit(summary["errored"])


def _errored_exit(errored: int) -> int:
    """Exit 1 when the LLM failed on some instances (their rows say `errored`; not a result)."""
    if errored:
        print(
            f"error: the LLM failed on {errored} baseline instance(s) (errored, not scored)", file=sys.stderr
        )
        return 1
    return 0


def run_handover(args: argparse.Namespace) -> int:
    from nl2hltl2plan.planning.coop import MAX_EXPANSIONS
    from nl2hltl2plan.suites.handover.handover_bench import run_bench

    with _llm_client(args) as client:
        summary = run_bench(
            args.out,
            instances=args.instances,
            seed=args.seed,
            client=client,
            backend=args.llm,
            max_expansions=args.expansions or MAX_EXPANSIONS,
        )
    print((args.out / "report.md").read_text())
    print(f"wrote {args.out / 'summary.json'} ({len(summary['tasks'])} tasks)", file=sys.stderr)
    return _errored_exit(sum(t["baseline"].get("errored", 0) for t in summary["tasks"]))
