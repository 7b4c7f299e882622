"""The local web app: type an instruction, choose a world, a team and the planner's options, watch it
being planned, and take the HTT, the spec, the plan, its pictures and its files away (docs/web.md).

Routes (FastAPI; `nl2hltl2plan serve` runs it with uvicorn; the Swagger page is `/docs`):

- `GET /` the page; `GET /api/options` the worlds, teams, objectives, modes, backends, limits and
  example instructions; `GET /api/worlds/{name}` a world's geometry; `.../map.svg` its picture;
- `POST /api/plan` (a `PlanRequest`) answers with the JSON of `plan --json`, its job id in the
  `X-Outcome-Id` header; `POST /api/plan/stream` answers the same request as Server-Sent Events:
  `job`, `progress` (each stage, then the search's expansions and costs so far), `result`, `files`,
  `error`, and last `done`;
- `GET /api/jobs/{id}/files/{name}` one file of a finished job (`result.json`, `spec.json`,
  `spec.hoa`, `htt|world|plan|gantt.png|svg`), `GET /api/jobs/{id}/files.zip` all of them;
  `DELETE /api/jobs/{id}` cancels a job; `GET /api/status` the workers and the queue.

Plans run in worker processes (`web.jobs`): a full queue is a 503 with Retry-After, a request past
its deadline a 504, a client that goes away cancels its job, and a body over MAX_BODY_BYTES is a 413.
Every error is `{"error": "one readable sentence"}`.
"""

from __future__ import annotations

import asyncio
import functools
import io
import json
import zipfile
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from importlib import resources
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse, JSONResponse, Response, StreamingResponse

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.web import maps
from nl2hltl2plan.web.jobs import Busy, Job, Jobs
from nl2hltl2plan.web.requests import (
    DEFAULT_TIMEOUT_S,
    MAX_INSTRUCTION,
    MAX_ROBOTS,
    MAX_TIMEOUT_S,
    WEB_BACKENDS,
    PlanRequest,
)
from nl2hltl2plan.worlds import BUILT_IN

BUILT_IN_WORLDS = tuple(BUILT_IN)  # demo, tabletop, handover-line, handover-square
MAX_BODY_BYTES = 256 * 1024  # a request is an instruction, options and at most a small team file
RETRY_AFTER_S = 5
MEDIA = {"json": "application/json", "hoa": "text/plain; charset=utf-8", "png": "image/png",
         "svg": "image/svg+xml"}  # fmt: skip


def _error(status: int, message: str, headers: dict[str, str] | None = None) -> JSONResponse:
    return JSONResponse({"error": message}, status_code=status, headers=headers)


