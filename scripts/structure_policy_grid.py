"""How the structure model's reading and the grammar's compare, and what other arbitration thresholds
would convert, on saved rows (results/language/unseen_h49.md).

    python scripts/structure_policy_grid.py --rows DIR --sets refsdev_unseen:1,trainstyle_unseen,...

For each instruction: whether the grammar-first reading is complete and right, whether the structure
model's reading is complete and right, its confidence, and whether it has a span that points back (REF,
RPRE, ALL). Then the conversions of `structured.StructurePolicy`-like rules: rescue threshold, override
threshold (separately for readings that point back), `doubt` (-> unparsed), as differences from the
shipped policy, per set. Rows come from `scripts/language_failures.py --save-rows DIR`.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from nl2hltl2plan.language.learned.inference import grammar_complete, load_model
from nl2hltl2plan.language.learned.slot_model import SlotModel
from nl2hltl2plan.language.learned.span_order import POINTING
from nl2hltl2plan.language.learned.structure import StructureModel, load_structure
from nl2hltl2plan.language.learned.structured import same_reading
from nl2hltl2plan.suites.alfred.structure_validation import both_readings, converts

# (rescue, override, override when the reading points back, doubt); the first is the shipped policy
GRID = (
    [(0.5, 0.97, 0.97, 0.0)]
    + [(0.5, 0.97, o, 0.0) for o in (0.3, 0.5, 0.7, 0.8, 0.9, 0.95)]
    + [(r, 0.97, 0.97, 0.0) for r in (0.3, 0.4, 0.6)]
    + [(0.5, 0.97, 0.97, d) for d in (0.2, 0.3, 0.5)]
    + [(0.5, o, o, 0.0) for o in (0.9, 0.95, 0.99)]
)


def record(row: dict[str, Any], model: SlotModel, structure: StructureModel) -> dict[str, Any]:
    """What every rule of the grid needs to know of one row's two readings."""
    g, s = both_readings(row, model, structure)
    rels = {x.relation for x in structure.read(row["instruction"]).spans}
    return {
        "g_ok": converts(g.model_copy(deep=True), row),
        "g_complete": grammar_complete(g),
        "m": s is not None,
        "m_ok": s is not None and converts(s[0].model_copy(deep=True), row),
        "conf": s[1] if s else 0.0,
        "points": bool(rels & set(POINTING)),
        "same": s is not None and bool(g.tasks) and same_reading(s[0].tasks, s[0].before, g.tasks, g.before),
    }


def choice(r: dict[str, Any], rescue: float, override: float, pointing: float, doubt: float) -> bool:
    """Whether the rule converts the instruction."""
    if not r["m"]:
        return r["g_ok"]
    if not r["g_complete"]:
        return r["m_ok"] if r["conf"] >= rescue else r["g_ok"]
    if r["same"]:
        return r["g_ok"]
    if r["conf"] >= (pointing if r["points"] else override):
        return r["m_ok"]
    return False if r["conf"] < doubt else r["g_ok"]


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/structure_policy_grid.py")
    ap.add_argument("--rows", type=Path, required=True)
    ap.add_argument("--sets", required=True)
    args = ap.parse_args()
    model, structure = load_model(), load_structure()
    sets = [s for s in args.sets.split(",") if s]
    recs = {
        s: [record(r, model, structure) for r in json.loads((args.rows / f"{s}.json").read_text())]
        for s in sets
    }
    print("| rescue, override, override pointing back, doubt | " + " | ".join(sets) + " | all |")
    print("| --- |" + " --- |" * (len(sets) + 1))
    shipped = {s: sum(choice(r, *GRID[0]) for r in recs[s]) for s in sets}
    for rule in GRID:
        got = {s: sum(choice(r, *rule) for r in recs[s]) for s in sets}
        cells = [str(got[s]) if rule == GRID[0] else f"{got[s] - shipped[s]:+d}" for s in sets]
        total = sum(got.values()) - (0 if rule == GRID[0] else sum(shipped.values()))
        print(f"| {rule} | " + " | ".join(cells) + f" | {total if rule == GRID[0] else f'{total:+d}'} |")
    for s in sets:
        back = [r for r in recs[s] if r["points"] and r["m"] and r["g_complete"] and not r["same"]]
        print(
            f"{s}: {len(back)} readings that point back differ from a complete grammar reading; the model "
            f"right in {sum(r['m_ok'] for r in back)}, the grammar in {sum(r['g_ok'] for r in back)}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
