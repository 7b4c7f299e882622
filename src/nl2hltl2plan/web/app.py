"""The local web app: type an instruction, pick a world and a team, see the HTT, the hierarchical spec,
the plan on the map (animated in the browser) and its Gantt chart.

Routes (FastAPI; `nl2hltl2plan serve` runs it with uvicorn):

- `GET /` the page (static/index.html);
- `GET /api/worlds` the worlds one can pick; `GET /api/worlds/{name}` a world's geometry for the map;
- `POST /api/plan` with `{"instruction", "world", "robots"}` returns exactly the JSON of `plan --json`
  (`pipeline.Outcome.to_json()`), and its pictures' id in the `X-Outcome-Id` header;
- `GET /api/outcomes/{id}/htt.svg`, `.../gantt.svg`, `.../map.svg` the pictures of a recent outcome.

Bad requests get a 4xx answer `{"error": "one readable sentence"}`. The pipeline and matplotlib are not
thread-safe, so requests are served one at a time (a local, single-user tool).
"""

from __future__ import annotations

import functools
import hashlib
import io
import threading
from collections import OrderedDict
from importlib import resources
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse, JSONResponse, Response
from pydantic import BaseModel, ConfigDict, Field

from nl2hltl2plan.errors import Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.pipeline import Outcome, PipelineOptions, run
from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.model import World

MAX_ROBOTS = 8
KEPT_OUTCOMES = 32  # pictures of this many recent outcomes stay available
BUILT_IN_WORLDS = ("demo", "tabletop", "handover-line", "handover-square")
PICTURES = ("htt", "gantt", "map")


class PlanRequest(BaseModel):
    """The body of POST /api/plan."""

    model_config = ConfigDict(extra="forbid")

    instruction: str = Field(min_length=1, max_length=4000)
    world: str = Field(default="demo", min_length=1, max_length=64)
    robots: int = Field(default=1, ge=1, le=MAX_ROBOTS, strict=True)  # `true` is not 1 robot
    objective: str = Field(default="min", pattern="^(min|minmax)$")
    plan_timeout_s: float = Field(default=60.0, gt=0, le=600)
    partial: bool = False  # plan what was understood of a partly understood instruction (`plan --partial`)


def _error(status: int, message: str) -> JSONResponse:
    return JSONResponse({"error": message}, status_code=status)


@functools.lru_cache(maxsize=1)
def available_worlds() -> list[str]:
    """Built-in worlds this install has, then the ALFRED floor plans when the data is there."""
    names = []
    for name in BUILT_IN_WORLDS:
        try:
            load_world(name)
        except Nl2Hltl2PlanError:
            continue
        names.append(name)
    try:
        from nl2hltl2plan.worlds.alfred import floor_plans

        names += floor_plans()
    except (Nl2Hltl2PlanError, OSError):
        pass
    return names


@functools.lru_cache(maxsize=16)
def _world(name: str) -> World:
    return load_world(name)


def world_geometry(world: World) -> dict[str, Any]:
    """What the page's map needs: cells with their centres (m) and objects with their positions."""
    cells = [[r, c, *world.xz((r, c))] for r, c in sorted(world.cells)]
    objects = [
        {"id": o.id, "type": o.type, "x": o.xz[0], "z": o.xz[1], "movable": o.pickupable}
        for o in world.objects.values()
        if o.present
    ]
    return {"name": world.name, "cell_m": 0.25, "cells": cells, "objects": objects}


def _render(outcome: Outcome, kind: str) -> bytes:
    import matplotlib.pyplot as plt

    from nl2hltl2plan.language.render import htt_figure, htt_orderings
    from nl2hltl2plan.worlds.gantt import draw_gantt
    from nl2hltl2plan.worlds.pictures import draw_execution

    buf = io.BytesIO()
    execution = outcome.result.execution
    if kind == "htt":
        fig = htt_figure(outcome.language.htt)
    elif execution is None:
        raise WorldError(f"no plan to draw: {outcome.status.value}: {outcome.result.reason}")
    elif kind == "gantt":
        fig = draw_gantt(execution, before=htt_orderings(outcome.language.htt))
    else:
        fig = draw_execution(execution)
    fig.savefig(buf, format="svg", bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def create_app() -> FastAPI:
    app = FastAPI(title="nl2hltl2plan", description="Natural language to multi-robot plans")
    lock = threading.Lock()
    outcomes: OrderedDict[str, Outcome] = OrderedDict()

    @app.exception_handler(RequestValidationError)
    async def bad_request(_: Request, exc: RequestValidationError) -> JSONResponse:
        first = exc.errors()[0] if exc.errors() else {}
        where = ".".join(str(p) for p in first.get("loc", ()) if p != "body")
        return _error(
            422, f"{where}: {first.get('msg', 'invalid request')}" if where else first.get("msg", "")
        )

    @app.get("/", response_class=HTMLResponse)
    def index() -> str:
        return resources.files("nl2hltl2plan.web").joinpath("static/index.html").read_text()

    @app.get("/api/worlds")
    def worlds() -> dict[str, Any]:
        return {"worlds": available_worlds(), "max_robots": MAX_ROBOTS}

    @app.get("/api/worlds/{name}", response_model=None)
    def world(name: str) -> dict[str, Any] | JSONResponse:
        try:
            with lock:
                return world_geometry(_world(name))
        except Nl2Hltl2PlanError as exc:
            return _error(404, str(exc))

    @app.post("/api/plan", response_model=None)
    def plan(req: PlanRequest) -> JSONResponse:
        options = PipelineOptions(
            backend="offline",
            objective=req.objective,  # type: ignore[arg-type]  # the pattern admits only min / minmax
            plan_timeout_s=req.plan_timeout_s,
            partial=req.partial,
        )
        try:
            with lock:
                outcome = run(req.instruction, _world(req.world), robots=req.robots, options=options)
                payload = outcome.to_json()
        except WorldError as exc:
            return _error(404 if "unknown world" in str(exc) else 422, str(exc))
        except Nl2Hltl2PlanError as exc:
            return _error(422, str(exc))
        key = hashlib.sha1(repr(sorted(req.model_dump().items())).encode()).hexdigest()[:16]
        outcomes[key] = outcome
        outcomes.move_to_end(key)
        while len(outcomes) > KEPT_OUTCOMES:
            outcomes.popitem(last=False)
        return JSONResponse(payload, headers={"X-Outcome-Id": key})

    @app.get("/api/outcomes/{key}/{picture}.svg", response_model=None)
    def picture(key: str, picture: str) -> Response:
        if picture not in PICTURES:
            return _error(404, f"no picture {picture!r}; pictures are {', '.join(PICTURES)}")
        if key not in outcomes:
            return _error(404, f"no recent outcome {key!r}; POST /api/plan first")
        try:
            with lock:
                svg = _render(outcomes[key], picture)
        except Nl2Hltl2PlanError as exc:
            return _error(409, str(exc))
        return Response(svg, media_type="image/svg+xml")

    return app
