"""Issue 25, items 3 and 4: bad input is exit 2 (never 4), a damaged data file is named, and the exit
contract holds everywhere (serve, broken pipes, a bare command, NaN in a team file, the web API)."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
from collections.abc import Iterator
from http.server import BaseHTTPRequestHandler
from pathlib import Path
from typing import Any

import pytest
from http_stub import start_server, stop_server
from pydantic import BaseModel, ValidationError

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import DataError, LLMError
from nl2hltl2plan.language.llm import LLMClient, LLMSettings, extract_json
from nl2hltl2plan.suites.smartllm import smartllm_tasks as smartllm
from nl2hltl2plan.worlds import affordances, team
from nl2hltl2plan.worlds import floor_plans as alfred

ROOT = Path(__file__).parents[2]
PLATES = "put the plates in the lower rack"


def test_robots_superscript_two(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plan", PLATES, "--robots", "²", "--llm", "offline"]) == 2
    assert "unknown robot profile(s) ²" in capsys.readouterr().err


def test_robots_names_longer_than_a_file_name(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plan", PLATES, "--robots", ",".join(["robot1"] * 80), "--llm", "offline"]) == 2
    assert capsys.readouterr().err.startswith("error: --robots names 80 robots; a team has at most 64")


def test_check_a_formula_too_large_for_spot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    spec = tmp_path / "big.json"
    spec.write_text(json.dumps([{"root": " & ".join(f"F p{i}" for i in range(70_000))}]))
    assert main(["check", str(spec)]) == 2
    err = capsys.readouterr().err
    assert "L1 root: formula 'F p0 & F p1" in err and "too large for Spot" in err
    assert main(["check", str(spec), "--json"]) == 2
    out, err = capsys.readouterr()
    assert json.loads(out)["exit"] == 2 and err.startswith("error: L1 root: formula")


class Pair(BaseModel):
    a: int


def test_deeply_nested_llm_answer_is_an_invalid_answer() -> None:
    with pytest.raises(ValueError, match="nests JSON too deeply"):
        extract_json("[" * 200_000)


@pytest.fixture
def brackets_server() -> Iterator[str]:
    """Answers every chat request with 200,000 nested brackets."""
    content = json.dumps("[" * 200_000)
    body = (
        '{"id":"x","object":"chat.completion","created":0,"model":"m","choices":[{"index":0,'
        f'"finish_reason":"stop","message":{{"role":"assistant","content":{content}}}}}]}}'
    ).encode()

    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *a: Any) -> None:
            pass

        def do_POST(self) -> None:  # noqa: N802 - http.server API
            self.rfile.read(int(self.headers.get("Content-Length", 0)))
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

    server = start_server(Handler)
    yield f"http://127.0.0.1:{server.server_address[1]}/v1"
    stop_server(server)


def test_nested_brackets_from_a_server(brackets_server: str, capsys: pytest.CaptureFixture[str]) -> None:
    client = LLMClient(LLMSettings(base_url=brackets_server, api_key="k", max_reasks=1, cache_dir=None))
    with pytest.raises(LLMError, match="no valid answer after 2 attempts .*nests JSON too deeply"):
        client.ask([{"role": "user", "content": "x"}], Pair, "pair")
    argv = [
        "plan",
        PLATES,
        "--llm",
        "openai",
        "--base-url",
        brackets_server,
        "--api-key",
        "k",
        "--cache",
        "off",
    ]
    assert main(argv) == 2
    assert "nests JSON too deeply" in capsys.readouterr().err


@pytest.mark.parametrize(
    "url", ["::::", "localhost:8000", "http://", "ftp://host/v1", "http://h:99999/v1", "http://[::1"]
)
def test_a_base_url_that_is_not_an_http_url(
    url: str, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_BASE_URL", url)
    assert main(["plan", PLATES]) == 2
    err = capsys.readouterr().err
    assert "expected an http:// or https:// URL with a host" in err and "internal error" not in err


# ---------------------------------------------------------------- damaged data files
CACHED = [
    affordances.alfred_affordances,
    alfred.alfred_data,
    alfred.affordance_table,
    alfred.scene_types,
    alfred._free_xz,
    alfred._statics,
    team.smartllm_profiles,
    smartllm.load_tasks,
    smartllm.smartllm_world,
]


@pytest.fixture
def damaged_data(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A data folder of links to the shared data, into which a test writes damaged files."""
    shared = data_dir(required=False)
    if shared is None:
        pytest.skip("needs ../shared/data")
    root = tmp_path / "data"
    real_folders = ("alfred", "alfred/layouts", "smartllm")  # real folders of links: files can be replaced
    for folder in real_folders:  # all made before any link, so no folder is a link into the shared data
        (root / folder).mkdir(parents=True)
    for folder in ("", *real_folders):
        for item in (shared / folder).iterdir():
            if not (root / folder / item.name).exists():
                (root / folder / item.name).symlink_to(item)
    monkeypatch.setenv("NL2HLTL2PLAN_DATA", str(root))
    for f in CACHED:
        f.cache_clear()
    yield root
    for f in CACHED:
        f.cache_clear()


TRUNCATED = b"the real file, cut after 50 kB"


