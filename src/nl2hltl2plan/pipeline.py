"""The one pipeline: instruction -> language stage -> hierarchical sc-LTL -> planner -> checked plan.

The `plan` command, the web app and every benchmark job call these functions (and nothing else
chains the stages):

- `run(instruction, world, robots, options)` does everything and returns an `Outcome`;
- `language_stage(instruction, world, options, client)` is the first half (benchmarks run it once per
  instruction in the parent process, where the LLM client lives);
- `planning_stage(world, spec, starts, options, gt)` is the second half: plan (the planner executes
  and checks every plan before returning it), then, when a ground truth is given, judge the execution
  with the goal checker.

>>> from nl2hltl2plan.worlds.demo import demo_world
>>> out = run("Put the plates in the lower rack", demo_world(), robots=1)
>>> out.status.value, out.ok
('solved', True)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.backends import Backend
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.place_choices import ChosenPlace, chosen_places
from nl2hltl2plan.language.result import Ambiguity, LanguageResult
from nl2hltl2plan.language.suggest import not_understood
from nl2hltl2plan.language.translate import ActionSource, Chooser, LtlSource, translate
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning import PlanResult, PlanStatus, plan
from nl2hltl2plan.planning.api import Mode
from nl2hltl2plan.planning.objective import ObjectiveName
from nl2hltl2plan.planning.search import SearchStats
from nl2hltl2plan.worlds.checker import CheckResult, check
from nl2hltl2plan.worlds.starts import start_cells
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.team import Team, team_problems
from nl2hltl2plan.worlds.world import Cell, World


class PipelineOptions(BaseModel):
    """Every choice the pipeline makes, validated before any work starts."""

    model_config = ConfigDict(extra="forbid")

    backend: Backend = "offline"
    ltl: LtlSource = "compiler"
    actions: ActionSource = "auto"
    strict: bool = True  # an object the scene lacks is an error (else reported in `issues`)
    objective: ObjectiveName = "min"
    mode: Mode = "fast"
    plan_timeout_s: float = Field(default=300.0, gt=0, allow_inf_nan=False)
    starts: list[Cell] | None = None  # one per robot; default: the world's (see worlds.starts)
    capabilities: list[list[str] | None] | None = None  # per robot: verbs/atoms it can do (None: all)
    choices: dict[str, str] = Field(default_factory=dict)  # a user's picks for ambiguous words (--ask)
    partial: bool = False  # plan what was understood when part of the instruction was not (--partial)
    # "the forks" of more than a task takes: refused, or read by the world's convention (--plurals)
    plurals: Plurals = "ask"


class Progress(BaseModel):
    """One step of a run as it happens, for a progress display (the CLI's spinner, the web page's
    event stream): the stage, a line of words and, while planning, the search's counts so far."""

    stage: Literal["language", "specification", "planning", "execution"]
    detail: str
    expanded: int | None = None  # search expansions so far
    best_cost: float | None = None  # the best plan's cost so far (objective units)
    lower_bound: float | None = None  # proven lower bound on the optimal cost so far


OnProgress = Callable[[Progress], None]


def _search_progress(stats: SearchStats) -> Progress:
    best = "no plan yet" if stats.best_cost is None else f"best cost {stats.best_cost:g}"
    bound = f", lower bound {stats.lower_bound:g}" if stats.lower_bound > 0 else ""
    return Progress(stage="planning", detail=f"{stats.expanded} expansions, {best}{bound}",
                    expanded=stats.expanded, best_cost=stats.best_cost,
                    lower_bound=stats.lower_bound or None)  # fmt: skip


@dataclass
class Planned:
    """The planning stage's result: the planner's (checked) plan and, with a ground truth, its verdict."""

    result: PlanResult
    check: CheckResult | None = None

    @property
    def success(self) -> bool:
        return self.result.solved and (self.check is None or self.check.success)


def language_stage(
    instruction: str,
    world: World,
    options: PipelineOptions | None = None,
    client: LLMClient | None = None,
    ask: Chooser | None = None,
) -> LanguageResult:
    """Instruction -> HTT, base tasks, leaf actions and the hierarchical spec (`result.spec`).

    `ask`: shown the parse's ambiguous words, returns the user's picks (`plan --ask`)."""
    opt = options or PipelineOptions()
    return translate(
        instruction,
        world,
        opt.backend,
        client,
        ltl=opt.ltl,
        actions=opt.actions,
        strict=opt.strict,
        choices=opt.choices,
        ask=ask,
        plurals=opt.plurals,
    )


