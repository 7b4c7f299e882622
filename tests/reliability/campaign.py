# Run: PYTHONPATH=src python3 tests/reliability/campaign.py /tmp/campaign  (about 3 min: time limits)
"""Bad-input campaign over the reliability areas: each case runs in a child with a deadline and is
classified clean (an Nl2Hltl2PlanError with a one-line message), traceback (any other exception or a
multi-line message) or hang (past its time limit)."""

from __future__ import annotations

import json
import os
import sys
import threading
import time
from collections import Counter
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

from pydantic import BaseModel

from nl2hltl2plan.deadline import ChildError, run_with_deadline
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language import stages
from nl2hltl2plan.language.llm import AnswerCache, LLMClient, LLMSettings, read_answers
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.hierarchical import sequence_formula
from nl2hltl2plan.suites.runner import Scenario, run_scenarios

TMP = Path(sys.argv[1])
TMP.mkdir(exist_ok=True)
results = []


def case(area, name, fn, limit=40.0):
    def wrapped(_):
        try:
            out = fn()
            return ("ok", repr(out)[:80])
        except Nl2Hltl2PlanError as exc:
            msg = str(exc)
            return ("clean" if "\n" not in msg.strip() else "multiline", msg[:150])
        except BaseException as exc:
            return ("traceback", f"{type(exc).__name__}: {str(exc)[:120]}")

    t0 = time.monotonic()
    try:
        verdict, detail = run_with_deadline(wrapped, None, limit, memory_mb=3000)
    except ChildError as exc:
        verdict, detail = ("hang" if exc.kind == "timeout" else "traceback"), str(exc)
    results.append((area, name, verdict, round(time.monotonic() - t0, 2), detail))
    print(f"{verdict:9s} {time.monotonic() - t0:6.2f}s {area:8s} {name}: {detail[:130]}", flush=True)


# ---------- formulas


def dfa(text, **kw):
    return lambda: sb.dfa(sb.parse(text), **kw).num_states


def X(n):  # noqa: N802 - reads like the operator
    return "F(a & " + "X " * n + "b)"


formulas = {
    "empty": "",
    "blank": "   ",
    "unbalanced": "F(a &",
    "G": "G a",
    "R": "a R b",
    "implies": "a -> F b",
    "X22 two atoms": X(22),
    "X30 two atoms": X(30),
    "X12": X(12),
    "30-step sequence": sequence_formula([f"p{i}" for i in range(30)], check=False),
    "300-step sequence": sequence_formula([f"p{i}" for i in range(300)], check=False),
    "24 independent F": " & ".join(f"F p{i}" for i in range(24)),
    "40 independent F": " & ".join(f"F p{i}" for i in range(40)),
    "nested U depth 40": "(" * 0 + " U (".join(f"p{i}" for i in range(40)) + ")" * 39,
    "F nested 5000": "F(" * 5000 + "a" + ")" * 5000,
    "parens 100000": "(" * 100000 + "a" + ")" * 100000,
    "1 MB atom": "F " + "a" * 1_000_000,
    "NUL char": "F(a\x00b)",
    "unicode atoms": 'F("äpfel" & F "日本")',
    "X^100 no F": "X " * 100 + "a",
    "true": "true",
    "false": "F false",
    "disjunction of 20 sequences": " | ".join(
        sequence_formula([f"q{i}", f"r{i}", f"s{i}"], check=False) for i in range(20)
    ),
    "repeated atom sequence": "F(a & F(a & F(a & F b)))",
    "binary junk": "\xff\xfe\x00\x01",
    "mixed X and F 8 ops": "F(a & X X X b) & F(c & X X X d)",
}
for name, text in formulas.items():
    case("formula", name, dfa(text))
for bad in [float("nan"), 0.0, -1.0, float("inf")]:
    case("formula", f"timeout {bad}", dfa(" & ".join(f"F p{i}" for i in range(9)), timeout_s=bad))
case(
    "formula",
    "automaton_size of X22",
    lambda: sb.automaton_size(sb.parse(X(22)), timeout_s=20, memory_mb=512),
)

# ---------- runner


def quick(s):
    return {"status": "solved"}


