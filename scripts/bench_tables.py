"""Where a benchmark script's table goes: stdout, and with `--out FILE` also a markdown file that
starts with the command, the commit and the machine (so an unattended run documents itself). The
commit is read when the script starts (`STARTED`), the load average when it ends. The planner scripts
also share their run files: `--jsonl` (one line per run, appended as it finishes) and `--from-jsonl`
(only the table of a file's runs)."""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any


def _commit() -> str:
    """The checked-out commit, marked when the tree has uncommitted changes."""
    root = Path(__file__).resolve().parent.parent
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=root, capture_output=True,
                                text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=root,
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown (no git)"
    return commit + (" (with uncommitted changes)" if dirty else "")


STARTED = _commit()  # read when the benchmark script imports this module, before it measures


def provenance() -> list[str]:
    """The command line, the commit measured and the machine."""
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    return [
        f"command: `python {' '.join(sys.argv)}`",
        f"commit: {STARTED}",
        f"machine: {platform.platform()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
        f"load average at the end: {load}",
    ]


def emit(lines: list[str], out: str | None) -> None:
    """Print the table; with `out`, also write it there after its provenance."""
    text = "\n".join(lines)
    print(text)
    if out:
        Path(out).write_text("\n\n".join(["\n".join(provenance()), text]) + "\n")


def add_run_file_arguments(ap: argparse.ArgumentParser, unit: str = "run") -> None:
    """--jsonl, --from-jsonl and --out, as every planner benchmark script takes them."""
    ap.add_argument("--jsonl", default=None, help=f"also append one JSON line per {unit} to this file")
    ap.add_argument("--from-jsonl", default=None, help="only print the table of the runs in this file")
    ap.add_argument("--out", default=None, help="also write the table here (with command, commit, machine)")


def emit_from_jsonl(args: argparse.Namespace, table: Callable[[list[dict[str, Any]]], list[str]]) -> bool:
    """With --from-jsonl, emit the table of that file's runs and say so (no benchmark runs then)."""
    if not args.from_jsonl:
        return False
    with open(args.from_jsonl) as fh:
        emit(table([json.loads(line) for line in fh]), args.out)
    return True


def append_jsonl(path: str | None, row: dict[str, Any]) -> None:
    """Append `row` as one JSON line to `path` (nothing without one): a killed run keeps what it did."""
    if path:
        with open(path, "a") as fh:
            fh.write(json.dumps(row) + "\n")