def planning_stage(
    world: World,
    spec: HierarchicalSpec,
    starts: Sequence[Cell],
    options: PipelineOptions | None = None,
    gt: GTInstance | None = None,
    progress: OnProgress | None = None,
) -> Planned:
    """Plan for the team (every returned plan is executed and checked against `spec`), then judge the
    execution against the ground truth's goals and orderings when `gt` is given. `progress` hears
    the search's counts while it runs."""
    opt = options or PipelineOptions()
    hook = None if progress is None else (lambda stats: progress(_search_progress(stats)))
    result = plan(
        world,
        spec,
        list(starts),
        objective=opt.objective,
        mode=opt.mode,
        timeout_s=opt.plan_timeout_s,
        capabilities=opt.capabilities,
        on_progress=hook,
    )
    verdict = None
    if gt is not None and result.solved and result.execution is not None:
        verdict = check(result.execution, gt)
    return Planned(result, verdict)


@dataclass
class Outcome:
    """Everything one run produced, typed at every stage."""

    instruction: str
    world: World
    robots: int
    options: PipelineOptions
    language: LanguageResult
    spec: HierarchicalSpec
    starts: list[Cell]
    planned: Planned
    team: str = ""  # the team's description ("robot1, robot5" or "2 robot(s) with every skill")

    @property
    def result(self) -> PlanResult:
        return self.planned.result

    @property
    def status(self) -> PlanStatus:
        return PlanStatus(self.result.status)

    @property
    def ok(self) -> bool:
        return self.planned.success

    def idle_note(self) -> str | None:
        """Why a robot of the team does nothing in the plan (a newcomer reads an idle robot as broken
        multi-robot planning); None when every robot acts."""
        plan = self.result.plan
        if plan is None or len(plan.robots) < 2:
            return None
        idle = [rp.robot for rp in plan.robots if all(st.verb in ("move", "wait") for st in rp.steps)]
        if not idle:
            return None
        who = f"robot {', '.join(map(str, idle))} stays idle"
        if self.result.objective == "min":
            return (f"{who}: under the objective 'min' (the paper's summed travel) giving it work would not "
                    "lower the team's travel; the objective 'minmax' minimises the completion time instead")
        return f"{who}: giving it work would not finish the plan sooner (the tasks' order or distances)"

    def to_json(self) -> dict[str, Any]:
        """The JSON of `plan --json` and of the web API's `POST /api/plan` (see docs/plan_schema.md)."""
        lang = self.language
        r = self.result
        planner = r.to_dict(with_plan=False)
        planner["starts"] = [list(c) for c in self.starts]
        return {
            "backend": lang.backend,
            "instruction": self.instruction,
            "world": self.world.name,
            "robots": self.robots,
            "team": self.team,
            "status": self.status.value,
            "partial": lang.partial,
            "htt": lang.htt.model_dump(mode="json"),
            "tasks": [t.model_dump(mode="json") for t in lang.tasks],
            "before": [list(p) for p in lang.before],
            "constraints": lang.constraints,
            "task_node": lang.task_node,
            "leaf_specs": lang.leaf_specs,
            "spec": self.spec.to_json_obj(),
            "plan": r.plan.model_dump(mode="json") if r.plan is not None else None,
            "travel_cost_m": r.travel_m,
            "completion_time": r.steps,
            "planner": planner,
            "ambiguities": [a.model_dump(mode="json") for a in lang.ambiguities],
            "unparsed": lang.unparsed,
            "issues": lang.issues,
            "warnings": lang.warnings,
            "assumptions": lang.assumptions,
            "ltl_checks": lang.ltl_checks,
            "llm_calls": lang.llm_calls,
            "idle_note": self.idle_note(),
            "place_choices": [c.model_dump(mode="json") for c in self.place_choices()],
        }

    def place_choices(self) -> list[ChosenPlace]:
        """Each task the user allowed several places for ("the fridge or the microwave"), and the one the
        checked plan took (`language.place_choices`)."""
        return chosen_places(self.language.tasks, self.language.leaf_task, self.result.events)


