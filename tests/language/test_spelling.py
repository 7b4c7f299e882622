"""Misspelt names of things (language/spelling.py): read as the lexicon's words by the grammar, and never
passed over by check 1; real English words that look like names stay as they are."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.spelling import respelt, spelt_name, spelt_word
from nl2hltl2plan.language.task_specs import BaseTaskSpec

KITCHEN = {"Tomato", "Bread", "Mug", "Kettle", "Lettuce", "Fridge", "CounterTop", "SinkBasin", "StoveBurner"}


@pytest.mark.parametrize(
    "word, name",
    [
        ("tomatoe", "tomato"),  # a letter too many
        ("microwve", "microwave"),  # a letter left out
        ("cabnet", "cabinet"),
        ("kettel", "kettle"),  # two neighbours swapped
        ("Frige", "fridge"),
        # English words close to a name are what they say: "ridge" is not the fridge
        ("ridge", None),
        ("dressed", None),
        ("status", None),
        ("garage", None),
        ("fridge", None),  # a name the lexicon knows
        ("tomatoes", None),  # and its plural
        ("lapdog", None),  # close to no name
    ],
)
def test_a_misspelt_name_is_the_closest_name_unless_english_knows_the_word(word, name):
    assert spelt_name(word) == name


def test_respelt_keeps_the_capital_and_the_rest_of_the_text():
    assert respelt("Put the Tomatoe in the coffe machine, then wash it") == (
        "Put the Tomato in the coffee machine, then wash it"
    )


@pytest.mark.parametrize(
    "text, tasks",
    [
        # the misspelt object once hid the first task: the whole sentence was read as "chill the bread"
        (
            "put the tomatoe in the fridge and then the bread on the counter",
            ["place Tomato -> Fridge", "place Bread -> CounterTop"],
        ),
        (
            "put the bread in the fridge and then the tomatoe on the counter",
            ["place Bread -> Fridge", "place Tomato -> CounterTop"],
        ),
        (
            "put the kettel on the stove and then the mug in the sink",
            ["place Kettle -> StoveBurner", "place Mug -> SinkBasin"],
        ),
    ],
)
def test_the_grammar_reads_a_misspelt_object_in_a_list_of_tasks(text, tasks):
    r = parse_instruction(text, KITCHEN, "kitchen")
    assert ([t.summary() for t in r.tasks], r.before, r.unparsed) == (tasks, [("A", "B")], [])


def test_check_one_names_a_misspelt_object_that_the_reading_leaves_out():
    chill_bread = BaseTaskSpec(
        id="A", kind="cool_place", object=["Bread"], receptacle=["CounterTop"]
    )  # what a re-read of the whole sentence once returned
    text = "put the tomatoe in the fridge and then the bread on the counter"
    assert "tomato" in [u.words for u in account(text, [chill_bread], [])]


@pytest.mark.parametrize(
    "word, english",
    [
        ("woould", "would"),
        ("cleean", "clean"),
        ("slcie", "slice"),  # two neighbours swapped
        ("alriight", "alright"),
        ("finsihed", None),  # "finished", "finessed": two words one edit away
        # an order word only where no other English word is one edit away (users_h128dev.txt)
        ("firrst", "first"),
        ("befoer", "before"),
        ("frst", None),  # "first", "fist"
        ("thne", "then"),  # "then", "the", "thee": "then" is the one two neighbours swapped make
        ("firsst", "first"),  # "first", "firsts": "first" is the one a letter typed twice makes
        ("firt", None),  # "first", "fit", "fir", "dirt": no slip makes one of them alone
        ("colour", None),  # a British spelling is English
        ("wilco", None),  # a word of the project's own lists (the handover radio words)
        ("woud", None),  # one edit from several words: which is meant is a guess
        # ... unless exactly one of them is two neighbours swapped, the commonest slip ("clan", "caen")
        ("claen", "clean"),
        ("celan", "clean"),
        ("thorw", "throw"),
        ("clan", None),  # an English word stays
    ],
)
def test_another_misspelt_word_is_the_one_english_word_one_edit_away(word, english):
    assert spelt_word(word) == english


def test_a_contraction_is_no_misspelling():
    assert respelt("it doesn't matter, woould you") == "it doesn't matter, would you"


def test_a_four_letter_word_is_a_name_only_by_a_swap():
    assert [spelt_name(w) for w in ("lmap", "snik", "dsek")] == ["lamp", "sink", "desk"]
    assert spelt_name("plae") is None  # "place" or "plate": a letter left out of a short word is a guess
