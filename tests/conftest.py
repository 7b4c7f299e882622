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

from nl2hltl2plan.config import data_dir  # noqa: E402

# The user's cache (LLM answers, a retrained language model that the loader prefers) must not change
# what the tests see: every test, and every command a test starts, gets an empty cache of its own.
# Matplotlib keeps its font list in the cache folder too (rebuilding it scans the system's fonts: 0.2 s
# CPU and seconds of disk per process), so it keeps the folder it had.
_user_cache = os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache")
os.environ.setdefault("MPLCONFIGDIR", os.path.join(_user_cache, "matplotlib"))
os.environ["XDG_CACHE_HOME"] = tempfile.mkdtemp(prefix="nl2hltl2plan-test-cache-")


# Test modules that start first: those waiting on a slow start (Ray, the web app's server, Chromium)
# and those holding the suite's longest tests (`--durations=30`). xdist's worksteal hands each worker a
# contiguous half of the collection and steals from the tail of a queue, so what is collected last runs
# last; these modules, collected late (planning, suites, web, worlds), left one worker finishing them
# while the other idled (about 20 s of a 105 s run, results/reliability/test_suite_time.md). Run first,
# the other worker meanwhile takes the many short tests, and the run ends on short tests of either
# queue. Modules with a test marked `slow` start first too; a path not collected is ignored.
_START_FIRST = (
    "tests/suites/test_ray_engine.py",
    "tests/web/test_browser.py",
    "tests/web/test_api.py",
    "tests/planning/test_random_demo_plans.py",
    "tests/planning/test_specs_and_agreement.py",
    "tests/language/test_measure.py",
    "tests/worlds/test_worlds_cli_pictures.py",
    "tests/planning/test_determinism.py",
    "tests/planning/test_alfred_instances.py",
    "tests/language/test_pipeline_cli.py",
    "tests/web/test_load.py",
)


def _start_slow_modules_first(items: list[pytest.Item]) -> None:
    """Stable reordering by whole modules, so module-scoped fixtures are still set up once."""
    slow_modules = {item.nodeid.split("::")[0] for item in items if item.get_closest_marker("slow")}
    rank = {path: i for i, path in enumerate(_START_FIRST)}

    def key(item: pytest.Item) -> int:
        module = item.nodeid.split("::")[0]
        if module in rank:
            return rank[module]
        return len(rank) if module in slow_modules else len(rank) + 1

    items.sort(key=key)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    _start_slow_modules_first(items)
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
