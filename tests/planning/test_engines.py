"""`planning.plan` picks its engine by what each supports, not by a switch on the world's name."""

from __future__ import annotations

from nl2hltl2plan.planning.api import ENGINES
from nl2hltl2plan.worlds import load_world


def _engine(world_name: str) -> str:
    world = load_world(world_name)
    return next(e for e in ENGINES if e.supports(world)).name


def test_each_world_goes_to_the_engine_that_supports_it() -> None:
    assert [e.name for e in ENGINES] == ["cooperative", "search"]  # the general planner is asked last
    assert _engine("handover-square") == _engine("handover-line") == "cooperative"
    assert _engine("demo") == _engine("tabletop") == "search"
