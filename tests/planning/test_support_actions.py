"""Support actions: the planner opens what is in the way, once while it stays open; leaves and
oracle specs carry no opens."""

from __future__ import annotations

from planning_worlds import corridor, gt

from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.demo import demo_world


def test_one_open_serves_two_tasks():
    # fridge (closed) at 20, apple at 10, mug at 30; robot at 20 stands in all three regions
    # (4..16 is the apple's: it walks 4). open once: 4 + pick + open + put + pick + put = 9
    world = corridor({"Apple_0": 10, "Mug_0": 26, "Fridge_0": 20})
    spec = HierarchicalSpec([{"task1": "F task1.1 & F task1.2"},
                             {"task1.1": ["pickup(Apple)", "put(Apple,Fridge)"],
                              "task1.2": ["pickup(Mug)", "put(Mug,Fridge)"]}])
    for mode in ("exact", "fast"):
        r = plan(world, spec, [(0, 20)], mode=mode)
        atoms = [e.atom for e in r.events]
        assert r.solved and atoms.count("open(Fridge)") == 1, atoms
        assert atoms.index("open(Fridge)") < atoms.index("put(Apple,Fridge)")
        assert r.total_cost == 9


def test_heat_reopens_the_microwave_it_closed_and_no_leaf_opens_or_closes():
    world = demo_world()
    inst = gt([{"id": "A", "kind": "heat_place", "object": ["Apple"], "receptacle": ["DiningTable"]},
               {"id": "B", "kind": "cool_place", "object": ["Tomato"], "receptacle": ["CounterTop"]}])
    oracle = oracle_spec(inst, world)
    for name in oracle.spec.leaves:
        assert not any(a.startswith(("open(", "close(")) for a in oracle.spec.leaf_actions(name)), name
    r = plan(world, oracle.spec, [(0, 0), (9, 13)])
    assert r.solved and check(r.execution, inst).success
    atoms = [e.atom for e in r.events]
    # open, put, close (support: it runs only closed), on, off, open again (support), pick
    heat = [a for a in atoms if "Microwave" in a]
    assert heat == ["open(Microwave)", "put(Apple,Microwave)", "close(Microwave)", "toggle_on(Microwave)",
                    "toggle_off(Microwave)", "open(Microwave)"]
    assert atoms.count("open(Fridge)") == 1  # the tomato is taken from the closed fridge and put back


def test_switching_on_an_open_appliance_closes_it_first():
    # the leaf neither opens nor closes: open to put the apple in, close to switch it on
    world = demo_world()
    spec = HierarchicalSpec([{"task1": "F task1.1"},
                             {"task1.1": ["pickup(Apple)", "put(Apple,Microwave)", "toggle_on(Microwave)"]}])
    r = plan(world, spec, [(0, 0)])
    assert r.solved
    assert [e.atom for e in r.events] == ["pickup(Apple)", "open(Microwave)", "put(Apple,Microwave)",
                                             "close(Microwave)", "toggle_on(Microwave)"]


def test_two_heat_tasks_close_the_microwave_only_to_switch_it_on():
    # the heat recipe carries no close: every close(Microwave) is the support action right before a
    # toggle_on(Microwave), so two heat tasks never close it more often than they switch it on
    world = demo_world()
    inst = gt([{"id": "A", "kind": "heat_place", "object": ["Apple"], "receptacle": ["DiningTable"]},
               {"id": "B", "kind": "heat_place", "object": ["Mug"], "receptacle": ["CounterTop"]}])
    spec = oracle_spec(inst, world).spec
    for starts in ([(0, 0)], [(0, 0), (9, 13)]):
        r = plan(world, spec, starts)
        assert r.solved and check(r.execution, inst).success
        micro = [e.atom for e in r.events if "Microwave)" in e.atom and "put(" not in e.atom
                 and "pickup(" not in e.atom]
        closes = [i for i, a in enumerate(micro) if a == "close(Microwave)"]
        assert closes and all(micro[i + 1] == "toggle_on(Microwave)" for i in closes), micro
        assert len(closes) <= micro.count("toggle_on(Microwave)")
