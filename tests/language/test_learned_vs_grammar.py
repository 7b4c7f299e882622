"""The two measuring scripts of issue 28's arbitration study: what they put a changed reading down to
(`scripts/learned_vs_grammar.py`) and how they compare two outcome files row by row
(`scripts/compare_outcomes.py`). Their pure parts only: no model is loaded."""

from __future__ import annotations

import sys
from pathlib import Path

from nl2hltl2plan.language.task_specs import BaseTaskSpec

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from compare_outcomes import cause, transitions  # noqa: E402
from learned_vs_grammar import changed_fields, stage  # noqa: E402


def _task(id_: str, receptacle: str, sliced: bool = False) -> BaseTaskSpec:
    return BaseTaskSpec(id=id_, kind="place", object=["Mug"], receptacle=[receptacle], sliced=sliced)


def test_changed_fields_names_the_task_and_slot_or_the_task_count() -> None:
    a = [_task("A", "SinkBasin"), _task("B", "Cabinet")]
    assert changed_fields(a, [_task("A", "SinkBasin"), _task("B", "Drawer", sliced=True)]) == [
        "B.sliced",
        "B.receptacle",
    ]
    assert changed_fields(a, a[:1]) == ["tasks 2 -> 1"]
    assert changed_fields(a, list(a)) == []


def test_a_change_is_put_down_to_the_arbitration_only_where_it_did_not_keep_the_grammar() -> None:
    assert stage("model", 0.934, ["tasks 2 -> 3"]) == "arbitration: model (0.93)"
    assert stage("neither", 0.1, []) == "arbitration: neither (0.10)"
    assert stage("grammar", 0.99, ["A.receptacle"]) == "slot model or rescue: A.receptacle"
    assert stage("grammar", None, []) == "order"


def test_outcomes_compare_row_by_row_and_group_the_new_refusals_by_cause() -> None:
    def row(cls: str, why: str = "") -> dict[str, object]:
        return {"class": cls, "why": why, "instruction": "x"}

    before = {("s", 0): row("ok"), ("s", 1): row("ok"), ("s", 2): row("slot: kind/count/sliced/type")}
    after = {
        ("s", 0): row("error", "'spoons': FloorPlan23 has 6 of them and the task would take 2"),
        ("s", 1): row("error", "'forks': FloorPlan5 has 8 of them and the task would take 2"),
        ("s", 2): row("error", "refused"),
        ("t", 0): row("ok"),  # a row only one file holds is not compared
    }
    moved, lost = transitions(before, after)
    assert moved == {("ok", "error"): 2, ("slot: kind/count/sliced/type", "error"): 1}
    assert lost == {"_: _ has _ of them and the task would take _": 2}
    assert cause("'towel' is both || the grammar's why") == "_ is both"
