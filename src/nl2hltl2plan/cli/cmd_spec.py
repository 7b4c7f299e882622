"""`nl2hltl2plan spec HTT.json`: Algorithm 1 on an HTT file, printing the hierarchical spec."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.io import ensure_writable_dir, write_text
from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.flatten import size_report
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec, format_spec


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "spec",
        help=COMMANDS["spec"],
        description="Build the hierarchical sc-LTL specification of a Hierarchical Task Tree "
        "(JSON file) with the exact relation compiler and the leaves' action lists.",
    )
    p.add_argument("htt", help="HTT JSON file (see examples/dishwasher_htt.json)")
    p.add_argument("--sizes", action="store_true", help="also report automaton sizes: hierarchy vs flat")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument(
        "--hoa",
        type=Path,
        metavar="DIR",
        default=None,
        help="write each flat formula's automaton to DIR/<name>.hoa in the HOA format (written by Spot)",
    )
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    spec = build_spec(HTT.load(args.htt))
    sizes = size_report(spec) if args.sizes else None
    written = write_hoa(spec, args.hoa) if args.hoa else None
    if args.json:
        out: dict = {"levels": spec.to_json_obj()}
        if sizes:
            out["sizes"] = sizes.to_dict()
        if written is not None:
            out["hoa"] = {name: str(path) for name, path in written.items()}
        print(json.dumps(out, indent=2))
        return 0
    print(format_spec(spec))
    if written is not None:
        print(f"\nwrote {len(written)} automata in HOA format to {args.hoa}/")
    if sizes:
        print(
            f"\nautomaton sizes: hierarchy {sizes.hierarchical_states} states / "
            f"{sizes.hierarchical_edges} edges "
            f"(sum of {len(sizes.per_formula)} DFAs); flat formula"
            + (" (exact)" if sizes.flat_exact else " (substitution)")
            + ": "
            + (
                f"{sizes.flat_states} states / {sizes.flat_edges} edges (Büchi automaton)"
                if sizes.flat_states is not None
                else f"not translated: {sizes.flat_error}"
            )
        )
    return 0


def write_hoa(spec: HierarchicalSpec, folder: Path) -> dict[str, Path]:
    """DIR/<name>.hoa for every flat formula (leaves too: their action sequence formula)."""
    ensure_writable_dir(folder, "HOA folder")
    written = {}
    for name in spec.names:
        path = folder / f"{name}.hoa"
        write_text(path, sb.hoa(spec.formula(name)), "HOA file")
        written[name] = path
    return written

