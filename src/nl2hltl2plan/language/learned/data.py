"""Training and validation data from ALFRED's human annotations, honestly split.

One `Example` per (trial, annotation): the crowd-written `task_desc` and the base task its trial's
`task_type` / `pddl_params` define. Train: ALFRED `train` trials minus every trial listed in
`benchmark/training_exclusions.txt` (the families test50 was composed from); validation: `valid_seen`
and `valid_unseen`. Text-faithful labels and the synthetic multi-task validation: `faithful.py`.
"""

from __future__ import annotations

import hashlib
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import lru_cache

from nl2hltl2plan.config import data_path
from nl2hltl2plan.errors import DataError
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.worlds.floor_plans import TrialRecord, alfred_data, excluded_trials

KIND_OF_TASK_TYPE = {
    "pick_and_place_simple": "place",
    "pick_two_obj_and_place": "place_two",
    "pick_and_place_with_movable_recep": "place_in_container",
    "look_at_obj_in_light": "examine_in_light",
    "pick_clean_then_place_in_recep": "clean_place",
    "pick_heat_then_place_in_recep": "heat_place",
    "pick_cool_then_place_in_recep": "cool_place",
}
SPLITS = ("train", "valid_seen", "valid_unseen")


@dataclass(frozen=True)
class Example:
    text: str
    trial: str
    split: str
    floor_plan: str
    kind: str
    object: str
    container: str  # "" when the kind has none
    receptacle: str
    light: str
    sliced: bool

    def slot(self, name: str) -> str:
        return str(getattr(self, name))

    def as_task(self, task_id: str = "A") -> BaseTaskSpec:
        return BaseTaskSpec(
            id=task_id,
            text=self.text,
            kind=self.kind,  # type: ignore[arg-type]
            object=[self.object],
            count=2 if self.kind == "place_two" else 1,
            sliced=self.sliced,
            container=[self.container] if self.container else None,
            receptacle=[self.receptacle] if self.receptacle else None,
            light=[self.light] if self.light else None,
        )


# What a text must say for a treatment kind to be read from it. ALFRED annotators often leave the
# treatment out ("put the apple on the table" for a cool task); the instruction is the authority
# (ANNOTATION_GUIDE.md), so the kind head learns only from texts that state it.
_TREATMENT = {
    "heat_place": (re.compile(r"heat|warm|cook|hot\b|micro"), re.compile(r"microwave")),
    "cool_place": (re.compile(r"cool|chill|cold|froz|freez"), re.compile(r"fridge|refrigerat|freezer")),
    "clean_place": (re.compile(r"clean|wash|rins|scrub|wet|water"), re.compile(r"sink|faucet|tap\b")),
}
_APPLIANCE = {"heat_place": "Microwave", "cool_place": "Fridge", "clean_place": "SinkBasin"}


def states_kind(e: Example) -> bool:
    """Whether the text states its treatment (words, or the appliance when it is not the destination)."""
    if e.kind not in _TREATMENT:
        return True
    text = e.text.lower()
    words, appliance = _TREATMENT[e.kind]
    return bool(words.search(text)) or (e.receptacle != _APPLIANCE[e.kind] and bool(appliance.search(text)))


def states_slots(e: Example) -> bool:
    """Whether every labelled type is named in the text (a lexicon phrase that can mean it): ALFRED's
    labels are the trial's parameters, and annotators often name another object or none."""
    from nl2hltl2plan.language.grounding import find_mentions

    named = {t for m in find_mentions(e.text) for t in m.entry.types}
    return all(t in named for t in (e.object, e.container, e.receptacle, e.light) if t)


def faithful(e: Example) -> bool:
    """The text states the kind and names every slot's type: what the benchmark's annotation asks."""
    return states_kind(e) and states_slots(e)


@dataclass
class Composition:
    """A synthetic multi-task instruction with its ground truth (validation only)."""

    instruction: str
    scene: str
    tasks: list[BaseTaskSpec]
    before: list[tuple[str, str]]
    template: str = ""
    trials: list[str] = field(default_factory=list)


def data_fingerprint(items: Sequence[object]) -> str:
    """A digest of training items (their reprs: dataclasses of strings, lists and numbers, the same under
    every hash seed), stored in a model so that `tests/language/test_models_current.py` can tell, without
    retraining, whether today's training data is still what the committed model was fitted on."""
    return hashlib.sha256("\n".join(map(repr, items)).encode()).hexdigest()


def _example(row: TrialRecord, text: str) -> Example:
    p = row.pddl_params or {}
    kind = KIND_OF_TASK_TYPE[row.task_type or ""]
    return Example(
        text=" ".join(text.split()),
        trial=row.trial,
        split=row.split,
        floor_plan=row.floor_plan,
        kind=kind,
        object=p["object_target"],
        container=p["mrecep_target"] if kind == "place_in_container" else "",
        receptacle=p["parent_target"] if kind != "examine_in_light" else "",
        light=p["toggle_target"] if kind == "examine_in_light" else "",
        sliced=bool(p["object_sliced"]),
    )


@lru_cache(maxsize=1)
def load_examples() -> dict[str, list[Example]]:
    """Examples by split (train / valid_seen / valid_unseen); excluded trials never appear."""
    banned = excluded_trials()
    out: dict[str, list[Example]] = {s: [] for s in SPLITS}
    path = data_path("alfred", "trials.jsonl.gz")
    rows = alfred_data().example_fields  # the world loader's pass over the file keeps these fields
    try:
        for row in rows:
            if row.split not in out or not row.task_type or row.trial in banned:
                continue
            for ann in row.annotations:
                if ann.get("task_desc", "").strip():
                    out[row.split].append(_example(row, ann["task_desc"]))
    except (KeyError, ValueError, TypeError, AttributeError, IndexError) as exc:
        raise DataError(f"ALFRED trials file {path} is damaged: a record lacks or mistypes {exc}") from None
    if not out["train"]:
        raise DataError("no ALFRED training examples found in alfred/trials.jsonl.gz")
    return out
