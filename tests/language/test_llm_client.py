"""The OpenAI-compatible client against a local stub server: JSON by schema, re-asks, retries,
timeouts, format fallback, the answer cache and batch files."""

from __future__ import annotations

import json
import time
from http.server import BaseHTTPRequestHandler

import pytest
from http_stub import start_server, stop_server
from pydantic import BaseModel, Field

from nl2hltl2plan.errors import LLMError
from nl2hltl2plan.language.llm import (
    AnswerCache,
    BatchCollector,
    LLMClient,
    LLMSettings,
    PendingAnswer,
    extract_json,
    read_answers,
    request_key,
)


class Pair(BaseModel):
    a: int
    b: list[str] = Field(max_length=3)


def client_for(stub, tmp_path=None, **kw) -> LLMClient:
    settings = LLMSettings(
        base_url=stub.base_url,
        model="stub-model",
        api_key="k",
        backoff=0.01,
        cache_dir=(tmp_path / "cache") if tmp_path else None,
        **kw,
    )
    return LLMClient(settings)


MSGS = [{"role": "user", "content": "give a pair"}]


def test_valid_answer_and_schema_request(stub):
    stub.queue = ['{"a": 1, "b": ["x"]}']
    c = client_for(stub)
    assert c.ask(MSGS, Pair, "pair") == Pair(a=1, b=["x"])
    req = stub.requests[0]
    assert req["model"] == "stub-model" and req["temperature"] == 0
    assert req["response_format"]["type"] == "json_schema"
    assert req["response_format"]["json_schema"]["schema"]["required"] == ["a", "b"]


def test_invalid_json_is_reasked_with_the_error(stub):
    stub.queue = ["sure! here it is", '```json\n{"a": 2, "b": []}\n```']
    c = client_for(stub)
    assert c.ask(MSGS, Pair, "pair").a == 2
    assert c.stats.reasks == 1
    second = stub.requests[1]["messages"]
    assert second[-2] == {"role": "assistant", "content": "sure! here it is"}
    assert "not valid" in second[-1]["content"] and "not JSON" in second[-1]["content"]


def test_wrong_schema_is_reasked_then_fails(stub):
    stub.queue = ['{"a": "one"}'] * 3
    c = client_for(stub, max_reasks=2)
    with pytest.raises(LLMError, match=r"pair: no valid answer after 3 attempts \(a: .*b: Field required"):
        c.ask(MSGS, Pair, "pair")
    assert len(stub.requests) == 3
    assert "b: Field required" in stub.requests[1]["messages"][-1]["content"]


def test_extra_validator_errors_are_fed_back(stub):
    stub.queue = ['{"a": 5, "b": []}', '{"a": 1, "b": []}']

    def small(p: Pair) -> None:
        if p.a > 3:
            raise ValueError("a must be at most 3")

    assert client_for(stub).ask(MSGS, Pair, "pair", validate=small).a == 1
    assert "a must be at most 3" in stub.requests[1]["messages"][-1]["content"]


def test_server_errors_are_retried_with_backoff(stub):
    slept = []
    stub.queue = [
        (500, {"error": {"message": "boom"}}),
        (503, {"error": {"message": "busy"}}),
        '{"a": 3, "b": []}',
    ]
    c = LLMClient(
        LLMSettings(base_url=stub.base_url, api_key="k", backoff=0.5, cache_dir=None), sleep=slept.append
    )
    assert c.ask(MSGS, Pair, "pair").a == 3
    assert slept == [0.5, 1.0] and c.stats.retries == 2


def test_timeout_gives_llm_error(stub):
    stub.answer = lambda body: ("sleep", 2.0, '{"a": 1, "b": []}')
    c = LLMClient(
        LLMSettings(
            base_url=stub.base_url, api_key="k", timeout=0.3, max_retries=1, backoff=0.01, cache_dir=None
        )
    )
    with pytest.raises(LLMError, match=r"timed out after 2 attempts \(timeout 0.3s\)"):
        c.ask(MSGS, Pair, "pair")


