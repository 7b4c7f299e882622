"""Issue 28, order in paper-style instructions of three and four tasks (h163, paper_h163dev.txt): "finally" /
"once all that is done" after a "before you X, Y" clause come after X too (a task the reference states
goes with its clause), a trailing reference takes no ", and finally Z" into itself, and "and only after
that" is "and after that". Before each fix the reading was wrong (exit 0, a changed order or kind)."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"
BREAD = "place Bread -> CounterTop"


@pytest.mark.parametrize(
    "text",
    [
        "Before you put the apple in the fridge, put the mug in the sink. Finally put the bread on the "
        "counter.",
        "Before you put the apple in the fridge, put the mug in the sink. Once all that is done, put the "
        "bread on the counter.",
        "Put the mug in the sink before you put the apple in the fridge, and finally put the bread on the "
        "counter.",
        "Put the mug in the sink before the apple goes in the fridge, and finally put the bread on the "
        "counter.",
    ],
)
def test_last_step_comes_after_the_task_a_before_clause_states(text):
    """Before: the bread after the mug only (the apple, stated by the reference, has the last index), or
    the bread taken into the reference and ordered after the mug alone."""
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE, BREAD]) and not unread
    assert order == {(MUG, APPLE), (APPLE, BREAD), (MUG, BREAD)}


@pytest.mark.parametrize("ref", ["after you put", "once you have put"])
def test_last_step_after_a_trailing_after_reference(ref):
    """Before: "Y after you X, and finally Z" put Z before Y (the reference took Z in)."""
    tasks, order, unread = read(f"Put the mug in the sink {ref} the apple in the fridge, and finally put the "
                                "bread on the counter.")
    assert sorted(tasks) == sorted([MUG, APPLE, BREAD]) and not unread
    assert order == {(APPLE, MUG), (MUG, BREAD), (APPLE, BREAD)}


def test_any_time_task_stays_free_of_finally_after_a_before_clause():
    """Near miss: a task allowed at any time is still after nothing and before nothing."""
    tasks, order, unread = read(
        "Before you put the apple in the fridge, put the mug in the sink. Put the egg in the microwave at "
        "any time, and finally put the bread on the counter."
    )
    assert len(tasks) == 4 and not unread
    assert not any(EGG in pair for pair in order)
    assert {(MUG, APPLE), (APPLE, BREAD)} <= order


@pytest.mark.parametrize("focus", ["only after that", "just after that", "right after that,", "only then"])
def test_focus_word_before_a_connective(focus):
    """Before: "and only after that" left "only," in the first clause, which then read "put a tomato in the
    microwave" as heating it."""
    tasks, order, unread = read(
        f"Put a tomato in the microwave, and {focus} put a cooked potato slice in the fridge."
    )
    assert tasks == ["place Tomato -> Microwave", "heat_place Potato(sliced) -> Fridge"] and not unread
    assert order == {("place Tomato -> Microwave", "heat_place Potato(sliced) -> Fridge")}


def test_right_as_a_side_is_no_focus_word():
    """Near miss: "to the right" is a place; nothing is dropped."""
    tasks, _, _ = read("Put the mug in the sink to the right, and then put the apple in the fridge.")
    assert APPLE in tasks


@pytest.mark.parametrize(
    ("opener", "mug_first"),
    [("After that, though,", False), ("Then, however,", False), ("Before you do that, though,", True)],
)
def test_contrast_word_after_a_leading_order_phrase(opener, mug_first):
    """Before: "After that, though, Y" left "though" unread, and the learned structure model, taking it for
    "though first", put Y first."""
    tasks, order, unread = read(f"Put the apple in the fridge. {opener} put the mug in the sink.")
    assert sorted(tasks) == sorted([APPLE, MUG]) and not unread
    assert order == ({(MUG, APPLE)} if mug_first else {(APPLE, MUG)})


def test_then_after_a_before_that_sentence_follows_the_whole_step():
    """Before: "W, plus X. Ahead of that, Y. After which, Z" put Z after X only (the clause "plus" added),
    though Y was put before both W and X."""
    tasks, order, unread = read(
        "Put the mug in the sink, plus put the apple in the fridge. Ahead of that, put the bread on the "
        "counter. After which, put the egg in the microwave."
    )
    assert len(tasks) == 4 and not unread
    assert {(BREAD, MUG), (BREAD, APPLE), (MUG, EGG), (APPLE, EGG)} <= order
    assert (MUG, APPLE) not in order and (APPLE, MUG) not in order


@pytest.mark.parametrize("done", ["all that is done", "everything is done", "all three are done"])
def test_and_once_all_is_done_opens_the_last_step(done):
    """Before: ", and once all that is done, put Y" took Y into the reference and put Y before every
    other task."""
    tasks, order, unread = read(
        f"Put the mug in the sink, the apple in the fridge and the bread on the counter, and once {done}, "
        "put the egg in the microwave."
    )
    assert len(tasks) == 4 and not unread
    assert order == {(MUG, EGG), (APPLE, EGG), (BREAD, EGG)}


def test_last_on_a_list_item_is_about_that_item():
    """Before: "A first, then B, and C last" made both B and C last (B not before C)."""
    tasks, order, unread = read(
        "Put the mug in the sink first, then the apple in the fridge, and the bread on the counter last."
    )
    assert tasks == [MUG, APPLE, BREAD] and not unread
    assert order == {(MUG, APPLE), (APPLE, BREAD), (MUG, BREAD)}


def test_last_as_an_adjective_is_no_order():
    """Near miss: "the last mug" names a mug; the rewrite leaves it alone (the order word stays unread)."""
    _, order, unread = read("Put the apple in the fridge and the last mug in the sink.")
    assert not order and unread


def test_a_task_freed_by_its_own_words_is_not_made_last():
    """Before: "X whenever, but put Y last" (one clause unit) made X last too, after every other task."""
    tasks, order, unread = read(
        "Put the mug in the sink. Put the apple in the fridge whenever, but put the bread on the counter "
        "last."
    )
    assert len(tasks) == 3 and not unread
    assert order == {(MUG, BREAD)}


@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge. Put the mug in the sink before anything else.",
        "Put the mug in the sink before doing anything else, then put the apple in the fridge.",
        "Before doing anything else, put the mug in the sink. Then put the apple in the fridge.",
    ],
)
def test_before_anything_else_is_first(text):
    """Before: "Y before anything else" in a later sentence read the apple first (the reference named no
    task, and the structure model chose), and "before doing anything else" was unread."""
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and not unread
    assert order == {(MUG, APPLE)}


def test_first_though_stays_but_first():
    """Near miss: "A. First, though, B" is "but first": B before A (the contrast word is kept)."""
    tasks, order, unread = read("Put the apple in the fridge. First, though, put the mug in the sink.")
    assert sorted(tasks) == sorted([APPLE, MUG]) and not unread
    assert order == {(MUG, APPLE)}
