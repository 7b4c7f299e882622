"""Fixtures for the planning tests (worlds in planning_worlds.py)."""

from __future__ import annotations

import pytest
from planning_worlds import corridor

from nl2hltl2plan.worlds.world import World


@pytest.fixture
def two_tasks_world() -> World:
    """Apple at 10, counter at 2, mug at 30, table at 37."""
    return corridor({"Apple_0": 10, "CounterTop_0": 2, "Mug_0": 30, "DiningTable_0": 37})
