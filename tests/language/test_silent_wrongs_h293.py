"""users_h284's three silent wrongs, as classes (h293, issue 23): a plural keeps its plural through a
respelling and through a wish said without its subject, and a plural a reading took as one thing is refused;
a mid-sentence "in that order" closes the clauses before it; "as well as" joins a thing to the task before it
(and a counted list of a container type is a list, not a container and its content); a colour or "N of the" in
a verbless list. Floor plans' default worlds, through the public reading path."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.referents import check_referents
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import scene_instances, translate
from nl2hltl2plan.suites.alfred.conversion import scenario_world

pytestmark = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def read(scene: str, text: str, plurals: str = "ask"):
    world = scenario_world({"scene": scene, "source_trials": []})
    return translate(text, world, "offline", build=False, actions="none", plurals=plurals)  # type: ignore[arg-type]


def said(res) -> list[tuple[str, str, int]]:
    return [(t.kind, t.object[0], t.count) for t in res.tasks]


def test_a_respelt_plural_is_asked_about_as_the_plural_is():
    # FloorPlan201 holds 3 remotes: "the remots" asks how many, as "the remotes" does
    for text in ["put the remots on the sofa", "need the remotes on the sofa"]:
        with pytest.raises(HTTError, match=r"^'remotes': FloorPlan201 has 3 of them"):
            read("FloorPlan201", text)
    two = read("FloorPlan201", "need the remotes on the sofa", "two")
    assert said(two) == [("place_two", "RemoteControl", 2)]


def test_a_plural_read_as_one_thing_by_any_reading_is_refused():
    held = scene_instances(scenario_world({"scene": "FloorPlan201", "source_trials": []}))
    one = [BaseTaskSpec(id="A", kind="place", object=["Pillow"], receptacle=["Sofa"])]
    with pytest.raises(HTTError, match=r"^'pillows': FloorPlan201 has 2 of them and the task would take 1"):
        check_referents("gotta have the pillows on the sofa", one, [], held, "FloorPlan201")
    assert check_referents("the pillows: put one on the sofa", one, [], held, "FloorPlan201") == []


def test_a_mid_sentence_in_that_order_orders_the_clauses_before_it():
    text = "put the box and a pillow on the bed in that order, and put a watch on the desk whenever"
    res = read("FloorPlan301", text)
    assert said(res) == [("place", "Box", 1), ("place", "Pillow", 1), ("place", "Watch", 1)]
    assert res.before == [("A", "B")] and not res.unparsed


def test_as_well_as_joins_a_thing_and_a_counted_list_stays_a_list():
    res = read("FloorPlan201", "Put a box on the coffee table, as well as a tissue box.")
    assert said(res) == [("place", "Box", 1), ("place", "TissueBox", 1)]
    res = read("FloorPlan201", "put two plates and two watches on the dining table")
    assert said(res) == [("place_two", "Plate", 2), ("place_two", "Watch", 2)]
    # one container and one thing is still ALFRED's pair: the watch in the bowl
    assert said(read("FloorPlan201", "put a bowl and a watch on the coffee table")) == [
        ("place_in_container", "Watch", 1)
    ]


def test_a_colour_in_a_verbless_list():
    res = read("FloorPlan413", "2 red cloths and 2 soaps on the toilet")
    assert said(res) == [("place_two", "Cloth", 2), ("place_two", "SoapBar", 2)]



def test_a_container_chain_inside_a_longer_list_is_one_task():
    # the chain as an item of a list, with its verb or without ("then a pen in a bowl and that one on P")
    text = "put a pen in a bowl and the bowl on the coffee table, and a watch on the sofa"
    res = read("FloorPlan201", text)
    assert said(res) == [("place_in_container", "Pen", 1), ("place", "Watch", 1)] and not res.unparsed
    text = (
        "put a watch on the sofa and a pillow on the armchair, then a pen in a bowl and that one on the sofa"
    )
    res = read("FloorPlan201", text)
    assert said(res) == [("place", "Watch", 1), ("place", "Pillow", 1), ("place_in_container", "Pen", 1)]
    assert res.before == [("A", "C"), ("B", "C")] and not res.unparsed


def test_a_treatment_said_as_an_adjective_of_a_reference():
    # "a rinsed one" after "two mugs"; "a warm slice" in a sentence after "slice a tomato"
    res = read("FloorPlan12", "put 2 mugs in the sink, and a rinsed one in there too")
    assert said(res) == [("place_two", "Mug", 2), ("clean_place", "Mug", 1)] and not res.unparsed
    res = read("FloorPlan12", "slice a tomato. put a warm slice on the counter, a cold slice in the sink")
    assert said(res) == [("heat_place", "Tomato", 1), ("cool_place", "Tomato", 1)]
    assert all(t.sliced for t in res.tasks) and not res.unparsed


def test_a_list_led_by_its_topic_or_by_counts_with_their_noun_left_out():
    res = read("FloorPlan201", "credit cards: two go on the sofa, and one on the armchair")
    assert said(res) == [("place_two", "CreditCard", 2), ("place", "CreditCard", 1)] and not res.unparsed
    res = read("FloorPlan201", "put two credit cards on the sofa, one on the armchair")
    assert said(res) == [("place_two", "CreditCard", 2), ("place", "CreditCard", 1)] and not res.unparsed


def test_references_between_tasks():
    # "wash one more and put it ...": another cloth, not the first one again; "when the rest is done": after
    # every task said before
    text = "rinse a mug and put it in the sink, then rinse one more and put it in the cabinet"
    res = read("FloorPlan12", text)
    assert said(res) == [("clean_place", "Mug", 1), ("clean_place", "Mug", 1)] and res.before == [("A", "B")]
    text = "put a watch on the sofa and a pen on the coffee table, and when the rest is done put a vase there"
    res = read("FloorPlan201", text)
    assert res.before == [("A", "C"), ("B", "C")] and not res.unparsed


def test_a_misspelt_plural_is_respelt_as_a_plural():
    # "sptulas" is near "spatula": respelt as the one name it would lose its count (FloorPlan5 holds 3)
    with pytest.raises(HTTError, match=r"^'spatulas': FloorPlan5 has 3 of them"):
        read("FloorPlan5", "put the sptulas in the drawer")
