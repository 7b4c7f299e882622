"""Issues 28 and 23 (h216): idioms that add a task or a thing to a task. "don't forget the X - it goes in Y"
is a request, not a negation; "X and Y both go on Z" counts nothing of its own; "..., and so does X", "the
same goes for X", "likewise X", "..., and the Y too", "plus X", "one more for the shelf" repeat the task
before for another thing. Before: refused or partial, and "do the same with a slice of potato" read a whole
potato (wrong at exit 0); a task dropped for "a slice of apple" was not named by check 1 (it took "of apple"
for a landmark)."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import translate
from tests.language.test_trust_corrections import _world

pytestmark = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def _tasks(text: str, world: str, backend: str = "offline") -> list[str]:
    res = translate(text, _world(world), backend, build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks]


CASES = [
    # a reminder of a thing and the placing said after it
    ("Don't forget the spatula - it goes in the sink.", "FloorPlan1", ["place Spatula -> SinkBasin"]),
    # a verbless list placed together: "both" is no count
    ("The lotion bottle and the box of tissues both go on the toilet tank.", "FloorPlan402",
     ["place SoapBottle -> Toilet", "place TissueBox -> Toilet"]),
    ("The hand towel goes in the trash can, and so do the 2 pump bottles and 2 bars of soap.", "FloorPlan402",
     ["place HandTowel -> GarbageCan", "place_two 2x SoapBottle -> GarbageCan",
      "place_two 2x SoapBar -> GarbageCan"]),
    # the task before, whole (its treatment and its slice), for another thing
    ("Rinse a plate and put it in the fridge, and the same goes for a potato.", "FloorPlan5",
     ["clean_place Plate -> Fridge", "clean_place Potato -> Fridge"]),
    ("Rinse a plate and put it in the fridge, and do the same with a slice of potato.", "FloorPlan5",
     ["clean_place Plate -> Fridge", "clean_place Potato(sliced) -> Fridge"]),
    ("Heat a mug and put it on the counter, and one more for the shelf.", "FloorPlan1",
     ["heat_place Mug -> CounterTop", "heat_place Mug -> Shelf"]),
]  # fmt: skip


@pytest.mark.parametrize(("text", "world", "want"), CASES)
def test_an_added_thing_gets_the_task_it_is_added_to(text, world, want):
    assert _tasks(text, world) == want


@pytest.mark.sweep
@pytest.mark.parametrize("backend", ["offline", "grammar"])
@pytest.mark.parametrize(
    ("text", "world", "want"),
    [
        *CASES,
        ("Rinse a plate and put it in the fridge, and likewise the potato.", "FloorPlan5",
         ["clean_place Plate -> Fridge", "clean_place Potato -> Fridge"]),
        ("Rinse a plate and put it in the fridge, and so does a potato.", "FloorPlan5",
         ["clean_place Plate -> Fridge", "clean_place Potato -> Fridge"]),
        ("Chill the apple and put it on the counter, plus the tomato.", "FloorPlan1",
         ["cool_place Apple -> CounterTop", "cool_place Tomato -> CounterTop"]),
        ("Heat a potato and put it in the fridge, and a slice of potato as well.", "FloorPlan11",
         ["heat_place Potato -> Fridge", "heat_place Potato(sliced) -> Fridge"]),
        ("Chill a slice of tomato and put it in the sink. Same for an apple.", "FloorPlan5",
         ["cool_place Tomato(sliced) -> SinkBasin", "cool_place Apple(sliced) -> SinkBasin"]),
        ("The apple, the potato and the egg each go in the fridge.", "FloorPlan5",
         ["place Apple -> Fridge", "place Potato -> Fridge", "place Egg -> Fridge"]),
        ("A chilled cup and a chilled pot both go on the dining table, and so does a washed butter knife.",
         "FloorPlan4",
         ["cool_place Cup -> DiningTable", "cool_place Pot -> DiningTable",
          "clean_place ButterKnife -> DiningTable"]),
        ("Wash the ladle and put it in a drawer, and the two spatulas go in a drawer as well.", "FloorPlan16",
         ["clean_place Ladle -> Drawer", "place_two 2x Spatula -> Drawer"]),
        ("Put two mugs on the counter, and two cups too.", "FloorPlan1",
         ["place_two 2x Mug -> CounterTop", "place_two 2x Cup -> CounterTop"]),
    ],
)  # fmt: skip
def test_additive_idioms_sweep(backend, text, world, want):
    assert _tasks(text, world, backend) == want


@pytest.mark.parametrize(
    "text",
    [
        "Don't forget the mug.",  # a reminder with no request after it names nothing to do
        "Don't put the apple in the fridge.",  # a real negation stays one (nothing to do but it)
    ],
)
def test_a_reminder_of_nothing_and_a_negation_are_no_requests(text):
    with pytest.raises(Nl2Hltl2PlanError):
        translate(text, _world("FloorPlan1"), "offline", build=False, actions="none")


def test_check_1_names_a_slice_no_task_takes():
    text = "Chill a slice of tomato and put it in the sink. Chill a slice of apple and put it in the sink."
    tomato = BaseTaskSpec(id="A", kind="cool_place", object=["Tomato"], sliced=True, receptacle=["SinkBasin"])
    assert any(u.words == "apple" for u in account(text, [tomato], []))
