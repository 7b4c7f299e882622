"""A word that is one type's own name is not read as another of its types because the task's place can
hold only that one (`grounding.role_swap_conflict`, asked by `referents.exact_names`): "the cup in the
coffee machine" where the floor plan has a Cup and a Mug is refused naming both (ALFRED's coffee machine
holds only a Mug); with a Mug and no Cup, "cup" is the Mug (the annotation guide's "cup -> Cup, else Mug");
with a Cup and no Mug it stays the Cup. And h125's user-style sets read as their ground truth says."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.referents import exact_names, stand_ins
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def place(tid: str, obj: str, dest: str) -> BaseTaskSpec:
    return BaseTaskSpec(id=tid, text="", kind="place", object=[obj], receptacle=[dest])


BOTH = {"Cup": 2, "Mug": 2, "CoffeeMachine": 1, "SinkBasin": 1}
MUG_ONLY = {"Mug": 1, "CoffeeMachine": 1, "Desk": 1}
CUP_ONLY = {"Cup": 1, "CoffeeMachine": 1, "SinkBasin": 1}


def test_the_cup_read_as_the_mug_is_refused_where_the_floor_plan_has_a_cup() -> None:
    said = r"'cup' is the Cup of FloorPlan1, which the CoffeeMachine cannot hold: say 'mug' for its Mug"
    with pytest.raises(HTTError, match=said):
        tasks = [place("A", "Mug", "CoffeeMachine")]
        exact_names("put the cup in the coffee machine", tasks, BOTH, "FloorPlan1")


def test_the_cup_is_the_mug_where_there_is_no_cup_and_the_cup_where_there_is() -> None:
    exact_names("put the cup in the coffee machine", [place("A", "Mug", "CoffeeMachine")], MUG_ONLY, "s")
    exact_names("put the cup on the desk", [place("A", "Mug", "Desk")], MUG_ONLY, "s")
    exact_names("put the cup in the coffee machine", [place("A", "Cup", "CoffeeMachine")], CUP_ONLY, "s")
    exact_names("put the cup in the sink", [place("A", "Cup", "SinkBasin")], BOTH, "s")


def test_the_cup_read_as_the_mug_where_there_is_no_cup_is_said() -> None:
    """The reading depends on the world, not on the words alone: it is stated as an assumption."""
    cup_in_machine = [place("A", "Mug", "CoffeeMachine")]
    said = stand_ins("put the cup in the coffee machine", cup_in_machine, MUG_ONLY, "F1")
    assert said == ["'cup': F1 has no Cup; read as its Mug"]
    # near misses: the word names what is read ("mug"), the Cup is there, or no task uses the Mug
    assert not stand_ins("put the mug in the coffee machine", cup_in_machine, MUG_ONLY, "F1")
    assert not stand_ins("put the cup in the sink", [place("A", "Cup", "SinkBasin")], BOTH, "F1")
    pen = [place("A", "Pen", "Desk")]
    assert not stand_ins("put the pen by the cup on the desk", pen, {"Pen": 1, "Desk": 1, "Mug": 1}, "F1")
    # a word no type is named by ("glass", the Cup first) is the lexicon's, not a name the world lacks
    assert not stand_ins("put the glass on the desk", [place("A", "Mug", "Desk")], MUG_ONLY, "F1")


def test_a_name_two_other_types_could_be_is_not_said_as_one() -> None:
    # "towel" where the floor plan has no Towel but a HandTowel and a Cloth: the roles decide, not this
    counts = {"HandTowel": 1, "Cloth": 1, "CounterTop": 1}
    assert not stand_ins("put the towel on the counter", [place("A", "HandTowel", "CounterTop")], counts, "F")
    counts = {"HandTowel": 1, "CounterTop": 1}
    said = stand_ins("put the towel on the counter", [place("A", "HandTowel", "CounterTop")], counts, "F")
    assert said == ["'towel': F has no Towel; read as its HandTowel"]


def test_a_towel_washed_read_as_the_cloth_is_said() -> None:
    # ALFRED cannot wash a Towel or a HandTowel: the role reads the Cloth, and the result says so
    counts = {"Towel": 1, "HandTowel": 1, "Cloth": 1, "Cabinet": 2}
    washed = [BaseTaskSpec(id="A", kind="clean_place", object=["Cloth"], receptacle=["Cabinet"])]
    said = stand_ins("put a wet towel in the cabinet", washed, counts, "F")
    assert said == ["'towel': read as the Cloth of F; its Towel cannot do what is asked"]
    # near miss: a word of its own in the task names the Cloth ("the rag"), so the towel is not read as it
    washed = [BaseTaskSpec(id="A", kind="clean_place", object=["Cloth"], receptacle=["Cabinet"],
                           text="put a wet rag by the towel in the cabinet")]
    assert not stand_ins("put a wet rag by the towel in the cabinet", washed, counts, "F")


def test_a_stand_in_is_said_of_the_task_whose_words_name_it() -> None:
    # the mug of one task does not hide the cup read as a Mug in another
    counts = {"Mug": 2, "Cabinet": 1, "CoffeeMachine": 1}
    tasks = [BaseTaskSpec(id="A", kind="place", object=["Mug"], receptacle=["Cabinet"],
                          text="put a mug away"),
             BaseTaskSpec(id="B", kind="place", object=["Mug"], receptacle=["CoffeeMachine"],
                          text="put a cup in the coffee maker")]
    said = stand_ins("put a mug away, then put a cup in the coffee maker", tasks, counts, "F")
    assert said == ["'cup': F has no Cup; read as its Mug"]
    # near miss: the cup is only where the mug goes (a landmark of the mug's task)
    tasks = [BaseTaskSpec(id="A", kind="place", object=["Mug"], receptacle=["Cabinet"],
                          text="put the mug by the cup in the cabinet")]
    assert not stand_ins("put the mug by the cup in the cabinet", tasks, counts | {"Cup": 1}, "F")


def test_a_mug_named_by_its_own_word_beside_the_cup_is_no_swap() -> None:
    tasks = [place("A", "Mug", "CoffeeMachine"), place("B", "Cup", "SinkBasin")]
    exact_names("put the mug in the coffee machine and the cup in the sink", tasks, BOTH, "s")
    # near miss: the same reading of a text whose only word for the mug is "cup"
    tasks = [place("A", "Mug", "CoffeeMachine"), place("B", "Cup", "SinkBasin")]
    with pytest.raises(HTTError, match="'cup' is the Cup"):
        exact_names("put the cup in the coffee machine and the cup in the sink", tasks, BOTH, "s")


def test_the_mug_of_another_task_does_not_let_the_cup_be_the_mug() -> None:
    tasks = [
        BaseTaskSpec(id="A", kind="heat_place", object=["Mug"], receptacle=["SinkBasin"], text="heat a mug"),
        BaseTaskSpec(id="B", kind="clean_place", object=["Mug"], receptacle=["CoffeeMachine"],
                     text="place a clean cup in the coffee maker"),
    ]
    text = "heat a mug, then place a clean cup in the coffee maker"
    with pytest.raises(HTTError, match="'cup' is the Cup of s, which the CoffeeMachine cannot hold"):
        exact_names(text, tasks, BOTH, "s")
    # the place named is the cup's, whichever task comes first
    text = "place a clean cup in the coffee maker after you heat a mug"
    with pytest.raises(HTTError, match="which the CoffeeMachine cannot hold"):
        exact_names(text, [tasks[1], tasks[0]], BOTH, "s")
    # near miss: the same task says "mug" too ("the mug or cup"): that word may mean the Mug
    tasks[1] = tasks[1].model_copy(update={"text": "place the clean mug or cup in the coffee maker"})
    exact_names("heat a mug, then place the clean mug or cup in the coffee maker", tasks, BOTH, "s")


def test_a_type_another_word_can_mean_is_that_words() -> None:
    # the Knife is the utensil's, not "the butter knife" (a negated thing) read as the Knife
    text = "put a utensil in the sink but do not touch the butter knife"
    exact_names(text, [place("A", "Knife", "SinkBasin")], {"ButterKnife": 1, "Knife": 1, "SinkBasin": 1}, "s")


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h125dev", "users_h125held"])
def test_the_h125_user_sets_read_as_their_ground_truth(name: str) -> None:
    """Every line with tasks converts to them, every line marked for refusal is refused, as `plan` reads."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    rows = trust_sets.load(name)
    got = [(gt.instruction, trust_sets.outcome(gt)[0]) for gt in rows]
    want = [(gt.instruction, "converted" if gt.feasible else "refused") for gt in rows]
    assert got == want
