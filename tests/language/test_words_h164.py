"""Issue 23, everyday words and referents (h164): a state the spec cannot check that picks one of several
things ("the empty mug") is unread; a place picked by position ("the left drawer") is read as its type
and the result says so; "the other one" read as the same thing again is refused; British names of
household things are read as the lexicon's. Each beside the near miss that keeps its reading."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar.everyday import everyday_names
from nl2hltl2plan.language.grounding import find_mentions, lookup
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.picked_states import picked_states
from nl2hltl2plan.language.referents import another_thing, picked_places
from nl2hltl2plan.language.task_specs import BaseTaskSpec

KITCHEN = {"Potato": 2, "Drawer": 4, "Fridge": 1, "Apple": 3, "CounterTop": 4, "Shelf": 8, "Statue": 3}


def task(tid: str, obj: str, dest: str, kind: str = "place", count: int = 1) -> BaseTaskSpec:
    return BaseTaskSpec(id=tid, text="", kind=kind, object=[obj], receptacle=[dest], count=count)


BEDROOM = {"Mug": 3, "Dresser": 1, "Drawer": 4, "SinkBasin": 1, "Cabinet": 3, "SoapBottle": 1, "Box": 2}
MUG = [task("A", "Mug", "Dresser")]


def states(text: str, tasks: list[BaseTaskSpec] = MUG, instances=BEDROOM) -> list[str]:
    parse = ParseUsage(tasks, [], [], [])
    return [u.words for u in picked_states(text, find_mentions(text), parse, instances)]


@pytest.mark.parametrize(
    ("text", "tasks", "word"),
    [
        ("put the empty mug on the dresser", MUG, "empty"),
        ("put my full mug on the dresser", MUG, "full"),
        ("put the mug that's empty on the dresser", MUG, "empty"),
        ("put the mug on the dresser which is open", MUG, []),  # one dresser: picks nothing
        ("put the mug in the open drawer", [task("A", "Mug", "Drawer")], "open"),
        ("put that closed box on the dresser", [task("A", "Box", "Dresser")], "closed"),
        ("put the used box in the cabinet", [task("A", "Box", "Cabinet")], "used"),
    ],
)
def test_a_state_that_picks_one_of_several_is_unread(text, tasks, word):
    assert states(text, tasks) == ([word] if word else [])


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("put the empty soap bottle in the cabinet", [task("A", "SoapBottle", "Cabinet")]),  # only one
        ("examine an empty box by the light of a floor lamp", [task("A", "Box", "Dresser")]),  # any box
        ("put the clean mug on the dresser", MUG),  # a treatment makes it so
        ("rinse the dirty mug and put it on the dresser", MUG),  # what the cleaning undoes
        ("put the red mug on the dresser", MUG),  # a colour
        ("open the drawer and put the mug on the dresser", MUG),  # a verb
    ],
)
def test_near_misses_keep_their_reading(text, tasks):
    assert states(text, tasks) == []
    assert states("put the empty mug on the dresser", MUG, None) == []  # the scene unknown: not judged


def test_a_place_picked_by_position_is_read_as_its_type_and_said():
    tasks = [task("A", "Potato", "Drawer")]
    said = picked_places("put the potato in the left drawer", tasks, KITCHEN, "FloorPlan6")
    assert said == [
        "'left drawer': read as any Drawer (FloorPlan6 has 4; the spec names types, not which one)"
    ]
    # "top drawer" is a lexicon name of its own; "top shelf" is not: both said
    assert picked_places("put the potato in the top drawer", tasks, KITCHEN, "FloorPlan6")
    shelf = [task("A", "Statue", "Shelf")]
    said = picked_places("put the statue on the top shelf", shelf, KITCHEN, "FloorPlan6")
    assert said[0].startswith("'top shelf': read as any Shelf")


def test_a_place_not_picked_or_the_only_one_is_not_said():
    assert picked_places("put the potato in the drawer", [task("A", "Potato", "Drawer")], KITCHEN, "F") == []
    one = {"Fridge": 1, "Apple": 3}
    assert picked_places("put the apple in the left fridge", [task("A", "Apple", "Fridge")], one, "F") == []
    assert picked_places("put the apple in the left drawer", [task("A", "Apple", "Drawer")], None, "F") == []


def test_the_other_one_read_as_the_same_thing_is_refused():
    chilled = [task("A", "Apple", "CounterTop", kind="cool_place")]
    with pytest.raises(HTTError, match="'the other one' names a second apple"):
        another_thing("put the apple in the fridge and put the other one on the counter", chilled)
    with pytest.raises(HTTError, match="'another' names a second apple"):
        another_thing("put an apple in the fridge and then another on the counter", chilled)
    # near misses: two apples read; the other one a place; "it"
    two = [task("A", "Apple", "Fridge"), task("B", "Apple", "CounterTop")]
    another_thing("put the apple in the fridge and put the other one on the counter", two)
    pair = [task("A", "Apple", "Fridge", count=2)]
    another_thing("put the apple in the fridge, then put another one in the fridge", pair)
    apart = [task("A", "Apple", "Drawer"), task("B", "Potato", "Drawer")]
    another_thing("put the apple in the left drawer and the potato in the other one", apart)
    another_thing("put the apple in the fridge and then put it on the counter", chilled)
    another_thing("heat the apple and put it on the counter, one after the other", chilled)
    # with no thing moved said before it, the word names a second thing where each type is taken once
    with pytest.raises(HTTError, match="'the other one' names a second thing, and the reading acts on one"):
        another_thing("put the other one on the counter", chilled)


@pytest.mark.parametrize(
    ("phrase", "type_"),
    [("kitchen roll", "PaperTowelRoll"), ("loo roll", "ToiletPaper"), ("settee", "Sofa"),
     ("telly remote", "RemoteControl"), ("worktop", "CounterTop")],
)  # fmt: skip
def test_a_british_name_names_its_scene_type(phrase, type_):
    entry = lookup(everyday_names(f"the {phrase}"))
    assert entry is not None and entry.canonical == type_, (phrase, entry)
