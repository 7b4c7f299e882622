"""`plan(world, spec, starts, ...)`: the planner's public entry point (see `plan`'s docstring)."""

from __future__ import annotations

import gc
import time
from collections.abc import Iterable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import replace
from typing import Any, Literal

from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.budget import Budget, StopReason
from nl2hltl2plan.planning.engines import CooperativeEngine, Engine
from nl2hltl2plan.planning.extract import refine_stand_cells, to_plan
from nl2hltl2plan.planning.heuristic import Heuristic
from nl2hltl2plan.planning.improve import improve
from nl2hltl2plan.planning.lns import lns
from nl2hltl2plan.planning.model import Infeasible, Problem, build_problem, required_leaves
from nl2hltl2plan.planning.navigation import Navigator
from nl2hltl2plan.planning.node import Node, with_free_stands
from nl2hltl2plan.planning.objective import Objective, ObjectiveName, objective_for
from nl2hltl2plan.planning.results import (
    GRID_MODEL,
    NEAREST_CELL_MODEL,
    PlanResult,
    PlanStatus,
    optimality_words,
    validate,
)
from nl2hltl2plan.planning.search import NODE_BYTES, Deadline, ProgressHook, Searcher, SearchStats, Stall
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.worlds.world import CELL_M, Cell, World

Mode = Literal["fast", "exact"]
DEFAULT_TIMEOUT_S = 300.0
DEFAULT_W = 1.5
# fast mode's budgets, chosen on valid_seen scenarios (scripts/planner_validation.py, docs/planning.md)
FAST_EXPANSIONS = 300  # AWA* expansions `fast` spends improving its first plan (at most)
FAST_GENERATED = 5_000  # and AWA* successors generated (at most: large teams branch widely)
FAST_WORK = 400_000  # and heuristic work (assignment-matrix cells: fewer evaluations on larger problems)
FAST_GAP = 1.05  # fast mode stops once its plan is proven within this factor of the optimum
# and its A* stops once the proven bound has stopped rising: after FAST_STALL_WORK units of work, when
# the bound last rose more than STALL_SHARE of the work spent ago, unless the plan is at most STALL_NEAR
# objective units above the bound (the next rise may prove it; chosen on valid_seen, docs/planning.md)
FAST_STALL_WORK = 100_000
STALL_SHARE = 2 / 3
STALL_NEAR = 1.0
IMPROVE_EVALS = 600  # local-search candidate replays (both modes)
LNS_EVALS = 2000  # large-neighbourhood-search candidate replays (both modes)
# replays cost in proportion to the plan's events: both local searches also stop after this many
# replayed events (a 10-event plan keeps its 600 / 2,000 replays, a 50-event one gets fewer)
IMPROVE_EVENTS = 12_000
LNS_EVENTS = 30_000
MAX_NODES = 400_000  # search nodes held at once (about 1.5 GB), the memory bound
BEAM_WIDTH = 8
BEAM_INSTANCES = 3
SOLO_WIDTH = 4  # beam width of the single-robot seeds
SOLO_SEEDS = 4  # robots tried alone (the best placed ones)


def _seed(searcher: Searcher, x: Expander, root: Node, light: bool) -> Node | None:
    """The cheapest of beam searches in which one well-placed robot does everything (for the summed
    cost, which often favours one robot; ranked by the full bound, which finds much cheaper solo
    plans on large problems), then a greedy and a team beam search, ranked by the assignment bound
    alone when `light` and pruned by the solo plans' cost (a child whose bound reaches it cannot
    lead to a cheaper plan); local search then shares work out."""
    found: list[Node] = []
    if searcher.obj.solo_seeds and x.p.n_robots > 1:
        for robot in _well_placed(x, root)[:SOLO_SEEDS]:
            goal = searcher.beam(root, SOLO_WIDTH, BEAM_INSTANCES, robots=frozenset({robot}))
            if goal is not None:
                found.append(goal)
    searcher.h.light = light
    try:
        for width, limit in ((1, 1), (BEAM_WIDTH, BEAM_INSTANCES)):
            ub = min(map(searcher.cost, found)) if found else None
            goal = searcher.beam(root, width, limit, ub=ub)
            if goal is not None:
                found.append(goal)
    finally:
        searcher.h.light = False
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