def test_unreachable_server_and_auth_errors():
    c = LLMClient(LLMSettings(base_url="http://127.0.0.1:9/v1", api_key="k", max_retries=0, cache_dir=None))
    with pytest.raises(LLMError, match="request to http://127.0.0.1:9/v1 failed"):
        c.ask(MSGS, Pair, "pair")


def test_auth_error(stub):
    stub.queue = [(401, {"error": {"message": "bad key"}})]
    with pytest.raises(LLMError, match="authentication failed"):
        client_for(stub).ask(MSGS, Pair, "pair")


def test_json_schema_rejected_falls_back_to_json_object_then_plain(stub):
    def answer(body):
        fmt = body.get("response_format")
        if fmt and fmt["type"] != "json_object":
            return (400, {"error": {"message": "response_format json_schema is not supported"}})
        if fmt:
            return (400, {"error": {"message": "unknown response_format json_object"}})
        return '{"a": 4, "b": []}'

    stub.answer = answer
    c = client_for(stub)
    assert c.ask(MSGS, Pair, "pair").a == 4
    assert [r.get("response_format", {}).get("type") for r in stub.requests] == [
        "json_schema",
        "json_object",
        None,
    ]
    stub.answer = lambda body: '{"a": 5, "b": []}' if "response_format" not in body else (400, {})
    assert c.ask([{"role": "user", "content": "again"}], Pair, "pair").a == 5  # remembered: no format sent


def test_cache_replays_without_server(stub, tmp_path):
    stub.queue = ['{"a": 7, "b": []}']
    c = client_for(stub, tmp_path)
    assert c.ask(MSGS, Pair, "pair").a == 7
    c2 = client_for(stub, tmp_path)  # the queue is empty now: an answer must come from the cache
    assert c2.ask(MSGS, Pair, "pair").a == 7
    assert c2.stats.cached == 1 and c2.stats.sent == 0 and len(stub.requests) == 1
    assert len(AnswerCache(tmp_path / "cache")) == 1


def test_cache_key_is_the_full_request():
    r = {"model": "m", "messages": MSGS, "temperature": 0}
    assert request_key(r) == request_key(json.loads(json.dumps(r)))
    assert request_key(r) != request_key({**r, "temperature": 0.5})
    assert request_key(r) != request_key({**r, "model": "n"})


def test_batch_mode_writes_pending_requests_and_reads_answers(tmp_path):
    cache = AnswerCache(tmp_path / "cache")
    batch = BatchCollector()
    c = LLMClient(LLMSettings(model="gpt-x", api_key="k", cache_dir=None), cache=cache, batch=batch)
    with pytest.raises(PendingAnswer):
        c.ask(MSGS, Pair, "pair")
    assert batch.write(tmp_path / "in.jsonl") == 1
    line = json.loads((tmp_path / "in.jsonl").read_text())
    assert line["method"] == "POST" and line["url"] == "/v1/chat/completions"
    assert line["body"]["model"] == "gpt-x" and line["body"]["messages"] == MSGS
    out = {
        "id": "b1",
        "custom_id": line["custom_id"],
        "error": None,
        "response": {
            "status_code": 200,
            "body": {"choices": [{"message": {"content": '{"a": 9, "b": []}'}}]},
        },
    }
    bad = {"custom_id": "x" * 64, "response": {"status_code": 500, "body": {}}, "error": None}
    (tmp_path / "out.jsonl").write_text(json.dumps(out) + "\n" + json.dumps(bad) + "\n")
    stored, errors = read_answers(tmp_path / "out.jsonl", cache, tmp_path / "in.jsonl")
    assert stored == 1 and len(errors) == 1
    assert c.ask(MSGS, Pair, "pair").a == 9  # now answered from the cache, nothing pending


def test_extract_json_variants():
    assert extract_json('{"a": 1}') == {"a": 1}
    assert extract_json('Here:\n```json\n{"a": 2}\n```') == {"a": 2}
    assert extract_json('The answer is {"a": 3} ok') == {"a": 3}
    with pytest.raises(ValueError):
        extract_json("no json here")


