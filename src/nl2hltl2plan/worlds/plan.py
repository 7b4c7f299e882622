"""Multi-robot plans: per-robot timed step lists (the shapes fixed in docs/CONTRACTS.md)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ConfigDict, Field, model_validator

if TYPE_CHECKING:
    from nl2hltl2plan.worlds.world import World

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


def _step_rules(schema: dict[str, Any]) -> None:
    """What `Step._shape` checks, in JSON Schema: a move names its cell, an action its objects."""
    rules: list[dict[str, Any]] = [
        {"if": {"properties": {"verb": {"const": "move"}}, "required": ["verb"]},
         "then": {"required": ["cell"], "properties": {"cell": {"type": "array"}}}}
    ]  # fmt: skip
    rules += [
        {"if": {"properties": {"verb": {"const": verb}}, "required": ["verb"]},
         "then": {"required": ["objects"], "properties": {"objects": {"minItems": n, "maxItems": n}}}}
        for verb, n in ACTION_ARITY.items()
    ]  # fmt: skip
    schema["allOf"] = rules


class Step(BaseModel):
    """What one robot does at one time step. Time steps a robot does not list are waits."""

    model_config = ConfigDict(frozen=True, json_schema_extra=_step_rules)

    t: int = Field(ge=1, description="1-based time step; a robot does one thing per step")
    verb: str = Field(
        description="move to a neighbouring cell, wait, or an action", json_schema_extra={"enum": list(VERBS)}
    )
    cell: tuple[int, int] | None = Field(
        default=None, description="for move: the neighbouring cell entered [row, col] (0.25 m cells)"
    )
    objects: list[str] = Field(
        default=[], description='object instance ids the action uses, e.g. ["Apple_3", "Fridge_0"] for put'
    )
    task: str | None = Field(
        default=None, description="the leaf specification this action serves, e.g. task1.2"
    )

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
    """One robot's steps."""

    robot: int = Field(ge=0, description="robot index (0-based)")
    start: tuple[int, int] = Field(description="the robot's cell at t = 0 [row, col]")
    steps: list[Step] = Field(default=[], description="strictly increasing t; missing time steps are waits")

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
    """A timed multi-robot plan: one step list per robot."""

    robots: list[RobotPlan] = Field(description="one entry per robot, robot indices distinct")

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


SCHEMA_ID = "https://github.com/nl2hltl2plan/nl2hltl2plan/docs/plan.schema.json"


def plan_json_schema() -> dict[str, Any]:
    """The JSON Schema of a plan, generated from `Plan` (docs/plan.schema.json is this, written by
    scripts/plan_schema.py; a test fails when the two drift apart)."""
    schema = Plan.model_json_schema()
    head = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCHEMA_ID,
        "title": "nl2hltl2plan multi-robot plan",
        "description": "A timed multi-robot plan: one step list per robot, steps in strictly increasing "
        'time. Written by `nl2hltl2plan plan --json` (key "plan"), result.json of `plan -o DIR` and '
        "POST /api/plan. Generated from nl2hltl2plan.worlds.plan.Plan; see docs/plan_schema.md.",
    }
    schema.pop("title", None)
    schema.pop("description", None)
    return {**head, **schema}
