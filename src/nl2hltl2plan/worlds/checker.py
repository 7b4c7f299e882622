"""Goal checker: does an execution reach every ground-truth task goal, in the demanded order?

Semantics (ANNOTATION_GUIDE.md, judged on the execution alone, however the plan was made):
- a task's goal holds for an object instance when (state after a step):
  place / place_two: the instance is in/on a receptacle of an acceptable type (direct parent);
  place_in_container: it is in a container of an acceptable type that is in/on an acceptable receptacle;
  examine_in_light: a robot holds it while a lamp of an acceptable type is on;
  clean_place / heat_place / cool_place: it is clean / hot / cold and in/on an acceptable receptacle.
  Sliced tasks need instances of the slice type (AppleSliced); place_two needs `count` instances at once.
- goals must be brought about by the plan: a state that already holds at t=0 counts only after it
  was broken and made true again (an apple already on the table does not "place" it).
- a goal is reached at the first step it holds; different tasks need different object instances
  (ALFRED base tasks work on distinct objects); for every pair [X, Y] in `before`, X's goal must be
  reached strictly earlier than Y's. The checker searches all instance assignments for one that works.
- strict (default): a plan with failed steps (executor violations) does not succeed either.

`constraint_violations(execution, constraints, completed)` judges the same execution against the
constraints beside a spec (G !p, until-guards; `logic.constraints`): every executed action, support
actions and put-downs included, and every change of state (`state_events`: `heat(Mug)` at the step
a mug becomes hot, `cool(X)`, `clean(X)`) is matched against what they forbid. `planning.validate`
runs it on every plan the planner returns, and on a plan from elsewhere.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence

from pydantic import BaseModel

from nl2hltl2plan.domain.task_kinds import Goal
from nl2hltl2plan.logic.constraints import Constraint, violations
from nl2hltl2plan.worlds.simulator import CLEAN, COLD, HOT, ON, PRESENT, Execution, Snapshot, _compiled
from nl2hltl2plan.worlds.tasks import GTInstance

_STATE_FLAG = {"clean_place": CLEAN, "heat_place": HOT, "cool_place": COLD}
# a constraint's state atoms: `heat(Mug)` is true at the step some mug becomes hot
STATE_EVENTS = {HOT: "heat", COLD: "cool", CLEAN: "clean"}
_SEARCH_BUDGET = 200_000


class CheckResult(BaseModel):
    success: bool
    reasons: list[str] = []
    goal_steps: dict[str, int | None] = {}  # task id -> first step its goal held (chosen instances)
    instances: dict[str, list[str]] = {}  # task id -> object instances that reached it
    execution_ok: bool = True


def _holds(goal: Goal, types: list[str], snap: Snapshot, i: int, lamp_on: bool) -> bool:
    flags = snap.flags[i]
    if not flags & PRESENT:
        return False
    if goal.kind == "examine_in_light":
        return snap.holder[i] >= 0 and lamp_on
    flag = _STATE_FLAG.get(goal.kind)
    if flag is not None and not goal.receptacles:  # "wash the towel": the state is the whole goal
        return bool(flags & flag)
    p = snap.parent[i]
    if p < 0:
        return False
    if goal.kind == "place_in_container":
        if types[p] not in goal.containers or snap.holder[p] >= 0:
            return False
        q = snap.parent[p]
        return q >= 0 and types[q] in goal.receptacles
    if types[p] not in goal.receptacles:
        return False
    return flag is None or bool(flags & flag)


def goal_series(execution: Execution, goal: Goal) -> dict[int, list[bool]]:
    """For each candidate instance index: does the goal hold after each snapshot (t=0 run masked)."""
    world = execution.world
    comp = _compiled(world)
    types = comp.types
    history = execution.state_history
    cands = [i for i, t in enumerate(types) if t in goal.objects]
    lamps = [i for i, t in enumerate(types) if t in goal.lights]
    out: dict[int, list[bool]] = {}
    for i in cands:
        series = []
        for snap in history:
            lamp_on = any(snap.flags[j] & ON for j in lamps) if lamps else False
            series.append(_holds(goal, types, snap, i, lamp_on))
        k = 0
        while k < len(series) and series[k]:  # true from the start: not achieved by the plan
            series[k] = False
            k += 1
        out[i] = series
    return out


def _options(execution: Execution, goal: Goal) -> list[tuple[int, frozenset[int]]]:
    """(first step, instances) ways the goal is reached, earliest first."""
    series = goal_series(execution, goal)
    times = [s.t for s in execution.state_history]
    opts = []
    for combo in itertools.combinations(sorted(series), goal.count):
        for k in range(len(times)):
            if all(series[i][k] for i in combo):
                opts.append((times[k], frozenset(combo)))
                break
    opts.sort(key=lambda o: (o[0], sorted(o[1])))
    return opts


def check(execution: Execution, gt_instance: GTInstance | dict, strict: bool = True) -> CheckResult:
    """Judge an execution against a ground-truth instance (see the module docstring)."""
    gt = gt_instance if isinstance(gt_instance, GTInstance) else GTInstance.model_validate(gt_instance)
    ids = execution.world.ids
    goals = {t.id: t.goal() for t in gt.tasks}
    options = {tid: _options(execution, g) for tid, g in goals.items()}
    reasons: list[str] = []
    if strict and not execution.ok:
        first = execution.violations[0]
        reasons.append(f"the execution has {len(execution.violations)} failed step(s), first: {first}")
    for tid, opts in options.items():
        if not opts:
            reasons.append(f"task {tid} ({goals[tid].describe()}) is never reached")
    before = [tuple(p) for p in gt.before]
    assignment = _assign(list(goals), options, before) if all(options.values()) else None
    if assignment is None and all(options.values()):
        reasons.extend(_explain(list(goals), options, before))
    chosen = assignment or _greedy(list(goals), options)
    goal_steps = {tid: (chosen[tid][0] if tid in chosen else None) for tid in goals}
    instances = {tid: sorted(ids[i] for i in chosen[tid][1]) for tid in chosen}
    return CheckResult(
        success=not reasons,
        reasons=reasons,
        goal_steps=goal_steps,
        instances=instances,
        execution_ok=execution.ok,
    )


def _assign(tasks, options, before) -> dict | None:
    """DFS for distinct instances per task that meet every `before` pair; None if there is none."""
    budget = [_SEARCH_BUDGET]
    chosen: dict[str, tuple[int, frozenset[int]]] = {}

    def ok_with(tid: str, t: int) -> bool:
        for x, y in before:
            if x == tid and y in chosen and not t < chosen[y][0]:
                return False
            if y == tid and x in chosen and not chosen[x][0] < t:
                return False
        return True

    def dfs(k: int, used: frozenset[int]) -> bool:
        if k == len(tasks):
            return True
        tid = tasks[k]
        for t, inst in options[tid]:
            budget[0] -= 1
            if budget[0] < 0:
                return False
            if inst & used or not ok_with(tid, t):
                continue
            chosen[tid] = (t, inst)
            if dfs(k + 1, used | inst):
                return True
            del chosen[tid]
        return False

    return dict(chosen) if dfs(0, frozenset()) else None


def _greedy(tasks, options) -> dict:
    """Earliest option per task, instances kept distinct where possible (for reporting)."""
    used: frozenset[int] = frozenset()
    out = {}
    for tid in tasks:
        for t, inst in options.get(tid, []):
            if not inst & used:
                out[tid] = (t, inst)
                used |= inst
                break
    return out


def _explain(tasks, options, before) -> list[str]:
    greedy = _greedy(tasks, options)
    reasons = []
    for tid in tasks:
        if tid not in greedy:
            reasons.append(f"task {tid} is only reached with objects another task already used")
    for x, y in before:
        if x in greedy and y in greedy and not greedy[x][0] < greedy[y][0]:
            reasons.append(
                f"order broken: task {x} must be reached before task {y}, "
                f"but {x} is first reached at t={greedy[x][0]} and {y} at t={greedy[y][0]}"
            )
    if not reasons:
        reasons.append("no assignment of distinct objects to tasks meets every ordering")
    return reasons


def constraint_violations(
    execution: Execution, constraints: Sequence[Constraint], completed: Mapping[str, int | None]
) -> list[str]:
    """Why the executed actions break the constraints (empty: they keep them). `completed`: spec node
    -> the step it completed (`logic.trace.check_trace`), which lifts an until-guard."""
    if not constraints:
        return []
    events = [(e.t, e.atom) for e in execution.events]
    if watches_states(constraints):
        types = _compiled(execution.world).types
        history = execution.state_history
        for before, after in zip(history, history[1:], strict=False):
            events += [(after.t, s) for s in state_events(types, before.flags, after.flags)]
    return violations(constraints, sorted(events), completed)


def watches_states(constraints: Sequence[Constraint]) -> bool:
    """Does a constraint forbid a change of state (`heat(Mug)`, `STATE_EVENTS`)? Only then are the
    state events of a trace worth computing."""
    return any(p.verb in STATE_EVENTS.values() for c in constraints for p in c.patterns)


def state_events(types: Sequence[str], before: Sequence[int], after: Sequence[int]) -> list[str]:
    """The state atoms a step makes true: `heat(Mug)` for each mug that was not hot before and is after."""
    out = []
    for i, (a, b) in enumerate(zip(before, after, strict=True)):
        gained = b & ~a
        out += [f"{verb}({types[i]})" for flag, verb in STATE_EVENTS.items() if gained & flag]
    return out


def final_conditions(
    execution: Execution, conditions: list[tuple[str, str | None, str | None]]
) -> list[bool]:
    """Final-state conditions (object name, state, contained name) as SMART-LLM judges them: on the
    last snapshot, each met by some object (`worlds.effects.condition_holds`)."""
    from nl2hltl2plan.worlds.effects import condition_holds

    return [condition_holds(execution.world, execution.final, n, s, c) for n, s, c in conditions]
