"""Tests marked `data` need the shared data folder (`NL2HLTL2PLAN_DATA`, default ../shared/data) and
are skipped with a message where it is absent."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if data_dir(required=False) is not None:
        return
    skip = pytest.mark.skip(reason="needs ../shared/data (set NL2HLTL2PLAN_DATA)")
    for item in items:
        if "data" in item.keywords:
            item.add_marker(skip)
