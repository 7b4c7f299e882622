"""Imported once by the web server's fork server (`jobs.PRELOAD`), after the pipeline: it reads and
plans one small demo instruction there, so that every request forked from it finds the reader's
compiled patterns, word lists and models and the demo world already loaded instead of loading them
again (about 0.25 s of each request's CPU here, a quarter of a light request's time)."""

from __future__ import annotations

import contextlib

from nl2hltl2plan.web.requests import PlanRequest
from nl2hltl2plan.web.worker import plan_request

WARM_UP = "Put the apple in the fridge. Then put the mug in the cabinet."

# A failure here only loses the head start: the request that needs the part will load it itself.
with contextlib.suppress(Exception):
    plan_request(PlanRequest(instruction=WARM_UP, world="demo", robots=2, pictures=False))
