"""Start-up time of the CLI, measured against the interpreter's own (issue: a fast CLI).

Runs, alternately and `--repeat` times each, `python -c "import argparse"` (the floor: an interpreter
that parses arguments), `nl2hltl2plan --help`, and `nl2hltl2plan COMMAND --help` for every command
(the import cost a command pays on top of its real work). Prints a markdown table of medians and the
ratio to the floor; `-o` writes it to a report with the command, commit and machine.

    python scripts/bench_startup.py --repeat 15 -o results/startup/report.md
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

from nl2hltl2plan.cli.commands import COMMANDS

CLI = [sys.executable, "-m", "nl2hltl2plan.cli.main"]


def _seconds(argv: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - t0


def measure(repeat: int) -> dict[str, list[float]]:
    cases = {"python -c 'import argparse'": [sys.executable, "-c", "import argparse"],
             "nl2hltl2plan --help": [*CLI, "--help"]}
    cases |= {f"nl2hltl2plan {name} --help": [*CLI, name, "--help"] for name in COMMANDS}
    times: dict[str, list[float]] = {name: [] for name in cases}
    for _ in range(repeat):  # alternate, so that a change of load hits every case alike
        for name, argv in cases.items():
            times[name].append(_seconds(argv))
    return times


def report(times: dict[str, list[float]], repeat: int) -> str:
    floor = statistics.median(next(iter(times.values())))
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout
    lines = [
        "# CLI start-up",
        "",
        f"Command: `python scripts/bench_startup.py --repeat {repeat} -o results/startup/report.md`  ",
        f"Commit: {commit.strip() or 'unknown'}; machine: {platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}; each case run {repeat} times, alternating.",
        "",
        "| command | median s | max s | x floor |",
        "| --- | ---: | ---: | ---: |",
    ]
    for name, ts in times.items():
        med = statistics.median(ts)
        lines.append(f"| `{name}` | {med:.3f} | {max(ts):.3f} | {med / floor:.1f} |")
    return "\n".join(lines) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=15, help="runs of each case (default 15)")
    ap.add_argument("-o", "--out", type=Path, default=None, help="write the report here too")
    args = ap.parse_args()
    text = report(measure(args.repeat), args.repeat)
    print(text)
    if args.out:
        args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
