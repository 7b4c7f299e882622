"""Benchmark instances (need ../shared/data; skipped without it)."""

from __future__ import annotations

import json

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.config import data_dir
from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.checker import check

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def run_instance(instance_id: str, robots: int, **kw):
    from nl2hltl2plan.suites.alfred.ground_truth import gt_instance
    from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world
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
