"""Baselines of the tabletop study (Table II): mention order, nearest item first, and an LLM used
directly as the planner.

- mention order: the arm places the objects in the order the instruction names them, each on a
  shortest grid path (the behaviour the paper observed in its LLM planner, Fig. 5);
- nearest item first: a greedy that always takes the nearest item whose ordered predecessors are
  placed (a fair, trivial baseline: the paper's LLM planner was optimal on task 1);
- LLM-as-planner: the prompt the paper describes (initial 2-D coordinates of every object and of the
  arm, the API, "minimise the trajectory"), answered as a list of API calls, which is parsed,
  turned into a grid plan, executed by our simulator and checked like our own plans. It runs only
  through the project's LLM client; nothing is invented when no LLM is configured.

Both produce `Plan`s through `script_plan`, so the simulator and checker judge them exactly as ours.
"""

from __future__ import annotations

import json
import time
from dataclasses import dataclass, field
from typing import Any, Literal

from pydantic import BaseModel, Field

from nl2hltl2plan.errors import LLMError, Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.language.grounding import camel_words
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step
from nl2hltl2plan.worlds.simulator import execute
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.world import Cell, World

Call = tuple[str, str, str | None]  # (verb "pick" | "place", object id, plate id or None)


@dataclass
class BaselineOutcome:
    """One baseline run on one instance."""

    name: str
    success: bool
    cost: float | None  # end-effector travel in grid cells
    runtime_s: float
    calls: list[Call] = field(default_factory=list)
    reasons: list[str] = field(default_factory=list)
    plan: Plan | None = None
    errored: bool = False  # the LLM failed (HTTP errors, no connection, invalid answers): not a result


def script_plan(world: World, calls: list[Call], start: Cell) -> Plan:
    """One-arm plan doing `calls` in order, walking a shortest grid path to each object or plate."""
    steps: list[Step] = []
    cur = start
    t = 0
    for verb, obj, plate in calls:
        target_id = obj if verb == "pick" else plate
        if target_id is None:
            raise WorldError(f"place({obj}) names no plate")
        target = world.get(target_id).interaction_cells[0]
        for cell in world.path(cur, target)[1:]:
            t += 1
            steps.append(Step(t=t, verb="move", cell=cell))
        cur = target
        t += 1
        if verb == "pick":
            steps.append(Step(t=t, verb="pickup", objects=[obj]))
        else:
            steps.append(Step(t=t, verb="put", objects=[obj, target_id]))
    return Plan(robots=[RobotPlan(robot=0, start=start, steps=steps)])


def judge(
    name: str, world: World, calls: list[Call], start: Cell, gt: GTInstance, t0: float
) -> BaselineOutcome:
    """Execute scripted calls in the simulator and check them against the task's ground truth."""
    plan = script_plan(world, calls, start)
    execution = execute(world, plan)
    verdict = check(execution, gt)
    runtime = time.perf_counter() - t0
    cost = float(sum(execution.cells_moved.values()))
    return BaselineOutcome(name, verdict.success, cost, runtime, calls, verdict.reasons, plan)


def instance_of(world: World, type_: str) -> str:
    """The one instance id of a tabletop type (GreenApple -> GreenApple_0)."""
    found = world.instances(type_)
    if not found:
        raise WorldError(f"no {type_} in {world.name}")
    return found[0].id


def mention_order(world: World, tasks: list[Any], start: Cell, gt: GTInstance, t0: float) -> BaselineOutcome:
    """Place objects in the order the instruction names them (`tasks` in mention order)."""
    calls: list[Call] = []
    for task in tasks:
        obj = instance_of(world, task.object[0])
        plate = instance_of(world, (task.receptacle or [""])[0])
        calls += [("pick", obj, None), ("place", obj, plate)]
    return judge("mention-order", world, calls, start, gt, t0)


