"""Issue 28 (h234): a sentence-leading order marker over several clauses. ANNOTATION_GUIDE.md: "Then Y",
"Next Y", "Afterwards Y", "After that Y" with no named referent -> [previous task, Y]; a marker set off at the
head of a sentence introduces the whole sentence, so every clause of it is after the previous task ("A. After
that, B, and C." -> A<B, A<C). A clause closed by "too" adds one more task with no order word of its own
(h213's class: "A. After that, B, and C too." -> A<B only), and a bare "Then" opens its first clause only."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

APPLE = "place Apple -> Fridge"
MUG = "place Mug -> SinkBasin"
HOT_EGG = "heat_place Egg -> Microwave"
BREAD = "place Bread -> CounterTop"


@pytest.mark.parametrize(
    ("text", "order"),
    [
        # before h234: the egg unordered (only the first clause after the marker was ordered)
        (
            "Put the apple in the fridge. When done, put the mug in the sink, and heat the egg and put it in "
            "the microwave.",
            {(APPLE, MUG), (APPLE, HOT_EGG)},
        ),
        # three clauses under one marker (before: only the mug after the apple)
        (
            "Put the apple in the fridge. Afterwards, put the mug in the sink, heat the egg and put it in "
            "the microwave, and put the bread on the counter.",
            {(APPLE, MUG), (APPLE, HOT_EGG), (APPLE, BREAD)},
        ),
        # near miss: a closing "too" adds a task the marker does not order (as h213 read it)
        (
            "Put the apple in the fridge. After that, put the mug in the sink, and heat the egg and put it "
            "in the microwave too.",
            {(APPLE, MUG)},
        ),
        # near miss: a bare "Then" opens its first clause only (the committed sets' truths, paper_h166held,
        # paper_h170dev / held: "X. Then B, C, and D." -> [X, B])
        (
            "Put the apple in the fridge. Then put the mug in the sink, and heat the egg and put it in the "
            "microwave.",
            {(APPLE, MUG)},
        ),
    ],
)
def test_a_leading_marker_orders_every_clause_of_its_sentence(text, order):
    _, said, unread = read(text)
    assert said == order and not unread
