"""h312 (issue 28): a tabletop stage's leave to pick which of its things goes first, closing its clause
("..., either one first.", "..., whichever goes first.", "..., whichever of the two you prefer to begin
with."), frees that stage's order: a later stage said as a wait on "those two" no longer takes its "first"
and leaves "either one" as a list of destinations (h286 plumber 4, left by h308). An aside ", and not
before," after a wait says that wait again."""

from __future__ import annotations

import pytest
from rephrasings import HELD_H286
from test_tabletop import TASKS, signature

STAGE_TWO = " Once those two are both in, the carrot and the red apple go in the blue plate, in any order."
STAGE_ONE = "The green apple and the orange go in the yellow plate"


@pytest.mark.parametrize(
    "text",
    [
        HELD_H286["plumber"][4][0],  # "..., either one first. Once those two are both in, ..."
        STAGE_ONE + ", whichever goes first." + STAGE_TWO,
        STAGE_ONE + ", whichever of the two you prefer to begin with." + STAGE_TWO,
        # ", and not before," says the wait again (h302 firefighter 4's stage two)
        STAGE_ONE + ", in any order." + STAGE_TWO.replace("both in,", "both in, and not before,"),
    ],
)
def test_a_stages_pick_of_its_first_thing_frees_that_stage(text: str) -> None:
    assert signature(text) == signature(TASKS[4].instruction), text