def test_settings_from_env(monkeypatch, tmp_path):
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_BASE_URL", "http://x/v1")
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_TEMPERATURE", "0.3")
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_CACHE", "off")
    s = LLMSettings.from_env(model="m1", timeout=None)
    assert (s.base_url, s.temperature, s.model, s.cache_dir, s.configured) == (
        "http://x/v1",
        0.3,
        "m1",
        None,
        True,
    )
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_TIMEOUT", "soon")
    with pytest.raises(LLMError, match="invalid LLM settings"):
        LLMSettings.from_env()


# ----- reliability (issue 10.6): a real local HTTP server misbehaving in every way -------------------
class Misbehaving:
    """An HTTP server on 127.0.0.1 whose first path segment picks the misbehaviour."""

    BODIES: dict[str, bytes] = {
        "html": b"<html>502 bad gateway</html>",
        "notjson": b"not json at all",
        "empty": b"",
        "binary": b"\xff\xfe\x00\x01garbage",
        "deep": b"[" * 100_000,
        "array": b"[1, 2]",
        "nochoices": b'{"id": "x"}',
        "choicesstr": b'{"choices": "x"}',
        "emptychoices": b'{"choices": []}',
        "nullmessage": b'{"choices": [{"message": null}]}',
        "intcontent": b'{"choices": [{"message": {"content": 5}}]}',
    }

    def __init__(self) -> None:
        outer = self
        self.hits = 0

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *a: object) -> None:
                pass

            def do_POST(self) -> None:  # noqa: N802 - http.server API
                outer.hits += 1
                self.rfile.read(int(self.headers.get("Content-Length", 0)))
                kind = self.path.split("/")[1]
                if kind == "trickle":  # valid headers, then one byte every 0.2 s, forever
                    self.send_response(200)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", "100000")
                    self.end_headers()
                    try:
                        while True:
                            self.wfile.write(b" ")
                            self.wfile.flush()
                            time.sleep(0.2)
                    except OSError:
                        return
                body = Misbehaving.BODIES[kind]
                ctype = "text/html" if kind == "html" else "application/json"
                self.send_response(200)
                self.send_header("Content-Type", ctype)
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)

        self.server = start_server(Handler)

    def url(self, kind: str) -> str:
        return f"http://127.0.0.1:{self.server.server_address[1]}/{kind}/v1"

    def close(self) -> None:
        stop_server(self.server)


@pytest.fixture
def bad_server():
    s = Misbehaving()
    yield s
    s.close()


def test_trickling_server_hits_the_total_deadline(bad_server):
    c = LLMClient(
        LLMSettings(
            base_url=bad_server.url("trickle"),
            api_key="k",
            timeout=0.6,
            max_retries=1,
            backoff=0.01,
            cache_dir=None,
        )
    )
    t0 = time.monotonic()
    with pytest.raises(LLMError, match=r"pair: request to .* timed out after 2 attempts \(timeout 0.6s\)"):
        c.ask(MSGS, Pair, "pair")
    assert time.monotonic() - t0 < 2.5  # 2 x 0.6 s, not forever (the HTTP timeout is per read)


def test_instruction_deadline_covers_all_requests(stub):
    stub.answer = lambda body: ("sleep", 0.3, '{"a": 1, "b": []}')
    c = LLMClient(
        LLMSettings(
            base_url=stub.base_url,
            api_key="k",
            timeout=5,
            instruction_timeout=0.5,
            max_retries=0,
            cache_dir=None,
        )
    )
    c.start_instruction()
    assert c.ask(MSGS, Pair, "first").a == 1  # 0.3 s of the 0.5 s
    t0 = time.monotonic()
    with pytest.raises(LLMError, match=r"second: .*(timed out|past their deadline)"):
        c.ask([{"role": "user", "content": "again"}], Pair, "second")
    assert time.monotonic() - t0 < 1.0
    with c.instruction(5.0):  # an explicit, longer deadline for the next instruction
        assert c.ask([{"role": "user", "content": "third"}], Pair, "third").a == 1


@pytest.mark.parametrize("kind", sorted(Misbehaving.BODIES))
def test_non_json_and_wrong_schema_bodies_are_clean_errors(bad_server, kind):
    c = LLMClient(LLMSettings(base_url=bad_server.url(kind), api_key="k", max_retries=0, cache_dir=None))
    with pytest.raises(LLMError) as exc:
        c.ask(MSGS, Pair, "pair")
    msg = str(exc.value)
    assert msg.startswith("pair: ") and "\n" not in msg and bad_server.url(kind) in msg
    assert any(w in msg for w in ("not JSON", "not a chat completion", "not text"))


