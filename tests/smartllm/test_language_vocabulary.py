"""SMART-LLM's vocabulary in the offline language stage (language/state_tasks.py): lights, switching
appliances, breaking, throwing away, washing / chilling / heating / toasting without a destination,
and goals that only name a room's state, read right or refused (exit 2, naming the words).

The sentences here are our own rephrasings, written for these rules; SMART-LLM's benchmark sentences
are measured by `bench smartllm --llm offline` (results/smartllm_offline), not repeated here."""

from __future__ import annotations

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.pipeline import run
from nl2hltl2plan.suites.smartllm.smartllm_bench import llm_maker, run_task
from nl2hltl2plan.suites.smartllm.smartllm_tasks import parse_task, smartllm_world
from nl2hltl2plan.worlds.checker import final_conditions

pytestmark = pytest.mark.data  # AI2-THOR floor plans from ALFRED's data

EXTRAS = {
    "FloorPlan15": ("LightSwitch", "Toaster"),  # a kitchen
    "FloorPlan303": ("Blinds", "LightSwitch"),  # a bedroom
    "FloorPlan209": ("LightSwitch", "Television"),  # a living room
    "FloorPlan414": ("LightSwitch",),  # a bathroom
}


def world(fp: str):
    return smartllm_world(fp, EXTRAS[fp])


def reading(text: str, fp: str) -> tuple[list[str], list[tuple[str, str]]]:
    res = translate(text, world(fp), "offline", build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks], res.before


@pytest.mark.parametrize(
    ("fp", "text", "tasks", "before"),
    [
        # a room's light, as a state or as a switch
        ("FloorPlan15", "Please make the room dark.", ["set_state LightSwitch off"], []),
        ("FloorPlan15", "Darken the kitchen", ["set_state LightSwitch off"], []),
        ("FloorPlan15", "Could you turn out the lights?", ["set_state LightSwitch off"], []),
        ("FloorPlan15", "Switch the kitchen lights off", ["set_state LightSwitch off"], []),
        ("FloorPlan15", "Turn off all the lights", ["set_state LightSwitch off"], []),
        ("FloorPlan209", "Make the living room bright", ["set_state LightSwitch on"], []),
        ("FloorPlan15", "Light up the kitchen", ["set_state LightSwitch on"], []),
        # a light condition comes first
        (
            "FloorPlan303",
            "Open the book with the lights on",
            ["set_state LightSwitch on", "set_state Book open"],
            [("A", "B")],
        ),
        (
            "FloorPlan303",
            "Close the laptop in the dark",
            ["set_state LightSwitch off", "set_state Laptop closed"],
            [("A", "B")],
        ),
        # switching appliances, "it" the one that can be switched
        (
            "FloorPlan209",
            "Switch the TV on and turn off the lights",
            ["set_state Television on", "set_state LightSwitch off"],
            [],
        ),
        (
            "FloorPlan303",
            "Open the laptop and switch it on",
            ["set_state Laptop open", "set_state Laptop on"],
            [],
        ),
        (
            "FloorPlan15",
            "Put the bread in the toaster and turn it on",
            ["place Bread -> Toaster", "set_state Toaster on"],
            [("A", "B")],
        ),
        (
            "FloorPlan15",
            "Put the mug in the sink and turn on the faucet",
            ["place Mug -> SinkBasin", "set_state Faucet on"],
            [("A", "B")],
        ),
        (
            "FloorPlan15",
            "Turn on the light, and then open the fridge",
            ["set_state LightSwitch on", "set_state Fridge open"],
            [("A", "B")],
        ),
        # breaking, throwing away
        (
            "FloorPlan303",
            "Smash the cell phone and shut the blinds",
            ["set_state CellPhone broken", "set_state Blinds closed"],
            [],
        ),
        ("FloorPlan15", "Get rid of the apple", ["place Apple -> GarbageCan"], []),
        ("FloorPlan15", "Throw the potato away", ["place Potato -> GarbageCan"], []),
        # treatments with no destination: the state is the goal
        ("FloorPlan15", "Rinse the mug", ["clean_place Mug -> ?"], []),
        ("FloorPlan414", "Wash the cloth", ["clean_place Cloth -> ?"], []),
        ("FloorPlan15", "Warm up the mug", ["heat_place Mug -> ?"], []),
        (
            "FloorPlan15",
            "Cool the tomato and switch off the light",
            ["cool_place Tomato -> ?", "set_state LightSwitch off"],
            [],
        ),
        ("FloorPlan15", "Toast a piece of bread", ["set_state Bread(sliced) toasted"], []),
        (
            "FloorPlan15",
            "Put the apple in the fridge, wash the mug and turn off the lights",
            ["place Apple -> Fridge", "clean_place Mug -> ?", "set_state LightSwitch off"],
            [],
        ),
    ],
)
def test_requests_are_read(fp, text, tasks, before):
    assert reading(text, fp) == (tasks, before)


