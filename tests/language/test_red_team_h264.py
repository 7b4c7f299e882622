"""Issue 23 (h264, red team of session 32's household rules): a treatment said in the passive with what
tells that its state is already so or someone else's job ("should be washed already", "gets washed by
someone else", `states_said.txt`) is no duty for the robots, and a cut said only as the state a thing ends
in ("..., halved") is a slicing word that the reading must use or refuse, never frame dropped at exit 0; a
wait on a thing that only the clause's own task names as its place ("once the bed is sorted, put the pillow
on it") is unread, not dropped."""

from __future__ import annotations

import pytest
from household_readings import outcome

from nl2hltl2plan.language.grammar.treatments_said import treatments_said
from nl2hltl2plan.worlds import load_world


@pytest.mark.parametrize(
    "text",
    [
        "the cup should be washed already, so just put it in the cabinet",
        "the mug should be chilled by now",
        "the plate gets washed by someone else",
        "the tomato could be cooled down already",
    ],
)
def test_a_state_said_as_already_so_is_no_duty(text):
    assert treatments_said(text) == text


def test_the_same_passive_without_it_is_still_a_duty():
    assert treatments_said("the cup should be washed and put in the cabinet") == (
        "wash the cup and put it in the cabinet"
    )


@pytest.fixture(scope="module")
def kitchen():
    return load_world("FloorPlan7")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        ("The cup should be washed already, so just put it in the cabinet.", "refused"),  # was clean_place
        ("Put an apple in the fridge, halved.", "refused"),  # was place Apple, 'halved' dropped as frame
        ("The cup should be washed and put in the cabinet.", ["clean_place Cup -> Cabinet"]),
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert outcome(text, kitchen) == read


@pytest.mark.data
def test_a_wait_on_the_own_task_place_is_unread(kitchen):
    # "sorted" read as done (h254) about the task's own place, which no task moves: a wait, never dropped
    assert outcome("Once the table is sorted, put the apple on it.", kitchen) == "partial"
    own_thing = outcome("Once the apple is sorted, put it on the table.", kitchen)
    assert own_thing == ["place Apple -> DiningTable"]
