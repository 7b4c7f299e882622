
import pytest
from pydantic import ValidationError

from nl2hltl2plan.worlds import Plan, RobotPlan, Step, execute
from nl2hltl2plan.worlds.scripted import scripted_plan
from nl2hltl2plan.worlds.simulator import CLEAN, COLD, HOT, ON, OPEN, PRESENT


def run(world, lines, start=(9, 2), robot=0, check=False):
    return execute(world, scripted_plan(world, {robot: (start, lines)}, check=check))


def flags(ex, oid):
    return ex.final.flags[ex.world.index[oid]]


def test_plan_model_validation():
    with pytest.raises(ValidationError):
        Step(t=0, verb="wait")
    with pytest.raises(ValidationError):
        Step(t=1, verb="fly")
    with pytest.raises(ValidationError):
        Step(t=1, verb="put", objects=["Apple_0"])
    with pytest.raises(ValidationError):
        Step(t=1, verb="move")
    with pytest.raises(ValidationError):
        RobotPlan(robot=0, start=(0, 0), steps=[Step(t=2, verb="wait"), Step(t=2, verb="wait")])
    with pytest.raises(ValidationError):
        Plan(robots=[RobotPlan(robot=0, start=(0, 0)), RobotPlan(robot=0, start=(0, 1))])


def test_atom(demo):
    assert Step(t=1, verb="put", objects=["Apple_0", "Fridge_0"]).atom(demo) == "put(Apple,Fridge)"
    assert Step(t=1, verb="move", cell=(0, 1)).atom(demo) is None


def test_moves_travel_and_time(demo):
    plan = Plan(
        robots=[
            RobotPlan(
                robot=0,
                start=(0, 0),
                steps=[Step(t=1, verb="move", cell=(0, 1)), Step(t=3, verb="move", cell=(0, 2))],
            ),
            RobotPlan(
                robot=1, start=(0, 0), steps=[Step(t=1, verb="move", cell=(1, 0)), Step(t=5, verb="wait")]
            ),
        ]
    )
    ex = execute(demo, plan)
    assert ex.ok and ex.travel_m == 0.75 and ex.steps == 3
    assert ex.trajectories[0] == [(0, 0), (0, 1), (0, 1), (0, 2), (0, 2), (0, 2)]
    assert ex.cells_moved == {0: 2, 1: 1}


def test_bad_moves(demo):
    plan = Plan(
        robots=[
            RobotPlan(
                robot=0,
                start=(3, 6),
                steps=[Step(t=1, verb="move", cell=(4, 6)), Step(t=2, verb="move", cell=(3, 8))],
            )
        ]
    )
    ex = execute(demo, plan)
    assert not ex.ok and len(ex.violations) == 2
    assert "not a free cell" in ex.violations[0] and "not a 4-neighbour" in ex.violations[1]
    assert ex.travel_m == 0
    bad_start = execute(demo, Plan(robots=[RobotPlan(robot=0, start=(4, 6))]))
    assert "start cell (4, 6) is not a free cell" in bad_start.violations[0]


def test_pickup_put_and_events(demo):
    ex = run(demo, ["pickup Plate_0 :A", "open Dishwasher_0 :A", "put Plate_0 DishwasherLowerRack_0 :A"])
    assert ex.ok, ex.violations
    assert [e.atom for e in ex.events] == [
        "pickup(Plate)",
        "open(Dishwasher)",
        "put(Plate,DishwasherLowerRack)",
    ]
    assert ex.events[0].task == "A" and ex.events[2].objects == ("Plate_0", "DishwasherLowerRack_0")
    assert ex.describe()["Plate_0"]["in"] == "DishwasherLowerRack_0"
    assert ex.state_at(ex.events[0].t).holder[demo.index["Plate_0"]] == 0


@pytest.mark.parametrize(
    "lines, reason",
    [
        (["pickup Plate_0", "pickup Plate_1"], "already holds Plate_0 (one object in hand)"),
        (["pickup CounterTop_0"], "cannot be picked up"),
        (["put Plate_0 CounterTop_0"], "does not hold Plate_0 (it holds nothing)"),
        (["pickup Plate_0", "put Plate_0 DishwasherLowerRack_0"], "inside Dishwasher_0, which is closed"),
        (["pickup Plate_0", "put Plate_0 Fridge_0"], "Fridge_0 is closed (open it first)"),
        (["pickup Plate_0", "put Plate_0 Mug_0"], "Mug does not accept Plate"),
        (["pickup Apple_1"], "inside Fridge_0, which is closed"),
        (["slice Apple_0"], "must hold a Knife or ButterKnife"),
        (["pickup Knife_0", "slice Plate_0"], "cannot be sliced"),
        (["pickup AppleSliced_0"], "does not exist yet (slice Apple_0 first)"),
        (["toggle_on Plate_0"], "cannot be switched on or off"),
        (["open CounterTop_0"], "cannot be opened or closed"),
        (["open Microwave_0", "toggle_on Microwave_0"], "is open (close it before turning it on)"),
        (["toggle_on Microwave_0", "open Microwave_0"], "is on (turn it off first)"),
        (["pickup Ghost_0"], "no object Ghost_0 in demo"),
    ],
)
def test_precondition_failures(demo, lines, reason):
    ex = run(demo, lines)
    assert not ex.ok
    assert reason in ex.violations[0], ex.violations


