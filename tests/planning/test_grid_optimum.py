"""Exact mode is the grid optimum of the summed cost: the stand cell of every action is part of the
search. Hand-worked cases where the nearest cell is not the best, and an independent brute force
(every assignment, order, instance and stand cell, with the world's own BFS distances)."""

from __future__ import annotations

import itertools
import random

import numpy as np
import pytest
from planning_worlds import affordances, gt, two_rows

from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.world import Cell, World, WorldObject

PLACE_APPLE = {"id": "A", "kind": "place", "object": ["Apple"], "receptacle": ["CounterTop"]}
PLACE_MUG = {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["DiningTable"]}


@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_nearest_cell_is_not_the_best(mode):
    # robot at row 0, column 20. Nearest apple cell: (0, 18), 2 steps; but the counter is on row 10,
    # reached only through column 30: 12 + 10 + 23 = 45 more, walk 47. Best: walk on to column 30,
    # up, back to (10, 18) (32 steps), pick, then 11 to (10, 7): walk 43, + 2 actions = 45.
    world = two_rows()
    inst = gt([PLACE_APPLE])
    r = plan(world, oracle_spec(inst, world).spec, [(0, 20)], mode=mode)
    assert r.solved and check(r.execution, inst).success
    assert r.total_cost == 45 and r.travel_m == 43 * 0.25
    steps = r.plan.robots[0].steps
    pick = next(i for i, s in enumerate(steps) if s.verb == "pickup")
    assert steps[pick - 1].cell[0] == 10  # it picks the apple from the far row
    if mode == "exact":
        assert r.proven_optimal and r.lower_bound == 45 and r.optimality == "proven optimal"
        assert r.model.startswith("the grid")


def _random_world(rng: random.Random) -> World:
    """A 14 x 5 grid with a wall across most of it (paths bend), a few objects."""
    wall = {(r, 6) for r in range(0, 4)}
    free = [(c * 0.25, r * 0.25) for r in range(5) for c in range(14) if (r, c) not in wall]
    spots = rng.sample([(c, r) for r in range(5) for c in range(14) if (r, c) not in wall], 5)
    ids = ["Apple_0", "Apple_1", "Mug_0", "CounterTop_0", "DiningTable_0"]
    objs = [WorldObject(id=i, type=i.rsplit("_", 1)[0], position=(c * 0.25 + 0.1, 0.9, r * 0.25 - 1.2),
                        affordances=affordances(i.rsplit("_", 1)[0]))
            for i, (c, r) in zip(ids, spots, strict=True)]
    return World.create("grid", free, objs, kind="demo")


def _distances(world: World) -> tuple[np.ndarray, dict[Cell, int]]:
    """The world's BFS distances between all its cells as a matrix, and each cell's index in it."""
    cells = world.cells
    d = np.array([[world.distances_from(a).get(b, 10**6) for b in cells] for a in cells])
    return d, {c: i for i, c in enumerate(cells)}


def _walk(distances: tuple[np.ndarray, dict[Cell, int]], start: Cell, regions: list[tuple[Cell, ...]]) -> int:
    """Fewest steps from start through one cell of each region in turn: every combination of stand
    cells, enumerated (numpy broadcasting), with the world's BFS distances (`_distances`)."""
    if not regions:
        return 0
    d, idx = distances
    total = d[idx[start], [idx[c] for c in regions[0]]]
    for prev, cur in itertools.pairwise(regions):
        step = d[np.ix_([idx[c] for c in prev], [idx[c] for c in cur])]
        total = total.reshape(total.shape + (1,)) + step.reshape((1,) * (total.ndim - 1) + step.shape)
    return int(total.min())


def brute_force(world: World, tasks: list[tuple[str, str]], starts: list[Cell]) -> int:
    """Least moves + actions for place tasks (pickup O, put O on R), each done by one robot."""
    best = 10**9
    distances = _distances(world)  # once per world, not once per walk
    for owners in itertools.product(range(len(starts)), repeat=len(tasks)):
        for objs in itertools.product(*[world.instances(o) for o, _ in tasks]):
            if len({o.id for o in objs}) < len(objs):
                continue  # each task takes its own object
            for recs in itertools.product(*[world.instances(r) for _, r in tasks]):
                cost = 2 * len(tasks)
                for r, start in enumerate(starts):
                    mine = [k for k in range(len(tasks)) if owners[k] == r]
                    cost += min((_walk(distances, start, [reg for k in order for reg in (
                        objs[k].interaction_cells, recs[k].interaction_cells)])
                        for order in itertools.permutations(mine)), default=0)
                best = min(best, cost)
    return best


# seed 9, two robots: the grid optimum is 12, the best plan walking to nearest cells costs 16
@pytest.mark.parametrize("seed", [2, 3, 8, 9])
def test_exact_equals_brute_force_on_small_grids(seed):
    rng = random.Random(seed)
    world = _random_world(rng)
    starts = rng.sample(world.cells, 2)
    inst = gt([PLACE_APPLE, PLACE_MUG])
    for team in (starts[:1], starts):
        r = plan(world, oracle_spec(inst, world).spec, team, mode="exact")
        assert r.solved and r.proven_optimal and check(r.execution, inst).success
        expected = brute_force(world, [("Apple", "CounterTop"), ("Mug", "DiningTable")], team)
        assert r.total_cost == expected, (seed, team)
        fast = plan(world, oracle_spec(inst, world).spec, team)
        assert expected <= fast.total_cost <= fast.bound * expected + 1e-9
