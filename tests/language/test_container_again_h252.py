"""h252 (issue 28): a container said as where a thing goes and then moved, in more shapes than "put X in
the C and the C on Y": the container with words before its name ("the grey bowl", "the frying pan"), after
"on" ("on a plate"), joined by ";" or a comma, said again by "that" or with its own verb ("the bowl goes in
the sink"), and "a spoon in a glass goes on the table" (a container named for the first time holds the
thing). Never where the second container is another one or the first place is a fixed receptacle."""

from __future__ import annotations

import pytest
from household_readings import outcome, reading

from nl2hltl2plan.language.grammar.sentence_joins import container_again, content_goes


@pytest.fixture(scope="module")
def kitchen():
    from nl2hltl2plan.worlds import load_world

    return load_world("FloorPlan26")


@pytest.mark.parametrize(
    "text, said",
    [
        (
            "put the spoon in the grey bowl, and the bowl goes in the sink",
            "put the spoon in the grey bowl and put the bowl in the sink",
        ),
        (
            "cut a potato and put a slice in the pan; the pan goes on the table",
            "cut a potato and put a slice in the pan and put the pan on the table",
        ),
        (
            "put a spoon in a glass, and that glass in the sink",
            "put a spoon in a glass and put the glass in the sink",
        ),
        # kept: a fixed place, another container, a head with no verb, a second thing ("another slice")
        ("put the tomato in the fridge and the pan in the sink",) * 2,
        ("put a spoon in a bowl and another bowl in the sink",) * 2,
        ("the sponge goes in the pot, and the pot goes on the table",) * 2,
        ("put another slice in a pan and the pan in the fridge",) * 2,
    ],
)
def test_a_container_said_again_is_moved_with_its_content(text, said):
    assert container_again(text) == said


@pytest.mark.parametrize(
    "text, said",
    [
        ("a spoon in a glass goes on the table", "put a spoon in a glass and put the glass on the table"),
        # a container named definitely, or a fixed place, says where the thing is now
        ("the spoon in the bowl goes in the sink",) * 2,
        ("a mug in a cabinet goes on the table",) * 2,
    ],
)
def test_a_thing_in_a_new_container_that_goes_somewhere_is_its_content(text, said):
    assert content_goes(text) == said


@pytest.mark.data
@pytest.mark.parametrize(
    "text, task",
    [
        (
            "A butter knife in a pan goes on the counter.",
            "place_in_container ButterKnife in Pan -> CounterTop",
        ),
        ("Spoon in a glass, and that glass in the sink.", "place_in_container Spoon in Cup -> SinkBasin"),
        (
            "Put the fork in the wooden bowl, and the bowl goes on the table.",
            "place_in_container Fork in Bowl -> DiningTable",
        ),
    ],
)
def test_the_shapes_read_one_task(kitchen, text, task):
    assert reading(text, kitchen) == ([task], [])


@pytest.mark.data
def test_a_pair_after_other_things_keeps_its_container(kitchen):
    """The verb carried over to a second pair, and a verbless list whose container has a colour."""
    text = (
        "put a spoon in a wine glass and the glass on the counter, "
        "and a fork in a bowl and the bowl in the sink"
    )
    assert reading(text, kitchen)[0] == [
        "place_in_container Spoon in Cup -> CounterTop",
        "place_in_container Fork in Bowl -> SinkBasin",
    ]
    text = "A tomato onto the table, and a fork in the wooden bowl with the bowl on the counter."
    assert reading(text, kitchen)[0][-1] == "place_in_container Fork in Bowl -> CounterTop"


@pytest.mark.data
def test_another_container_is_not_the_first_one(kitchen):
    assert outcome("Put a spoon in a bowl and put another bowl in the sink.", kitchen) != [
        "place_in_container Spoon in Bowl -> SinkBasin"
    ]
