"""Train the structure model (`structure.py`) on synthetic compositions of ALFRED train annotations.

The clauses are ALFRED `train` annotations minus the excluded trials (`data.py`), labelled
text-faithfully (`faithful.py`); the connectives are `compose.TRAIN_STYLE`'s (the voices and numbered
lists of `compose_voices.VOICE_STYLE` are measured and off: `N_VOICES`; the held-out style and the
validation compositions' templates are never trained on). CRFsuite (L-BFGS, L1 + L2)
fits the tags; the weights are exported to numpy (`StructureModel`). The relation head
(`relation_head.py`) is fitted on the spans that point back at an earlier one (REF / RPRE), with the
gold spans.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from nl2hltl2plan.language.learned.compose import TRAIN_STYLE, Synth, synthesise
from nl2hltl2plan.language.learned.data import data_fingerprint
from nl2hltl2plan.language.learned.relation_head import HeadCase, RelationHead
from nl2hltl2plan.language.learned.structure import StructureModel, features, tags_of, token_ranges, tokenize

N_TRAIN = 10000
# compositions of the second family (`compose_voices.VOICE_STYLE`) per N_TRAIN, on top: measured at 3,000
# and 1,500 and not adopted (held-out connectives' spans +5 points, but five readings of the committed
# style sets regress; results/language/h193.md), so the shipped model is trained without them
N_VOICES = 0
# compositions of the first family wrapped in a voice's frame (`compose_frames`, its `train` pools) per
# N_TRAIN, on top: measured at 2,500 and not adopted (held-out frames' spans 87.8 -> 90.2 %, but over the
# committed sets 2 lines convert, 4 stop converting and 1 more is read wrong; results/language/h272.md)
N_FRAMES = 0


def training_data(
    n: int = N_TRAIN, seed: int = 0, voices: int = N_VOICES, frames: int = N_FRAMES
) -> list[Synth]:
    """`n` compositions of the first family, `n` * `voices` / N_TRAIN of the second (`compose_voices`)
    and `n` * `frames` / N_TRAIN of the third (`compose_frames`: the first family's connectives in a
    frame); none of the second and third by default. An under-specified annotation
    (`faithful.FaithfulExample.unsaid`) stays in: the CRF learns where the task spans are and how they
    are ordered, not the slot its text leaves unsaid (leaving them out moved the model's reading of three
    committed test sentences)."""
    from nl2hltl2plan.language.learned.compose_frames import frame_all
    from nl2hltl2plan.language.learned.compose_voices import VOICE_STYLE
    from nl2hltl2plan.language.learned.train import text_faithful_items

    items = text_faithful_items("train")
    out = synthesise(items, n, TRAIN_STYLE, seed, said_only=False)
    if voices:
        out += synthesise(items, n * voices // N_TRAIN, VOICE_STYLE, seed + 1, said_only=False)
    if frames:
        unframed = synthesise(items, n * frames // N_TRAIN, TRAIN_STYLE, seed + 2, said_only=False)
        out += frame_all(unframed, "train", seed + 2)
    return out


def training_sequences(data: list[Synth]) -> list[tuple[list[list[str]], list[str]]]:
    """The CRF's (features, tags) per instruction."""
    out = []
    for s in data:
        words, tags = tags_of(s.text, s.spans, s.relations)
        out.append((features(words), tags))
    return out


def head_cases(data: list[Synth]) -> list[HeadCase]:
    """The relation head's cases: each span that points at an earlier one, with the gold spans."""
    out = []
    for s in data:
        words = [w for w, _, _ in tokenize(s.text)]
        ranges = token_ranges(s.text, s.spans)
        out += [(words, ranges, i, j) for i, j in enumerate(s.targets) if j is not None]
    return out


def fit(
    seqs: list[tuple[list[list[str]], list[str]]], cases: list[HeadCase], iterations: int = 120
) -> StructureModel:
    import pycrfsuite

    trainer = pycrfsuite.Trainer(verbose=False)
    for feats, tags in seqs:
        trainer.append(feats, tags)
    # a strong L2 term (0.3, was 0.01) spreads the weight over the features that carry over to unseen
    # connectives (clause kinds, word shapes) instead of the training phrasings' words: held-out spans
    # 69 -> 74.5 % right, and fewer wrong readings on every development set (results/language/unseen_h53.md)
    trainer.set_params({"c1": 0.05, "c2": 0.3, "max_iterations": iterations})
    with tempfile.TemporaryDirectory() as tmp:
        path = str(Path(tmp) / "crf.bin")
        trainer.train(path)
        tagger = pycrfsuite.Tagger()
        tagger.open(path)
        info = tagger.info()
        tagger.close()
    tags = sorted(info.labels)
    col = {t: i for i, t in enumerate(tags)}
    names = sorted({a for (a, _), w in info.state_features.items() if w != 0.0})
    row = {f: i for i, f in enumerate(names)}
    weights = np.zeros((len(names), len(tags)), dtype=np.float64)
    for (attr, label), w in info.state_features.items():
        if w != 0.0:
            weights[row[attr], col[label]] = w
    trans = np.zeros((len(tags), len(tags)), dtype=np.float64)
    for (a, b), w in info.transitions.items():
        trans[col[a], col[b]] = w
    return StructureModel(tags, names, weights, trans, RelationHead.fit(cases))


def span_accuracy(model: StructureModel, n: int = 400, seed: int = 7) -> dict[str, float]:
    """On compositions of valid_unseen annotations: the share whose spans are all right, and whose spans'
    number and `before` pairs are right, per connective style (training's, held-out; training's in a
    frame of the held-out pools, `compose_frames`)."""
    from nl2hltl2plan.language.learned.compose import HELDOUT_STYLE
    from nl2hltl2plan.language.learned.compose_frames import frame_all
    from nl2hltl2plan.language.learned.span_order import before_pairs
    from nl2hltl2plan.language.learned.train import text_faithful_items

    items = text_faithful_items("valid_unseen")
    out = {}
    styles = (("training style", TRAIN_STYLE), ("held-out style", HELDOUT_STYLE), ("held-out frames", None))
    for name, style in styles:
        spans_ok = order_ok = 0
        synth = synthesise(items, n, style or TRAIN_STYLE, seed)
        synth = frame_all(synth, "held", seed) if style is None else synth
        for s in synth:
            r = model.read(s.text)
            spans_ok += [(x.start, x.end) for x in r.spans] == s.spans
            rels = [x.relation for x in r.spans]
            order_ok += len(rels) == len(s.relations) and before_pairs(rels, [x.target for x in r.spans]) == (
                before_pairs(s.relations, s.targets)
            )
        out[f"{name}: spans"] = spans_ok / len(synth)
        out[f"{name}: spans+order"] = order_ok / len(synth)
    return out


def train_and_report(out: Path, seed: int = 0) -> str:
    import time

    t0 = time.monotonic()
    data = training_data(N_TRAIN, seed)
    model = fit(training_sequences(data), head_cases(data))
    model.data_sha = data_fingerprint(data)
    secs = time.monotonic() - t0
    model.save(out)
    shares = ", ".join(f"{k} {100 * v:.1f}%" for k, v in span_accuracy(model).items())
    return (
        f"structure model: {len(data)} synthetic instructions, "
        f"{len(model.feature_names)} features, "
        f"trained in {secs:.0f} s -> {out}\nvalid_unseen compositions: {shares}"
    )
