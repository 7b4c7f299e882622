"""The one process-with-deadline runner: results, errors, limits, and no orphans when a parent dies."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from nl2hltl2plan.deadline import ChildError, run_with_deadline


def _square(x: int) -> int:
    return x * x


def _boom(_: object) -> None:
    raise ValueError("no good")


def _sleep(s: float) -> None:
    time.sleep(s)


def _allocate(mb: int) -> int:
    return len(bytearray(mb << 20))


def test_result_error_timeout_and_memory():
    assert run_with_deadline(_square, 7, timeout_s=5) == 49
    with pytest.raises(ChildError, match=r"ValueError: no good at test_deadline.py:\d+") as exc:
        run_with_deadline(_boom, None, timeout_s=5)
    assert exc.value.kind == "error"
    t0 = time.monotonic()
    with pytest.raises(ChildError, match="took longer than 0.3 s"):
        run_with_deadline(_sleep, 30, timeout_s=0.3)
    assert time.monotonic() - t0 < 3
    with pytest.raises(ChildError) as exc:
        run_with_deadline(_allocate, 400, timeout_s=10, memory_mb=100)
    assert exc.value.kind == "memory" and "100 MiB" in str(exc.value)
    assert run_with_deadline(_allocate, 10, timeout_s=10, memory_mb=100) == 10 << 20


@pytest.mark.parametrize("bad", [0, -2, float("nan"), float("inf")])
def test_bad_time_limits_are_refused(bad):
    with pytest.raises(ChildError, match="finite number of seconds > 0"):
        run_with_deadline(_square, 1, timeout_s=bad)


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(") ")[1][0] != "Z"  # a zombie is dead
    except (FileNotFoundError, IndexError):
        return False


PARENT = textwrap.dedent(
    """
    import os, sys, time
    from pathlib import Path
    from nl2hltl2plan.deadline import run_with_deadline
    from nl2hltl2plan.suites.runner import Scenario, run_scenarios

    pids = Path(sys.argv[1])

    def grandchild(_):
        with pids.open("a") as f:
            f.write(f"{os.getpid()}\\n")
        time.sleep(120)

    def job(scenario):
        with pids.open("a") as f:
            f.write(f"{os.getpid()}\\n")
        run_with_deadline(grandchild, None, timeout_s=120)  # a worker's own child (a Spot translation)
        return {"status": "solved"}

    run_scenarios([Scenario(f"s{i}", 1, 1) for i in range(2)], job, Path(sys.argv[2]), workers=2,
                  hard_timeout_s=120, notes=None)
    """
)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG is Linux only")
def test_killing_the_parent_takes_workers_and_their_children_with_it(tmp_path: Path):
    script = tmp_path / "parent.py"
    script.write_text(PARENT)
    pids_file = tmp_path / "pids"
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).parents[2] / "src")}
    argv = [sys.executable, str(script), str(pids_file), str(tmp_path / "rows.jsonl")]
    parent = subprocess.Popen(argv, env=env)
    pids: list[int] = []
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            pids = [int(x) for x in pids_file.read_text().split()] if pids_file.exists() else []
            if len(pids) == 4:  # two workers, each with one child
                break
            time.sleep(0.05)
        assert len(pids) == 4, pids
        assert all(_alive(p) for p in pids)
        parent.send_signal(signal.SIGKILL)
        parent.wait()
        deadline = time.monotonic() + 5
        while any(_alive(p) for p in pids) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not [p for p in pids if _alive(p)], "orphaned workers survived their parent"
    finally:
        if parent.poll() is None:
            parent.kill()
        for p in pids:  # when the test fails, do not leave its processes behind
            if _alive(p):
                os.kill(p, signal.SIGKILL)


def _unpicklable(_: object) -> object:
    return lambda: 0


def test_a_result_that_cannot_be_sent_back_is_an_error():
    with pytest.raises(ChildError, match="the result could not be sent back: .*pickle"):
        run_with_deadline(_unpicklable, None, timeout_s=5)
