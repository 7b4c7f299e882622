"""Issue 23: negations become constraints beside the spec, which the planner and the checker enforce
(real Spot, real planner, real plan validator)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
import spot

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import Grounder, alfred_lookup
from nl2hltl2plan.language.negations import read_negations
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec
from nl2hltl2plan.logic.constraints import Constraint
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.pipeline import run
from nl2hltl2plan.planning import plan, validate
from nl2hltl2plan.worlds.demo import demo_world

needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))  # trust_sets
KITCHEN = {"Apple", "Fridge", "Microwave", "Mug", "CounterTop", "SinkBasin", "Cup", "DishwasherUpperRack"}


def read(text: str) -> tuple[str, list[tuple[str, list[str], str]]]:
    rest, found = read_negations(text, Grounder(KITCHEN))
    return rest, [(n.spec.text, n.spec.forbid, n.until_words) for n in found]


def test_negated_clauses_are_read_as_forbidden_actions_and_taken_out_of_the_tasks():
    assert read("put the apple in the fridge but don't put the mug on the counter") == (
        "put the apple in the fridge",
        [("don't put the mug on the counter", ["put(Mug,CounterTop)"], "")],
    )
    assert read("never turn on the microwave and put the apple in the fridge")[1] == [
        ("never turn on the microwave", ["toggle_on(Microwave)"], "")
    ]
    rest, [(_, forbid, _)] = read("put the mug in the sink without using the microwave")
    assert rest == "put the mug in the sink" and "open(Microwave)" in forbid and "put(*,Microwave)" in forbid
    assert read("put the mug in the sink, never the cup")[1] == [
        ("never the cup", ["put(Cup,SinkBasin)"], "")
    ]
    _, [opening, using] = read("put the mug in the sink without opening the fridge or using the microwave")
    assert opening[1] == ["open(Fridge)"] and using[0] == "or using the microwave"
    assert "put(*,Microwave)" in using[1]
    _, [(_, _, until)] = read(
        "put the mug in the sink. Do not open the fridge before the mug is in the sink."
    )
    assert until == "the mug is in the sink"
    # left to the task parser (an ordering) or to the word accounting (refused)
    for kept in (
        "Do not put the apple in the fridge until you put the mug in the cabinet.",
        "Do not open the fridge and put the apple in it until you put the mug in the sink.",
        "put the mug in the sink and never examine the apple",
        "put the mug in the sink in any order; the order is not specified",
        "put the mug in the sink and never open the safe",  # no safe in the scene
    ):
        assert read(kept) == (kept, []), kept


def test_the_accounting_counts_a_negation_as_used_when_a_constraint_carries_it():
    text = "put the apple in the fridge but never open the microwave"
    apple = BaseTaskSpec(id="A", kind="place", object=["Apple"], receptacle=["Fridge"])
    never = ConstraintSpec(text="never open the microwave", forbid=["open(Microwave)"])
    assert {u.category for u in account(text, [apple], [])} == {"negation", "place"}
    assert account(text, [apple], [], constraints=[never]) == []
    # a constraint that forbids something else than its words say is not a reading of them
    wrong = ConstraintSpec(text="never turn on the microwave", forbid=["open(Microwave)"])
    found = account(
        "put the apple in the fridge but never turn on the microwave", [apple], [], constraints=[wrong]
    )
    assert [u.category for u in found] == ["action"]
    invented = ConstraintSpec(text="never open the microwave", forbid=["open(Cabinet)"])
    assert {u.category for u in account(text, [apple], [], constraints=[invented])} == {"invented", "place"}


def test_a_constraint_is_a_safety_formula_beside_the_sc_ltl_nodes():
    never = Constraint("never open the fridge", ("open(Fridge)",))
    assert spot.formula(never.formula).is_syntactic_safety()
    assert not spot.formula(never.formula).is_syntactic_guarantee()  # so not a node of the hierarchy
    guard = Constraint("not before", ("open(Fridge)",), "task1")
    assert spot.formula(guard.formula).is_syntactic_guarantee()
    spec = HierarchicalSpec([{"task1": ["pickup(Apple)", "put(Apple,Fridge)"]}], [guard])
    again = HierarchicalSpec.from_json(spec.to_json())
    assert again.constraints == spec.constraints and "U task1" in again.constraints[0].formula
    with pytest.raises(Exception, match="no formula of the spec"):
        HierarchicalSpec([{"task1": ["pickup(Apple)"]}], [Constraint("x", ("open(Fridge)",), "task9")])


def test_the_planner_avoids_what_a_constraint_forbids_and_the_checker_rejects_a_violation():
    world = demo_world()
    free = run("put a utensil in the sink", world)
    took = [e.atom for e in free.result.events if e.atom.startswith("pickup")]
    banned = took[0].removeprefix("pickup(").removesuffix(")")  # the utensil it chose
    words = {"ButterKnife": "butter knife", "Fork": "fork", "Spoon": "spoon", "Knife": "knife"}[banned]
    kept = run(f"put a utensil in the sink but do not touch the {words}", world)
    assert kept.ok and kept.spec.constraints and kept.result.total_cost >= free.result.total_cost
    assert not any(banned in e.atom for e in kept.result.events)
    # the unconstrained plan, checked against the constrained spec: rejected, naming the constraint
    verdict = validate(world, kept.spec, free.result.plan)
    assert not verdict.ok and "breaks the constraint" in verdict.reasons[0]
    assert validate(world, kept.spec, kept.result.plan).ok


def test_a_constraint_against_a_task_is_refused_and_an_infeasible_one_is_a_definite_no(capsys):
    # the rack sits in the closed dishwasher: the text contradicts itself, exit 2 naming both (h255; was 1)
    text = "put a cup in the upper rack, never open the dishwasher"
    assert main(["plan", text, "--world", "demo", "--llm", "offline"]) == 2
    err = capsys.readouterr().err
    assert "'never open the dishwasher' forbids open(Dishwasher)" in err
    assert "'put a cup in the upper rack'" in err
    spec = HierarchicalSpec([{"task1": ["pickup(Cup)", "put(Cup,DishwasherUpperRack)"]}],
                            [Constraint("no cups in the rack", ("put(Cup,*)",))])  # fmt: skip
    result = plan(demo_world(), spec, [(0, 0)])
    assert result.status == "infeasible" and "no cups in the rack" in result.reason


def test_plan_json_lists_the_constraints_and_a_bare_negation_has_nothing_to_do(capsys):
    text = "put the plates in the lower rack and never open the fridge"
    assert main(["plan", text, "--world", "demo", "--llm", "offline", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["constraints"] == ['never open the fridge: G!"open(Fridge)"'] and not out["partial"]
    with pytest.raises(HTTError, match="nothing to do: .* only says what not to do"):
        run("do not put the cups in the upper rack", demo_world())
    assert (
        main(["plan", "heat the plate and put it on the counter, never examine the mug", "--world", "demo"])
        == 2
    )
    assert "'never' (negation)" in capsys.readouterr().err


def test_a_negation_typed_without_its_apostrophe_is_read_as_with_it(capsys):
    # "dont" is read as "don't" by the words' accounting (`grammar.everyday`), so the constraint read
    # from "dont ..." must be found there too, and the other bare forms are cues of their own
    for bare, written in (("dont", "don't"), ("shouldnt", "shouldn't"), ("mustnt", "mustn't")):
        said = {}
        for cue in (bare, written):
            text = f"put the plates in the lower rack but you {cue} open the fridge"
            assert main(["plan", text, "--world", "demo", "--json"]) == 0, text
            out = json.loads(capsys.readouterr().out)
            forbidden = [c.split(": ", 1)[1] for c in out["constraints"]]
            said[cue] = ([t["object"] for t in out["tasks"]], forbidden)
        assert said[bare] == said[written] == ([["Plate"]], ['G!"open(Fridge)"']), said
    assert read("put the mug in the sink but dont put it in the microwave")[1] == [
        ("dont put it in the microwave", ["put(Mug,Microwave)"], "")
    ]


def test_an_it_after_a_negated_clause_is_the_thing_that_clause_named():
    # the negated clause leaves the text the task parser reads, so its thing goes back into the "it"
    for text in (
        "dont put the mug in the sink, put it in the fridge",
        "Don't put the mug in the sink. Put it in the fridge.",
        "never put the mug in the sink, put it in the fridge instead",
    ):
        rest, [(_, forbid, _)] = read(text)
        assert "the mug in the fridge" in rest and forbid == ["put(Mug,SinkBasin)"], (text, rest)
    # a thing named before the "it" is what it stands for; none named gives no "it" back
    assert read("never put the mug in the sink; put the apple in it")[0] == "put the apple in it"
    # "them" is the things a negated list names, exactly; a pronoun of the other number is refused
    two = "don't put the mug or the cup in the sink, put them in the fridge"
    assert read(two)[0] == "put the mug and the cup in the fridge"
    assert read("never put the mugs in the sink, put them in the fridge")[0] == "put the mugs in the fridge"
    with pytest.raises(HTTError, match="'it' after \"don't put the mug and the cup in the sink\" is one of"):
        read("don't put the mug and the cup in the sink, put it in the fridge")
    with pytest.raises(HTTError, match="'them' after \"don't put the mug in the sink\" names more than"):
        read("don't put the mug in the sink, put them in the fridge")
    spaced = "don't put the mug in the sink or the cup in the fridge, put them on the table"
    assert read(spaced)[0] == "put them on the table"  # not one list: what "them" names is unsure
    assert read("heat the mug but don't put it in the microwave, put it on the counter")[0] == (
        "heat the mug, put it on the counter"
    )


@needs_data
def test_a_constraint_can_make_the_plan_costlier():
    from nl2hltl2plan.worlds import load_world

    world = load_world("FloorPlan1")  # one apple lies in the microwave, the other on the counter
    free = run("put an apple in the sink", world)
    kept = run("put an apple in the sink without using the microwave", world)
    assert "open(Microwave)" in [e.atom for e in free.result.events]
    assert kept.ok and kept.result.total_cost > free.result.total_cost
    assert not validate(world, kept.spec, free.result.plan).ok
    guard = run("put the apple in the fridge and put the mug in the sink. Do not open the fridge before "
                "the mug is in the sink.", world)  # fmt: skip
    events = [e.atom for e in guard.result.events]
    assert guard.ok and events.index("open(Fridge)") > events.index("put(Mug,SinkBasin)")


@needs_data
def test_a_change_of_state_can_be_forbidden():
    from nl2hltl2plan.worlds import load_world

    world = load_world("FloorPlan1")  # an apple lies in the microwave: heating the potato heats it too
    free = run("heat the potato and put it on the counter", world)
    kept = run("heat the potato and put it on the counter, but do not heat the apple", world)
    assert kept.spec.constraints[0].forbid == ("heat(Apple)",)
    assert kept.status == "infeasible" and "do not heat the apple" in kept.result.reason
    (why,) = validate(world, kept.spec, free.result.plan).reasons
    assert "heat(Apple) breaks the constraint 'do not heat the apple'" in why


def test_an_llm_backend_states_constraints(stub):
    from nl2hltl2plan.config.llm_settings import LLMSettings
    from nl2hltl2plan.language.llm.client import LLMClient
    from nl2hltl2plan.language.stages import SemanticCheckError
    from nl2hltl2plan.language.translate import translate

    text = "put the apple in the fridge but never open the microwave"
    answer = {
        "tasks": [{"id": "1.1", "text": "put the apple in the fridge", "kind": "place", "object": "apple",
                   "receptacle": "fridge"}],
        "constraints": [{"text": "never open the microwave", "verb": "open", "object": "microwave"}],
    }  # fmt: skip
    stub.answer = lambda body: json.dumps(answer)
    client = LLMClient(LLMSettings(base_url=stub.base_url, api_key="k", max_retries=0, cache_dir=None))
    res = translate(text, _Kitchen(), "openai", client, build=False, actions="none")
    assert [c.forbid for c in res.constraint_specs] == [["open(Microwave)"]] and not res.partial
    answer["constraints"] = []  # the negation dropped: an error naming it, never a plan
    client = LLMClient(LLMSettings(base_url=stub.base_url, api_key="k", max_retries=0, cache_dir=None))
    with pytest.raises(SemanticCheckError, match="names 'microwave'"):
        translate(text, _Kitchen(), "openai", client, build=False, actions="none")


def test_an_llm_answer_of_constraints_only_has_nothing_to_do(stub):
    from nl2hltl2plan.config.llm_settings import LLMSettings
    from nl2hltl2plan.errors import LLMError
    from nl2hltl2plan.language.llm.client import LLMClient
    from nl2hltl2plan.language.translate import translate

    answer: dict = {
        "tasks": [],
        "constraints": [{"text": "never open the microwave", "verb": "open", "object": "microwave"}],
    }
    stub.answer = lambda body: json.dumps(answer)
    client = LLMClient(LLMSettings(base_url=stub.base_url, api_key="k", max_retries=0, cache_dir=None))
    with pytest.raises(HTTError, match="nothing to do: .* only says what not to do"):
        translate("never open the microwave", _Kitchen(), "openai", client, build=False, actions="none")
    answer["constraints"] = []  # neither a task nor a constraint: an invalid answer, not an empty plan
    client = LLMClient(LLMSettings(base_url=stub.base_url, api_key="k", max_retries=0, cache_dir=None))
    with pytest.raises(LLMError, match="no task and no constraint"):
        translate("never open the microwave", _Kitchen(), "openai", client, build=False, actions="none")


class _Kitchen:
    name = "a kitchen"

    def object_types(self) -> set[str]:
        return KITCHEN


@needs_data
def test_benchmark_records_keep_the_constraints_for_the_planning_workers():
    import trust_sets

    from nl2hltl2plan.pipeline import PipelineOptions
    from nl2hltl2plan.suites.alfred.alfred_language import language_record

    (gt,) = [g for g in trust_sets.load("mixed") if g.instruction.endswith("never touch the tomato")]
    rec = language_record(gt, PipelineOptions(), None)
    spec = HierarchicalSpec.from_json({"levels": rec.levels, "constraints": rec.constraints})
    assert rec.conversion_ok and [c.text for c in spec.constraints] == ["never touch the tomato"]


def test_it_and_there_in_a_negation_stand_for_the_thing_and_the_place_named_before():
    """ "don't put it in the sink" forbids putting the mug there, not "putting the sink" somewhere."""
    assert read("wash the mug but don't put it in the sink")[1] == [
        ("don't put it in the sink", ["put(Mug,SinkBasin)"], "")
    ]
    assert read("put the apple on the counter but don't put the mug there")[1] == [
        ("don't put the mug there", ["put(Mug,CounterTop)"], "")
    ]
    assert read("never put it in the sink")[1] == []  # "it" with nothing before: unread, so refused


@needs_data
def test_not_followed_by_a_place_forbids_the_thing_going_there():
    """ "put the tomato in the fridge, not the microwave": the microwave is the place the thing must not go
    (it was read as "the microwave must not go in the fridge"); a word that may be a thing stays a thing."""
    look = alfred_lookup()
    grounder = Grounder(KITCHEN | {"Tomato", "Bowl", "Cabinet"})

    def forbids(text: str) -> list[list[str]]:
        return [n.spec.forbid for n in read_negations(text, grounder, look)[1]]

    assert forbids("put the tomato in the fridge, not the microwave") == [["put(Tomato,Microwave)"]]
    assert forbids("put the mug in the sink, not the cabinet") == [["put(Mug,Cabinet)"]]
    assert forbids("put the apple in the fridge, not the bowl") == [["put(Bowl,Fridge)"]]
    assert forbids("put the apple in the fridge, not the tomato") == [["put(Tomato,Fridge)"]]


@needs_data
def test_a_place_named_only_as_the_source_is_no_destination(capsys):
    assert main(["plan", "take the mug out of the sink", "--world", "FloorPlan1", "--llm", "offline"]) == 2
    assert "no destination for the 'the mug'" in capsys.readouterr().err
    # an LLM's reading "put the mug in the sink" is judged invented by check 1
    sink = [BaseTaskSpec(kind="place", object=["Mug"], receptacle=["SinkBasin"])]
    assert [u.category for u in account("take the mug out of the sink", sink, [])] == ["invented"]
    assert account("take the mug out of the cabinet and put it in the sink", sink, []) == []
