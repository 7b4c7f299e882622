"""Run benchmark scenarios in worker processes with a hard per-scenario time limit.

`run_scenarios(scenarios, job, out, workers, hard_timeout_s)` forks one child per scenario (at most
`workers` at a time, with `nl2hltl2plan.deadline.Child`: a child dies with its parent, so a killed
run leaves no orphaned worker); the child runs `job(scenario) -> dict` and sends the row back. The
parent kills a child that runs past `hard_timeout_s` and records a "timeout" row marked `killed`, so
nothing can hang, and a job that raises (or a worker that dies) records an "error" row with a
one-line reason (no traceback). Rows are appended to `out` as JSON lines as they finish; with
`resume`, scenarios whose key is already in `out` are not run again, except those whose row is an
"error" (the job raised: a dead LLM, a crashed worker), which run again.

A results file is repaired before anything is appended: a torn last line (a run killed mid-write)
or any line that is not a JSON object with a "key" is reported (`notes`, default stderr) and
dropped, so its scenario runs again instead of being appended onto. `count_errored(rows)` is the
number of scenarios that errored or had to be killed (what makes a benchmark run exit non-zero).
"""

from __future__ import annotations

import json
import math
import os
import sys
import tempfile
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from nl2hltl2plan.deadline import Child, ChildError, wait_any
from nl2hltl2plan.errors import Nl2Hltl2PlanError

Row = dict[str, Any]
Notes = Callable[[str], None]


class RunnerError(Nl2Hltl2PlanError):
    """The runner cannot start: bad worker count or time limit."""


@dataclass(frozen=True)
class Scenario:
    """One benchmark run: an instance, a team size, a draw of start positions."""

    instance: str
    n_base: int
    robots: int
    draw: int = 0

    @property
    def key(self) -> str:
        return f"{self.instance}|r{self.robots}|d{self.draw}"


def stderr_note(text: str) -> None:
    print(f"warning: {text}", file=sys.stderr)


def read_rows(path: Path) -> tuple[dict[str, Row], list[str]]:
    """Rows of a JSON-lines results file by key, and one problem per line that is not a row."""
    rows: dict[str, Row] = {}
    problems: list[str] = []
    if not path.exists():
        return rows, problems
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise RunnerError(f"cannot read the results file {path}: {exc.strerror}") from None
    lines = data.split(b"\n")
    last = len(lines) - (1 if data.endswith(b"\n") else 0)
    for n, raw in enumerate(lines[:last], 1):
        if not raw.strip():
            continue
        try:
            row = json.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, json.JSONDecodeError, RecursionError):
            row = None
        if isinstance(row, dict) and isinstance(row.get("key"), str):
            rows[row["key"]] = row
            continue
        torn = n == last and not data.endswith(b"\n")
        what = "is torn (no end of line: a run was killed writing it)" if torn else "is not a result row"
        problems.append(f"{path.name} line {n} {what}; dropped, its scenario runs again")
    return rows, problems


def load_rows(path: Path, notes: Notes | None = stderr_note) -> dict[str, Row]:
    """Rows already written to a JSON-lines file, by key. Bad lines (a torn last line above all) are
    reported through `notes` and removed from the file, so what is appended next starts a line."""
    rows, problems = read_rows(path)
    if problems:
        for p in problems:
            if notes is not None:
                notes(p)
        _rewrite(path, rows.values())
    return rows


def _rewrite(path: Path, rows: Iterable[Row]) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".tmp")
    with os.fdopen(fd, "w") as fh:
        for row in rows:
            fh.write(json.dumps(row) + "\n")
    os.replace(tmp, path)


def is_errored(row: Row) -> bool:
    """A scenario whose run failed (the job raised, the worker died, or it had to be killed)."""
    return row.get("status") == "error" or bool(row.get("killed"))


def count_errored(rows: Iterable[Row]) -> int:
    return sum(1 for r in rows if is_errored(r))


def checked_row(row: object) -> Row:
    """The job's row, or an "error" row when the job returned something else (both engines)."""
    if not isinstance(row, dict):
        return {"status": "error", "reason": f"the job returned {type(row).__name__}, not a row"}
    return row


def killed_row(elapsed: float, hard_timeout_s: float) -> Row:
    """The row of a scenario killed for running past `hard_timeout_s` (both engines)."""
    return {"status": "timeout", "killed": True, "plan_time_s": round(elapsed, 3),
            "reason": f"killed after {hard_timeout_s:g} s"}


