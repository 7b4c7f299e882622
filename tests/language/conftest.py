"""Fixtures of the language tests: a local stub of an OpenAI-compatible server, data skips, one reading
of a set's line per test process."""

from __future__ import annotations

import inspect
import json
import sys
import threading
import time
from collections.abc import Callable, Iterator
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import pytest
from household_readings import shared_world

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.worlds.world import World

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import trust_sets  # noqa: E402

DATA = Path(__file__).parent / "data"

# A reply: str (assistant content), or (status, body dict), or ("sleep", seconds, reply)
Reply = Any


def completion(content: str, model: str = "stub") -> dict[str, Any]:
    return {
        "id": "chatcmpl-stub",
        "object": "chat.completion",
        "created": 0,
        "model": model,
        "choices": [
            {"index": 0, "finish_reason": "stop", "message": {"role": "assistant", "content": content}}
        ],
        "usage": {"prompt_tokens": 1, "completion_tokens": 1, "total_tokens": 2},
    }


class StubLLM:
    """A tiny OpenAI-compatible chat server on 127.0.0.1 that replays scripted answers.

    `answer` is called with the request body and returns a reply; by default replies are taken from
    `queue` in order, or from `rules` (substring of the last user message -> reply).
    """

    def __init__(self) -> None:
        self.requests: list[dict[str, Any]] = []
        self.queue: list[Reply] = []
        self.rules: list[tuple[str, Reply]] = []
        self.answer: Callable[[dict[str, Any]], Reply] | None = None
        stub = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *a: Any) -> None:  # quiet
                pass

            def do_POST(self) -> None:  # noqa: N802 - http.server API
                body = json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))) or b"{}")
                stub.requests.append(body)
                reply = stub._reply(body)
                while isinstance(reply, tuple) and reply and reply[0] == "sleep":
                    time.sleep(reply[1])
                    reply = reply[2]
                if isinstance(reply, tuple):
                    status, payload = reply
                else:
                    status, payload = 200, completion(str(reply), body.get("model", "stub"))
                data = json.dumps(payload).encode()
                try:
                    self.send_response(status)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):
                    pass

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.server.daemon_threads = True
        self.thread = threading.Thread(target=self.server.serve_forever, args=(0.05,), daemon=True)
        self.thread.start()

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.server.server_address[1]}/v1"

    def _reply(self, body: dict[str, Any]) -> Reply:
        if self.answer is not None:
            return self.answer(body)
        if self.queue:
            return self.queue.pop(0)
        last = next((m["content"] for m in reversed(body.get("messages", [])) if m["role"] == "user"), "")
        for key, reply in self.rules:
            if key in last:
                return reply
        return (500, {"error": {"message": "stub has no answer for this request", "type": "server_error"}})

    def close(self) -> None:
        self.server.shutdown()
        self.server.server_close()


@pytest.fixture
def stub() -> Iterator[StubLLM]:
    s = StubLLM()
    yield s
    s.close()


@pytest.fixture
def shared_data() -> Path:
    d = data_dir(required=False)
    if d is None:
        pytest.skip("../shared/data is absent")
    return d


@pytest.fixture(scope="session")
def world() -> Callable[..., World]:
    """`world("FloorPlan7")`, `world(plan, trials)`: a world as `load_world` builds it, one per test process
    for every module that reads in it (each module still pins its own floor plan)."""
    return shared_world


@pytest.fixture(scope="session", autouse=True)
def one_reading_per_line() -> Iterator[None]:
    """`trust_sets.outcome` answers each line once per test process. `-m sweep`'s all-sets check
    (test_user_styles.py) reads every committed style set, and the per-set tests read some of them again
    with the same question (about 600 of 5,800 lines); the reader's own memos keep only parts of a reading.
    The key is all that a verdict depends on: the row as loaded (text, floor plan, trials, truth), its
    constraints, the backend and the plural mode; not the environment or patched code, so a test that
    patches the reader (or sets a reader's environment variable) must not ask `trust_sets` for a verdict."""
    read = trust_sets.read_line
    params = inspect.signature(read)
    kept: dict[tuple[str, ...], tuple[str, str, tuple[str, ...]]] = {}

    def read_once(*args: object, **kwargs: object) -> tuple[str, str, list[str]]:
        bound = params.bind(*args, **kwargs)
        bound.apply_defaults()
        gt, backend, plurals = (bound.arguments[k] for k in ("gt", "backend", "plurals"))
        constraints = json.dumps(trust_sets.constraints_of(gt), sort_keys=True)
        key = gt.model_dump_json(), constraints, backend, plurals
        if key not in kept:
            what, why, assumed = read(*args, **kwargs)
            kept[key] = what, why, tuple(assumed)
        what, why, assumed = kept[key]
        return what, why, list(assumed)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(trust_sets, "read_line", read_once)
        yield
