"""Issues 28 and 23 (h213): what "then" orders, by ANNOTATION_GUIDE.md: "Then Y" -> [previous task, Y], the
previous task "the one stated in the immediately preceding clause/sentence"; a clause with no order word of
its own gets none; "Finally Y" after every earlier task, no transitive pairs. Where the guide leaves it open
("A and B, then C": one clause of two tasks, or two joined by "and") the reading stays after both."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

APPLE = "place Apple -> Fridge"
MUG = "place Mug -> SinkBasin"
EGG = "place Egg -> Microwave"
BREAD = "place Bread -> CounterTop"
HOT_EGG = "heat_place Egg -> Microwave"


@pytest.mark.parametrize(
    ("text", "order"),
    [
        # "A, B, and then C": the comma list states no order, "then" follows B (before: A < B < C)
        (
            "put the apple in the fridge, put the mug in the sink, and then put the egg in the microwave",
            {(MUG, EGG)},
        ),
        # a verbless list: "then" follows the item before it (before: after the whole list)
        ("put the apple in the fridge, the mug in the sink, then the egg in the microwave", {(MUG, EGG)}),
        # "Then B, and C too": C's clause, a verb of its own, has no order word (before: C after A too)
        (
            "Put the apple in the fridge. Then put the mug in the sink, and heat the egg and put it in the "
            "microwave too.",
            {(APPLE, MUG)},
        ),
        # near miss: ", and <the same verb>" may be the reader's restated verb of one clause: after A too
        (
            "Put the apple in the fridge. Then put the mug in the sink, and put the egg in the microwave "
            "too.",
            {(APPLE, MUG), (APPLE, EGG)},
        ),
        # "A, then B, C, and finally D": [A, B], and D after B and C (before: B < C as well)
        (
            "put the apple in the fridge, then put the mug in the sink, heat the egg and put it in the "
            "microwave, and finally put the bread on the counter",
            {(APPLE, MUG), (APPLE, BREAD), (MUG, BREAD), (HOT_EGG, BREAD)},
        ),
        # near miss, left open by the guide: "A and B, then C" stays after both
        (
            "put the apple in the fridge and the mug in the sink, then put the egg in the microwave",
            {(APPLE, EGG), (MUG, EGG)},
        ),
        # near miss: a list that "and" closes ("A, B and C, then D") is one clause: after all of it
        (
            "put the apple in the fridge, the mug in the sink and the bread on the counter, then put the egg "
            "in the microwave",
            {(APPLE, EGG), (MUG, EGG), (BREAD, EGG)},
        ),
    ],
)
def test_then_orders_what_the_guide_says(text, order):
    _, said, unread = read(text)
    assert said == order and not unread
