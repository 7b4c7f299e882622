"""SMART-LLM's tasks, oracle specs and metrics (one real floor plan, kept small for speed)."""

import argparse
import json

import pytest

from nl2hltl2plan.cli.bench_smartllm import register
from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.suites.smartllm.smartllm_bench import (
    llm_maker,
    oracle_maker,
    robot_utilisation,
    run_task,
    stages,
    summarize,
)
from nl2hltl2plan.suites.smartllm.smartllm_tasks import load_tasks, parse_task

pytestmark = pytest.mark.data  # SMART-LLM's tasks and robot profiles


def test_tasks_repairs_and_missing_gt():
    tasks = {t.id: t for t in load_tasks()}
    assert len(tasks) == 36 and sum(t.has_gt for t in tasks.values()) == 35
    assert not tasks["FloorPlan209#1"].has_gt
    cabinet = tasks["FloorPlan414#4"]
    assert [c.describe() for c in cabinet.conditions] == ["LightSwitch OFF"]
    assert any("dropped" in n for n in cabinet.notes)
    trash = tasks["FloorPlan414#2"]
    assert [c.describe() for c in trash.conditions] == ["GarbageCan contains Cloth"]


def test_robot_utilisation_formula():
    assert robot_utilisation(1, 0, 2) == 1.0 and robot_utilisation(3, 0, 2) == 0.0
    assert robot_utilisation(2, 0, 2) == 0.5 and robot_utilisation(2, 1, 1) == 1.0
    assert robot_utilisation(1, 1, 1) == 0.0 and robot_utilisation(1, None, None) is None
    ev = [
        PlanEvent(t=5, robot=0, atom="pickup(A)", task="a", travel_m=1.0),
        PlanEvent(t=6, robot=0, atom="put(A,B)", task="a"),
        PlanEvent(t=3, robot=1, atom="pickup(B)", task="b", travel_m=0.5),
        PlanEvent(t=9, robot=2, atom="pickup(C)", task="c", travel_m=0.25),
    ]
    assert stages(ev) == 2  # a (t 1..6) and b (1..3) overlap; c sets off at 8, after both ended
    assert stages(ev, [("b", "a")]) == 3  # ordered by the spec: b, then a, then c
    ev[2] = ev[2].model_copy(update={"robot": 2, "t": 2})
    ev[3] = ev[3].model_copy(update={"t": 4})  # b (t 0..2) then c (3..4) by robot 2, while a (1..6) runs
    assert stages(ev) == 2


def test_oracle_task_respects_the_team_and_scores():
    task = next(t for t in load_tasks() if t.id == "FloorPlan15#3")  # slice, trash, light off: robots 8, 6, 5
    row = run_task(task, oracle_maker, timeout_s=20)
    assert row["status"] == "solved" and row["TC"] == 1.0 and row["GCR"] == 1.0 and row["Exe"] == 1.0
    bad = parse_task(
        1,
        {
            "floor_plan": "FloorPlan15",
            "task": "Slice the lettuce",
            "robot list": [24],
            "object_states": [{"name": "Lettuce", "contains": [], "state": "SLICED"}],
            "trans": 0,
            "max_trans": 0,
        },
    )
    row = run_task(bad, oracle_maker)
    assert row["status"] == "infeasible team" and "no robot in the team can" in row["reason"]
    assert row["TC"] == 0.0 and row["Exe"] == 0.0
    summary = summarize(
        [
            row,
            {
                "id": "x",
                "task": "t",
                "has_gt": False,
                "status": "no ground truth",
                "floor_plan": "FloorPlan209",
            },
        ]
    )
    assert summary["overall"]["tasks"] == 1 and summary["not_scored"][0]["id"] == "x"
    json.dumps(summary)


def test_cli_registers_under_bench():
    parser = argparse.ArgumentParser()
    register(parser.add_subparsers(dest="suite"))
    args = parser.parse_args(["smartllm", "--oracle", "--out", "d"])
    assert args.oracle and args.objective == "minmax" and callable(args.func)


def test_mass_capacity_and_language_stage():
    weak = parse_task(
        4,
        {
            "floor_plan": "FloorPlan15",
            "task": "Put the potato in the fridge",
            "robot list": [10],
            "object_states": [{"name": "Fridge", "contains": ["Potato"], "state": None}],
            "trans": 0,
            "max_trans": 0,
        },
    )
    row = run_task(weak, oracle_maker, masses={"Potato": 0.18})
    assert row["status"] == "infeasible team" and "carry a Potato (0.18 kg" in row["reason"]
    assert run_task(weak, oracle_maker)["TC"] == 1.0  # masses unknown: not limited
    mug = next(t for t in load_tasks() if t.id == "FloorPlan21#1")  # "Put mug in coffee machine"
    row = run_task(mug, llm_maker("offline"))
    assert row["status"] == "solved" and row["TC"] == 1.0


def test_smartllm_script_scoring_counts_as_end_thread_does():
    """SMART-LLM's own script: one task per entry, +1 per match (GCR can pass 1, then TC = 0), no BROKEN
    check, raw names, RU unclipped; tasks without a stage annotation are left out of SR."""
    from nl2hltl2plan.suites.smartllm.smartllm_script import script_ru

    tasks = {t.id: t for t in load_tasks()}
    plate = run_task(tasks["FloorPlan15#5"], oracle_maker, timeout_s=20)  # a plate holding egg and tomato
    assert plate["TC"] == 1.0 and plate["GCR"] == 1.0
    assert plate["script"]["GCR"] == 2.0 and plate["script"]["TC"] == 0.0  # one entry, two contents
    trash = run_task(tasks["FloorPlan414#2"], oracle_maker, timeout_s=20)  # raw name "trash"
    assert trash["GCR"] == 1.0 and trash["script"]["GCR"] == 0.0
    assert script_ru(4, 0, 2) == -0.5 and script_ru(1, 1, 3) == 1.5  # unclipped
    assert script_ru(2, 1, 1) == 1.0 and script_ru(1, 1, 1) == 0.0 and script_ru(1, None, 3) is None
    no_annotation = run_task(tasks["FloorPlan21#6"], oracle_maker, timeout_s=20)
    assert no_annotation["RU"] is None and no_annotation["SR"] is None
    assert summarize([no_annotation, plate])["left_out_of_SR"] == ["FloorPlan21#6"]
