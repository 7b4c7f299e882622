import pytest

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.logic.action_sequences import sequences_formula
from nl2hltl2plan.worlds import BaseTask, GTInstance, check, execute
from nl2hltl2plan.worlds.scripted import scripted_plan

DISHWASHER_GT = {
    "id": "demo.dishwasher",
    "scene": "demo",
    "tasks": [
        {"id": "A", "kind": "place", "object": ["Plate"], "receptacle": ["DishwasherLowerRack"]},
        {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["DishwasherLowerRack"]},
        {"id": "C", "kind": "place", "object": ["Saucer"], "receptacle": ["DishwasherUpperRack"]},
        {"id": "D", "kind": "place", "object": ["Cup"], "receptacle": ["DishwasherUpperRack"]},
    ],
    "before": [["A", "C"], ["B", "C"], ["C", "D"]],
}


def task(**kw):
    return BaseTask(id="A", **kw)


def test_recipes_single_choice(demo):
    # leaves carry no opens (the planner inserts them); support=True writes them in
    plate = task(kind="place", object=["Plate"], receptacle=["DishwasherLowerRack"])
    assert plate.leaf_specs(demo) == [["pickup(Plate)", "put(Plate,DishwasherLowerRack)"]]
    assert plate.leaf_specs(demo, support=True) == [
        ["pickup(Plate)", "open(Dishwasher)", "put(Plate,DishwasherLowerRack)"]
    ]
    assert task(kind="place", object=["Apple"], receptacle=["DiningTable"]).leaf_specs(demo) == [
        ["pickup(Apple)", "put(Apple,DiningTable)"]
    ]
    two = task(kind="place_two", object=["Mug"], receptacle=["Cabinet"], count=2).leaf_specs(demo)
    assert two == [["pickup(Mug)", "put(Mug,Cabinet)"]] * 2
    assert task(
        kind="place_in_container", object=["Fork"], container=["Mug"], receptacle=["DiningTable"]
    ).leaf_specs(demo) == [["pickup(Fork)", "put(Fork,Mug)", "pickup(Mug)", "put(Mug,DiningTable)"]]
    assert task(kind="examine_in_light", object=["Book"], light=["FloorLamp"]).leaf_specs(demo) == [
        ["pickup(Book)", "toggle_on(FloorLamp)"]
    ]
    clean = task(kind="clean_place", object=["Plate"], receptacle=["CounterTop"]).leaf_specs(demo)[0]
    assert clean[1:4] == ["put(Plate,SinkBasin)", "toggle_on(Faucet)", "toggle_off(Faucet)"]
    heat = task(kind="heat_place", object=["Mug"], receptacle=["DiningTable"]).leaf_specs(demo)[0]
    assert heat == [
        "pickup(Mug)",
        "put(Mug,Microwave)",
        "toggle_on(Microwave)",
        "toggle_off(Microwave)",
        "pickup(Mug)",
        "put(Mug,DiningTable)",
    ]
    # the scripted runner's recipe (support=True) writes the microwave's opens and its close
    heat_task = task(kind="heat_place", object=["Mug"], receptacle=["DiningTable"])
    assert heat_task.leaf_specs(demo, support=True)[0][1:6] == [
        "open(Microwave)", "put(Mug,Microwave)", "close(Microwave)", "toggle_on(Microwave)",
        "toggle_off(Microwave)"]
    # closed-fridge apples are the only Tomatoes: open it first; cool into the fridge stops there
    cool = task(kind="cool_place", object=["Tomato"], receptacle=["Fridge"])
    assert cool.leaf_specs(demo) == [["pickup(Tomato)", "put(Tomato,Fridge)"]]
    assert cool.leaf_specs(demo, support=True) == [
        ["open(Fridge)", "pickup(Tomato)", "open(Fridge)", "put(Tomato,Fridge)"]
    ]


def test_recipe_sliced(demo):
    spec = task(
        kind="place_two", object=["Bread"], receptacle=["DiningTable"], count=2, sliced=True
    ).leaf_specs(demo)
    assert spec[0] == [
        "pickup(Knife)",
        "slice(Bread)",
        "put(Knife,CounterTop)",
        "pickup(BreadSliced)",
        "put(BreadSliced,DiningTable)",
    ]
    assert spec[1] == ["pickup(BreadSliced)", "put(BreadSliced,DiningTable)"]


