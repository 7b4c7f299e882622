# Run: PYTHONPATH=src python3 tests/reliability/campaign25.py /tmp/campaign25 [--report FILE]
# (FILE: results/reliability/report.md; about 10 minutes on 2 cores)
"""Fault campaign of issue 25: every case runs the real `nl2hltl2plan` command in a child process with a
time limit, and is judged on what a user sees:

- hang: still running at its limit (killed);
- traceback: a Python traceback or an internal error (exit 4) on stderr;
- wrong status: an exit status other than the documented one (0 success, 1 a definite "no", 2 bad
  input, 3 batch pending, 141 output cut by a closed pipe);
- bad message: exit 2 without a final one-line `error: ...` (or any stderr with a closed pipe);
- data loss: a post-check on the files the case touched fails (a torn or overwritten file).

Areas: non-regular input files, instruction length, bounds of count/time options, bad values that
must be exit 2, damaged data folders, the exit contract, LLM servers that misbehave, and kills while
writing. Data folders are copies (never links into the shared data: a damaged file must not be able to
reach it). The shared data is read-only input here.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
SHARED = Path(os.environ.get("NL2HLTL2PLAN_DATA") or ROOT.parent / "shared" / "data").resolve()
HTT = str(ROOT / "examples" / "dishwasher_htt.json")
PLATES = "put the plates in the lower rack"
DISH = (
    "Put the plates, mugs and utensils in the lower rack in any order; after that, first the saucers, "
    "then the cups, in the upper rack. "
)


@dataclass
class Case:
    area: str
    name: str
    argv: list[str]
    expect: set[int]
    limit: float = 60.0
    env: dict[str, str] = field(default_factory=dict)
    setup: Callable[[Path], None] | None = None  # prepares the case's folder
    check: Callable[[Path], str | None] | None = None  # data-loss post-check: a problem or None
    kill_on_write: tuple[str, float] | None = None  # (watched folder, delay): SIGKILL this long after the
    # command's first write into the folder is seen (a temporary file or a changed file), mid-write
    close_stdout: bool = False  # the reader of stdout is gone before the command writes (| head -0)
    words: str | None = None  # expected in the error line


@dataclass
class Result:
    case: Case
    code: int | None
    seconds: float
    verdict: str
    detail: str


def run_case(case: Case, work: Path) -> Result:
    folder = work / f"{case.area}-{case.name}".replace("/", "_").replace(" ", "_")[:120]
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    if case.setup:
        case.setup(folder)
    argv = [a.replace("{d}", str(folder)) for a in case.argv]
    env = {
        **os.environ,
        "PYTHONPATH": str(ROOT / "src"),
        "XDG_CACHE_HOME": str(folder / "cache"),
        **{k: v.replace("{d}", str(folder)) for k, v in case.env.items()},
    }
    t0 = time.monotonic()
    proc = subprocess.Popen(
        [sys.executable, "-m", "nl2hltl2plan", *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        stdin=subprocess.DEVNULL,
        env=env,
        cwd=folder,
        start_new_session=True,
    )
    assert proc.stdout is not None and proc.stderr is not None
    if case.close_stdout:
        proc.stdout.close()
        proc.stdout = None  # communicate() then reads stderr only
    killed = False
    if case.kill_on_write is not None:
        killed = _kill_when_writing(proc, folder / case.kill_on_write[0], case.kill_on_write[1], case.limit)
    try:
        _, err = proc.communicate(timeout=case.limit)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return Result(case, None, round(time.monotonic() - t0, 2), "hang", f"still running at {case.limit}s")
    seconds = round(time.monotonic() - t0, 2)
    code = proc.returncode
    text = err.decode("utf-8", "replace")
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.startswith(("note:", "warning:"))]
    last = lines[-1] if lines else ""
    problem = case.check(folder) if case.check else None
    if "Traceback (most recent call last)" in text or code == 4 or "internal error" in text:
        verdict, detail = "traceback", (last or text[-200:])
    elif problem:
        verdict, detail = "data loss", problem
    elif killed:
        assert case.kill_on_write is not None
        verdict = "ok"
        watched, delay = case.kill_on_write
        detail = f"killed {delay}s after its first write; {_state(folder / watched)}"
    elif code not in case.expect:
        verdict, detail = "wrong status", f"exit {code}, expected {sorted(case.expect)}: {last[:200]}"
    elif code == 2 and not last.startswith("error:"):
        verdict, detail = "bad message", f"exit 2 without an error line: {text[-200:]!r}"
    elif code == 141 and lines:
        verdict, detail = "bad message", f"closed pipe but stderr: {text[-200:]!r}"
    elif case.words and case.words not in text:
        verdict, detail = "bad message", f"expected {case.words!r} in: {last[:200]}"
    else:
        verdict, detail = "ok", last[:200]
    return Result(case, code, seconds, verdict, detail)


def _snapshot(folder: Path) -> dict[str, tuple[int, int]]:
    try:
        return {p.name: (p.stat().st_size, p.stat().st_mtime_ns) for p in folder.iterdir()}
    except OSError:  # not there yet, or a file vanished while listed
        return {}


def _kill_when_writing(proc: subprocess.Popen[bytes], watched: Path, delay: float, limit: float) -> bool:
    """SIGKILL the command `delay` s after it first writes into `watched`; False if it ended first."""
    before = _snapshot(watched)
    end = time.monotonic() + limit
    while proc.poll() is None and time.monotonic() < end:
        if _snapshot(watched) != before:
            time.sleep(delay)
            if proc.poll() is not None:
                return False
            os.killpg(proc.pid, signal.SIGKILL)
            return True
        time.sleep(0.001)
    return False


def _state(watched: Path) -> str:
    """What a kill left: files replaced by whole new ones, old files, temporary files."""
    new = old = tmp = 0
    for p in watched.iterdir() if watched.exists() else []:
        if p.name.startswith("."):
            tmp += 1
        elif p.read_bytes() in (b"old", b'{"old": true}'):
            old += 1
        else:
            new += 1
    return f"files whole: {new} new, {old} old, {tmp} temporary left behind"


# ---------------------------------------------------------------- file kinds
def make_input(kind: str, folder: Path, name: str) -> None:
    p = folder / name
    if kind == "fifo":
        os.mkfifo(p)
    elif kind == "folder":
        p.mkdir()
    elif kind == "symlink loop":
        p.symlink_to(p)
    elif kind == "dangling symlink":
        p.symlink_to(folder / "nowhere")
    elif kind == "socket":
        s = socket.socket(socket.AF_UNIX)
        s.bind(str(p))  # left bound: the file stays a socket
        _keep.append(s)
    elif kind == "empty":
        p.write_bytes(b"")
    elif kind == "binary":
        p.write_bytes(bytes(range(256)) * 64)
    elif kind == "sparse 100 MB":
        with open(p, "wb") as fh:
            fh.truncate(100 * 1024 * 1024)
    elif kind == "link to /dev/zero":
        p.symlink_to("/dev/zero")
    elif kind == "link to /dev/stdin":
        p.symlink_to("/dev/stdin")


_keep: list[socket.socket] = []
KINDS = [
    "fifo",
    "folder",
    "symlink loop",
    "dangling symlink",
    "socket",
    "empty",
    "binary",
    "sparse 100 MB",
    "link to /dev/zero",
    "link to /dev/stdin",
]
DEAD_LLM = ["--llm", "openai", "--base-url", "http://127.0.0.1:9/v1", "--retries", "0", "--cache", "off"]
INPUTS: dict[str, tuple[str, list[str]]] = {  # option -> (file name, argv with {f} for the file)
    "spec": ("in.json", ["spec", "{f}"]),
    "check": ("in.json", ["check", "{f}"]),
    "show": ("in.json", ["show", "{f}", "-o", "{d}/x.png"]),
    "--robots": ("team.json", ["plan", PLATES, "--robots", "{f}"]),
    "--batch-answers": ("answers.jsonl", ["plan", PLATES, *DEAD_LLM[:-2], "--batch-answers", "{f}"]),
    "bench --gt": ("gt.jsonl", ["bench", "alfred", "--oracle", "--gt", "{f}", "-o", "{d}/b", "--quiet"]),
    "--masses": ("m.json", ["bench", "smartllm", "--oracle", "--masses", "{f}", "-o", "{d}/s", "--quiet"]),
}


def input_cases() -> list[Case]:
    out = []
    for option, (fname, argv) in INPUTS.items():
        for kind in KINDS:
            expect = {2}
            out.append(
                Case(
                    "input files",
                    f"{option} {kind}",
                    [a.replace("{f}", "{d}/" + fname) for a in argv],
                    expect,
                    limit=60,
                    setup=lambda d, k=kind, n=fname: make_input(k, d, n),
                )
            )
    return out


# ---------------------------------------------------------------- instruction length
def length_cases() -> list[Case]:
    sentences = "Put the plate in the lower rack. "
    out = [
        Case(
            "length",
            "1,980 chars: parsed, not refused",
            ["plan", sentences * 60, "--timeout", "10"],
            {0, 1, 2},
            90,
        ),
        Case(
            "length",
            "2,000 chars of the paper's sentence",
            ["plan", (DISH * 20)[:2000], "--timeout", "10"],
            {0, 1, 2},
            90,
        ),  # fmt: skip
        Case("length", "2,001 chars", ["plan", (DISH * 20)[:2001]], {2}, words="the limit is 2,000"),
        Case("length", "15.7 kB (46 s before)", ["plan", (DISH * 120)[:15_700]], {2}, 30, words="15,700"),
        Case("length", "35 kB (>150 s before)", ["plan", (DISH * 270)[:35_000]], {2}, 30, words="35,000"),
        Case("length", "120 kB", ["plan", "x " * 60_000], {2}, 30, words="120,000"),
        Case("length", "2,001 accented chars", ["plan", "é" * 2001], {2}, 30, words="2,001"),
        Case("length", "5,000 spaces", ["plan", " " * 5000], {2}, 30),
        Case("length", "empty", ["plan", ""], {2}, 30),
        Case(
            "length",
            "long instruction with an LLM: no request",
            ["plan", (DISH * 30)[:3000], *DEAD_LLM],
            {2},
            30,
            words="the limit is 2,000",
        ),
        Case("length", "long --json", ["plan", (DISH * 30)[:3000], "--json"], {2}, 30),
    ]
    return out


# ---------------------------------------------------------------- option bounds
def bound_cases() -> list[Case]:
    tab = ["bench", "tabletop", "--out", "{d}/t"]
    alf = ["bench", "alfred", "--oracle", "-o", "{d}/a"]
    values = {
        "tabletop --instances 1000000000": [*tab, "--instances", "1000000000"],
        "tabletop --instances 0": [*tab, "--instances", "0"],
        "tabletop --instances 1001": [*tab, "--instances", "1001"],
        "handover --instances 99999": ["bench", "handover", "--out", "{d}/h", "--instances", "99999"],
        "tabletop --seed -1": [*tab, "--seed", "-1"],
        "tabletop --seed 2^40": [*tab, "--seed", str(2**40)],
        "tabletop --instances ١٢": [*tab, "--instances", "١٢"],
        "tabletop --instances 1_000": [*tab, "--instances", "1_000"],
        "tabletop --instances 0x10": [*tab, "--instances", "0x10"],
        "alfred --workers 0": [*alf, "--workers", "0"],
        "alfred --workers 100000": [*alf, "--workers", "100000"],
        "alfred --limit 10^10": [*alf, "--limit", "10000000000"],
        "alfred --limit -1": [*alf, "--limit", "-1"],
        "alfred --draw 5": [*alf, "--draw", "5"],
        "alfred --draw -1": [*alf, "--draw", "-1"],
        "alfred --robots 1,1000": [*alf, "--robots", "1,1000"],
        "alfred --robots 65 entries": [*alf, "--robots", ",".join(["1"] * 65)],
        "alfred --robots ,,": [*alf, "--robots", ",,"],
        "alfred --n-base 1000": [*alf, "--n-base", "1000"],
        "alfred --timeout 1e300": [*alf, "--timeout", "1e300"],
        "alfred --timeout nan": [*alf, "--timeout", "nan"],
        "alfred --timeout -5": [*alf, "--timeout", "-5"],
        "smartllm --timeout inf": ["bench", "smartllm", "--oracle", "-o", "{d}/s", "--timeout", "inf"],
        "plan --timeout 0": ["plan", PLATES, "--timeout", "0"],
        "plan --timeout 1e9": ["plan", PLATES, "--timeout", "1e9"],
        "plan --llm-timeout 1e12": ["plan", PLATES, "--llm-timeout", "1e12"],
        "plan --llm-timeout -1": ["plan", PLATES, "--llm-timeout", "-1"],
        "plan --llm-instruction-timeout nan": ["plan", PLATES, "--llm-instruction-timeout", "nan"],
        "plan --retries 1000": ["plan", PLATES, "--retries", "1000"],
        "plan --retries -1": ["plan", PLATES, "--retries", "-1"],
        "plan --threads 100000": ["plan", PLATES, "--threads", "100000"],
        "plan --robots 100": ["plan", PLATES, "--robots", "100"],
        "plan --robots 1000000000": ["plan", PLATES, "--robots", "1000000000"],
        "plan --robots 80 names": ["plan", PLATES, "--robots", ",".join(["robot1"] * 80)],
        "train --seed 99999999999": ["train", "language", "--seed", "99999999999", "-o", "{d}/m.npz"],
        "plan --temperature nan": ["plan", PLATES, "--temperature", "nan"],
    }
    return [Case("bounds", name, argv, {2}, 30) for name, argv in values.items()]


# ---------------------------------------------------------------- bad values: exit 2, not 4
def _team(text: str) -> Callable[[Path], None]:
    return lambda d: (d / "team.json").write_text(text)


def _spec(obj: Any) -> Callable[[Path], None]:
    return lambda d: (d / "spec.json").write_text(json.dumps(obj))


def bad_value_cases() -> list[Case]:
    team = ["plan", PLATES, "--robots", "{d}/team.json"]
    prof = '{"name": "a", "skills": ["PickupObject", "PutObject"], "mass": %s}'
    out = [Case("bad values", f"--robots {v}", ["plan", PLATES, "--robots", v], {2}, 30) for v in
           ["²", "½", "-1", "0", "robot1,,robot999", "a" * 5000, "robot1;robot2", "٣"]]  # fmt: skip
    for v in ["NaN", "Infinity", "-Infinity", "1e309", "-0", "0", "true", '"x"', "[1]"]:
        out.append(Case("bad values", f"team mass {v}", team, {2}, 30, setup=_team("[" + prof % v + "]")))
    for name, text in {
        "team empty list": "[]",
        "team 65 robots": json.dumps(["robot1"] * 65),
        "team unknown skill": '[{"name": "a", "skills": ["Fly"]}]',
        "team skills not a list": '[{"name": "a", "skills": 5}]',
        "team deep nesting": "[" * 5000 + "]" * 5000,
        "team a number": "42",
    }.items():
        out.append(Case("bad values", name, team, {2}, 30, setup=_team(text)))
    big = " & ".join(f"F p{i}" for i in range(120_000))
    for name, obj in {
        "check 120,000-atom formula": [{"root": big}],
        "check 70,000-way disjunction": [{"root": " | ".join(f"p{i}" for i in range(70_000))}],
    }.items():
        out.append(
            Case("bad values", name, ["check", "{d}/spec.json"], {2}, 60, setup=_spec(obj), words="too large")
        )
    out.append(
        Case(
            "bad values",
            "check --json 120,000 atoms",
            ["check", "{d}/spec.json", "--json"],
            {2},
            60,
            setup=_spec([{"root": big}]),
        )  # fmt: skip
    )
    out.append(Case("bad values", "show 120,000 atoms", ["show", "{d}/spec.json", "-o", "{d}/s.png"], {2}, 60,
                    setup=_spec([{"root": big}])))  # fmt: skip
    for url in ["::::", "localhost:8000", "http://", "ftp://h/v1", "http://h:0/v1", "http://[::1"]:
        out.append(Case("bad values", f"BASE_URL={url!r}", ["plan", PLATES], {2}, 30,
                        env={"NL2HLTL2PLAN_LLM_BASE_URL": url}, words="expected an http://"))  # fmt: skip
    out.append(Case("bad values", "BASE_URL blank: not configured", ["plan", PLATES], {0}, 60,
                    env={"NL2HLTL2PLAN_LLM_BASE_URL": " "}))  # fmt: skip
    for var, val in [
        ("TIMEOUT", "-1"),
        ("TIMEOUT", "1e300"),
        ("INSTRUCTION_TIMEOUT", "nan"),
        ("RETRIES", "99"),
        ("REASKS", "-1"),
        ("JSON", "bogus"),
        ("TEMPERATURE", "3"),
        ("MAX_TOKENS", "0"),
    ]:
        out.append(Case("bad values", f"NL2HLTL2PLAN_LLM_{var}={val}", ["plan", PLATES, *DEAD_LLM], {2}, 30,
                        env={f"NL2HLTL2PLAN_LLM_{var}": val}))  # fmt: skip
    return out


# ---------------------------------------------------------------- damaged data folders
def _data_copy(folder: Path) -> Path:
    """A copy of the data folder (real files; the big corpora that no case damages are linked)."""
    root = folder / "data"
    root.mkdir()
    for item in SHARED.iterdir():
        if item.name in ("alfred", "benchmark", "smartllm"):
            shutil.copytree(item, root / item.name)
        else:
            (root / item.name).symlink_to(item)
    for p in root.rglob("*"):
        if p.is_file() and not p.is_symlink():
            p.chmod(0o644)
    return root


def _damaged(relative: str, data: bytes | Callable[[bytes], bytes]) -> Callable[[Path], None]:
    def setup(folder: Path) -> None:
        target = _data_copy(folder) / relative
        assert not target.is_symlink() and SHARED not in target.resolve().parents
        target.write_bytes(data(target.read_bytes()) if callable(data) else data)

    return setup


def _npy(arr_maker: Callable[[], Any]) -> bytes:
    import io

    import numpy as np

    buf = io.BytesIO()
    np.save(buf, arr_maker(), allow_pickle=True)
    return buf.getvalue()


def data_cases() -> list[Case]:
    import numpy as np

    world = ["world", "FloorPlan17"]
    plan17 = ["plan", "put the apple in the fridge", "--world", "FloorPlan17", "--timeout", "20"]
    env = {"NL2HLTL2PLAN_DATA": "{d}/data"}
    damage = {
        "trials.jsonl.gz truncated": ("alfred/trials.jsonl.gz", lambda b: b[: len(b) // 3]),
        "trials.jsonl.gz garbage": ("alfred/trials.jsonl.gz", b"garbage" * 100),
        "trials.jsonl.gz empty": ("alfred/trials.jsonl.gz", b""),
        "trials.jsonl.gz bad JSON line": ("alfred/trials.jsonl.gz", __import__("gzip").compress(b'{"x": \n')),
        "trials.jsonl.gz record lacks fields": (
            "alfred/trials.jsonl.gz",
            __import__("gzip").compress(b'{"a": 1}\n'),
        ),
        "layout.npy truncated": ("alfred/layouts/FloorPlan17-layout.npy", lambda b: b[:50]),
        "layout.npy empty": ("alfred/layouts/FloorPlan17-layout.npy", b""),
        "layout.npy pickled objects": (
            "alfred/layouts/FloorPlan17-layout.npy",
            _npy(lambda: np.array([{"a": 1}], dtype=object)),
        ),
        "layout.npy 3 columns": ("alfred/layouts/FloorPlan17-layout.npy", _npy(lambda: np.zeros((5, 3)))),
        "layout.npy strings": ("alfred/layouts/FloorPlan17-layout.npy", _npy(lambda: np.array([["a", "b"]]))),
        "objects.json bad JSON": ("alfred/layouts/FloorPlan17-objects.json", b'{"bad'),
        "objects.json an object": ("alfred/layouts/FloorPlan17-objects.json", b'{"a": 1}'),
        "objects.json numbers": ("alfred/layouts/FloorPlan17-objects.json", b"[1, 2]"),
        "objects.json binary": ("alfred/layouts/FloorPlan17-objects.json", bytes(range(256))),
        "openable.json bad JSON": ("alfred/layouts/FloorPlan17-openable.json", b"[1, 2"),
        "openable.json a list": ("alfred/layouts/FloorPlan17-openable.json", b"[1, 2]"),
        "affordances.json bad": ("alfred/affordances.json", b"\xff\xfe"),
        "affordances.json a list": ("alfred/affordances.json", b"[]"),
    }
    out = []
    for name, (rel, data) in damage.items():
        out.append(Case("data files", f"world: {name}", world, {2}, 60, env=env, setup=_damaged(rel, data)))
    for name in ("trials.jsonl.gz truncated", "layout.npy truncated", "objects.json bad JSON"):
        rel, data = damage[name]
        out.append(Case("data files", f"plan: {name}", plan17, {2}, 60, env=env, setup=_damaged(rel, data)))
    out += [
        Case(
            "data files",
            "robots.json bad",
            ["plan", PLATES, "--robots", "robot1"],
            {2},
            30,
            env=env,
            setup=_damaged("smartllm/robots.json", b"{"),
        ),  # fmt: skip
        Case(
            "data files",
            "robots.json a list",
            ["plan", PLATES, "--robots", "robot1"],
            {2},
            30,
            env=env,
            setup=_damaged("smartllm/robots.json", b"[]"),
        ),  # fmt: skip
        Case(
            "data files",
            "smartllm tasks bad",
            ["bench", "smartllm", "--oracle", "-o", "{d}/s", "--quiet"],
            {2},
            60,
            env=env,
            setup=_damaged("smartllm/final_test_all.jsonl", b"{not json\n"),
        ),  # fmt: skip
        Case(
            "data files",
            "test50 gt bad",
            ["bench", "alfred", "--oracle", "-o", "{d}/a", "--quiet"],
            {2},
            60,
            env=env,
            setup=_damaged("benchmark/alfred_test50_gt.jsonl", b"[1,\n"),
        ),  # fmt: skip
        Case("data files", "NL2HLTL2PLAN_DATA is a file", world, {2}, 30, env={"NL2HLTL2PLAN_DATA": HTT}),
        Case(
            "data files", "NL2HLTL2PLAN_DATA missing", world, {2}, 30, env={"NL2HLTL2PLAN_DATA": "{d}/none"}
        ),
        Case(
            "data files", "NL2HLTL2PLAN_DATA empty folder", world, {2}, 30, env={"NL2HLTL2PLAN_DATA": "{d}"}
        ),
    ]
    return out


# ---------------------------------------------------------------- the exit contract
def contract_cases() -> list[Case]:
    busy = socket.socket()
    busy.bind(("127.0.0.1", 0))
    busy.listen(1)
    _keep.append(busy)
    port = str(busy.getsockname()[1])
    out = [
        Case("contract", f"serve --host {h!r}", ["serve", "--host", h, "--port", "8765"], {2}, 30,
             words="cannot listen")
        for h in ["256.1.1.1", "999.999.999.999", "1.2.3", "", "exa mple", "::::"]
    ]  # fmt: skip
    out.append(Case("contract", "serve on a busy port", ["serve", "--port", port], {2}, 30, words="in use"))
    out.append(Case("contract", "serve --port 70000", ["serve", "--port", "70000"], {2}, 30))
    pipes = {
        "spec | head -0": ["spec", HTT],
        "spec --json | head -0": ["spec", HTT, "--json"],
        "plan | head -0": ["plan", PLATES],
        "plan --json | head -0": ["plan", PLATES, "--json"],
        "world demo --json | head -0": ["world", "demo", "--json"],
        "--help | head -0": ["--help"],
        "plan --help | head -0": ["plan", "--help"],
        "world FloorPlan17 --json | head -0": ["world", "FloorPlan17", "--json"],
    }
    for name, argv in pipes.items():  # argparse writes --help itself and ignores a closed pipe: 0 there
        expect = {0, 141} if "--help" in argv else {141}
        out.append(Case("contract", name, argv, expect, 60, close_stdout=True))
    out += [
        Case("contract", "bare command", [], {2}, 30, words="error: nl2hltl2plan: no command given"),
        Case("contract", "bench without a suite", ["bench"], {2}, 30),
        Case("contract", "train without WHAT", ["train"], {2}, 30),
        Case("contract", "unknown command", ["frobnicate"], {2}, 30),
        Case("contract", "--version", ["--version"], {0}, 30),
        Case("contract", "plan of the demo", ["plan", PLATES], {0}, 60),
        Case("contract", "an infeasible plan is 1", ["plan", PLATES, "--timeout", "0.001"], {0, 1}, 60),
        Case(
            "contract",
            "check a valid spec is 0",
            ["check", "{d}/spec.json"],
            {0},
            30,
            setup=_spec([{"a": "F b"}]),
        ),
        Case(
            "contract",
            "check an invalid spec is 1",
            ["check", "{d}/spec.json"],
            {1},
            30,
            setup=_spec([{"a": "F(a &"}]),
        ),  # fmt: skip
        Case(
            "contract",
            "batch mode pending is 3",
            ["plan", PLATES, "--llm", "openai", "--batch-out", "{d}/b.jsonl"],
            {3},
            60,
        ),  # fmt: skip
        Case(
            "contract",
            "--batch-out on bench is refused",
            ["bench", "tabletop", "--out", "{d}/t", "--batch-out", "{d}/x"],
            {2},
            30,
        ),  # fmt: skip
    ]
    return out


# ---------------------------------------------------------------- LLM servers that misbehave
class Misbehaving:
    """One local HTTP server; the path prefix picks the behaviour (`/silent/v1`, `/trickle/v1` ...)."""

    def __init__(self) -> None:
        owner = self
        self.counts: Counter[str] = Counter()

        class Handler(BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def log_message(self, *a: Any) -> None:
                pass

            def do_POST(self) -> None:  # noqa: N802 - http.server API
                mode = self.path.strip("/").split("/")[0]
                self.rfile.read(int(self.headers.get("Content-Length", 0)))
                owner.counts[mode] += 1
                try:
                    owner.answer(self, mode, owner.counts[mode])
                except (BrokenPipeError, ConnectionResetError, OSError):
                    pass

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.server.daemon_threads = True
        self.server.handle_error = lambda *a: None  # type: ignore[method-assign]  # clients that hang up
        threading.Thread(target=self.server.serve_forever, args=(0.05,), daemon=True).start()
        self.port = self.server.server_address[1]

    def url(self, mode: str) -> str:
        return f"http://127.0.0.1:{self.port}/{mode}/v1"

    @staticmethod
    def send(
        h: BaseHTTPRequestHandler, status: int, body: bytes, headers: dict[str, str] | None = None
    ) -> None:
        h.send_response(status)
        for k, v in {"Content-Type": "application/json", **(headers or {})}.items():
            h.send_header(k, v)
        h.send_header("Content-Length", str(len(body)))
        h.end_headers()
        h.wfile.write(body)

    @staticmethod
    def chat(content: str) -> bytes:
        message = {"role": "assistant", "content": content}
        choice = {"index": 0, "finish_reason": "stop", "message": message}
        return json.dumps({"id": "x", "object": "chat.completion", "created": 0, "model": "m",
                           "choices": [choice]}).encode()  # fmt: skip

    def answer(self, h: BaseHTTPRequestHandler, mode: str, n: int) -> None:
        err = b'{"error": {"message": "no", "type": "x"}}'
        if mode == "silent":
            time.sleep(3600)
        elif mode == "trickle":
            h.send_response(200)
            h.send_header("Content-Type", "application/json")
            h.send_header("Content-Length", "100000")
            h.end_headers()
            for _ in range(3600):
                h.wfile.write(b" ")
                h.wfile.flush()
                time.sleep(1)
        elif mode == "ra3600":
            self.send(h, 429, err, {"Retry-After": "3600"})
        elif mode == "radate":
            self.send(h, 503, err, {"Retry-After": "Wed, 21 Oct 2099 07:28:00 GMT"})
        elif mode == "ra1":
            self.send(h, 429, err, {"Retry-After": "1"}) if n == 1 else self.send(
                h, 200, self.chat("not json")
            )
        elif mode == "ra-junk":
            self.send(h, 429, err, {"Retry-After": "soon"})
        elif mode == "429":
            self.send(h, 429, err)
        elif mode == "500":
            self.send(h, 500, err)
        elif mode == "401":
            self.send(h, 401, err)
        elif mode == "404":
            self.send(h, 404, err)
        elif mode == "html":
            self.send(h, 200, b"<html><body>Bad gateway</body></html>", {"Content-Type": "text/html"})
        elif mode == "empty":
            self.send(h, 200, b"")
        elif mode == "binary":
            self.send(h, 200, bytes(range(256)) * 10, {"Content-Type": "application/octet-stream"})
        elif mode == "brackets":
            self.send(h, 200, self.chat("[" * 200_000))
        elif mode == "deep-body":
            self.send(h, 200, b"[" * 200_000)
        elif mode == "huge":
            self.send(h, 200, self.chat("x" * 5_000_000))
        elif mode == "list":
            self.send(h, 200, b"[1, 2, 3]")
        elif mode == "no-choices":
            self.send(h, 200, b'{"choices": []}')
        elif mode == "null-content":
            self.send(h, 200, b'{"choices": [{"message": {"content": null}}]}')
        elif mode == "wrong-json":
            self.send(h, 200, self.chat('{"tasks": "many"}'))
        elif mode == "cut":
            h.send_response(200)
            h.send_header("Content-Length", "5000")
            h.end_headers()
            h.wfile.write(b'{"choices": [')
            h.close_connection = True
        elif mode == "close":
            h.close_connection = True
            h.connection.shutdown(socket.SHUT_RDWR)
        elif mode == "slow-ok":
            time.sleep(2)
            self.send(h, 200, self.chat("not json either"))


def llm_cases(server: Misbehaving) -> list[Case]:
    fast = ["--llm-timeout", "2", "--llm-instruction-timeout", "4", "--cache", "off", "--api-key", "k"]
    modes = {
        "silent": 15, "trickle": 15, "ra3600": 10, "radate": 10, "ra1": 20, "ra-junk": 15, "429": 15,
        "500": 15, "401": 10, "404": 10, "html": 15, "empty": 15, "binary": 15, "brackets": 20,
        "deep-body": 15, "huge": 30, "list": 15, "no-choices": 15, "null-content": 15, "wrong-json": 20,
        "cut": 15, "close": 15, "slow-ok": 20,
    }  # fmt: skip
    out = [
        Case(
            "LLM server",
            mode,
            ["plan", PLATES, "--llm", "openai", "--base-url", server.url(mode), *fast],
            {2},
            limit,
        )  # fmt: skip
        for mode, limit in modes.items()
    ]
    default = ["plan", PLATES, "--llm", "openai", "--cache", "off", "--api-key", "k"]
    out += [
        Case(
            "LLM server",
            "silent, default deadlines (60 s)",
            [*default, "--base-url", server.url("silent")],
            {2},
            75,
            words="deadline",
        ),  # fmt: skip
        Case(
            "LLM server",
            "ra3600, default deadlines",
            [*default, "--base-url", server.url("ra3600")],
            {2},
            20,
            words="asks to retry after 3600s",
        ),  # fmt: skip
        Case("LLM server", "connection refused", [*default, "--base-url", "http://127.0.0.1:9/v1"], {2}, 75),
    ]
    return out


# ---------------------------------------------------------------- kills while writing (data loss)
def _whole_outputs(folder: Path) -> str | None:
    """Every file in out/ is the old one or a whole new one (JSON parses, PNG ends with IEND)."""
    out = folder / "out"
    for p in sorted(out.glob("*")) if out.exists() else []:
        if p.name.startswith("."):
            continue  # a temporary file a kill left behind: never read as output
        data = p.read_bytes()
        if p.suffix == ".json":
            try:
                json.loads(data)
            except ValueError:
                return f"{p.name} is torn ({len(data)} bytes)"
        elif p.suffix == ".png" and data != b"old" and not data.rstrip(b"\x00").endswith(b"IEND\xaeB`\x82"):
            return f"{p.name} is not a whole PNG ({len(data)} bytes)"
    return None


def _old_outputs(folder: Path) -> None:
    out = folder / "out"
    out.mkdir()
    (out / "result.json").write_text('{"old": true}')
    (out / "summary.json").write_text('{"old": true}')
    for name in ("htt.png", "world.png", "plan.png", "gantt.png", "x.png"):
        (out / name).write_bytes(b"old")


def _model_loads(folder: Path) -> str | None:
    path = folder / "cache" / "nl2hltl2plan" / "models" / "slot_model.npz"
    if not path.exists():
        return None  # killed before writing: the packaged model is used
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "XDG_CACHE_HOME": str(folder / "cache")}
    code = "from nl2hltl2plan.language.learned.slot_model import SlotModel; SlotModel.load()"
    res = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, timeout=120)
    return None if res.returncode == 0 else f"the user model does not load: {res.stderr[-200:]!r}"


def _unchanged(name: str, content: str) -> Callable[[Path], str | None]:
    def check(folder: Path) -> str | None:
        p = folder / name
        return None if p.exists() and p.read_text() == content else f"{name} was changed or removed"

    return check


def kill_cases() -> list[Case]:
    out = []
    for d in (0.0, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.2, 1.6, 2.0, 2.5, 3.0):
        out.append(Case("kills", f"plan -o killed {d}s into writing", ["plan", PLATES, "-o", "{d}/out"], {0},
                        90, setup=_old_outputs, check=_whole_outputs, kill_on_write=("out", d)))  # fmt: skip
    for d in (0.0, 0.01, 0.05):
        out.append(Case("kills", f"bench tabletop killed {d}s into writing",
                        ["bench", "tabletop", "--out", "{d}/out", "--instances", "1", "--baseline", "none"],
                        {0}, 180, setup=_old_outputs, check=_whole_outputs,
                        kill_on_write=("out", d)))  # fmt: skip
    models = "cache/nl2hltl2plan/models"
    for d in (0.0, 0.005, 0.02, 0.1):  # the model is written once, at the end of 20-40 s of training
        out.append(Case("kills", f"train language killed {d}s into writing", ["train", "language"], {0}, 180,
                        check=_model_loads, kill_on_write=(models, d)))  # fmt: skip
    for d in (0.0, 0.01):
        out.append(Case("kills", f"show -o killed {d}s into writing", ["show", HTT, "-o", "{d}/out/x.png"],
                        {0}, 60, setup=_old_outputs, check=_whole_outputs,
                        kill_on_write=("out", d)))  # fmt: skip
    out += [
        Case(
            "kills",
            "--batch-out onto an existing file",
            ["plan", PLATES, "--llm", "openai", "--batch-out", "{d}/b.jsonl"],
            {2},
            30,
            setup=lambda d: (d / "b.jsonl").write_text("keep\n"),
            check=_unchanged("b.jsonl", "keep\n"),
            words="exists already",
        ),  # fmt: skip
        Case(
            "kills",
            "show -o into a file's folder",
            ["show", HTT, "-o", "{d}/f.txt/x.png"],
            {2},
            30,
            setup=lambda d: (d / "f.txt").write_text("keep"),
            check=_unchanged("f.txt", "keep"),
        ),  # fmt: skip
        Case(
            "kills",
            "plan -o is a file",
            ["plan", PLATES, "-o", "{d}/f.txt"],
            {2},
            30,
            setup=lambda d: (d / "f.txt").write_text("keep"),
            check=_unchanged("f.txt", "keep"),
        ),  # fmt: skip
        Case("kills", "train -o unknown format", ["train", "language", "-o", "{d}/m.pkl"], {2}, 30),
        Case("kills", "train -o a folder", ["train", "language", "-o", "{d}"], {2}, 30),
    ]
    return out


# ---------------------------------------------------------------- main
def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("work", type=Path)
    ap.add_argument("--report", type=Path, default=None)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default=None, help="run only the cases whose area or name contains this")
    args = ap.parse_args()
    args.work.mkdir(parents=True, exist_ok=True)
    server = Misbehaving()
    cases = (
        input_cases() + length_cases() + bound_cases() + bad_value_cases() + data_cases() + contract_cases()
        + llm_cases(server) + kill_cases()
    )  # fmt: skip
    if args.only:
        cases = [c for c in cases if args.only in c.area or args.only in c.name]
    print(f"{len(cases)} cases, {args.jobs} at a time", flush=True)
    results: list[Result] = []
    lock = threading.Lock()
    todo = list(cases)
    t_all = time.monotonic()

    def worker() -> None:
        while True:
            with lock:
                if not todo:
                    return
                case = todo.pop(0)
            res = run_case(case, args.work)
            with lock:
                results.append(res)
                print(f"{res.verdict:12s} {res.seconds:6.1f}s {case.area:11s} {case.name[:60]:60s} "
                      f"{res.detail[:110]}", flush=True)  # fmt: skip

    threads = [threading.Thread(target=worker) for _ in range(args.jobs)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    total = round(time.monotonic() - t_all)
    order = {id(c): k for k, c in enumerate(cases)}
    results.sort(key=lambda r: order[id(r.case)])
    verdicts = Counter(r.verdict for r in results)
    print(f"\n{len(results)} cases in {total}s: " + ", ".join(f"{v} {n}" for v, n in verdicts.most_common()))
    if args.report:
        write_report(args.report, results, total)


def write_report(path: Path, results: list[Result], total: int) -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, cwd=ROOT)
    dirty = subprocess.run(["git", "status", "--porcelain", "src"], capture_output=True, text=True, cwd=ROOT)
    verdicts = Counter(r.verdict for r in results)
    areas = Counter(r.case.area for r in results)
    lines = [
        "# Fault campaign of issue 25 (reliability)",
        "",
        "Command: `PYTHONPATH=src python3 tests/reliability/campaign25.py /tmp/campaign25 "
        "--report results/reliability/report.md`  ",
        f"Commit: {commit.stdout.strip()}"
        + (" (uncommitted changes in src/)" if dirty.stdout.strip() else "")
        + "  ",
        f"Machine: {platform.node()}, {os.cpu_count()} cores (shared with other work), Python "
        f"{platform.python_version()}, {platform.system()} {platform.release()}  ",
        f"Wall time: {total} s, 2 cases at a time",
        "",
        f"**{len(results)} cases: {verdicts.get('ok', 0)} as documented, "
        f"{verdicts.get('traceback', 0)} tracebacks, "
        f"{verdicts.get('hang', 0)} hangs, {verdicts.get('data loss', 0)} data loss, "
        f"{verdicts.get('wrong status', 0)} wrong exit statuses, "
        f"{verdicts.get('bad message', 0)} bad messages.**",
        "",
        "Every case runs `python -m nl2hltl2plan ...` in a child process with a time limit "
        "(tests/reliability/campaign25.py says how each is judged); a kill case shows exit -9 (the "
        "campaign's SIGKILL, sent a set delay after the command's first write is seen) and is judged on "
        "its files. None of these cases is in the earlier "
        "campaigns (tests/reliability/campaign.py, 104 cases, and the 398-case campaign of the issue).",
        "",
        "| area | cases |",
        "| --- | --- |",
        *[f"| {a} | {n} |" for a, n in areas.items()],
        "",
        "| area | case | expected | exit | s | verdict | what the user sees (last stderr line) |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in results:
        detail = r.detail.replace("|", "\\|").replace("\n", " ")[:160]
        name = r.case.name.replace("|", "\\|")
        lines.append(f"| {r.case.area} | {name} | {'/'.join(map(str, sorted(r.case.expect)))} | {r.code} | "
                     f"{r.seconds} | {r.verdict} | {detail} |")  # fmt: skip
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
