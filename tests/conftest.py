"""Tests marked `data` need the shared data folder (`NL2HLTL2PLAN_DATA`, default ../shared/data) and
are skipped with a message where it is absent."""

from __future__ import annotations

import os
import tempfile

import pytest

from nl2hltl2plan.config import data_dir

# The user's cache (LLM answers, a retrained language model that the loader prefers) must not change
# what the tests see: every test, and every command a test starts, gets an empty cache of its own.
os.environ["XDG_CACHE_HOME"] = tempfile.mkdtemp(prefix="nl2hltl2plan-test-cache-")


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if data_dir(required=False) is not None:
        return
    skip = pytest.mark.skip(reason="needs ../shared/data (set NL2HLTL2PLAN_DATA)")
    for item in items:
        if "data" in item.keywords:
            item.add_marker(skip)
