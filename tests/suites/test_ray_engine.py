"""The Ray engine gives the local engine's rows (and resume semantics) on a local Ray instance."""

from __future__ import annotations

import json
import time

import pytest

from nl2hltl2plan.suites.ray_engine import EngineError, run_with_engine
from nl2hltl2plan.suites.runner import Scenario

INSTRUCTIONS = {
    "apple": "Put the apple in the fridge.",
    "two": "Put the apple in the fridge. Then put the mug in the cabinet.",
    "statue": "Put the statue in the fridge.",  # the demo has no statue: an error row
    "slow": "",  # sleeps past the hard time limit: a timeout row
}
SCENARIOS = [Scenario("apple", 1, 1), Scenario("two", 2, 2), Scenario("statue", 1, 1)]
VOLATILE = ("plan_time_s", "expanded", "generated")


def make_job():
    """A real pipeline job on the demo world (a closure, so Ray ships it by value)."""

    def job(scenario: Scenario) -> dict:
        from nl2hltl2plan.pipeline import run
        from nl2hltl2plan.worlds.demo import demo_world

        if scenario.instance == "slow":
            time.sleep(30)
        outcome = run(INSTRUCTIONS[scenario.instance], demo_world(), robots=scenario.robots)
        return {k: v for k, v in outcome.to_json()["planner"].items() if k not in VOLATILE}

    return job


def _stable(rows: list[dict]) -> list[dict]:
    return [{k: v for k, v in r.items() if k != "plan_time_s"} for r in rows]


@pytest.fixture(scope="module")
def ray():
    ray = pytest.importorskip("ray", reason="Ray is not installed (pip install 'nl2hltl2plan[ray]')")
    ray.init(num_cpus=1, include_dashboard=False, log_to_driver=False)
    yield ray
    ray.shutdown()


@pytest.mark.slow  # starts Ray (about 8 s here) and waits out a hard time limit
@pytest.mark.sweep  # the engine's choice is checked by test_engine_errors, its local rows by test_runner_*
def test_ray_rows_equal_local_rows_and_resume(ray, tmp_path):
    job = make_job()
    local = run_with_engine("local", SCENARIOS, job, tmp_path / "local.jsonl", workers=1)
    # resume: the first scenario is already done; the Ray engine must not run it again
    done_row = {**local[0], "marker": "from the earlier run"}
    (tmp_path / "ray.jsonl").write_text(json.dumps(done_row) + "\n")
    seen = []
    remote = run_with_engine("ray", SCENARIOS, job, tmp_path / "ray.jsonl", workers=1,
                             progress=lambda row, k, n: seen.append((row["key"], k, n)))  # fmt: skip
    assert remote[0]["marker"] == "from the earlier run"
    assert [k for k, _, _ in seen] == [s.key for s in SCENARIOS[1:]] and seen[-1][1:] == (3, 3)
    assert _stable(local) == _stable([{k: v for k, v in r.items() if k != "marker"} for r in remote])
    statuses = [r["status"] for r in remote]
    assert statuses == ["solved", "solved", "error"] and "no Statue in demo" in remote[2]["reason"]
    on_disk = [json.loads(line) for line in (tmp_path / "ray.jsonl").read_text().splitlines()]
    assert [r["key"] for r in on_disk] == [s.key for s in SCENARIOS]
    # not resuming starts afresh
    fresh = run_with_engine("ray", SCENARIOS[:1], job, tmp_path / "ray.jsonl", resume=False, workers=1)
    assert "marker" not in fresh[0] and len((tmp_path / "ray.jsonl").read_text().splitlines()) == 1
    # a task past the hard limit is cancelled and recorded as the local engine records it (1 s: the
    # limit is a wait that leaves this worker's core idle; the warm Ray worker starts the task in ms)
    slow = [Scenario("slow", 1, 1)]
    (timed_out,) = run_with_engine("ray", slow, job, tmp_path / "slow.jsonl", workers=1, hard_timeout_s=1)
    assert (
        timed_out["status"] == "timeout" and timed_out["killed"] and timed_out["reason"] == "killed after 1 s"
    )


def test_engine_errors(tmp_path):
    with pytest.raises(EngineError, match="unknown engine 'spark'"):
        run_with_engine("spark", SCENARIOS, make_job(), tmp_path / "x.jsonl")
    with pytest.raises(EngineError, match="--address needs --engine ray"):
        run_with_engine("local", SCENARIOS, make_job(), tmp_path / "x.jsonl", address="10.0.0.1:6379")
