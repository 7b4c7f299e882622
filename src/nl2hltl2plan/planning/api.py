"""`plan(world, spec, starts, ...)`: the planner's public entry point (see `plan`'s docstring)."""

from __future__ import annotations

import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any, Literal

from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.extract import refine_stand_cells, to_plan, verify
from nl2hltl2plan.planning.heuristic import Heuristic
from nl2hltl2plan.planning.improve import improve
from nl2hltl2plan.planning.model import Infeasible, _required_leaves, build_problem
from nl2hltl2plan.planning.navigation import Navigator
from nl2hltl2plan.planning.search import Deadline, Searcher
from nl2hltl2plan.planning.state import Expander, Node
from nl2hltl2plan.worlds.model import CELL_M, Cell, World
from nl2hltl2plan.worlds.plan import Plan
from nl2hltl2plan.worlds.simulator import Execution

Objective = Literal["min", "minmax"]
Mode = Literal["fast", "exact"]
DEFAULT_TIMEOUT_S = 300.0
DEFAULT_W = 1.5
FAST_EXPANSIONS = 2000  # AWA* expansions `fast` spends improving its first plan (at most)
FAST_IMPROVE_S = 1.0  # and seconds (at most): half local search, half AWA*
LNS_EXACT_S = 2.0  # local search before the exact search (a good incumbent prunes it)
BEAM_WIDTH = 8
BEAM_INSTANCES = 3
SOLO_WIDTH = 4  # beam width of the single-robot seeds
SOLO_SEEDS = 4  # robots tried alone (the best placed ones)


def _seed(searcher: Searcher, x: Expander, root: Node, objective: str) -> Node | None:
    """The cheapest of a greedy and a beam search over the team and, for the summed cost, of beam
    searches in which one well-placed robot does everything (summed cost often favours one robot,
    which the team beam, deciding one step at a time, can miss); local search then shares work out."""
    found = [searcher.beam(root, 1, 1), searcher.beam(root, BEAM_WIDTH, BEAM_INSTANCES)]
    if objective == "min" and x.p.n_robots > 1:
        for r in _well_placed(x, root)[:SOLO_SEEDS]:
            x.only = {r}
            try:
                found.append(searcher.beam(root, SOLO_WIDTH, BEAM_INSTANCES))
            finally:
                x.only = None
    found = [n for n in found if n is not None]
    return min(found, key=searcher.cost) if found else None


def _well_placed(x: Expander, root: Node) -> list[int]:
    """Robots by the summed walk from their start to each leaf's nearest first object."""
    nav = x.nav
    firsts = []
    for lf in x.p.leaves:
        anchors = set()
        for k, _ in lf.moves.get(lf.init, []):
            atom = lf.atoms[k]
            for o in x.candidates(root, lf, atom, len(atom.types) - 1):
                a = nav.anchor(root.sim, o if x.slice_of[o] < 0 else x.slice_of[o])
                if a >= 0:
                    anchors.add(a)
        if anchors:
            firsts.append(anchors)

    def spread(r: int) -> tuple[int, int]:
        cell = root.cell[r]
        return (sum(min(nav.dist(cell, a) for a in anchors) for anchors in firsts), r)

    return sorted(range(x.p.n_robots), key=spread)


class PlanStatus(StrEnum):
    """How a planning call ended (a str enum: `status == "solved"` keeps working)."""

    SOLVED = "solved"
    INFEASIBLE = "infeasible"
    TIMEOUT = "timeout"
    ERROR = "error"


@dataclass
class PlanResult:
    """Outcome of `plan`. `status`: "solved" (a verified plan), "infeasible" (`reason` says why no
    plan exists) or "timeout" (no plan within the time limit)."""

    status: Literal["solved", "infeasible", "timeout"]
    reason: str = ""
    objective: str = "min"
    mode: str = "fast"
    plan: Plan | None = None
    travel_m: float | None = None  # metres walked, summed over robots
    steps: int | None = None  # completion time: last step at which some robot acts
    total_cost: int | None = None  # moves + actions, summed over robots (the paper's cost)
    cost: float | None = None  # the objective: total_cost (min) or steps (minmax)
    model_cost: float | None = None  # the objective before stand-cell refinement (the search's value)
    lower_bound: float | None = None  # proven lower bound on the optimal model_cost
    bound: float | None = None  # cost / lower_bound (1.0: proven optimal)
    proven_optimal: bool = False
    plan_time_s: float = 0.0
    expanded: int = 0
    generated: int = 0
    stopped: str = ""  # why the search stopped: bound, exhausted, budget, timeout
    execution: Execution | None = field(default=None, repr=False)
    events: list[dict[str, Any]] = field(default_factory=list)

    @property
    def solved(self) -> bool:
        return self.status == "solved"

    def to_dict(self, with_plan: bool = True) -> dict[str, Any]:
        out = {k: getattr(self, k) for k in (
            "status", "reason", "objective", "mode", "travel_m", "steps", "total_cost", "cost",
            "model_cost", "lower_bound", "bound", "proven_optimal", "plan_time_s", "expanded", "generated",
            "stopped")}
        if with_plan:
            out["plan"] = self.plan.model_dump(mode="json") if self.plan is not None else None
            out["events"] = self.events
        return out