class BodyLimit:
    """ASGI middleware: a body over `max_bytes` gets 413 before the app reads it (a declared length
    at once; a chunked body as soon as it grows past the limit)."""

    def __init__(self, app: Any, max_bytes: int) -> None:
        self.app, self.max_bytes = app, max_bytes

    def _too_large(self) -> JSONResponse:
        return _error(413, f"the request body is larger than {self.max_bytes} bytes")

    async def __call__(self, scope: dict[str, Any], receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        declared = dict(scope["headers"]).get(b"content-length")
        if declared is not None:
            if not declared.isdigit() or int(declared) > self.max_bytes:
                return await self._too_large()(scope, receive, send)
            return await self.app(scope, receive, send)
        body, more = b"", True
        while more:  # no length given: read at most max_bytes, then hand the body on
            message = await receive()
            if message["type"] != "http.request":
                return
            body += message.get("body", b"")
            if len(body) > self.max_bytes:
                return await self._too_large()(scope, receive, send)
            more = message.get("more_body", False)
        replayed = False

        async def replay() -> dict[str, Any]:
            nonlocal replayed
            if not replayed:
                replayed = True
                return {"type": "http.request", "body": body, "more_body": False}
            return dict(await receive())

        await self.app(scope, replay, send)


@functools.lru_cache(maxsize=1)
def available_worlds() -> list[str]:
    """Built-in worlds this install has, then the ALFRED floor plans when the data is there."""
    names = []
    for name in BUILT_IN_WORLDS:
        try:
            maps.cached_world(name)
        except Nl2Hltl2PlanError:
            continue
        names.append(name)
    try:
        from nl2hltl2plan.worlds.floor_plans import floor_plans

        names += floor_plans()
    except (Nl2Hltl2PlanError, OSError):
        pass
    return names


@functools.lru_cache(maxsize=1)
def options() -> dict[str, Any]:
    """Every choice the page offers (the same as `plan`'s options) and the example instructions."""
    try:
        from nl2hltl2plan.worlds.team import smartllm_profiles

        profiles = {name: sorted(p.skills) for name, p in smartllm_profiles().items()}
    except (Nl2Hltl2PlanError, OSError):
        profiles = {}
    worlds = available_worlds()
    examples = json.loads(resources.files("nl2hltl2plan.web").joinpath("examples.json").read_text())
    return {
        "worlds": worlds,
        "examples": {w: e for w, e in examples.items() if w in worlds},
        "max_robots": MAX_ROBOTS,
        "profiles": profiles,
        "objectives": {"min": "summed travel and actions (the paper's cost)", "minmax": "completion time"},
        "modes": {"fast": "anytime, with a proven bound", "exact": "proven optimal"},
        "backends": list(WEB_BACKENDS),
        "timeout_s": {"default": DEFAULT_TIMEOUT_S, "max": MAX_TIMEOUT_S},
        "max_instruction": MAX_INSTRUCTION,
        "max_body_bytes": MAX_BODY_BYTES,
    }


def _sse(kind: str, data: dict[str, Any]) -> str:
    return f"event: {kind}\ndata: {json.dumps(data, default=str)}\n\n"


def _zip(job: Job) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in job.files.items():
            z.writestr(f"nl2hltl2plan-{job.id}/{name}", data)
    return buf.getvalue()


def create_app(workers: int | None = None, queue: int = 8) -> FastAPI:
    """The app; `workers` plans run at once (default: one per CPU), `queue` more may wait."""
    jobs = Jobs(workers, queue)

    @asynccontextmanager
    async def lifespan(_: FastAPI) -> AsyncIterator[None]:
        await asyncio.to_thread(jobs.warm_up)
        await asyncio.to_thread(maps.world_map, "demo")  # the page's first map, drawn before anyone waits
        yield
        jobs.close()

    app = FastAPI(
        title="nl2hltl2plan", description="Natural language to multi-robot plans", lifespan=lifespan
    )
    app.add_middleware(BodyLimit, max_bytes=MAX_BODY_BYTES)
    app.state.jobs = jobs

    @app.exception_handler(RequestValidationError)
    async def bad_request(_: Request, exc: RequestValidationError) -> JSONResponse:
        first = exc.errors()[0] if exc.errors() else {}
        where = ".".join(str(p) for p in first.get("loc", ()) if p != "body")
        message = str(first.get("msg", "invalid request")).removeprefix("Value error, ")
        return _error(422, f"{where}: {message}" if where else message)

    _page_routes(app)
    _plan_routes(app, jobs)
    _job_routes(app, jobs)
    return app


def _page_routes(app: FastAPI) -> None:
    """The page, the choices it offers and the worlds it draws."""

    @app.get("/", response_class=HTMLResponse)
    def index() -> str:
        return resources.files("nl2hltl2plan.web").joinpath("static/index.html").read_text()

    @app.get("/api/worlds")
    def worlds() -> dict[str, Any]:
        return {"worlds": available_worlds(), "max_robots": MAX_ROBOTS}

    @app.get("/api/options")
    def choices() -> dict[str, Any]:
        return options()

    @app.get("/api/worlds/{name}", response_model=None)
    async def world(name: str) -> dict[str, Any] | JSONResponse:
        try:
            geo = maps.geometry(maps.cached_world(name))
        except Nl2Hltl2PlanError as exc:
            return _error(404, str(exc))
        geo["frame"] = (await asyncio.to_thread(maps.world_map, name))[1]
        return geo

    @app.get("/api/worlds/{name}/map.svg", response_model=None)
    async def world_picture(name: str) -> Response:
        try:
            svg, _ = await asyncio.to_thread(maps.world_map, name)
        except Nl2Hltl2PlanError as exc:
            return _error(404, str(exc))
        return Response(svg, media_type=MEDIA["svg"], headers={"Cache-Control": "max-age=3600"})


def _plan_routes(app: FastAPI, jobs: Jobs) -> None:
    """Planning: a JSON answer or an event stream, each a job in a worker process."""

    @app.get("/api/status")
    async def status() -> dict[str, int]:
        return jobs.counts()

    def submit(req: PlanRequest) -> Job | JSONResponse:
        try:
            return jobs.submit(req)
        except Busy as exc:
            return _error(503, str(exc), {"Retry-After": str(RETRY_AFTER_S)})

    @app.post("/api/plan", response_model=None)
    async def plan(req: PlanRequest, request: Request) -> JSONResponse:
        job = submit(req)
        if isinstance(job, JSONResponse):
            return job
        async for event in job.follow():
            if event is None and await request.is_disconnected():
                jobs.cancel(job)
                return _error(499, "the client went away; the job was cancelled")
        error, result = job.first("error"), job.first("result")
        if error is not None and result is None:
            return _error(int(error["status"]), str(error["error"]))
        if result is None:
            return _error(499, "the job was cancelled")
        return JSONResponse(result, headers={"X-Outcome-Id": job.id})

    @app.post("/api/plan/stream", response_model=None)
    async def plan_stream(req: PlanRequest, request: Request) -> Response:
        job = submit(req)
        if isinstance(job, JSONResponse):
            return job

        async def events() -> AsyncIterator[str]:
            try:
                yield _sse("job", {"id": job.id, **jobs.counts()})
                async for event in job.follow():
                    if event is None:
                        if await request.is_disconnected():
                            return
                        yield ": waiting\n\n"  # a comment line: keeps proxies from timing out
                    else:
                        yield _sse(*event)
            finally:
                jobs.cancel(job)  # a no-op for a finished job; a client that left cancels its job

        return StreamingResponse(
            events(), media_type="text/event-stream", headers={"Cache-Control": "no-store"}
        )


def _job_routes(app: FastAPI, jobs: Jobs) -> None:
    """A recent job's files, and cancelling it."""

    @app.delete("/api/jobs/{job_id}", response_model=None)
    async def cancel(job_id: str) -> JSONResponse:  # in the event loop, where jobs change state
        job = jobs.get(job_id)
        if job is None:
            return _error(404, f"no recent job {job_id!r}")
        jobs.cancel(job)
        return JSONResponse({"id": job.id, "state": job.state})

    @app.get("/api/jobs/{job_id}/files.zip", response_model=None)
    async def bundle(job_id: str) -> Response:
        job = jobs.get(job_id)
        if job is None or not job.files:
            return _error(404, f"no files for job {job_id!r} (a recent job that planned with pictures on)")
        disposition = f'attachment; filename="nl2hltl2plan-{job.id}.zip"'
        data = await asyncio.to_thread(_zip, job)  # compressing: off the event loop
        return Response(data, media_type="application/zip", headers={"Content-Disposition": disposition})

    @app.get("/api/jobs/{job_id}/files/{name}", response_model=None)
    async def file(job_id: str, name: str) -> Response:
        job = jobs.get(job_id)
        if job is None:
            return _error(404, f"no recent job {job_id!r}; POST /api/plan first")
        if name not in job.files:
            have = ", ".join(job.files) or "none yet"
            return _error(404, f"job {job_id} has no file {name!r} (files: {have})")
        return Response(job.files[name], media_type=MEDIA[name.rsplit(".", 1)[-1]])
