"""Issue 23, the lead's probes of session 14: a correction said in passing, a verb that also names a thing
and an action no base task does were read as plain placings and reported solved. Each is now refused,
naming the words, next to a near miss that keeps its right reading."""

from __future__ import annotations

import pytest
from household_readings import shared_world

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.world import World

pytestmark = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")
BOTH = pytest.mark.parametrize("backend", ["offline", "grammar"])


def _world(name: str) -> World:
    return shared_world(name)


def _summaries(text: str, world: str, backend: str) -> list[str]:
    res = translate(text, _world(world), backend)
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks]


def _refused(text: str, world: str, backend: str) -> str:
    """The refusal's message: an input error, or the words a partial parse did not read."""
    try:
        res = translate(text, _world(world), backend)
    except HTTError as exc:
        return str(exc)
    assert res.partial, [t.summary() for t in res.tasks]
    return "; ".join(res.unparsed)


# "in the fridge, I mean the microwave" was a chilled apple put in the microwave: the correction is read
# (the apple goes in the microwave) or refused, never a reading that still uses the fridge
@BOTH
@pytest.mark.parametrize("marker", ["I mean", "actually", "or rather", "sorry,"])
def test_a_correction_in_passing_is_followed_or_refused(backend, marker):
    text = f"put the apple in the fridge, {marker} the microwave"
    try:
        res = translate(text, _world("FloorPlan4"), backend)
    except HTTError:
        return
    assert res.partial or [t.summary() for t in res.tasks] == ["place Apple -> Microwave"]


# ("Actually, ... too" opening a sentence adds: `self_corrections` drops the word; the session-28 retrain left
# it unread, a false partial, which the learned stage had read before)
@pytest.mark.parametrize("backend", ["offline"])
def test_what_a_correction_word_does_not_take_back_stays_read(backend):
    text = "put the bread in the fridge. Actually, put the egg in the fridge too"
    assert _summaries(text, "FloorPlan4", backend) == [
        "place Bread -> Fridge",
        "place Egg -> Fridge",
    ]
    assert _summaries("sorry, could you put the bread in the fridge", "FloorPlan4", backend) == [
        "place Bread -> Fridge"
    ]


# the lead's user set 9 (session 16): "put the book on the desk lamp... sorry, look at the book under the desk
# lamp" was two examinations, reported solved: an own mistake that opens its sentence takes back the sentence
# before, so a reading that still does it is refused; an apology that opens the text takes nothing back
@BOTH
@pytest.mark.parametrize("marker", ["... sorry,", ". Oops,", ". Sorry,"])
def test_an_own_mistake_opening_a_sentence_takes_back_the_one_before(backend, marker):
    text = f"put the book on the bed{marker} put the book in the box"
    assert "correction" in _refused(text, "FloorPlan317", backend)
    if backend == "offline":  # (the grammar alone leaves a leading remark unread, as above)
        assert _summaries("sorry, put the book in the box", "FloorPlan317", backend) == ["place Book -> Box"]


# "spray the counter" was the spray bottle put on the counter
@BOTH
def test_a_verb_that_also_names_a_thing_is_a_verb_where_a_command_starts(backend):
    why = _refused("spray the counter and put the spray bottle in a cabinet", "FloorPlan402", backend)
    assert "spray" in why
    assert _summaries("put the spray on the counter", "FloorPlan402", backend) == [
        "place SprayBottle -> CounterTop"
    ]


# "and change the channel" was dropped
@BOTH
def test_changing_the_channel_is_no_base_task(backend):
    assert "change" in _refused("put the remote on the sofa and change the channel", "FloorPlan211", backend)


# "the spatula in a different drawer", "the pan on the other burner": places are type-level atoms, so
# the spec cannot keep two tasks to two drawers (or to one); "a drawer" twice stays read
@BOTH
@pytest.mark.parametrize(
    "text",
    [
        "put the ladle in a drawer and the spatula in a different drawer",
        "put the ladle in a drawer and the spatula in the same drawer",
        "put the pot on the stove and the pan on the other burner",
    ],
)
def test_another_or_the_same_instance_of_a_place_is_refused(backend, text):
    assert "two tasks take this type" in _refused(text, "FloorPlan4", backend)


# two tasks that pick a type up take two different things (the planner's leaves own what they pick up, the
# goal checker asks distinct things): "a different apple", "the other tomato" are read (h153)
@BOTH
def test_a_different_thing_of_two_tasks_is_read(backend):
    text = "put an apple in the fridge and a different apple in the sink"
    assert _summaries(text, "FloorPlan4", backend) == ["place Apple -> Fridge", "place Apple -> SinkBasin"]


@BOTH
def test_two_tasks_on_one_place_type_without_identity_words_stay_read(backend):
    assert _summaries("put the ladle in a drawer and the spatula in a drawer", "FloorPlan4", backend) == [
        "place Ladle -> Drawer",
        "place Spatula -> Drawer",
    ]


# "and then sit on it" was dropped
@BOTH
def test_sitting_is_no_base_task(backend):
    assert "sit" in _refused("put the newspaper on the sofa and then sit on it", "FloorPlan211", backend)


# "the same garbage can" where the scene has one: that one, whichever task comes first
@BOTH
def test_the_same_of_a_type_the_scene_holds_once_is_that_one(backend):
    text = "put the apple in the garbage can, then put the egg in the same garbage can"
    assert _summaries(text, "FloorPlan4", backend) == ["place Apple -> GarbageCan", "place Egg -> GarbageCan"]