def test_recipe_alternatives_are_a_formula(demo):
    spec = task(kind="place", object=["Cup", "Mug", "Teapot"], receptacle=["Saucer", "Sofa"]).leaf_specs(demo)
    assert spec == ['F("pickup(Cup)" & F "put(Cup,Saucer)") | F("pickup(Mug)" & F "put(Mug,Saucer)")']
    assert sequences_formula([["a", "b"], ["a", "c"]]) == 'F("a" & (F "b" | F "c"))'
    assert sequences_formula([["a", "b"]]) == 'F("a" & F "b")'


def test_missing(demo):
    assert task(kind="place", object=["Statue"], receptacle=["DiningTable"]).missing(demo) == [
        "A: no Statue in demo"
    ]
    assert task(kind="place", object=["Plate"], receptacle=["Sofa", "Bed"]).missing(demo) == [
        "A: no Sofa or Bed in demo"
    ]
    assert task(kind="place", object=["Book"], receptacle=["Fridge"]).missing(demo) == [
        "A: Fridge does not accept Book"
    ]
    assert task(kind="heat_place", object=["Saucer"], receptacle=["DiningTable"]).missing(demo) == [
        "A: Saucer cannot be heated in the Microwave"
    ]
    with pytest.raises(WorldError, match="no Statue"):
        task(kind="place", object=["Statue"], receptacle=["DiningTable"]).leaf_specs(demo)
    # a fixture is no thing to pick up: the world says so first, whatever else the task lacks
    scrub = task(kind="clean_place", object=["SinkBasin"], receptacle=["Sofa"])
    assert scrub.missing(demo) == [
        "A: a sink basin cannot be picked up, so no task can wash it; things there to wash: apple, bowl, "
        "butter knife, cup"
    ]
    assert task(kind="set_state", object=["Fridge"], state="open").unmovable(demo) is None


def test_goal_description():
    g = BaseTask(id="B", kind="cool_place", object=["Apple"], receptacle=["CounterTop"], sliced=True).goal()
    assert g.objects == {"AppleSliced"} and g.describe() == "cold AppleSliced in/on CounterTop"


DISHWASHER_SCRIPT = [
    "open Dishwasher_0",
    "pickup Plate_0 :A",
    "put Plate_0 DishwasherLowerRack_0 :A",
    "pickup Mug_0 :B",
    "put Mug_0 DishwasherLowerRack_0 :B",
    "pickup Saucer_0 :C",
    "put Saucer_0 DishwasherUpperRack_0 :C",
    "pickup Cup_0 :D",
    "put Cup_0 DishwasherUpperRack_0 :D",
]


def test_checker_success_single_robot(demo):
    ex = execute(demo, scripted_plan(demo, {0: ((0, 0), DISHWASHER_SCRIPT)}))
    res = check(ex, DISHWASHER_GT)
    assert res.success, res.reasons
    assert res.goal_steps["A"] < res.goal_steps["C"] < res.goal_steps["D"]
    assert res.instances["C"] == ["Saucer_0"]


def test_checker_order_broken(demo):
    swapped = DISHWASHER_SCRIPT[:3] + DISHWASHER_SCRIPT[5:7] + DISHWASHER_SCRIPT[3:5] + DISHWASHER_SCRIPT[7:]
    ex = execute(demo, scripted_plan(demo, {0: ((0, 0), swapped)}))
    res = check(ex, DISHWASHER_GT)
    assert not res.success
    assert any(r.startswith("order broken: task B must be reached before task C") for r in res.reasons), (
        res.reasons
    )


def test_checker_two_robots_and_missing_task(demo):
    plan = scripted_plan(
        demo,
        {
            0: ((9, 2), ["open Dishwasher_0", "pickup Plate_0", "put Plate_0 DishwasherLowerRack_0"]),
            1: ((3, 6), ["pickup Mug_0", "put Mug_0 DishwasherLowerRack_0"]),
        },
    )
    res = check(execute(demo, plan), DISHWASHER_GT)
    assert not res.success
    assert "task C (Saucer in/on DishwasherUpperRack) is never reached" in res.reasons


