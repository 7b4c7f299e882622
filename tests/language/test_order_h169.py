"""Issue 28, order in paper-style instructions of three and four tasks (h169, paper_h169dev.txt): a closing
"at the very end" / "last of all" / "as the final step" / "when you're all done" makes its
clause the last step, "when you have done both" is "when both are done" (also inside a "Before that, Y"
sentence), "After that" after a "Before you X, Y" sentence comes after X too, and a trailing reference
after two clauses states its task once. Before each fix the reading was wrong (exit 0, an order lost or
changed, or a task twice) or partial."""

from __future__ import annotations

import pytest

from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"
BOWL = "place Bowl -> Cabinet"
SEQ = "Put the mug in the sink. Then put the apple in the fridge"


@pytest.mark.parametrize(
    "closing",
    ["at the very end", "last of all", "as the very last thing", "as the final step", "as a last step",
     "at the very last", "when you're all done", "once you are all done"],
)
def test_closing_phrase_makes_the_clause_the_last_step(closing):
    """Before: the closing phrase was left over and the egg had no order at all."""
    tasks, order, unread = read(f"{SEQ}. Put the egg in the microwave {closing}.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, APPLE), (APPLE, EGG), (MUG, EGG)}


def test_closing_phrase_inside_a_sentence_after_then():
    """Before: "Then B, and C at the very end" put C after A only (the "Then" of its sentence)."""
    tasks, order, unread = read(f"{SEQ}, and put the egg in the microwave at the very end.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, APPLE), (APPLE, EGG), (MUG, EGG)}


@pytest.mark.parametrize(
    "text",
    [
        "Put the egg in the microwave at the very end of the counter.",  # a place, not the last step
        "Put the egg in the microwave to finish the job.",  # a purpose
    ],
)
def test_closing_phrase_near_misses_stay_as_they_were(text):
    """Near miss: "at the very end of" names a place and "to finish the job" a purpose; neither is read
    as "last" (one task: no order to state either way)."""
    tasks, order, _ = read(text)
    assert order == set() and len(tasks) == 1


@pytest.mark.parametrize(
    "ref",
    ["When you have done both", "Once you've finished both", "When you're done with both of them",
     "Once you have done those two things"],
)
def test_you_have_done_both_is_both_are_done(ref):
    """Before: "could not tell which tasks 'you have done both' refers to" (partial)."""
    tasks, order, unread = read(f"Put the mug in the sink and the apple in the fridge. {ref}, put the egg in "
                                "the microwave.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, EGG), (APPLE, EGG)}


def test_both_done_inside_a_before_that_sentence():
    """Before: "X. Before that, Y, and when you have done both, Z" put Z before X (the sentence's "before
    that" took Z in), against "both"."""
    tasks, order, unread = read("Put the apple in the fridge. Before that, put the mug in the sink, and when "
                                "you have done both, put the egg in the microwave.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, APPLE), (APPLE, EGG), (MUG, EGG)}


def test_both_done_inside_a_sentence_of_two_clauses():
    """Near miss (read so before too): "A and B, and once both are done, C" is C after both."""
    tasks, order, unread = read("Put the mug in the sink and the apple in the fridge, and once both are "
                                "done, put the egg in the microwave.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, EGG), (APPLE, EGG)}


@pytest.mark.parametrize("then", ["After that,", "Then", "Once that's done,"])
def test_then_after_a_before_you_sentence_comes_after_the_stated_task(then):
    """Before: "Before you X, Y. After that, Z" put Z after Y only (X, stated by the reference, could come
    after Z)."""
    tasks, order, unread = read(f"Before you put the apple in the fridge, put the mug in the sink. {then} "
                                "put the egg in the microwave.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, APPLE), (APPLE, EGG), (MUG, EGG)}


def test_then_after_an_after_you_sentence_is_unchanged():
    """Near miss: "Y after you X. Then Z": X comes before Y, so Z is after Y (and X) as before."""
    tasks, order, unread = read("Put the mug in the sink after you put the apple in the fridge. Then put the "
                                "egg in the microwave.")
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(APPLE, MUG), (MUG, EGG), (APPLE, EGG)}


def test_trailing_reference_after_two_clauses_states_one_task():
    """Before: "A and B, but only after you've put X" stated X twice (four tasks, one X before each)."""
    tasks, order, unread = read("Put the mug in the sink and put the apple in the fridge, but only after "
                                "you've put a bowl in a cabinet.")
    assert sorted(tasks) == sorted([MUG, APPLE, BOWL]) and not unread
    assert order == {(BOWL, MUG), (BOWL, APPLE)}


@pytest.mark.parametrize(
    "freed",
    ["Do those first, in any order, and then", "Do these first in either order, then",
     "Do them in any order, then"],
)
def test_freed_pair_said_first_then_the_next_task(freed):
    """The lead, at h169's merge (its held-out half, read wrong once the trials' worlds held both soap bars):
    "A, and B. Do those first, in any order, and then C" gave C no order at all ("first" was not read)."""
    text = f"Put the mug in the sink, and put the apple in the fridge. {freed} put the egg in the microwave."
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, EGG), (APPLE, EGG)}


@pytest.mark.parametrize(
    "closing", ["Put the egg in the microwave first.", "Before anything else, put the egg in the microwave."]
)
def test_a_closing_first_after_ordered_tasks_is_named(closing):
    """The lead (session 27): "A. Then B. <D first>" left D unordered at exit 0, the "first" dropped, where
    other tasks were ordered; it is named now. "A. First B, then C" (a "first" that opens a sequence) stays
    as it was."""
    _, order, unread = read(f"{SEQ}. {closing}")
    assert any("'first' after tasks said before it" in u for u in unread) and order == {(MUG, APPLE)}
    opens = "Put the apple in the fridge. First put the mug in the sink, then the egg in the microwave."
    _, order, unread = read(opens)
    assert order == {(MUG, EGG)} and not unread


@pytest.mark.parametrize(
    "before",
    ["Before you start on any of this,", "Before you do any of that,", "Before you begin with all of this,"],
)
def test_before_you_start_on_any_of_this_comes_before_everything(before):
    """The lead (session 27, h170's held-out line): "A. Then B. Before you start on any of this, D" put D
    between A and B at exit 0 (the writer's doing was read as a reference to the sentence before)."""
    _, order, unread = read(f"{SEQ}. {before} put the egg in the microwave.")
    assert order == {(MUG, APPLE), (EGG, MUG), (EGG, APPLE)} and not unread
