"""A count said of a plate (`tabletop_counts`): read where the placements on that plate are that many,
refused otherwise."""

from __future__ import annotations

import pytest

from tests.language.test_tabletop_lines import YELLOW_THEN_BLUE
from tests.language.test_tabletop_pairs import _reading


@pytest.mark.parametrize(
    "text",
    [
        "Two for the yellow plate first (green apple, orange), then two for the blue plate (carrot, red "
        "apple).",
        "Green apple and orange on the yellow plate, carrot and red apple on the blue plate; the yellow "
        "plate's two placed before the blue plate's two.",
        "The yellow plate gets two things, the green apple and the orange; then the blue plate gets two "
        "things, the carrot and the red apple.",
    ],
)
def test_a_count_said_of_a_plate_that_the_placements_on_it_keep_is_read(text):
    assert _reading(text) == YELLOW_THEN_BLUE


@pytest.mark.parametrize(
    "text",
    [
        "Three for the yellow plate first (green apple, orange), then two for the blue plate (carrot, red "
        "apple).",
        "The yellow plate gets one thing, the green apple and the orange; then the blue plate gets two "
        "things, the carrot and the red apple.",
        "Green apple and orange on the yellow plate, carrot on the blue plate; the yellow plate's two placed "
        "before the blue plate's two.",
    ],
)
def test_a_count_said_of_a_plate_that_the_placements_on_it_do_not_keep_is_refused(text):
    assert _reading(text) is None


ORDERED = "Green apple and orange on the yellow plate first, then carrot and red apple on the blue plate."


@pytest.mark.parametrize(
    "text, read",
    [
        (f"{ORDERED} Four placements in all.", True),
        (f"{ORDERED} Three placements in all.", False),
        (f"{ORDERED[:-1]} - those four placements, that's all.", True),
        (f"{ORDERED[:-1]} - just those two, that's it.", False),
    ],
)
def test_a_clause_that_counts_the_placements_in_all_is_read_where_they_are_that_many(text, read):
    assert _reading(text) == (YELLOW_THEN_BLUE if read else None)
