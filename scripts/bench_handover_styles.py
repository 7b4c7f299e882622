"""First contact of the handover reader on rephrasings by style (issue 24: held-out rephrasings of the
eight Table III instructions must give the written specs).

    PYTHONPATH=src python scripts/bench_handover_styles.py [--batch NAME] [--verbose] [--file F]
    (NAME: a batch of the file: dev, dev2 ... dev44, dev50 ... dev54, validation, validation2 ...
    validation17, dev64 ... dev69, dev70 ..., or 'all' for a row per batch; default dev)
    (default F: tests/experiments/handover_styles_session10.json)

Each sentence of the batch is read on instance 0 of its task (`translate`, offline) and judged against the
task's written spec node by node (`specs_equivalent`): "same", "refused" (exit 2, named) or "other" (a
different spec: a misreading). Prints a markdown table per style, the mean time per sentence (reading and
judging) and, with --verbose, each sentence that is not "same" with the reason.
"""

from __future__ import annotations

import argparse
import json
import platform
import subprocess
import time
from collections import Counter
from pathlib import Path

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.handover.handover_bench import instance, load_tasks, specs_equivalent

DEFAULT = Path(__file__).resolve().parents[1] / "tests" / "experiments" / "handover_styles_session10.json"
TASKS = {t.id: t for t in load_tasks()}


def verdict(task_id: int, text: str) -> tuple[str, str]:
    try:
        result = translate(text, instance(TASKS[task_id], 0, 0).as_world())
    except Nl2Hltl2PlanError as exc:
        return "refused", str(exc)
    assert result.spec is not None
    equal, why = specs_equivalent(result.spec, TASKS[task_id].hierarchical())
    return ("same", "") if equal else ("other", why)


def judge(styles: dict[str, dict[str, str]]) -> tuple[dict[str, Counter[str]], list[str]]:
    """Per style: counts of "same", "refused" and "other"; and a line per sentence that is not "same"."""
    per_style: dict[str, Counter[str]] = {}
    misses: list[str] = []
    for style, texts in styles.items():
        counts: Counter[str] = Counter()
        for task, text in texts.items():
            kind, why = verdict(int(task), text)
            counts[kind] += 1
            if kind != "same":
                misses.append(f"- {kind} ({style}, task {task}): {text!r}\n  {why[:300]}")
        per_style[style] = counts
    return per_style, misses


def row(name: str, counts: Counter[str]) -> str:
    cells = [sum(counts.values()), counts["same"], counts["refused"], counts["other"]]
    return f"| {name} | " + " | ".join(map(str, cells)) + " |"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--batch", default="dev", help="a batch (key) of --file, e.g. dev10; 'all': each")
    parser.add_argument("--file", type=Path, default=DEFAULT)
    parser.add_argument("--verbose", action="store_true")
    args = parser.parse_args()
    batches = json.loads(args.file.read_text())
    names = [b for b in batches if b != "about"] if args.batch == "all" else [args.batch]
    if any(b not in batches or b == "about" for b in names):
        parser.error(f"no batch {args.batch!r} in {args.file}")
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout
    print(f"batch {args.batch} of {args.file.name}; commit {commit.strip()}; {platform.machine()} CPU\n")
    first = "batch" if args.batch == "all" else "style"
    print(f"| {first} | sentences | same spec | refused | other spec |\n|---|---|---|---|---|")
    total: Counter[str] = Counter()
    misses: list[str] = []
    start = time.perf_counter()
    for name in names:
        per_style, missed = judge(batches[name])
        misses += [f"{name}: {line[2:]}" if args.batch == "all" else line for line in missed]
        batch_total: Counter[str] = sum(per_style.values(), Counter())
        total += batch_total
        rows = [row(name, batch_total)] if args.batch == "all" else [row(s, c) for s, c in per_style.items()]
        print("\n".join(rows))
    print(row("**all**" if args.batch == "all" else "all", total))
    per = (time.perf_counter() - start) / max(1, sum(total.values()))
    print(f"\n{per * 1000:.0f} ms per sentence (reading and the node-by-node Spot check)")
    if args.verbose:
        print("\n" + "\n".join(misses))


if __name__ == "__main__":
    main()
