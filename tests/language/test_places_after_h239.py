"""Issue 28 (h239): one verb over several things whose places follow ("Heat an egg and a plate. The egg goes
on the side table, the plate on the counter."), "one at a time" after such a list, "then drop the slice"
after a treated slice, a place shared by "as well" after a source ("..., and the keys from the sofa as
well"), and two things with one need ("the soap and a cloth both need washing, and both go back on the
rack"). Where a place names no thing of the list, or two of them, the text is left to be read or refused."""

from __future__ import annotations

import pytest
from household_readings import outcome

from nl2hltl2plan.language.grammar.treated_lists import treated_lists
from nl2hltl2plan.language.grammar.treatments_said import treatments_said


@pytest.mark.parametrize(
    "text, rewritten",
    [
        ("Heat an egg and a plate. The egg goes on the side table, the plate on the counter.",
         "Heat an egg and put it on the side table, heat a plate and put it on the counter."),
        ("Wash a plate, a pan and a mug, one at a time. The plate and the pan go on the counter, "
         "the mug in the sink.",
         "Wash a plate and put it on the counter, wash a pan and put it on the counter, "
         "wash a mug and put it in the sink."),
        ("Heat a tomato and an egg in the microwave, one at a time, and put each of them on the counter.",
         "Heat a tomato and an egg in the microwave, and put each of them on the counter."),
        ("Cut a potato and microwave a slice, then drop the slice in the sink.",
         "Cut a potato and microwave a slice, then drop it in the sink."),
    ],
)  # fmt: skip
def test_one_verb_over_a_list_with_places_after_is_written_per_thing(text, rewritten):
    assert treated_lists(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "Heat an egg and a plate. The apple goes on the side table, the plate on the counter.",  # no egg
        # "the potato" fits both things of the list
        "Heat a potato and a potato slice. The potato goes on the table, the slice on the counter.",
        "Heat an egg and a plate. The egg goes on the side table.",  # the plate has no place
    ],
)
def test_a_place_that_names_no_one_thing_of_the_list_leaves_the_text(text):
    assert treated_lists(text) == text


def test_two_things_with_one_need_share_the_place():
    said = "The pink bar of soap and a red cloth both need washing, and both go back on the rack."
    assert treatments_said(said) == "wash The pink bar of soap and a red cloth and put them on the rack."
    no_thing = "The idea and the plate both need washing."
    assert treatments_said(no_thing) == no_thing


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan7")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        ("Chill a slice of bread and a potato. The bread goes in the microwave, the potato on the counter.",
         ["cool_place Bread(sliced) -> Microwave", "cool_place Potato -> CounterTop"]),
        ("Move the mug to the counter, and the pan from the stove as well.",
         ["place Mug -> CounterTop", "place Pan -> CounterTop"]),
        ("The apple and the mug need to be washed and put in the fridge.",
         ["clean_place Apple -> Fridge", "clean_place Mug -> Fridge"]),
        ("One potato to be rinsed and left on the counter.", ["clean_place Potato -> CounterTop"]),
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert outcome(text, kitchen) == read


def test_a_reference_by_treatment_is_read_by_one_reader():
    """`references.treated_tasks` reads "the washing (jobs)" and "the looking" for `_described` and the
    remarks (`remark_edges`) alike; words that name no one treatment are no such reference."""
    from nl2hltl2plan.language.grammar.references import treated_tasks
    from nl2hltl2plan.language.task_specs import BaseTaskSpec

    def spec(kind: str, obj: str, tid: str) -> BaseTaskSpec:
        return BaseTaskSpec(kind=kind, object=[obj], receptacle=["Desk"], id=tid, text="")  # type: ignore[arg-type]

    specs = [spec("clean_place", "Mug", "A"), spec("examine_in_light", "Book", "B")]
    specs.append(spec("clean_place", "Cup", "C"))
    assert treated_tasks(["the", "washing"], specs, [0, 1, 2]) == [0, 2]
    assert treated_tasks(["looking"], specs, [0, 1, 2]) == [1]
    assert treated_tasks(["the", "pen"], specs, [0, 1, 2]) is None
    assert treated_tasks(["washing", "heating"], specs, [0, 1, 2]) is None


def test_a_subject_line_is_matched_by_the_projects_stems():
    from nl2hltl2plan.language.handover_headers import _stem

    assert {_stem(w) for w in ("moves", "moving", "move")} == {"mov"}
    assert _stem("swapping") == _stem("swap") and _stem("blocks") == _stem("block")
