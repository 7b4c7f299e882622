"""h246 (issue 23): near misses of session 31's reference rules that were read at exit 0 with a request
dropped or a task invented (results/language/h246.md).

- A chore with no thing ("then clean up.", "wash up", "tidy up please") is named by check 1; "clean up" was
  accounted as tidying and dropped, "wash up" gave the thing before a washing.
- "do the same with X" after a sentence of two tasks (joined by a comma or a ';') repeats neither: the text
  does not say which; after a sentence of one task it repeats that task, as before.
- "the other" with no noun, after a sentence that names things of two types, is refused by name.
"""

from __future__ import annotations

import pytest
from household_readings import outcome, refusal


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, named",
    [
        ("Put the apple in the fridge, then clean up.", "'clean up' (action)"),  # main: place Apple only
        ("Put the apple in the fridge, then wash up.", "'wash up' (action)"),  # main: a washed apple
        ("Put the apple in the fridge. Tidy up after.", "'tidy up'"),
    ],
)
def test_a_chore_with_no_thing_is_named(text, named, kitchen):
    assert named in refusal(text, kitchen)


@pytest.mark.data
def test_clean_up_with_its_thing_is_left_to_the_readers(kitchen):
    assert "chore" not in refusal("Clean up the apple and put it in the fridge.", kitchen)


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        # the comma: partial on main in this world (the structure re-read repeats it in others); the ';':
        # main repeated the cup's task for the mug at exit 0
        "Heat an egg and put it on the counter, wash a cup and put it in a cabinet, then do the same with "
        "the mug.",
        "Heat an egg and put it on the counter; wash a cup and put it in a cabinet. Then do the same with "
        "the mug.",
    ],
)
def test_do_the_same_after_two_tasks_repeats_neither(text, kitchen):
    assert outcome(text, kitchen) in ("partial", "refused")


@pytest.mark.data
def test_do_the_same_after_one_task_still_repeats_it(kitchen):
    text = "Heat an egg and put it on the counter. Wash a cup and put it in a cabinet. Then do the same with "
    text += "the mug."
    said = ["heat_place Egg -> CounterTop", "clean_place Cup -> Cabinet", "clean_place Mug -> Cabinet"]
    assert outcome(text, kitchen) == said


@pytest.mark.data
def test_the_other_after_two_kinds_of_thing_is_refused(kitchen):
    # main: place Plate -> SinkBasin at exit 0 ("the other" apple or plate?)
    assert outcome("Apple on a plate, plate on the counter. And the other in the sink.", kitchen) in (
        "partial",
        "refused",
    )
    said = ["place Mug -> SinkBasin", "place Mug -> CounterTop"]
    assert outcome("Put a mug in the sink and the other on the counter.", kitchen) == said