def test_cache_key_includes_the_server(stub, tmp_path):
    other = type(stub)()  # a second stub server with the same model name
    try:
        stub.queue = ['{"a": 1, "b": []}']
        other.queue = ['{"a": 2, "b": []}']
        assert client_for(stub, tmp_path).ask(MSGS, Pair, "pair").a == 1
        assert client_for(other, tmp_path).ask(MSGS, Pair, "pair").a == 2  # not replayed from stub
        assert client_for(stub, tmp_path).ask(MSGS, Pair, "pair").a == 1  # cached, per server
        assert len(stub.requests) == 1 and len(other.requests) == 1
    finally:
        other.close()
    r = {"model": "m", "messages": MSGS}
    assert request_key(r, "http://a/v1") != request_key(r, "http://b/v1")
    assert LLMSettings(base_url="http://A/v1/").scope == LLMSettings(base_url="http://a/v1").scope
    assert LLMSettings(base_url="http://a/v1", cache_scope="local:x.gguf").scope == "local:x.gguf"


@pytest.mark.parametrize(
    "var, value",
    [
        ("TIMEOUT", "nan"),
        ("TIMEOUT", "0"),
        ("TIMEOUT", "inf"),
        ("RETRIES", "-1"),
        ("INSTRUCTION_TIMEOUT", "-5"),
        ("CTX", "0"),
    ],
)
def test_invalid_numeric_settings_are_refused(monkeypatch, var, value):
    monkeypatch.setenv(f"NL2HLTL2PLAN_LLM_{var}", value)
    with pytest.raises(LLMError, match="invalid LLM settings"):
        LLMSettings.from_env()


def test_damaged_cache_entries_are_asked_again(stub, tmp_path):
    stub.queue = ['{"a": 1, "b": []}', '{"a": 1, "b": []}']
    c = client_for(stub, tmp_path)
    c.ask(MSGS, Pair, "pair")
    (entry,) = (tmp_path / "cache").glob("*/*.json")
    entry.write_bytes(b"\xff[[[")
    assert client_for(stub, tmp_path).ask(MSGS, Pair, "pair").a == 1
    assert len(stub.requests) == 2


def test_bad_batch_files_are_clean_errors(tmp_path):
    cache = AnswerCache(tmp_path / "cache")
    binary = tmp_path / "bin.jsonl"
    binary.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(LLMError, match="is not UTF-8 text"):
        read_answers(binary, cache)
    with pytest.raises(LLMError, match="cannot read batch answers"):
        read_answers(tmp_path / "missing.jsonl", cache)
    answers = tmp_path / "answers.jsonl"
    answers.write_text(
        '[1]\n{"custom_id": "k", "response": 5}\n{"custom_id": "k", "response": {"body": '
        '{"choices": [{"message": {"content": 7}}]}}}\n' + "[" * 5000 + "\n"
    )
    stored, errors = read_answers(answers, cache)
    assert stored == 0 and len(errors) == 4
    requests = tmp_path / "requests.jsonl"
    requests.write_text("{not json\n")
    with pytest.raises(LLMError, match="line 1: not a Batch API request line"):
        read_answers(answers, cache, requests)


def test_clients_share_one_verifying_tls_context_and_keep_their_own_connections():
    """The CA bundle loads once per process (30 to 90 ms each time otherwise); each client still has
    its own HTTP client, with the SDK's request timeout, and closing one leaves the others usable."""
    import ssl

    from nl2hltl2plan.language.llm.client import _tls_context

    settings = LLMSettings(base_url="http://127.0.0.1:9/v1", api_key="k", timeout=7.0, cache_dir=None)
    first, second = LLMClient(settings).client, LLMClient(settings).client
    assert first._client is not second._client and first.timeout == second.timeout == 7.0
    ctx = _tls_context()
    assert ctx is _tls_context() and ctx.verify_mode == ssl.CERT_REQUIRED and ctx.check_hostname
    first.close()
    assert first.is_closed() and not second.is_closed()
