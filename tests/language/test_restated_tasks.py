"""A task said again is the task read before (`language/restated_tasks.py`, issue 23): its orders join the
earlier task (a cycle so made is refused), another thing stays another task, and where the words cannot
tell which, the reading is refused naming them."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.htt_build import build_htt
from nl2hltl2plan.language.restated_tasks import joined_restatements, restated
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def task(tid: str, text: str, obj: str = "Mug", dest: str = "Desk") -> BaseTaskSpec:
    return BaseTaskSpec(id=tid, text=text, kind="place", object=[obj], receptacle=[dest])


def reading(instruction: str, tasks: list[BaseTaskSpec], before: list[tuple[str, str]]) -> LanguageResult:
    htt, task_node, leaf_task = build_htt(instruction, tasks, before)
    return LanguageResult(
        backend="grammar",
        instruction=instruction,
        htt=htt,
        tasks=tasks,
        before=before,
        task_node=task_node,
        leaf_task=leaf_task,
    )


@pytest.mark.parametrize(
    ("first", "later"),
    [
        ("put the mug on the desk", "put the mug on the desk"),
        ("put a mug on the desk", "putting the mug on the desk"),
        ("put a mug on the desk", "you have put the mug on the desk"),
        ("put the mug on the desk", "putting it on the desk"),
        ("put a mug on the desk", "the mug is on the desk"),
    ],
)
def test_a_task_said_again_definitely_is_the_task_before(first, later):
    tasks = [task("A", first), task("B", "put the pillow on the bed", "Pillow", "Bed"), task("C", later)]
    assert restated(f"{first}, {tasks[1].text} after {later}", tasks) == {"C": "A"}


@pytest.mark.parametrize(
    "later",
    [
        "put another mug on the desk",
        "put the other mug on the desk",
        "put a second mug on the desk",
        "put a mug on the desk",  # "a mug ... a mug": two
        "putting a mug on the desk",  # "after putting a mug on the desk": another one
    ],
)
def test_another_thing_stays_another_task(later):
    tasks = [task("A", "put a mug on the desk"), task("B", later)]
    assert restated(f"put a mug on the desk and {later}", tasks) == {}


def test_a_task_of_another_place_or_thing_is_not_said_again():
    tasks = [task("A", "put the mug on the desk"), task("B", "put the mug on the bed", dest="Bed")]
    assert restated("put the mug on the desk and put the mug on the bed", tasks) == {}
    tasks = [task("A", "put the mug on the desk"), task("B", "put the pencil on the desk", "Pencil")]
    assert restated("put the mug on the desk and put the pencil on the desk", tasks) == {}


def test_a_task_asked_again_in_other_words_stays_two():
    """ALFRED's annotations of two identical trials name the thing definitely in two wordings."""
    for first, later in [
        ("put a mug on the desk", "put the mug on the desk"),
        ("put the mug on the desk", "set the mug down on the desk"),
    ]:
        tasks = [task("A", first), task("B", later)]
        assert restated(f"{first}, then {later}", tasks) == {}


def test_the_thing_after_two_identical_tasks_is_refused_naming_both():
    two = [task("A", "put a mug on the desk"), task("B", "put a mug on the desk")]
    two.append(task("C", "putting the mug on the desk"))
    said = "put a mug on the desk and put a mug on the desk, then put the pillow on the bed after "
    said += "putting the mug on the desk"
    with pytest.raises(HTTError, match="'putting the mug on the desk' may be the task 'put a mug on the"):
        restated(said, two)


def test_the_orders_of_a_task_said_again_join_the_task_before():
    said = "put a mug on the desk, then put the pillow on the bed after putting the mug on the desk"
    tasks = [task("A", "put a mug on the desk"), task("B", "put the pillow on the bed", "Pillow", "Bed")]
    tasks.append(task("C", "putting the mug on the desk"))
    res = joined_restatements(reading(said, tasks, [("A", "B"), ("C", "A")]))
    assert [t.id for t in res.tasks] == ["A", "B"]
    assert [t.text for t in res.tasks] == ["put a mug on the desk", "put the pillow on the bed"]
    assert res.before == [("A", "B")]
    assert sorted(res.task_node) == ["A", "B"] and sorted(res.leaf_task.values()) == ["A", "B"]


def test_a_cycle_through_a_task_said_again_is_refused_naming_it():
    said = (
        "put the mug on the desk before putting the pillow on the bed, and put the pillow on the bed "
        "before putting the mug on the desk"
    )
    texts = {"B": "putting the pillow on the bed", "C": "put the pillow on the bed"}
    pillow = [task(k, text, "Pillow", "Bed") for k, text in texts.items()]
    tasks = [task("A", "put the mug on the desk"), *pillow, task("D", "putting the mug on the desk")]
    with pytest.raises(HTTError, match="cyclic order in the instruction: 'put the mug on the desk' before"):
        joined_restatements(reading(said, tasks, [("A", "B"), ("C", "D")]))


def test_a_reading_without_a_task_said_again_is_left_as_it_is():
    one = [task("A", "put the mug on the desk")]
    res = reading("put the mug on the desk and the pillow on the bed", one, [])
    assert joined_restatements(res) is res


@pytest.mark.data
@pytest.mark.parametrize("name", ["trust_h131dev", "trust_h131held"])
def test_the_h131_sets_read_as_their_ground_truth_says(name):
    """h131's sentences, read as `plan` reads them: nothing read wrong; each line the ground truth can
    take is converted, and each it cannot is refused (an error or words named as not understood)."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [(gt, *trust_sets.outcome(gt)) for gt in trust_sets.load(name)]
    assert [gt.instruction for gt, what, _ in outcomes if what == "wrong"] == []
    refusals = ("refused", "partial")
    assert all(what in (("converted",) if gt.feasible else refusals) for gt, what, _ in outcomes)


def test_an_llm_backend_that_reads_a_reference_as_a_task_has_its_cycle_named(stub):
    """The LLM backends pass the same rule: a decomposition that reads the two "before putting ..."
    clauses as two more tasks is the cycle the text states."""
    import json

    from nl2hltl2plan.config.llm_settings import LLMSettings
    from nl2hltl2plan.language.llm.client import LLMClient
    from nl2hltl2plan.language.translate import translate
    from nl2hltl2plan.worlds.demo import demo_world

    said = (
        "put the mug in the fridge before putting the plate in the microwave, and put the plate in the "
        "microwave before putting the mug in the fridge"
    )
    texts = [
        ("put the mug in the fridge", "mug", "fridge"),
        ("putting the plate in the microwave", "plate", "microwave"),
        ("put the plate in the microwave", "plate", "microwave"),
        ("putting the mug in the fridge", "mug", "fridge"),
    ]
    tasks = [
        {"id": f"1.{k}", "text": t, "kind": "place", "object": o, "receptacle": r}
        for k, (t, o, r) in enumerate(texts, 1)
    ]
    relations = {"relations": [["1.1", "1.2"], ["1.3", "1.4"]]}
    decomposition = {"tasks": tasks}
    stub.answer = lambda body: json.dumps(relations if "temporal constraints" in str(body) else decomposition)
    client = LLMClient(LLMSettings(base_url=stub.base_url, api_key="k", max_retries=0, cache_dir=None))
    with pytest.raises(HTTError, match="cyclic order in the instruction: 'put the mug in the fridge' before"):
        translate(said, demo_world(), "openai", client, build=False, actions="none")
