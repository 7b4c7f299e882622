"""HTT construction, the offline pipeline, grounding, scoring and the `plan` command."""

from __future__ import annotations

import json

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.backends import resolve_backend
from nl2hltl2plan.language.grounding import Grounder, find_mentions
from nl2hltl2plan.language.htt_build import build_htt, flat_before
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import translate


def spec(i: str, obj: str, kind: str = "place", rec: str = "Fridge", **kw) -> BaseTaskSpec:
    return BaseTaskSpec(id=i, text=f"task {i}", kind=kind, object=[obj], receptacle=[rec], **kw)


@pytest.fixture(scope="module")
def demo(world):
    return world("demo")


def test_build_htt_single_task_is_the_root_leaf():
    htt, tn, lt = build_htt("Put the apple in the fridge.", [spec("A", "Apple")], [])
    assert [n.id for n in htt.nodes] == ["1"] and tn == {"A": "1"} and lt == {"1": "A"}


def test_build_htt_place_two_has_two_leaves_and_groups_become_nodes():
    tasks = [spec("A", "Apple"), spec("B", "Mug", "place_two", count=2), spec("C", "Cup"), spec("D", "Egg")]
    htt, tn, lt = build_htt("x", tasks, [("A", "C"), ("B", "C"), ("C", "D")], groups=[["A", "B"]])
    assert htt.node("1").children == ["1.1", "1.2", "1.3"]
    assert htt.node("1.1").children == ["1.1.1", "1.1.2"] and tn["B"] == "1.1.2"
    assert htt.node("1.1.2").children == ["1.1.2.1", "1.1.2.2"] and lt["1.1.2.1"] == "B"
    assert sorted(htt.relations) == [("1.1", "1.2"), ("1.2", "1.3")]
    assert flat_before(htt, tn) == [("A", "C"), ("B", "C"), ("C", "D")]


def test_build_htt_dissolves_groups_with_mixed_outside_relations():
    tasks = [spec("A", "Apple"), spec("B", "Mug"), spec("C", "Cup")]
    htt, tn, _ = build_htt("x", tasks, [("A", "C")], groups=[["A", "B"]])
    assert htt.node("1").children == ["1.1", "1.2", "1.3"] and htt.relations == [("1.1", "1.3")]


def test_offline_translate_in_demo_world_has_recipe_actions(demo):
    res = translate("Put a washed apple in the fridge. Then put two mugs on the dining table.", demo)
    assert res.backend == "offline" and res.before == [("A", "B")]
    assert res.htt.node("1.1").actions[:2] == ["pickup(Apple)", "put(Apple,SinkBasin)"]
    assert res.htt.node("1.2.2").actions == ["pickup(Mug)", "put(Mug,DiningTable)"]
    assert set(res.leaf_specs) == {"1.1", "1.2.1", "1.2.2"}


def test_offline_translate_errors(demo):
    with pytest.raises(WorldError, match="no Statue in demo"):
        translate("Put the statue on the table.", demo)
    with pytest.raises(HTTError, match="understood no task"):
        translate("Hello there.", demo)


def test_grounding_rules():
    g = Grounder({"DiningTable", "SideTable", "Mug", "Knife", "ButterKnife", "KeyChain"}, "FloorPlan5")
    assert g.ground("table") == ["DiningTable", "SideTable"]
    assert g.ground("cup") == ["Mug"]  # cup -> Mug when the scene has no Cup
    assert g.ground("knife") == ["Knife", "ButterKnife"]
    assert g.ground("keys") == ["KeyChain"]
    with pytest.raises(WorldError, match="no Statue in FloorPlan5"):
        g.ground("statue")
    with pytest.raises(WorldError, match="cannot map the object 'unicorn'"):
        g.ground("unicorn")
    assert [m.surface for m in find_mentions("put the toilet paper on the toilet paper hanger")] == [
        "toilet paper",
        "toilet paper hanger",
    ]


def test_scoring_strict_and_lenient():
    gt = [
        {"id": "A", "kind": "place", "object": ["Apple"], "receptacle": ["DiningTable"]},
        {"id": "B", "kind": "place", "object": ["Mug"], "receptacle": ["Fridge"]},
    ]
    pred = [
        spec("X", "Mug"),
        BaseTaskSpec(id="Y", kind="place", object=["Apple"], receptacle=["DiningTable", "SideTable"]),
    ]
    assert not match(pred, [("Y", "X")], gt, [("A", "B")]).tasks_ok  # SideTable is not accepted
    lenient = match(pred, [("Y", "X")], gt, [("A", "B")], strict=False)
    assert lenient.ok and lenient.mapping == {"X": "B", "Y": "A"}
    wrong_order = match(pred, [("X", "Y")], gt, [("A", "B")], strict=False)
    assert wrong_order.tasks_ok and not wrong_order.order_ok


