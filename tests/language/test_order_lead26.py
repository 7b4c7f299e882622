"""Issue 28, order in paper-style instructions (session 26, the lead's and h166's paper-style sets), each a
wrong reading at exit 0 before:
- a reference to the two tasks just said: "A. Then B. Before either of these, C" puts C before A and B
  ("either of these" named the sentence before alone, B, and C went after A and before B);
- "..., and once you've done that, C" inside a sentence is "then" (its "that" was left behind, ", then
  that, C", and C lost its order after the task before);
- "..., and to finish, D" inside a sentence is "and finally" (D came after the sentence before only)."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
BREAD = "place Bread -> CounterTop"
EGG = "place Egg -> Microwave"


@pytest.mark.parametrize(
    "ref",
    ["either of these", "both of these", "either of those", "both of them", "you do either", "doing both"],
)
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


@pytest.mark.parametrize(
    "done", ["once you've done that", "after you have finished that", "when you've done it"]
)
def test_once_you_have_done_that_inside_a_sentence(done):
    tasks, order, unread = read(
        f"Put the mug in the drawer. Then put the apple on the counter, and {done}, move the bread to the "
        "counter."
    )
    mug, apple, bread = "place Mug -> Drawer", "place Apple -> CounterTop", BREAD
    assert sorted(tasks) == sorted([mug, apple, bread]) and not unread
    assert order == {(mug, apple), (apple, bread), (mug, bread)}


@pytest.mark.parametrize("fin", ["to finish,", "to wrap up,", "to end,"])
def test_to_finish_inside_a_sentence_is_finally(fin):
    tasks, order, unread = read(
        f"First, put the mug in the sink. Then put the apple in the fridge. After that, put the bread on the "
        f"counter, and {fin} put the egg in the microwave."
    )
    assert len(tasks) == 4 and not unread
    assert {(MUG, EGG), (APPLE, EGG), (BREAD, EGG)} <= order


def test_to_finish_a_thing_is_a_purpose():
    """Near miss: "to finish the job," says why, not when: no task read from it."""
    _, _, unread = read("Put the mug in the sink, to finish the job, and put the apple in the fridge.")
    assert unread
