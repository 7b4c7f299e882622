"""Validation of the structure model and of the rule that weighs it against the grammar.

    python -m nl2hltl2plan.suites.alfred.structure_validation [--n 400] [--sets plain,heldout,...]

Sets (never test50, never the excluded trials):
- `plain`: issue 23's user-style instructions (tests/language/data/trust/plain.jsonl, 6 floor plans);
- `heldout_unseen`: compositions of valid_unseen annotations with the held-out connectives
  (`compose.HELDOUT_STYLE`, never trained on);
- `trainstyle_unseen`: valid_unseen annotations with the training connectives (unseen clauses, scenes);
- `framed_unseen`: the same in a voice's frame of `compose_frames`' held-out pools (never trained on);
- `faithful_seen` / `faithful_unseen`: `faithful.compose_faithful` (the earlier validation's 25
  templates) over valid_seen / valid_unseen;
- `refsdev_seen` / `refsdev_unseen` / `refsheld_seen` / `refsheld_unseen` / `refsnew_seen` / `refsnew_unseen`:
  `compose_refs.compose_refs` (the paper's multi-agent style: tasks named by their object, "at any time";
  the development phrase family, the held-out one and the newer held-out one).
A name with `:SEED` composes the set with that seed (`faithful_unseen:21`).

For each instruction the grammar-first reading and the structure model's reading are computed once;
every candidate `StructurePolicy` is then scored on them (the benchmark's strict match; a reading with
unread words is a failure), per set and per number of base tasks. The readings are the learned parse's of
the text as written, where the policies act; what `plan` gives (the household reader's rewriting, the floor
plan's counts) is measured by `scripts/language_failures.py` on the same sets (`rows_of_set`).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.compose import HELDOUT_STYLE, TRAIN_STYLE, synthesise
from nl2hltl2plan.language.learned.inference import (
    DEFAULT_POLICY,
    LearnedParse,
    ParseContext,
    grammar_complete,
    grammar_first_reading,
    load_model,
    structure_reading,
)
from nl2hltl2plan.language.learned.slot_model import SlotModel
from nl2hltl2plan.language.learned.structure import StructureModel, load_structure
from nl2hltl2plan.language.learned.structured import StructurePolicy, decide
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.translate import apply_choices, top_candidates

TRUST = Path(__file__).resolve().parents[4] / "tests" / "language" / "data" / "trust"

CANDIDATES: dict[str, StructurePolicy | None] = {
    "grammar_first": None,
    "rescue_0.5": StructurePolicy(rescue=0.5),
    "rescue_0.8": StructurePolicy(rescue=0.8),
    "rescue_0.5_override_0.9": StructurePolicy(rescue=0.5, override=0.9),
    "rescue_0.5_override_0.97": StructurePolicy(rescue=0.5, override=0.97),
    "rescue_0.5_override_0.99": StructurePolicy(rescue=0.5, override=0.99),
    "rescue_0.5_override_0.9_doubt_0.5": StructurePolicy(rescue=0.5, override=0.9, doubt=0.5),
    "structure_always": StructurePolicy(rescue=0.0, override=0.0),
}


def rows_of_set(name: str, n: int) -> list[dict[str, Any]]:
    """The rows of a set; `NAME:SEED` composes it with another seed (e.g. `faithful_unseen:21`)."""
    from nl2hltl2plan.language.learned.compose_frames import frame_all
    from nl2hltl2plan.language.learned.compose_refs import DEV_REFS, HELDOUT_REFS, NEW_REFS, compose_refs
    from nl2hltl2plan.language.learned.train import text_faithful_items
    from nl2hltl2plan.suites.alfred.learned_validation import faithful_split, rows_of, validation_rows

    name, _, seed_text = name.partition(":")
    if name == "plain":
        return [json.loads(line) for line in (TRUST / "plain.jsonl").read_text().splitlines() if line]
    if name.startswith("faithful_"):
        return validation_rows("valid_" + name.split("_")[1], n, int(seed_text or 0))
    if name.startswith("refs"):  # refsdev_unseen / refsheld_seen ...: `compose_refs` phrase families
        family = {"refsheld": HELDOUT_REFS, "refsnew": NEW_REFS}.get(name.split("_")[0], DEV_REFS)
        items = list(faithful_split("valid_" + name.split("_")[1]))
        return rows_of(compose_refs(items, n, family, int(seed_text or 0)))
    style = HELDOUT_STYLE if name.startswith("heldout") else TRAIN_STYLE
    synth = synthesise(text_faithful_items("valid_unseen"), n, style, seed=int(seed_text or 11))
    if name.startswith("framed"):
        synth = frame_all(synth, "held", int(seed_text or 11))
    return [
        {"id": f"{name}.{i}", "n_base": len(s.tasks), "instruction": s.text, "scene": s.scene,
         "tasks": [t.model_dump() for t in s.tasks], "before": s.before, "source_trials": s.trials}
        for i, s in enumerate(synth)
    ]


def converts(parse: LearnedParse, row: dict[str, Any]) -> bool:
    """Whether a reading converts the row: complete, every word accounted for, and the benchmark's strict
    match with the row's tasks and order."""
    if parse.unparsed or not parse.tasks:
        return False
    parse = apply_choices(parse, top_candidates(parse.ambiguities))
    try:
        if account(row["instruction"], parse.tasks, parse.before):
            return False
    except Exception:  # noqa: BLE001 - a cyclic order or a count error is a failure here
        return False
    return match(parse.tasks, parse.before, row["tasks"], row["before"], strict=True).order_ok


