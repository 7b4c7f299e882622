"""Ray as the distributed engine for benchmarks: `run_scenarios_ray` has the interface, rows and resume
semantics of `runner.run_scenarios`, but runs each scenario as a Ray task, on this machine or on a
cluster (`address`), so an evaluation can outgrow one machine.

- Rows: `{**scenario fields, "key": ..., **job row}` appended to `out` (JSON lines) as they finish,
  exactly as the local engine writes them (both keep `out` with `runner.ResultsFile`): with `resume`,
  scenarios already in `out` are skipped except "error" rows, which run again (the file is repaired
  first: torn lines are reported and dropped); without, `out` is started afresh. Worker count and
  time limit are checked as the local engine checks them.
- A job that raises gives an "error" row with the same one-line reason (`deadline.describe_exception`);
  a task that runs past `hard_timeout_s` (counted from its submission, at most `workers` tasks in
  flight) is cancelled with force (its worker process is killed) and gives the same "timeout" row
  marked `killed`; a worker that dies gives an "error" row.
- The job is any picklable callable of a scenario (Ray pickles closures with cloudpickle). On a
  cluster every node needs this package and the data folder (`NL2HLTL2PLAN_DATA`).

`run_with_engine("local" | "ray", ...)` picks the engine; Ray is the optional extra `[ray]`.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from nl2hltl2plan.deadline import describe_exception
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.suites.runner import (
    Notes,
    ResultsFile,
    Row,
    Scenario,
    check_limits,
    checked_row,
    killed_row,
    run_scenarios,
    stderr_note,
)

ENGINES = ("local", "ray")  # `run_with_engine`'s names for run_scenarios and run_scenarios_ray


class EngineError(Nl2Hltl2PlanError):
    """The benchmark engine cannot run (Ray missing, a cluster that cannot be joined)."""


def _run_job(job: Callable[[Scenario], Row], scenario: Scenario) -> Row:
    """The job's row, or an "error" row with the message and where it happened (as the local engine)."""
    try:
        row = job(scenario)
    except Exception as exc:  # every failure of a job is data for its row
        return {"status": "error", "reason": describe_exception(exc)}
    return checked_row(row)


def _ray() -> Any:
    try:
        import ray
    except ModuleNotFoundError:
        raise EngineError("the ray engine needs Ray: pip install 'nl2hltl2plan[ray]'") from None
    return ray


def _connect(ray: Any, address: str | None, workers: int) -> bool:
    """Join `address` or start a local instance with `workers` CPUs; True when we started Ray here."""
    if ray.is_initialized():
        return False
    try:
        if address:
            ray.init(address=address, include_dashboard=False, log_to_driver=False)
        else:
            ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
    except (ConnectionError, RuntimeError, ValueError) as exc:
        raise EngineError(f"cannot start or join Ray at {address or 'this machine'}: {exc}") from None
    return True


def run_scenarios_ray(
    scenarios: Iterable[Scenario],
    job: Callable[[Scenario], Row],
    out: Path,
    workers: int | None = None,
    hard_timeout_s: float = 360.0,
    resume: bool = True,
    progress: Callable[[Row, int, int], None] | None = None,
    notes: Notes | None = stderr_note,
    address: str | None = None,
) -> list[Row]:
    """Run every scenario as a Ray task (at most `workers` at a time) and return the rows in order."""
    ray = _ray()
    scenarios = list(scenarios)
    workers = check_limits(workers, hard_timeout_s)
    results = ResultsFile(out, scenarios, resume, progress, notes)
    started_here = _connect(ray, address, workers) if results.todo else False
    try:
        with results:
            if results.todo:
                _loop(ray, results.todo, job, workers, hard_timeout_s, results.record)
    finally:
        if started_here:
            ray.shutdown()
    return results.rows()


def _loop(
    ray: Any,
    todo: list[Scenario],
    job: Callable[[Scenario], Row],
    workers: int,
    hard_timeout_s: float,
    record: Callable[[Scenario, Row], None],
) -> None:
    remote = ray.remote(max_retries=0)(_run_job)
    job_ref = ray.put(job)  # shipped once, not once per scenario
    running: dict[Any, tuple[Scenario, float]] = {}
    pending = list(todo)
    try:
        while pending or running:
            while pending and len(running) < workers:
                scenario = pending.pop(0)
                running[remote.remote(job_ref, scenario)] = (scenario, time.perf_counter())
            ready, _ = ray.wait(list(running), num_returns=1, timeout=0.2)
            for ref in ready:
                scenario, _started = running.pop(ref)
                try:
                    row = ray.get(ref)
                except ray.exceptions.RayError as exc:  # the worker died or the task was lost
                    row = {"status": "error", "reason": f"worker died ({type(exc).__name__})"}
                record(scenario, row)
            now = time.perf_counter()
            for ref, (scenario, started) in list(running.items()):
                if now - started > hard_timeout_s:
                    ray.cancel(ref, force=True)
                    del running[ref]
                    record(scenario, killed_row(now - started, hard_timeout_s))
    finally:
        for ref in running:  # interrupted: leave no task behind
            ray.cancel(ref, force=True)


def run_with_engine(
    engine: str,
    scenarios: Iterable[Scenario],
    job: Callable[[Scenario], Row],
    out: Path,
    address: str | None = None,
    **kwargs: Any,
) -> list[Row]:
    """`runner.run_scenarios` (engine "local") or `run_scenarios_ray` (engine "ray", `address` to join
    a running cluster); the other keyword arguments are those of `run_scenarios`."""
    runners: dict[str, Callable[..., list[Row]]] = {
        "local": run_scenarios,
        "ray": functools.partial(run_scenarios_ray, address=address),
    }
    if engine not in runners:
        raise EngineError(f"unknown engine {engine!r}; expected one of {', '.join(ENGINES)}")
    if address and runners[engine] is run_scenarios:
        raise EngineError("--address needs --engine ray")
    return runners[engine](scenarios, job, out, **kwargs)
