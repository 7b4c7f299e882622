"""h236 (issue 23): session 30's red-team leftovers, read through `translate` (the `plan` language stage).

- a treatment added after the placing ("..., but wash it first", "but heat it up before", "only after rinsing
  it") comes before that task's placing (its kind) and never orders the task after the others;
- a keep-in-place wish ("the keys stay on the coffee table") is a ban on picking the thing up, not a placing;
- a thing taken out of a container and left so ("then take the knife out") is unread by name, never dropped;
- the subject of a relative clause that leaves its preposition at its end ("the bowl the mug is in") is a
  landmark, never a destination or a task;
- a negation's "it" names the place said before ("don't put the apple in it": that place only) or, with a
  treatment, the thing said before ("don't slice it": that thing only).
"""

from __future__ import annotations

import pytest
from household_readings import full_reading, refusal

from nl2hltl2plan.language.grounding import tokens
from nl2hltl2plan.language.negations import unmoved_said
from nl2hltl2plan.language.order_words import unordered_steps
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.unsupported_steps import taken_out


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


@pytest.fixture(scope="module")
def living_room(world):
    return world("FloorPlan201")


_APPLE_AND_WASHED_MUG = ["place Apple -> Fridge", "clean_place Mug -> Fridge"]


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        # main: A<B at exit 0, the mug's placing ordered after the apple's (h225's leftover)
        ("put the apple in the fridge, and the mug too, but wash it first", _APPLE_AND_WASHED_MUG),
        ("put the apple in the fridge, and put the mug in the fridge, wash it first", _APPLE_AND_WASHED_MUG),
        # main: partial ('heat' unread) without the comma, refused with "only after"
        ("put the mug in the cabinet but heat it up before", ["heat_place Mug -> Cabinet"]),
        ("put the mug in the fridge, but only after rinsing it", ["clean_place Mug -> Fridge"]),
    ],
)
def test_a_treatment_said_after_the_placing_comes_before_it_and_orders_nothing(kitchen, text, tasks):
    got, before, unread, _ = full_reading(text, kitchen)
    assert (got, before, unread) == (tasks, [], [])


@pytest.mark.data
def test_then_still_orders_the_task_whose_treatment_is_said_after_it(kitchen):
    got, before, unread, _ = full_reading(
        "put the apple in the fridge, then put the mug in the fridge, but wash it first", kitchen
    )
    assert (got, before, unread) == (["place Apple -> Fridge", "clean_place Mug -> Fridge"], [("A", "B")], [])


def test_check_one_takes_a_closing_first_of_a_treatment_as_its_own():
    tasks = [
        BaseTaskSpec(id="A", kind="place", object=["Apple"], receptacle=["Fridge"]),
        BaseTaskSpec(id="B", kind="clean_place", object=["Mug"], receptacle=["Fridge"]),
    ]
    parse = ParseUsage(tasks, [], [], [])
    for text, unread in [
        ("put the apple in the fridge and the mug in the fridge but wash it first", []),
        ("put the apple in the fridge and the mug in the fridge first", ["first"]),  # an order of its own
    ]:
        assert [u.words for u in unordered_steps(tokens(text), set(), parse)] == unread


@pytest.mark.data
def test_a_keep_in_place_wish_is_a_ban_on_moving_the_thing(living_room):
    text = "put the watch on the sofa, the keys stay on the table"
    got, _, unread, forbids = full_reading(text, living_room)
    assert (got, unread) == (["place Watch -> Sofa"], [])
    assert forbids == ["don't move the keys: forbids pickup(KeyChain)"]  # main: a placing of the keys


def test_where_a_thing_stays_is_read_only_after_its_name_at_a_clause_start():
    assert unmoved_said("Put the plate away, but the pot remains on the stove.") == (
        "Put the plate away, but don't move the pot."
    )
    assert unmoved_said("Put the watch on the sofa and make sure the vase stays on the table.") == (
        "Put the watch on the sofa and don't move the vase."
    )
    # "leave it on the counter" says where it goes: a placing, untouched
    assert unmoved_said("Put the mug in the sink and leave it on the counter.") == (
        "Put the mug in the sink and leave it on the counter."
    )


@pytest.mark.parametrize(
    "text, unread",
    [
        ("put the pen in the box, then take the pen out", ["take the pen out"]),
        ("put a spoon in the mug and pull the spoon back out of it", ["pull the spoon back out of it"]),
        # where the thing comes from, before a task moves it on
        ("take the apple out of the fridge and put it on the counter", []),
        ("take out the apple from the fridge and place it on the counter", []),
    ],
)
def test_a_thing_taken_out_and_left_so_is_unread(text, unread):
    from nl2hltl2plan.language.grounding import find_mentions

    apple = BaseTaskSpec(id="A", kind="place", object=["Apple"], receptacle=["CounterTop"])
    pen = BaseTaskSpec(id="A", kind="place", object=["Pen"], receptacle=["Box"])
    spoon = BaseTaskSpec(id="A", kind="place", object=["Spoon"], receptacle=["Mug"])
    parse = ParseUsage([apple, pen, spoon], [], [], [])
    assert [u.words for u in taken_out(text, find_mentions(text), parse)] == unread


@pytest.mark.data
def test_a_removal_is_refused_by_name(living_room):
    why = refusal("put the pen in the box, then take the pen out", living_room)
    assert "'take the pen out' (action): a removal from a container" in why  # main: exit 0, place Pen -> Box


@pytest.mark.data
@pytest.mark.parametrize(
    "text, task",
    [
        ("put the bowl the mug is in on the counter", "place Bowl -> CounterTop"),  # main: partial ('mug')
        ("put the apple that the mug is next to in the fridge", "place Apple -> Fridge"),
        ("put the apple in the bowl the mug is next to", "place Apple -> Bowl"),
    ],
)
def test_a_relative_clause_names_a_landmark_not_a_task(kitchen, text, task):
    assert full_reading(text, kitchen)[:3] == ([task], [], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, forbids",
    [
        # main: forbids put(Apple,*) (h227's KNOWN_WRONG line)
        ("put the egg in the fridge don't put the apple in it", "put(Apple,Fridge)"),
        ("put the apple in the fridge, don't slice it", "slice(Apple)"),  # main: refused
        ("put the apple in the fridge but don't heat it", "heat(Apple)"),  # main: partial
    ],
)
def test_a_negations_it_forbids_only_what_it_names(kitchen, text, forbids):
    _, _, unread, said = full_reading(text, kitchen)
    assert unread == [] and len(said) == 1 and said[0].endswith(f"forbids {forbids}")


@pytest.mark.data
def test_a_negated_it_that_may_be_the_place_stays_refused(kitchen):
    assert refusal("put the apple in the fridge, don't open it", kitchen)  # the fridge, or the apple?