def runner_case(name, content: bytes | None, **kw):
    path = TMP / f"{name.replace(' ', '_')}.jsonl"
    if content is not None:
        path.write_bytes(content)

    def go():
        rows = run_scenarios(
            [Scenario("a", 1, 1), Scenario("b", 1, 1)],
            kw.pop("job", quick),
            kw.pop("out", path),
            notes=lambda t: None,
            **kw,
        )
        lines = [x for x in path.read_text().splitlines() if x.strip()] if path.is_file() else []
        assert all(json.loads(x).get("key") for x in lines), "a bad line stayed"
        return [r.get("status") for r in rows]

    case("runner", name, go)


good = json.dumps({"key": "a|r1|d0", "status": "solved"}).encode()
for name, content in {
    "torn last line": good + b'\n{"key": "b|r1',
    "binary": b"\xff\xfe\x00\n",
    "deep json": b"[" * 100000 + b"\n",
    "non-dict": b"[1]\n42\nnull\n",
    "no key": b'{"a": 1}\n',
    "key not str": b'{"key": 5}\n',
    "empty": b"",
    "only newlines": b"\n\n\n",
    "huge line 50 MB": b'{"key": "' + b"x" * 50_000_000 + b'"}\n',
}.items():
    runner_case(name, content)
(TMP / "isdir.jsonl").mkdir(exist_ok=True)
case("runner", "out is a directory", lambda: run_scenarios([Scenario("a", 1, 1)], quick, TMP / "isdir.jsonl"))
case(
    "runner",
    "out under a file",
    lambda: run_scenarios([Scenario("a", 1, 1)], quick, TMP / "torn_last_line.jsonl" / "x.jsonl"),
)
for kw in [
    {"workers": 0},
    {"workers": -3},
    {"hard_timeout_s": 0},
    {"hard_timeout_s": float("nan")},
    {"hard_timeout_s": float("inf")},
    {"hard_timeout_s": -1},
]:
    case(
        "runner",
        f"limits {kw}",
        lambda kw=kw: run_scenarios([Scenario("a", 1, 1)], quick, TMP / "limits.jsonl", **kw),
    )


def raising(s):
    raise RuntimeError("job blew up")


def exiting(s):
    os._exit(7)


def killing(s):
    os.kill(os.getpid(), 9)


def unpicklable(s):
    return {"f": lambda: 0}


def nonrow(s):
    return [1, 2]


def sleeper(s):
    time.sleep(100)


def hog(s):
    return len(bytearray(1 << 40))


for name, job in [
    ("job raises", raising),
    ("job exits", exiting),
    ("job SIGKILLs itself", killing),
    ("job returns unpicklable", unpicklable),
    ("job returns a list", nonrow),
    ("job allocates 1 TB", hog),
]:
    case(
        "runner",
        name,
        lambda job=job, name=name: [
            (r["status"], r.get("reason", "")[:60])
            for r in run_scenarios(
                [Scenario("a", 1, 1)], job, TMP / f"{name.replace(' ', '_')}.jsonl", resume=False
            )
        ],
    )
case(
    "runner",
    "job hangs",
    lambda: [
        (r["status"], r.get("reason"))
        for r in run_scenarios(
            [Scenario("a", 1, 1)], sleeper, TMP / "hang.jsonl", hard_timeout_s=1, resume=False
        )
    ],
)

# ---------- LLM client


class Pair(BaseModel):
    a: int


MSGS = [{"role": "user", "content": "x"}]
BODIES = {
    "html": (200, b"<html>bad gateway</html>", "text/html"),
    "notjson": (200, b"nope", "application/json"),
    "empty": (200, b"", "application/json"),
    "binary": (200, b"\xff\xfe\x00", "application/json"),
    "deep": (200, b"[" * 100000, "application/json"),
    "array": (200, b"[1]", "application/json"),
    "nochoices": (200, b'{"id": 1}', "application/json"),
    "choicesstr": (200, b'{"choices": "x"}', "application/json"),
    "emptychoices": (200, b'{"choices": []}', "application/json"),
    "nullmessage": (200, b'{"choices": [{"message": null}]}', "application/json"),
    "intcontent": (200, b'{"choices": [{"message": {"content": 5}}]}', "application/json"),
    "nullcontent": (200, b'{"choices": [{"message": {"content": null}}]}', "application/json"),
    "content not json": (
        200,
        json.dumps({"choices": [{"message": {"content": "hello"}}]}).encode(),
        "application/json",
    ),
    "content wrong schema": (
        200,
        json.dumps({"choices": [{"message": {"content": '{"b": 1}'}}]}).encode(),
        "application/json",
    ),
    "500": (500, b'{"error": {"message": "boom"}}', "application/json"),
    "401": (401, b'{"error": {"message": "key"}}', "application/json"),
    "404": (404, b"not found", "text/plain"),
    "429": (429, b"{}", "application/json"),
    "302": (302, b"", "text/plain"),
    "418 html": (418, b"<h1>teapot</h1>", "text/html"),
    "10 MB content": (
        200,
        json.dumps({"choices": [{"message": {"content": "x" * 10_000_000}}]}).encode(),
        "application/json",
    ),
}


