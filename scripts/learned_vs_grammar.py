"""Where the learned layers change the grammar's reading, and whether they are right to (issue 28).

    python scripts/learned_vs_grammar.py --sets faithful_seen:1300,refsheld_seen:1300 [--rows DIR] [--show]

For each instruction of a set with ground truth (`structure_validation.rows_of_set`, or the rows that
`scripts/language_failures.py --save-rows DIR` saved): the grammar alone (`grammar.parse_instruction`, no
model at all), the learned parse of the offline backend (`learned.inference.parse_instruction`: the slot
model fills and orders slots, the structure model's reading is weighed against the grammar's by
`structured.decide`), and which decision the arbitration took, at what confidence. Where exactly one of the
two converts the row (the benchmark's strict match, a reading with unread words is a failure), the change
is put down to its stage: the arbitration (the structure model's reading taken, or neither) or the slot
model (the fields of the tasks it changed). Both read the text as written in the scene's object lists
(the household reader's rewriting and the world's counts and refusals are `language_failures.py`'s
household reader; compare its two readers row by row with `scripts/compare_outcomes.py`). Last, where
both readings are complete and differ and only the override threshold decides (no order word or unsaid
treatment rules the model's out: `structured.against_the_words`), which one is right, per band of the
structure model's confidence: the evidence for `StructurePolicy.override` and `doubt`.
"""

from __future__ import annotations

import argparse
import itertools
import json
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.grammar import parse_instruction as grammar_parse
from nl2hltl2plan.language.grammar.order_relations import ORDER_LEFT_OPEN
from nl2hltl2plan.language.grammar.references import NOT_CERTAIN
from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.inference import (
    DEFAULT_POLICY,
    LearnedParse,
    ParseContext,
    grammar_complete,
    grammar_first_reading,
    load_model,
    structure_reading,
)
from nl2hltl2plan.language.learned.structure import load_structure
from nl2hltl2plan.language.learned.structured import against_the_words, decide, same_reading
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.suites.alfred.structure_validation import converts, rows_of_set

FIELDS = ("kind", "object", "count", "sliced", "container", "receptacle", "light")
BANDS = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.97, 1.01)  # the structure model's confidence


def changed_fields(a: list[BaseTaskSpec], b: list[BaseTaskSpec]) -> list[str]:
    """What differs between two readings' tasks, task by task in text order ("A.receptacle"), or the
    number of tasks when that differs."""
    if len(a) != len(b):
        return [f"tasks {len(a)} -> {len(b)}"]
    pairs = zip(a, b, strict=True)
    return [f"{x.id}.{f}" for x, y in pairs for f in FIELDS if getattr(x, f) != getattr(y, f)]


def stage(decision: str, confidence: float | None, fields: list[str]) -> str:
    """The stage a change of the reading is put down to: the arbitration when it took the structure
    model's reading or neither, else the slot model (or the order alone, where no field changed)."""
    if decision != "grammar":
        return f"arbitration: {decision} ({confidence:.2f})" if confidence is not None else decision
    return "slot model or rescue: " + ", ".join(fields) if fields else "order"


def _refused(text: str) -> LearnedParse:
    return LearnedParse(instruction=text, unparsed=["refused"])


