"""Plan requests as jobs in worker processes: a bounded queue, a deadline each, cancel by kill.

- At most `workers` plans run at once, each in its own process (`web.worker.work`), forked from a
  fork server that has the pipeline imported already, so the server's event loop only passes
  messages and stays quick for light requests (the page, world geometry) while plans run.
- At most `queue` more wait for a worker; one more is refused at once (`Busy`: HTTP 503 with
  Retry-After), never left to hang.
- Each job has a deadline counted from its submission (waiting, language stage, planning and
  pictures together): the worker gets what is left of it, and is killed when it runs past.
- `cancel` kills the worker (the server calls it when the client disconnects or asks).
- A job's events (`progress`, `result`, `files`, `error`, then `done`) are kept in order, with its
  files in memory, for the `kept` most recent jobs (downloads and shared pictures read them there).
"""

from __future__ import annotations

import asyncio
import multiprocessing as mp
import os
import secrets
import shutil
import tempfile
import time
from collections import OrderedDict
from collections.abc import AsyncIterator
from dataclasses import dataclass, field
from multiprocessing.connection import Connection
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.web.requests import PlanRequest

HEARTBEAT_S = 0.25  # how often a follower wakes up with no news (to notice a gone client)
KILL_GRACE_S = 1.0  # past the deadline, how long the worker may take to say so itself
# imported by the fork server once; `web.warm` plans a small demo instruction there (see its docstring)
PRELOAD = ["nl2hltl2plan.web.worker", "nl2hltl2plan.present.outputs", "matplotlib.pyplot",
           "nl2hltl2plan.web.warm"]
Event = tuple[str, dict[str, Any]]


class Busy(Nl2Hltl2PlanError):
    """Every worker is busy and the queue is full (HTTP 503)."""


@dataclass
class Job:
    """One plan request: its events in order, its state, and its files once written."""

    id: str
    request: PlanRequest
    deadline: float  # time.monotonic() by which it must be over
    state: str = "queued"  # queued, running, done, failed, cancelled
    events: list[Event] = field(default_factory=list)
    files: dict[str, bytes] = field(default_factory=dict)
    proc: Any = None
    written: dict[str, Any] | None = None  # the worker's `files` event, passed on once they are read
    _changed: asyncio.Event = field(default_factory=asyncio.Event)

    @property
    def finished(self) -> bool:
        return self.state in ("done", "failed", "cancelled")

    def push(self, kind: str, data: dict[str, Any]) -> None:
        self.events.append((kind, data))
        self._changed.set()

    def first(self, kind: str) -> dict[str, Any] | None:
        return next((data for k, data in self.events if k == kind), None)

    def finish(self, state: str, **extra: Any) -> None:
        if not self.finished:
            self.state = state
            self.push("done", {"state": state, **extra})

    async def follow(self) -> AsyncIterator[Event | None]:
        """The job's events in order, from the first, until `done`; None every HEARTBEAT_S without news."""
        seen = 0
        while True:
            while seen < len(self.events):
                seen += 1
                yield self.events[seen - 1]
            if self.finished:
                return
            self._changed.clear()
            try:
                await asyncio.wait_for(self._changed.wait(), HEARTBEAT_S)
            except TimeoutError:
                yield None


