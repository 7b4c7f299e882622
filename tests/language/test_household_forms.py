"""h115's household forms (issues 23 and 28): colon lists and topic questions, a step said first or last
among three, a treatment before a "respectively" list, and its user-style sets read with nothing wrong."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import DRINK_FOOD, categories, shared_words
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS, VERBS
from nl2hltl2plan.language.household_forms import PARTICIPLES, paired, topic_said, treated_lists
from nl2hltl2plan.language.household_words import contents_hint, descriptive_names
from nl2hltl2plan.language.translate import translate


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


ON_COUNTER = "move the soap on the counter top to the toilet"  # a landmark, read as the counter too
MUG_SINK, APPLE_FRIDGE, EGG_SINK = "place Mug -> SinkBasin", "place Apple -> Fridge", "place Egg -> SinkBasin"


@pytest.mark.parametrize(
    "text, said",
    [
        ("mug: sink; apple: fridge", "mug -> sink, apple -> fridge"),
        ("the mug: the sink, then the egg: a pan", "the mug -> the sink, then the egg -> a pan"),
        ("Task: put the mug in the sink", "Task: put the mug in the sink"),  # a label, not a pair
        ("Note: the fridge", "Note: the fridge"),  # "note" names no thing
    ],
)
def test_colon_pairs_of_a_thing_and_a_place_become_arrows(text, said):
    assert paired(text) == said


@pytest.mark.parametrize(
    "text, said",
    [
        ("The mug? Heat it and put it in the sink.", "Heat the mug and put it in the sink."),
        ("what about the apple? put it in the fridge", "Put the apple in the fridge"),
        ("The mug or the cup? Put it in the sink.", "The mug or the cup? Put it in the sink."),  # two things
        ("Where is the mug? Put it away.", "Where is the mug? Put it away."),  # a question, not a topic
    ],
)
def test_a_topic_question_names_what_it_is(text, said):
    assert topic_said(text) == said


def test_a_treatment_before_a_respectively_list_goes_with_each_thing():
    text = "wash the mug and a plate, and then put them in the sink and the cabinet, respectively"
    said = "put the washed mug and a washed plate in the sink and the cabinet, respectively"
    assert treated_lists(text) == said
    assert treated_lists("wash the mug and put them in the sink respectively").startswith("wash")  # one thing


def test_the_treatments_participles_are_the_grammars():
    # one table: each verb's participle is the state word the grammar reads as that verb's treatment
    assert {"wash", "rinse", "scrub", "heat", "microwave", "chill", "slice", "cut"} <= set(PARTICIPLES)
    assert all(STATE_WORDS[done] == VERBS[verb][0] for verb, done in PARTICIPLES.items())
    text = "toast the bread and the potato and put them in the fridge and the sink respectively"
    said = "put the toasted bread and the toasted potato in the fridge and the sink respectively"
    assert treated_lists(text) == said


@pytest.mark.data
def test_the_household_reader_reads_the_forms(kitchen):
    assert reading("mug: sink; apple: fridge", kitchen) == ([MUG_SINK, APPLE_FRIDGE], [])
    heated = ["heat_place Mug -> SinkBasin"]
    assert reading("The mug? Heat it and put it in the sink.", kitchen) == (heated, [])
    text = "rinse the mug and the apple and put them in the sink and the fridge respectively"
    assert reading(text, kitchen) == (["clean_place Mug -> SinkBasin", "clean_place Apple -> Fridge"], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "said, tasks, before",
    [
        ("Do step 3 first.", [EGG_SINK, MUG_SINK, APPLE_FRIDGE], [("A", "B"), ("B", "C")]),
        ("Step 1 comes last.", [APPLE_FRIDGE, EGG_SINK, MUG_SINK], [("A", "B"), ("B", "C")]),
    ],
)
def test_a_step_said_first_or_last_among_three(kitchen, said, tasks, before):
    """One of three numbered steps said first (last): the others after (before) it in their numbered turn."""
    text = f"1. put the mug in the sink. 2. put the apple in the fridge. 3. put the egg in the sink. {said}"
    assert reading(text, kitchen) == (tasks, before)


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "Step 1: put the mug in the sink. Step 2: put the apple in the fridge.",
        "Step one: put the mug in the sink. Step two: put the apple in the fridge.",  # "two" is no count
        "1. put the mug in the sink 2. put the apple in the fridge",
        "put the mug in the sink. Step 2: put the apple in the fridge.",  # an unnumbered first step
        "Hi, put the mug in the sink. Step two: put the apple in the fridge.",
    ],
)
def test_steps_numbered_in_turn_are_a_sequence(kitchen, text):
    """A recipe numbered in turn with no order said: the steps in their numbered turn, one thing each."""
    assert reading(text, kitchen) == ([MUG_SINK, APPLE_FRIDGE], [("A", "B")])


@pytest.mark.data
def test_numbered_steps_with_a_free_order_remark_order_nothing(kitchen):
    text = "Step one: put the mug in the sink. Step two: put the apple in the fridge. Any order is fine."
    assert reading(text, kitchen) == ([MUG_SINK, APPLE_FRIDGE], [])


@pytest.mark.data
def test_a_free_order_remark_inside_a_step_frees_that_step_only(kitchen):
    text = "Put the mug in the sink. Step two: put the apple and the egg in the fridge in any order."
    tasks = [MUG_SINK, APPLE_FRIDGE, "place Egg -> Fridge"]
    assert reading(text, kitchen) == (tasks, [("A", "B"), ("A", "C")])


@pytest.mark.data
def test_steps_numbered_out_of_turn_are_refused(kitchen):
    with pytest.raises(HTTError, match="out of turn"):
        translate("Step 2: put the mug in the sink. Step 1: put the apple in the fridge.", kitchen)


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h115dev", "users_h115held"])
def test_the_h115_user_set_reads_nothing_wrong(name):
    """h115's user-style set, read as `plan` reads it: no line is read wrong."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [trust_sets.outcome(gt) for gt in trust_sets.load(name)]
    assert [why for what, why in outcomes if what == "wrong"] == []


