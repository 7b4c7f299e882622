"""h159 (issue 28, paper-style): a treatment said in one sentence and where the treated thing goes said in
the next ("Heat the egg in the microwave. Then put it in the fridge.") is one task, as with a comma."""

from __future__ import annotations

import pytest
from household_readings import reading

from nl2hltl2plan.language.grammar.sentence_joins import joined_treatments


@pytest.mark.parametrize(
    "text, said",
    [
        ("Heat the egg. Then put it in the fridge.", "Heat the egg, then put it in the fridge."),
        ("Wash the mug. Put it in the cabinet.", "Wash the mug, then put it in the cabinet."),
        (
            "Grab the egg and heat it up; when it's warm, put it in the fridge.",
            "Grab the egg and heat it up, then put it in the fridge.",
        ),
        # near misses, kept as written: the first sentence places something, negates, or is a condition;
        # the second places no "it"
        ("Put the apple in the fridge. Then put it in the microwave.",) * 2,
        ("Do not heat the egg. Put it in the fridge.",) * 2,
        ("If it is dirty, wash the mug. Put it in the cabinet.",) * 2,
        ("Heat the egg. Then put the mug in the sink.",) * 2,
    ],
)
def test_a_treatment_and_the_placing_of_it_are_joined(text, said):
    assert joined_treatments(text) == said


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan17")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks, before",
    [
        # each read before as the treatment alone, the placing of "it" unread (partial)
        ("Heat the egg in the microwave. Then put it in the fridge.", ["heat_place Egg -> Fridge"], []),
        (
            "Grab the egg from the sink and heat it up in the microwave; when it's warm, put it in the "
            "fridge.",
            ["heat_place Egg -> Fridge"],
            [],
        ),
        (
            "Chill the tomato. Put it in the microwave. Then put the mug in the sink.",
            ["cool_place Tomato -> Microwave", "place Mug -> SinkBasin"],
            [("A", "B")],
        ),
    ],
)
def test_the_joined_sentences_read_one_task(kitchen, text, tasks, before):
    assert reading(text, kitchen) == (tasks, before)
