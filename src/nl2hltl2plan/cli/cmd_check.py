"""`nl2hltl2plan check SPEC.json`: validate a hierarchical spec (exit 0 valid, 1 invalid, 2 unreadable)."""

from __future__ import annotations

import argparse
import json
import sys

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.errors import DataError, FormulaTooLargeError, SpecError
from nl2hltl2plan.io import read_json
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "check",
        help=COMMANDS["check"],
        description="Validate a hierarchical sc-LTL specification in the paper's JSON form "
        '(a list of levels, each {"name": "formula" or [actions]}). Exit 0 when valid, '
        "1 with the reasons when not, 2 when the file cannot be read as JSON or holds a formula too large "
        "to check.",
    )
    p.add_argument("spec", help="specification JSON file")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    try:
        data = read_json(args.spec, "specification file")
    except DataError as exc:
        return _report(args, 2, [str(exc)])
    try:
        spec = HierarchicalSpec.from_json(data)
    except FormulaTooLargeError as exc:  # cannot be checked at all: bad input
        return _report(args, 2, [str(exc)])
    except SpecError as exc:
        reasons = [line.strip()[2:] for line in str(exc).splitlines()[1:]] or [str(exc)]
        return _report(args, 1, reasons)
    summary = {
        "levels": len(spec.levels),
        "formulas": len(spec.names),
        "leaves": len(spec.leaves),
        "atoms": sorted(spec.atoms()),
        "constraints": [c.describe() for c in spec.constraints],
    }
    return _report(args, 0, [], summary)


def _report(args: argparse.Namespace, code: int, reasons: list[str], summary: dict | None = None) -> int:
    if args.json:
        print(json.dumps({"valid": code == 0, "exit": code, "reasons": reasons, **(summary or {})}, indent=2))
        if code == 2:  # bad input: its one-line error on stderr, with --json too
            print(f"error: {reasons[0]}", file=sys.stderr)
    elif code == 0 and summary:
        print(
            f"valid: {summary['levels']} levels, {summary['formulas']} formulas, {summary['leaves']} leaves, "
            f"{len(summary['atoms'])} atomic propositions, {len(summary['constraints'])} constraints"
        )
    elif code == 2:
        print(f"error: {reasons[0]}", file=sys.stderr)
    else:
        print("invalid:")
        for r in reasons:
            print(f"  - {r}")
    if code == 1:
        more = f" (and {len(reasons) - 1} more)" if len(reasons) > 1 else ""
        print(f"error: invalid specification: {reasons[0]}{more}", file=sys.stderr)
    return code
