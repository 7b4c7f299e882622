"""`nl2hltl2plan spec HTT.json`: Algorithm 1 on an HTT file, printing the hierarchical spec."""

from __future__ import annotations

import argparse
import json

from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.logic.flatten import size_report
from nl2hltl2plan.logic.hierarchical import format_spec


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "spec",
        help="build the hierarchical sc-LTL spec of an HTT (Algorithm 1)",
        description="Build the hierarchical sc-LTL specification of a Hierarchical Task Tree "
        "(JSON file) with the exact relation compiler and the leaves' action lists.",
    )
    p.add_argument("htt", help="HTT JSON file (see examples/dishwasher_htt.json)")
    p.add_argument("--sizes", action="store_true", help="also report automaton sizes: hierarchy vs flat")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    spec = build_spec(HTT.load(args.htt))
    sizes = size_report(spec) if args.sizes else None
    if args.json:
        out: dict = {"levels": spec.to_json_obj()}
        if sizes:
            out["sizes"] = sizes.to_dict()
        print(json.dumps(out, indent=2))
        return 0
    print(format_spec(spec))
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
