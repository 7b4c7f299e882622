"""Does the pretrained encoder (all-MiniLM-L6-v2, frozen) help the slot model or the type ranker?

    python scripts/encoder_measure.py [--part slots|ranker|all] [--scales 1,3] [--cases FILE.json]

Validation only (ALFRED train minus the excluded trials for fitting; valid_seen / valid_unseen and the
family-held-out folds for scoring; test50 is never read):
- slots: today's slot model (TF-IDF) against TF-IDF + the clause's sentence embedding x scale, both
  fitted the same way (seed 0, C 8), scored on the text-faithful labels of valid_seen / valid_unseen
  (`train.text_slot_accuracy`);
- ranker: the type ranker against the ranker + the encoder's features (`encoder_features.py`: the
  clause-type cosine, and that plus the candidate x embedding dimensions), in rank_check's group 5-fold
  over the train families and on valid_seen / valid_unseen (fitted on all train cases).
Needs the `encoder` and `train` extras and the wheel (docs/learned.md). Output: a markdown table per part.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.learned.data import load_examples
from nl2hltl2plan.language.learned.encoder import SentenceEncoder
from nl2hltl2plan.language.learned.encoder_features import EncoderFeatures
from nl2hltl2plan.language.learned.inference import load_model
from nl2hltl2plan.language.learned.ranker import ExtraFeatures, RankCase, TypeRanker
from nl2hltl2plan.language.learned.slot_model import SlotModel
from nl2hltl2plan.language.learned.train import (
    ranking_cases,
    text_faithful_items,
    text_faithful_train,
    text_slot_accuracy,
)
from nl2hltl2plan.suites.alfred.rank_check import family_cases, top_share

COLUMNS = ("kind", "object", "receptacle", "container", "light", "sliced", "all")


def measure_slots(encoder: SentenceEncoder, scales: list[float]) -> list[str]:
    train = text_faithful_train()
    splits = {s: text_faithful_items(s) for s in ("valid_seen", "valid_unseen")}
    lines = ["| model | split | " + " | ".join(COLUMNS) + " |", "|" + " --- |" * (len(COLUMNS) + 2)]
    t0 = time.monotonic()
    models = {"TF-IDF (today)": SlotModel.fit(train, seed=0)}
    print(f"fitted today's slot model in {time.monotonic() - t0:.0f} s", file=sys.stderr)
    cache: dict[str, Any] = {}  # one embedding per text, shared by every scale
    for scale in scales:
        feats = EncoderFeatures(encoder, scale=scale)
        feats.cache = cache
        t0 = time.monotonic()
        feats.embed([e.text for e in train] + [it.text for items in splits.values() for it in items])
        print(f"embedded {len(feats.cache)} texts in {time.monotonic() - t0:.0f} s", file=sys.stderr)
        models[f"TF-IDF + encoder x{scale:g}"] = SlotModel.fit(train, seed=0, dense=feats.slot_features)
    for name, model in models.items():
        for split, items in splits.items():
            acc = text_slot_accuracy(model, items)
            cells = " | ".join(f"{100 * acc[c]:.1f}" for c in COLUMNS)
            lines.append(f"| {name} | {split} ({len(items)}) | {cells} |")
    return lines


def train_cases(cache: Path | None) -> tuple[list[RankCase], list[str]]:
    """rank_check's cases (the slot model alone's candidates) with their families; cached as JSON."""
    if cache and cache.exists():
        rows = json.loads(cache.read_text())
        return [RankCase(r[0], tuple((t, q) for t, q in r[1]), r[2]) for r in rows[0]], rows[1]
    cases, groups = family_cases()
    if cache:
        cache.write_text(json.dumps([[[c.clause, c.candidates, c.label] for c in cases], groups]))
    return cases, groups


def measure_ranker(encoder: SentenceEncoder, cache: Path | None, folds: int = 5) -> list[str]:
    from sklearn.model_selection import GroupKFold

    cases, groups = train_cases(cache)
    plain = load_model().without_ranker()
    valid = {s: ranking_cases(plain, load_examples()[s]) for s in ("valid_seen", "valid_unseen")}
    # name -> (a ranker is fitted, its extra features)
    variants: dict[str, tuple[bool, ExtraFeatures | None]] = {
        "slot model alone": (False, None),
        "ranker (today)": (True, None),
        "ranker + encoder cosine": (True, EncoderFeatures(encoder).rank_features),
        "ranker + encoder cosine + type x dims": (True, EncoderFeatures(encoder, dims=True).rank_features),
    }
    lines = [
        f"| model | train, group {folds}-fold by family ({len(cases)}) | "
        + " | ".join(f"{s} ({len(v)})" for s, v in valid.items())
        + " |",
        "| --- | --- | --- | --- |",
    ]
    for name, (fitted, extra) in variants.items():
        right = 0
        for train_idx, test_idx in GroupKFold(folds).split(cases, groups=groups):
            ranker = TypeRanker.fit([cases[i] for i in train_idx], seed=0, extra=extra) if fitted else None
            right += top_share([cases[i] for i in test_idx], ranker)
        full = TypeRanker.fit(cases, seed=0, extra=extra) if fitted else None
        cells = [f"{right} ({100 * right / len(cases):.1f} %)"]
        for v in valid.values():
            r = top_share(v, full)
            cells.append(f"{r} ({100 * r / len(v):.1f} %)")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
        print(lines[-1], file=sys.stderr)
    return lines


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python scripts/encoder_measure.py")
    ap.add_argument("--part", choices=["slots", "ranker", "all"], default="all")
    ap.add_argument("--scales", default="1,3", help="embedding scales tried in the slot model")
    ap.add_argument("--cases", type=Path, default=None, help="cache of the train ranking cases (JSON)")
    args = ap.parse_args(argv)
    try:
        scales = [float(s) for s in args.scales.split(",")]
    except ValueError:
        print(f"error: --scales must be numbers separated by commas, not {args.scales!r}", file=sys.stderr)
        return 2
    try:
        encoder = SentenceEncoder.load()
        if args.part in ("slots", "all"):
            print("\n".join(measure_slots(encoder, scales)))
        if args.part in ("ranker", "all"):
            print("\n".join(measure_ranker(encoder, args.cases)))
    except Nl2Hltl2PlanError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