def plan(
    world: World,
    spec: HierarchicalSpec | list | str,
    starts: Sequence[Cell],
    objective: Objective = "min",
    mode: Mode = "fast",
    timeout_s: float = DEFAULT_TIMEOUT_S,
    capabilities: Sequence[Iterable[str] | None] | None = None,
    w: float = DEFAULT_W,
    fast_expansions: int | None = FAST_EXPANSIONS,
    fast_improve_s: float | None = FAST_IMPROVE_S,
    refine: bool | None = None,
) -> PlanResult:
    """Plan for a robot team under a hierarchical sc-LTL spec; every returned plan is executed in
    the simulator and checked against the spec before it is returned.

    world: a `worlds.World`. spec: a `HierarchicalSpec` (or its JSON levels) whose leaf atoms are
    robot actions on object types. starts: one free cell per robot. capabilities: optional, per
    robot, the verbs ("pickup") or atoms ("toggle_on(Faucet)") it may do (None: everything).

    objective: "min" minimises moves + actions summed over robots (the paper's cost); "minmax"
    minimises the completion time (steps), ties broken by the summed cost.
    mode: "exact" returns a plan proven optimal for the objective in the planner's model (robots walk
    shortest paths to the nearest cell of each interaction region; a leaf follows one of its minimal
    action sequences; a leaf starts after the tasks ordered before it are complete). "fast" (default)
    is anytime: a beam-search plan first, then anytime weighted A* (weight `w`) improves it until
    it is proven optimal or the improvement budget (`fast_expansions` expansions, `fast_improve_s`
    seconds) is spent; `bound` is the ratio to the optimum it could prove. With both budgets None,
    fast stops as soon as the plan is proven within factor `w` (bounded suboptimality). `refine`
    (default: on in fast, off in exact, so that an exact plan is the model's optimum) then
    re-optimises each robot's stand cells for the chosen events, which never makes a plan worse
    (`model_cost` is the value before, `cost` after).

    Returns a `PlanResult`: status solved / infeasible (with the reason) / timeout (no plan within
    `timeout_s`); plan (per-robot timed steps), travel_m, steps, total_cost, cost, lower_bound,
    bound, plan_time_s, expanded, execution (the simulator's run). Malformed input (a start cell
    that is not free, a leaf atom that is not an action) raises `PlanningError`.
    """
    t0 = time.perf_counter()
    if objective not in ("min", "minmax"):
        raise PlanningError(f"unknown objective {objective!r}; use 'min' or 'minmax'")
    if mode not in ("fast", "exact"):
        raise PlanningError(f"unknown mode {mode!r}; use 'fast' or 'exact'")
    if w < 1.0:
        raise PlanningError(f"the suboptimality bound w must be >= 1, got {w}")
    if not isinstance(spec, HierarchicalSpec):
        spec = HierarchicalSpec.from_json(spec)
    result = PlanResult(status="timeout", objective=objective, mode=mode)
    deadline = t0 + timeout_s
    try:
        problem = build_problem(world, spec, starts, capabilities, dfa_timeout_s=max(1.0, timeout_s))
    except Infeasible as exc:
        result.status, result.reason = "infeasible", exc.reason
        result.plan_time_s = time.perf_counter() - t0
        return result
    nav = Navigator(world)
    x = Expander(problem, nav)
    required = {problem.leaf_index[n] for n in _required_leaves(problem)}
    searcher = Searcher(x, Heuristic(x, required), objective, deadline)
    best: Node | None = None
    root = x.root()
    try:
        if x.is_goal(root):
            best = root
            searcher.stats.proven_optimal = True
        else:
            best = _seed(searcher, x, root, objective)
            if best is not None:
                searcher.stats.seed_cost = float(searcher.cost(best))
                searcher.stats.seed_time_s = time.perf_counter() - t0
                # local search on the allocation first: a better incumbent also prunes the A*
                share = LNS_EXACT_S if mode == "exact" else (fast_improve_s or FAST_IMPROVE_S) / 2
                best, searcher.stats.lns_moves = improve(x, best, objective,
                                                         min(deadline, time.perf_counter() + share))
            if mode == "exact":
                best = searcher.awa(root, best, 1.0, 1.0)
            else:
                unbounded = fast_expansions is None and fast_improve_s is None
                best = searcher.awa(
                    root, best, w, w if unbounded else 1.0, max_expansions=fast_expansions,
                    stop_at=None if fast_improve_s is None else time.perf_counter() + fast_improve_s / 2,
                )
    except Deadline:
        searcher.stats.stopped = "timeout"
        if best is None:
            result.reason = f"no plan found within {timeout_s:g} s"
    stats = searcher.stats
    result.expanded, result.generated, result.stopped = stats.expanded, stats.generated, stats.stopped
    if best is None:
        if stats.exhausted:
            result.status = "infeasible"
            result.reason = ("no sequence of robot actions satisfies the specification in this world "
                             f"(searched {stats.expanded} states)")
        result.plan_time_s = time.perf_counter() - t0
        return result
    unit_cost = searcher.cost(best) if objective == "min" else best.ms
    if refine is None:
        refine = mode == "fast"
    refined = refine_stand_cells(x, best, objective) if refine else best
    events = refined.events()
    the_plan = to_plan(problem, x, events)
    execution = verify(problem, the_plan)
    result.status = "solved"
    result.plan = the_plan
    result.execution = execution
    result.travel_m = execution.travel_m
    result.steps = execution.steps
    result.total_cost = refined.g
    result.cost = float(refined.g if objective == "min" else refined.ms)
    result.model_cost = float(unit_cost)
    if stats.proven_optimal:
        stats.lower_bound = float(unit_cost)
    result.lower_bound = stats.lower_bound
    result.bound = (unit_cost / stats.lower_bound) if stats.lower_bound > 0 else None
    result.proven_optimal = stats.proven_optimal
    result.events = [
        {"t": e.t, "robot": e.robot, "atom": e.atom,
         "task": problem.leaves[e.leaf].name if e.leaf >= 0 else None,
         "objects": [world.ids[o] for o in e.objs], "travel_m": e.travel * CELL_M}
        for e in events
    ]
    result.plan_time_s = time.perf_counter() - t0
    return result
