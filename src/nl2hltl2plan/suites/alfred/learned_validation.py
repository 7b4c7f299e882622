"""The text-faithful validation: grammar vs learned backends, per stage, on synthetic 1-4 task instructions.

    python -m nl2hltl2plan.suites.alfred.learned_validation [--split valid_seen] [--n 800] [--seed 0]

Rows come from `faithful.compose_faithful` over the split's annotations re-labelled the benchmark's way
(`faithful.text_task`), a quarter each with 1, 2, 3 and 4 base tasks. Scored with `scoring.match`
(strict), as the benchmark. Stages: `segment` = the number of base tasks is right; `tasks` = a one-to-one
match of the base tasks exists (kind, slots, sliced, count); `order` = ... and the `before` closure
agrees (the conversion).
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from functools import lru_cache
from pathlib import Path
from typing import Any

from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.data import Composition, load_examples
from nl2hltl2plan.language.learned.faithful import FaithfulExample, compose_faithful, faithful_examples
from nl2hltl2plan.suites.alfred.conversion import Generator, evaluate, grammar_generator, learned_generator


@lru_cache(maxsize=4)
def faithful_split(split: str) -> tuple[FaithfulExample, ...]:
    """The split's annotations whose text-faithful label is clear (see `faithful.text_task`)."""
    examples = load_examples()[split]
    plans = {e.floor_plan for e in examples}
    return tuple(faithful_examples(examples, {p: scene_types(p) for p in plans}))


def rows_of(comps: list[Composition]) -> list[dict[str, Any]]:
    return [
        {
            "id": f"{c.scene}#{i}",
            "n_base": len(c.tasks),
            "instruction": c.instruction,
            "scene": c.scene,
            "tasks": [t.model_dump() for t in c.tasks],
            "before": c.before,
            "feasible": True,
            "ambiguous": False,
            "source_trials": c.trials,  # its world holds their objects, as a benchmark scenario's
        }
        for i, c in enumerate(comps)
    ]


def validation_rows(split: str = "valid_seen", n: int = 800, seed: int = 0) -> list[dict[str, Any]]:
    return rows_of(compose_faithful(list(faithful_split(split)), n, seed))


def stage_table(records: list[dict[str, Any]]) -> str:
    """Markdown: per number of base tasks, the share right at each stage (cumulative)."""
    lines = ["| base tasks | n | segment | tasks | tasks+order |", "| --- | --- | --- | --- | --- |"]
    for g in [*sorted({r["n_base"] for r in records}), "all"]:
        rs = [r for r in records if g == "all" or r["n_base"] == g]
        seg = sum(len(r["tasks"]) == r["n_base"] for r in rs)
        tasks = sum(r["tasks_ok"] for r in rs)
        ok = sum(r["ok"] for r in rs)
        n = len(rs)
        lines.append(f"| {g} | {n} | {100 * seg / n:.1f}% | {100 * tasks / n:.1f}% | {100 * ok / n:.1f}% |")
    return "\n".join(lines)


def error_kinds(records: list[dict[str, Any]]) -> Counter[str]:
    """What the strict match complains about (first word of each reason: kind / object / sliced ...)."""
    out: Counter[str] = Counter()
    for r in records:
        for reason in r["reasons"]:
            part = reason.split(": ", 1)[-1]
            for p in part.split("; "):
                out[p.split(" ", 1)[0] if "tasks generated" not in p else "segment"] += 1
    return out


def generators(model_path: Path | None = None) -> dict[str, Generator]:
    from nl2hltl2plan.language.learned.inference import POLICIES, load_model

    model = load_model(model_path)
    out: dict[str, Generator] = {"grammar": grammar_generator}
    for name, policy in POLICIES.items():
        out[name] = learned_generator(policy, model)
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m nl2hltl2plan.suites.alfred.learned_validation")
    ap.add_argument("--split", default="valid_seen", choices=["valid_seen", "valid_unseen"])
    ap.add_argument("--n", type=int, default=800, help="instructions (a quarter each with 1-4 tasks)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument(
        "--model", type=Path, default=None, help="slot model artifact (default: the committed one)"
    )
    ap.add_argument("--backends", nargs="*", default=None, help="grammar and/or policy names")
    args = ap.parse_args(argv)
    rows = validation_rows(args.split, args.n, args.seed)
    print(
        f"{args.split}: {len(faithful_split(args.split))} text-faithful annotations, {len(rows)} instructions"
    )
    for name, gen in generators(args.model).items():
        if args.backends and name not in args.backends:
            continue
        records = evaluate(rows, gen)
        print(f"\n{name}:")
        print(stage_table(records))
        print("errors:", dict(error_kinds(records).most_common(8)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