class H(BaseHTTPRequestHandler):
    def log_message(self, *a):
        pass

    def do_POST(self):
        self.rfile.read(int(self.headers.get("Content-Length", 0)))
        kind = self.path.split("/")[1].replace("%20", " ")
        if kind == "trickle":
            self.send_response(200)
            self.send_header("Content-Length", "100000")
            self.end_headers()
            try:
                while True:
                    self.wfile.write(b" ")
                    self.wfile.flush()
                    time.sleep(1)
            except OSError:
                return
        if kind == "sleep":
            time.sleep(30)
        if kind == "cut":
            self.send_response(200)
            self.send_header("Content-Length", "1000")
            self.end_headers()
            self.wfile.write(b'{"choices": [')
            return
        if kind == "close":
            self.connection.close()
            return
        status, body, ctype = BODIES[kind]
        self.send_response(status)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        if status == 302:
            self.send_header("Location", self.path)
        self.end_headers()
        self.wfile.write(body)


srv = ThreadingHTTPServer(("127.0.0.1", 0), H)
srv.daemon_threads = True
threading.Thread(target=srv.serve_forever, daemon=True).start()


def url(k):
    return f"http://127.0.0.1:{srv.server_address[1]}/{k.replace(' ', '%20')}/v1"


def ask(kind, **kw):
    s = LLMSettings(
        base_url=url(kind),
        api_key="k",
        cache_dir=None,
        backoff=0.01,
        **{"max_retries": 0, "timeout": 3, **kw},
    )
    return lambda: LLMClient(s).ask(MSGS, Pair, "pair")


for k in [*BODIES, "trickle", "sleep", "cut", "close"]:
    case("llm", f"server {k}", ask(k))
case(
    "llm",
    "unreachable port",
    lambda: LLMClient(
        LLMSettings(base_url="http://127.0.0.1:9/v1", api_key="k", max_retries=0, cache_dir=None)
    ).ask(MSGS, Pair, "p"),
)
case(
    "llm",
    "bad scheme url",
    lambda: LLMClient(LLMSettings(base_url="ftp://x/v1", api_key="k", max_retries=0, cache_dir=None)).ask(
        MSGS, Pair, "p"
    ),
)
case(
    "llm",
    "instruction deadline 1s, trickle",
    lambda: (lambda c: (c.start_instruction(), c.ask(MSGS, Pair, "p")))(
        LLMClient(
            LLMSettings(
                base_url=url("trickle"),
                api_key="k",
                timeout=30,
                instruction_timeout=1,
                max_retries=3,
                backoff=0.01,
                cache_dir=None,
            )
        )
    ),
)
for var, val in [
    ("TIMEOUT", "nan"),
    ("TIMEOUT", "-1"),
    ("TIMEOUT", "inf"),
    ("RETRIES", "x"),
    ("TEMPERATURE", "9"),
    ("JSON", "yaml"),
    ("CTX", "0"),
    ("INSTRUCTION_TIMEOUT", "0"),
]:

    def settings_case(var=var, val=val):
        os.environ[f"NL2HLTL2PLAN_LLM_{var}"] = val
        return LLMSettings.from_env()

    case("llm", f"env {var}={val}", settings_case)
for name, content in {
    "binary": b"\xff\xfe",
    "deep": b"[" * 100000,
    "list rows": b"[1]\n",
    "bad response": b'{"custom_id": "k", "response": 3}\n',
}.items():
    f = TMP / f"answers_{name}.jsonl"
    f.write_bytes(content)
    case("llm", f"batch answers {name}", lambda f=f: read_answers(f, AnswerCache(TMP / "cache")))