def test_resolve_backend_default_is_offline_with_a_note(monkeypatch):
    from nl2hltl2plan.language.llm import LLMSettings

    backend, note = resolve_backend(None, LLMSettings(cache_dir=None))
    assert backend == "offline" and "offline" in note
    assert resolve_backend(None, LLMSettings(base_url="http://x/v1", cache_dir=None)) == ("openai", None)


def test_cli_plan_json(capsys, monkeypatch, tmp_path):
    for var in ("NL2HLTL2PLAN_LLM_BASE_URL", "NL2HLTL2PLAN_LLM_API_KEY", "OPENAI_API_KEY", "OPENAI_BASE_URL"):
        monkeypatch.delenv(var, raising=False)
    rc = main(
        [
            "plan",
            "Put a washed apple in the fridge. Then put two mugs on the dining table.",
            "--world",
            "demo",
            "--robots",
            "2",
            "--json",
            "-o",
            str(tmp_path / "out"),
        ]
    )
    out = capsys.readouterr()
    assert rc == 0
    payload = json.loads(out.out)
    assert {"backend", "htt", "spec", "plan"} <= set(payload)
    assert payload["backend"] == "offline" and payload["htt"]["relations"] == [["1.1", "1.2"]]
    assert (
        payload["planner"]["status"] == "solved"
        and payload["plan"]["robots"]
        and payload["travel_cost_m"] > 0
    )
    assert "offline parser (grammar + learned model)" in out.err
    assert (tmp_path / "out" / "htt.png").stat().st_size > 1000
    from nl2hltl2plan.present.outputs import output_names  # the files the web page offers for download too

    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == sorted(output_names(has_plan=True))
    assert json.loads((tmp_path / "out" / "result.json").read_text())["tasks"][0]["kind"] == "clean_place"


def test_cli_plan_human_and_errors(capsys, monkeypatch):
    monkeypatch.delenv("NL2HLTL2PLAN_LLM_BASE_URL", raising=False)
    monkeypatch.delenv("NL2HLTL2PLAN_LLM_API_KEY", raising=False)
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)
    assert main(["plan", "Put the apple in the fridge.", "--llm", "offline"]) == 0
    out = capsys.readouterr().out
    assert "Hierarchical Task Tree" in out and "pickup(Apple)" in out and "Plan" in out
    assert main(["plan", "Put the statue in the fridge.", "--llm", "offline"]) == 2
    assert "error: no Statue in demo" in capsys.readouterr().err


def test_cli_plan_note_says_what_happens_to_an_ambiguous_word(capsys, monkeypatch):
    # "utensils" fits four types: without --ask every one stays acceptable, and the note says so
    rc = main(["plan", "Put the utensils in the lower rack.", "--llm", "offline", "--robots", "2"])
    err = capsys.readouterr().err
    assert rc == 0
    note = next(line for line in err.splitlines() if "'utensils'" in line)
    assert "could be" in note and "any of them is accepted (--ask to choose)" in note and "using" not in note


def test_cli_plan_with_stub_llm(stub, capsys, tmp_path, monkeypatch):
    from pathlib import Path

    recorded = json.loads((Path(__file__).parent / "data" / "recorded_demo.json").read_text())
    stub.rules = [tuple(r) for r in recorded["rules"]]
    monkeypatch.setenv("NL2HLTL2PLAN_LLM_CACHE", str(tmp_path / "cache"))
    rc = main(
        [
            "plan",
            recorded["instruction"],
            "--llm",
            "openai",
            "--base-url",
            stub.base_url,
            "--api-key",
            "k",
            "--json",
        ]
    )
    assert rc == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["backend"] == "openai" and payload["llm_calls"]["sent"] == 6
    # batch mode: everything is cached now (answers are keyed by server and model), so nothing is pending
    rc = main(
        [
            "plan",
            recorded["instruction"],
            "--llm",
            "openai",
            "--base-url",
            stub.base_url,
            "--json",
            "--base-url",  # the cache is keyed by server: same server, batch mode
            stub.base_url,
            "--batch-out",
            str(tmp_path / "pending.jsonl"),
        ]
    )
    assert rc == 0
    rc = main(
        [
            "plan",
            "Put the bread in the fridge.",
            "--llm",
            "openai",
            "--batch-out",
            str(tmp_path / "pending.jsonl"),
        ]
    )
    assert rc == 3 and "1 LLM request(s) pending" in capsys.readouterr().err
    assert json.loads((tmp_path / "pending.jsonl").read_text())["url"] == "/v1/chat/completions"
