"""Issue 28, a reference to the two tasks just said: "A. Then B. Before either of these, C" puts C before A
and B. Before, "either of these" named the sentence before alone (B), and C went after A and before B, a
wrong reading at exit 0 (the lead's paper-style set, session 26)."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
BREAD = "place Bread -> CounterTop"
EGG = "place Egg -> Microwave"


@pytest.mark.parametrize("ref", ["either of these", "both of these", "either of those", "both of them"])
def test_before_either_of_two_sentences(ref):
    tasks, order, unread = read(
        f"Put the mug in the sink. Then put the apple in the fridge. Before {ref}, put the bread on the "
        "counter."
    )
    assert sorted(tasks) == sorted([MUG, APPLE, BREAD]) and not unread
    assert order == {(BREAD, MUG), (BREAD, APPLE), (MUG, APPLE)}


def test_before_either_of_one_sentence_of_two():
    """Near miss (read so before too): the sentence before holds both tasks."""
    tasks, order, unread = read(
        "Put the mug in the sink and the apple in the fridge. Before either of these, put the bread on the "
        "counter."
    )
    assert sorted(tasks) == sorted([MUG, APPLE, BREAD]) and not unread
    assert order == {(BREAD, MUG), (BREAD, APPLE)}


@pytest.mark.parametrize(
    "text",
    [
        # three said before, each in a sentence of its own: which two is not certain
        "Put the mug in the sink. Then put the apple in the fridge. Then put the egg in the microwave. "
        "Before both of these, put the bread on the counter.",
        # after one of them, whichever: no `before` pair says it
        "Put the mug in the sink. Then put the apple in the fridge. After either of these, put the bread on "
        "the counter.",
    ],
)
def test_either_of_not_certain_is_unread(text):
    _, _, unread = read(text)
    assert any("either of these" in u or "both of these" in u for u in unread)
