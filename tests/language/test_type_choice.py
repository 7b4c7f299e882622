"""Issue 28, a word with two types in one floor plan (h165, `language/type_choice.py`): the text decides
where only one of them can do what is asked, or where the place the thing is at holds only one; nothing
decides otherwise, and the refusal stays. A refusal for a missing type says what is true of the word's
other types ("chair": ALFRED's Chair holds nothing)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.grounding import alfred_lookup, find_mentions, lookup
from nl2hltl2plan.language.missing_types import other_types_note
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.type_choice import text_decides

pytestmark = pytest.mark.data

TOWELS = ["HandTowel", "Towel", "Cloth"]  # "towel": the lexicon's order
BATHROOM = {"Towel": 1, "HandTowel": 1, "Cloth": 1, "GarbageCan": 1, "TowelHolder": 1, "HandTowelHolder": 1}


def towel_task(kind: str, **slots: list[str]) -> BaseTaskSpec:
    return BaseTaskSpec(id="A", text="", kind=kind, object=["HandTowel"], **slots)


def decides(text: str, task: BaseTaskSpec, instances=BATHROOM) -> str | None:
    m = next(m for m in find_mentions(text) if m.entry.phrase == "towel")
    return text_decides(m, TOWELS, [task], text, instances, "FloorPlan402")


def test_a_place_only_one_of_the_two_can_go_decides():
    said = decides("put the towel in the trash", towel_task("place", receptacle=["GarbageCan"]))
    assert said == "'towel': read as the HandTowel; its Towel cannot be put in or on the GarbageCan in ALFRED"


def test_a_place_both_can_go_decides_nothing():
    racks = towel_task("place", receptacle=["TowelHolder", "HandTowelHolder"])
    assert decides("put the towel on the towel rack", racks) is None


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("look at the towel from the hand towel holder under the lamp", "the HandTowelHolder it is at"),
        ("look at the towel hanging on the hand towel holder under the lamp", "the HandTowelHolder it is at"),
        # a landmark, or a place said without a word of where it is at, says nothing of which towel
        ("look at the towel next to the hand towel holder under the lamp", None),
        ("look at the towel by the hand towel holder under the lamp", None),
    ],
)
def test_the_place_a_thing_comes_from_decides_where_it_holds_one_of_them(text, said):
    got = decides(text, towel_task("examine_in_light", light=["DeskLamp"]))
    assert (got is None) if said is None else (said in (got or ""))


def test_a_holder_the_floor_plan_lists_but_its_world_does_not_build_decides_nothing():
    """FloorPlan401 builds a HandTowelHolder only, yet lists a TowelHolder: "the towel holder" may be the
    bath towel's, so the HandTowel is not the only reading."""
    from nl2hltl2plan.language.translate import translate
    from nl2hltl2plan.worlds import load_world

    bathroom = load_world("FloorPlan401")
    with pytest.raises(Nl2Hltl2PlanError, match="'towel' is both the Towel"):
        translate("hang the towel on the towel holder", bathroom, build=False, actions="none")
    res = translate("put the towel in the garbage can", bathroom, build=False, actions="none")
    assert [t.summary() for t in res.tasks] == ["place HandTowel -> GarbageCan"]
    assert any("its Towel cannot be put in or on the GarbageCan" in a for a in res.assumptions)


def test_a_missing_place_says_what_the_words_other_type_cannot_do():
    from nl2hltl2plan.language.translate import translate
    from nl2hltl2plan.worlds import load_world

    bedroom = load_world("FloorPlan326")
    for backend in ("offline", "grammar"):  # the grammar alone does not know the thing to hold
        with pytest.raises(Nl2Hltl2PlanError) as refused:
            translate("put the basketball on the chair", bedroom, backend, build=False, actions="none")
        said = str(refused.value)
        chair = "no ArmChair in FloorPlan326 ('chair' also names its Chair, which holds nothing"
        assert said.startswith(chair)
        able = "what there can hold the BasketBall: Bed, DiningTable, SideTable)"
        assert said.endswith(able) == (backend == "offline")


def test_the_note_says_nothing_where_nothing_more_is_true():
    chair = lookup("chair")
    assert chair is not None
    look = alfred_lookup()
    assert other_types_note(chair, "ArmChair", {"Bed"}, "tabletop", look, ["BasketBall"]) == ""  # no ALFRED
    mug = lookup("mug")
    assert mug is not None  # "mug": a Cup holds no Laptop either, but the word names a thing, not a place
    assert other_types_note(mug, "Mug", {"Cup"}, "FloorPlan1", look) == ""


@pytest.mark.parametrize("name", ["users_h165dev", "users_h165held"])
def test_the_h165_user_set_reads_nothing_wrong(name):
    """h165's lines over floor plans with two-type words, read as `plan` reads them: nothing read wrong,
    and each line converted or, where its ground truth says so, refused."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [(gt, *trust_sets.outcome(gt)) for gt in trust_sets.load(name)]
    assert [gt.instruction for gt, what, _ in outcomes if what == "wrong"] == []
    assert sum(what == ("converted" if gt.feasible else "refused") for gt, what, _ in outcomes) >= 16
