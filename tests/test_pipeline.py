"""The one pipeline (`nl2hltl2plan.pipeline`): what the CLI, the web app and the benchmarks all call."""

from __future__ import annotations

import json
from typing import Any

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.pipeline import PipelineOptions, run
from nl2hltl2plan.worlds.demo import demo_world
from nl2hltl2plan.worlds.team import RobotProfile, Team

ORDERED = "First put the saucers in the upper rack, then put the cups in the upper rack"


@pytest.fixture(scope="module")
def world():
    return demo_world()


def test_run_returns_typed_stages_and_a_checked_plan(world) -> None:
    out = run(ORDERED, world, robots=2)
    assert out.ok and out.status == "solved"
    assert [t.object for t in out.language.tasks] == [["Saucer"], ["Cup"]]
    assert out.language.before == [("A", "B")]
    assert out.spec is out.language.spec and len(out.spec.levels) >= 2
    execution = out.result.execution
    assert execution is not None and execution.ok
    # the ordering holds in the executed plan: the last saucer is put before the first cup
    puts = [(e.t, e.atom) for e in execution.events if e.atom.startswith("put(")]
    last_saucer = max(t for t, a in puts if "Saucer" in a)
    first_cup = min(t for t, a in puts if "Cup" in a)
    assert last_saucer < first_cup


def test_to_json_is_what_plan_json_prints(world, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plan", ORDERED, "--robots", "2", "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    expected = json.loads(json.dumps(run(ORDERED, world, robots=2).to_json(), default=str))
    for key in ("tasks", "before", "spec", "plan", "travel_cost_m", "completion_time", "status", "team"):
        assert printed[key] == expected[key], key


def test_a_team_without_a_needed_skill_is_a_definite_no_with_the_reason(world) -> None:
    looker = RobotProfile.from_dict({"name": "looker", "skills": ["GoToObject", "OpenObject"]})
    out = run(ORDERED, world, robots=Team.of([looker]))
    assert not out.ok and out.status == "infeasible"
    assert "no robot in the team can pick up" in out.result.reason


def test_a_team_splits_work_by_skill(world) -> None:
    carrier = RobotProfile.from_dict(
        {"name": "carrier", "skills": ["PickupObject", "PutObject", "OpenObject"]}
    )
    idle = RobotProfile.from_dict({"name": "idle", "skills": ["GoToObject"]})
    out = run(ORDERED, world, robots=Team.of([idle, carrier]))
    assert out.ok and out.team == "idle, carrier"
    plan = out.result.plan
    assert plan is not None
    acting = {rp.robot for rp in plan.robots for st in rp.steps if st.verb not in ("move", "wait")}
    assert acting == {1}


def test_options_are_validated_before_any_work() -> None:
    from pydantic import ValidationError

    for bad in ({"plan_timeout_s": float("nan")}, {"plan_timeout_s": 0}, {"objective": "fastest"}):
        with pytest.raises(ValidationError):
            PipelineOptions.model_validate(bad)


needs_data = pytest.mark.skipif(
    __import__("nl2hltl2plan.config", fromlist=["data_dir"]).data_dir(required=False) is None,
    reason="needs ../shared/data",
)
TABLE = "Put the remote control on the table"


@needs_data
def test_learned_backend_ranks_ambiguous_words_and_json_lists_them(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["plan", TABLE, "--world", "FloorPlan201", "--llm", "learned", "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    (amb,) = payload["ambiguities"]
    assert amb["word"] == "table" and amb["role"] == "receptacle"
    assert set(amb["candidates"]) == {"CoffeeTable", "DiningTable", "SideTable"}
    assert amb["confidence"] == sorted(amb["confidence"], reverse=True)


@needs_data
def test_ask_lets_the_user_pick_the_type(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    import io

    monkeypatch.setattr("sys.stdin", io.StringIO("3\n"))
    assert main(["plan", TABLE, "--world", "FloorPlan201", "--llm", "learned", "--ask", "--json"]) == 0
    out = capsys.readouterr()
    payload = json.loads(out.out)
    assert "could mean" in out.err
    picked = [line.split(". ")[1].split(" ")[0] for line in out.err.splitlines() if line.startswith("  3.")][
        0
    ]
    assert payload["tasks"][0]["receptacle"] == [picked] and payload["ambiguities"] == []
    monkeypatch.setattr("sys.stdin", io.StringIO("9\n"))
    assert main(["plan", TABLE, "--world", "FloorPlan201", "--llm", "learned", "--ask"]) == 2


@needs_data
def test_run_asks_once_applies_and_records_the_picks(monkeypatch: pytest.MonkeyPatch) -> None:
    """`ask` sees the ambiguities of the one parse; its pick is applied and kept in the options."""
    from nl2hltl2plan.language import learned
    from nl2hltl2plan.worlds import load_world

    parses = []
    original = learned.parse_instruction

    def counted(*args: Any, **kwargs: Any) -> Any:
        parses.append(args[0])
        return original(*args, **kwargs)

    monkeypatch.setattr(learned, "parse_instruction", counted)
    seen = []

    def pick_last(ambiguities: list[Any]) -> dict[str, str]:
        seen.extend(ambiguities)
        return {f"{a.task}.{a.role}": a.candidates[-1] for a in ambiguities}

    out = run(TABLE, load_world("FloorPlan201"), robots=1, ask=pick_last)
    assert len(parses) == 1 and len(seen) == 1
    key = f"{seen[0].task}.{seen[0].role}"
    assert out.options.choices == {key: seen[0].candidates[-1]}
    assert out.language.tasks[0].receptacle == [seen[0].candidates[-1]] and out.language.ambiguities == []
    assert out.ok


def test_the_learned_parser_cross_checks_an_llm_reading(world) -> None:
    """An LLM's tasks that differ from the learned parser's reading are reported, not silently used."""
    from nl2hltl2plan.language.llm_reading import cross_check
    from nl2hltl2plan.language.translate import translate

    res = translate(ORDERED, world, "offline", build=False)
    assert cross_check(res, world.object_types(), world.name).warnings == []  # the same reading
    mugs = res.tasks[0].model_copy(update={"object": ["Mug"]})  # an LLM that moved mugs, not saucers
    moved = res.model_copy(update={"tasks": [mugs, *res.tasks[1:]]})
    warned = cross_check(moved, world.object_types(), world.name)
    assert any("reads this instruction differently" in w for w in warned.warnings)
    assert moved.warnings == []  # a new result; the one given is unchanged
