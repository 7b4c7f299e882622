"""A statement that sets the scene or tells of an event beside a request is frame (issue 28, h279;
`frame_remarks`): "Tenant away until Monday.", "Photographer arrives at 3!" are dropped and said in the
assumptions; an order said of the tasks' labels and a statement that
asks for a treatment stay, to be read or refused by name. The dev set's lines (paper_h279dev.txt) are
measured by `scripts/trust_sets.py measure --sets paper_h279dev`."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import Nl2Hltl2PlanError

# the same request and reader as h244's frame tests, whose rule this one extends
from tests.language.test_household_frames_h244 import EGG, MUG, REQUEST, read


@pytest.mark.data
@pytest.mark.parametrize(
    "text, dropped",
    [
        (f"{REQUEST} Tenant away until Monday.", "Tenant away until Monday"),
        (f"{REQUEST} Photographer arrives at 3!", "Photographer arrives at 3"),
        (f"{REQUEST} Landlord inspects Friday.", "Landlord inspects Friday"),
    ],
)
def test_a_scene_or_event_statement_is_dropped_and_said(text: str, dropped: str) -> None:
    tasks, before, unparsed, assumptions = read(text)
    assert (tasks, before, unparsed) == ([EGG, MUG], [("A", "B")], [])
    assert any("dropped as frame" in a and repr(dropped) in a for a in assumptions), assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        f"{REQUEST} Everything needs washing.",  # a statement that asks for a treatment
        "Put the egg in the fridge. Put the mug in the sink. Step two goes first.",  # an order by label
        f"{REQUEST} Dishes are dirty.",  # a thing's state
    ],
)
def test_a_treatment_an_order_or_a_thing_is_never_a_remark(text: str) -> None:
    try:
        _, _, unparsed, assumptions = read(text)
    except Nl2Hltl2PlanError:
        return  # refused by name
    assert unparsed
    assert not any("dropped as frame" in a for a in assumptions), assumptions
