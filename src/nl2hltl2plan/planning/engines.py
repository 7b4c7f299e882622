"""Planning engines behind one interface, chosen by what each supports rather than by a switch.

`planning.plan` asks its engines in order whether they support the world; the first that does plans.
The cooperative engine (`planning.coop`) supports the four-arm handover worlds, whose fixed arms pass
blocks through shared cells; the search planner (`planning.api.SearchEngine`) supports every grid world
with mobile robots and is asked last. Both answer in one `PlanResult` with one `PlanStatus`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol

from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.results import PlanResult
from nl2hltl2plan.worlds.world import Cell, World


class Engine(Protocol):
    """A planner for some worlds: `supports` says which, `solve` plans (options as `planning.plan`'s)."""

    name: str

    def supports(self, world: World) -> bool: ...

    def solve(
        self, world: World, spec: HierarchicalSpec, starts: Sequence[Cell], **options: Any
    ) -> PlanResult: ...


class CooperativeEngine:
    """The four-arm handover worlds' engine (`planning.coop`): it minimises moves + actions and stops on
    its own expansion budget; of the options it reads only `timeout_s`, the last-resort wall clock."""

    name = "cooperative"

    def supports(self, world: World) -> bool:
        return world.kind == "handover"

    def solve(
        self, world: World, spec: HierarchicalSpec, starts: Sequence[Cell], **options: Any
    ) -> PlanResult:
        from nl2hltl2plan.planning.coop import plan_world

        if spec.constraints:  # its guards are compiled into the leaves (language/handover_reading.py) instead
            raise PlanningError("the handover worlds' engine does not take constraints beside the spec "
                                f"({spec.constraints[0].text!r}); state them as guards in the leaves")
        return plan_world(world, spec, starts, timeout_s=options.get("timeout_s"))