def test_the_same_place_is_judged_against_the_scene():
    text = "put the ladle in a drawer and the spatula in the same drawer"
    tasks = [
        BaseTaskSpec(id="A", kind="place", object=["Ladle"], receptacle=["Drawer"]),
        BaseTaskSpec(id="B", kind="place", object=["Spatula"], receptacle=["Drawer"]),
    ]
    def same(instances: dict[str, int] | None) -> bool:
        return any(u.words == "the same" for u in account(text, tasks, [], instances))

    assert same({"Drawer": 6, "Ladle": 1, "Spatula": 2})
    assert not same({"Drawer": 1, "Ladle": 1, "Spatula": 2})
    assert not same(None)  # scene unknown: not judged


# "the towel ... and the hand towel ..." in two clauses was two HandTowels (exit 1: the scene has one)
@BOTH
def test_a_phrase_naming_the_type_keeps_it_across_clauses(backend):
    text = "put the towel on the towel holder and the hand towel on the hand towel holder"
    assert _summaries(text, "FloorPlan402", backend) == [
        "place Towel -> TowelHolder",
        "place HandTowel -> HandTowelHolder",
    ]


# "... and the bread on the counter after the apple is in the fridge" was a second apple put in the
# fridge (the reference read as a task); "after the egg is in the sink, and put the bread ..." ordered the
# bread before the apple (the reference ran on into the command: now a sentence of its own)
@BOTH
@pytest.mark.parametrize(
    "text",
    [
        "put the apple in the fridge after the egg is in the sink, and the bread on the counter after the"
        " apple is in the fridge",
        "put the apple in the fridge after the egg is in the sink, and put the bread on the counter",
    ],
)
def test_a_state_reference_is_no_task_and_ends_before_a_command(backend, text):
    try:
        res = translate(text, _world("FloorPlan1"), backend)
    except HTTError:
        return
    name = {t.id: t.summary() for t in res.tasks}
    order = {(name[a], name[b]) for a, b in res.before}
    three = ["place Apple -> Fridge", "place Bread -> CounterTop", "place Egg -> SinkBasin"]
    assert res.partial or (
        sorted(name.values()) == three and ("place Bread -> CounterTop", "place Apple -> Fridge") not in order
    ), (sorted(name.values()), order)


# "the second egg", "the left apple" were any egg, any apple
@BOTH
@pytest.mark.parametrize(
    "text",
    ["put the second egg in the fridge", "put the left apple in the sink", "put the top pot on the stove"],
)
def test_words_that_pick_one_of_several_things_are_refused(backend, text):
    assert "picks one of several" in _refused(text, "FloorPlan4", backend)


@BOTH
def test_a_place_picked_among_several_is_read_as_its_type(backend):
    text = "put the spoon in the second drawer"
    assert _summaries(text, "FloorPlan4", backend) == ["place Spoon -> Drawer"]
    assert _summaries("put the fork in the top drawer", "FloorPlan4", backend) == ["place Fork -> Drawer"]


@BOTH
@pytest.mark.parametrize(
    "text", ["put half the lettuce in the bowl", "put a quarter of the bread on the counter"]
)
def test_a_part_of_one_thing_is_refused(backend, text):
    # the lead's probes of session 25: "half the lettuce" moved a whole lettuce, exit 0
    assert "a part of one thing" in _refused(text, "FloorPlan2", backend)


@BOTH
def test_a_slice_of_one_thing_keeps_its_reading(backend):
    assert _summaries("put a slice of lettuce in the bowl", "FloorPlan2", backend) == [
        "place Lettuce(sliced) -> Bowl"
    ]


def test_a_place_named_only_after_under_is_refused():
    # the learned re-read filled "put the apple under the counter" as a placing on the counter, exit 0
    _refused("put the apple under the counter", "FloorPlan2", "offline")
    task = BaseTaskSpec(id="A", kind="place", object=["Apple"], receptacle=["CounterTop"])
    assert any("under another" in u.reason for u in account("put the apple under the counter", [task], []))
    assert not account("put the apple on the counter under the window", [task], [])


@BOTH
def test_a_mug_under_the_coffee_machine_is_placed_in_it(backend):
    text = "put the mug under the coffee machine"
    assert _summaries(text, "FloorPlan2", backend) == ["place Mug -> CoffeeMachine"]


@BOTH
def test_a_command_after_a_state_reference_is_a_sentence_of_its_own(backend):
    text = "put the apple in the fridge after the egg is in the sink, and put the bread on the counter"
    res = translate(text, _world("FloorPlan1"), backend)
    name = {t.id: t.summary() for t in res.tasks}
    assert not res.partial and {(name[a], name[b]) for a, b in res.before} == {
        ("place Egg -> SinkBasin", "place Apple -> Fridge")
    }


@BOTH
def test_zap_is_a_word_for_heating(backend):
    # the lead's user set 19: "zap the potato in the microwave" was refused, 'zap' unread
    text = "zap the potato in the microwave and then leave it on the counter"
    assert _summaries(text, "FloorPlan13", backend) == ["heat_place Potato -> CounterTop"]


def test_an_appliance_where_the_thing_ends_names_no_treatment():
    # h154's finding: the learned re-read read "put the apple in the fridge and stuff" as cooling, exit 0
    cooled = BaseTaskSpec(id="A", kind="cool_place", object=["Apple"], receptacle=["Fridge"])
    unread = account("put the apple in the fridge and stuff", [cooled], [])
    assert any("treatment is named nowhere" in u.reason for u in unread)
    via_fridge = BaseTaskSpec(id="A", kind="cool_place", object=["Apple"], receptacle=["CounterTop"])
    assert not account("put the apple in the fridge, then on the counter", [via_fridge], [])
