"""Worlds: AI2-THOR household scenes (from ALFRED data) as grid worlds, a multi-robot simulator that
executes plans, base tasks with their recipes, and a goal checker.

Entry points: `load_world(name)` ("demo" or "FloorPlanN"), `build_benchmark_world(gt)`,
`execute(world, plan)`, `check(execution, gt)`, `BaseTask.leaf_specs(world)`. See docs/worlds.md.
"""

from __future__ import annotations

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.worlds.checker import CheckResult, check
from nl2hltl2plan.worlds.demo import demo_world
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step
from nl2hltl2plan.worlds.simulator import Event, Execution, SimState, execute
from nl2hltl2plan.worlds.tasks import BaseTask, Goal, GTInstance
from nl2hltl2plan.worlds.world import CELL_M, VISIBILITY_M, Affordances, Cell, World, WorldObject

__all__ = [
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
    "FloorPlanN" (movables from `trials`, see alfred.py)."""
    if name.lower() == "demo":
        if trials:
            raise WorldError("the demo world takes no ALFRED trials")
        return demo_world()
    if name.lower() in ("tabletop", "handover-line", "handover-square"):
        if trials:
            raise WorldError(f"the {name} world takes no ALFRED trials")
        return _experiment_world(name.lower())
    from nl2hltl2plan.worlds.floor_plans import load_floor_plan

    return load_floor_plan(name, trials)


def _experiment_world(name: str) -> World:
    """The paper's tabletop and four-arm handover worlds (default instance)."""
    if name == "tabletop":
        from nl2hltl2plan.worlds.tabletop_world import tabletop_world

        return tabletop_world()
    from nl2hltl2plan.worlds.handover_world import handover_world

    return handover_world(name.split("-", 1)[1]).as_world()


def build_benchmark_world(gt: GTInstance | dict) -> World:
    """The world of one benchmark instance: its floor plan with its source trials' objects."""
    from nl2hltl2plan.worlds.floor_plans import build_benchmark_world as build

    return build(gt)
