"""Score user-style sets (tests/language/data/styles/NAME.txt) as `plan --json` answers them, planning
included (a line with a `trials:` column as `plan --world SCENE --trials ...`): converted (exit 0, solved,
not partial, tasks and order as the ground truth), refused as meant (exit 2 on a line to refuse), false
refusal (exit 2 on a line to read), wrong (exit 0 on a line to refuse, or another reading), other (any
other exit).

    python scripts/plan_json_sets.py users_h153dev users_h153held
"""

from __future__ import annotations

import contextlib
import io
import json
import sys
from collections import Counter

import trust_sets

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def score(name: str) -> Counter[str]:
    counts: Counter[str] = Counter()
    for gt in trust_sets.load(name):
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                # a line's `trials:` column: the world holds those trials' objects (trust_sets.world_of)
                trials = ["--trials", *gt.source_trials] if gt.source_trials else []
                rc = main(["plan", gt.instruction, "--world", gt.scene, *trials, "--json", "--timeout", "60"])
            except SystemExit as exc:
                rc = exc.code if isinstance(exc.code, int) else 2
        said = json.loads(out.getvalue()) if out.getvalue().strip().startswith("{") else {}
        if rc == 0 and said.get("status") == "solved" and not said.get("partial"):
            tasks = [BaseTaskSpec.model_validate(t) for t in said.get("tasks", [])]
            before = [tuple(b) for b in said.get("before", [])]
            gt_tasks = [t.model_dump() for t in gt.tasks]
            ok = gt.feasible and match(tasks, before, gt_tasks, gt.before, strict=False).order_ok
            what = "converted" if ok else "wrong"
        elif rc == 2:
            what = "false refusal" if gt.feasible else "refused as meant"
        else:
            what = f"other (exit {rc})"
        counts[what] += 1
        last = (err.getvalue().strip().splitlines() or [""])[-1][:160]
        print(f"{name}\t{rc}\t{what}\t{gt.instruction}\t{last}", flush=True)
    return counts


if __name__ == "__main__":
    for set_name in sys.argv[1:]:
        print(set_name, dict(score(set_name)))
