"""Handover worlds (geometry, simulator, atoms), the cooperative planner and the eight task specs."""

from __future__ import annotations

import json

import pytest

from nl2hltl2plan.errors import PlanningError, WorldError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.coop import coop_plan, plan_world
from nl2hltl2plan.suites.handover.handover_bench import instance, judge, load_tasks
from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.handover_world import (
    ARMS,
    HandoverWorld,
    compile_atom,
    execute_handover,
    handover_world,
    initial_snap,
    layout,
)
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step

TASKS = {t.id: t for t in load_tasks()}


@pytest.mark.parametrize("config", ["square", "line"])
def test_geometry_arms_share_cells_only_with_neighbours(config):
    lay = layout(config)
    assert set(lay.regions) == set("EFGHIJ")
    for a in range(4):
        assert lay.own(a), f"arm {ARMS[a]} has no own cell"
        for b in range(4):
            shared = lay.reach[a] & lay.reach[b]
            neighbours = abs(a - b) in (1, 3) if config == "square" else abs(a - b) == 1
            assert bool(shared) == (a == b or neighbours), (a, b)
    assert all(len(lay.arms_reaching(c)) == 1 for c in lay.regions.values())  # regions are one arm's


def test_bad_instances_are_refused():
    lay = layout("square")
    with pytest.raises(WorldError, match="cannot reach"):
        HandoverWorld(lay, {"Red": (0, 1)}, ((4, 4), (0, 4), (4, 4), (4, 0)))
    with pytest.raises(WorldError, match="same cell"):
        HandoverWorld(lay, {"Red": (0, 1), "Blue": (0, 1)}, tuple(lay.own(a)[0] for a in range(4)))
    with pytest.raises(WorldError, match="cannot read atom"):
        compile_atom(handover_world(), "fly(Red)")
    with pytest.raises(PlanningError, match="cannot be planned"):
        coop_plan(handover_world(), [{"t": 'F "at(Green,J)"'}])


def _plan(hw, steps_by_arm):
    return Plan(
        robots=[RobotPlan(robot=a, start=hw.arm_starts[a], steps=steps_by_arm.get(a, [])) for a in range(4)]
    )


def test_simulator_enforces_reach_collisions_and_capacity():
    hw = handover_world("square")  # red E (0,1), blue F (0,3), yellow G (1,4); arms at their first own cell
    # arm a walks out of its reach
    bad = execute_handover(
        hw,
        _plan(
            hw,
            {
                0: [
                    Step(t=1, verb="move", cell=(0, 1)),
                    Step(t=2, verb="move", cell=(0, 2)),
                    Step(t=3, verb="move", cell=(0, 3)),
                ]
            },
        ),
    )
    assert not bad.ok and "out of arm a's reach" in bad.violations[0]
    # a and b both step onto the shared cell (0, 2)
    clash = execute_handover(
        hw,
        _plan(
            hw,
            {
                0: [Step(t=1, verb="move", cell=(0, 1)), Step(t=2, verb="move", cell=(0, 2))],
                1: [Step(t=2, verb="move", cell=(0, 2))],
            },
        ),
    )
    assert not clash.ok and "occupied" in clash.violations[0]
    # arm b picks blue on F and may not put it back onto G, which holds yellow
    full = execute_handover(
        hw,
        _plan(
            hw,
            {
                1: [
                    Step(t=1, verb="move", cell=(0, 4)),
                    Step(t=2, verb="move", cell=(0, 3)),
                    Step(t=3, verb="pickup", objects=["Blue"]),
                    Step(t=4, verb="move", cell=(0, 4)),
                    Step(t=5, verb="move", cell=(1, 4)),
                    Step(t=6, verb="put", objects=["Blue", "G"]),
                ]
            },
        ),
    )
    assert full.violations == ["t=6 arm b: put(Blue,G): G already holds a block"]
    assert full.final[1][1] == 1  # still holding blue


def test_atoms_read_the_state():
    hw = handover_world("square")
    snap = initial_snap(hw)
    assert compile_atom(hw, "at(Red,E)")(snap, None)
    assert compile_atom(hw, "at(Blue,@Blue)")(snap, None)
    assert compile_atom(hw, "occupied(F)")(snap, None) and compile_atom(hw, "empty(H)")(snap, None)
    assert not compile_atom(hw, "away(Red)")(snap, None)
    assert compile_atom(hw, "put(RedBlock,RegionJ)")(snap, ("put", 0, (3, 4)))


