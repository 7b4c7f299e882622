"""h296 (issue 28): the tabletop voices' wording. A later stage said as a wait ("Round two doesn't start till
both of them are in: then ...", "Nobody touches the carrot or the red apple till ...; then ...") is read as
"once STATE, REST" where that is all it says (`tabletop_waits`); a person's ease with any order ("the
captain's happy either way") frees the order (`free_order.txt`). A wait on other things than the ones
placed after it stays refused.

The lines of the dev batch are `DEV_H296` (tests/experiments/rephrasings.py), written with the held-out
`HELD_H296` before the rules."""

from __future__ import annotations

import pytest
from tabletop_readings import pairs_read

STAGE_ONE = "The green apple and the orange into the yellow plate, whichever goes first. "
STAGE_TWO = "then the carrot and the red apple into the blue plate, either order."
YELLOW = [("GreenApple", "YellowPlate"), ("Orange", "YellowPlate")]
BLUE = [("Carrot", "BluePlate"), ("RedApple", "BluePlate")]
TASK_4_PAIRS = sorted(YELLOW + BLUE)
TASK_4_ORDER = sorted((first, then) for first in YELLOW for then in BLUE)


@pytest.mark.parametrize(
    "wait",
    [
        "Round two doesn't start till both of them are in: ",
        "The second load waits till both of them are in; ",
        "Nobody touches the carrot or the red apple until both of them are in. ",
    ],
)
def test_a_later_stage_said_as_a_wait_comes_after_the_first(wait: str) -> None:
    assert pairs_read(STAGE_ONE + wait + STAGE_TWO) == (TASK_4_PAIRS, TASK_4_ORDER)


def test_a_wait_on_other_things_than_the_ones_placed_stays_refused() -> None:
    assert pairs_read(STAGE_ONE + "Nobody touches the carrot until both of them are in. " + STAGE_TWO) is None


def test_a_persons_ease_frees_the_order() -> None:
    text = (
        "The green apple goes in the pink plate, the orange in the yellow plate and the red apple in the "
        "blue plate. No fixed order, the depot's fine either way."
    )
    pairs = sorted([("GreenApple", "PinkPlate"), ("Orange", "YellowPlate"), ("RedApple", "BluePlate")])
    assert pairs_read(text) == (pairs, [])