class Jobs:
    """The server's plan jobs (see the module docstring)."""

    def __init__(self, workers: int | None = None, queue: int = 8, kept: int = 32) -> None:
        self.workers = max(1, workers or os.cpu_count() or 1)
        self.queue = max(0, queue)
        self.kept = kept
        self.ctx = mp.get_context("forkserver")
        self.ctx.set_forkserver_preload(PRELOAD)
        self.jobs: OrderedDict[str, Job] = OrderedDict()
        self._slots: asyncio.Semaphore | None = None
        self._tasks: set[asyncio.Task] = set()

    def counts(self) -> dict[str, int]:
        states = [j.state for j in self.jobs.values()]
        return {"workers": self.workers, "queue": self.queue,
                "running": states.count("running"), "waiting": states.count("queued")}  # fmt: skip

    def submit(self, request: PlanRequest) -> Job:
        """Start a job (it waits for a worker); `Busy` when the workers and the queue are full."""
        c = self.counts()
        if c["running"] + c["waiting"] >= self.workers + self.queue:
            raise Busy(f"the server is busy: {c['running']} plan(s) running and {c['waiting']} waiting "
                       f"(at most {self.workers} + {self.queue}); try again in a few seconds")  # fmt: skip
        if self._slots is None:
            self._slots = asyncio.Semaphore(self.workers)
        job = Job(secrets.token_hex(8), request, time.monotonic() + request.timeout_s)
        self.jobs[job.id] = job
        self._forget_old()
        task = asyncio.get_running_loop().create_task(self._run(job))
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)
        return job

    def get(self, job_id: str) -> Job | None:
        return self.jobs.get(job_id)

    def cancel(self, job: Job) -> None:
        """Stop the job: a waiting one never starts, a running one's worker is killed."""
        if job.finished:
            return
        job.finish("cancelled")
        if job.proc is not None and job.proc.is_alive():
            job.proc.kill()

    def close(self) -> None:
        for job in list(self.jobs.values()):
            self.cancel(job)

    def warm_up(self) -> None:
        """Start the fork server now (it imports the pipeline: seconds), not on the first request."""
        proc = self.ctx.Process(target=os.getpid)
        proc.start()
        proc.join()

    def _forget_old(self) -> None:
        finished = [k for k, j in self.jobs.items() if j.finished]
        for k in finished[: max(0, len(finished) - self.kept)]:
            del self.jobs[k]

    async def _run(self, job: Job) -> None:
        assert self._slots is not None
        async with self._slots:
            if job.finished:  # cancelled while it waited
                return
            if time.monotonic() >= job.deadline:
                job.push("error", {"status": 504, "error": f"the request waited past its deadline of "
                                   f"{job.request.timeout_s:g} s for a free worker"})  # fmt: skip
                job.finish("failed")
                return
            job.state = "running"
            folder = tempfile.mkdtemp(prefix="nl2hltl2plan-job-")
            try:
                await self._execute(job, folder)
            finally:
                shutil.rmtree(folder, ignore_errors=True)

    async def _execute(self, job: Job, folder: str) -> None:
        from nl2hltl2plan.web.worker import work

        left = job.deadline - time.monotonic()
        body = {**job.request.model_dump(), "timeout_s": left}
        conn, child_end = self.ctx.Pipe(duplex=False)
        job.proc = self.ctx.Process(target=work, args=(body, folder, child_end), daemon=True)
        try:
            await asyncio.to_thread(job.proc.start)
            child_end.close()
            if job.finished:  # cancelled while it started
                job.proc.kill()
            await self._relay(job, conn, left + KILL_GRACE_S)
        finally:
            conn.close()
            if job.proc.is_alive():
                job.proc.kill()
            await asyncio.to_thread(job.proc.join, 5)
        self._conclude(job, folder)

    async def _relay(self, job: Job, conn: Connection, timeout_s: float) -> None:
        """Pass the worker's events on to the job until it exits (or the deadline passes: kill)."""
        loop = asyncio.get_running_loop()
        ended: asyncio.Future[None] = loop.create_future()

        def readable() -> None:
            try:
                while conn.poll():
                    kind, data = conn.recv()
                    if kind == "files":  # said once the server has read them (see _conclude)
                        job.written = data
                    elif not job.finished:
                        job.push(kind, data)
            except (EOFError, OSError):
                loop.remove_reader(fd)
                if not ended.done():
                    ended.set_result(None)

        fd = conn.fileno()
        loop.add_reader(fd, readable)
        try:
            await asyncio.wait_for(ended, timeout_s)
        except TimeoutError:
            job.proc.kill()
            if not job.finished:
                job.push("error", {"status": 504, "error": f"the request ran past its deadline of "
                                   f"{job.request.timeout_s:g} s (language stage, planning and pictures "
                                   "together)"})  # fmt: skip
        finally:
            loop.remove_reader(fd)  # a no-op when the end of the pipe already removed it

    def _conclude(self, job: Job, folder: str) -> None:
        """Read the files the worker wrote, and say how the job ended."""
        files = job.written
        for name in files["names"] if files else []:
            with open(os.path.join(folder, name), "rb") as f:
                job.files[name] = f.read()
        if job.finished:
            return
        if files is not None:
            job.push("files", files)
        if job.first("error") is None and job.first("result") is None:
            code = job.proc.exitcode
            why = f"signal {-code}" if code is not None and code < 0 else f"exit code {code}"
            job.push("error", {"status": 500, "error": f"the worker process died ({why})"})
        elif job.first("result") is not None and job.request.pictures and files is None:
            job.push(
                "error", {"status": 500, "error": "the plan is ready but its pictures were not finished"}
            )
        job.finish("failed" if job.first("error") is not None else "done")