@pytest.mark.parametrize(
    "text, types, said",
    [
        ("put the apple on the island", {"DiningTable", "CounterTop"}, "put the apple on the dining table"),
        ("put the apple on the island", {"CounterTop"}, "put the apple on the counter top"),
        ("put it on the kitchen island", {"DiningTable", "CounterTop"}, "put it on the dining table"),
        ("put it on the tv stand", {"TVStand", "Dresser"}, "put it on the tv stand"),
        ("put it on the tv stand", {"Dresser", "CoffeeTable"}, "put it on the dresser"),
        ("put it on the tv stand", {"CoffeeTable"}, "put it on the tv stand"),  # refused: no TVStand
        ("put the cd on the nightstand", {"Dresser"}, "put the cd on the dresser"),
        ("put the cd on the nightstand", {"SideTable", "Dresser"}, "put the cd on the side table"),
        ("put the keys on the entertainment center", {"Dresser"}, "put the keys on the dresser"),
        ("put the keys on the entertainment center", {"Shelf"}, "put the keys on the entertainment center"),
        ("move the soap on the vanity to the toilet", {"Cabinet", "Drawer", "CounterTop"}, ON_COUNTER),
        ("put the candle in the vanity", {"Drawer", "CounterTop"}, "put the candle in the drawer"),
    ],
)
def test_a_descriptive_name_is_the_type_alfred_uses_it_for(text, types, said):
    assert descriptive_names(text, types) == said


def test_a_descriptive_name_of_two_types_the_floor_plan_has_is_refused():
    with pytest.raises(HTTError, match="'vanity' could be the Cabinet or the Drawer"):
        descriptive_names("put the candle in the vanity", {"Cabinet", "Drawer", "CounterTop"})


@pytest.mark.data
@pytest.mark.parametrize(
    "text, drink",
    [
        ("heat a cup of coffee and put it in the cabinet", "coffee"),
        ("put a bowl of soup in the fridge", "soup"),
    ],
)
def test_a_drink_or_food_is_named_by_check_1_never_read_away(text, drink, kitchen):
    # a plan that heats the cup cannot check that it holds coffee (issue 23's "heat a cup of coffee")
    res = translate(text, kitchen, build=False, actions="none")
    assert res.partial and any(u.startswith(repr(drink)) for u in res.unparsed), res.unparsed
    with pytest.raises(HTTError, match="no floor plan has coffee apart from its container"):
        translate("heat up some coffee and put it in the cabinet", kitchen, build=False, actions="none")


@pytest.mark.parametrize("said", sorted(shared_words(DRINK_FOOD)))
def test_one_list_of_drinks_and_food_for_check_1_and_the_refusal(said):
    drink = said.replace("_", " ")  # "hot_chocolate": a phrase
    assert "noun_unsupported" in categories(drink.split()[-1])
    assert contents_hint(f"heat a mug of {drink.upper()}") == (
        f"no floor plan has {drink} apart from its container: to act on the container, name it alone"
    )


@pytest.mark.data
def test_a_greeting_before_when_you_are_done_changes_nothing(kitchen):
    """ "when you're done" with nothing before it waits on no task of the instruction; after a task it
    orders the next one after it, and a greeting before it is no step of its own either way (the grammar
    read "hey, when you're done, A and B" as B after "hey", and check 1 named both words)."""
    for opener in ("", "hey, ", "Hi! "):
        text = f"{opener}when you're done, put the apple in the fridge"
        assert reading(text, kitchen) == ([APPLE_FRIDGE], [])
        text = f"{opener}when you're done, put the apple in the fridge and the mug in the sink"
        assert reading(text, kitchen) == ([APPLE_FRIDGE, MUG_SINK], [])  # the greeting is no step before
        text = f"put the mug in the sink. {opener}once that's done, put the apple in the fridge"
        assert reading(text, kitchen) == ([MUG_SINK, APPLE_FRIDGE], [("A", "B")])



def _placed(task: str, thing: str, place: str, count: int = 1) -> dict:
    kind = "place_two" if count == 2 else "place"
    return {"id": task, "text": "", "kind": kind, "object": [thing], "count": count, "sliced": False,
            "container": None, "receptacle": [place], "light": None}  # fmt: skip


@pytest.mark.data
def test_the_failure_measure_reads_as_plan_does():
    """scripts/language_failures.py measures the shipped reading (the household reader's forms, the floor
    plan's counts); `--reader grammar` keeps the earlier measure of the text as written."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    from language_failures import WORLD, classify

    placed = [_placed("A", "Mug", "SinkBasin"), _placed("B", "Apple", "Fridge")]
    pairs = {"id": "trust.t.1", "scene": "FloorPlan1", "instruction": "mug: sink; apple: fridge",
             "tasks": placed, "before": []}  # fmt: skip
    assert classify(pairs) == ("ok", "", "mug -> sink, apple -> fridge")
    assert classify(pairs, "grammar")[0] == "refused, reading wrong"
    pillows = {"id": "g.1", "scene": "FloorPlan219", "instruction": "put two pillows on the sofa",
               "tasks": [_placed("A", "Pillow", "Sofa", 2)], "before": []}  # fmt: skip
    assert classify(pillows)[:2] == (WORLD, "'two pillows': FloorPlan219 holds only 1 pillow")
    assert classify(pillows, "grammar")[0] == "ok"  # a generator row: judged without the floor plan's counts
