"""Which cases of a large parametrised table the default run keeps (docs/reliability.md, "What runs by
default and what only in `sweep`").

A table is the cases of one parametrised test function. One of `MIN_CASES` or more cases (not counting
those already marked `sweep`) is sampled: the default run keeps its first case and every case whose id
hashes to 0 modulo `EVERY`; the others get the `sweep` mark, so `python -m pytest -m sweep` (and CI) runs
them with the same assertions. The key is the case's own id (CRC-32, the same in every process and on
every machine, unlike `hash`), so adding or removing a case never moves another one between the runs.
A table whose cases each take another code path (one bad input per case) is marked `whole` and never
sampled."""

from __future__ import annotations

import zlib
from collections import defaultdict

import pytest

MIN_CASES = 20
EVERY = 4


def kept_by_key(case_id: str) -> bool:
    return zlib.crc32(case_id.encode("utf-8")) % EVERY == 0


def tables(items: list[pytest.Item]) -> dict[str, list[pytest.Item]]:
    """The sampled tables among the collected items: test function -> its cases, in collection order."""
    by_function: dict[str, list[pytest.Item]] = defaultdict(list)
    for item in items:
        if hasattr(item, "callspec") and "sweep" not in item.keywords:  # a parametrised case
            by_function[item.nodeid.split("[", 1)[0]].append(item)
    return {
        name: cases
        for name, cases in by_function.items()
        if len(cases) >= MIN_CASES and cases[0].get_closest_marker("whole") is None
    }


def mark_sampled(items: list[pytest.Item]) -> int:
    """Gives the `sweep` mark to the cases the default run leaves out; returns how many."""
    moved = 0
    for cases in tables(items).values():
        for case in cases[1:]:
            if not kept_by_key(case.callspec.id):  # type: ignore[attr-defined]
                case.add_marker(pytest.mark.sweep)
                moved += 1
    return moved
