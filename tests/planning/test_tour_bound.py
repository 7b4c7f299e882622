"""The root's tour bound (`planning/tour.py`): cell-level paths out of the robots through the
events' regions. Exact on hand-worked cases, never above the optimum (an independent brute force on
random small grids), and stronger where regions overlap in a chain."""

from __future__ import annotations

import random

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from planning_worlds import corridor, gt
from test_grid_optimum import PLACE_APPLE, PLACE_MUG, _random_world, brute_force

from nl2hltl2plan.planning import heuristic, oracle_spec, plan
from nl2hltl2plan.planning.heuristic import Heuristic
from nl2hltl2plan.planning.model import build_problem, required_leaves
from nl2hltl2plan.planning.navigation import Navigator
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.planning.tour import _forest, _split_chain

# a chain of overlapping regions along the corridor (each covers its column +- 6): the apple's
# (6..18) meets the counter's (18..30), which meets the mug's and the table's (30..39)
CHAIN = {"Apple_0": 12, "CounterTop_0": 24, "Mug_0": 36, "DiningTable_0": 36}
PLACE_BOOK = {"id": "C", "kind": "place", "object": ["Book"], "receptacle": ["Shelf"]}


def _root_bound(world, inst, starts) -> int:
    problem = build_problem(world, oracle_spec(inst, world).spec, starts, None)
    x = Expander(problem, Navigator(world))
    h = Heuristic(x, {problem.leaf_index[n] for n in required_leaves(problem)})
    return h.evaluate(x.root())[0]


def _line(n: int) -> np.ndarray:
    """The distance matrix of n cells in a row."""
    idx = np.arange(n)
    return np.abs(idx[:, None] - idx[None, :])


def test_forest_on_a_line():
    dm = _line(40)
    stops = [np.arange(10, 13), np.arange(20, 23)]
    cells = np.concatenate(stops)
    # one robot at 0: through 10 to 20
    assert _forest(dm, stops, dm[[0]][:, cells]) == 20
    # robots at 0 and 30: each takes the stop nearer to it (10 + 8), or one takes both (20)
    assert _forest(dm, stops, dm[[0, 30]][:, cells]) == 18
    # a robot at 21 stands in the second stop already: it walks 9, to 12
    assert _forest(dm, stops, dm[[21]][:, cells]) == 9
    # a stop nobody reaches: no claim
    assert _forest(np.where(dm > 15, 1 << 30, dm), stops, np.array([[1 << 30] * len(cells)])) == 0


def test_a_chain_of_overlapping_regions_is_walked_cell_by_cell(monkeypatch):
    # one robot at column 0: walk to 6, pick the apple, walk to 18, put it, walk to 30, pick the mug,
    # put it: 30 steps + 4 actions = 34. Region to region, the chain costs nothing past the apple
    # (the regions touch); the carries through one cell give 18: 22. Cell by cell, the robot must
    # reach column 30: 34, the optimum.
    world = corridor(CHAIN)
    inst = gt([PLACE_APPLE, PLACE_MUG])
    r = plan(world, oracle_spec(inst, world).spec, [(0, 0)], mode="exact")
    assert r.proven_optimal and r.total_cost == 34
    assert _root_bound(world, inst, [(0, 0)]) == 34
    monkeypatch.setattr(heuristic, "tour_walk", lambda *args: 0)
    monkeypatch.setattr(heuristic, "chain_walk", lambda *args: 0)  # one leaf's chain walks to 30 too
    monkeypatch.setattr(heuristic, "hands_walk", lambda *args: 0)  # and the hands' walk (hands.py)
    assert _root_bound(world, inst, [(0, 0)]) == 22


def test_a_robot_inside_a_stop_does_it_for_free(monkeypatch):
    # a second robot at column 39 stands in the mug's and the table's region, so that stop is
    # dropped (it costs nothing); the apple's and the counter's are split: the first robot walks 6 to
    # the apple, the second 9 to the counter (15). The optimum: the second robot does the mug
    # without walking, the first walks 18 for the apple: 22.
    world = corridor(CHAIN)
    inst = gt([PLACE_APPLE, PLACE_MUG])
    r = plan(world, oracle_spec(inst, world).spec, [(0, 0), (0, 39)], mode="exact")
    assert r.proven_optimal and r.total_cost == 22
    walks = []
    real = heuristic.tour_walk
    monkeypatch.setattr(heuristic, "tour_walk", lambda *args: walks.append(real(*args)) or walks[-1])
    assert _root_bound(world, inst, [(0, 0), (0, 39)]) <= 22
    assert walks == [15]


