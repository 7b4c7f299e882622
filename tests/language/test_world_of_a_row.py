"""The world side of validation and referents (issue 28 item 4, session 23's review): a composed row's world
holds the objects of the ALFRED trials it was composed from, as a benchmark scenario's; "look at the CD in
the light" is the lamp, not the room's light switch; a plural counted before is those things; one list
of "another thing" words."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.grounding import Grounder
from nl2hltl2plan.language.learned.compose import TRAIN_STYLE, synthesise
from nl2hltl2plan.language.learned.data import Example
from nl2hltl2plan.language.learned.faithful import FaithfulExample, text_task
from nl2hltl2plan.language.referents import ANOTHER, INDEFINITE, check_referents
from nl2hltl2plan.language.restated_tasks import _wording
from nl2hltl2plan.language.state_tasks import light_condition, read_state_clause
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import scene_instances, translate

PILLOWS = "valid_unseen/pick_two_obj_and_place-Pillow-None-Sofa-219/trial_T20190907_163240_345855"


def _reading(text: str, world) -> list[str]:
    res = translate(text, world, "offline", build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks]


@pytest.mark.data
def test_a_composed_row_gets_the_world_of_its_trials_and_a_user_row_the_first_trial(shared_data):
    from nl2hltl2plan.suites.alfred.conversion import scenario_world

    composed = scenario_world({"scene": "FloorPlan219", "source_trials": [PILLOWS]})
    user = scenario_world({"scene": "FloorPlan219"})
    assert composed.source_trials == (PILLOWS,) and user.source_trials != (PILLOWS,)
    assert scene_instances(composed)["Pillow"] == 2 and scene_instances(user)["Pillow"] == 1
    text = "put two pillows on the sofa"
    assert _reading(text, composed) == ["place_two 2x Pillow -> Sofa"]
    with pytest.raises(HTTError, match="'two pillows': FloorPlan219 holds only 1 pillow"):
        translate(text, user, "offline", build=False, actions="none")


@pytest.mark.data
def test_a_rows_counts_are_its_worlds_without_building_it(shared_data):
    from nl2hltl2plan.suites.alfred.conversion import scenario_counts, scenario_world
    from nl2hltl2plan.worlds.floor_plans import alfred_data

    plans = alfred_data().by_floor_plan
    rows = [{"scene": "FloorPlan219", "source_trials": [PILLOWS]}, {"scene": "FloorPlan10"}]
    rows += [{"scene": fp, "source_trials": plans[fp][1:4]} for fp in ("FloorPlan10", "FloorPlan308")]
    for row in rows:
        assert scenario_counts(row) == scene_instances(scenario_world(row)), row


def _example(obj: str, rec: str, trial: str) -> FaithfulExample:
    e = Example(f"Put the {obj.lower()} in the {rec.lower()}.", trial, "valid_seen", "FloorPlan1", "place",
                obj, "", rec, "", False)  # fmt: skip
    task = text_task(e, {obj, rec})
    assert task is not None
    return FaithfulExample(e, task)


def test_a_synthesised_instruction_records_the_trials_it_composes_outside_its_fingerprint():
    pairs = [("Apple", "Fridge"), ("Mug", "Cabinet"), ("Tomato", "CounterTop"), ("Bowl", "Microwave")]
    items = [_example(obj, rec, f"t{i}") for i, (obj, rec) in enumerate(pairs)]
    trial_of = {it.task.object[0]: it.example.trial for it in items}
    made = synthesise(items, 12, TRAIN_STYLE, seed=3)
    assert made and any(len(s.trials) > 1 for s in made)
    for s in made:
        assert s.trials == [trial_of[t.object[0]] for t in s.tasks]
        assert "trials" not in repr(s)  # the structure model's data fingerprint reads reprs


@pytest.mark.parametrize(
    ("clause", "types", "light"),
    [
        ("Look at the CD in the light", {"CD", "DeskLamp", "LightSwitch"}, None),  # the lamp
        ("start by looking at the CD in the light", {"CD", "FloorLamp"}, None),
        ("Look at the CD in the light", {"CD", "LightSwitch"}, "on"),  # no lamp: the room's light
        ("examine the CD in a well lit room", {"CD", "DeskLamp", "LightSwitch"}, "on"),  # a room named
        ("put the CD on the desk in the light", {"CD", "Desk", "DeskLamp", "LightSwitch"}, "on"),
        ("look at the CD in the dark", {"CD", "DeskLamp", "LightSwitch"}, "off"),
    ],
)
def test_the_light_of_an_examine_clause_is_the_lamp_where_the_world_has_one(clause, types, light):
    head, condition = light_condition(clause, Grounder(types, "FloorPlan308"))
    assert (condition.state if condition else None) == light
    assert head == clause if light is None else head != clause


def test_turning_on_the_light_is_the_light_switch_where_the_world_has_one():
    task = read_state_clause("turn on the light", Grounder({"LightSwitch", "DeskLamp", "CD"}))
    assert task is not None and task.summary() == "set_state LightSwitch on"


@pytest.mark.data
def test_a_bedroom_without_a_light_switch_reads_the_lamp_and_names_what_it_lacks(shared_data):
    from nl2hltl2plan.worlds import load_world

    bedroom = load_world("FloorPlan308")
    assert "LightSwitch" not in bedroom.object_types() and "DeskLamp" in bedroom.object_types()
    assert _reading("Look at the CD in the light.", bedroom) == ["examine_in_light CD under DeskLamp"]
    with pytest.raises(WorldError, match="no light switch in FloorPlan308"):
        translate("put the CD on the desk in a well lit room", bedroom, build=False, actions="none")


def _forks(text: str) -> list[BaseTaskSpec]:
    fork = BaseTaskSpec(id="A", text=text, kind="place_two", object=["Fork"], receptacle=["Drawer"], count=2)
    return [fork]


@pytest.mark.parametrize(
    "text",
    ["put two forks in the drawer. once the forks are in, wash the mug", "put both forks in the drawer"],
)
def test_a_plural_counted_before_names_those_things(text):
    check_referents(text, _forks(text), [], {"Fork": 3, "Drawer": 2}, "FloorPlan11")


@pytest.mark.parametrize(
    "text",
    ["put the forks in the drawer", "put two of the forks in the drawer. then put the forks away"],
)
def test_a_plural_not_counted_before_is_still_refused(text):
    with pytest.raises(HTTError, match="'forks': FloorPlan11 has 3 of them"):
        check_referents(text, _forks(text), [], {"Fork": 3, "Drawer": 2}, "FloorPlan11")


def test_a_plural_counted_before_that_two_tasks_take_is_still_refused():
    text = "put two forks in the drawer, then put the forks on the table"
    second = _forks(text)[0].model_copy(update={"id": "B", "receptacle": ["DiningTable"]})
    with pytest.raises(HTTError, match="'forks': FloorPlan11 has 3 of them"):
        check_referents(text, [*_forks(text), second], [("A", "B")], {"Fork": 3}, "FloorPlan11")


def test_one_list_of_another_thing_words_for_both_rules():
    assert {"another", "other", "second", "next", "remaining"} <= ANOTHER and {"a", "some"} <= INDEFINITE
    assert _wording("put the remaining mug on the desk", {"Mug"}) == "another"
    assert _wording("put some mug on the desk", {"Mug"}) == "indefinite"
    # one thing moved twice, unless the later words name another one (the same list)
    first = BaseTaskSpec(id="A", text="put the kettle on the stove", kind="place", object=["Kettle"],
                         receptacle=["StoveBurner"])  # fmt: skip
    for said, refused in (("the kettle", True), ("the remaining kettle", False), ("a kettle", False)):
        update = {"id": "B", "text": f"put {said} in the sink", "receptacle": ["SinkBasin"]}
        later = first.model_copy(update=update)
        text = f"{first.text}. then {later.text}"
        if refused:
            with pytest.raises(HTTError, match="'the kettle' is one kettle put in two places"):
                check_referents(text, [first, later], [("A", "B")], {"Kettle": 3}, "FloorPlan11")
        else:
            check_referents(text, [first, later], [("A", "B")], {"Kettle": 3}, "FloorPlan11")
