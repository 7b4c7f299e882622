"""Multi-robot plans: per-robot timed step lists (the shapes fixed in docs/CONTRACTS.md)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from pydantic import BaseModel, ConfigDict, Field, model_validator

if TYPE_CHECKING:
    from nl2hltl2plan.worlds.model import World

# verb -> number of object arguments
ACTION_ARITY = {
    "pickup": 1,
    "put": 2,
    "open": 1,
    "close": 1,
    "toggle_on": 1,
    "toggle_off": 1,
    "slice": 1,
    "break": 1,  # SMART-LLM's BreakObject (worlds/effects.py)
}
VERBS = ("move", "wait", *ACTION_ARITY)


class Step(BaseModel):
    """One time step of one robot."""

    model_config = ConfigDict(frozen=True)

    t: int = Field(ge=1, description="1-based time step; a robot does one thing per step")
    verb: str
    cell: tuple[int, int] | None = None  # for "move": the neighbouring cell entered
    objects: list[str] = []  # instance ids, e.g. ["Apple_3", "Fridge_0"] for put
    task: str | None = None  # the leaf spec this action serves (attribution)

    @model_validator(mode="after")
    def _shape(self) -> Step:
        if self.verb not in VERBS:
            raise ValueError(f"unknown verb {self.verb!r}; expected one of {', '.join(VERBS)}")
        if self.verb == "move" and self.cell is None:
            raise ValueError(f"t={self.t}: a move needs the cell it enters")
        if self.verb in ACTION_ARITY and len(self.objects) != ACTION_ARITY[self.verb]:
            raise ValueError(
                f"t={self.t}: {self.verb} takes {ACTION_ARITY[self.verb]} object id(s), got {self.objects}"
            )
        return self

    def atom(self, world: World) -> str | None:
        """Type-level atom (`put(Apple,Fridge)`); None for move/wait."""
        if self.verb not in ACTION_ARITY:
            return None
        types = ",".join(world.get(o).type for o in self.objects)
        return f"{self.verb}({types})"


class RobotPlan(BaseModel):
    robot: int = Field(ge=0)
    start: tuple[int, int]
    steps: list[Step] = []  # strictly increasing t; gaps are waits

    @model_validator(mode="after")
    def _increasing(self) -> RobotPlan:
        last = 0
        for s in self.steps:
            if s.t <= last:
                raise ValueError(
                    f"robot {self.robot}: step times must strictly increase (t={s.t} after {last})"
                )
            last = s.t
        return self

    @property
    def end(self) -> int:
        return self.steps[-1].t if self.steps else 0


class Plan(BaseModel):
    robots: list[RobotPlan]

    @model_validator(mode="after")
    def _distinct(self) -> Plan:
        ids = [r.robot for r in self.robots]
        if len(set(ids)) != len(ids):
            raise ValueError(f"robot indices must be distinct, got {ids}")
        return self

    @property
    def horizon(self) -> int:
        """Last time step of any robot."""
        return max((r.end for r in self.robots), default=0)
