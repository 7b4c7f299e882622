"""Offline language stage time against instruction length (issue 25: the parser must be near-linear and
the instruction capped at 2,000 characters).

    PYTHONPATH=src python scripts/bench_instruction_length.py [--out FILE]
    (default FILE: results/reliability/instruction_length.md)

For five instruction shapes (the paper's dishwasher sentence repeated, long `and` lists, comma lists,
`then` chains, many short sentences) it times `translate(..., backend="offline")` on the demo world,
Algorithm 1 included, at lengths up to the cap (median of 7 runs), and reports the growth exponent
over 500 to 2,000 characters (time ~ length^k: k = 1 is linear), then the time to refuse longer
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
RUNS = 7  # median of 7: the machine is shared


def longest(shape: Callable[[int], str], limit: int) -> str:
    """The longest text of this shape within `limit` characters."""
    k = 1
    while len(shape(k + 1)) <= limit:
        k += 1
    return shape(k)


def growth_exponent(lengths: list[int], times: list[float]) -> float:
    """The least-squares slope of log(time) against log(length): time ~ length^k."""
    xs, ys = [math.log(x) for x in lengths], [math.log(y) for y in times]
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys, strict=True)) / sum((x - mx) ** 2 for x in xs)


def timed(text: str, world: object) -> tuple[float, str]:
    runs, outcome = [], ""
    for _ in range(RUNS):
        t0 = time.perf_counter()
        try:
            res = translate(text, world)  # type: ignore[arg-type]
            outcome = f"{len(res.tasks)} tasks"
        except Nl2Hltl2PlanError as exc:
            outcome = f"refused: {exc}"
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
        f"`translate(text, demo_world())`, offline backend, Algorithm 1 included; median of {RUNS} runs, "
        "seconds; k: least-squares slope of log time against log length over 500, 1,000 and 2,000 "
        "characters.",
        "",
        "| shape | " + " | ".join(f"≤ {t:,} chars" for t in TARGETS) + " | exponent k |",
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
        k = growth_exponent(lengths[2:], times[2:])
        lines.append(f"| {name} | " + " | ".join(cells) + f" | {k:.2f} |")
    lines += [
        "",
        "Before this issue's linear-time changes (Algorithm 1 looking nodes up in a list and walking to the "
        "root for each depth, the recipes counting all tasks' demand once per task), the same script gave "
        "0.558 s for the 2,000-character comma list (k = 1.45); without the cap, the dishwasher sentence "
        "took 2.85 s at 8.4 kB and the issue measured 46 s at 15.7 kB.",
        "",
        "Longer instructions are refused before any parsing (exit 2):",
        "",
    ]
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
