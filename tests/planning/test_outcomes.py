"""Clear outcomes: infeasible with a reason, timeout, malformed input as PlanningError."""

from __future__ import annotations

import json

import pytest
from planning_worlds import corridor

from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.errors import PlanningError, SpecError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning import api, heuristic, plan
from nl2hltl2plan.worlds.demo import demo_world


def leaf_spec(*actions: str) -> HierarchicalSpec:
    return HierarchicalSpec([{"task1": "F task1.1"}, {"task1.1": list(actions)}])


def test_missing_object_type(two_tasks_world):
    r = plan(two_tasks_world, leaf_spec("pickup(Statue)", "put(Statue,CounterTop)"), [(0, 0)])
    assert r.status == "infeasible"
    assert "there is no Statue in corridor" in r.reason


def test_object_no_robot_can_reach():
    world = corridor({"CounterTop_0": 2}, island={"Apple_0": 51})
    r = plan(world, leaf_spec("pickup(Apple)", "put(Apple,CounterTop)"), [(0, 0)])
    assert r.status == "infeasible"
    assert "no robot can reach any Apple" in r.reason


def test_receptacle_that_refuses_the_object():
    world = corridor({"Book_0": 5, "Fridge_0": 9})
    r = plan(world, leaf_spec("pickup(Book)", "open(Fridge)", "put(Book,Fridge)"), [(0, 0)])
    assert r.status == "infeasible"
    assert "a Fridge cannot accept a Book" in r.reason


def test_precedence_cycle(two_tasks_world):
    spec = HierarchicalSpec([
        {"task1": "F(task1.1 & F task1.2) & F(task1.2 & F task1.1)"},
        {"task1.1": ["pickup(Apple)", "put(Apple,CounterTop)"],
         "task1.2": ["pickup(Mug)", "put(Mug,DiningTable)"]},
    ])
    r = plan(two_tasks_world, spec, [(0, 0)])
    assert r.status == "infeasible"
    assert "cycle" in r.reason and "task1.1" in r.reason


def test_no_robot_has_the_capability(two_tasks_world):
    spec = leaf_spec("pickup(Apple)", "put(Apple,CounterTop)")
    r = plan(two_tasks_world, spec, [(0, 0), (0, 39)], capabilities=[["put"], ["toggle_on"]])
    assert r.status == "infeasible" and "no robot in the team can pickup(Apple)" in r.reason
    # with one capable robot it is solved, and only that robot acts
    r = plan(two_tasks_world, spec, [(0, 0), (0, 39)], capabilities=[["open"], None])
    assert r.solved and {e.robot for e in r.events} == {1}


def test_events_are_typed_and_keep_their_json():
    world = corridor({"Apple_0": 10, "CounterTop_0": 2})
    r = plan(world, leaf_spec("pickup(Apple)", "put(Apple,CounterTop)"), [(0, 0)])
    assert r.solved and all(isinstance(e, PlanEvent) for e in r.events)
    assert [(e.robot, e.atom, e.task, e.objects) for e in r.events] == [
        (0, "pickup(Apple)", "task1.1", ["Apple_0"]),
        (0, "put(Apple,CounterTop)", "task1.1", ["Apple_0", "CounterTop_0"]),
    ]
    assert sum(e.travel_m for e in r.events) == r.travel_m  # the walk before each action
    # the JSON is the planner's event object, field for field, and reads back as the same events
    shown = json.loads(json.dumps(r.to_dict()))["events"]
    assert [list(e) for e in shown] == [["t", "robot", "atom", "task", "objects", "travel_m"]] * 2
    assert [PlanEvent.model_validate(e) for e in shown] == r.events