@pytest.mark.parametrize(
    ("fp", "text", "error", "words"),
    [
        ("FloorPlan303", "Make the kitchen dark", WorldError, "FloorPlan303 is a bedroom, not a kitchen"),
        ("FloorPlan15", "Toast the bread", WorldError, "a slice of it can"),
        ("FloorPlan15", "Toast two slices of bread", HTTError, "slices"),
        ("FloorPlan15", "Make the kitchen tidy", HTTError, "'tidy' (action)"),
        ("FloorPlan15", "Make the kitchen warm", HTTError, "'make' (action)"),
        ("FloorPlan303", "Break the pillow", WorldError, "no Pillow in FloorPlan303 can be broken"),
    ],
)
def test_requests_it_cannot_do_are_refused(fp, text, error, words):
    with pytest.raises(error) as exc:
        run(text, world(fp))
    assert words in str(exc.value)


def test_a_room_without_a_light_switch_is_refused_with_exit_2(capsys):
    """ALFRED's floor plans place no light switch: the room's lights cannot be switched there."""
    assert main(["plan", "Make the kitchen dark", "--world", "FloorPlan15"]) == 2
    err = capsys.readouterr().err
    assert "no light switch in FloorPlan15" in err and "Traceback" not in err


def test_several_instances_of_all_the_x_are_refused():
    """'all the X' with several X in the scene: a state task switches one object."""
    w = world("FloorPlan15")
    n = len(w.instances("Cabinet"))
    assert n > 1
    with pytest.raises(HTTError, match=f"holds {n} of them"):
        translate("Close all the cabinets", w, "offline", build=False, actions="none")


@pytest.mark.parametrize(
    ("fp", "text", "conditions"),
    [
        ("FloorPlan15", "Please make the room dark.", [("LightSwitch", "OFF", None)]),
        ("FloorPlan15", "Toast a piece of bread", [("Bread", "COOKED", None)]),
        (
            "FloorPlan15",
            "Put the bread in the toaster and turn it on",
            [("Toaster", None, "Bread"), ("Bread", "HOT", None)],
        ),
        (
            "FloorPlan15",
            "Cool the tomato and switch off the light",
            [("Fridge", None, "Tomato"), ("LightSwitch", "OFF", None)],
        ),
        (
            "FloorPlan303",
            "Open the book with the lights on",
            [("Book", "OPENED", None), ("LightSwitch", "ON", None)],
        ),
    ],
)
def test_plans_reach_the_requested_states(fp, text, conditions):
    out = run(text, world(fp), robots=2)
    assert out.ok and out.result.execution is not None
    assert all(final_conditions(out.result.execution, conditions))


def test_washing_needs_the_faucet_run():
    out = run("Rinse the mug", world("FloorPlan15"))
    acts = [st.verb for r in out.result.plan.robots for st in r.steps if st.verb not in ("move", "wait")]
    assert out.ok and acts[:2] == ["pickup", "put"] and "toggle_on" in acts


def test_a_refused_instruction_is_no_success_even_without_ground_truth():
    """A task whose ground truth lists no condition is still planned from its words: a refusal scores 0
    (SMART-LLM's script would count it complete)."""
    row = {"floor_plan": "FloorPlan414", "task": "Fill the bathtub with water", "robot list": [1],
           "object_states": [], "trans": 0, "max_trans": 0}  # fmt: skip
    scored = run_task(parse_task(1, row), llm_maker("offline"))
    assert scored["status"] == "no spec" and scored["SR"] == 0.0 and scored["TC"] == 0.0
    done = run_task(parse_task(2, {**row, "task": "Throw the cloth away"}), llm_maker("offline"))
    assert done["status"] == "solved" and done["SR"] == 1.0
