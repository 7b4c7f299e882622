"""The typed rows every benchmark writes and reads: one `ScenarioRow` per scenario (scenarios.jsonl)
and one `LanguageRecord` per instruction (language.jsonl, the language stage scored once).

Rows travel as JSON (worker pipes, results files); `ScenarioRow.model_validate` reads them back, and
every report is computed from the models, never from loose dictionaries.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.pipeline import Planned

IDENTITY = {"key", "instance", "n_base", "robots", "draw"}


class ScenarioRow(BaseModel):
    """One scenario (instance x team size x start draw) after planning, execution and checking."""

    model_config = ConfigDict(extra="ignore")

    key: str = ""
    instance: str = ""
    n_base: int = 0
    robots: int = 1
    draw: int = 0
    # the planner (PlanResult.to_dict) and the runner ("error" rows, "killed" timeouts)
    status: str = "error"
    reason: str = ""
    killed: bool = False
    objective: str | None = None
    mode: str | None = None
    travel_m: float | None = None
    steps: int | None = None
    total_cost: float | None = None
    cost: float | None = None
    lower_bound: float | None = None
    bound: float | None = None
    proven_optimal: bool = False
    plan_time_s: float | None = None
    expanded: int | None = None
    stopped: str | None = None
    events: list[PlanEvent] = Field(default_factory=list)
    # the goal checker against the ground truth
    success: bool = False
    check_reasons: list[str] = Field(default_factory=list)
    goal_steps: dict[str, int | None] = Field(default_factory=dict)
    # the instance and the stage that failed first
    feasible: bool | None = None
    issues: list[str] = Field(default_factory=list)
    gt_feasible: bool | None = None
    ambiguous: bool = False
    conversion_ok: bool | None = None
    partial: bool = False  # part of the instruction was not understood (a conversion failure)
    planning_ok: bool | None = None
    stage: str | None = None
    starts: list[list[int]] = Field(default_factory=list)

    @classmethod
    def from_planned(cls, planned: Planned, **fields: Any) -> ScenarioRow:
        """The planner's result and the goal checker's verdict (plus `fields`) as one row."""
        result = planned.result
        row = cls.model_validate({**result.to_dict(with_plan=False), "events": result.events, **fields})
        row.success = planned.success
        if planned.check is not None:
            row.check_reasons = planned.check.reasons
            row.goal_steps = planned.check.goal_steps
        return row

    def to_json(self) -> dict[str, Any]:
        """JSON for the runner, which adds the scenario's identity (key, instance, ...) itself."""
        return self.model_dump(mode="json", exclude=IDENTITY - self.model_fields_set)


class LanguageRecord(BaseModel):
    """The language stage on one instruction, scored against the ground truth."""

    model_config = ConfigDict(extra="ignore")

    key: str
    instance: str
    n_base: int
    backend: str
    ok: bool = False  # a hierarchical spec was built
    error: str | None = None  # why the spec cannot be planned in this world (grounding), if so
    errored: bool = False  # the LLM failed (HTTP errors, no connection, invalid answers): rerun on resume
    partial: bool = False  # part of the instruction was not understood (`unparsed`): a conversion failure
    tasks: list[dict[str, Any]] = Field(default_factory=list)
    before: list[list[str]] = Field(default_factory=list)
    unparsed: list[str] = Field(default_factory=list)
    issues: list[str] = Field(default_factory=list)
    assumptions: list[str] = Field(default_factory=list)  # what a plural convention read (`--plurals two`)
    ltl_checks: list[str] = Field(default_factory=list)
    llm_calls: dict[str, int] = Field(default_factory=dict)
    levels: list[dict[str, Any]] | None = None  # the hierarchical spec's JSON levels
    constraints: list[dict[str, Any]] = Field(default_factory=list)  # beside them (negations), as JSON
    tasks_ok: bool = False
    conversion_ok: bool = False
    match_reasons: list[str] = Field(default_factory=list)
    stage: str | None = None  # the first stage that went wrong (None: conversion succeeded)


def rows_of(raw: list[dict[str, Any]]) -> list[ScenarioRow]:
    """Rows read back from a results file or a runner."""
    return [ScenarioRow.model_validate(r) for r in raw]
