# Run: PYTHONPATH=src python3 tests/reliability/coverage_false_alarms.py   (needs ../shared/data)
"""False-positive rate of decomposition_problems on ALFRED valid_seen/valid_unseen task descriptions,
with the trial's own PDDL targets as the (correct) decomposition."""

import collections
import gzip
import json
from dataclasses import dataclass

from nl2hltl2plan.config import data_path
from nl2hltl2plan.language.learned.data import KIND_OF_TASK_TYPE
from nl2hltl2plan.language.semantic_check import decomposition_problems

KIND = KIND_OF_TASK_TYPE


@dataclass
class T:
    kind: str
    object: str
    sliced: bool
    container: str | None
    receptacle: str | None
    light: str | None


n = bad = 0
words = collections.Counter()
shown = 0
with gzip.open(data_path("alfred", "trials.jsonl.gz"), "rt") as f:
    for line in f:
        r = json.loads(line)
        if r["split"] not in ("valid_seen", "valid_unseen") or r["task_type"] not in KIND:
            continue
        p = r["pddl_params"]
        t = T(
            KIND[r["task_type"]],
            p["object_target"],
            bool(p.get("object_sliced")),
            p.get("mrecep_target") or None,
            p.get("parent_target") or None,
            p.get("toggle_target") or None,
        )
        for a in r["annotations"]:
            desc = a["task_desc"] if isinstance(a, dict) else a
            n += 1
            pr = decomposition_problems(desc, [t])
            if pr:
                bad += 1
                for x in pr:
                    words[x.split("'")[1].lower()] += 1
                if shown < 10:
                    shown += 1
                    print(desc, "|", pr, "|", t.kind, t.object, t.receptacle)
print("task descriptions", n, "flagged", bad, f"{bad / n * 100:.1f}%")
print(words.most_common(20))
