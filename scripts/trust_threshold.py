"""Choose the learned model's fill threshold (`learned.inference.Policy.fill`) on validation data only.

    python scripts/trust_threshold.py [--split valid_seen] [--n 800]

For each candidate threshold, the default backend runs on the split's composed instructions
(`suites.alfred.learned_validation.validation_rows`) and on issue 23's own sets
(tests/language/data/trust); each
instruction is converted (matches, nothing unread), refused/partial (an error or `unparsed` after check
1) or wrong (does not match, yet nothing unread: a plan would miss or change part of the text). The
threshold kept is the lowest with the fewest wrong conversions, then the most converted.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from collections import Counter
from pathlib import Path

from nl2hltl2plan.language.learned.inference import Policy
from nl2hltl2plan.suites.alfred.conversion import evaluate, learned_generator
from nl2hltl2plan.suites.alfred.learned_validation import validation_rows

sys.path.insert(0, str(Path(__file__).resolve().parent))
import trust_sets  # noqa: E402

CANDIDATES = (0.0, 0.3, 0.5, 0.7, 0.9)


def validation_counts(rows: list[dict], policy: Policy) -> Counter[str]:
    out: Counter[str] = Counter()
    for r in evaluate(rows, learned_generator(policy)):
        out["refused" if r["refused"] else "converted" if r["ok"] else "wrong"] += 1
    return out


def own_counts(policy: Policy) -> Counter[str]:
    import nl2hltl2plan.language.learned.inference as inference

    default = inference.DEFAULT_POLICY
    inference.DEFAULT_POLICY = policy  # the backend's policy for this run (`plan` as a user runs it)
    try:
        out: Counter[str] = Counter()
        for name in ("plain", "mixed"):
            for gt in trust_sets.load(name):
                what, _ = trust_sets.outcome(gt)
                out["refused" if what in ("refused", "partial") else what] += 1
        return out
    finally:
        inference.DEFAULT_POLICY = default


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/trust_threshold.py")
    ap.add_argument("--split", default="valid_seen", choices=["valid_seen", "valid_unseen"])
    ap.add_argument("--n", type=int, default=800)
    args = ap.parse_args()
    rows = validation_rows(args.split, args.n, 0)
    print(f"| fill | {args.split} converted | refused | wrong | own sets converted | refused | wrong |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    scores = []
    for fill in CANDIDATES:
        policy = dataclasses.replace(Policy(), fill=fill)
        v, o = validation_counts(rows, policy), own_counts(policy)
        print(
            f"| {fill} | {v['converted']} | {v['refused']} | {v['wrong']} | {o['converted']} | "
            f"{o['refused']} | {o['wrong']} |"
        )
        scores.append((v["wrong"] + o["wrong"], -(v["converted"] + o["converted"]), fill))
    print(f"chosen: fill = {min(scores)[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
