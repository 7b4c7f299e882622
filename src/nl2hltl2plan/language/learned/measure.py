"""Measure the learned backend against the grammar parser, on validation or (once, at the end) test50.

    python -m nl2hltl2plan.language.learned.measure valid [--split valid_seen] [--n-compose 300]
    python -m nl2hltl2plan.language.learned.measure test50

`valid`: single ALFRED task descriptions of the split plus synthetic compositions of that split
(`data.compose`), scored with `language.scoring.match` like the benchmark. `test50`: the benchmark
table (`language.measure.table`) for both backends, and speed.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from typing import Any

from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.data import Composition, Example, compose, faithful, load_examples
from nl2hltl2plan.language.learned.model import SlotModel
from nl2hltl2plan.language.learned.inference import Policy, load_model, parse_instruction
from nl2hltl2plan.language.measure import Generator, evaluate, load_benchmark, offline_generator, table
from nl2hltl2plan.language.tasks import BaseTaskSpec


def learned_generator(policy: Policy | None = None, model: SlotModel | None = None) -> Generator:
    def generate(
        instruction: str, types: set[str], scene: str
    ) -> tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str]]:
        r = parse_instruction(instruction, types, scene, strict=False, policy=policy, model=model)
        return r.tasks, r.before, r.unparsed

    return generate


def _row_single(i: int, e: Example) -> dict[str, Any]:
    return {
        "id": f"{e.trial}#{i}",
        "n_base": 1,
        "instruction": e.text,
        "scene": e.floor_plan,
        "tasks": [e.as_task().model_dump()],
        "before": [],
        "feasible": True,
        "ambiguous": False,
    }


def _row_comp(i: int, c: Composition) -> dict[str, Any]:
    return {
        "id": f"compose{i}",
        "n_base": len(c.tasks),
        "instruction": c.instruction,
        "scene": c.scene,
        "tasks": [t.model_dump() for t in c.tasks],
        "before": c.before,
        "feasible": True,
        "ambiguous": False,
    }


def validation_rows(
    split: str, n_compose: int, seed: int = 0, only_faithful: bool = True
) -> list[dict[str, Any]]:
    """Single annotations and compositions of a validation split (by default those whose text states
    their task, `data.faithful`, as the benchmark's annotation follows the text)."""
    ex = [e for e in load_examples()[split] if faithful(e) or not only_faithful]
    return [_row_single(i, e) for i, e in enumerate(ex)] + [
        _row_comp(i, c) for i, c in enumerate(compose(ex, n_compose, seed))
    ]


def speed(rows: list[dict[str, Any]]) -> str:
    t0 = time.monotonic()
    load_model.cache_clear()
    load_model()
    load_s = time.monotonic() - t0
    gen = learned_generator()
    ms = []
    for r in rows:
        types = scene_types(r["scene"])
        t = time.perf_counter()
        gen(r["instruction"], types, r["scene"])
        ms.append(1000 * (time.perf_counter() - t))
    med = statistics.median(ms)
    return f"model load {load_s:.2f} s; median {med:.1f} ms per instruction (max {max(ms):.0f})"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m nl2hltl2plan.language.learned.measure")
    ap.add_argument("what", choices=["valid", "test50"])
    ap.add_argument("--split", default="valid_seen", choices=["valid_seen", "valid_unseen"])
    ap.add_argument("--n-compose", type=int, default=300)
    ap.add_argument(
        "--all-annotations", action="store_true", help="validate on every annotation, not only faithful ones"
    )
    ap.add_argument("--kind-override", type=float, nargs="*", default=[Policy().kind_override])
    args = ap.parse_args(argv)
    rows = (
        validation_rows(args.split, args.n_compose, only_faithful=not args.all_annotations)
        if args.what == "valid"
        else load_benchmark()
    )
    print(f"{args.what} {args.split if args.what == 'valid' else ''}: {len(rows)} instructions")
    print("grammar (offline):")
    print(table(evaluate(rows, offline_generator)))
    for ov in args.kind_override:
        print(f"learned (kind override {ov}):")
        print(table(evaluate(rows, learned_generator(Policy(kind_override=ov)))))
    if args.what == "test50":
        print(speed(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
