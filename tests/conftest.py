"""Tests marked `data` need the shared data folder (`NL2HLTL2PLAN_DATA`, default ../shared/data) and
are skipped with a message where it is absent."""

from __future__ import annotations

import gc
import os
import sys
import tempfile

# Keep compiled modules between processes and runs even where PYTHONDONTWRITEBYTECODE is set (it is on
# our shared machine): else each test worker compiles every test module again (pytest's assertion
# rewriting: about 3 s of a worker's start), and every command a test starts compiles the package. The
# __pycache__ folders are git-ignored; Python and pytest write them atomically, so workers may race.
sys.dont_write_bytecode = False
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)

import pytest  # noqa: E402
import sampled_tables  # noqa: E402

from nl2hltl2plan.config import data_dir  # noqa: E402

# The user's cache (LLM answers, a retrained language model that the loader prefers) must not change
# what the tests see: every test, and every command a test starts, gets an empty cache of its own.
# Matplotlib keeps its font list in the cache folder too (rebuilding it scans the system's fonts: 0.2 s
# CPU and seconds of disk per process), so it keeps the folder it had.
# a script that runs its campaign at import (`python tests/reliability/campaign.py DIR`): never collected,
# not even by `pytest --doctest-modules tests` (it took pytest's first argument for its output folder)
collect_ignore = ["reliability/campaign.py"]

_user_cache = os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache")
os.environ.setdefault("MPLCONFIGDIR", os.path.join(_user_cache, "matplotlib"))
os.environ["XDG_CACHE_HOME"] = tempfile.mkdtemp(prefix="nl2hltl2plan-test-cache-")

# Opt-in measurement: how often the run reads the same instruction again (tests/reading_counts.py). The
# reader is wrapped here, before any test module imports it; off, nothing is imported or changed.
_count_readings = os.environ.get("NL2HLTL2PLAN_COUNT_READINGS")
if _count_readings:
    import reading_counts

    _stop_counting = reading_counts.install(_count_readings)

    def pytest_unconfigure(config: pytest.Config) -> None:
        _stop_counting()


@pytest.hookimpl(tryfirst=True)  # before pytest's own `-m` deselection reads the marks
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    sampled_tables.mark_sampled(items)  # most cases of a large table run only with `-m sweep`
    if data_dir(required=False) is not None:
        return
    skip = pytest.mark.skip(reason="needs ../shared/data (set NL2HLTL2PLAN_DATA)")
    for item in items:
        if "data" in item.keywords:
            item.add_marker(skip)


def pytest_collection_finish(session: pytest.Session) -> None:
    """Less garbage-collector work per test process: everything imported and collected so far (Spot,
    matplotlib, the package, ~3,000 test items) lives to the end, so it is frozen out of the collector's
    scans, and a young collection runs every 20,000 allocations instead of 700. The planning and
    experiment tests spent about 6 % of their CPU in the collector, mostly rescanning those long-lived
    objects (results/reliability/test_suite_time.md). Objects are still collected; only when differs."""
    gc.collect()
    gc.freeze()
    gc.set_threshold(20_000, 20, 50)
