"""The web API on the real pipeline (demo world): same JSON as `plan --json`, pictures, 4xx messages."""

from __future__ import annotations

import json

import pytest

pytest.importorskip("fastapi", reason="the web app needs the [web] extra (fastapi); it is not installed")
pytest.importorskip("httpx", reason="FastAPI's TestClient needs httpx; it is not installed")

from fastapi.testclient import TestClient  # noqa: E402

from nl2hltl2plan.cli.main import main  # noqa: E402
from nl2hltl2plan.web.app import create_app  # noqa: E402

INSTRUCTION = "Put the apple in the fridge. Then put the mug in the cabinet."


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app())


@pytest.fixture(scope="module")
def planned(client):
    res = client.post("/api/plan", json={"instruction": INSTRUCTION, "world": "demo", "robots": 2})
    assert res.status_code == 200, res.text
    return res


def test_plan_returns_the_json_of_plan_json(planned, capsys):
    assert main(["plan", INSTRUCTION, "--world", "demo", "--robots", "2", "--llm", "offline", "--json"]) == 0
    cli = json.loads(capsys.readouterr().out)
    api = planned.json()
    volatile = {"plan_time_s", "expanded", "generated"}  # timings and search counters may differ
    for out in (cli, api):
        for key in volatile:
            out["planner"].pop(key, None)
    assert api == cli
    assert api["status"] == "solved" and len(api["plan"]["robots"]) == 2


def test_pictures_of_the_outcome(client, planned):
    key = planned.headers["X-Outcome-Id"]
    for name in ("htt", "gantt", "map"):
        res = client.get(f"/api/outcomes/{key}/{name}.svg")
        assert res.status_code == 200 and res.headers["content-type"].startswith("image/svg+xml")
        assert b"<svg" in res.content[:500]
    gantt = client.get(f"/api/outcomes/{key}/gantt.svg").text
    assert "robot 1" in gantt and "task1.1" in gantt
    assert client.get(f"/api/outcomes/{key}/video.svg").status_code == 404
    assert "POST /api/plan first" in client.get("/api/outcomes/nope/htt.svg").json()["error"]


def test_page_and_worlds(client):
    page = client.get("/")
    assert page.status_code == 200 and 'id="instruction"' in page.text
    worlds = client.get("/api/worlds").json()["worlds"]
    assert worlds[0] == "demo"
    geo = client.get("/api/worlds/demo").json()
    assert len(geo["cells"]) == 132 and any(o["id"] == "Fridge_0" for o in geo["objects"])
    assert client.get("/api/worlds/Kitchen").status_code == 404


@pytest.mark.parametrize(
    "body, status, message",
    [
        (
            {"instruction": "", "world": "demo", "robots": 1},
            422,
            "instruction: String should have at least 1",
        ),
        (
            {"instruction": INSTRUCTION, "robots": 0},
            422,
            "robots: Input should be greater than or equal to 1",
        ),
        ({"instruction": INSTRUCTION, "robots": 99}, 422, "robots: Input should be less than or equal to 8"),
        ({"world": "demo"}, 422, "instruction: Field required"),
        ({"instruction": INSTRUCTION, "colour": "red"}, 422, "colour: Extra inputs are not permitted"),
        ({"instruction": "put the statue in the fridge"}, 422, "no Statue in demo"),
        ({"instruction": INSTRUCTION, "world": "Kitchen"}, 404, "unknown world 'Kitchen'"),
    ],
)
def test_bad_requests_get_a_message(client, body, status, message):
    res = client.post("/api/plan", json=body)
    assert res.status_code == status
    assert message in res.json()["error"]


def test_not_json(client):
    res = client.post("/api/plan", content=b"{not json", headers={"content-type": "application/json"})
    assert res.status_code == 422 and res.json()["error"]


def test_serve_command_starts_uvicorn_with_the_app_factory(monkeypatch, capsys):
    import uvicorn

    calls = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: calls.append((app, kw)))
    assert main(["serve", "--port", "8123"]) == 0
    ((app, kw),) = calls
    assert kw == {"factory": True, "host": "127.0.0.1", "port": 8123, "log_level": "warning"}
    module, name = app.split(":")
    assert getattr(__import__(module, fromlist=[name]), name) is create_app
    assert "http://127.0.0.1:8123/" in capsys.readouterr().out


def test_serve_command_errors(monkeypatch, capsys):
    import importlib.util

    assert main(["serve", "--port", "0"]) == 2
    assert "between 1 and 65535" in capsys.readouterr().err
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda n, *a: None if n == "fastapi" else real(n, *a))
    assert main(["serve"]) == 2
    assert "pip install 'nl2hltl2plan[web]'" in capsys.readouterr().err


def test_a_partly_understood_instruction_is_refused_unless_partial_is_asked(client):
    body = {"instruction": "put the apple in the fridge and make some tea", "world": "demo", "robots": 1}
    refused = client.post("/api/plan", json=body)
    assert refused.status_code == 422 and "'make' (action)" in refused.json()["error"]
    partial = client.post("/api/plan", json={**body, "partial": True})
    assert partial.status_code == 200 and partial.json()["partial"] is True
