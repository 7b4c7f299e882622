"""Regenerate every committed `results/<suite>/` with the command that made it.

    python scripts/reproduce_results.py              # the quick suites (a few minutes on 2 cores)
    python scripts/reproduce_results.py --slow       # also the slow ones (handover, ALFRED: an hour+)
    python scripts/reproduce_results.py --only tabletop,handover

Each suite is run through the `nl2hltl2plan bench ...` command listed in SUITES, into results/<suite>/;
then its report.md gets a provenance section: the command, the commit (with "+ uncommitted changes"
when the tree is dirty) and the machine. tests/experiments/test_reproduce.py reruns the cheap suites
and compares them with the committed summary.json, so a result the code no longer produces fails CI.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from nl2hltl2plan.io import machine_description

ROOT = Path(__file__).resolve().parent.parent


@dataclass(frozen=True)
class Suite:
    name: str
    args: tuple[str, ...]  # after `nl2hltl2plan`; the output folder is appended
    slow: bool = False


SUITES = (
    Suite("smartllm_oracle", ("bench", "smartllm", "--oracle")),
    Suite("smartllm_offline", ("bench", "smartllm", "--llm", "offline")),
    Suite("tabletop", ("bench", "tabletop", "--instances", "25", "--seed", "0", "--baseline", "none")),
    Suite(
        "handover",
        ("bench", "handover", "--instances", "10", "--seed", "0", "--llm", "offline", "--baseline", "none"),
        slow=True,
    ),
    Suite(
        "alfred_oracle",
        ("bench", "alfred", "--oracle", "--robots", "1,2,4", "--workers", "2", "--fresh"),
        True,
    ),
    Suite(
        "alfred_offline",
        ("bench", "alfred", "--llm", "offline", "--robots", "1,2,4", "--workers", "1", "--fresh"),
        True,
    ),
    Suite(  # the same, with every bare plural of more than two refused, as `plan` does by default
        "alfred_offline_ask",
        ("bench", "alfred", "--llm", "offline", "--plurals", "ask", "--robots", "1,2,4", "--workers", "1")
        + ("--fresh",),
        True,
    ),
)
PROVENANCE = "## Provenance"


def commit() -> str:
    def git(*args: str) -> str:
        return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True).stdout.strip()

    head = git("rev-parse", "--short", "HEAD") or "unknown"
    # the state of what makes the results (the package and its data), not of tests, docs or results
    dirty = bool(git("status", "--porcelain", "--untracked-files=no", "--", "src", "pyproject.toml"))
    return head + (" + uncommitted changes" if dirty else "")


def command_line(suite: Suite, out: Path) -> list[str]:
    return ["nl2hltl2plan", *suite.args, "-o", str(out)]


def stamp(report: Path, command: list[str], seconds: float) -> None:
    """Replace the report's provenance section with this run's command, commit and machine."""
    text = report.read_text() if report.exists() else ""
    text = text.split("\n" + PROVENANCE)[0].rstrip("\n")
    lines = [PROVENANCE, "", f"Command: `{' '.join(command)}`  ", f"Commit: {commit()}  "]
    lines += [f"Machine: {machine_description()}  ", f"Wall time: {seconds:.0f} s"]
    text += "\n\n" + "\n".join(lines) + "\n"
    report.write_text(text)


def run(suite: Suite, results: Path) -> int:
    out = results / suite.name
    command = command_line(suite, out.relative_to(ROOT) if out.is_relative_to(ROOT) else out)
    print(f"[{suite.name}] {' '.join(command)}", file=sys.stderr)
    t0 = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, stdout=subprocess.DEVNULL)
    if done.returncode != 0:
        print(f"[{suite.name}] failed with exit status {done.returncode}", file=sys.stderr)
        return done.returncode
    stamp(out / "report.md", command, time.perf_counter() - t0)
    return 0


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--slow", action="store_true", help="also the slow suites (handover, ALFRED)")
    p.add_argument("--only", default="", help="comma-separated suite names (default: all quick ones)")
    p.add_argument("--results", type=Path, default=ROOT / "results", help="where results/<suite>/ live")
    args = p.parse_args(argv)
    names = {n for n in args.only.split(",") if n}
    unknown = names - {s.name for s in SUITES}
    if unknown:
        print(f"error: unknown suite(s) {', '.join(sorted(unknown))}", file=sys.stderr)
        return 2
    chosen = (
        [s for s in SUITES if s.name in names] if names else [s for s in SUITES if args.slow or not s.slow]
    )
    failed = [s.name for s in chosen if run(s, args.results.resolve()) != 0]
    if failed:
        print(f"error: {', '.join(failed)} failed", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
