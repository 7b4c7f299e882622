"""The scenario runner (parallel, hard time limits, resumable) and the summary / table."""

from __future__ import annotations

import json
import os
import time

import pytest

from nl2hltl2plan.suites.rows import rows_of
from nl2hltl2plan.suites.runner import RunnerError, Scenario, count_errored, run_scenarios
from nl2hltl2plan.suites.summaries import format_table, paper_table1, percentile, summarize


def job(scenario: Scenario) -> dict:
    if scenario.instance == "sleepy":
        time.sleep(60)
    if scenario.instance == "broken":
        raise ValueError("bad scenario")
    return {
        "status": "solved",
        "plan_time_s": 0.01 * scenario.robots,
        "success": True,
        "feasible": True,
        "travel_m": 1.0 * scenario.robots,
        "steps": 10,
    }


def job_never_run(scenario: Scenario) -> dict:
    raise AssertionError(f"{scenario.key} was run again on resume")


def test_runner_kills_hangs_reports_errors_and_resumes(tmp_path):
    out = tmp_path / "rows.jsonl"
    scenarios = [Scenario("ok", 1, r) for r in (1, 2)] + [Scenario("sleepy", 1, 1), Scenario("broken", 1, 1)]
    rows = run_scenarios(scenarios, job, out, workers=2, hard_timeout_s=1.0)
    by = {r["instance"]: r for r in rows}
    assert [r["key"] for r in rows] == [s.key for s in scenarios]
    assert by["sleepy"]["status"] == "timeout" and by["sleepy"]["killed"]
    assert by["broken"]["status"] == "error" and "ValueError: bad scenario" in by["broken"]["reason"]
    assert by["ok"]["success"]
    assert len(out.read_text().splitlines()) == 4
    # resuming runs again only what errored (a job that fails on every call shows which ran): the finished
    # and timed-out rows stay as stored
    again = run_scenarios(scenarios, job_never_run, out, workers=2, hard_timeout_s=1.0)
    assert again[:3] == rows[:3]
    assert "broken|r1|d0 was run again" in again[3]["reason"]


def test_summary_and_table():
    rows = [
        {
            "n_base": 1,
            "robots": 1,
            "status": "solved",
            "success": True,
            "feasible": True,
            "travel_m": 1.0,
            "steps": 10,
            "plan_time_s": 0.1,
        },
        {
            "n_base": 1,
            "robots": 1,
            "status": "solved",
            "success": True,
            "feasible": True,
            "travel_m": 3.0,
            "steps": 20,
            "plan_time_s": 0.3,
        },
        {
            "n_base": 1,
            "robots": 1,
            "status": "infeasible",
            "success": False,
            "feasible": False,
            "plan_time_s": 0.01,
        },
        {"n_base": 2, "robots": 4, "status": "timeout", "success": False, "feasible": True},
    ]
    s = summarize(rows_of(rows))
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


# ----- robustness (issue 10.5) -----------------------------------------------------------------------
def quick(scenario: Scenario) -> dict:
    return {"status": "solved", "success": True}


def test_torn_last_line_is_reported_dropped_and_rerun(tmp_path):
    out = tmp_path / "rows.jsonl"
    scenarios = [Scenario("a", 1, 1), Scenario("b", 1, 1), Scenario("c", 1, 1)]
    run_scenarios(scenarios[:2], quick, out, workers=1, notes=None)
    text = out.read_text()
    out.write_text(text + '{"instance": "c", "key": "c|r1|d0", "sta')  # killed mid-write
    notes: list[str] = []
    rows = run_scenarios(scenarios, quick, out, workers=1, notes=notes.append)
    assert len(notes) == 1 and "line 3 is torn" in notes[0] and "runs again" in notes[0]
    lines = out.read_text().splitlines()
    assert [json.loads(x)["key"] for x in lines] == [s.key for s in scenarios]  # every line is a row
    assert [r["key"] for r in rows] == [s.key for s in scenarios]


def test_invalid_lines_anywhere_are_reported(tmp_path):
    out = tmp_path / "rows.jsonl"
    good = json.dumps({"key": "a|r1|d0", "status": "solved"})
    out.write_bytes(b"\xff\xfe binary\n[1, 2]\n" + good.encode() + b"\n" + b"[" * 5000 + b"\n")
    notes: list[str] = []
    rows = run_scenarios([Scenario("a", 1, 1), Scenario("b", 1, 1)], quick, out, notes=notes.append)
    assert [n.split(" is ")[0] for n in notes] == [f"rows.jsonl line {k}" for k in (1, 2, 4)]
    assert rows[0]["status"] == "solved" and "instance" not in rows[0]  # kept, not re-run
    assert len(out.read_text().splitlines()) == 2


def test_errored_scenarios_are_counted(tmp_path):
    scenarios = [Scenario("ok", 1, 1), Scenario("broken", 1, 1), Scenario("sleepy", 1, 1)]
    rows = run_scenarios(scenarios, job, tmp_path / "rows.jsonl", workers=3, hard_timeout_s=0.5)
    assert count_errored(rows) == 2  # the job that raised and the one that had to be killed
    assert count_errored(rows[:1]) == 0


def dies(scenario: Scenario) -> dict:
    os._exit(3)


def not_a_row(scenario: Scenario) -> object:
    return 42


def test_dead_worker_and_bad_return_are_error_rows(tmp_path):
    rows = run_scenarios([Scenario("x", 1, 1)], dies, tmp_path / "a.jsonl", workers=1)
    assert rows[0]["status"] == "error" and "died of exit code 3" in rows[0]["reason"]
    rows = run_scenarios([Scenario("x", 1, 1)], not_a_row, tmp_path / "b.jsonl", workers=1)
    assert rows[0]["status"] == "error" and "returned int" in rows[0]["reason"]


@pytest.mark.parametrize(
    "kw, msg",
    [
        ({"hard_timeout_s": 0}, "time limit"),
        ({"hard_timeout_s": float("nan")}, "time limit"),
        ({"workers": 0}, "workers must be at least 1"),
    ],
)
def test_bad_limits_are_refused(tmp_path, kw, msg):
    with pytest.raises(RunnerError, match=msg):
        run_scenarios([Scenario("x", 1, 1)], quick, tmp_path / "rows.jsonl", **kw)


def test_unusable_results_paths_are_clean_errors(tmp_path):
    (tmp_path / "dir.jsonl").mkdir()
    with pytest.raises(RunnerError, match="cannot read the results file .*dir.jsonl"):
        run_scenarios([Scenario("x", 1, 1)], quick, tmp_path / "dir.jsonl")
    (tmp_path / "file").write_text("")
    with pytest.raises(RunnerError, match="cannot write the results file"):
        run_scenarios([Scenario("x", 1, 1)], quick, tmp_path / "file" / "rows.jsonl")