case("llm", "batch answers missing", lambda: read_answers(TMP / "nope.jsonl", AnswerCache(TMP / "cache")))
case("llm", "batch answers is a dir", lambda: read_answers(TMP, AnswerCache(TMP / "cache")))
(TMP / "req.jsonl").write_bytes(b"{bad\n")
case(
    "llm",
    "batch requests broken",
    lambda: read_answers(TMP / "answers_list_rows.jsonl", AnswerCache(TMP / "cache"), TMP / "req.jsonl"),
)

# ---------- semantic checks through the stages (a scripted server)
ANSWERS = {}


class S(BaseHTTPRequestHandler):
    def log_message(self, *a):
        pass

    def do_POST(self):
        self.rfile.read(int(self.headers.get("Content-Length", 0)))
        content = ANSWERS[self.path.split("/")[1]]
        data = json.dumps({"choices": [{"message": {"role": "assistant", "content": content}}]}).encode()
        self.send_response(200)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)


s2 = ThreadingHTTPServer(("127.0.0.1", 0), S)
s2.daemon_threads = True
threading.Thread(target=s2.serve_forever, daemon=True).start()


def client(k):
    return LLMClient(
        LLMSettings(base_url=f"http://127.0.0.1:{s2.server_address[1]}/{k}/v1", api_key="k", cache_dir=None)
    )


ANSWERS["mugs"] = '{"actions": ["pickup(Mug)", "put(Mug,Cabinet)"]}'
case(
    "semantic",
    "plates asked, mugs moved",
    lambda: stages.complete_actions(
        client("mugs"),
        "plates",
        {"id": "1.1", "kind": "place", "object": ["Plate"], "receptacle": ["Cabinet"]},
        {"Plate", "Mug", "Cabinet"},
    ),
)
ANSWERS["wrongdest"] = '{"actions": ["pickup(Plate)", "put(Plate,Sink)"]}'
case(
    "semantic",
    "wrong destination",
    lambda: stages.complete_actions(
        client("wrongdest"),
        "plates",
        {"id": "1.1", "kind": "place", "object": ["Plate"], "receptacle": ["Cabinet"]},
        {"Plate", "Sink", "Cabinet"},
    ),
)
ANSWERS["cycle"] = '{"relations": [["1.1", "1.2"], ["1.2", "1.3"], ["1.3", "1.1"]]}'
case(
    "semantic",
    "cyclic relations",
    lambda: stages.relations(client("cycle"), "x", "1", "all", [("1.1", "a"), ("1.2", "b"), ("1.3", "c")]),
)
ANSWERS["dropped"] = json.dumps(
    {"tasks": [{"id": "1", "kind": "place", "object": "apple", "receptacle": "fridge"}]}
)
case(
    "semantic",
    "decomposition drops the mug",
    lambda: stages.decompose(client("dropped"), "Put the apple in the fridge and the mug in the sink.", []),
)
ANSWERS["nolamp"] = '{"actions": ["pickup(KeyChain)"]}'
case(
    "semantic",
    "examine without the lamp",
    lambda: stages.complete_actions(
        client("nolamp"),
        "keys",
        {"id": "1.1", "kind": "examine_in_light", "object": ["KeyChain"], "light": ["FloorLamp"]},
        {"KeyChain", "FloorLamp"},
    ),
)
ANSWERS["nowash"] = '{"actions": ["pickup(Apple)", "put(Apple,Fridge)"]}'
case(
    "semantic",
    "clean without washing",
    lambda: stages.complete_actions(
        client("nowash"),
        "x",
        {"id": "1.1", "kind": "clean_place", "object": ["Apple"], "receptacle": ["Fridge"]},
        {"Apple", "Fridge", "SinkBasin", "Faucet"},
    ),
)

print("\nSUMMARY", dict(Counter(r[2] for r in results)), "of", len(results))
for area in ("formula", "runner", "llm", "semantic"):
    print(area, dict(Counter(r[2] for r in results if r[0] == area)))
json.dump(results, open(TMP / "campaign.json", "w"), indent=1)
