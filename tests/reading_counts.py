"""How often a test run reads the same instruction again, and what the repeats cost (off by default).

`NL2HLTL2PLAN_COUNT_READINGS=<folder> python -m pytest ...` makes `tests/conftest.py` wrap the household
reader (`language.translate.translate`, which every world's reading goes through) before any test module
imports it; each test process writes one JSON line per outermost call to `<folder>/<worker>.jsonl`: the
call's key (the text, the world's content, the backend and every option) and its CPU seconds
(`time.process_time`). `python tests/reading_counts.py <folder>` then prints the calls, the distinct keys
per process and per run, and the CPU of the repeats, by test file (results/reliability/test_suite_time.md,
round h162). Commands the tests start (the CLI, the scripts) run in other processes and are not counted.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import threading
import time
from collections import Counter, defaultdict
from collections.abc import Callable
from pathlib import Path
from typing import Any

import nl2hltl2plan.language.translate as reader


def world_key(world: Any) -> str | None:
    """The world as far as a reading can see it: its name, kind, plural convention and every object (a
    world is rebuilt per test, so identity would miss repeats on equal worlds)."""
    if world is None:
        return None
    if getattr(world, "objects", None) is None:  # a scene that only names its types
        return repr((type(world).__qualname__, world.name, sorted(world.object_types())))
    objects = sorted(world.objects.items())
    seen = repr((world.name, world.kind, world.plurals, sorted(world.unplaced.items()), objects))
    return f"{world.name}:{hashlib.sha1(seen.encode()).hexdigest()[:16]}"


def install(folder: str) -> Callable[[], None]:
    """Wrap the reader; returns the function that unwraps it and writes this process's calls."""
    original = reader.translate
    depth = threading.local()
    rows: list[dict[str, Any]] = []

    def counted(instruction: str, world: object = None, backend: str = "offline", client: object = None,
                **options: Any) -> Any:
        outer = not getattr(depth, "inside", False)
        depth.inside = True
        start = time.process_time()
        try:
            return original(instruction, world, backend, client, **options)  # type: ignore[arg-type]
        finally:
            if outer:
                depth.inside = False
                cpu = time.process_time() - start
                said = sorted((k, repr(v) if callable(v) else v) for k, v in options.items())
                key = [instruction, world_key(world), backend, client is None, repr(said)]
                test = os.environ.get("PYTEST_CURRENT_TEST", "").split(" ")[0]
                rows.append({"key": key, "cpu": cpu, "test": test})

    reader.translate = counted  # type: ignore[assignment]

    def finish() -> None:
        reader.translate = original
        name = os.environ.get("PYTEST_XDIST_WORKER", "main")
        Path(folder).mkdir(parents=True, exist_ok=True)
        with open(Path(folder) / f"{name}.jsonl", "a") as out:
            out.writelines(json.dumps(row) + "\n" for row in rows)

    return finish


def summary(processes: dict[str, list[dict[str, Any]]]) -> list[str]:
    """Calls, distinct keys and the repeats' CPU, within each process and over the run."""
    rows = [row for kept in processes.values() for row in kept]
    lines = [f"{len(rows)} calls, {sum(r['cpu'] for r in rows):.1f} s CPU"]
    seen: set[str] = set()
    within: list[dict[str, Any]] = []  # a call whose key this process had read before
    for name, kept in processes.items():
        for row in kept:
            key = json.dumps([row["key"], name])
            if key in seen:
                within.append(row)
            seen.add(key)
    over_run = len(rows) - len({json.dumps(row["key"]) for row in rows})
    lines.append(f"repeats within a process: {len(within)} calls, {sum(r['cpu'] for r in within):.1f} s CPU")
    lines.append(f"repeats over the run: {over_run} calls")
    by_file: defaultdict[str, float] = defaultdict(float)
    count: Counter[str] = Counter()
    for row in within:
        by_file[row["test"].split("::")[0]] += row["cpu"]
        count[row["test"].split("::")[0]] += 1
    for file, cpu in sorted(by_file.items(), key=lambda item: -item[1])[:15]:
        lines.append(f"  {cpu:6.2f} s {count[file]:5d} repeats  {file}")
    return lines


if __name__ == "__main__":
    folder = Path(sys.argv[1])
    files = sorted(folder.glob("*.jsonl"))
    found = {p.stem: [json.loads(line) for line in p.read_text().splitlines()] for p in files}
    print("\n".join(summary(found)))
