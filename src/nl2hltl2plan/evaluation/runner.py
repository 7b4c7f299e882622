"""Run benchmark scenarios in worker processes with a hard per-scenario time limit.

`run_scenarios(scenarios, job, out, workers, hard_timeout_s)` forks one child per scenario (at most
`workers` at a time); the child runs `job(scenario) -> dict` and sends the row back. The parent kills
a child that runs past `hard_timeout_s` and records a "timeout" row, so nothing can hang, and a job
that raises records an "error" row with the message (no traceback). Rows are appended to `out` as
JSON lines as they finish; with `resume`, scenarios whose key is already in `out` are not run again.
The job is any function of a scenario (oracle specs here; the language stage plugs in its own).
"""

from __future__ import annotations

import json
import multiprocessing as mp
import os
import signal
import time
import traceback
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import Any

Row = dict[str, Any]


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


def load_rows(path: Path) -> dict[str, Row]:
    """Rows already written to a JSON-lines file, by scenario key (a torn last line is ignored)."""
    rows: dict[str, Row] = {}
    if not path.exists():
        return rows
    for line in path.read_text().splitlines():
        try:
            row = json.loads(line)
        except json.JSONDecodeError:
            continue
        if isinstance(row, dict) and "key" in row:
            rows[row["key"]] = row
    return rows


def _child(job: Callable[[Scenario], Row], scenario: Scenario, conn: Connection) -> None:
    os.setpgid(0, 0)  # own process group: a kill also ends what the job itself started
    try:
        row = job(scenario)
    except BaseException as exc:  # report every failure to the parent as data
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" at {os.path.basename(tb[-1].filename)}:{tb[-1].lineno}" if tb else ""
        row = {"status": "error", "reason": f"{type(exc).__name__}: {exc}{where}"}
    try:
        conn.send(row)
    finally:
        conn.close()


def run_scenarios(
    scenarios: Iterable[Scenario],
    job: Callable[[Scenario], Row],
    out: Path,
    workers: int | None = None,
    hard_timeout_s: float = 360.0,
    resume: bool = True,
    progress: Callable[[Row, int, int], None] | None = None,
) -> list[Row]:
    """Run every scenario (in parallel, each in its own process) and return the rows in order."""
    scenarios = list(scenarios)
    out.parent.mkdir(parents=True, exist_ok=True)
    done = load_rows(out) if resume else {}
    if not resume and out.exists():
        out.unlink()
    todo = [s for s in scenarios if s.key not in done]
    workers = max(1, workers or os.cpu_count() or 1)
    ctx = mp.get_context("fork")
    running: dict[Connection, tuple[Any, Scenario, float]] = {}
    finished = len(scenarios) - len(todo)
    with out.open("a") as sink:

        def record(scenario: Scenario, row: Row) -> None:
            nonlocal finished
            row = {**asdict(scenario), "key": scenario.key, **row}
            done[scenario.key] = row
            sink.write(json.dumps(row) + "\n")
            sink.flush()
            finished += 1
            if progress:
                progress(row, finished, len(scenarios))

        try:
            _loop(todo, running, workers, hard_timeout_s, ctx, job, record)
        finally:
            for conn, (proc, _, _) in running.items():  # interrupted: leave no worker behind
                _kill(proc)
                conn.close()
    return [done[s.key] for s in scenarios if s.key in done]


def _loop(todo, running, workers, hard_timeout_s, ctx, job, record) -> None:
    while todo or running:
        while todo and len(running) < workers:
            scenario = todo.pop(0)
            parent_end, child_end = ctx.Pipe(duplex=False)
            # not a daemon: the planner may itself fork (Spot translations with a time limit)
            proc = ctx.Process(target=_child, args=(job, scenario, child_end))
            proc.start()
            child_end.close()
            running[parent_end] = (proc, scenario, time.perf_counter())
        for conn in wait(list(running), timeout=0.2):
            proc, scenario, _ = running.pop(conn)  # type: ignore[index]
            try:
                row = conn.recv()
            except (EOFError, OSError):
                row = {"status": "error", "reason": f"worker died (exit code {proc.exitcode})"}
            conn.close()
            proc.join(timeout=5)
            record(scenario, row)
        now = time.perf_counter()
        for conn, (proc, scenario, started) in list(running.items()):
            if now - started > hard_timeout_s:
                _kill(proc)
                conn.close()
                del running[conn]
                record(scenario, {"status": "timeout", "killed": True, "plan_time_s": round(now - started, 3),
                                  "reason": f"killed after {hard_timeout_s:g} s"})


def _kill(proc) -> None:
    """Kill a worker and its process group (it made itself the group leader)."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        proc.kill()
    proc.join(timeout=5)
