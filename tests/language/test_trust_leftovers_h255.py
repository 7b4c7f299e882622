"""h255 (issue 23): session 31's trust leftovers, through `plan` (results/language/h255.md).

- A constraint that forbids what a task of the same reading requires is refused at the spec (exit 2),
  naming the constraint's words and the task, where the planner answered "infeasible" (exit 1), and one
  shape was kept refused by a special case of the negation reader.
- Words dropped at exit 0: a closing "Then stack them." / "Then serve." (an arranging verb with no place
  and no thing of its own), an exclamation naming a thing and no action ("Carrot time!"), and "... and
  label it" (a verb known only from a word list's comment or category name) are named.
"""

from __future__ import annotations

import pytest

from nl2hltl2plan.cli.main import main


def plan(text: str, world: str, capsys) -> tuple[int, str]:
    code = main(["plan", text, "--world", world, "--llm", "offline"])
    return code, capsys.readouterr().err


CONTRADICTS = "the instruction contradicts itself"


def test_a_ban_on_what_the_task_does_is_refused_naming_both(capsys):
    code, err = plan("put the plates in the lower rack and never pick up the plates", "demo", capsys)
    assert code == 2 and CONTRADICTS in err
    assert "'never pick up the plates' forbids pickup(Plate)" in err
    assert "'put the plates in the lower rack'" in err


def test_a_ban_on_something_else_still_plans(capsys):
    code, err = plan("put the plates in the lower rack and never open the fridge", "demo", capsys)
    assert code == 0 and CONTRADICTS not in err


@pytest.mark.data
def test_the_opening_a_placing_needs_is_required(capsys):
    code, err = plan("Put the apple in the fridge but never open the fridge.", "FloorPlan1", capsys)
    assert code == 2 and "'never open the fridge' forbids open(Fridge)" in err


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(
    "text, world, named",
    [
        ("Wash the mug and put it in the sink, without washing it.", "FloorPlan1", "forbids clean(Mug)"),
        ("Put the egg on the counter, don't touch the egg.", "FloorPlan1", "forbids pickup(Egg)"),
        ("Heat the potato in the microwave and never turn on the microwave.", "FloorPlan1", "toggle_on"),
        ("Heat the apple and put it in the fridge, don't heat it.", "FloorPlan1", "forbids heat(Apple)"),
        ("Slice the bread and put it on the counter, without slicing it.", "FloorPlan1", "slice(Bread)"),
        ("Put the orange on the yellow plate. Don't touch the orange.", "tabletop", "pickup(Orange)"),
        ("Put the orange on the yellow plate, but never pick up the orange.", "tabletop", "pickup(Orange)"),
    ],
)
def test_contradictions_sweep(text, world, named, capsys):
    code, err = plan(text, world, capsys)
    assert code == 2 and CONTRADICTS in err and named in err, err


@pytest.mark.data
@pytest.mark.parametrize(
    "text, world, named",
    [
        ("Put the orange on the yellow plate. Then stack them.", "tabletop", "'stack' (action)"),
        ("Put the orange on the yellow plate. Carrot time!", "tabletop", "'Carrot time' (action)"),
        ("Put the apple in the fridge and label it.", "FloorPlan1", "'label' (action)"),
    ],
)
def test_a_request_no_task_makes_is_named(text, world, named, capsys):
    code, err = plan(text, world, capsys)
    assert code == 2 and named in err, err


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(
    "text, named",
    [
        ("Put the orange on the yellow plate. Then arrange them.", "'arrange' (action)"),
        ("Put the orange on the yellow plate. Then serve.", "'serve' (action)"),
        ("Put the orange on the yellow plate and stack them.", "'stack' (action)"),
        ("Put the orange on the yellow plate. Carrot duty!", "'Carrot duty' (action)"),
    ],
)
def test_tabletop_requests_no_task_makes_sweep(text, named, capsys):
    code, err = plan(text, "tabletop", capsys)
    assert code == 2 and named in err, err


@pytest.mark.data
def test_an_arranging_verb_with_a_place_and_an_added_thing_still_read(capsys):
    assert plan("Stack the orange on the yellow plate.", "tabletop", capsys)[0] == 0
    assert plan("Put the orange on the yellow plate. The carrot too!", "tabletop", capsys)[0] == 0