def _damage(path: Path, data: bytes) -> None:
    """Replace the link `path` by a damaged file; never writes through a link into the shared data."""
    assert path.is_symlink() and path.parent.resolve() == path.parent.absolute(), path  # no linked folder
    real = path.resolve()
    path.unlink()  # the link, not the shared file
    path.write_bytes(real.read_bytes()[:50_000] if data == TRUNCATED else data)


def test_a_damaged_trials_file_is_exit_2_naming_it(
    damaged_data: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    _damage(damaged_data / "alfred" / "trials.jsonl.gz", TRUNCATED)
    assert main(["world", "FloorPlan17"]) == 2
    err = capsys.readouterr().err
    assert f"cannot read ALFRED trials file {damaged_data}/alfred/trials.jsonl.gz after line" in err
    assert "damaged (EOFError" in err and "internal error" not in err


@pytest.mark.parametrize(
    "relative, data, load, words",
    [
        ("alfred/trials.jsonl.gz", b"not gzip at all", alfred.alfred_data, "damaged (BadGzipFile"),
        ("alfred/trials.jsonl.gz", b"", alfred.alfred_data, "holds no trial"),
        (
            "alfred/layouts/FloorPlan17-layout.npy",
            b"\x93NUMPY\x01\x00v\x00{'descr'",
            "FloorPlan17",
            "damaged",
        ),
        ("alfred/layouts/FloorPlan17-layout.npy", b"", "FloorPlan17", "damaged (EOFError"),
        ("alfred/layouts/FloorPlan17-objects.json", b'{"bad', "FloorPlan17", "not valid JSON"),
        ("alfred/layouts/FloorPlan17-objects.json", b'{"a": 1}', "FloorPlan17", "expected a JSON list"),
        ("alfred/affordances.json", b"\xff\xfe", affordances.alfred_affordances, "not UTF-8 text"),
        ("alfred/affordances.json", b"[]", affordances.alfred_affordances, "expected a JSON object"),
    ],
)
def test_a_damaged_data_file_is_named(
    damaged_data: Path, relative: str, data: bytes, load: Any, words: str
) -> None:
    _damage(damaged_data / relative, data)
    if load == "FloorPlan17":  # the floor plan's own files
        load = alfred.scene_types if "objects" in relative else alfred._free_xz
        args: tuple[str, ...] = ("FloorPlan17",)
    else:
        args = ()
    with pytest.raises(DataError) as exc:
        load(*args)
    assert str(damaged_data / relative) in str(exc.value) and words in str(exc.value)
    assert "\n" not in str(exc.value)


def test_a_damaged_robot_profiles_file(damaged_data: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _damage(damaged_data / "smartllm" / "robots.json", b"")
    assert main(["plan", PLATES, "--robots", "robot1,robot2", "--llm", "offline"]) == 2
    assert "robots.json: not valid JSON" in capsys.readouterr().err


# ---------------------------------------------------------------- the exit contract
def test_serve_on_a_host_that_is_no_address(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["serve", "--host", "256.1.1.1", "--port", "8765"]) == 2
    assert "cannot listen on --host '256.1.1.1'" in capsys.readouterr().err


def test_serve_on_a_port_in_use(capsys: pytest.CaptureFixture[str]) -> None:
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen(1)
        port = busy.getsockname()[1]
        assert main(["serve", "--port", str(port)]) == 2
    assert f"cannot listen on 127.0.0.1:{port}: Address already in use" in capsys.readouterr().err


def test_a_closed_pipe_ends_quietly() -> None:
    """`nl2hltl2plan spec ... | head -0`: the reader is gone before the first write."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    cmd = [sys.executable, "-m", "nl2hltl2plan", "spec", str(ROOT / "examples" / "dishwasher_htt.json")]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    assert proc.stdout is not None and proc.stderr is not None
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=60) == 141  # 128 + SIGPIPE, as a shell reports a Unix tool cut short
    assert err == ""


def test_a_bare_command_prints_usage_and_one_error_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([]) == 2
    out, err = capsys.readouterr()
    assert out == ""  # usage goes to stderr: nothing for a pipe to mistake for output
    assert err.startswith("usage: nl2hltl2plan")
    assert (
        err.strip().splitlines()[-1].startswith("error: nl2hltl2plan: no command given; choose one of spec")
    )


@pytest.mark.parametrize("value", ["NaN", "Infinity", "-1", "true", '"heavy"'])
def test_a_team_file_mass_must_be_a_finite_positive_number(
    value: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "team.json"
    path.write_text(f'[{{"name": "a", "skills": ["PickupObject", "PutObject"], "mass": {value}}}]')
    assert main(["plan", PLATES, "--robots", str(path), "--llm", "offline"]) == 2
    assert "mass capacity must be a positive number of kg" in capsys.readouterr().err


def test_web_api_robots_must_be_a_number() -> None:
    pytest.importorskip("fastapi")
    from nl2hltl2plan.web.app import PlanRequest

    assert PlanRequest.model_validate({"instruction": PLATES, "robots": 2}).robots == 2
    for bad in (True, "2", 2.0):
        with pytest.raises(ValidationError, match="robots"):
            PlanRequest.model_validate({"instruction": PLATES, "robots": bad})
