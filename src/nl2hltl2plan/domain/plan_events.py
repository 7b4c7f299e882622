"""One action of a plan as the planner reports it (`PlanResult.events`) and the benchmarks record it
(`ScenarioRow.events`): when, by which robot, the atom, the task it serves, the objects it acted on
and the metres walked before it. Its JSON (`model_dump`) is the planner's event object."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field


class PlanEvent(BaseModel):
    """`t` the step of the action, `task` the name of the leaf task it serves (None when it serves
    none), `objects` the object ids acted on, `travel_m` walked since the robot's previous action."""

    model_config = ConfigDict(frozen=True)

    t: int
    robot: int
    atom: str
    task: str | None = None
    objects: list[str] = Field(default_factory=list)
    travel_m: float = 0.0