def plan(
    world: World,
    spec: HierarchicalSpec,
    starts: Sequence[Cell],
    objective: ObjectiveName = "min",
    mode: Mode = "fast",
    timeout_s: float = DEFAULT_TIMEOUT_S,
    capabilities: Sequence[Iterable[str] | None] | None = None,
    w: float = DEFAULT_W,
    fast_expansions: int | None = FAST_EXPANSIONS,
    fast_work: int | None = FAST_WORK,
    fast_stall_work: int | None = FAST_STALL_WORK,
    improve_evals: int = IMPROVE_EVALS,
    lns_evals: int = LNS_EVALS,
    max_nodes: int | None = MAX_NODES,
    refine: bool | None = None,
    on_progress: ProgressHook | None = None,
) -> PlanResult:
    """Plan for a robot team under a hierarchical sc-LTL spec; every returned plan is executed in
    the simulator and checked against the spec (`validate`) before it is returned.

    world: a `worlds.World`. spec: a `HierarchicalSpec` whose leaf atoms are robot actions on
    object types. starts: one free cell per robot. capabilities: optional, per robot, the verbs
    ("pickup") or atoms ("toggle_on(Faucet)") it may do (None: everything).

    objective: "min" minimises moves + actions summed over robots (the paper's cost); "minmax"
    minimises the completion time (steps), ties broken by the summed cost.
    mode: "exact" searches until the plan is proven optimal (`result.model` names the model the
    optimum is over). "fast" (default) is anytime: beam-search seeds, local search
    (`improve_evals` candidate replays), large-neighbourhood search (`lns_evals` replays), then
    anytime weighted A* (weight `w`) for at most `fast_expansions` expansions, FAST_GENERATED
    successors and `fast_work` units of heuristic work (assignment-matrix cells: a larger problem
    gets fewer evaluations), stopping as soon as the plan is proven within FAST_GAP (5 %), or, past
    `fast_stall_work` units, once its proven bound has not risen for STALL_SHARE of the work spent
    while the plan is more than STALL_NEAR above it (None: never); `bound` is the ratio to the
    optimum it could prove. With `fast_expansions=None`, fast stops as soon as the plan is proven
    within factor `w`. Every budget
    counts machine-independent units, so the same input gives the same plan; `timeout_s` is a
    wall-clock last resort, reported as such (`stopped == "timeout"`). `max_nodes` bounds the
    search's memory (nodes held at once; reported as `peak_nodes`, `memory_mb`).
    `refine` (default: on in fast, off in exact) re-optimises each robot's stand cells for the chosen
    events, which never makes a plan worse (`model_cost` is the value before, `cost` after).

    Returns a `PlanResult` (status solved / infeasible with the reason / timeout / error: a plan that
    failed validation, a planner bug, with the reason). The first of `ENGINES` that supports the world
    plans: a `handover` world (fixed arms) goes to the cooperative engine (`planning.engines`), which
    answers in the same `PlanResult`; every other world to the search planner. Malformed input
    (not a HierarchicalSpec, a start cell that is not free, a leaf atom that is not an action)
    raises `PlanningError`. `on_progress`, when given, hears the search's `SearchStats` (expansions,
    best cost and lower bound so far) every quarter second or so (the web page's progress).
    """
    _check_arguments(spec, objective, mode, w)
    engine = next(e for e in ENGINES if e.supports(world))
    with _without_cycle_collection():
        return engine.solve(
            world, spec, starts, objective=objective, mode=mode, timeout_s=timeout_s,
            capabilities=capabilities, w=w, fast_expansions=fast_expansions, fast_work=fast_work,
            fast_stall_work=fast_stall_work, improve_evals=improve_evals, lns_evals=lns_evals,
            max_nodes=max_nodes, refine=refine, on_progress=on_progress,
        )


