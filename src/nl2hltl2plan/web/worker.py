"""One plan request in a worker process: the pipeline, its progress and its files, sent to the server.

The server (`web.jobs`) starts `work` in a fresh process forked from a preloaded fork server, so a
request starts in milliseconds with the pipeline already imported, and cancelling it is killing it.
Everything goes back over the pipe as `(event, data)` pairs, in this order:

- `progress` (many): a `pipeline.Progress` with `elapsed_s`;
- `result` (once): the JSON of `plan --json`;
- `files` (once, with pictures on): the names written into the job's folder, and warnings;
- or `error` instead: `{"status": 4xx/5xx, "error": one sentence}`.
"""

from __future__ import annotations

import os
import signal
import time
from multiprocessing.connection import Connection
from typing import Any

from nl2hltl2plan.deadline import describe_exception, die_with_parent, limit_memory
from nl2hltl2plan.errors import Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.pipeline import Outcome, PipelineOptions, Progress, run
from nl2hltl2plan.web.requests import PlanRequest
from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.team import Team, smartllm_profiles, team_from_json

MEMORY_MB = 3000  # address space a request may add (the planner's node limit stays below it)
PLAN_SHARE = 0.6  # of the time left, the planner's own limit (the rest: pictures, a loaded machine)
GRACE_S = 3.0  # the worker ends itself this long after the deadline, should the server not


def team_of(req: PlanRequest) -> Team:
    """The request's team (a number, SMART-LLM profile names or a team file's content)."""
    if req.team is not None:
        return team_from_json(req.team, "team file")
    if req.profiles is not None:
        profiles = smartllm_profiles()
        unknown = [n for n in req.profiles if n not in profiles]
        if unknown:
            raise WorldError(
                f"unknown robot profile(s) {', '.join(unknown)}; use robot1..robot{len(profiles)}"
            )
        return Team.of([profiles[n] for n in req.profiles])
    return Team(req.robots)


def plan_request(req: PlanRequest, on_progress: Any = None) -> Outcome:
    """Run the pipeline for one request (in this process)."""
    from nl2hltl2plan.config.llm_settings import LLMSettings
    from nl2hltl2plan.language.backends import open_client

    options = PipelineOptions(
        backend=req.backend,
        objective=req.objective,
        mode=req.mode,
        plan_timeout_s=req.timeout_s * PLAN_SHARE,
        choices=req.choices,
        partial=req.partial,
        plurals=req.plurals,
    )
    world = load_world(req.world)
    team = team_of(req)
    count = [0]

    def on_request(name: str) -> None:  # an LLM request: said in the language stage's words
        count[0] += 1
        if on_progress is not None:
            on_progress(Progress(stage="language", detail=f"asking the LLM: {name} (request {count[0]})"))

    with open_client(req.backend, LLMSettings(), on_request=on_request) as client:
        return run(req.instruction, world, team, options, client, progress=on_progress)


def error_status(exc: BaseException) -> int:
    """404 for a world that does not exist, 422 for other input the pipeline refuses, 500 for a bug."""
    if isinstance(exc, WorldError) and "unknown world" in str(exc):
        return 404
    return 422 if isinstance(exc, Nl2Hltl2PlanError) else 500


def work(body: dict[str, Any], folder: str, conn: Connection) -> None:
    """The worker process's main: plan, send the events, write the files into `folder`."""
    die_with_parent(os.getppid())  # the fork server, which ends with the web server
    req = PlanRequest.model_validate(body)
    signal.alarm(int(req.timeout_s + GRACE_S) + 1)  # a last resort: SIGALRM ends the process
    limit_memory(MEMORY_MB)
    started = time.monotonic()

    def send_progress(p: Progress) -> None:
        conn.send(("progress", {**p.model_dump(), "elapsed_s": round(time.monotonic() - started, 2)}))

    try:
        outcome = plan_request(req, send_progress)
        payload = outcome.to_json()
        conn.send(("result", payload))
        if req.pictures:
            from nl2hltl2plan.present.outputs import output_names, write_outputs

            warnings = write_outputs(folder, outcome, payload)
            names = [n for n in output_names(outcome.result.execution is not None) if os.path.exists(
                os.path.join(folder, n))]  # fmt: skip
            conn.send(("files", {"names": names, "warnings": warnings}))
    except MemoryError:
        conn.send(("error", {"status": 507, "error": f"the request ran out of memory ({MEMORY_MB} MiB)"}))
    except Exception as exc:  # every failure goes back as one sentence; none is a traceback
        conn.send(("error", {"status": error_status(exc), "error": describe_exception(exc)}))
    finally:
        conn.close()
