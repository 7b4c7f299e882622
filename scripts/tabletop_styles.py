"""Everyday-style tabletop rephrasings (issue 28): how many give the original wording's tasks and closed
order, and the exit status of `nl2hltl2plan plan TEXT --world tabletop` for each.

    python scripts/tabletop_styles.py --batch DEV_S11 [--per-sentence]    (STYLES: every style at once)

Prints `batch: same N/M, exit 0 and same E/M, wrong W (exit 0 with other tasks or order), exit codes
{...}`: "same" compares the reading's tasks and closed order with the ground truth, partial readings
included (the command refuses those, exit 2); "exit 0 and same" is what a user gets. --per-sentence adds
one line per wording (never for a held-out batch while rules are being written).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
from collections import Counter
from pathlib import Path

from nl2hltl2plan.language.task_specs import transitive_closure
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.tabletop.tabletop_bench import load_tasks
from nl2hltl2plan.worlds.tabletop_world import tabletop_world

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "experiments"))
import rephrasings  # noqa: E402


def _closed(tasks, before) -> tuple[list, list]:
    key = {t.id: (t.kind, tuple(t.object), tuple(t.receptacle or ())) for t in tasks}
    closure = transitive_closure(before, list(key))
    return sorted(key.values()), sorted((key[a], key[b]) for a, b in closure)


def signature(instruction: str) -> tuple[list, list] | None:
    """Base tasks and closed order, as tests/experiments/test_tabletop.py reads them; None on a refusal."""
    try:
        r = translate(instruction, tabletop_world())
    except Exception:  # a refusal counts as not the same; its exit code is measured separately
        return None
    return _closed(r.tasks, r.before)


def _rows(batch: dict) -> list[tuple[int, list[str]]]:
    """A batch's (task id, wordings) rows; a batch of styles (STYLES: style -> task id -> wordings) gives
    each style's rows in turn."""
    if all(isinstance(v, dict) for v in batch.values()):
        return [row for style in batch.values() for row in style.items()]
    return list(batch.items())


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--batch", required=True)
    parser.add_argument("--per-sentence", action="store_true")
    args = parser.parse_args()
    batch = getattr(rephrasings, args.batch, None)
    if not isinstance(batch, dict):
        print(f"error: no batch {args.batch!r} in tests/experiments/rephrasings.py", file=sys.stderr)
        sys.exit(2)
    tasks = {t.id: t for t in load_tasks()}
    same, exact, wrong, total, codes = 0, 0, 0, 0, Counter()
    for task_id, texts in _rows(batch):
        gt = tasks[task_id].gt_instance()
        reference = _closed(gt.tasks, gt.before)  # the task's ground truth, not a parse of its wording
        for text in texts:
            ok = signature(text) == reference
            rc = subprocess.run(
                ["nl2hltl2plan", "plan", text, "--world", "tabletop"], capture_output=True, check=False
            ).returncode
            same, wrong, total = same + ok, wrong + (rc == 0 and not ok), total + 1
            exact += ok and rc == 0
            codes[rc] += 1
            if args.per_sentence:
                print(f"{'same' if ok else 'DIFF'} rc={rc} task {task_id}: {text}")
    print(
        f"{args.batch}: same {same}/{total}, exit 0 and same {exact}/{total}, wrong {wrong}, exit codes "
        f"{dict(sorted(codes.items()))}"
    )


if __name__ == "__main__":
    main()