def test_support_open_inserted_and_infeasible_found_by_search():
    # the apple sits in a closed fridge and the leaf never opens it: the planner opens it (walk 4 to
    # the fridge's region 4..16, open, pick, put on the counter whose region 0..8 holds cell 4: 7)
    world = corridor({"Apple_0": 10, "Fridge_0": 10, "CounterTop_0": 2}, parents={"Apple_0": "Fridge_0"})
    spec = leaf_spec("pickup(Apple)", "put(Apple,CounterTop)")
    for mode in ("exact", "fast"):
        r = plan(world, spec, [(0, 0)], mode=mode)
        assert r.solved and r.total_cost == 7
        assert [(e.atom, e.task) for e in r.events] == [
            ("open(Fridge)", "task1.1"), ("pickup(Apple)", "task1.1"), ("put(Apple,CounterTop)", "task1.1")]
    # a robot that may not open anything: nothing static is wrong, the exhaustive search proves there
    # is no plan and names the missing ability
    r = plan(world, spec, [(0, 0)], capabilities=[["pickup", "put"]])
    assert r.status == "infeasible"
    assert "no robot in the team can open(Fridge)" in r.reason and "no sequence of robot actions" in r.reason


def test_a_timeout_returns_no_plan_and_says_so():
    world = demo_world()
    spec = HierarchicalSpec([
        {"task1": " & ".join(f"F task1.{k}" for k in range(1, 7))},
        {f"task1.{k}": body for k, body in enumerate([
            ["pickup(Plate)", "open(Dishwasher)", "put(Plate,DishwasherLowerRack)"],
            ["pickup(Mug)", "put(Mug,SinkBasin)", "toggle_on(Faucet)", "toggle_off(Faucet)"],
            ["pickup(Cup)", "open(Dishwasher)", "put(Cup,DishwasherUpperRack)"],
            ["pickup(Apple)", "open(Microwave)", "put(Apple,Microwave)", "close(Microwave)"],
            ["pickup(Book)", "toggle_on(FloorLamp)"],
            ["pickup(Fork)", "put(Fork,Bowl)", "pickup(Bowl)", "put(Bowl,DiningTable)"],
        ], start=1)},
    ])
    # by behaviour, not a wall clock (a loaded machine makes one fail): the status and reason say the
    # search stopped at its time limit
    r = plan(world, spec, [(0, 0), (9, 13), (0, 13)], mode="exact", timeout_s=0.001)
    assert r.status == "timeout" and r.plan is None and "within 0.001 s" in r.reason
    # stopped by its deterministic node budget (not the wall clock, which a loaded machine makes
    # unpredictable), the exact search returns its best plan so far, verified, and says so
    r = plan(world, spec, [(0, 0), (9, 13), (0, 13)], mode="exact", max_nodes=400)
    assert r.status == "solved" and r.stopped == "memory" and not r.proven_optimal
    assert r.execution is not None and r.execution.ok


def test_malformed_input(two_tasks_world):
    with pytest.raises(PlanningError, match="not a free cell"):
        plan(two_tasks_world, leaf_spec("pickup(Apple)", "put(Apple,CounterTop)"), [(3, 3)])
    with pytest.raises(PlanningError, match="not a robot action"):
        plan(two_tasks_world, leaf_spec("grab(Apple)", "put(Apple,CounterTop)"), [(0, 0)])
    with pytest.raises(PlanningError, match="unknown objective"):
        plan(two_tasks_world, leaf_spec("pickup(Apple)"), [(0, 0)], objective="sum")
    with pytest.raises(SpecError):
        plan(two_tasks_world, HierarchicalSpec([{"task1": "G task1.1"}, {"task1.1": ["pickup(Apple)"]}]),
             [(0, 0)])
    with pytest.raises(PlanningError, match="takes a HierarchicalSpec"):
        plan(two_tasks_world, [{"task1": "F task1.1"}, {"task1.1": ["pickup(Apple)"]}], [(0, 0)])