def test_one_robot_walks_ordered_tasks_in_their_order(monkeypatch):
    # mug, then apple, then book, one robot at column 0: to 30 for the mug (its region and the
    # book's: 30..39), back to 18 for the apple (apple and counter: 6..18), again to 30 for the book:
    # walk 54, + 6 actions = 60. In any order (the tour) the walk is 30; along the order of the
    # tasks, cell by cell, the chain walks 54: the optimum.
    world = corridor({"Mug_0": 36, "DiningTable_0": 36, "Apple_0": 12, "CounterTop_0": 12,
                      "Book_0": 36, "Shelf_0": 36})
    inst = gt([PLACE_APPLE, PLACE_MUG, PLACE_BOOK], before=[("B", "A"), ("A", "C")])
    r = plan(world, oracle_spec(inst, world).spec, [(0, 0)], mode="exact")
    assert r.proven_optimal and r.total_cost == 60
    walks = []
    real = heuristic.chain_walk
    monkeypatch.setattr(heuristic, "chain_walk", lambda *args: walks.append(real(*args)) or walks[-1])
    assert _root_bound(world, inst, [(0, 0)]) == 60
    assert walks == [54]


def test_robots_split_a_chain_in_its_order():
    # a chain 0 -> 1 -> 2 with steps 10 and 10 (0 to 2: 20); robot a at chain event 0's place,
    # robot b at 2's: a does 0 and 1 (10), b does 2 (0)
    step = np.array([[0, 10, 20], [10, 0, 10], [20, 10, 0]])
    assert _split_chain(step, np.array([[0, 20], [10, 10], [20, 0]])) == 10
    # one robot: the whole chain, in order
    assert _split_chain(step, np.array([[0], [10], [20]])) == 20


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), robots=st.integers(1, 3))
def test_the_root_bound_never_exceeds_the_brute_force_optimum(seed, robots):
    # random 14 x 5 grids with a wall, two place tasks, 1-3 robots at random cells: the bound at the
    # root (tour included) is at most the least cost over every assignment, order, instance and
    # stand cell (an independent brute force with the world's BFS distances)
    rng = random.Random(seed)
    world = _random_world(rng)
    team = rng.sample(world.cells, robots)
    optimum = brute_force(world, [("Apple", "CounterTop"), ("Mug", "DiningTable")], team)
    assert _root_bound(world, gt([PLACE_APPLE, PLACE_MUG]), team) <= optimum


@pytest.mark.parametrize("seed", [1, 4, 7])
def test_exact_mode_keeps_the_grid_optimum(seed):
    # the stronger root bound prunes more, never the optimum
    rng = random.Random(seed)
    world = _random_world(rng)
    team = rng.sample(world.cells, 2)
    optimum = brute_force(world, [("Apple", "CounterTop"), ("Mug", "DiningTable")], team)
    r = plan(world, oracle_spec(gt([PLACE_APPLE, PLACE_MUG]), world).spec, team, mode="exact")
    assert r.proven_optimal and r.total_cost == optimum


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), robots=st.integers(1, 2), order=st.booleans())
def test_the_root_bound_of_ordered_tasks_never_exceeds_the_optimum(seed, robots, order):
    # with one task ordered before the other, exact mode's optimum (the grid optimum: checked
    # against the brute force above and in test_grid_optimum.py) is the reference
    rng = random.Random(seed)
    world = _random_world(rng)
    team = rng.sample(world.cells, robots)
    inst = gt([PLACE_APPLE, PLACE_MUG], before=[("A", "B") if order else ("B", "A")])
    r = plan(world, oracle_spec(inst, world).spec, team, mode="exact")
    assert r.proven_optimal
    assert _root_bound(world, inst, team) <= r.total_cost
