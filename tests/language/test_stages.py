"""The prompted stages and the LLM pipeline, deterministic: the stub server replays recorded answers."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nl2hltl2plan.errors import LLMError, WorldError
from nl2hltl2plan.language import stages
from nl2hltl2plan.language.llm import LLMClient, LLMSettings
from nl2hltl2plan.language.prompts import STAGES, load_prompt
from nl2hltl2plan.language.translate import translate

DATA = Path(__file__).parent / "data"

RECORDED = json.loads((DATA / "recorded_demo.json").read_text())


@pytest.fixture(scope="module")  # read only: one demo world for the module
def demo(world):
    return world("demo")


def make_client(stub, tmp_path=None) -> LLMClient:
    return LLMClient(
        LLMSettings(
            base_url=stub.base_url,
            model="recorded",
            api_key="k",
            backoff=0.01,
            cache_dir=(tmp_path / "cache") if tmp_path else None,
        )
    )


def test_prompt_files_have_examples_and_placeholders():
    for name in STAGES:
        p = load_prompt(name)
        assert p.examples, name
        assert all(u and a for u, a in p.examples)
        for _, a in p.examples:
            json.loads(a)  # every few-shot answer is valid JSON
    msgs = load_prompt("decompose").messages(
        instruction="Put the apple in the fridge.", objects="Apple, Fridge"
    )
    assert msgs[0]["role"] == "system" and msgs[-1]["content"].startswith("Instruction: Put the apple")
    with pytest.raises(LLMError, match="needs the value"):
        load_prompt("decompose").messages(instruction="x")


def test_llm_pipeline_with_recorded_answers(stub, demo, tmp_path):
    stub.rules = [tuple(r) for r in RECORDED["rules"]]
    client = make_client(stub, tmp_path)
    res = translate(RECORDED["instruction"], demo, "openai", client)
    assert [t.summary() for t in res.tasks] == [
        "clean_place Apple -> Fridge",
        "place_two 2x Mug -> DiningTable",
        "examine_in_light KeyChain under FloorLamp",
    ]
    assert res.before == [("A", "B")]
    assert res.htt.relations == [("1.1", "1.2")]
    assert res.htt.node("1.2").children == ["1.2.1", "1.2.2"]
    assert res.htt.node("1.2.1").actions == ["pickup(Mug)", "put(Mug,DiningTable)"]
    assert res.leaf_specs["1.3"] == ["pickup(KeyChain)", "toggle_on(FloorLamp)"]
    # 1 decomposition + 1 relation query (root) + 4 leaves (action completion)
    assert res.llm_calls["sent"] == 6 and len(stub.requests) == 6
    again = translate(RECORDED["instruction"], demo, "openai", make_client(stub, tmp_path))
    assert again.llm_calls["sent"] == 0 and again.llm_calls["cached"] == 6
    assert again.tasks == res.tasks


def test_unknown_object_names_the_missing_type(stub, demo):
    dec = {
        "tasks": [
            {
                "id": "1.1",
                "text": "put the statue on the table",
                "kind": "place",
                "object": "statue",
                "receptacle": "table",
            }
        ]
    }
    stub.queue = [json.dumps(dec)]
    with pytest.raises(WorldError, match="no Statue in demo"):
        translate("Put the statue on the table.", demo, "openai", make_client(stub))


def test_relations_with_unknown_ids_or_cycles_are_reasked(stub):
    stub.queue = [
        '{"relations": [["1.1", "1.9"]]}',
        '{"relations": [["1.1", "1.2"], ["1.2", "1.1"]]}',
        '{"relations": [["1.2", "1.1"]]}',
    ]
    rel = stages.relations(make_client(stub), "B after A", "1", "all", [("1.1", "A"), ("1.2", "B")])
    assert rel == [("1.2", "1.1")]
    feedback = [r["messages"][-1]["content"] for r in stub.requests[1:]]
    assert "unknown subtask id(s) ['1.9']" in feedback[0] and "cycle" in feedback[1]


def test_action_completion_is_grounded_in_the_scene(stub):
    stub.queue = [
        '{"actions": ["pickup(Statue)", "put(Statue,Table)"]}',
        '{"actions": ["grab(Apple)"]}',
        '{"actions": ["pickup(Apple)", "put(Apple,DiningTable)"]}',
    ]
    acts = stages.complete_actions(
        make_client(stub),
        "put the apple on the table",
        {"kind": "place", "object": ["Apple"], "receptacle": ["DiningTable"]},
        {"Apple", "DiningTable"},
        "demo",
    )
    assert acts == ["pickup(Apple)", "put(Apple,DiningTable)"]
    assert "no Statue in demo" in stub.requests[1]["messages"][-1]["content"]
    assert "is not an action" in stub.requests[2]["messages"][-1]["content"]


def test_decomposition_schema_errors_are_reasked(stub):
    bad = {"tasks": [{"id": "1.1", "text": "x", "kind": "place", "object": "Apple"}]}  # no receptacle
    good = {
        "tasks": [
            {"id": "7", "text": "x", "kind": "place", "object": "Apple", "receptacle": "Fridge"},
            {
                "id": "8",
                "text": "y",
                "subtasks": [
                    {"id": "a", "text": "y1", "kind": "place_two", "object": "Mug", "receptacle": "Cabinet"}
                ],
            },
        ]
    }
    stub.queue = [json.dumps(bad), json.dumps(good)]
    dec = stages.decompose(make_client(stub), "x", ["Apple", "Fridge"])
    assert [n.id for n in dec.tasks] == ["1.1", "1.2"] and dec.tasks[1].subtasks[0].id == "1.2.1"
    assert dec.tasks[1].subtasks[0].count == 2
    assert "needs a receptacle" in stub.requests[1]["messages"][-1]["content"]


def test_stage_timeout_is_an_llm_error(stub, demo):
    stub.answer = lambda body: ("sleep", 1.5, "{}")
    client = LLMClient(
        LLMSettings(base_url=stub.base_url, api_key="k", timeout=0.2, max_retries=0, cache_dir=None)
    )
    with pytest.raises(LLMError, match="decomposition: request to .* timed out"):
        translate("Put the apple in the fridge.", demo, "openai", client)


def test_translate_stage_checks_propositions(stub):
    stub.queue = ['{"ltl": "F(task1_1 & F task1_3)"}', '{"ltl": "F(task1_1 & F task1_2)"}']
    out = stages.translate(make_client(stub), ["task 1.1 before task 1.2"], ["1.1", "1.2"])
    assert out == "F(task1_1 & F task1_2)"
    assert "unknown propositions ['task1_3']" in stub.requests[1]["messages"][-1]["content"]


def test_learned_translator_is_checked_reported_and_reasked(stub, demo, monkeypatch, tmp_path):
    """--ltl learned: lifted sentences -> translator server; a wrong formula is reported with a witness
    trace and re-asked once; the corrected answer is used."""
    monkeypatch.setenv("NL2HLTL2PLAN_TRANSLATOR_BASE_URL", stub.base_url)
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_CACHE", str(tmp_path / "cache"))
    stub.queue = ['{"ltl": "F(task1_2 & F task1_1)"}', '{"ltl": "F(task1_1 & F task1_2)"}']
    res = translate(
        "Put a washed apple in the fridge. Then put the mug on the table.", demo, "offline", ltl="learned"
    )
    assert res.spec is not None
    assert "task 1.1 must be completed before task 1.2" in stub.requests[0]["messages"][-1]["content"]
    assert len(res.ltl_checks) == 1 and "differs from" in res.ltl_checks[0]
    assert "does not match the constraints" in stub.requests[1]["messages"][-1]["content"]
    top = res.spec.levels[0]["task1"]
    assert top.replace(" ", "").replace('"', "") in {"F(task1.1&Ftask1.2)"}


def test_learned_translator_falls_back_to_the_compiler(stub, demo, monkeypatch, tmp_path):
    monkeypatch.setenv("NL2HLTL2PLAN_TRANSLATOR_BASE_URL", stub.base_url)
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_CACHE", "off")
    stub.queue = ['{"ltl": "F task1_1 & F task1_2"}'] * 2
    res = translate(
        "Put a washed apple in the fridge. Then put the mug on the table.", demo, "offline", ltl="learned"
    )
    assert res.ltl_checks[-1].endswith("using the compiler's formula")
    assert "task1.1" in res.spec.levels[0]["task1"] and "F" in res.spec.levels[0]["task1"]


# ----- semantic checks with re-asks (issue 10.7) ------------------------------------------------------
PLATE = {"id": "1.2", "kind": "place", "object": ["Plate"], "receptacle": ["Cabinet"]}
TYPES = {"Plate", "Mug", "Cabinet"}


def test_actions_on_the_wrong_objects_are_reasked_with_the_reason(stub):
    stub.queue = [
        '{"actions": ["pickup(Mug)", "put(Mug,Cabinet)"]}',
        '{"actions": ["pickup(Plate)", "put(Plate,Cabinet)"]}',
    ]
    client = make_client(stub)
    acts = stages.complete_actions(client, "put the plate in the cabinet", PLATE, TYPES, "demo")
    assert acts == ["pickup(Plate)", "put(Plate,Cabinet)"]
    feedback = stub.requests[1]["messages"][-1]["content"]
    assert "does not fit" in feedback and "1.2 is about Plate, not Mug" in feedback
    assert client.stats.reasks == 1


def test_actions_that_stay_wrong_are_an_error_not_a_plan(stub):
    stub.queue = ['{"actions": ["pickup(Mug)", "put(Mug,Cabinet)"]}'] * 3
    with pytest.raises(stages.SemanticCheckError, match=r"actions of 1.2: .* after 3 attempts: .*not Mug"):
        stages.complete_actions(make_client(stub), "put the plate in the cabinet", PLATE, TYPES, "demo")


def test_decomposition_missing_a_named_object_is_reasked_then_reported(stub):
    apple = {"id": "1", "text": "apple", "kind": "place", "object": "apple", "receptacle": "fridge"}
    one = {"tasks": [apple]}
    stub.queue = [json.dumps(one)] * 3
    with pytest.raises(stages.SemanticCheckError, match=r"decomposition: .*names 'mug'.*no task uses it"):
        stages.decompose(make_client(stub), "Put the apple in the fridge and the mug in the sink.", [])
    assert "names 'mug'" in stub.requests[1]["messages"][-1]["content"]


def test_relations_that_stay_cyclic_name_the_cycle(stub):
    stub.queue = ['{"relations": [["1.1", "1.2"], ["1.2", "1.1"]]}'] * 3
    with pytest.raises(stages.SemanticCheckError, match=r"cycle: 1.1 before 1.2 before 1.1"):
        stages.relations(make_client(stub), "A then B", "1", "all", [("1.1", "A"), ("1.2", "B")])


def test_pipeline_with_wrong_leaf_actions_fails_instead_of_solving(stub, demo):
    """Plates asked, mugs moved: the recorded run with the mug leaves answered by plates."""
    plates = '{"actions": ["pickup(Plate)", "put(Plate,DiningTable)"]}'
    rules = [(k, plates if k.startswith("Task: put two mugs") else v) for k, v in RECORDED["rules"]]
    stub.rules = rules + [("does not fit the request", plates)]  # and it insists when re-asked
    with pytest.raises(LLMError, match=r"1.2.1.*is about Mug, not Plate"):
        translate(RECORDED["instruction"], demo, "openai", make_client(stub))
