"""The web API on the real pipeline (demo world): the JSON of `plan --json`, the files of `plan -o`,
the event stream, cancel, deadlines, a full queue, body limits and 4xx messages."""

from __future__ import annotations

import io
import json
import re
import threading
import time
import zipfile

import pytest

pytest.importorskip("fastapi", reason="the web app needs the [web] extra (fastapi); it is not installed")
pytest.importorskip("httpx", reason="FastAPI's TestClient needs httpx; it is not installed")

from fastapi.testclient import TestClient  # noqa: E402

from nl2hltl2plan.cli.main import main  # noqa: E402
from nl2hltl2plan.web.app import create_app  # noqa: E402

INSTRUCTION = "Put the apple in the fridge. Then put the mug in the cabinet."
# five robots, exact mode: a search that does not prove its optimum for a long while
HARD = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack."
)


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app(workers=1, queue=1)) as c:  # one CPU: the suite's other worker keeps one
        yield c


@pytest.fixture(scope="module")
def planned(client):
    res = client.post("/api/plan", json={"instruction": INSTRUCTION, "world": "demo", "robots": 2})
    assert res.status_code == 200, res.text
    return res


def events(client, body) -> list[tuple[str, dict]]:
    out = []
    with client.stream("POST", "/api/plan/stream", json=body) as res:
        assert res.status_code == 200 and res.headers["content-type"].startswith("text/event-stream")
        kind = None
        for line in res.iter_lines():
            if line.startswith("event: "):
                kind = line[7:]
            elif line.startswith("data: "):
                out.append((kind, json.loads(line[6:])))
    return out


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


def test_downloads_are_the_files_of_plan_o(client, planned):
    from nl2hltl2plan.present.outputs import output_names

    written = sorted(output_names(has_plan=True))  # `plan -o` writes these (tests/language/test_pipeline_cli)
    key = planned.headers["X-Outcome-Id"]
    bundle = zipfile.ZipFile(io.BytesIO(client.get(f"/api/jobs/{key}/files.zip").content))
    assert sorted(n.split("/", 1)[1] for n in bundle.namelist()) == written
    assert {"result.json", "spec.json", "spec.hoa", "gantt.svg", "plan.png", "htt.svg"} <= set(written)
    for name in written:
        res = client.get(f"/api/jobs/{key}/files/{name}")
        assert res.status_code == 200 and len(res.content) > 100, name
    assert client.get(f"/api/jobs/{key}/files/gantt.svg").headers["content-type"].startswith("image/svg+xml")
    assert client.get(f"/api/jobs/{key}/files/spec.hoa").text.startswith("HOA: v1")
    assert json.loads(client.get(f"/api/jobs/{key}/files/result.json").text)["status"] == "solved"
    assert "files:" in client.get(f"/api/jobs/{key}/files/video.svg").json()["error"]
    assert "POST /api/plan first" in client.get("/api/jobs/nope/files/htt.svg").json()["error"]


def test_progress_streams_each_stage_in_order(client):
    got = events(client, {"instruction": INSTRUCTION, "robots": 2, "pictures": False})
    kinds = [k for k, _ in got]
    assert kinds[0] == "job" and kinds[-2:] == ["result", "done"] and got[-1][1]["state"] == "done"
    stages = [d["stage"] for k, d in got if k == "progress"]
    order = ["language", "specification", "planning", "execution"]
    assert sorted(set(stages), key=order.index) == order
    assert stages == sorted(stages, key=order.index)  # never back to an earlier stage
    planning = [d for k, d in got if k == "progress" and d["expanded"] is not None]
    assert planning and planning[-1]["best_cost"] == got[-2][1]["planner"]["cost"]
    elapsed = [d["elapsed_s"] for k, d in got if k == "progress"]
    assert elapsed == sorted(elapsed)


def test_an_ambiguity_choice_replans(client):
    free = client.post(
        "/api/plan", json={"instruction": "Put the utensils in the lower rack.", "pictures": False}
    )
    (amb,) = free.json()["ambiguities"]
    pick = amb["candidates"][1]  # not the top-ranked one, which is used when nobody chooses
    chosen = client.post(
        "/api/plan",
        json={"instruction": "Put the utensils in the lower rack.", "pictures": False,
              "choices": {f"{amb['task']}.{amb['role']}": pick}},
    )  # fmt: skip
    picked = {o for r in chosen.json()["plan"]["robots"] for s in r["steps"] for o in s["objects"]}
    assert any(o.startswith(pick + "_") for o in picked)
    assert chosen.json()["tasks"][0][amb["role"]] == [pick]


def test_deadline_and_cancel_end_the_worker(client):
    slow = {"instruction": HARD, "robots": 5, "mode": "exact", "pictures": False}
    started = time.monotonic()
    res = client.post("/api/plan", json={**slow, "timeout_s": 1.5})
    assert time.monotonic() - started < 10  # not the minute the search would take
    assert res.status_code in (200, 504), res.text
    if res.status_code == 200:  # the planner's own limit (a share of the deadline) came first
        assert res.json()["planner"]["stopped"] == "timeout"
    else:
        assert "ran past its deadline of 1.5 s" in res.json()["error"]
    got = []
    with client.stream("POST", "/api/plan/stream", json={**slow, "timeout_s": 60}) as stream:
        for line in stream.iter_lines():
            if line.startswith("data: ") and '"id"' in line and not got:
                got.append(json.loads(line[6:])["id"])
            if '"stage": "planning"' in line:
                assert client.delete(f"/api/jobs/{got[0]}").json()["state"] == "cancelled"
            if line.startswith("event: done"):
                break
    assert client.get("/api/status").json()["running"] == 0


