"""Everyday-style tabletop rephrasings (issue 28): how many give the original wording's tasks and closed
order, and the exit status of `nl2hltl2plan plan TEXT --world tabletop` for each.

    python scripts/tabletop_styles.py --batch DEV_S11 [--per-sentence]    (STYLES: every style at once)
    python scripts/tabletop_styles.py --batch all                         (every batch, one line each)

Prints `batch: same N/M, exit 0 and same E/M, wrong W (exit 0 with other tasks or order), exit codes
{...}`: "same" compares the reading's tasks and closed order with the ground truth, partial readings
included (the command refuses those, exit 2); "exit 0 and same" is what a user gets. --per-sentence adds
one line per wording (never for a held-out batch while rules are being written).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
from collections import Counter
from pathlib import Path

from nl2hltl2plan.cli.main import main as cli_main
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


def exit_code(text: str) -> int:
    """The exit status of `nl2hltl2plan plan TEXT --world tabletop`, run in this process (a subprocess per
    wording made `--batch all` take a quarter of an hour); its output is discarded."""
    sink = io.StringIO()
    with contextlib.redirect_stdout(sink), contextlib.redirect_stderr(sink):
        return cli_main(["plan", text, "--world", "tabletop"])


def measure(name: str, batch: dict, tasks: dict, per_sentence: bool) -> Counter:
    """Print the batch's line (and one line per wording if asked); return its counts."""
    counts: Counter = Counter()
    codes: Counter = Counter()
    for task_id, texts in _rows(batch):
        gt = tasks[task_id].gt_instance()
        reference = _closed(gt.tasks, gt.before)  # the task's ground truth, not a parse of its wording
        for text in texts:
            ok = signature(text) == reference
            rc = exit_code(text)
            counts.update(same=ok, wrong=rc == 0 and not ok, total=1, exact=ok and rc == 0)
            codes[rc] += 1
            if per_sentence:
                print(f"{'same' if ok else 'DIFF'} rc={rc} task {task_id}: {text}")
    n = counts["total"]
    print(
        f"{name}: same {counts['same']}/{n}, exit 0 and same {counts['exact']}/{n}, wrong {counts['wrong']}, "
        f"exit codes {dict(sorted(codes.items()))}"
    )
    return counts


def batches() -> dict[str, dict]:
    """Every batch of tests/experiments/rephrasings.py, in file order."""
    return {k: v for k, v in vars(rephrasings).items() if k.isupper() and isinstance(v, dict)}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--batch", required=True, help="a batch's name, or 'all'")
    parser.add_argument("--per-sentence", action="store_true")
    args = parser.parse_args()
    tasks = {t.id: t for t in load_tasks()}
    if args.batch == "all":
        total: Counter = Counter()
        for name, batch in batches().items():
            total.update(measure(name, batch, tasks, args.per_sentence))
        print(
            f"all: same {total['same']}/{total['total']}, exit 0 and same {total['exact']}/{total['total']}, "
            f"wrong {total['wrong']}"
        )
        return
    batch = getattr(rephrasings, args.batch, None)
    if not isinstance(batch, dict):
        print(f"error: no batch {args.batch!r} in tests/experiments/rephrasings.py", file=sys.stderr)
        sys.exit(2)
    measure(args.batch, batch, tasks, args.per_sentence)


if __name__ == "__main__":
    main()
