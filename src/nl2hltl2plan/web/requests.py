"""The web API's request model: every choice `nl2hltl2plan plan` offers, validated before any work.

Strict types: `"robots": true` is not 1 robot, `"robots": "2"` is not 2.
"""

from __future__ import annotations

from typing import Any, Literal, get_args

from pydantic import BaseModel, ConfigDict, Field, StrictBool, StrictInt, model_validator

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.language.translate import MAX_INSTRUCTION_CHARS

MAX_ROBOTS = 8
MAX_INSTRUCTION = MAX_INSTRUCTION_CHARS  # characters: the language stage's own cap, refused before any work
MAX_TIMEOUT_S = 600.0
DEFAULT_TIMEOUT_S = 60.0
WebBackend = Literal["offline", "grammar", "openai", "local"]  # the page offers these, in this order
WEB_BACKENDS: tuple[str, ...] = get_args(WebBackend)


class PlanRequest(BaseModel):
    """The body of `POST /api/plan` and `POST /api/plan/stream`.

    The team is one of: `robots` (a number of robots that can do everything), `profiles` (SMART-LLM
    robot profile names, "robot1".."robot28") or `team` (the content of a team file: a list of
    profile names or of `{"name", "skills", "mass_capacity"}` objects, docs/web.md)."""

    model_config = ConfigDict(extra="forbid")

    instruction: str = Field(min_length=1, max_length=MAX_INSTRUCTION)
    world: str = Field(default="demo", min_length=1, max_length=64)
    robots: StrictInt = Field(default=1, ge=1, le=MAX_ROBOTS)
    profiles: list[str] | None = Field(default=None, min_length=1, max_length=MAX_ROBOTS)
    team: list[str | dict[str, Any]] | None = Field(default=None, min_length=1, max_length=MAX_ROBOTS)
    objective: Literal["min", "minmax"] = "min"
    mode: Literal["fast", "exact"] = "fast"
    backend: WebBackend = "offline"
    timeout_s: float = Field(default=DEFAULT_TIMEOUT_S, gt=0, le=MAX_TIMEOUT_S, allow_inf_nan=False)
    choices: dict[str, str] = Field(default_factory=dict, max_length=64)  # "task.role" -> scene type
    pictures: StrictBool = True  # render the pictures and downloads after the plan
    partial: StrictBool = False  # plan what was understood of a partly understood one (`plan --partial`)
    plurals: Plurals = "ask"  # "the forks" of more than a task takes (`plan --plurals`)

    @model_validator(mode="after")
    def one_team(self) -> PlanRequest:
        if self.profiles is not None and self.team is not None:
            raise ValueError("give the team as profiles or as a team file, not both")
        return self

    def team_text(self) -> str:
        """The team in words, for messages."""
        if self.profiles is not None:
            return ", ".join(self.profiles)
        if self.team is not None:
            return f"a team file of {len(self.team)} robot(s)"
        return f"{self.robots} robot(s)"
