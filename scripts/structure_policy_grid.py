"""How the structure model's reading and the grammar's compare, and what other arbitration thresholds
would convert, on saved rows (results/language/unseen_h49.md).

    python scripts/structure_policy_grid.py --rows DIR --sets refsdev_unseen:1,trainstyle_unseen,...

For each instruction: whether the grammar-first reading is complete and right, whether the structure
model's reading is complete and right, its confidence, and whether it has a span that points back (REF,
RPRE, ALL). Then the conversions and the wrong readings (complete, wrong, reported as success) of
`structured.StructurePolicy` rules: rescue threshold, override threshold (separately for readings that
point back), `doubt` (-> unparsed), as differences from the shipped policy, per set; `--search` lists
the rules of a whole grid under which no set has more wrong readings than under the shipped policy (or
than `--wrong-limits` allows; results/language/unseen_h53.md). Rows come from
`scripts/language_failures.py --save-rows DIR`.

    python scripts/structure_policy_grid.py --rows DIR --sets ... [--search]
"""

from __future__ import annotations

import argparse
import itertools
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

# (rescue, override, override when the reading points back, doubt): each is compared with the shipped
# policy (`StructurePolicy()`); `--search` tries every combination of these values instead
RESCUE = (0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6)
OVERRIDE = (0.9, 0.95, 0.97, 0.99)
POINTING_OVERRIDE = (0.5, 0.6, 0.7, 0.8, 0.9, 0.97, 0.99)
DOUBT = (0.0, 0.1, 0.15, 0.2, 0.25, 0.3)
GRID = (
    [(r, 0.97, 0.97, 0.0) for r in (0.3, 0.4, 0.5, 0.6)]
    + [(0.5, 0.97, o, 0.0) for o in (0.5, 0.7, 0.8, 0.9)]
    + [(0.5, o, o, 0.0) for o in (0.9, 0.95, 0.99)]
    + [(0.5, 0.97, 0.97, d) for d in (0.2, 0.3, 0.5)]
)
Rule = tuple[float, float, float, float]


@dataclass(frozen=True)
class Record:
    """What every rule of the grid needs to know of one row's two readings."""

    grammar: tuple[list[BaseTaskSpec], list[tuple[str, str]], bool]  # tasks, before, complete
    model: tuple[list[BaseTaskSpec], list[tuple[str, str]], float] | None  # tasks, before, confidence
    grammar_ok: bool  # the grammar-first reading converts the row
    model_ok: bool  # the structure model's reading converts it
    points: bool  # the model's reading has a span that points back
    same: bool  # both readings state the same tasks and order
    instruction: str


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
        instruction=row["instruction"],
    )


def outcome(r: Record, rescue: float, override: float, pointing: float, doubt: float) -> str:
    """"ok" (converted), "wrong" (a complete reading that is wrong: success reported for a wrong plan)
    or "refused", under `structured.decide` with these thresholds."""
    rule = StructurePolicy(rescue=rescue, override=override, doubt=doubt, override_pointing=pointing)
    choice = decide(r.grammar, r.model, rule, r.instruction, points=r.points)
    if choice == "neither" or (choice == "grammar" and not r.grammar[2]):
        return "refused"
    right = r.grammar_ok if choice == "grammar" else r.model_ok
    return "ok" if right else "wrong"


def counts(recs: list[Record], rule: Rule) -> tuple[int, int]:
    """(converted, wrong) of a set under one rule."""
    got = [outcome(r, *rule) for r in recs]
    return got.count("ok"), got.count("wrong")


def shipped_rule() -> Rule:
    p = StructurePolicy()
    return (p.rescue, p.override, p.override if p.override_pointing is None else p.override_pointing, p.doubt)


def search(recs: dict[str, list[Record]], limits: dict[str, int]) -> list[tuple[int, int, Rule]]:
    """Every rule of the grid under which no set has more wrong readings than its limit, by conversions
    (most first)."""
    out = []
    for rule in itertools.product(RESCUE, OVERRIDE, POINTING_OVERRIDE, DOUBT):
        got = {s: counts(rs, rule) for s, rs in recs.items()}
        if all(got[s][1] <= limits[s] for s in recs):
            out.append((sum(c for c, _ in got.values()), sum(w for _, w in got.values()), rule))
    return sorted(out, key=lambda x: (-x[0], x[1]))


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/structure_policy_grid.py")
    ap.add_argument("--rows", type=Path, required=True)
    ap.add_argument("--sets", required=True)
    ap.add_argument("--search", action="store_true", help="the best rules of the whole grid")
    ap.add_argument(
        "--wrong-limits", default="", help="SET=N,...: most wrong readings allowed per set in --search "
        "(default: the shipped rule's; e.g. the previous model's counts)"
    )
    args = ap.parse_args()
    model, structure = load_model(), load_structure()
    sets = [s for s in args.sets.split(",") if s]
    recs = {
        s: [record(r, model, structure) for r in json.loads((args.rows / f"{s}.json").read_text())]
        for s in sets
    }
    first = shipped_rule()
    shipped = {s: counts(recs[s], first) for s in sets}
    print("converted / wrong per set; the shipped rule first, then differences from it")
    print("| rescue, override, override pointing back, doubt | " + " | ".join(sets) + " | all |")
    print("| --- |" + " --- |" * (len(sets) + 1))
    total = (sum(c for c, _ in shipped.values()), sum(w for _, w in shipped.values()))
    print(f"| {first} (shipped) | " + " | ".join(f"{c} / {w}" for c, w in shipped.values())
          + f" | {total[0]} / {total[1]} |")
    for rule in GRID:
        got = {s: counts(recs[s], rule) for s in sets}
        cells = [f"{got[s][0] - shipped[s][0]:+d} / {got[s][1] - shipped[s][1]:+d}" for s in sets]
        all_c = sum(c for c, _ in got.values()) - total[0]
        all_w = sum(w for _, w in got.values()) - total[1]
        print(f"| {rule} | " + " | ".join(cells) + f" | {all_c:+d} / {all_w:+d} |")
    if args.search:
        limits = {s: w for s, (_, w) in shipped.items()}
        limits |= {k: int(v) for k, _, v in (x.partition("=") for x in args.wrong_limits.split(",") if x)}
        print(f"\nrules with no set's wrong readings above {limits}, most conversions first:")
        for conv, wrong, rule in search(recs, limits)[:10]:
            print(f"  {rule}: {conv} converted, {wrong} wrong")
    for s in sets:
        back = [r for r in recs[s] if r.points and r.model and r.grammar[2] and not r.same]
        print(
            f"{s}: {len(back)} readings that point back differ from a complete grammar reading; the model "
            f"right in {sum(r.model_ok for r in back)}, the grammar in {sum(r.grammar_ok for r in back)}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