def _job_main(job_and_scenario: tuple[Callable[[Scenario], Row], Scenario]) -> Row:
    job, scenario = job_and_scenario
    return job(scenario)


def check_limits(workers: int | None, hard_timeout_s: float) -> int:
    finite = isinstance(hard_timeout_s, (int, float)) and math.isfinite(hard_timeout_s)
    if not finite or hard_timeout_s <= 0:
        raise RunnerError(f"the per-scenario time limit must be finite and > 0 s, got {hard_timeout_s!r}")
    if workers is not None and workers < 1:
        raise RunnerError(f"workers must be at least 1, got {workers}")
    return workers or os.cpu_count() or 1


class ResultsFile:
    """A run's JSON-lines results file, as both engines keep it: the rows already there (`done`, the
    file repaired by `load_rows`; without `resume` it is started afresh), the scenarios still to run
    (`todo`: not there yet, or there as an "error"), and `record`, which appends a finished row."""

    def __init__(
        self,
        out: Path,
        scenarios: list[Scenario],
        resume: bool,
        progress: Callable[[Row, int, int], None] | None,
        notes: Notes | None,
    ) -> None:
        self.out, self.scenarios, self._progress = out, scenarios, progress
        try:
            out.parent.mkdir(parents=True, exist_ok=True)
            if not resume and out.exists():
                out.unlink()
            self.done = load_rows(out, notes)
        except OSError as exc:
            raise self._unwritable(exc) from None
        done = self.done
        self.todo = [s for s in scenarios if s.key not in done or done[s.key].get("status") == "error"]
        self._finished = len(scenarios) - len(self.todo)

    def _unwritable(self, exc: OSError) -> RunnerError:
        return RunnerError(f"cannot write the results file {self.out}: {exc.strerror}")

    def __enter__(self) -> ResultsFile:
        try:
            self._sink = self.out.open("a")
        except OSError as exc:
            raise self._unwritable(exc) from None
        return self

    def __exit__(self, *exc: object) -> None:
        self._sink.close()

    def record(self, scenario: Scenario, row: Row) -> None:
        row = {**asdict(scenario), "key": scenario.key, **row}
        self.done[scenario.key] = row
        self._sink.write(json.dumps(row) + "\n")
        self._sink.flush()
        self._finished += 1
        if self._progress:
            self._progress(row, self._finished, len(self.scenarios))

    def rows(self) -> list[Row]:
        """The rows of every scenario that has one, in the scenarios' order."""
        return [self.done[s.key] for s in self.scenarios if s.key in self.done]


def run_scenarios(
    scenarios: Iterable[Scenario],
    job: Callable[[Scenario], Row],
    out: Path,
    workers: int | None = None,
    hard_timeout_s: float = 360.0,
    resume: bool = True,
    progress: Callable[[Row, int, int], None] | None = None,
    notes: Notes | None = stderr_note,
) -> list[Row]:
    """Run every scenario (in parallel, each in its own process) and return the rows in order."""
    scenarios = list(scenarios)
    n_workers = check_limits(workers, hard_timeout_s)
    results = ResultsFile(out, scenarios, resume, progress, notes)
    running: dict[Child, Scenario] = {}
    with results:
        try:
            _loop(results.todo, running, n_workers, hard_timeout_s, job, results.record)
        finally:
            for child in running:  # interrupted: leave no worker behind
                child.kill()
    return results.rows()


def _loop(
    todo: list[Scenario],
    running: dict[Child, Scenario],
    workers: int,
    hard_timeout_s: float,
    job: Callable[[Scenario], Row],
    record: Callable[[Scenario, Row], None],
) -> None:
    while todo or running:
        while todo and len(running) < workers:
            scenario = todo.pop(0)
            # own process group: a timeout kill also ends whatever the job started
            running[Child(_job_main, (job, scenario), own_group=True)] = scenario
        for child in wait_any(list(running), timeout_s=0.2):
            scenario = running.pop(child)
            try:
                row = child.result()
            except ChildError as exc:
                row = {"status": "error", "reason": str(exc)}
            record(scenario, checked_row(row))
        for child, scenario in list(running.items()):
            elapsed = child.elapsed()
            if elapsed > hard_timeout_s:
                child.kill()
                del running[child]
                record(scenario, killed_row(elapsed, hard_timeout_s))
