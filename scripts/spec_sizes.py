"""Automaton sizes, hierarchy vs flat (the paper's motivation), for Example 1 and the benchmark.

    python scripts/spec_sizes.py [--n-base 4] [--limit 50] [--timeout 10]

Hierarchy: the sum of the DFAs of every flat formula. Flat: Spot's cheapest Büchi automaton of the
exact flattening (`HierarchicalSpec.flatten`), which is never larger than the flat DFA, translated
under a time limit (a timeout counts as "too large").
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from pathlib import Path

from nl2hltl2plan.language.htt import HTT
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.logic.flatten import size_report
from nl2hltl2plan.planning.oracle import oracle_spec
from nl2hltl2plan.suites.alfred.ground_truth import load_gt
from nl2hltl2plan.worlds.floor_plans import build_benchmark_world

ROOT = Path(__file__).resolve().parents[1]


def row(name: str, spec, timeout: float) -> dict:
    t0 = time.perf_counter()
    rep = size_report(spec, flat_timeout_s=timeout)
    return {
        "name": name,
        "formulas": len(rep.per_formula),
        "hier_states": rep.hierarchical_states,
        "hier_edges": rep.hierarchical_edges,
        "flat_states": rep.flat_states,
        "flat_edges": rep.flat_edges,
        "flat_exact": rep.flat_exact,
        "seconds": round(time.perf_counter() - t0, 2),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n-base", type=int, default=4)
    ap.add_argument("--limit", type=int, default=50)
    ap.add_argument("--timeout", type=float, default=10.0)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    rows = [
        row(
            "Example 1 (dishwasher)",
            build_spec(HTT.load(ROOT / "examples/dishwasher_htt.json")),
            args.timeout,
        )
    ]
    gts = [g for g in load_gt() if g.n_base == args.n_base][: args.limit]
    bench = []
    for gt in gts:
        spec = oracle_spec(gt, build_benchmark_world(gt)).spec
        bench.append(row(gt.id, spec, args.timeout))
    done = [r for r in bench if r["flat_states"] is not None]
    summary = {
        "instances": len(bench),
        "flat_translated": len(done),
        "flat_timeouts": len(bench) - len(done),
        "hier_states_median": statistics.median(r["hier_states"] for r in bench) if bench else None,
        "flat_states_median_of_translated": statistics.median(r["flat_states"] for r in done)
        if done
        else None,
        "ratio_median_of_translated": statistics.median(r["flat_states"] / r["hier_states"] for r in done)
        if done
        else None,
    }
    if args.json:
        print(json.dumps({"example1": rows[0], "benchmark": bench, "summary": summary}, indent=2))
        return
    for r in rows + bench[:5]:
        flat = f"{r['flat_states']} states" if r["flat_states"] is not None else f"> {args.timeout:g} s"
        print(f"{r['name']:45s} hierarchy {r['hier_states']:4d} states ({r['formulas']} DFAs)  flat {flat}")
    print(f"{args.n_base} base tasks, {len(bench)} instances: {summary}")


if __name__ == "__main__":
    main()
