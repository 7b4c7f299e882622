"""Work the planner does once instead of per node: the pending work shared by nodes in one object
state, local-search replays that stop once they cannot win, and the cycle collector off while
planning. None of it may change a bound, a plan or the caller's collector setting."""

from __future__ import annotations

import gc
import random
import time

import pytest
from planning_worlds import gt
from test_grid_optimum import PLACE_APPLE, PLACE_MUG, _random_world

from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.planning.extract import reaching, replay_from
from nl2hltl2plan.planning.heuristic import HANDS, Heuristic
from nl2hltl2plan.planning.model import build_problem, required_leaves
from nl2hltl2plan.planning.navigation import Navigator
from nl2hltl2plan.planning.objective import objective_for
from nl2hltl2plan.planning.search import Searcher
from nl2hltl2plan.planning.state import Expander


def _expander(seed: int, robots: int) -> tuple[Expander, set[int]]:
    rng = random.Random(seed)
    world = _random_world(rng)
    starts = rng.sample(world.cells, robots)
    problem = build_problem(world, oracle_spec(gt([PLACE_APPLE, PLACE_MUG]), world).spec, starts, None)
    return Expander(problem, Navigator(world)), {problem.leaf_index[n] for n in required_leaves(problem)}


@pytest.mark.parametrize("seed", [2, 8])
def test_shared_pending_work_gives_the_bound_of_a_fresh_evaluation(seed):
    x, required = _expander(seed, 3)
    shared = Heuristic(x, required)
    nodes = [x.root()]
    for _depth in range(3):  # three layers of successors: the same events by other robots meet
        nodes += [child for node in nodes[-40:] for child in x.successors(node)][:120]
    for node in nodes:
        assert shared.evaluate(node) == Heuristic(x, required).evaluate(node)
    # nodes whose objects are in one state share one entry, and so do the robot-independent parts
    # of its hand rules (per_pending.py)
    assert 0 < len(shared._pending_cache) < len(nodes)
    assert 0 < sum(HANDS in pending.memo for pending in shared._pending_cache.values()) < len(nodes)


def test_a_replay_stops_once_its_cost_reaches_the_bar():
    x, required = _expander(3, 2)
    obj = objective_for("min")
    goal = Searcher(x, Heuristic(x, required), obj, time.perf_counter() + 60).beam(x.root(), 1, 1)
    assert goal is not None
    events = goal.events()
    replayed = replay_from(x, x.root(), events, keep_stands=False)
    assert replayed is not None and x.is_goal(replayed) and replayed.g == goal.g
    # a bar above the plan's cost lets it through unchanged; one its first event reaches stops it
    through = replay_from(x, x.root(), events, keep_stands=False, cutoff=reaching(obj, (goal.g + 1,)))
    assert through is not None and through.g == goal.g
    first = replay_from(x, x.root(), events[:1], keep_stands=False)
    assert first is not None and 0 < first.g < goal.g
    assert replay_from(x, x.root(), events, keep_stands=False, cutoff=reaching(obj, (first.g,))) is None


@pytest.mark.parametrize("enabled", [True, False])
def test_planning_leaves_the_cycle_collector_as_it_found_it(enabled):
    x, _ = _expander(2, 1)
    was = gc.isenabled()
    try:
        gc.enable() if enabled else gc.disable()
        result = plan(x.p.world, x.p.spec, x.p.starts)
        assert result.status == "solved"
        assert gc.isenabled() is enabled
    finally:
        gc.enable() if was else gc.disable()
