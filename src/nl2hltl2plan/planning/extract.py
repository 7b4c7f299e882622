"""From a goal node to a verified timed plan.

- `replay` re-runs an event sequence through the transition relation, optionally with other stand
  cells; it recomputes the timed schedule and re-checks every precondition.
- `refine_stand_cells`: the search walks to the *nearest* cell of each region. Given the chosen
  events, the best stand cells of one robot are a shortest path through its sequence of regions
  (a layered shortest-path problem, solved exactly with the distance matrix). The refined plan is
  kept when it is better for the objective (for `min` it never is worse).
- `to_plan` writes per-robot timed steps (moves along shortest paths, gaps are waits); `plan()` then
  validates it (`results.validate`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.planning.model import Problem
from nl2hltl2plan.planning.node import Event, Node
from nl2hltl2plan.planning.objective import Objective
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.planning.support import SUPPORT, support_event
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step


def replay(x: Expander, events: list[Event], stands: list[int] | None = None) -> Node | None:
    """The goal node of `events` replayed from the root (`stands`: per event, a stand cell)."""
    return replay_from(x, x.root(), events, stands)


def replay_from(x: Expander, node: Node, events: list[Event], stands: list[int] | None = None,
                keep_stands: bool = True, cutoff: Callable[[Node], bool] | None = None) -> Node | None:
    """Re-run events from `node` through the transition relation (None if one no longer applies);
    stand cells from `stands`, else the events' own (`keep_stands`) or the nearest ones. Support
    events are skipped: the actions they serve re-insert what the replayed state needs. `cutoff`:
    None as soon as it holds for a replayed node (the local searches stop a candidate whose cost so
    far already rules it out: every objective's value only grows along a replay)."""
    for i, e in enumerate(events):
        if cutoff is not None and cutoff(node):
            return None
        stand = stands[i] if stands is not None else (e.stand if keep_stands and e.stand >= 0 else None)
        if e.k == SUPPORT:
            if stands is None and not keep_stands:
                continue  # re-inserted, where still needed, by the action it serves
            child = support_event(x, node, e.robot, e.leaf, e.verb, e.objs[0], stand)
            if child is None:
                return None
            node = child
            continue
        if e.k < 0:
            child = x.put_down(node, e.robot, e.objs[1], e.leaf, stand=stand)
        else:
            leaf = x.p.leaves[e.leaf]
            q_next = next((q2 for k, q2 in leaf.moves.get(node.q[e.leaf], ()) if k == e.k), None)
            child = None if q_next is None else x.apply(node, e.robot, leaf, e.k, e.objs, q_next, stand=stand)
        if child is None:
            return None
        node = child
    return node


def reaching(objective: Objective, bar: tuple[int, ...]) -> Callable[[Node], bool]:
    """A replay's `cutoff`: the node's value already reaches `bar` (values only grow along a
    replay: summed cost, makespan), so the candidate cannot beat it."""

    def reached(node: Node) -> bool:
        return objective.value(node) >= bar

    return reached


def refine_stand_cells(x: Expander, goal: Node, objective: Objective, force: bool = False) -> Node:
    """Per robot, the stand cells minimising its walk through its regions (kept if better; with
    `force`, always: the search with free stand cells left them to be chosen here)."""
    events = goal.events()
    nav = x.nav
    stands = [e.stand for e in events]
    changed = False
    for r, start in enumerate(x.p.starts):
        idx = [i for i, e in enumerate(events) if e.robot == r]
        if not idx:
            continue
        regions = [nav.region_idx[events[i].anchor] for i in idx]
        cost = nav.dm[nav.cell_index[start], regions[0]].astype(np.int64)
        back = []
        for prev, cur in zip(regions, regions[1:], strict=False):
            total = cost[:, None] + nav.dm[np.ix_(prev, cur)]
            arg = total.argmin(axis=0)
            back.append(arg)
            cost = total[arg, np.arange(len(cur))]
        walked = sum(events[i].travel for i in idx)
        if int(cost.min()) >= walked and not force:
            continue
        k = int(cost.argmin())
        chosen = [0] * len(idx)
        for j in range(len(idx) - 1, -1, -1):
            chosen[j] = int(regions[j][k])
            if j:
                k = int(back[j - 1][k])
        for j, i in enumerate(idx):
            stands[i] = chosen[j]
        changed = True
    if not changed:
        return goal
    better = replay(x, events, stands)
    if better is None or not x.is_goal(better):
        if force:
            raise PlanningError("internal error: the chosen stand cells do not replay")
        return goal
    if force:
        return better
    return better if objective.value(better) < objective.value(goal) else goal


def to_plan(problem: Problem, x: Expander, events: list[Event]) -> Plan:
    world = problem.world
    ids = world.ids
    cells = x.nav.cells
    leaf_names = [lf.name for lf in problem.leaves]
    robots = []
    for r, start in enumerate(problem.starts):
        steps: list[Step] = []
        cur = start
        clock = 0
        for e in events:
            if e.robot != r:
                continue
            target = cells[e.stand]
            for cell in world.path(cur, target)[1:]:
                clock += 1
                steps.append(Step(t=clock, verb="move", cell=cell))
            cur = target
            if e.t <= clock:
                raise PlanningError(f"internal error: robot {r} cannot reach its action at t={e.t} in time")
            clock = e.t
            task = leaf_names[e.leaf] if e.leaf >= 0 else None
            steps.append(Step(t=e.t, verb=e.verb, objects=[ids[o] for o in e.objs], task=task))
        robots.append(RobotPlan(robot=r, start=start, steps=steps))
    return Plan(robots=robots)
