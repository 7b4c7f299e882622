"""The end-to-end benchmark (issue 6): language records, three-way success, failure stages, report."""

from __future__ import annotations

import json

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.config import data_dir
from nl2hltl2plan.pipeline import PipelineOptions
from nl2hltl2plan.suites.alfred.alfred_language import STAGES, failure_stage, language_record
from nl2hltl2plan.suites.alfred.alfred_report import failure_breakdown, pipeline_summary, table1_markdown
from nl2hltl2plan.suites.rows import LanguageRecord, ScenarioRow

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def test_failure_stage_order():
    def rec(stage=None):
        return LanguageRecord(key="x", instance="x", n_base=1, backend="offline", stage=stage)

    def row(**kw):
        return ScenarioRow.model_validate(kw)

    assert failure_stage(rec(), row(success=True)) is None
    assert failure_stage(rec("temporal extraction"), row(success=False)) == "temporal extraction"
    assert failure_stage(rec(), row(success=False, planning_ok=False)) == "planning"
    reached = row(success=False, planning_ok=True, check_reasons=["task A (x) is never reached"])
    assert failure_stage(rec(), reached) == "action completion"
    order = row(success=False, planning_ok=True, check_reasons=["order broken: task A ..."])
    assert failure_stage(rec(), order) == "execution"


def _row(n, k, conv, plan, ok, stage=None):
    return ScenarioRow.model_validate(
        {
            "n_base": n,
            "robots": k,
            "conversion_ok": conv,
            "planning_ok": plan,
            "success": ok,
            "status": "solved" if plan else "infeasible",
            "plan_time_s": 0.1,
            "feasible": True,
            "travel_m": 2.0,
            "steps": 10,
            "stage": stage,
        }
    )


def test_rates_follow_table_1():
    rows = [
        _row(1, 1, True, True, True),
        _row(1, 1, True, False, False, "planning"),
        _row(1, 1, False, True, False, "task decomposition"),
        _row(1, 1, True, True, True),
    ]
    s = pipeline_summary(rows)
    r = s["rows"][0]
    assert r["conversion_rate"] == 0.75 and r["planning_rate"] == round(2 / 3, 4) and r["overall_rate"] == 0.5
    assert "**50** (75, 67)" in table1_markdown(s)
    f = failure_breakdown(rows)
    assert f["counts"]["planning"] == 1 and f["counts"]["task decomposition"] == 1
    assert set(f["counts"]) == set(STAGES)


@needs_data
def test_language_record_scores_conversion_against_ground_truth():
    from nl2hltl2plan.suites.alfred.ground_truth import gt_instance

    ok = language_record(gt_instance("FloorPlan15.tasks_1.compose_0.fintune_1"), PipelineOptions(), None)
    assert ok.conversion_ok and ok.stage is None and ok.levels
    # the scene lacks the statue: conversion still scored, no spec to plan (a planning failure)
    statue = language_record(gt_instance("FloorPlan17.tasks_2.compose_0.fintune_1"), PipelineOptions(), None)
    assert statue.error is not None and "Statue" in statue.error and statue.levels is None


@needs_data
def test_bench_llm_offline_end_to_end_with_custom_ground_truth(tmp_path, capsys):
    from nl2hltl2plan.config import data_path

    lines = data_path("benchmark", "alfred_test50_gt.jsonl").read_text().splitlines()
    gt = tmp_path / "gt.jsonl"
    gt.write_text("\n".join(lines[4:7]) + "\n")
    out = tmp_path / "bench"
    args = ["bench", "alfred", "--llm", "offline", "--robots", "1,2", "--gt", str(gt), "--out", str(out)]
    args.append("--quiet")
    assert main(args) == 0
    assert "overall (conversion, planning)" in capsys.readouterr().out
    summary = json.loads((out / "summary.json").read_text())
    assert summary["scenarios"] == 6 and {"conversion_rate", "planning_rate"} <= set(summary["rows"][0])
    assert (out / "report.md").read_text().count("Table I layout") == 1
    assert (out / "success_vs_base_tasks.png").stat().st_size > 1000
    assert len((out / "language.jsonl").read_text().splitlines()) == 3
    for row in map(json.loads, (out / "scenarios.jsonl").read_text().splitlines()):
        assert row["success"] == (row["stage"] is None)
    bad = tmp_path / "bad.jsonl"
    bad.write_text("{not json}\n")
    assert main(["bench", "alfred", "--llm", "offline", "--gt", str(bad), "--out", str(out)]) == 2
    assert "not valid JSON" in capsys.readouterr().err