def test_a_full_queue_is_a_503(client):
    slow = {"instruction": HARD, "robots": 5, "mode": "exact", "pictures": False, "timeout_s": 30}
    codes: list[int] = []
    threads = [threading.Thread(target=lambda: codes.append(client.post("/api/plan", json=slow).status_code))
               for _ in range(2)]  # fmt: skip
    for t in threads:
        t.start()
    try:
        deadline = time.monotonic() + 60
        while sum(client.get("/api/status").json()[k] for k in ("running", "waiting")) < 2:  # 1 + 1 queued
            assert time.monotonic() < deadline, "the jobs did not start"
            time.sleep(0.05)
        busy = client.post("/api/plan", json=slow)
        assert busy.status_code == 503 and busy.headers["Retry-After"]
        # a job between the queue and its worker may count as waiting for a moment: the limit is what matters
        assert re.search(r"the server is busy: \d plan\(s\) running and \d waiting \(at most 1 \+ 1\)",
                         busy.json()["error"])
    finally:
        for job_id in list(client.app.state.jobs.jobs):
            client.delete(f"/api/jobs/{job_id}")
        for t in threads:
            t.join(30)
    assert codes == [499, 499]  # each client hears that its job was cancelled
    assert client.get("/api/status").json() == {"workers": 1, "queue": 1, "running": 0, "waiting": 0}


def test_page_options_and_worlds(client):
    page = client.get("/")
    assert page.status_code == 200 and 'id="instruction"' in page.text and "/docs" in page.text
    opts = client.get("/api/options").json()
    assert opts["worlds"][0] == "demo" and set(opts["objectives"]) == {"min", "minmax"}
    assert opts["examples"]["demo"] and opts["modes"].keys() == {"fast", "exact"}
    geo = client.get("/api/worlds/demo").json()
    assert len(geo["cells"]) == 132 and any(
        o["id"] == "Fridge_0" and "closed" in o["state"] for o in geo["objects"]
    )
    frame = geo["frame"]
    assert 0 < frame["left"] < frame["right"] < 1 and 0 < frame["top"] < frame["bottom"] < 1
    assert client.get("/api/worlds/demo/map.svg").text.lstrip().startswith("<?xml")
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
        ({"instruction": INSTRUCTION, "robots": True}, 422, "robots: Input should be a valid integer"),
        ({"world": "demo"}, 422, "instruction: Field required"),
        ({"instruction": INSTRUCTION, "colour": "red"}, 422, "colour: Extra inputs are not permitted"),
        ({"instruction": INSTRUCTION, "timeout_s": 601}, 422, "timeout_s: Input should be less than"),
        ({"instruction": INSTRUCTION, "profiles": ["robot1"], "team": ["robot1"]}, 422, "not both"),
        (
            {"instruction": INSTRUCTION, "team": [{"name": "r", "skills": ["Fly"]}]},
            422,
            "unknown skill(s) Fly",
        ),
        ({"instruction": "put the statue in the fridge"}, 422, "no Statue in demo"),
        ({"instruction": INSTRUCTION, "world": "Kitchen"}, 404, "unknown world 'Kitchen'"),
    ],
)
def test_bad_requests_get_a_message(client, body, status, message):
    res = client.post("/api/plan", json={**body, "pictures": False} if "instruction" in body else body)
    assert res.status_code == status
    assert message in res.json()["error"]


def test_bodies_not_json_or_too_large(client):
    res = client.post("/api/plan", content=b"{not json", headers={"content-type": "application/json"})
    assert res.status_code == 422 and res.json()["error"]
    big = b'{"instruction": "' + b"a" * 300_000 + b'"}'
    res = client.post("/api/plan", content=big, headers={"content-type": "application/json"})
    assert res.status_code == 413 and "larger than" in res.json()["error"]
    chunked = client.post("/api/plan", content=iter([big[:150_000], big[150_000:]]),
                          headers={"content-type": "application/json"})  # fmt: skip
    assert chunked.status_code == 413


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
    body = {"instruction": "put the apple in the fridge and make some tea", "world": "demo", "robots": 1,
            "pictures": False}  # the JSON is what is checked here: no pictures (about 3 s of CPU a plan)
    refused = client.post("/api/plan", json=body)
    assert refused.status_code == 422 and "'make' (action)" in refused.json()["error"]
    partial = client.post("/api/plan", json={**body, "partial": True})
    assert partial.status_code == 200 and partial.json()["partial"] is True


def test_every_example_is_understood():
    from nl2hltl2plan.pipeline import language_stage
    from nl2hltl2plan.web.app import BUILT_IN_WORLDS, options
    from nl2hltl2plan.web.maps import cached_world

    examples = {w: e for w, e in options()["examples"].items() if w in BUILT_IN_WORLDS}  # no data needed
    assert set(examples) == set(BUILT_IN_WORLDS)
    for world, instructions in examples.items():
        for text in instructions:
            lang = language_stage(text, cached_world(world))
            assert lang.spec is not None and not lang.unparsed, (world, text)


def test_a_negation_comes_back_as_a_constraint(client):
    body = {"instruction": "put the apple in the fridge but never open the microwave", "world": "demo",
            "pictures": False}
    res = client.post("/api/plan", json=body)
    assert res.status_code == 200, res.text
    out = res.json()
    assert out["status"] == "solved"
    assert out["constraints"] == ['never open the microwave: G!"open(Microwave)"']