def both_readings(
    row: dict[str, Any], model: SlotModel, structure: StructureModel
) -> tuple[LearnedParse, tuple[LearnedParse, float, bool] | None]:
    """The row's grammar-first reading and the structure model's (with its confidence; None: none)."""
    ctx = ParseContext(scene_types(row["scene"]), row["scene"], None, DEFAULT_POLICY, model)
    try:
        g = grammar_first_reading(row["instruction"], ctx)
    except Nl2Hltl2PlanError:  # a refusal (e.g. a contradictory order): a failure, whatever the model
        g = LearnedParse(instruction=row["instruction"], unparsed=["refused"])
    return g, structure_reading(row["instruction"], ctx, structure)


def choose(
    g: LearnedParse, s: tuple[LearnedParse, float, bool] | None, rule: StructurePolicy | None
) -> str:
    """Which reading `rule` takes (`structured.decide`); None: the grammar-first reading alone."""
    if rule is None:
        return "grammar"
    model = (s[0].tasks, s[0].before, s[1]) if s else None
    complete = grammar_complete(g)
    return decide((g.tasks, g.before, complete), model, rule, g.instruction, points=bool(s and s[2]))


def score_set(rows: list[dict[str, Any]]) -> dict[str, dict[Any, list[int]]]:
    """Per candidate policy, per number of base tasks: [right, total]."""
    model, structure = load_model(), load_structure()
    out: dict[str, dict[Any, list[int]]] = {name: {} for name in CANDIDATES}
    for row in rows:
        g, s = both_readings(row, model, structure)
        right = {"grammar": converts(g.model_copy(deep=True), row), "neither": False}
        right["model"] = s is not None and converts(s[0].model_copy(deep=True), row)
        for name, rule in CANDIDATES.items():
            ok = right[choose(g, s, rule)]
            for key in (row["n_base"], "all"):
                cell = out[name].setdefault(key, [0, 0])
                cell[0] += int(ok)
                cell[1] += 1
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m nl2hltl2plan.suites.alfred.structure_validation")
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--sets", default="plain,heldout_unseen,trainstyle_unseen,faithful_seen,faithful_unseen")
    args = ap.parse_args(argv)
    for name in args.sets.split(","):
        rows = rows_of_set(name, args.n)
        scores = score_set(rows)
        keys = sorted(k for k in scores["grammar_first"] if k != "all") + ["all"]
        print(f"\n{name} ({len(rows)} instructions): conversion per number of base tasks")
        print("| policy | " + " | ".join(str(k) for k in keys) + " |")
        print("| --- |" + " --- |" * len(keys))
        for policy, cells in scores.items():
            vals = [f"{100 * cells[k][0] / cells[k][1]:.1f}% ({cells[k][0]}/{cells[k][1]})" for k in keys]
            print(f"| {policy} | " + " | ".join(vals) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
