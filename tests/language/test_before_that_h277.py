"""Issue 28/23 (h277): "A, before that B" with no "but" in plain user voice (users_h271's W3). The step said
second comes first. Before, ", before that" / "; before you do that" / "- before that" was read as a following
"then" (A before B) at exit 0."""

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
    """"before that mug ..." opens no step: the rule leaves it to the reading as before (no order of its own)."""
    _, order, _ = read("put the mug in the sink, before that mug gets dirty")
    assert (EGG_FRIDGE, MUG_SINK) not in order and order == set()
