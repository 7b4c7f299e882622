"""Offline language stage time against instruction length (issue 25: the parser must be near-linear and
the instruction capped at 2,000 characters).

    PYTHONPATH=src python scripts/bench_instruction_length.py [--out FILE]
    (default FILE: results/reliability/instruction_length.md)

For five instruction shapes (the paper's dishwasher sentence repeated, long `and` lists, comma lists,
`then` chains, many short sentences) it times `translate(..., backend="offline")` on the demo world,
Algorithm 1 included, at lengths up to the cap (median of 3 runs), and reports the growth exponent
between 500 and 2,000 characters (time ~ length^k: k = 1 is linear), then the time to refuse longer
instructions (15.7 kB and 1 MB, which the last campaign measured at 46 s and "still running").
"""

from __future__ import annotations

import argparse
import math
import platform
import statistics
import subprocess
import time
from collections.abc import Callable
from pathlib import Path

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import MAX_INSTRUCTION_CHARS, translate
from nl2hltl2plan.worlds.demo import demo_world

DISHWASHER = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack. "
)
ITEMS = ["plate", "mug", "fork", "cup", "saucer"]
SHAPES: dict[str, Callable[[int], str]] = {
    "dishwasher sentence repeated": lambda k: DISHWASHER * k,
    "one long 'and' list": lambda k: "put the " + " and the ".join((ITEMS * k)[:k]) + " in the lower rack",
    "one long comma list": lambda k: "put the " + ", ".join((ITEMS * k)[:k]) + " in the lower rack",
    "'then' chain": lambda k: "put the plate in the lower rack" + " then put the mug in the upper rack" * k,
    "short sentences": lambda k: "Put the plate in the lower rack. " * k,
}
TARGETS = [125, 250, 500, 1000, 2000]


def longest(shape: Callable[[int], str], limit: int) -> str:
    """The longest text of this shape within `limit` characters."""
    k = 1
    while len(shape(k + 1)) <= limit:
        k += 1
    return shape(k)


def timed(text: str, world: object) -> tuple[float, str]:
    runs, outcome = [], ""
    for _ in range(3):
        t0 = time.perf_counter()
        try:
            res = translate(text, world)  # type: ignore[arg-type]
            outcome = f"{len(res.tasks)} tasks"
        except Nl2Hltl2PlanError as exc:
            outcome = f"refused: {str(exc)[:60]}"
        runs.append(time.perf_counter() - t0)
    return statistics.median(runs), outcome


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=Path("results/reliability/instruction_length.md"))
    args = ap.parse_args()
    world = demo_world()
    translate("Put the plates in the lower rack", world)  # load the model and the grammar once
    lines = [
        "# Offline language stage: time against instruction length",
        "",
        "Command: `PYTHONPATH=src python scripts/bench_instruction_length.py` "
        f"(cap: {MAX_INSTRUCTION_CHARS:,} characters)  ",
        f"Commit: {_commit()}  ",
        f"Machine: {platform.node()}, {platform.processor() or platform.machine()}, "
        f"Python {platform.python_version()} (2 shared cores)",
        "",
        "`translate(text, demo_world())`, offline backend, Algorithm 1 included; median of 3 runs, seconds.",
        "",
        "| shape | " + " | ".join(f"≤ {t:,} chars" for t in TARGETS) + " | exponent k (500 → 2,000) |",
        "| --- | " + " | ".join("---" for _ in TARGETS) + " | --- |",
    ]
    for name, shape in SHAPES.items():
        cells, times, lengths = [], [], []
        for target in TARGETS:
            text = longest(shape, target)
            t, outcome = timed(text, world)
            cells.append(f"{t:.3f} ({len(text)} ch, {outcome})")
            times.append(t)
            lengths.append(len(text))
            print(f"{name:32s} {len(text):5d} chars {t:7.3f} s  {outcome}", flush=True)
        k = math.log(times[-1] / times[2]) / math.log(lengths[-1] / lengths[2])
        lines.append(f"| {name} | " + " | ".join(cells) + f" | {k:.2f} |")
    lines += ["", "Longer instructions are refused before any parsing (exit 2):", ""]
    for size in (2001, 15_700, 1_000_000):
        text = (DISHWASHER * (size // len(DISHWASHER) + 1))[:size]
        t, outcome = timed(text, world)
        lines.append(f"- {size:,} characters: {t * 1000:.3f} ms, {outcome}")
        print(f"refusal {size:7d} chars {t * 1000:.3f} ms {outcome}", flush=True)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines) + "\n")
    print(f"wrote {args.out}")


def _commit() -> str:
    try:
        return subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, check=True
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


if __name__ == "__main__":
    main()
