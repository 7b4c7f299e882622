"""Issue 25, item 2: no hang. FIFOs and other non-regular files are refused before opening, instructions
are capped at 2,000 characters, every count and time option is bounded, and an LLM server that never
answers, trickles, or asks to come back in an hour is reported within the instruction's deadline."""

from __future__ import annotations

import os
import signal
import socket
import time
from collections.abc import Iterator
from http.server import BaseHTTPRequestHandler
from pathlib import Path
from typing import Any

import pytest
from http_stub import start_server, stop_server
from pydantic import BaseModel

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import HTTError, LLMError
from nl2hltl2plan.language.llm import LLMClient, LLMSettings
from nl2hltl2plan.language.translate import MAX_INSTRUCTION_CHARS, translate
from nl2hltl2plan.worlds.demo import demo_world

HTT = str(Path(__file__).parents[2] / "examples" / "dishwasher_htt.json")
PLATES = "put the plates in the lower rack"


@pytest.fixture
def deadline() -> Iterator[None]:
    """Fail the test (instead of hanging the suite) if it blocks for 20 s: a FIFO open would."""

    def stop(*_: Any) -> None:
        raise TimeoutError("blocked for 20 s")

    old = signal.signal(signal.SIGALRM, stop)
    signal.alarm(20)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, old)


@pytest.fixture
def fifo(tmp_path: Path) -> Path:
    path = tmp_path / "input.json"
    os.mkfifo(path)
    return path


