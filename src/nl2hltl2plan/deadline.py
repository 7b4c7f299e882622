"""One way to run a function in a forked child with a deadline and a memory limit.

Used by the Spot translation (native code that Python cannot interrupt) and by the benchmark
runner's workers. Every child

- dies with its parent: on Linux `prctl(PR_SET_PDEATHSIG, SIGKILL)`, so a killed run leaves no
  orphaned worker (and a worker's own children die with the worker, and so on down);
- optionally leads its own process group (`own_group`), so a kill also ends what the job started;
- optionally has its address space limited (`RLIMIT_AS`, counted on top of what the fork inherited),
  so a runaway allocation ends in the child instead of swapping the machine;
- reports its result, or its exception as one line of text, through a pipe.

`run_with_deadline(fn, arg, timeout_s, memory_mb)` is the blocking form; `Child` is the handle for
callers that run many at once (`wait_any`). Layer-neutral: imports only `errors`.
"""

from __future__ import annotations

import ctypes
import faulthandler
import math
import multiprocessing as mp
import os
import resource
import signal
import sys
import time
import traceback
from collections.abc import Callable, Sequence
from multiprocessing.connection import Connection, wait
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError

PR_SET_PDEATHSIG = 1
_MIB = 1 << 20


class ChildError(Nl2Hltl2PlanError):
    """A child run failed; `kind` is "timeout", "memory", "died", "error" or "invalid" (bad limit)."""

    def __init__(self, kind: str, message: str) -> None:
        super().__init__(message)
        self.kind = kind


def die_with_parent(parent_pid: int) -> None:
    """Ask the kernel to SIGKILL this process when its parent dies (Linux; elsewhere a no-op)."""
    if sys.platform.startswith("linux"):
        try:
            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        except (OSError, AttributeError):  # no prctl: nothing better to do than run on
            pass
    if os.getppid() != parent_pid:  # the parent died before prctl took effect
        os._exit(1)


def limit_memory(extra_mb: float) -> None:
    """Cap this process's address space at its current size plus `extra_mb` MiB."""
    try:
        with open("/proc/self/statm") as f:
            current = int(f.read().split()[0]) * resource.getpagesize()
    except (OSError, ValueError, IndexError):
        current = 0
    cap = current + int(extra_mb * _MIB)
    _soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard != resource.RLIM_INFINITY:
        cap = min(cap, hard)
    resource.setrlimit(resource.RLIMIT_AS, (cap, hard))


def describe_exception(exc: BaseException) -> str:
    """`Type: message at file.py:line` (one line; our own errors without the location)."""
    text = " ".join(str(exc).split())
    if isinstance(exc, Nl2Hltl2PlanError):
        return text
    tb = traceback.extract_tb(exc.__traceback__)
    where = f" at {os.path.basename(tb[-1].filename)}:{tb[-1].lineno}" if tb else ""
    return f"{type(exc).__name__}: {text}{where}"


def _child_main(
    fn: Callable[[Any], Any],
    arg: Any,
    conn: Connection,
    parent_pid: int,
    memory_mb: float | None,
    own_group: bool,
    quiet: bool,
) -> None:
    die_with_parent(parent_pid)
    if own_group:
        os.setpgid(0, 0)
    if quiet:  # native code may print (std::bad_alloc ...) before dying: the parent reports instead
        faulthandler.disable()
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 2)
    if memory_mb is not None:
        limit_memory(memory_mb)
    try:
        reply: tuple[str, Any] = ("ok", fn(arg))
    except MemoryError:
        reply = ("memory", "")
    except BaseException as exc:  # every failure goes back to the parent as data
        reply = ("error", describe_exception(exc))
    try:
        conn.send(reply)
    except MemoryError:
        conn.send(("memory", ""))
    except Exception as exc:  # a result that cannot be pickled
        conn.send(("error", f"the result could not be sent back: {describe_exception(exc)}"))
    finally:
        conn.close()


class Child:
    """One forked run of `fn(arg)`; poll `conn` (or use `wait_any`) and then call `result()`."""

    def __init__(
        self,
        fn: Callable[[Any], Any],
        arg: Any,
        *,
        memory_mb: float | None = None,
        own_group: bool = False,
        quiet: bool = False,
    ) -> None:
        ctx = mp.get_context("fork")
        self.conn, child_end = ctx.Pipe(duplex=False)
        self.memory_mb = memory_mb
        # not a daemon: the job may fork children of its own (they die with it, see die_with_parent)
        self.proc = ctx.Process(
            target=_child_main, args=(fn, arg, child_end, os.getpid(), memory_mb, own_group, quiet)
        )
        self.own_group = own_group
        self.proc.start()
        child_end.close()
        self.started = time.monotonic()

    def elapsed(self) -> float:
        return time.monotonic() - self.started

    def result(self) -> Any:
        """The child's return value; ChildError when it raised, ran out of memory or died."""
        try:
            status, payload = self.conn.recv()
        except (EOFError, OSError):
            self.proc.join(timeout=5)
            code = self.proc.exitcode
            why = f"signal {-code}" if code is not None and code < 0 else f"exit code {code}"
            raise ChildError("died", f"the child process died of {why}") from None
        finally:
            self.close()
        if status == "ok":
            return payload
        if status == "memory":
            limit = f" (limit: {self.memory_mb:g} MiB above the parent)" if self.memory_mb is not None else ""
            raise ChildError("memory", f"ran out of memory{limit}")
        raise ChildError("error", str(payload))

    def kill(self) -> None:
        """Kill the child (and its process group when it leads one) and reap it."""
        pid = self.proc.pid
        if pid is not None and self.proc.is_alive():
            try:
                if self.own_group:
                    os.killpg(pid, signal.SIGKILL)
                else:
                    os.kill(pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                self.proc.kill()
        self.close()

    def close(self) -> None:
        self.conn.close()
        self.proc.join(timeout=5)


def wait_any(children: Sequence[Child], timeout_s: float) -> list[Child]:
    """The children whose answer (or death) is ready within `timeout_s` seconds."""
    by_conn = {c.conn: c for c in children}
    return [by_conn[c] for c in wait(list(by_conn), timeout=timeout_s)]  # type: ignore[index]


def check_timeout(timeout_s: float) -> float:
    if not isinstance(timeout_s, (int, float)) or not math.isfinite(timeout_s) or timeout_s <= 0:
        raise ChildError("invalid", f"a time limit must be a finite number of seconds > 0, got {timeout_s!r}")
    return float(timeout_s)


def run_with_deadline(
    fn: Callable[[Any], Any],
    arg: Any,
    timeout_s: float,
    memory_mb: float | None = None,
    quiet: bool = False,
) -> Any:
    """`fn(arg)` in a forked child; ChildError("timeout") after `timeout_s` s, ("memory") past the
    limit, ("died") when the child was killed (native code failing to allocate aborts)."""
    timeout_s = check_timeout(timeout_s)
    child = Child(fn, arg, memory_mb=memory_mb, quiet=quiet)
    try:
        if not child.conn.poll(timeout_s):
            raise ChildError("timeout", f"took longer than {timeout_s:g} s")
        return child.result()
    finally:
        child.kill()
