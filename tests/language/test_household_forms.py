"""h115's household forms (issues 23 and 28): colon lists and topic questions, a step said first or last
among three, a treatment before a "respectively" list, and its user-style sets read with nothing wrong."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import reading

from nl2hltl2plan.language.household_forms import paired, topic_said, treated_lists


@pytest.fixture(scope="module")
def kitchen():
    from nl2hltl2plan.worlds import load_world

    return load_world("FloorPlan1")


MUG_SINK, APPLE_FRIDGE, EGG_SINK = "place Mug -> SinkBasin", "place Apple -> Fridge", "place Egg -> SinkBasin"


@pytest.mark.parametrize(
    "text, said",
    [
        ("mug: sink; apple: fridge", "mug -> sink, apple -> fridge"),
        ("the mug: the sink, then the apple: the fridge", "the mug -> the sink, then the apple -> the fridge"),
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
    assert treated_lists(text) == "put the washed mug and a washed plate in the sink and the cabinet, respectively"
    assert treated_lists("wash the mug and put them in the sink respectively").startswith("wash")  # one thing


@pytest.mark.data
def test_the_household_reader_reads_the_forms(kitchen):
    assert reading("mug: sink; apple: fridge", kitchen) == ([MUG_SINK, APPLE_FRIDGE], [])
    assert reading("The mug? Heat it and put it in the sink.", kitchen) == (["heat_place Mug -> SinkBasin"], [])
    text = "rinse the mug and the apple and put them in the sink and the fridge respectively"
    assert reading(text, kitchen) == (["clean_place Mug -> SinkBasin", "clean_place Apple -> Fridge"], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "said, tasks, before",
    [
        ("Do step 3 first.", [EGG_SINK, MUG_SINK, APPLE_FRIDGE], [("A", "B"), ("A", "C")]),
        ("Step 1 comes last.", [APPLE_FRIDGE, EGG_SINK, MUG_SINK], [("A", "C"), ("B", "C")]),
    ],
)
def test_a_step_said_first_or_last_among_three(kitchen, said, tasks, before):
    """One of three numbered steps said first (last): before (after) both others, which stay unordered, as
    "put A, B and C, but C first" reads."""
    text = f"1. put the mug in the sink. 2. put the apple in the fridge. 3. put the egg in the sink. {said}"
    assert reading(text, kitchen) == (tasks, before)


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h115dev", "users_h115held"])
def test_the_h115_user_set_reads_nothing_wrong(name):
    """h115's user-style set, read as `plan` reads it: no line is read wrong."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [trust_sets.outcome(gt) for gt in trust_sets.load(name)]
    assert [why for what, why in outcomes if what == "wrong"] == []