def test_one_leaf_is_carried_out_by_several_arms():
    hw = handover_world("square")
    result = coop_plan(hw, [{"task1": 'F "at(Red,I)"'}])
    assert result.solved and result.proven_optimal
    assert result.handovers >= 1
    arms_acting = {rp.robot for rp in result.plan.robots if any(s.verb == "pickup" for s in rp.steps)}
    assert len(arms_acting) >= 2
    assert [h.block for h in result.execution.handovers] == ["Red"] * result.handovers


@pytest.mark.slow
@pytest.mark.sweep  # the slow plain search; the A* it checks plans in every other test here
def test_astar_matches_plain_dijkstra_on_a_small_task():
    hw = handover_world("square")
    spec = [{"task1": "F(task1.1 & F task1.2)"}, {"task1.1": 'F "at(Red,H)"', "task1.2": 'F "away(Yellow)"'}]
    fast = coop_plan(hw, spec)
    slow = coop_plan(hw, spec, use_heuristic=False, weights=(1.0,))
    assert fast.solved and slow.solved and slow.proven_optimal
    assert fast.cost == slow.cost


def test_negated_atoms_are_respected():
    hw = handover_world("square")
    spec = HierarchicalSpec.from_json(
        [{"task1": '(!"pick(Blue)" U "pick(Red)") & F "at(Blue,I)" & F "at(Red,H)"'}]
    )
    result = coop_plan(hw, spec)
    assert result.solved
    picks = sorted((s.t, s.objects[0]) for rp in result.plan.robots for s in rp.steps if s.verb == "pickup")
    assert picks[0][1] == "Red"


def test_the_eight_task_specs_are_valid_and_bench_instances_are_seeded():
    assert sorted(TASKS) == list(range(1, 9))
    for task in TASKS.values():
        spec = task.hierarchical()
        hw = instance(task, 0, 0)
        assert hw.layout.name == task.config
        assert instance(task, 0, 0).blocks == hw.blocks and instance(task, 0, 1).arm_starts is not None
        for atom in spec.atoms():
            compile_atom(hw, atom)  # every atom is readable
    assert instance(TASKS[4], 0, 3).start_region("Red") == "G"


# tasks 1 and 4 plan the same way as 5 and 6, for several times as long: `sweep` (docs/reliability.md)
SLOW_TWINS = [pytest.mark.slow, pytest.mark.sweep]


@pytest.mark.parametrize(
    "task_id", [5, 6, pytest.param(1, marks=SLOW_TWINS), pytest.param(4, marks=SLOW_TWINS)]
)
def test_paper_tasks_are_solved_and_checked(task_id):
    task = TASKS[task_id]
    hw = instance(task, 0, 0)
    result = coop_plan(hw, task.hierarchical())
    ok, reasons = judge(hw, task.hierarchical(), result)
    assert ok, reasons
    if task_id == 6:  # "separately to G, H and I": all three there at the end, one per region
        regions = hw.layout.regions
        assert set(result.execution.final[2]) == {regions["G"], regions["H"], regions["I"]}
    if task_id == 5:  # exchanging red and blue needs a temporary place for one of them
        puts = [s.objects for rp in result.plan.robots for s in rp.steps if s.verb == "put"]
        temp = [
            p
            for p in puts
            if p[0] in ("Red", "Blue") and p[1] not in (hw.start_region("Red"), hw.start_region("Blue"))
        ]
        assert temp


def test_plan_on_a_handover_world_uses_the_cooperative_planner():
    world = load_world("handover-line")
    result = plan_world(world, [{"task1": ["pickup(RedBlock)", "put(RedBlock,RegionJ)"]}])
    assert result.status == "solved" and result.travel_m > 0 and result.total_cost > 0
    # red goes from E (arm a) to J (arm d): every arm picks it up once
    pickers = [rp.robot for rp in result.plan.robots for s in rp.steps if s.verb == "pickup"]
    assert sorted(pickers) == [0, 1, 2, 3]
    with pytest.raises(PlanningError, match="not a handover world"):
        plan_world(load_world("tabletop"), [{"task1": 'F "at(Red,J)"'}])


def test_pipeline_planning_stage_plans_handover_worlds_cooperatively():
    from nl2hltl2plan.pipeline import PipelineOptions, planning_stage

    world = load_world("handover-square")
    spec = HierarchicalSpec.from_json([{"task1": ["pickup(RedBlock)", "put(RedBlock,RegionI)"]}])
    planned = planning_stage(world, spec, world.default_starts[:1], PipelineOptions())
    assert planned.result.solved and planned.result.model.startswith("cooperative")
    pickers = {rp.robot for rp in planned.result.plan.robots for s in rp.steps if s.verb == "pickup"}
    assert len(pickers) >= 2  # red goes from E (arm a) to I (arm c): handed over