@contextmanager
def _without_cycle_collection() -> Iterator[None]:
    """Python's cycle collector off while planning: a search allocates hundreds of thousands of
    nodes, tuples and states that form no reference cycles (a node points to its parent only), and
    each full collection walks every live object of the process (a loaded data set included), which
    cost sub-second plans up to several times their own time. Reference counting still frees them."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


class SearchEngine:
    """The search planner (this module): every grid world with mobile robots."""

    name = "search"

    def supports(self, world: World) -> bool:
        return True

    def solve(
        self, world: World, spec: HierarchicalSpec, starts: Sequence[Cell], **options: Any
    ) -> PlanResult:
        return _search_plan(world, spec, starts, **options)


ENGINES: list[Engine] = [CooperativeEngine(), SearchEngine()]  # asked in order: the first that supports


def _search_plan(
    world: World,
    spec: HierarchicalSpec,
    starts: Sequence[Cell],
    objective: ObjectiveName,
    mode: Mode,
    timeout_s: float,
    capabilities: Sequence[Iterable[str] | None] | None,
    w: float,
    fast_expansions: int | None,
    fast_work: int | None,
    fast_stall_work: int | None,
    improve_evals: int,
    lns_evals: int,
    max_nodes: int | None,
    refine: bool | None,
    on_progress: ProgressHook | None,
) -> PlanResult:
    """`plan` by the search planner: seeds, local search, AWA* (see `plan`)."""
    t0 = time.perf_counter()
    obj = objective_for(objective)
    result = PlanResult(status=PlanStatus.TIMEOUT, objective=objective, mode=mode)
    deadline = t0 + timeout_s
    try:
        problem = build_problem(world, spec, starts, capabilities, dfa_timeout_s=max(1.0, timeout_s))
    except Infeasible as exc:
        result.status, result.reason = PlanStatus.INFEASIBLE, exc.reason
        result.plan_time_s = time.perf_counter() - t0
        return result
    x = Expander(problem, Navigator(world))
    required = {problem.leaf_index[n] for n in required_leaves(problem)}
    searcher = Searcher(x, Heuristic(x, required, makespan=obj.makespan_bound), obj, deadline, on_progress)
    budget = _budget(mode, w, fast_expansions, fast_work, fast_stall_work, improve_evals, lns_evals,
                     max_nodes, grid_model(objective, mode))
    best = _search(searcher, x, budget)
    stats = searcher.stats
    result.expanded, result.peak_nodes = stats.expanded, stats.peak_nodes
    result.memory_mb = round(stats.peak_nodes * NODE_BYTES / 2**20, 1)
    result.stopped, result.stop_reason = stats.stopped, stats.stopped.sentence
    if best is None:
        if stats.exhausted:
            result.status = PlanStatus.INFEASIBLE
            result.reason = ("no sequence of robot actions satisfies the specification in this world "
                             f"(searched {stats.expanded} states)")
            if x.missing_support:
                result.reason = (f"no robot in the team can {', '.join(sorted(x.missing_support))}, "
                                 "which the tasks need; " + result.reason)
            if x.blocked_by:
                result.reason += f"; the constraints forbade: {'; '.join(sorted(x.blocked_by))}"
        else:
            result.reason = f"no plan found within {timeout_s:g} s (wall-clock timeout, last resort)"
        result.plan_time_s = time.perf_counter() - t0
        return result
    try:
        _fill_solved(result, problem, x, obj, best, stats, True if refine is None else refine)
    except PlanningError as exc:  # a planner bug: reported, never a plan that fails validation
        result.status, result.reason, result.plan, result.execution = PlanStatus.ERROR, str(exc), None, None
    result.model = GRID_MODEL if grid_model(objective, mode) else NEAREST_CELL_MODEL
    result.plan_time_s = time.perf_counter() - t0
    return result


def _budget(mode: str, w: float, expansions: int | None, work: int | None, stall_work: int | None,
            improve_evals: int, lns_evals: int, max_nodes: int | None, free_stands: bool) -> Budget:
    """Exact: no A* budget, stop when proven optimal. Fast: the budgets (the work budget sizes the
    A* to the problem: a large problem's evaluations cost more, so it gets fewer; the stall stop),
    stopping as soon as the plan is proven within FAST_GAP; with `expansions=None`, until proven
    within `w`."""
    local = Budget(improve_evals=improve_evals, lns_evals=lns_evals, max_nodes=max_nodes,
                   free_stands=free_stands)
    if mode == "exact":
        return local
    if expansions is None:
        return replace(local, w_stop=w, w_order=w)
    return replace(local, expansions=expansions, generated=FAST_GENERATED, work=work, w_stop=min(w, FAST_GAP),
                   w_order=w, light_seeds=True, stall_work=stall_work)


def grid_model(objective: str, mode: str) -> bool:
    """Is the optimum searched over every stand cell (the grid), not only the nearest ones? For the
    summed cost (both modes). The makespan's schedule couples robots (one waits for another's
    event), so its search walks to nearest cells and refines the stand cells afterwards."""
    return objective == "min"


def _check_arguments(spec: object, objective: str, mode: str, w: float) -> None:
    if not isinstance(spec, HierarchicalSpec):
        raise PlanningError(f"plan() takes a HierarchicalSpec, got {type(spec).__name__} "
                            "(build one with HierarchicalSpec(levels) or HierarchicalSpec.from_json)")
    if objective not in ("min", "minmax"):
        raise PlanningError(f"unknown objective {objective!r}; use 'min' or 'minmax'")
    if mode not in ("fast", "exact"):
        raise PlanningError(f"unknown mode {mode!r}; use 'fast' or 'exact'")
    if w < 1.0:
        raise PlanningError(f"the suboptimality bound w must be >= 1, got {w}")


def _search(searcher: Searcher, x: Expander, budget: Budget) -> Node | None:
    """Seeds, local search, then AWA*; the best goal node found (None if none)."""
    best: Node | None = None
    root = x.root()
    try:
        if x.is_goal(root):
            searcher.stats.proven_optimal, searcher.stats.stopped = True, StopReason.TRIVIAL
            return root
        searcher.score(root)  # the full bound at the root: the A*'s first lower bound
        seed = _seed(searcher, x, root, budget.light_seeds)
        best = seed
        if best is not None and budget.free_stands:  # the incumbent's cost on the grid: its best stand cells
            best = refine_stand_cells(x, best, searcher.obj)
        if (seed is not None and best is not None
                and not searcher.obj.proven(searcher.cost(best), root.f, 1.0)):
            # local search on the allocation first (unless the root's bound proves the seed
            # optimal already): a better incumbent also prunes the A*. It compares candidates at
            # their nearest stand cells, so it starts from the seed's nearest-cell plan (a refined
            # incumbent against nearest-cell candidates would reject orders that refine better)
            n = max(1, len(seed.events()))
            found = improve(x, seed, searcher.obj, min(budget.improve_evals, max(1, IMPROVE_EVENTS // n)),
                            searcher.check_time)
            found = lns(x, found, searcher.obj, min(budget.lns_evals, max(1, LNS_EVENTS // n)),
                        searcher.check_time)
            if budget.free_stands:
                found = refine_stand_cells(x, found, searcher.obj)
            if searcher.obj.value(found) < searcher.obj.value(best):
                best = found
            searcher.found(best)
        start = with_free_stands(root) if budget.free_stands else root
        stall = None if budget.stall_work is None else Stall(budget.stall_work, STALL_SHARE, STALL_NEAR)
        best = searcher.awa(start, best, budget.w_order, budget.w_stop, max_expansions=budget.expansions,
                            max_nodes=budget.max_nodes, max_generated=budget.generated, max_work=budget.work,
                            stall=stall)
    except Deadline:
        searcher.stats.stopped = StopReason.TIMEOUT
    return best


def _fill_solved(result: PlanResult, problem: Problem, x: Expander, obj: Objective, best: Node,
                 stats: SearchStats, refine: bool) -> None:
    """Refine, write, validate and report a solved plan."""
    model_cost = obj.reported(best)
    if best.reach is not None:  # found with free stand cells: choose them now (same cost)
        refined = refine_stand_cells(x, best, obj, force=True)
    else:
        refined = refine_stand_cells(x, best, obj) if refine else best
    events = refined.events()
    the_plan = to_plan(problem, x, events)
    verdict = validate(problem.world, problem.spec, the_plan)
    if not verdict.ok:
        raise PlanningError("internal error: the planner's plan fails validation: "
                            + "; ".join(verdict.reasons))
    execution = verdict.execution
    result.status = PlanStatus.SOLVED
    result.plan, result.execution = the_plan, execution
    result.travel_m, result.steps = execution.travel_m, execution.steps
    result.total_cost = refined.g
    result.cost = float(obj.reported(refined))
    result.model_cost = float(model_cost)
    lower = float(model_cost) if stats.proven_optimal else stats.lower_bound
    result.lower_bound = lower
    result.bound = (model_cost / lower) if lower > 0 else None  # both over the search's model
    result.proven_optimal = stats.proven_optimal
    result.optimality = optimality_words(result.proven_optimal, result.bound)
    world = problem.world
    result.events = [
        PlanEvent(t=e.t, robot=e.robot, atom=e.atom,
                  task=problem.leaves[e.leaf].name if e.leaf >= 0 else None,
                  objects=[world.ids[o] for o in e.objs], travel_m=e.travel * CELL_M)
        for e in events
    ]
