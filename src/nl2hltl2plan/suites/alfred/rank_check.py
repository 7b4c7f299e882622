"""How often the type ranker's top candidate is the type the annotation was written for.

    python -m nl2hltl2plan.suites.alfred.rank_check [--folds 5]

Two checks, slot model alone against slot model + ranker, over the words that the parse leaves with
several scene types and whose ALFRED type is among them:
- group k-fold over the train annotations, whole task families (task type, objects, floor plan) held out
  together, as test50's families are held out of training (the ranker is refitted per fold; the slot
  model is the committed one);
- valid_seen and valid_unseen with the committed ranker.
"""

from __future__ import annotations

import argparse
import sys

from nl2hltl2plan.errors import DataError, Nl2Hltl2PlanError
from nl2hltl2plan.language.learned.data import Example, load_examples
from nl2hltl2plan.language.learned.inference import load_model
from nl2hltl2plan.language.learned.ranker import RankCase, TypeRanker
from nl2hltl2plan.language.learned.train import ranking_cases


def family(e: Example) -> str:
    return "|".join(map(str, (e.floor_plan, e.kind, e.object, e.container, e.receptacle, e.light, e.sliced)))


def top_share(cases: list[RankCase], ranker: TypeRanker | None) -> int:
    """How many cases' top candidate is their label (the slot model's order when `ranker` is None)."""
    right = 0
    for c in cases:
        order = (
            ranker.order(c.clause, list(c.candidates))
            if ranker
            else sorted(c.candidates, key=lambda x: -x[1])
        )
        right += order[0][0] == c.label
    return right


def family_cases() -> tuple[list[RankCase], list[str]]:
    """The ranking cases of ALFRED's train annotations (the slot model alone's candidates), each with its
    task family (`family`), for folds that hold whole families out."""
    plain = load_model().without_ranker()
    cases: list[RankCase] = []
    groups: list[str] = []
    for e in load_examples()["train"]:
        found = ranking_cases(plain, [e])
        cases += found
        groups += [family(e)] * len(found)
    return cases, groups


def cross_validation(folds: int = 5, seed: int = 0) -> tuple[int, int, int]:
    """(cases, right by the slot model alone, right by a ranker fitted on the other folds' families)."""
    try:
        from sklearn.model_selection import GroupKFold
    except ImportError as exc:
        raise DataError("the ranking check needs scikit-learn: pip install scikit-learn") from exc

    cases, groups = family_cases()
    alone = ranked = 0
    for train_idx, test_idx in GroupKFold(folds).split(cases, groups=groups):
        ranker = TypeRanker.fit([cases[i] for i in train_idx], seed=seed)
        held = [cases[i] for i in test_idx]
        alone += top_share(held, None)
        ranked += top_share(held, ranker)
    return len(cases), alone, ranked


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m nl2hltl2plan.suites.alfred.rank_check")
    ap.add_argument("--folds", type=int, default=5)
    args = ap.parse_args(argv)
    try:
        n, alone, ranked = cross_validation(args.folds)
    except Nl2Hltl2PlanError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(
        f"train, group {args.folds}-fold by family: {n} words; top = label: slot model {alone} "
        f"({100 * alone / n:.1f}%), + ranker {ranked} ({100 * ranked / n:.1f}%)"
    )
    model = load_model()
    for split in ("valid_seen", "valid_unseen"):
        cases = ranking_cases(model.without_ranker(), load_examples()[split])
        a, r = top_share(cases, None), top_share(cases, model.ranker)
        print(f"{split}: {len(cases)} words; top = label: slot model {a}, + ranker {r}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