def nearest_first(
    world: World,
    tasks: list[Any],
    before: list[tuple[str, str]],
    start: Cell,
    gt: GTInstance,
    t0: float,
) -> BaselineOutcome:
    """Greedy: from where the arm is, take the nearest item (grid path) among those whose ordered
    predecessors (`before`, between the tasks' ids) are placed, and put it into its plate."""
    from nl2hltl2plan.language.task_specs import transitive_closure

    closure = transitive_closure(before, [t.id for t in tasks])
    left = {
        t.id: (instance_of(world, t.object[0]), instance_of(world, (t.receptacle or [""])[0])) for t in tasks
    }
    calls: list[Call] = []
    cur = start
    while left:
        ready = [k for k in left if not any((p, k) in closure for p in left if p != k)]
        if not ready:
            raise WorldError("the orderings of the tasks form a cycle")

        here = cur
        k = min(ready, key=lambda x: (len(world.path(here, world.get(left[x][0]).interaction_cells[0])), x))
        obj, plate = left.pop(k)
        calls += [("pick", obj, None), ("place", obj, plate)]
        cur = world.get(plate).interaction_cells[0]
    return judge("nearest-first", world, calls, start, gt, t0)


# ----- LLM as the planner -----------------------------------------------------------------------------
class ApiCall(BaseModel):
    api: Literal["pick", "place"]
    object: str = Field(description="an object name as listed, e.g. 'green apple'")
    plate: str | None = Field(default=None, description="for place: a plate name, e.g. 'blue plate'")


class LLMPlanAnswer(BaseModel):
    calls: list[ApiCall] = Field(min_length=1, max_length=40)


def llm_prompt(world: World, instruction: str, start: Cell) -> list[dict[str, str]]:
    """The paper's LLM-as-planner prompt: coordinates, the API and the request to minimise travel."""
    lines = []
    for obj in world.objects.values():
        r, c = obj.interaction_cells[0]
        lines.append(f"- {camel_words(obj.type)}: (x={c}, y={r})")
    rows, cols = world.shape
    system = (
        "You are the task planner of a robot arm over a table. Answer with a JSON object "
        '{"calls": [{"api": "pick", "object": NAME}, {"api": "place", "object": NAME, "plate": PLATE}, ...]}.'
    )
    user = (
        f"The table is a grid of {cols} x {rows} cells (x = 0..{cols - 1}, y = 0..{rows - 1}). The arm's "
        f"end effector starts at (x={start[1]}, y={start[0]}) and moves along the grid; its cost is the "
        "length of its trajectory (grid distance).\nObjects and plates:\n" + "\n".join(lines) + "\n"
        "API: pick(object) moves the arm to the object and grasps it; place(object, plate) moves the arm "
        "holding the object to the plate and releases it there. The arm holds one object at a time.\n"
        f"Instruction: {instruction}\n"
        "Give the sequence of API calls that carries out the instruction, respects every ordering it "
        "states and minimises the total trajectory length of the end effector."
    )
    return [{"role": "system", "content": system}, {"role": "user", "content": user}]


def parse_llm_answer(world: World, answer: LLMPlanAnswer) -> list[Call]:
    """API calls with names -> calls on object ids; a name the scene lacks raises WorldError."""
    by_name = {camel_words(o.type): oid for oid, o in world.objects.items()}

    def resolve(name: str | None, role: str) -> str:
        key = " ".join((name or "").lower().replace("_", " ").split())
        if key not in by_name:
            raise WorldError(f"the LLM named a {role} {name!r} that is not on the table")
        return by_name[key]

    calls: list[Call] = []
    for c in answer.calls:
        obj = resolve(c.object, "object")
        calls.append((c.api, obj, resolve(c.plate, "plate") if c.api == "place" else None))
    return calls


def llm_planner(world: World, instruction: str, start: Cell, gt: GTInstance, client: Any) -> BaselineOutcome:
    """Ask the LLM for the API calls, then execute and check them; a bad answer is a failure."""
    t0 = time.perf_counter()
    try:
        answer = client.ask(llm_prompt(world, instruction, start), LLMPlanAnswer, "tabletop_llm_planner")
        calls = parse_llm_answer(world, answer)
    except LLMError as exc:  # a dead LLM is an error of the run, not a failure of the baseline
        return BaselineOutcome(
            "llm-planner", False, None, time.perf_counter() - t0, reasons=[f"LLM failed: {exc}"], errored=True
        )
    except Nl2Hltl2PlanError as exc:
        return BaselineOutcome("llm-planner", False, None, time.perf_counter() - t0, reasons=[str(exc)])
    return judge("llm-planner", world, calls, start, gt, t0)


def calls_json(calls: list[Call]) -> str:
    return json.dumps([list(c) for c in calls])