def test_checker_initial_state_does_not_count(demo):
    gt = {
        "id": "x",
        "scene": "demo",
        "tasks": [{"id": "A", "kind": "place", "object": ["Plate"], "receptacle": ["CounterTop"]}],
    }
    res = check(execute(demo, scripted_plan(demo, {0: ((0, 0), ["wait 2"])})), gt)
    assert not res.success
    ex = execute(demo, scripted_plan(demo, {0: ((0, 0), ["pickup Plate_0", "put Plate_0 CounterTop_0"])}))
    assert check(ex, gt).success


def test_checker_distinct_objects_and_place_two(demo):
    gt = {
        "id": "x",
        "scene": "demo",
        "tasks": [
            {"id": "A", "kind": "place_two", "object": ["Mug"], "count": 2, "receptacle": ["CounterTop"]},
            {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["CounterTop"]},
        ],
    }
    lines = ["pickup Mug_0", "put Mug_0 CounterTop_0", "pickup Mug_1", "put Mug_1 CounterTop_0"]
    res = check(execute(demo, scripted_plan(demo, {0: ((3, 6), lines)})), gt)
    assert not res.success and "task B is only reached with objects another task already used" in res.reasons


def test_checker_kinds(demo):
    gt = GTInstance(
        id="kinds",
        scene="demo",
        tasks=[
            BaseTask(id="A", kind="clean_place", object=["Plate"], receptacle=["DiningTable"]),
            BaseTask(id="B", kind="heat_place", object=["Apple"], receptacle=["CounterTop"], sliced=True),
            BaseTask(id="C", kind="examine_in_light", object=["Book"], light=["FloorLamp"]),
            BaseTask(
                id="D",
                kind="place_in_container",
                object=["Fork"],
                container=["Mug"],
                receptacle=["DiningTable"],
            ),
        ],
        before=[("A", "B")],
    )
    r0 = [
        "pickup Plate_0 :A",
        "put Plate_0 SinkBasin_0 :A",
        "toggle_on Faucet_0 :A",
        "toggle_off Faucet_0 :A",
        "pickup Plate_0 :A",
        "put Plate_0 DiningTable_0 :A",
        "pickup Fork_0 :D",
        "put Fork_0 Mug_1 :D",
        "pickup Mug_1 :D",
        "put Mug_1 DiningTable_0 :D",
    ]
    r1 = [
        "pickup Knife_0 :B",
        "slice Apple_0 :B",
        "put Knife_0 CounterTop_1 :B",
        "pickup AppleSliced_0 :B",
        "open Microwave_0 :B",
        "put AppleSliced_0 Microwave_0 :B",
        "close Microwave_0 :B",
        "until 30",
        "toggle_on Microwave_0 :B",
        "toggle_off Microwave_0 :B",
        "open Microwave_0 :B",
        "pickup AppleSliced_0 :B",
        "put AppleSliced_0 CounterTop_1 :B",
        "pickup Book_0 :C",
        "toggle_on FloorLamp_0 :C",
    ]
    ex = execute(demo, scripted_plan(demo, {0: ((9, 7), r0), 1: ((9, 11), r1)}))
    assert ex.ok, ex.violations
    res = check(ex, gt)
    assert res.success, res.reasons
    assert res.goal_steps["A"] < res.goal_steps["B"] and res.instances["B"] == ["AppleSliced_0"]


def test_checker_strict_violations(demo):
    gt = {
        "id": "x",
        "scene": "demo",
        "tasks": [{"id": "A", "kind": "place", "object": ["Plate"], "receptacle": ["DiningTable"]}],
    }
    lines = ["pickup Plate_0", "pickup Cup_0", "put Plate_0 DiningTable_0"]
    ex = execute(demo, scripted_plan(demo, {0: ((9, 2), lines)}, check=False))
    assert not check(ex, gt).success and check(ex, gt, strict=False).success
