"""Train the slot model on the honest split and measure it on validation.

    nl2hltl2plan train language [-o PATH] [--seed S]

Trains on ALFRED train minus the excluded trials, reports slot accuracy on valid_seen / valid_unseen
(each slot's top type among the trial scene's types), and writes the artifact.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import TYPE_CHECKING

from nl2hltl2plan.domain.task_kinds import SLOTS
from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.data import Example, data_fingerprint, faithful, load_examples
from nl2hltl2plan.language.learned.faithful import FaithfulExample, faithful_examples, training_example
from nl2hltl2plan.language.learned.inference import parse_instruction
from nl2hltl2plan.language.learned.ranker import RankCase, TypeRanker
from nl2hltl2plan.language.learned.slot_model import SlotModel, SlotPrediction

if TYPE_CHECKING:
    from nl2hltl2plan.language.learned.encoder_features import EncoderFeatures

ENCODER_SCALE = 1.0  # the embedding's weight against the TF-IDF columns (scripts/encoder_measure.py)


def text_faithful_items(split: str) -> list[FaithfulExample]:
    """The split's annotations whose text-faithful label is clear (`faithful.text_task`)."""
    examples = load_examples()[split]
    plans = {e.floor_plan for e in examples}
    return faithful_examples(examples, {p: scene_types(p) for p in plans})


def text_faithful_train() -> list[Example]:
    """The train annotations labelled as the text says (`faithful.training_example`)."""
    return [training_example(it) for it in text_faithful_items("train")]


def train(seed: int = 0, labels: str = "text", encoder: EncoderFeatures | None = None) -> SlotModel:
    """Fit on the train annotations: text-faithful labels (default) or ALFRED's, on those whose text
    states their task (`data.faithful`, the first version). With `encoder`, the slot model also reads
    the pretrained encoder's sentence embeddings (`encoder_features.py`; measured, not the default)."""
    if labels == "text":
        examples = text_faithful_train()
        dense = None
        if encoder is not None:
            encoder.embed([e.text for e in examples])  # one batched pass instead of one text at a time
            dense = encoder.slot_features
        model = SlotModel.fit(examples, seed=seed, dense=dense)
        model.meta["data_sha"] = data_fingerprint(examples)
        model.meta.update(encoder.describe() if encoder else {})
    else:
        model = SlotModel.fit([e for e in load_examples()["train"] if faithful(e)], seed=seed)
    model.ranker = TypeRanker.fit(ranking_cases(model, load_examples()["train"]), seed=seed)
    return model


def encoder_features() -> EncoderFeatures:
    """The pretrained encoder's features as `train language --encoder` uses them (the `encoder` extra)."""
    from nl2hltl2plan.language.learned.encoder import SentenceEncoder
    from nl2hltl2plan.language.learned.encoder_features import EncoderFeatures

    return EncoderFeatures(SentenceEncoder.load(), scale=ENCODER_SCALE)


def ranking_cases(model: SlotModel, examples: list[Example]) -> list[RankCase]:
    """Each annotation's words that the parse leaves with several scene types ("the table") and whose
    ALFRED type is one of them, with the slot model's probabilities (`model` without a ranker)."""
    cases = []
    for e in examples:
        r = parse_instruction(e.text, scene_types(e.floor_plan), e.floor_plan, strict=False, model=model)
        for a in r.ambiguities:
            task = next(t for t in r.tasks if t.id == a.task)
            label = e.slot(a.role)
            if len(getattr(task, a.role) or []) > 1 and label in a.candidates:
                cases.append(RankCase(task.text, tuple(zip(a.candidates, a.confidence, strict=True)), label))
    return cases


def _slot_ok(e: Example, p: SlotPrediction) -> dict[str, bool]:
    kind = p.top_kind
    ok = {"kind": kind == e.kind, "sliced": (p.sliced >= 0.5) == e.sliced}
    for s in SLOTS:
        want = e.slot(s)
        got = p.slots[s][0][0] if p.slots[s] else ""
        ok[s] = got == want if want else True
    ok["all"] = all(ok.values())
    return ok


def slot_accuracy(model: SlotModel, examples: list[Example]) -> dict[str, float]:
    """Share of examples whose kind / each slot / every slot is right (slots restricted to the scene)."""
    if not examples:
        return {}
    by_plan: dict[str, list[Example]] = {}
    for e in examples:
        by_plan.setdefault(e.floor_plan, []).append(e)
    totals: dict[str, int] = {}
    for plan, es in by_plan.items():
        preds = model.predict([e.text for e in es], scene_types(plan))
        for e, p in zip(es, preds, strict=True):
            for k, v in _slot_ok(e, p).items():
                totals[k] = totals.get(k, 0) + int(v)
    return {k: v / len(examples) for k, v in totals.items()}


def text_slot_accuracy(model: SlotModel, items: list[FaithfulExample]) -> dict[str, float]:
    """Share right against text-faithful labels (a slot is right when its top type is in the label's
    type list; "all" = kind, sliced and every slot right)."""
    totals: dict[str, int] = {}
    for it in items:
        p = model.predict([it.text], scene_types(it.example.floor_plan))[0]
        ok = {"kind": p.top_kind == it.task.kind, "sliced": (p.sliced >= 0.5) == it.task.sliced}
        for s in SLOTS:
            want = getattr(it.task, s) or []
            ok[s] = not want or bool(p.slots[s]) and p.slots[s][0][0] in want
        ok["all"] = all(ok.values())
        for k, v in ok.items():
            totals[k] = totals.get(k, 0) + int(v)
    return {k: v / len(items) for k, v in totals.items()} if items else {}


def train_and_report(out: Path, seed: int = 0, encoder: bool = False) -> str:
    t0 = time.monotonic()
    model = train(seed, encoder=encoder_features() if encoder else None)
    secs = time.monotonic() - t0
    model.save(out)
    data = load_examples()
    lines = [f"trained on {model.meta['n_train']} annotations in {secs:.0f} s (seed {seed}) -> {out}"]
    for split in ("valid_seen", "valid_unseen"):
        for name, ex in (("all", data[split]), ("faithful", [e for e in data[split] if faithful(e)])):
            acc = slot_accuracy(model, ex)
            shares = ", ".join(f"{k} {100 * v:.1f}%" for k, v in acc.items())
            lines.append(f"{split} {name} ({len(ex)}): {shares}")
        items = list(
            faithful_examples(data[split], {e.floor_plan: scene_types(e.floor_plan) for e in data[split]})
        )
        acc = text_slot_accuracy(model, items)
        shares = ", ".join(f"{k} {100 * v:.1f}%" for k, v in acc.items())
        lines.append(f"{split} text-faithful ({len(items)}): {shares}")
    return "\n".join(lines)
