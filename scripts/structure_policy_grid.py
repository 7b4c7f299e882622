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
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from nl2hltl2plan.language.learned.inference import grammar_complete, load_model
from nl2hltl2plan.language.learned.slot_model import SlotModel
from nl2hltl2plan.language.learned.span_order import POINTING
from nl2hltl2plan.language.learned.structure import StructureModel, load_structure
from nl2hltl2plan.language.learned.structured import StructurePolicy, decide, same_reading
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.suites.alfred.structure_validation import both_readings, converts

# (rescue, override, override when the reading points back, doubt); the first is the shipped policy
GRID = (
    [(0.5, 0.97, 0.97, 0.0)]
    + [(0.5, 0.97, o, 0.0) for o in (0.3, 0.5, 0.7, 0.8, 0.9, 0.95)]
    + [(r, 0.97, 0.97, 0.0) for r in (0.3, 0.4, 0.6)]
    + [(0.5, 0.97, 0.97, d) for d in (0.2, 0.3, 0.5)]
    + [(0.5, o, o, 0.0) for o in (0.9, 0.95, 0.99)]
)


@dataclass(frozen=True)
class Record:
    """What every rule of the grid needs to know of one row's two readings."""

    grammar: tuple[list[BaseTaskSpec], list[tuple[str, str]], bool]  # tasks, before, complete
    model: tuple[list[BaseTaskSpec], list[tuple[str, str]], float] | None  # tasks, before, confidence
    grammar_ok: bool  # the grammar-first reading converts the row
    model_ok: bool  # the structure model's reading converts it
    points: bool  # the model's reading has a span that points back
    same: bool  # both readings state the same tasks and order


def record(row: dict[str, Any], model: SlotModel, structure: StructureModel) -> Record:
    g, s = both_readings(row, model, structure)
    rels = {x.relation for x in structure.read(row["instruction"]).spans}
    return Record(
        grammar=(g.tasks, g.before, grammar_complete(g)),
        model=(s[0].tasks, s[0].before, s[1]) if s else None,
        grammar_ok=converts(g.model_copy(deep=True), row),
        model_ok=s is not None and converts(s[0].model_copy(deep=True), row),
        points=bool(rels & set(POINTING)),
        same=s is not None and bool(g.tasks) and same_reading(s[0].tasks, s[0].before, g.tasks, g.before),
    )


def converted(r: Record, rescue: float, override: float, pointing: float, doubt: float) -> bool:
    """Whether the rule converts the instruction: `structured.decide` with the override threshold
    `pointing` for a reading that points back."""
    rule = StructurePolicy(rescue=rescue, override=pointing if r.points else override, doubt=doubt)
    return {"grammar": r.grammar_ok, "model": r.model_ok, "neither": False}[decide(r.grammar, r.model, rule)]


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
    shipped = {s: sum(converted(r, *GRID[0]) for r in recs[s]) for s in sets}
    for rule in GRID:
        got = {s: sum(converted(r, *rule) for r in recs[s]) for s in sets}
        cells = [str(got[s]) if rule == GRID[0] else f"{got[s] - shipped[s]:+d}" for s in sets]
        total = sum(got.values()) - (0 if rule == GRID[0] else sum(shipped.values()))
        print(f"| {rule} | " + " | ".join(cells) + f" | {total if rule == GRID[0] else f'{total:+d}'} |")
    for s in sets:
        back = [r for r in recs[s] if r.points and r.model and r.grammar[2] and not r.same]
        print(
            f"{s}: {len(back)} readings that point back differ from a complete grammar reading; the model "
            f"right in {sum(r.model_ok for r in back)}, the grammar in {sum(r.grammar_ok for r in back)}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
