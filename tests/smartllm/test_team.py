"""Robot profiles, teams for `plan --robots`, capabilities and infeasible-team reasons."""

import json

import pytest

from nl2hltl2plan.errors import DataError, PlanningError
from nl2hltl2plan.worlds.team import RobotProfile, Team, parse_team, smartllm_profiles
from nl2hltl2plan.worlds.world import Affordances, World, WorldObject


@pytest.fixture(scope="module")
def world():
    objs = [
        WorldObject(
            id="Potato_0", type="Potato", position=(0.0, 0.9, 0.0), affordances=Affordances(pickupable=True)
        ),
        WorldObject(
            id="Knife_0", type="Knife", position=(0.0, 0.9, 0.0), affordances=Affordances(pickupable=True)
        ),
        WorldObject(
            id="Fridge_0",
            type="Fridge",
            position=(0.0, 0.9, 0.0),
            affordances=Affordances(receptacle=True, accepts=frozenset({"Potato"}), openable=True),
        ),
    ]
    return World.create("t", [(0.0, 0.0), (0.25, 0.0)], objs)


@pytest.mark.data
def test_parse_team_number_names_and_file(tmp_path):
    assert parse_team("3") == Team(3) and parse_team(2).capabilities  # plain sizes stay unrestricted
    team = parse_team("robot1,robot23")
    assert [p.name for p in team.profiles] == ["robot1", "robot23"]
    assert "SliceObject" not in team.profiles[1].skills
    f = tmp_path / "team.json"
    f.write_text(
        json.dumps(
            ["robot5", {"name": "lifter", "skills": ["PickupObject", "PutObject"], "mass_capacity": 0.5}]
        )
    )
    team = parse_team(str(f))
    assert team.size == 2 and team.profiles[1].mass_capacity == 0.5
    assert len(smartllm_profiles()) == 28 and smartllm_profiles()["robot7"].mass_capacity == 0.08


@pytest.mark.parametrize(
    "text, error, words",
    [
        pytest.param("robot99", PlanningError, "unknown robot profile", marks=pytest.mark.data),
        ("0", PlanningError, "at least 1"),
    ],
)
def test_parse_team_errors(text, error, words):
    with pytest.raises(error, match=words):
        parse_team(text)


def test_bad_team_file(tmp_path):
    f = tmp_path / "t.json"
    f.write_text(json.dumps([{"name": "x", "skills": ["Fly"]}]))
    with pytest.raises(DataError, match="unknown skill"):
        parse_team(str(f))
    f.write_text("{")
    with pytest.raises(DataError, match="not valid JSON"):
        parse_team(str(f))


def test_capabilities_skills_and_mass(world):
    weak = RobotProfile("weak", frozenset({"PickupObject", "PutObject", "OpenObject"}), 0.1)
    slicer = RobotProfile("slicer", frozenset({"SliceObject"}), None)
    team = Team.of([weak, slicer])
    masses = {"Potato": 0.2, "Knife": 0.05}
    caps = team.capabilities(world, masses)
    assert caps[0] == {"put", "open", "pickup(Knife)"} and caps[1] == {"slice"}
    atoms = ["pickup(Knife)", "slice(Potato)", "pickup(Potato)", "put(Potato,Fridge)"]
    problems = team.problems(atoms, world, masses)
    assert problems == [
        "no robot in the team can both hold a knife and slice (slice(Potato))",
        "no robot in the team can carry a Potato (0.2 kg; the strongest robot that picks up carries 0.1 kg)",
    ]
    assert Team.of([slicer]).problems(["open(Fridge)"], world) == [
        "no robot in the team can open (OpenObject), needed for open(Fridge)"
    ]
    assert Team(2).problems(atoms, world) == []


@pytest.mark.data
def test_team_problems_for_a_spec(world):
    from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
    from nl2hltl2plan.worlds.team import spec_atoms, team_problems

    spec = HierarchicalSpec([{"t": 'F("open(Fridge)" & F("pickup(Potato)" & F "put(Potato,Fridge)"))'}])
    assert spec_atoms(spec) == ["open(Fridge)", "pickup(Potato)", "put(Potato,Fridge)"]
    team = parse_team("robot24")  # GoToObject, SwitchOn, SwitchOff only
    assert team_problems(team, spec, world)[0] == (
        "no robot in the team can open (OpenObject), needed for open(Fridge)"
    )
    assert "pick up (PickupObject)" in team_problems(team, spec, world)[1]
    assert team_problems(parse_team("robot1"), spec, world) == []