def run(
    instruction: str,
    world: World,
    robots: int | Team = 1,
    options: PipelineOptions | None = None,
    client: LLMClient | None = None,
    gt: GTInstance | None = None,
    ask: Chooser | None = None,
    progress: OnProgress | None = None,
) -> Outcome:
    """Instruction -> checked plan for a team in `world` (see the module docstring).

    `ask`: shown the ambiguous words of the parse, returns the user's picks; they are applied and kept
    in `outcome.options.choices` (so the run can be repeated without asking).

    A content word the language stage did not use (`LanguageResult.unparsed`, see
    `language.accounting`) is a refusal (HTTError naming the words) unless `options.partial`; then the
    rest is planned and the outcome says `partial`.

    `robots`: a number of robots that can do everything, or a `worlds.team.Team` of robots with
    skills and carrying capacities (their capabilities bound the allocation). Raises an
    `Nl2Hltl2PlanError` for input the pipeline cannot use (an object the scene lacks, a sentence
    nothing understood, a cyclic ordering, too many robots); a spec with no plan is not an error but
    an outcome with status infeasible (a team that lacks a skill, with the reason) or timeout.

    `progress`: hears each stage as it starts, and the planner's counts while it searches.
    """
    tell = progress or (lambda _p: None)
    opt = options or PipelineOptions()
    team = robots if isinstance(robots, Team) else Team(robots)
    starts = start_cells(world, team.size, given=opt.starts)
    if team.profiles is not None:
        opt = opt.model_copy(update={"capabilities": [_listed(c) for c in team.capabilities(world)]})
    if opt.capabilities is not None and len(opt.capabilities) != team.size:
        raise HTTError(f"{len(opt.capabilities)} capability sets given for {team.size} robot(s)")
    picks: dict[str, str] = {}

    def recorded(ambiguities: list[Ambiguity]) -> dict[str, str]:
        assert ask is not None
        picks.update(ask(ambiguities))
        return picks

    tell(Progress(stage="language", detail=f"reading the instruction ({opt.backend} backend)"))
    lang = language_stage(instruction, world, opt, client, ask=recorded if ask is not None else None)
    if picks:
        opt = opt.model_copy(update={"choices": {**opt.choices, **picks}})
    if lang.partial and not opt.partial:
        raise HTTError(not_understood(lang, world))
    if lang.spec is None:
        why = "; ".join(lang.warnings + lang.issues + lang.unparsed) or "no leaf actions"
        raise HTTError(f"no hierarchical specification for {instruction!r}: {why}")
    tell(Progress(stage="specification", detail=f"{len(lang.spec.names)} formulas, "
                  f"{len(lang.spec.leaves)} leaf tasks"))  # fmt: skip
    problems = team_problems(team, lang.spec, world)
    if problems:  # a definite no before any search: the team lacks a skill or the strength
        planned = Planned(PlanResult(status=PlanStatus.INFEASIBLE, reason="; ".join(problems)))
    else:
        tell(Progress(stage="planning", detail=f"searching for {team.describe()}"))
        planned = planning_stage(world, lang.spec, starts, opt, gt, progress)
        r = planned.result
        tell(Progress(stage="planning", detail=f"{r.expanded} expansions: {PlanStatus(r.status).value}",
                      expanded=r.expanded, best_cost=r.cost if r.solved else None,
                      lower_bound=r.lower_bound or None))  # fmt: skip
    tell(Progress(stage="execution", detail=_execution_words(planned.result)))
    return Outcome(
        instruction=lang.instruction,
        world=world,
        robots=team.size,
        options=opt,
        language=lang,
        spec=lang.spec,
        starts=starts,
        planned=planned,
        team=team.describe(),
    )


def _execution_words(result: PlanResult) -> str:
    if result.execution is None:
        return f"no plan to execute: {PlanStatus(result.status).value}"
    return (f"executed and checked: travel {result.execution.travel_m:.2f} m, "
            f"{result.execution.steps} steps")  # fmt: skip


def _listed(caps: set[str] | None) -> list[str] | None:
    return None if caps is None else sorted(caps)