@pytest.mark.parametrize(
    "argv",
    [
        ["spec", "{fifo}"],
        ["check", "{fifo}"],
        ["show", "{fifo}", "-o", "{tmp}/x.png"],
        ["plan", PLATES, "--robots", "{fifo}"],
        [
            "plan",
            PLATES,
            "--llm",
            "openai",
            "--base-url",
            "http://127.0.0.1:9/v1",
            "--batch-answers",
            "{fifo}",
        ],
        ["bench", "alfred", "--oracle", "--gt", "{fifo}", "-o", "{tmp}/b", "--quiet"],
        ["bench", "smartllm", "--oracle", "--masses", "{fifo}", "-o", "{tmp}/s", "--quiet"],
    ],
    ids=["spec", "check", "show", "robots", "batch-answers", "bench-gt", "masses"],
)
def test_a_fifo_is_refused_before_opening(
    argv: list[str], fifo: Path, tmp_path: Path, deadline: None, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main([a.format(fifo=fifo, tmp=tmp_path) for a in argv]) == 2
    err = capsys.readouterr().err
    assert f"{fifo}: it is a FIFO (named pipe), not a regular file" in err


def test_devices_and_folders_are_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "/dev/null"]) == 2
    assert main(["spec", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "it is a character device, not a regular file" in err and "it is a folder" in err


def test_the_instruction_is_capped() -> None:
    world = demo_world()
    # "a plate" each time: "put the plate ..." said again is the one task (`restated_tasks`)
    longest = "Put a plate into the lower rack. " * (MAX_INSTRUCTION_CHARS // 33)
    assert len(longest) <= MAX_INSTRUCTION_CHARS == 2000
    assert len(translate(longest, world, build=False).tasks) == MAX_INSTRUCTION_CHARS // 33
    t0 = time.monotonic()
    with pytest.raises(HTTError, match=r"is 35,000 characters long; the limit is 2,000"):
        translate("x" * 35_000, world)
    assert time.monotonic() - t0 < 1.0  # refused before any parsing


def test_plan_refuses_a_long_instruction_with_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plan", PLATES + " and the mugs" * 200, "--llm", "offline"]) == 2
    assert "the limit is 2,000" in capsys.readouterr().err


@pytest.mark.parametrize(
    "argv, words",
    [
        (["bench", "tabletop", "--out", "{tmp}", "--instances", "1000000000"], "from 1 to 1000"),
        (["bench", "handover", "--out", "{tmp}", "--instances", "0"], "from 1 to 1000"),
        (["bench", "tabletop", "--out", "{tmp}", "--seed", "-1"], "from 0 to 4294967295"),
        (["bench", "alfred", "--oracle", "-o", "{tmp}", "--workers", "100000"], "from 1 to 256"),
        (["bench", "alfred", "--oracle", "-o", "{tmp}", "--limit", "10000000000"], "from 1 to 1000000"),
        (["bench", "alfred", "--oracle", "-o", "{tmp}", "--draw", "5"], "from 0 to 4"),
        (["bench", "alfred", "--oracle", "-o", "{tmp}", "--robots", "1,100"], "from 1 to 64"),
        (["bench", "alfred", "--oracle", "-o", "{tmp}", "--n-base", "1,1000"], "from 1 to 100"),
        (["bench", "alfred", "--oracle", "-o", "{tmp}", "--timeout", "1e300"], "at most 604800"),
        (["bench", "smartllm", "--oracle", "-o", "{tmp}", "--timeout", "inf"], "at most 604800"),
        (["plan", PLATES, "--timeout", "0"], "seconds > 0"),
        (["plan", PLATES, "--llm-timeout", "1e12"], "at most 604800"),
        (["plan", PLATES, "--llm-instruction-timeout", "nan"], "seconds > 0"),
        (["plan", PLATES, "--retries", "1000"], "from 0 to 20"),
        (["plan", PLATES, "--threads", "100000"], "from 1 to 256"),
        (["plan", PLATES, "--robots", "100"], "at most"),
        (["train", "language", "--seed", "99999999999"], "from 0 to 4294967295"),
    ],
)
def test_every_count_and_time_option_is_bounded(
    argv: list[str], words: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main([a.format(tmp=tmp_path) for a in argv]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err
    assert not any(tmp_path.iterdir())  # refused before any work


# ---------------------------------------------------------------- LLM servers that misbehave
class Pair(BaseModel):
    a: int


MSGS = [{"role": "user", "content": "a pair"}]


def test_default_deadlines_report_a_dead_server_within_60_s() -> None:
    s = LLMSettings(base_url="http://127.0.0.1:9/v1", cache_dir=None)
    assert (s.timeout, s.instruction_timeout) == (30.0, 60.0)
    assert (
        LLMSettings(base_url="http://x/v1", instruction_timeout=900, cache_dir=None).instruction_timeout
        == 900
    )


@pytest.fixture
def silent_server() -> Iterator[str]:
    """Accepts connections (the kernel does) and never answers."""
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    sock.listen(16)
    yield f"http://127.0.0.1:{sock.getsockname()[1]}/v1"
    sock.close()


def test_a_silent_server_is_reported_at_the_instruction_deadline(silent_server: str) -> None:
    client = LLMClient(
        LLMSettings(base_url=silent_server, api_key="k", timeout=0.4, instruction_timeout=1.0, cache_dir=None)
    )
    t0 = time.monotonic()
    with pytest.raises(LLMError, match="pair: "), client.instruction():
        client.ask(MSGS, Pair, "pair")
    assert time.monotonic() - t0 < 3.0  # the 1 s deadline, not 3 retries x the request timeout


class _Scripted:
    """An HTTP server answering each POST with the next (status, headers, body) of `replies`."""

    def __init__(self, replies: list[tuple[int, dict[str, str], bytes]]) -> None:
        self.replies = replies
        self.times: list[float] = []
        owner = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *a: Any) -> None:
                pass

            def do_POST(self) -> None:  # noqa: N802 - http.server API
                self.rfile.read(int(self.headers.get("Content-Length", 0)))
                owner.times.append(time.monotonic())
                status, headers, body = owner.replies.pop(0)
                self.send_response(status)
                for k, v in {"Content-Type": "application/json", **headers}.items():
                    self.send_header(k, v)
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)

        self.server = start_server(Handler)
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}/v1"

    def close(self) -> None:
        stop_server(self.server)


OK = (
    200,
    {},
    b'{"id":"x","object":"chat.completion","created":0,"model":"m","choices":[{"index":0,'
    b'"finish_reason":"stop","message":{"role":"assistant","content":"{\\"a\\": 7}"}}]}',
)
LIMITED = b'{"error": {"message": "slow down", "type": "rate_limit"}}'


def _client(url: str, **kw: Any) -> LLMClient:
    return LLMClient(LLMSettings(base_url=url, api_key="k", cache_dir=None, backoff=5.0, **kw))


def test_retry_after_past_the_deadline_is_an_error_at_once() -> None:
    server = _Scripted([(429, {"Retry-After": "3600"}, LIMITED), OK])
    try:
        t0 = time.monotonic()
        with pytest.raises(LLMError, match=r"asks to retry after 3600s, past the instruction's LLM deadline"):
            _client(server.url, instruction_timeout=60).ask(MSGS, Pair, "pair")
        assert time.monotonic() - t0 < 2.0 and len(server.times) == 1
    finally:
        server.close()


@pytest.mark.parametrize("header", [{"Retry-After": "0.5"}, {"retry-after-ms": "500"}])
def test_retry_after_within_the_deadline_is_honoured(header: dict[str, str]) -> None:
    server = _Scripted([(429, header, LIMITED), OK])
    try:
        assert _client(server.url).ask(MSGS, Pair, "pair").a == 7
        assert 0.45 <= server.times[1] - server.times[0] < 3.0  # the server's wait, not the 5 s backoff
    finally:
        server.close()


def test_retry_after_as_an_http_date() -> None:
    from email.utils import formatdate

    server = _Scripted([(503, {"Retry-After": formatdate(time.time() + 7200, usegmt=True)}, LIMITED), OK])
    try:
        with pytest.raises(LLMError, match=r"asks to retry after 7\d\d\d(\.\d)?s"):
            _client(server.url).ask(MSGS, Pair, "pair")
    finally:
        server.close()
