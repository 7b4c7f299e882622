"""The slot model keeps each text's head probabilities: answers equal a model that computes them afresh,
a caller that edits what it got edits its own copy, and the memo stays bounded."""

from __future__ import annotations

import numpy as np
import pytest

from nl2hltl2plan.language.learned import slot_model
from nl2hltl2plan.language.learned.inference import load_model
from nl2hltl2plan.language.learned.slot_model import SlotModel

TEXTS = ["put a washed apple in the fridge", "take the mug to the coffee machine", "slice the bread"]
KITCHEN = {"Apple", "Fridge", "Mug", "CoffeeMachine", "Bread", "CounterTop", "Knife"}


def _fresh(model: SlotModel) -> SlotModel:
    return SlotModel(model.vectorizers, model.heads, model.meta, dense=model.dense)


def test_kept_answers_equal_fresh_ones_and_are_the_callers_own() -> None:
    model = _fresh(load_model())
    first = model.predict(TEXTS, KITCHEN)
    first[0].kind.clear()
    first[0].slots["object"].append(("Nothing", 1.0))
    again = model.predict(TEXTS, KITCHEN)
    assert again == _fresh(model).predict(TEXTS, KITCHEN)
    assert again[0].kind and ("Nothing", 1.0) not in again[0].slots["object"]
    # the scene filter is applied to each call's own copy: no scene gives every type back
    unfiltered = model.predict(TEXTS[:1])[0]
    assert len(unfiltered.slots["object"]) > len(again[0].slots["object"])
    for head, probs in model.probabilities(TEXTS[0]).items():
        idx, val = model.features(TEXTS[0])
        assert np.array_equal(probs, model.heads[head].proba(idx, val))


def test_the_memo_keeps_at_most_its_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(slot_model, "_KEPT", 2)
    model = _fresh(load_model())
    for text in TEXTS:
        model.predict([text])
    assert list(model._probs) == TEXTS[1:]  # the oldest went first
