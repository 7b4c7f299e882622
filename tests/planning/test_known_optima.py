"""Instances with an optimum worked out by hand (corridor world, see conftest.py)."""

from __future__ import annotations

import pytest
from planning_worlds import corridor, gt

from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.checker import check

PLACE_APPLE = {"id": "A", "kind": "place", "object": ["Apple"], "receptacle": ["CounterTop"]}
PLACE_MUG = {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["DiningTable"]}


def solve(world, instance, starts, **kw):
    spec = oracle_spec(instance, world).spec
    result = plan(world, spec, starts, **kw)
    assert result.status == "solved", result.reason
    verdict = check(result.execution, instance)
    assert verdict.success, verdict.reasons
    return result


@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_one_robot_two_ordered_tasks(mode):
    # apple 10 -> table 30, then mug 30 -> counter 2; robot at 0.
    # walk 4 to the apple's region (4..16), 20 to the table's (24..36), mug is there (0),
    # 16 back to the counter's (0..8): 40 moves + 4 actions = 44, no waiting.
    world = corridor({"Apple_0": 10, "DiningTable_0": 30, "Mug_0": 30, "CounterTop_0": 2})
    inst = gt([
        {"id": "A", "kind": "place", "object": ["Apple"], "receptacle": ["DiningTable"]},
        {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["CounterTop"]},
    ], before=[("A", "B")])
    for objective in ("min", "minmax"):
        r = solve(world, inst, [(0, 0)], mode=mode, objective=objective)
        assert r.total_cost == 44
        assert r.steps == 44
        assert r.travel_m == 40 * 0.25
        atoms = [e.atom for e in r.events]
        assert atoms == ["pickup(Apple)", "put(Apple,DiningTable)", "pickup(Mug)", "put(Mug,CounterTop)"]


@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_two_robots_split_two_tasks(mode, two_tasks_world):
    # robot 0 at 0: 4 moves to the apple, pick, put (counter region 0..8 contains 4): 6.
    # robot 1 at 39: 3 moves to the mug (24..36), pick, put (table region 31..39): 5. Total 11.
    inst = gt([PLACE_APPLE, PLACE_MUG])
    r = solve(two_tasks_world, inst, [(0, 0), (0, 39)], mode=mode)
    assert r.total_cost == 11
    by_robot = {e.task: e.robot for e in r.events}
    assert by_robot == {"task1.1": 0, "task1.2": 1}
    r = solve(two_tasks_world, inst, [(0, 0), (0, 39)], mode=mode, objective="minmax")
    assert r.steps == 6  # robot 0 picks at t=5, puts at t=6; robot 1 done at t=5
    assert r.total_cost == 11


@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_task_waits_for_another_robots_task(mode, two_tasks_world):
    # as above, but the mug may only be placed after the apple: robot 0 finishes A at t=6, so robot 1
    # (at the mug's region after 3 moves) waits, picks the mug at t=7 and puts it at t=8.
    inst = gt([PLACE_APPLE, PLACE_MUG], before=[("A", "B")])
    for objective in ("min", "minmax"):
        r = solve(two_tasks_world, inst, [(0, 0), (0, 39)], mode=mode, objective=objective)
        assert r.total_cost == 11
        assert r.steps == 8
        robot1 = next(rp for rp in r.plan.robots if rp.robot == 1)
        actions = [(s.t, s.verb) for s in robot1.steps if s.verb != "move"]
        assert actions == [(7, "pickup"), (8, "put")]
        assert max(s.t for s in robot1.steps if s.verb == "move") == 3  # walked first, then waited


def test_leaf_passes_to_another_robot():
    # one leaf: pick the apple (10), put it on the counter (2), switch the lamp on (38).
    # robot 0 (at 0) does the first two, robot 1 (at 39, in the lamp's region) the third:
    # 4 + 1 + 0 + 1 + 0 + 1 = 7, whereas one robot alone would walk to the lamp.
    world = corridor({"Apple_0": 10, "CounterTop_0": 2, "DeskLamp_0": 38})
    leaf = ["pickup(Apple)", "put(Apple,CounterTop)", "toggle_on(DeskLamp)"]
    spec = HierarchicalSpec([{"task1": "F task1.1"}, {"task1.1": leaf}])
    for mode in ("exact", "fast"):
        r = plan(world, spec, [(0, 0), (0, 39)], mode=mode)
        assert r.solved and r.total_cost == 7
        assert [e.robot for e in r.events] == [0, 0, 1]
        assert {e.task for e in r.events} == {"task1.1"}


def test_clean_task_binds_the_faucet_of_its_basin():
    # two basins; only Faucet_0 serves SinkBasin_0 (conftest), so the leaf must use that pair
    world = corridor({"Apple_0": 10, "SinkBasin_0": 14, "Faucet_0": 14, "CounterTop_0": 2})
    inst = gt([{"id": "A", "kind": "clean_place", "object": ["Apple"], "receptacle": ["CounterTop"]}])
    r = solve(world, inst, [(0, 0)], mode="exact")
    atoms = [e.atom for e in r.events]
    assert atoms == ["pickup(Apple)", "put(Apple,SinkBasin)", "toggle_on(Faucet)", "toggle_off(Faucet)",
                     "pickup(Apple)", "put(Apple,CounterTop)"]
