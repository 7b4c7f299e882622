"""Shared fixtures for the worlds tests; tests that need ../shared/data skip with a clear message."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import DATA_ENV, data_dir
from nl2hltl2plan.worlds.demo import demo_world

NO_DATA = f"needs the shared data folder (../shared/data or ${DATA_ENV}); it is absent here"


def require_data():
    """Skip the calling test when the shared data folder is absent; else return its path."""
    path = data_dir(required=False)
    if path is None:
        pytest.skip(NO_DATA)
    return path


@pytest.fixture(scope="session")
def data():
    """The shared data folder; skips the test when it is absent."""
    return require_data()


@pytest.fixture
def demo():
    return demo_world()


@pytest.fixture(scope="session")
def gt_instances():
    require_data()
    from nl2hltl2plan.suites.alfred.ground_truth import load_gt

    return load_gt()
