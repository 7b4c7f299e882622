"""Load test on 127.0.0.1: a long plan holds the worker while short plans queue and light requests
come in. Light requests stay fast (they never wait behind a plan), and every client gets the answer
to its own request."""

from __future__ import annotations

import json
import time

import pytest

pytest.importorskip("fastapi", reason="the web app needs the [web] extra (fastapi); it is not installed")
uvicorn = pytest.importorskip("uvicorn", reason="the web app needs uvicorn; it is not installed")

from serving import served  # noqa: E402

from nl2hltl2plan.web.app import create_app  # noqa: E402
from nl2hltl2plan.web.load import run_load  # noqa: E402


@pytest.fixture(scope="module")
def url():
    with served(create_app(workers=1, queue=8)) as base:  # one CPU: the suite's other worker keeps one
        yield base


def test_light_requests_stay_fast_and_answers_stay_with_their_clients(url):
    report = run_load(url, clients=4, slow=1, slow_s=2.0)
    summary = report.summary()
    assert report.problems == []
    assert report.plans == 4
    assert summary["light_requests"] >= 10
    # one plan at a time made a world-geometry request wait 8 s behind a plan; now none waits for
    # one: measured against the plans of the same run (a ratio holds on a loaded machine too)
    assert summary["light_s"]["p95"] < 0.25 * summary["plan_s"]["median"], summary


def test_a_client_that_goes_away_cancels_its_job(url):
    from nl2hltl2plan.web.load import SLOW, Client

    body = {"instruction": SLOW, "robots": 5, "mode": "exact", "pictures": False, "timeout_s": 60}
    with Client(url, timeout=30) as c:
        stream = Client(url, timeout=30)
        stream.conn.request(
            "POST", "/api/plan/stream", body=json.dumps(body), headers={"Content-Type": "application/json"}
        )
        res = stream.conn.getresponse()
        line = b"start"
        while line and b'"stage": "planning"' not in line:
            line = res.readline()
        assert line, "the stream ended before the search started"
        stream.conn.close()  # the search runs: hang up
        deadline = time.time() + 10  # the search alone would run for half a minute
        while c.get("/api/status").json()["running"]:
            assert time.time() < deadline, "the job still runs after its client went away"
            time.sleep(0.1)
