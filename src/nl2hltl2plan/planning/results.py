"""What the planner returns: `PlanStatus`, `PlanResult`, and `validate` (execute a plan and judge it).

`validate(world, spec, plan)` is what `plan()` runs on every plan before returning it, and what a
user runs on a plan from elsewhere: the simulator executes it (every precondition), the spec
judges the executed, attributed events (`logic.trace.check_trace`) and the goal checker's
`constraint_violations` every executed action against the constraints beside the spec.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.logic.trace import TraceEvent, check_trace
from nl2hltl2plan.planning.budget import StopReason
from nl2hltl2plan.worlds.checker import constraint_violations
from nl2hltl2plan.worlds.plan import Plan
from nl2hltl2plan.worlds.simulator import Execution, execute
from nl2hltl2plan.worlds.world import World

# the model every optimum and bound is stated over
GRID_MODEL = ("the grid: robots move one 0.25 m cell per step (4-neighbour moves, as the simulator) and act "
              "from any cell of an object's interaction region; a leaf follows one of its minimal action "
              "sequences; a task starts after the tasks ordered before it are complete")
NEAREST_CELL_MODEL = ("the nearest-cell model: as the grid, but a robot always walks to the region cell "
                      "nearest to it; the grid optimum can be lower")


class PlanStatus(StrEnum):
    """How a planning call ended (a str, so `status == "solved"` works)."""

    SOLVED = "solved"  # a verified plan
    INFEASIBLE = "infeasible"  # `reason` says why no plan exists
    TIMEOUT = "timeout"  # no plan within the wall-clock limit
    ERROR = "error"  # the planner failed (a bug); `reason` says how




@dataclass
class Validation:
    """The verdict on a plan: `ok` when it executes and satisfies the spec; `reasons` otherwise."""

    ok: bool
    reasons: list[str]
    execution: Execution


def validate(world: World, spec: HierarchicalSpec, plan: Plan) -> Validation:
    """Execute `plan` in `world` and judge its attributed events with `check_trace`."""
    execution = execute(world, plan)
    if not execution.ok:
        return Validation(False, ["the plan fails in the simulator: " + "; ".join(execution.violations[:3])],
                          execution)
    trace = [TraceEvent(e.t, e.atom, e.task) for e in execution.events]
    verdict = check_trace(spec, trace)
    reasons = verdict.reasons + constraint_violations(execution, spec.constraints, verdict.completed)
    return Validation(not reasons, reasons, execution)


@dataclass
class PlanResult:
    """Outcome of `plan`. Costs: `total_cost` moves + actions summed over robots, `steps` the completion
    time, `cost` the objective (one of the two). `lower_bound` is a proven lower bound on the optimal
    objective over `model`; `bound` = cost / lower_bound; `optimality` says it in words: "proven
    optimal" only when it is, else "within <bound> of the optimum" (or "no bound proven")."""

    status: PlanStatus
    reason: str = ""
    objective: str = "min"
    mode: str = "fast"
    plan: Plan | None = None
    travel_m: float | None = None  # metres walked, summed over robots
    steps: int | None = None  # completion time: last step at which some robot acts
    total_cost: int | None = None  # moves + actions, summed over robots (the paper's cost)
    cost: float | None = None  # the objective: total_cost (min) or steps (minmax)
    model_cost: float | None = None  # the objective of the searched plan, before stand-cell refinement
    lower_bound: float | None = None  # proven lower bound on the optimal objective over `model`
    bound: float | None = None  # cost / lower_bound (1.0: proven optimal)
    proven_optimal: bool = False
    optimality: str = ""  # "proven optimal" | "within 1.04x of the optimum" | "no bound proven"
    model: str = ""  # the model the optimum / bound is over
    plan_time_s: float = 0.0
    expanded: int = 0  # search nodes expanded (the budgets count these)
    peak_nodes: int = 0  # most search nodes held at once
    memory_mb: float = 0.0  # rough memory of those nodes
    stopped: StopReason = StopReason.NONE  # why the search stopped (`stop_reason`: in words)
    stop_reason: str = ""  # the sentence
    execution: Execution | None = field(default=None, repr=False)
    events: list[PlanEvent] = field(default_factory=list)

    @property
    def solved(self) -> bool:
        return self.status == PlanStatus.SOLVED

    def to_dict(self, with_plan: bool = True) -> dict[str, Any]:
        out: dict[str, Any] = {k: getattr(self, k) for k in (
            "reason", "objective", "mode", "travel_m", "steps", "total_cost", "cost", "model_cost",
            "lower_bound", "bound", "proven_optimal", "optimality", "model", "plan_time_s", "expanded",
            "peak_nodes", "memory_mb", "stopped", "stop_reason")}
        out = {"status": self.status.value, **out, "stopped": str(self.stopped)}
        if with_plan:
            out["plan"] = self.plan.model_dump(mode="json") if self.plan is not None else None
            out["events"] = [e.model_dump() for e in self.events]
        return out


def optimality_words(proven: bool, bound: float | None) -> str:
    if proven:
        return "proven optimal"
    if bound is None:
        return "no bound proven"
    return f"within {bound:.3g}x of the optimum (proven bound)"
