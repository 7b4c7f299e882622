"""Issues 28 and 23 (h213): what "then" orders, by ANNOTATION_GUIDE.md: "Then Y" -> [previous task, Y], the
previous task "the one stated in the immediately preceding clause/sentence"; a clause with no order word of
its own gets none; "Finally Y" after every earlier task, no transitive pairs. "A and B then C" (two clauses,
no comma) orders C after B only, as "A, B, then C" (h243); "A and B, then C", a verbless B, one clause's
objects sharing its words, "first A and B, then C" and "A and B. Then C" stay after both."""

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
        # near miss, the committed truths: "A and B, then C" (a comma) stays after both
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
        # h243, "A and B then C" / "A and B and when you're done C" (no comma, B a clause): C after B only
        (
            "put the apple in the fridge and heat the egg and put it in the microwave then put the mug in "
            "the sink",
            {(HOT_EGG, MUG)},
        ),
        (
            "put the apple in the fridge and put the bread on the counter and when you're done put the mug "
            "in the sink",
            {(BREAD, MUG)},
        ),
        # near miss: a verbless item ("and the bread on the counter then"): after both (the committed truths)
        (
            "put the apple in the fridge and the bread on the counter then put the mug in the sink",
            {(APPLE, MUG), (BREAD, MUG)},
        ),
        # near misses: one clause's objects sharing its place, a leading "first", a full stop: after both
        (
            "put the apple and the egg in the fridge then put the mug in the sink",
            {("place Apple -> Fridge", MUG), ("place Egg -> Fridge", MUG)},
        ),
        (
            "first put the apple in the fridge and the bread on the counter, then put the mug in the sink",
            {(APPLE, MUG), (BREAD, MUG)},
        ),
        (
            "put the apple in the fridge and the bread on the counter. Then put the mug in the sink.",
            {(APPLE, MUG), (BREAD, MUG)},
        ),
    ],
)
def test_then_orders_what_the_guide_says(text, order):
    _, said, unread = read(text)
    assert said == order and not unread
