"""Worlds: AI2-THOR household scenes (from ALFRED data) as grid worlds, a multi-robot simulator that
executes plans, base tasks with their recipes, and a goal checker.

Entry points: `load_world(name)` ("demo" or "FloorPlanN"), `build_benchmark_world(gt)`,
`execute(world, plan)`, `check(execution, gt)`, `BaseTask.leaf_specs(world)`. See docs/worlds.md.
"""

from __future__ import annotations

from collections.abc import Callable

from nl2hltl2plan.domain.task_kinds import Goal
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.worlds.checker import CheckResult, check
from nl2hltl2plan.worlds.demo import demo_world
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step
from nl2hltl2plan.worlds.simulator import Event, Execution, SimState, execute
from nl2hltl2plan.worlds.tasks import BaseTask, GTInstance
from nl2hltl2plan.worlds.world import CELL_M, VISIBILITY_M, Affordances, Cell, World, WorldObject

__all__ = [
    "BUILT_IN",
    "CELL_M",
    "VISIBILITY_M",
    "Affordances",
    "BaseTask",
    "Cell",
    "CheckResult",
    "Event",
    "Execution",
    "GTInstance",
    "Goal",
    "Plan",
    "RobotPlan",
    "SimState",
    "Step",
    "World",
    "WorldObject",
    "build_benchmark_world",
    "check",
    "demo_world",
    "execute",
    "load_world",
]


def load_world(name: str, trials: list[str] | None = None) -> World:
    """ "demo", "tabletop", "handover-line", "handover-square" (built in) or an ALFRED floor plan
    "FloorPlanN" (movables from `trials`, see floor_plans.py)."""
    build = BUILT_IN.get(name.lower())
    if build is not None:
        if trials:
            raise WorldError(f"the {name.lower()} world takes no ALFRED trials")
        return build()
    from nl2hltl2plan.worlds.floor_plans import load_floor_plan

    return load_floor_plan(name, trials)


def _tabletop() -> World:
    """The paper's tabletop world (default instance)."""
    from nl2hltl2plan.worlds.tabletop_world import tabletop_world

    return tabletop_world()


def _handover(config: str) -> Callable[[], World]:
    """The paper's four-arm handover world `config` (default instance)."""

    def build() -> World:
        from nl2hltl2plan.worlds.handover_world import handover_world

        return handover_world(config).as_world()

    return build


# the worlds that need no data, by name (each imported when first built)
BUILT_IN: dict[str, Callable[[], World]] = {
    "demo": demo_world,
    "tabletop": _tabletop,
    "handover-line": _handover("line"),
    "handover-square": _handover("square"),
}


def build_benchmark_world(gt: GTInstance | dict) -> World:
    """The world of one benchmark instance: its floor plan with its source trials' objects."""
    from nl2hltl2plan.worlds.floor_plans import build_benchmark_world as build

    return build(gt)