def test_a_plan_failing_validation_is_an_error_not_a_plan(two_tasks_world, monkeypatch):
    import nl2hltl2plan.planning.api as api
    from nl2hltl2plan.planning import Validation, validate

    def broken(world, spec, plan):
        v = validate(world, spec, plan)
        return Validation(False, ["simulated failure"], v.execution)

    monkeypatch.setattr(api, "validate", broken)
    r = plan(two_tasks_world, leaf_spec("pickup(Apple)", "put(Apple,CounterTop)"), [(0, 0)])
    assert r.status == "error" and r.plan is None and "simulated failure" in r.reason


def test_validate_judges_plans_from_elsewhere(two_tasks_world):
    from nl2hltl2plan.planning import validate
    from nl2hltl2plan.worlds.plan import Plan, RobotPlan

    spec = leaf_spec("pickup(Apple)", "put(Apple,CounterTop)")
    good = plan(two_tasks_world, spec, [(0, 0)]).plan
    assert validate(two_tasks_world, spec, good).ok
    idle = Plan(robots=[RobotPlan(robot=0, start=(0, 0), steps=[])])
    verdict = validate(two_tasks_world, spec, idle)
    assert not verdict.ok and verdict.reasons
    late = good.model_copy(deep=True)
    late.robots[0].steps = [s for s in late.robots[0].steps if s.verb != "put"]
    assert not validate(two_tasks_world, spec, late).ok


def _three_kitchen_tasks() -> HierarchicalSpec:
    return HierarchicalSpec([
        {"task1": " & ".join(f"F task1.{k}" for k in range(1, 4))},
        {f"task1.{k}": body for k, body in enumerate([
            ["pickup(Plate)", "open(Dishwasher)", "put(Plate,DishwasherLowerRack)"],
            ["pickup(Mug)", "put(Mug,SinkBasin)", "toggle_on(Faucet)", "toggle_off(Faucet)"],
            ["pickup(Cup)", "open(Dishwasher)", "put(Cup,DishwasherUpperRack)"],
        ], start=1)},
    ])


def test_fast_mode_gives_up_a_search_whose_bound_stopped_rising(monkeypatch: pytest.MonkeyPatch):
    # three kitchen tasks for two robots: the A* finds no better plan after its seeds, and its bound
    # sits still for a while before the search space is exhausted (starts where the root's bound does
    # not prove the plan at once: without the hands' bound, which proves it at the root); the plan is
    # 2 units above the bound, more than STALL_NEAR
    monkeypatch.setattr(heuristic, "hands_walk", lambda *_: 0)
    world, spec = demo_world(), _three_kitchen_tasks()
    starts = [(7, 13), (6, 1)]
    stalled = plan(world, spec, starts, fast_stall_work=1)
    again = plan(world, spec, starts, fast_stall_work=1)
    full = plan(world, spec, starts, fast_stall_work=None)
    assert stalled.stopped == "stalled" and not stalled.proven_optimal and stalled.execution.ok
    assert "stopped rising" in stalled.stop_reason
    assert (again.stopped, again.cost, again.lower_bound, again.events) == (
        stalled.stopped, stalled.cost, stalled.lower_bound, stalled.events)
    # the search it gave up proves the same plan optimal; the bound it had reached is below that
    assert full.stopped == "exhausted" and full.proven_optimal and full.cost == stalled.cost
    assert stalled.lower_bound < full.lower_bound == full.cost
    assert full.cost - stalled.lower_bound > api.STALL_NEAR


def test_fast_mode_keeps_searching_while_its_plan_is_near_the_bound(monkeypatch: pytest.MonkeyPatch):
    # the same search with a plan 2 units above its bound: within STALL_NEAR = 2 the stall stop
    # waits, and the search goes on to prove the plan optimal by exhausting the space
    world, spec = demo_world(), _three_kitchen_tasks()
    monkeypatch.setattr(heuristic, "hands_walk", lambda *_: 0)
    monkeypatch.setattr(api, "STALL_NEAR", 2.0)
    near = plan(world, spec, [(7, 13), (6, 1)], fast_stall_work=1)
    assert near.stopped == "exhausted" and near.proven_optimal and near.cost == near.lower_bound
