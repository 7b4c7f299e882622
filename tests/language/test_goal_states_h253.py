"""Issue 28 (h253): goals said as the state a thing should end in. A need with the place said after it
("the cup wants chilling and then goes on the table", "... too, then back on the white table"), a verbless
list of treated slices ("a hot apple slice in the fridge and a cold slice of lettuce on the counter") under a
heading that says a list of goals ("What I need: ..."), and a sentence that only slices things whose slices
the later text names ("Slice the bread and the lettuce. ... a cold slice of the bread ..."), which a sliced
task includes. A need with neither "then" nor "goes", or a slicing whose slice is never named again, stays."""

from __future__ import annotations

import pytest
from household_readings import outcome

from nl2hltl2plan.language.grammar.treatments_said import treatments_said


@pytest.mark.parametrize(
    "text, rewritten",
    [
        ("The cup wants chilling and then goes on the table.", "chill The cup and put it on the table."),
        ("The loaf of bread wants chilling too, then back on the white table.",
         "chill The loaf of bread too and put it back on the white table."),
        ("The bowl needs a rinse and goes in the microwave.", "rinse The bowl and put it in the microwave."),
        ("Slice the bread and the lettuce. A cold slice of the bread goes on the table, and a lettuce slice "
         "in the sink.",
         "A cold slice of the bread goes on the table, and a lettuce slice in the sink."),
    ],
)  # fmt: skip
def test_a_goal_state_is_written_as_its_steps(text, rewritten):
    assert treatments_said(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "Slice the bread and the lettuce. Put a slice of bread in the fridge.",  # the lettuce's slice: never
        "Slice a potato. A hot slice goes in the sink.",  # the potato is not named again
    ],
)
def test_a_slicing_whose_slices_are_not_named_again_stays(text):
    assert treatments_said(text) == text


def test_a_need_with_no_then_or_goes_names_no_place():
    assert treatments_said("The mug needs washing and in the sink.") == "wash The mug and in the sink."


@pytest.fixture(scope="module")
def kitchen():
    from nl2hltl2plan.worlds import load_world

    return load_world("FloorPlan27")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        ("A hot apple slice in the fridge and a cold slice of lettuce on the counter.",
         ["heat_place Apple(sliced) -> Fridge", "cool_place Lettuce(sliced) -> CounterTop"]),
        ("What I need: a warm apple slice in the fridge, a chilled apple on the counter, and a washed "
         "potato in the sink.",
         ["heat_place Apple(sliced) -> Fridge", "cool_place Apple -> CounterTop",
          "clean_place Potato -> SinkBasin"]),
        ("Slice an apple and a tomato. A heated slice of the apple goes in the fridge, and a chilled slice "
         "of the tomato goes on the counter.",
         ["heat_place Apple(sliced) -> Fridge", "cool_place Tomato(sliced) -> CounterTop"]),
        ("The tomato wants chilling and then goes in the microwave.", ["cool_place Tomato -> Microwave"]),
        # "toast" names bread too: a verb and its slice, no verbless list of two things (paper_h178)
        ("Whenever you want, toast a slice of bread in the microwave and put it on the counter.",
         ["heat_place Bread(sliced) -> CounterTop"]),
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert outcome(text, kitchen) == read


@pytest.mark.data
def test_a_state_no_task_makes_is_not_read_as_a_placement(kitchen):
    """ "a broken egg": no task breaks an egg into a place; the list is refused, never read without it."""
    assert outcome("A broken egg in the fridge and a warm apple slice on the counter.", kitchen) == "refused"


@pytest.mark.parametrize(
    "text, tasks",
    [
        # a slice said as the subject of "goes" after a sentence with "take ... to": before, that sentence's
        # verb and place were carried over it and the slice went to the counter at exit 0
        ("Take the pan to the counter. A potato slice goes in the fridge.",
         ["place Pan -> CounterTop", "place Potato(sliced) -> Fridge"]),
        ("Put the butter knife in a pan and take the pan to the counter. A heated potato slice goes in the "
         "fridge afterwards.",
         ["place_in_container ButterKnife in Pan -> CounterTop", "heat_place Potato(sliced) -> Fridge"]),
    ],
)  # fmt: skip
def test_a_slice_said_as_the_subject_goes_where_it_is_said(text, tasks, world):
    from household_readings import reading

    assert reading(text, world("FloorPlan1"))[0] == tasks