def test_out_of_reach(demo):
    plan = Plan(
        robots=[RobotPlan(robot=0, start=(0, 0), steps=[Step(t=1, verb="pickup", objects=["Plate_0"])])]
    )
    ex = execute(demo, plan)
    assert "out of reach of Plate_0; stand e.g. at cell (9, 2)" in ex.violations[0]
    assert ex.violation_list[0].t == 1 and ex.events == []


def test_held_by_other_robot(demo):
    plan = scripted_plan(
        demo, {0: ((9, 2), ["pickup Plate_0"]), 1: ((9, 2), ["pickup Plate_0"])}, check=False
    )
    ex = execute(demo, plan)
    assert ex.violations == ["t=1 robot 1: pickup(Plate_0): Plate_0 is held by robot 0"]


def test_clean_heat_cool_slice(demo):
    ex = run(
        demo,
        [
            "pickup Plate_0",
            "put Plate_0 SinkBasin_0",
            "toggle_on Faucet_0",
            "toggle_off Faucet_0",
            "pickup Mug_0",
            "open Microwave_0",
            "put Mug_0 Microwave_0",
            "close Microwave_0",
            "toggle_on Microwave_0",
            "toggle_off Microwave_0",
            "pickup Knife_0",
            "slice Apple_0",
            "put Knife_0 CounterTop_1",
            "pickup AppleSliced_1",
            "open Fridge_0",
            "put AppleSliced_1 Fridge_0",
        ],
    )
    assert ex.ok, ex.violations
    assert flags(ex, "Plate_0") & CLEAN and flags(ex, "Mug_0") & HOT
    assert not flags(ex, "Apple_0") & PRESENT
    assert flags(ex, "AppleSliced_0") & PRESENT and flags(ex, "AppleSliced_1") & COLD
    assert flags(ex, "Microwave_0") & OPEN == 0 and flags(ex, "Faucet_0") & ON == 0
    t_hot = ex.first_time("Mug_0", "hot")
    assert t_hot == ex.first_time("Microwave_0", "on") and t_hot > ex.first_time(
        "Mug_0", inside="Microwave_0"
    )
    assert ex.first_time("AppleSliced_1", "cold", inside="Fridge_0") == ex.events[-1].t
    assert ex.first_time("Plate_0", "held") == ex.events[0].t and ex.first_time("Cup_0", "held") is None
    assert ex.first_time("Plate_0", inside="CounterTop_0") == 0


def test_running_faucet_cleans_on_put_and_contents_travel(demo):
    ex = run(
        demo,
        [
            "toggle_on Faucet_0",
            "pickup Fork_0",
            "put Fork_0 Bowl_0",
            "pickup Bowl_0",
            "put Bowl_0 SinkBasin_0",
        ],
        start=(3, 6),
    )
    assert ex.ok, ex.violations
    assert flags(ex, "Fork_0") & CLEAN and flags(ex, "Bowl_0") & CLEAN


def test_idempotent_open_and_toggle(demo):
    ex = run(
        demo,
        [
            "open Fridge_0",
            "open Fridge_0",
            "close Fridge_0",
            "close Fridge_0",
            "toggle_on FloorLamp_0",
            "toggle_on FloorLamp_0",
        ],
    )
    assert ex.ok and len(ex.events) == 6


def test_robot_order_within_a_step(demo):
    # robot 0 opens the fridge at t=1; robot 1 picks the apple inside at t=1 too: sees it open
    plan = Plan(
        robots=[
            RobotPlan(robot=0, start=(7, 0), steps=[Step(t=1, verb="open", objects=["Fridge_0"])]),
            RobotPlan(robot=1, start=(7, 0), steps=[Step(t=1, verb="pickup", objects=["Apple_1"])]),
        ]
    )
    assert execute(demo, plan).ok
    swapped = Plan(
        robots=[
            RobotPlan(robot=0, start=p.start, steps=p.steps)
            if p.robot == 1
            else RobotPlan(robot=1, start=p.start, steps=p.steps)
            for p in plan.robots
        ]
    )
    assert not execute(demo, swapped).ok
