"""h274 (issues 28, 23): a choice between places is one task that may go to either place, through `plan`
(results/language/h274.md, docs/language.md "A choice between places").

"put the egg in the fridge or the microwave" was refused by name; it is now one base task whose receptacle
takes both places, its leaf the recipe's disjunction, and the plan does the cheaper branch (its cost is
the cheaper single-place plan's), saying which place it took. A choice of treatment or of objects stays
refused; a place the world cannot take is dropped and said; none possible is exit 1 naming them.
"""

from __future__ import annotations

import json

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.alfred.conversion import scenario_world


def plan_json(text: str, world: str, capsys) -> tuple[int, dict, str]:
    code = main(["plan", text, "--world", world, "--llm", "offline", "--json", "--mode", "exact"])
    out = capsys.readouterr()
    return code, (json.loads(out.out) if code == 0 else {}), out.err


def cost(text: str, world: str, capsys) -> int:
    code, got, err = plan_json(text, world, capsys)
    assert code == 0, err
    return got["planner"]["total_cost"]


@pytest.mark.data
def test_either_place_plans_the_cheaper_one_and_says_which(capsys):
    code, got, err = plan_json("put the egg in the fridge or the microwave", "FloorPlan1", capsys)
    assert code == 0 and not got["unparsed"], err
    (task,) = got["tasks"]
    assert task["receptacle"] == ["Fridge", "Microwave"] and task["places"] == [["Fridge"], ["Microwave"]]
    # the leaf is the disjunction of the two places, the pickup shared (the formula stays small)
    assert got["spec"] == [{"task1": 'F("pickup(Egg)" & (F "put(Egg,Fridge)" | F "put(Egg,Microwave)"))'}]
    (choice,) = got["place_choices"]
    assert choice == {"task": "A", "allowed": ["Fridge", "Microwave"], "possible": ["Fridge", "Microwave"],
                      "chosen": "Microwave"}  # fmt: skip
    singles = [cost(f"put the egg in the {p}", "FloorPlan1", capsys) for p in ("fridge", "microwave")]
    assert got["planner"]["total_cost"] == min(singles) < max(singles)


@pytest.mark.data
def test_the_text_output_names_the_place_taken(capsys):
    code = main(["plan", "leave the mug in the sink or on the counter, whichever", "--world", "FloorPlan1",
                 "--llm", "offline"])  # fmt: skip
    out = capsys.readouterr().out
    assert code == 0
    assert "task A: SinkBasin or CounterTop allowed (the instruction left it open); the plan uses the" in out


@pytest.mark.data
@pytest.mark.parametrize(
    "text, named",
    [
        ("heat or chill the egg", "two treatments"),  # a choice of treatment: still refused
        ("put the egg or the apple in the fridge", "a choice between objects"),
    ],
)
def test_other_choices_stay_refused(text, named, capsys):
    code = main(["plan", text, "--world", "FloorPlan1", "--llm", "offline"])
    assert code == 2 and named in capsys.readouterr().err


@pytest.mark.data
def test_a_place_the_world_lacks_is_dropped_and_said():
    res = translate("put the egg in the bathtub or the fridge", scenario_world({"scene": "FloorPlan1"}))
    (task,) = res.tasks
    assert task.receptacle == ["Fridge"] and task.places == [["BathtubBasin"], ["Fridge"]]
    assert not res.unparsed
    assert any("no BathtubBasin in FloorPlan1, so the other is used" in a for a in res.assumptions)


@pytest.mark.data
def test_no_place_possible_is_exit_1_naming_them(capsys):
    code = main(["plan", "put the egg in the bathtub or the dresser", "--world", "FloorPlan1",
                 "--llm", "offline"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 1 and "BathtubBasin or Dresser" in err, err


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(
    "scene, thing, places",
    [
        ("FloorPlan1", "apple", ("fridge", "sink")),
        ("FloorPlan5", "mug", ("sink", "microwave")),
        ("FloorPlan201", "remote control", ("sofa", "armchair")),
    ],
)
def test_a_choice_costs_the_least_single_place(scene, thing, places, capsys):
    """The property: the choice's optimum is the minimum of the single-place optima (exact mode)."""
    a, b = places
    either = cost(f"put the {thing} on the {a} or the {b}", scene, capsys)
    assert either == min(cost(f"put the {thing} on the {p}", scene, capsys) for p in places)
