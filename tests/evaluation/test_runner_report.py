"""The scenario runner (parallel, hard time limits, resumable) and the summary / table."""

from __future__ import annotations

import json
import time

from nl2hltl2plan.evaluation.report import format_table, paper_table1, percentile, summarize
from nl2hltl2plan.evaluation.runner import Scenario, run_scenarios


def job(scenario: Scenario) -> dict:
    if scenario.instance == "sleepy":
        time.sleep(60)
    if scenario.instance == "broken":
        raise ValueError("bad scenario")
    return {"status": "solved", "plan_time_s": 0.01 * scenario.robots, "success": True, "feasible": True,
            "travel_m": 1.0 * scenario.robots, "steps": 10}


def test_runner_kills_hangs_reports_errors_and_resumes(tmp_path):
    out = tmp_path / "rows.jsonl"
    scenarios = [Scenario("ok", 1, r) for r in (1, 2)] + [Scenario("sleepy", 1, 1), Scenario("broken", 1, 1)]
    t0 = time.perf_counter()
    rows = run_scenarios(scenarios, job, out, workers=2, hard_timeout_s=1.0)
    assert time.perf_counter() - t0 < 20
    by = {r["instance"]: r for r in rows}
    assert [r["key"] for r in rows] == [s.key for s in scenarios]
    assert by["sleepy"]["status"] == "timeout" and by["sleepy"]["killed"]
    assert by["broken"]["status"] == "error" and "ValueError: bad scenario" in by["broken"]["reason"]
    assert by["ok"]["success"]
    assert len(out.read_text().splitlines()) == 4
    # resuming runs nothing again (the sleepy one would take 1 s)
    t0 = time.perf_counter()
    again = run_scenarios(scenarios, job, out, workers=2, hard_timeout_s=1.0)
    assert time.perf_counter() - t0 < 0.5
    assert [r["key"] for r in again] == [r["key"] for r in rows]


def test_summary_and_table():
    rows = [
        {"n_base": 1, "robots": 1, "status": "solved", "success": True, "feasible": True, "travel_m": 1.0,
         "steps": 10, "plan_time_s": 0.1},
        {"n_base": 1, "robots": 1, "status": "solved", "success": True, "feasible": True, "travel_m": 3.0,
         "steps": 20, "plan_time_s": 0.3},
        {"n_base": 1, "robots": 1, "status": "infeasible", "success": False, "feasible": False,
         "plan_time_s": 0.01},
        {"n_base": 2, "robots": 4, "status": "timeout", "success": False, "feasible": True},
    ]
    s = summarize(rows)
    assert (s["scenarios"], s["feasible"], s["solved"], s["success"]) == (4, 3, 2, 2)
    assert s["plan_time_s"] == {"median": 0.1, "p95": 0.3, "max": 0.3, "mean": 0.1367}
    row = s["rows"][0]
    assert (row["n_base"], row["robots"], row["success_rate"]) == (1, 1, 1.0)
    assert (row["travel_m_mean"], row["travel_m_std"], row["steps_mean"]) == (2.0, 1.0, 15.0)
    assert s["rows"][1]["success_rate"] == 0.0 and s["rows"][1]["travel_m_mean"] is None
    text = format_table(s, "title")
    assert "1-1" in text and "2.0±1.0" in text and "2.9±2.0" in text  # ours and the paper's 1-1 travel
    json.dumps(s)


def test_paper_table_and_percentile():
    paper = paper_table1()
    assert len(paper) == 12 and paper[(4, 4)]["ours"]["planning"] == 77
    assert percentile([5, 1, 4, 2, 3], 95) == 5 and percentile([1, 2, 3, 4], 50) == 2
