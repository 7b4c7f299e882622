"""The committed learned models are what `nl2hltl2plan train language` builds from today's code and data.

Retraining takes minutes, so the check compares fingerprints of the training data instead: each model
stores a digest of the instructions and labels it was fitted on. A lexicon, labelling or composition
change that alters the training data fails here, naming the command that rebuilds the models (a stale
model once read "X, then Y" as one task span while the rebuilt one did not).
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from nl2hltl2plan.language.learned import request_units, structure_train, train
from nl2hltl2plan.language.learned.data import data_fingerprint
from nl2hltl2plan.language.learned.slot_model import SlotModel, packaged_path
from nl2hltl2plan.language.learned.structure import ARTIFACT, StructureModel

REBUILD = (
    "stale: rebuild both models with "
    "`PYTHONHASHSEED=0 nl2hltl2plan train language -o {slot} --structure-out {structure}`"
)


@pytest.fixture(scope="module", autouse=True)
def train_items_read_once() -> Iterator[None]:
    """Both models' training data start from the same labelled train annotations (a second each): read
    them once for this module. The items are frozen dataclasses and every call gets a list of its own."""
    read = train.text_faithful_items
    items = read("train")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(
            train, "text_faithful_items", lambda split: list(items) if split == "train" else read(split)
        )
        yield


@pytest.fixture(scope="module")
def hint() -> str:
    return REBUILD.format(slot=packaged_path("slot_model.npz"), structure=packaged_path(ARTIFACT))


# composes the whole training set (7 s or more): `sweep`. The slot model's check below fingerprints the same
# labelled train annotations (a changed lexicon or labelling fails there too); a change to the compositions
# alone shows in CI's `-m sweep` run
@pytest.mark.sweep
def test_structure_model_was_trained_on_todays_data(hint: str) -> None:
    model = StructureModel.load(packaged_path(ARTIFACT))
    today = data_fingerprint(structure_train.training_data())
    assert model.data_sha == today, hint


# composes 4,000 framed messages (about 10 s): `sweep`
@pytest.mark.sweep
def test_request_model_was_trained_on_todays_data() -> None:
    path = packaged_path(request_units.ARTIFACT)
    model = request_units.RequestModel.load(path)
    rebuild = f"PYTHONHASHSEED=0 nl2hltl2plan train language --only request --request-out {path}"
    today = data_fingerprint(request_units.training_data())
    assert model.data_sha == today, f"stale: rebuild with `{rebuild}`"


def test_slot_model_was_trained_on_todays_data(hint: str) -> None:
    model = SlotModel.load(packaged_path("slot_model.npz"))
    assert model.meta.get("data_sha") == data_fingerprint(train.text_faithful_train()), hint


def test_fingerprint_sees_a_changed_label() -> None:
    data = structure_train.training_data(n=20)
    changed = list(data)
    changed[3] = type(data[3])(**{**vars(data[3]), "relations": list(reversed(data[3].relations))})
    assert changed[3].relations != data[3].relations
    assert data_fingerprint(changed) != data_fingerprint(data)