def compare_row(row: dict[str, Any]) -> dict[str, Any]:
    """The grammar alone and the learned parse of one row, and the arbitration's decision."""
    text, types = row["instruction"], scene_types(row["scene"])
    try:
        alone = LearnedParse(**grammar_parse(text, types, row["scene"], strict=False).model_dump())
    except Nl2Hltl2PlanError:  # a refusal (a contradictory order): a failure
        alone = _refused(text)
    ctx = ParseContext(types, row["scene"], None, DEFAULT_POLICY, load_model())
    try:
        first = grammar_first_reading(text, ctx)
    except Nl2Hltl2PlanError:
        first = _refused(text)
    s = structure_reading(text, ctx, load_structure())
    uncertain = any(NOT_CERTAIN in u or ORDER_LEFT_OPEN in u for u in first.unparsed)
    rule = DEFAULT_POLICY.structure
    assert rule is not None
    model = (s[0].tasks, s[0].before, s[1]) if s else None
    decision = decide(
        (first.tasks, first.before, grammar_complete(first)), model, rule, text, bool(s and s[2]), uncertain
    )
    learned = s[0] if decision == "model" and s else first if decision == "grammar" else _refused(text)
    # both readings complete and different where only the threshold decides (`structured.decide`)
    open_choice = (
        s is not None
        and grammar_complete(first)
        and not uncertain
        and not same_reading(s[0].tasks, s[0].before, first.tasks, first.before)
        and not against_the_words(text, (s[0].tasks, s[0].before), (first.tasks, first.before))
    )
    return {
        "first": converts(first.model_copy(deep=True), row),
        "model": s is not None and converts(s[0].model_copy(deep=True), row),
        "open_choice": open_choice,
        "grammar": converts(alone.model_copy(deep=True), row),
        "learned": converts(learned.model_copy(deep=True), row),
        "decision": decision,
        "confidence": s[1] if s else None,
        "fields": changed_fields(alone.tasks, learned.tasks),
    }


def bands(out: list[dict[str, Any]]) -> list[str]:
    """Markdown rows: where both readings are complete and differ and only the override threshold
    decides, per band of the structure model's confidence, which of the two converts the row."""
    lines = []
    for lo, hi in itertools.pairwise(BANDS):
        b = [o for o in out if o["open_choice"] and lo <= o["confidence"] < hi]
        grammar = sum(o["first"] and not o["model"] for o in b)
        model = sum(o["model"] and not o["first"] for o in b)
        neither = sum(not o["first"] and not o["model"] for o in b)
        lines.append(f"| {lo:.2f}-{min(hi, 1.0):.2f} | {len(b)} | {grammar} | {model} | {neither} |")
    return lines


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/learned_vs_grammar.py")
    ap.add_argument("--sets", required=True)
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--rows", type=Path, default=None, help="read the rows language_failures.py saved in DIR")
    ap.add_argument("--show", action="store_true", help="print each row the learned layers change")
    args = ap.parse_args()
    print("| set | rows | grammar alone | learned | learned wins | learned loses | structure model taken |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    stages: Counter[tuple[str, str]] = Counter()
    every: list[dict[str, Any]] = []
    for name in args.sets.split(","):
        saved = args.rows / f"{name}.json" if args.rows else None
        rows = json.loads(saved.read_text()) if saved and saved.exists() else rows_of_set(name, args.n)
        out = [compare_row(r) for r in rows]
        every += out
        wins = [o for o in out if o["learned"] and not o["grammar"]]
        losses = [o for o in out if o["grammar"] and not o["learned"]]
        for o, row in zip(out, rows, strict=True):
            if o["learned"] != o["grammar"]:
                what = stage(o["decision"], o["confidence"], o["fields"])
                stages["wins" if o["learned"] else "loses", what.split(" (")[0].split(":")[0]] += 1
                if args.show:
                    sign = "+" if o["learned"] else "-"
                    print(f"  {sign} {what}: {row['instruction'][:160]!r}", file=sys.stderr)
        taken = sum(o["decision"] == "model" for o in out)
        print(
            f"| {name} | {len(out)} | {sum(o['grammar'] for o in out)} | {sum(o['learned'] for o in out)} "
            f"| {len(wins)} | {len(losses)} | {taken} |"
        )
    print("\n| the learned layers | stage | rows |\n| --- | --- | --- |")
    for (verdict, where), n in sorted(stages.items()):
        print(f"| {verdict} | {where} | {n} |")
    print("\n| both complete, different: model confidence | rows | grammar right | model right | neither |")
    print("| --- | --- | --- | --- | --- |")
    print("\n".join(bands(every)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
