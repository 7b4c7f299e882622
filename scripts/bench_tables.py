"""Where a benchmark script's table goes: stdout, and with `--out FILE` also a markdown file that
starts with the command, the commit and the machine (so an unattended run documents itself). The
commit is read when the script starts (`STARTED`), the load average when it ends."""

from __future__ import annotations

import os
import platform
import subprocess
import sys
from pathlib import Path


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
