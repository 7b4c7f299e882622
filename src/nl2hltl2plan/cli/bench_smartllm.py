"""`nl2hltl2plan bench smartllm (--oracle | --llm offline|local|openai) --out DIR`

Runs SMART-LLM's 36 tasks (../shared/data/smartllm) in their AI2-THOR floor plans, each for its own
heterogeneous robot team: specs from the ground-truth final states (--oracle) or from the
instruction through the language stage (--llm), planned, executed in the simulator and scored by
SMART-LLM's metrics (SR, TC, GCR, RU, Exe). Writes DIR/rows.jsonl, DIR/summary.json (the five
metrics overall and per floor plan) and DIR/report.md (beside SMART-LLM's published numbers).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
from pathlib import Path
from typing import Any

from nl2hltl2plan.argtypes import seconds
from nl2hltl2plan.cli.options import add_backend_argument
from nl2hltl2plan.language.llm.llm_options import add_llm_arguments, llm_settings


def register(bench_subparsers: Any) -> None:
    """Add `smartllm` to the `bench` sub-commands."""
    p = bench_subparsers.add_parser(
        "smartllm",
        help="SMART-LLM's benchmark with its metrics (SR, TC, GCR, RU, Exe)",
        description=__doc__.split("\n\n")[1],
    )
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("--oracle", action="store_true", help="specs from the ground-truth final states")
    add_backend_argument(source, help_extra=" (the instruction through the language stage)")
    p.add_argument(
        "--timeout",
        type=seconds,
        default=30.0,
        help="planner time limit per task in seconds (default 30)",
    )
    p.add_argument(
        "--objective",
        choices=["min", "minmax"],
        default="minmax",
        help="minmax (default): completion time, which favours parallel robots (RU); min: summed cost",
    )
    p.add_argument("--quiet", action="store_true", help="no progress lines")
    p.add_argument(
        "--masses",
        type=Path,
        default=None,
        help="JSON object of AI2-THOR object masses in kg by type (robots' mass capacities then "
        "limit what they pick up; default: none, as the shared data has no masses)",
    )
    p.add_argument("-o", "--out", type=Path, required=True, help="output folder")
    add_llm_arguments(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.suites.smartllm.smartllm_bench import (
        METRICS,
        SpecMaker,
        llm_maker,
        oracle_maker,
        run_bench,
    )

    def progress(row: dict[str, Any]) -> None:
        if not args.quiet:
            vals = " ".join(f"{m}={row[m]:.2f}" for m in METRICS if row.get(m) is not None)
            print(f"{row['id']:<16} {row.get('status', ''):<16} {vals}", flush=True)

    maker: SpecMaker
    with contextlib.ExitStack() as stack:
        if args.oracle:
            maker, label = oracle_maker, "oracle"
        else:
            from nl2hltl2plan.language.backends import open_client

            # None for the backends that need no LLM (`parsers.PARSERS`)
            client = stack.enter_context(open_client(args.llm, llm_settings(args)))
            maker, label = llm_maker(args.llm, client), f"language backend {args.llm}"
        summary = run_bench(
            args.out, maker, label, args.timeout, progress, args.objective, _masses(args.masses)
        )
    print(json.dumps(summary["overall"]))
    return 0


def _masses(path: Path | None) -> dict[str, float]:
    if path is None:
        return {}
    from nl2hltl2plan.errors import DataError
    from nl2hltl2plan.io import read_json

    raw = read_json(path, "masses file")
    if not isinstance(raw, dict) or not all(
        isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v) and v > 0
        for v in raw.values()
    ):
        raise DataError(f"masses file {path}: expected an object of positive kg values by object type")
    return {str(k): float(v) for k, v in raw.items()}


def main(argv: list[str] | None = None) -> int:
    """Stand-alone entry (`python -m nl2hltl2plan.cli.bench_smartllm --oracle --out DIR`)."""
    from nl2hltl2plan.errors import Nl2Hltl2PlanError

    parser = argparse.ArgumentParser(prog="nl2hltl2plan bench")
    register(parser.add_subparsers(dest="suite", required=True))
    args = parser.parse_args(["smartllm", *(argv if argv is not None else __import__("sys").argv[1:])])
    try:
        return int(args.func(args))
    except Nl2Hltl2PlanError as exc:
        print(f"error: {exc}")
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