@pytest.mark.parametrize("world_name", ["handover-square", "handover-line"])
def test_plan_command_works_on_the_handover_worlds(world_name, capsys):
    """`plan` on a handover world: the language stage grounds blocks and regions, the cooperative planner
    returns a checked plan, and --json keeps the base tasks and orderings."""
    from nl2hltl2plan.cli.main import main

    text = "Put the red block in region H, then the blue block in region I"
    assert main(["plan", text, "--world", world_name, "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["status"] == "solved"
    assert [(t["kind"], t["object"], t["receptacle"]) for t in payload["tasks"]] == [
        ("place", ["RedBlock"], ["RegionH"]),
        ("place", ["BlueBlock"], ["RegionI"]),
    ]
    assert payload["before"] == [["A", "B"]]
    puts = [s for rp in payload["plan"]["robots"] for s in rp["steps"] if s["verb"] == "put"]
    red_in_h = min(
        s["t"] for s in puts if s["objects"][0].startswith("Red") and s["objects"][1].endswith("H")
    )
    blue_in_i = min(
        s["t"] for s in puts if s["objects"][0].startswith("Blue") and s["objects"][1].endswith("I")
    )
    assert (
        red_in_h < blue_in_i
    )  # handovers put blocks down in shared cells on the way; the goals keep the order


def _calls_from(plan) -> list[dict]:
    """A correct answer: our own cooperative plan's picks and puts, as API calls in time order."""
    from nl2hltl2plan.worlds.handover_world import ARMS

    steps = sorted(((st.t, rp.robot, st) for rp in plan.robots for st in rp.steps), key=lambda x: x[:2])
    calls, at = [], {}
    for _, arm, st in steps:
        if st.verb == "move":
            at[arm] = st.cell
        elif st.verb in ("pickup", "put"):
            place = st.objects[1] if st.verb == "put" else None
            calls.append(
                {
                    "arm": ARMS[arm],
                    "api": "pick" if st.verb == "pickup" else "place",
                    "block": st.objects[0],
                    "place": place,
                }
            )
    return calls


def test_llm_planner_baseline_for_handover_against_a_stub(stub_llm):
    from nl2hltl2plan.config.llm_settings import LLMSettings
    from nl2hltl2plan.language.llm.client import LLMClient
    from nl2hltl2plan.planning.coop import coop_plan
    from nl2hltl2plan.suites.handover.handover_bench import instance, load_tasks
    from nl2hltl2plan.suites.handover.handover_llm import llm_handover

    task = next(t for t in load_tasks() if t.id == 1)  # red before blue, blocks to the opposite side
    hw, spec = instance(task, 0, 0), task.hierarchical()
    ours = coop_plan(hw, spec)
    calls = _calls_from(ours.plan)
    good = _resolve_picks(hw, ours.plan, calls)

    def client_for(answer: list[dict]) -> LLMClient:
        stub = stub_llm(lambda body: json.dumps({"calls": answer}))
        return LLMClient(LLMSettings(base_url=stub.base_url, model="m", api_key="k", cache_dir=None))

    ok = llm_handover(hw, spec, task.instruction, client_for(good))
    assert ok["success"] and ok["cost"] is not None, ok["reasons"]
    short = llm_handover(hw, spec, task.instruction, client_for(good[:-2]))  # stops before the end
    assert not short["success"] and short["reasons"]
    far = [{"arm": "a", "api": "pick", "block": "Red", "place": "J"}]  # J is out of arm a's reach
    unreachable = llm_handover(hw, spec, task.instruction, client_for(far))
    assert not unreachable["success"] and "arm a cannot reach J" in unreachable["reasons"][0]


def _resolve_picks(hw, plan, calls: list[dict]) -> list[dict]:
    """Fill each pick's place with the cell the picking arm stands on (replayed from the plan)."""
    cells = {rp.robot: tuple(rp.start) for rp in plan.robots}
    steps = sorted(((st.t, rp.robot, st) for rp in plan.robots for st in rp.steps), key=lambda x: x[:2])
    picks = []
    for _, arm, st in steps:
        if st.verb == "move":
            cells[arm] = tuple(st.cell)
        elif st.verb == "pickup":
            picks.append(hw.layout.place_name(cells[arm]))
    it = iter(picks)
    return [dict(c, place=next(it)) if c["api"] == "pick" else c for c in calls]
