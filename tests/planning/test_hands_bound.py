"""The root's bound with the hands (`planning/hands.py`): cell-level paths out of the robots in
which a robot holds one object at a time. Worked out by hand on a line and in the corridor, and
strictly tighter than the bounds without it where a robot must walk back between two carries; never
above exact mode's optimum on kitchen tasks with a knife, a bowl and the microwave (the random
place tasks against the brute force are in `test_tour_bound.py`)."""

from __future__ import annotations

import random

import numpy as np
import pytest
from planning_worlds import corridor, gt
from test_grid_optimum import PLACE_APPLE, PLACE_MUG
from test_tour_bound import _line, _root_bound

from nl2hltl2plan.planning import heuristic, oracle_spec, plan
from nl2hltl2plan.planning.stops import FREE, GIVE, TAKE, Stop, hand_forest
from nl2hltl2plan.worlds.demo import demo_world


def _two_carries(rule_take: int = TAKE, rule_give: int = GIVE) -> list[Stop]:
    """Two carries on a line: pick at 0..2, put at 30..32; pick at 3..5, put at 33..35."""
    spans = [(0, rule_take, 0), (30, rule_give, 0), (3, rule_take, 1), (33, rule_give, 1)]
    return [Stop(np.arange(at, at + 3), rule, carry if rule != FREE else -1, k)
            for k, (at, rule, carry) in enumerate(spans)]


def test_one_hand_walks_back_between_carries():
    dm = _line(40)
    stops = _two_carries()
    cells = np.concatenate([stop.cells for stop in stops])
    no_order = [0, 0, 0, 0]
    # one robot at 0: pick at 0, put at 30, back to 5, put at 33: 30 + 25 + 28
    assert hand_forest(dm, stops, dm[[0]][:, cells], no_order) == 83
    # without the hands it picks both, then puts both: 33
    free = _two_carries(FREE, FREE)
    assert hand_forest(dm, free, dm[[0]][:, cells], no_order) == 33
    # the second carry ordered before the first: pick at 3, put at 33, back to 2, put at 30
    assert hand_forest(dm, stops, dm[[0]][:, cells], [0, 0, 0b0011, 0b0011]) == 92
    # two robots at 0: one carry each, 30 + 33
    assert hand_forest(dm, stops, dm[[0, 0]][:, cells], no_order) == 63


def test_the_hands_bound_is_tighter_where_the_tour_picks_both_objects_first(monkeypatch):
    # one robot at column 26 (in the counter's region, 24..36); the apple at 12 (region 6..18) goes
    # on the counter, the mug at 4 (0..10) on the table at 16 (10..22). Apple first: to 18, pick, to
    # 24, put, to 10, pick the mug and put it there: walk 8 + 6 + 14 = 28, + 4 actions = 32, the
    # optimum (mug first walks 30). Without the hands the tour picks both objects on one walk
    # to the left (the robot stands in the counter's region already): the bounds give less.
    world = corridor({"Apple_0": 12, "CounterTop_0": 30, "Mug_0": 4, "DiningTable_0": 16})
    inst = gt([PLACE_APPLE, PLACE_MUG])
    r = plan(world, oracle_spec(inst, world).spec, [(0, 26)], mode="exact")
    assert r.proven_optimal and r.total_cost == 32
    assert _root_bound(world, inst, [(0, 26)]) == 32
    monkeypatch.setattr(heuristic, "hands_walk", lambda *args: 0)
    assert _root_bound(world, inst, [(0, 26)]) == 26


# tasks of the demo kitchen whose carries differ: a knife kept in hand while slicing and put back,
# a fork carried in a bowl, a mug heated (the microwave closed, then opened again), a tomato cooled
KITCHEN = {
    "slice": {"kind": "place", "object": ["Apple"], "receptacle": ["Plate"], "sliced": True},
    "slice2": {"kind": "place", "object": ["Bread"], "receptacle": ["Plate"], "sliced": True},
    "heat": {"kind": "heat_place", "object": ["Mug"], "receptacle": ["CounterTop"]},
    "bowl": {"kind": "place_in_container", "object": ["Fork"], "container": ["Bowl"],
             "receptacle": ["DiningTable"]},
    "cool": {"kind": "cool_place", "object": ["Tomato"], "receptacle": ["DiningTable"]},
}


@pytest.mark.parametrize("names, robots, seed, lifts", [
    (("slice", "cool"), 2, 2, True), (("heat", "cool"), 2, 2, True), (("bowl", "cool"), 2, 2, True),
    (("slice", "slice2"), 1, 3, False), (("heat", "bowl"), 2, 4, False),
])
def test_the_root_bound_with_the_hands_never_exceeds_the_optimum_of_kitchen_tasks(
        monkeypatch, names, robots, seed, lifts):
    # exact mode's optimum is the reference; the root bound (the hands' walk included) is at most
    # it, and where `lifts`, the hands' walk raises it above the bounds without it
    world = demo_world()
    inst = gt([dict(KITCHEN[name], id=tag) for name, tag in zip(names, "AB", strict=True)])
    team = random.Random(seed).sample(world.cells, robots)
    r = plan(world, oracle_spec(inst, world).spec, team, mode="exact")
    assert r.proven_optimal
    root = _root_bound(world, inst, team)
    assert root <= r.total_cost
    monkeypatch.setattr(heuristic, "hands_walk", lambda *args: 0)
    assert (_root_bound(world, inst, team) < root) == lifts
