"""Benchmark instances (need ../shared/data; skipped without it) and random demo instructions."""

from __future__ import annotations

import json
import random

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.config import data_dir
from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.demo import demo_world
from nl2hltl2plan.worlds.tasks import BaseTask, GTInstance

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def run_instance(instance_id: str, robots: int, **kw):
    from nl2hltl2plan.worlds.alfred import benchmark_issues, build_benchmark_world
    from nl2hltl2plan.worlds.benchmark import gt_instance
    from nl2hltl2plan.worlds.starts import start_cells

    gt = gt_instance(instance_id)
    world = build_benchmark_world(gt)
    r = plan(world, oracle_spec(gt, world).spec, start_cells(world, robots, gt=gt), **kw)
    return gt, r, benchmark_issues(world, gt)


@needs_data
@pytest.mark.parametrize("instance, robots", [
    ("FloorPlan21.tasks_4.compose_4.fintune_2", 1),  # a knife to clean and a knife to slice with
    ("FloorPlan323.tasks_3.compose_1.fintune_0", 2),  # examine: hold the laptop until the lamp is on
    ("FloorPlan8.tasks_4.compose_0.fintune_2", 4),  # two heat tasks share the microwave
    ("FloorPlan7.tasks_4.compose_2.fintune_1", 2),  # Cup-or-Mug leaf, slicing, fridge and microwave
])
def test_hard_benchmark_instances_pass_the_checker(instance, robots):
    # a small A* budget keeps the suite quick: what is checked here is the plan, not its quality
    gt, r, issues = run_instance(instance, robots, fast_expansions=300)
    assert not issues and r.solved
    verdict = check(r.execution, gt)
    assert verdict.success, verdict.reasons


@needs_data
def test_infeasible_benchmark_instance_says_why():
    gt, r, issues = run_instance("FloorPlan17.tasks_2.compose_0.fintune_1", 2)
    assert issues and r.status == "infeasible"
    assert "no Statue in FloorPlan17" in r.reason


@needs_data
def test_bench_command(tmp_path, capsys):
    out = tmp_path / "bench"
    code = main(["bench", "alfred", "--oracle", "--robots", "1,2", "--n-base", "2", "--limit", "3",
                 "--workers", "2", "--out", str(out), "--quiet"])
    assert code == 0
    summary = json.loads((out / "summary.json").read_text())
    for key in ("scenarios", "feasible", "solved", "success", "plan_time_s", "rows"):
        assert key in summary
    assert summary["scenarios"] == 6 and summary["success"] == summary["feasible"]
    assert set(summary["plan_time_s"]) >= {"median", "p95", "max"}
    row = summary["rows"][0]
    keys = {"n_base", "robots", "success_rate", "travel_m_mean", "travel_m_std", "steps_mean", "steps_std"}
    assert keys <= set(row)
    lines = (out / "scenarios.jsonl").read_text().splitlines()
    assert len(lines) == 6 and all(json.loads(x)["key"] for x in lines)
    printed = capsys.readouterr().out
    assert "tasks-robots" in printed and "2-1" in printed and "paper PL %" in printed


def test_bench_command_needs_a_spec_source(tmp_path, capsys):
    assert main(["bench", "alfred", "--out", str(tmp_path)]) == 2
    assert "--oracle" in capsys.readouterr().err


KINDS = [
    dict(kind="clean_place", object=["Mug"], receptacle=["DishwasherUpperRack"]),
    dict(kind="heat_place", object=["Apple"], receptacle=["DiningTable"]),
    dict(kind="cool_place", object=["Tomato"], receptacle=["CounterTop"]),
    dict(kind="examine_in_light", object=["Book"], light=["FloorLamp"]),
    dict(kind="place_in_container", object=["Fork"], container=["Bowl"], receptacle=["Cabinet"]),
    dict(kind="place_two", object=["Plate"], count=2, receptacle=["DishwasherLowerRack"]),
    dict(kind="place", object=["Bread"], sliced=True, receptacle=["DiningTable"]),
    dict(kind="place", object=["Cup"], receptacle=["Saucer"]),
    dict(kind="place", object=["KeyChain"], receptacle=["Bowl"]),
]


def test_random_demo_instructions_always_give_checked_plans():
    rng = random.Random(7)
    world = demo_world()
    starts = [(0, 0), (9, 13), (0, 13), (9, 0)]
    for trial in range(12):
        picked = rng.sample(KINDS, 3)
        tasks = [BaseTask(id=chr(65 + i), **t) for i, t in enumerate(picked)]
        before = [(a.id, b.id) for a, b in zip(tasks, tasks[1:], strict=False) if rng.random() < 0.5]
        gt = GTInstance(id=f"random{trial}", scene="demo", tasks=tasks, before=before)
        spec = oracle_spec(gt, world).spec
        robots = rng.choice([1, 2, 4])
        objective = rng.choice(["min", "minmax"])  # a small search budget: this checks plans, not quality
        r = plan(world, spec, starts[:robots], objective=objective, timeout_s=60, fast_expansions=300)
        assert r.solved, (trial, r.reason)
        verdict = check(r.execution, gt)
        assert verdict.success, (trial, [t.kind for t in tasks], before, verdict.reasons)
