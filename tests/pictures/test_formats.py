"""Standard formats: plans validate against docs/plan.schema.json; `spec --hoa` writes HOA that Spot reads."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nl2hltl2plan.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
INSTRUCTION = "Put the apple in the fridge. Then put the mug in the cabinet."


@pytest.fixture(scope="module")
def schema():
    jsonschema = pytest.importorskip("jsonschema", reason="jsonschema is not installed")
    data = json.loads((ROOT / "docs" / "plan.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(data)
    return jsonschema.Draft202012Validator(data)


def test_committed_schema_is_the_one_generated_from_the_model():
    from nl2hltl2plan.worlds.plan import ACTION_ARITY, plan_json_schema

    committed = json.loads((ROOT / "docs" / "plan.schema.json").read_text())
    assert committed == plan_json_schema(), "docs/plan.schema.json drifted: run python scripts/plan_schema.py"
    verbs = committed["$defs"]["Step"]["properties"]["verb"]["enum"]
    assert set(ACTION_ARITY) <= set(verbs)  # every action the simulator knows, "break" included


def test_plan_json_validates_against_the_schema(schema, capsys):
    assert main(["plan", INSTRUCTION, "--world", "demo", "--robots", "2", "--llm", "offline", "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["plan"] is not None and len(payload["plan"]["robots"]) == 2
    errors = list(schema.iter_errors(payload["plan"]))
    assert not errors, [e.message for e in errors]


@pytest.mark.parametrize(
    "bad",
    [
        {"robots": [{"robot": 0, "start": [0, 0], "steps": [{"t": 1, "verb": "move"}]}]},  # move, no cell
        {
            "robots": [
                {"robot": 0, "start": [0, 0], "steps": [{"t": 1, "verb": "put", "objects": ["Apple_0"]}]}
            ]
        },
        {"robots": [{"robot": 0, "start": [0, 0], "steps": [{"t": 0, "verb": "wait"}]}]},  # t starts at 1
        {"robots": [{"robot": 0, "start": [0], "steps": []}]},
        {"robots": [{"robot": 0, "start": [0, 0], "steps": [{"t": 1, "verb": "fly"}]}]},
    ],
)
def test_schema_rejects_malformed_plans(schema, bad):
    assert list(schema.iter_errors(bad))


def test_spec_hoa_writes_one_automaton_per_formula(tmp_path, capsys):
    spot = pytest.importorskip("spot")
    out = tmp_path / "hoa"
    assert main(["spec", str(ROOT / "examples" / "dishwasher_htt.json"), "--hoa", str(out), "--json"]) == 0
    written = json.loads(capsys.readouterr().out)["hoa"]
    assert set(written) == {p.stem for p in out.glob("*.hoa")} and "task1" in written
    root = spot.automaton(str(out / "task1.hoa"))
    assert {str(a) for a in root.ap()} == {"task1.1", "task1.2"}
    assert root.is_deterministic() and spot.is_terminal_automaton(root)
    # F(task1.1 & F task1.2): the word task1.1 ; task1.2 is accepted, task1.2 ; task1.1 is not
    word = spot.parse_word("task1.1 & !task1.2; !task1.1 & task1.2; cycle{1}")
    assert root.intersects(word.as_automaton())
    wrong = spot.parse_word("!task1.1 & task1.2; task1.1 & !task1.2; cycle{!task1.1 & !task1.2}")
    assert not root.intersects(wrong.as_automaton())


def test_spec_hoa_bad_folder(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert main(["spec", str(ROOT / "examples" / "dishwasher_htt.json"), "--hoa", str(blocker / "d")]) == 2
    assert "HOA folder" in capsys.readouterr().err
