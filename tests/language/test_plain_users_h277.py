"""Issue 28/23 (h277), users_h271's classes in plain user voice. "A, before that B" with no "but" (W3): the
step said second comes first; before, ", before that" / "; before you do that" / "- before that" was read as a
following "then" (A before B) at exit 0. A treatment said as a noun (C3): "give the kettle a rinse" is "rinse
the kettle"; before, refused. A thing's place said as a sentence, then "it" (C2): "my mug is by the sink, can
u heat it ..." takes the mug from there; before, refused."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

MUG_SINK, EGG_FRIDGE = "place Mug -> SinkBasin", "place Egg -> Fridge"


@pytest.mark.parametrize(
    "text",
    [
        "put the mug in the sink, before that put the egg in the fridge",
        "put the mug in the sink; before you do that put the egg in the fridge",
        "put the mug in the sink - before that tho put the egg in the fridge",
        "put the mug in the sink. oh and before that pls put the egg in the fridge",
    ],
)
def test_the_step_after_before_that_comes_first(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == [EGG_FRIDGE, MUG_SINK] and order == {(EGG_FRIDGE, MUG_SINK)} and not unread


def test_before_that_as_a_determiner_is_no_order_marker():
    """"before that mug ..." opens no step: the rule leaves it to the reading (no order of its own)."""
    _, order, _ = read("put the mug in the sink, before that mug gets dirty")
    assert order == set()


@pytest.mark.parametrize(
    "text, task",
    [
        ("give the mug a rinse and put it in the sink", "clean_place Mug -> SinkBasin"),
        ("give the apple a good chill and put it in the sink", "cool_place Apple -> SinkBasin"),
        (
            "cut a tomato, give one slice a quick warm up and put it in the fridge",
            "heat_place Tomato(sliced) -> Fridge",
        ),
    ],
)
def test_a_treatment_said_as_a_noun_is_its_verb(text, task):
    tasks, _, unread = read(text)
    assert tasks == [task] and not unread


def test_give_with_no_treatment_noun_or_no_thing_is_left_as_it_was():
    """"give the kid a wash" names no thing of the scene: not read as a washing task (nothing to wash)."""
    tasks, _, _ = read("give the kid a wash and put the mug in the sink")
    assert not any(t.startswith("clean_place") for t in tasks)


@pytest.mark.parametrize(
    "text, task",
    [
        ("my apple is on the counter, can you put it in the fridge", "place Apple -> Fridge"),
        ("there's a mug by the sink. heat it and put it on the table", "heat_place Mug -> DiningTable"),
        ("there are two spoons in the sink, put them in a drawer", "place_two 2x Spoon -> Drawer"),
    ],
)
def test_a_place_said_first_is_where_the_thing_is(text, task):
    """The third was clean_place at exit 0 before (the sink it is in read as its washing)."""
    tasks, _, unread = read(text)
    assert tasks == [task] and not unread


def test_a_place_said_of_the_holder_is_left_to_the_grammar():
    """"it" after "in" is the fridge, not a thing taken from the left: no rewrite, the clause stays unread."""
    _, _, unread = read("the fridge is on the left, put the apple in it")
    assert unread == ["the fridge is on the left"]
