"""Fixtures of the experiment tests: a tiny OpenAI-compatible stub server for the LLM baseline."""

from __future__ import annotations

import json
import sys
from collections.abc import Callable, Iterator
from http.server import BaseHTTPRequestHandler
from pathlib import Path
from typing import Any

import pytest
from http_stub import start_server, stop_server

sys.path.insert(0, str(Path(__file__).parent))


class StubLLM:
    """Answers every chat request with `answer(body)` (the assistant's text)."""

    def __init__(self, answer: Callable[[dict[str, Any]], str]) -> None:
        self.requests: list[dict[str, Any]] = []
        stub = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *a: Any) -> None:
                pass

            def do_POST(self) -> None:  # noqa: N802 - http.server API
                body = json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))) or b"{}")
                stub.requests.append(body)
                content = answer(body)
                data = json.dumps({
                    "id": "x", "object": "chat.completion", "created": 0, "model": "stub",
                    "choices": [{"index": 0, "finish_reason": "stop",
                                 "message": {"role": "assistant", "content": content}}],
                    "usage": {"prompt_tokens": 1, "completion_tokens": 1, "total_tokens": 2},
                }).encode()
                self.send_response(200)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

        self.server = start_server(Handler)

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.server.server_address[1]}/v1"

    def close(self) -> None:
        stop_server(self.server)


@pytest.fixture
def stub_llm() -> Iterator[Callable[[Callable[[dict[str, Any]], str]], StubLLM]]:
    made: list[StubLLM] = []

    def make(answer: Callable[[dict[str, Any]], str]) -> StubLLM:
        s = StubLLM(answer)
        made.append(s)
        return s

    yield make
    for s in made:
        s.close()
