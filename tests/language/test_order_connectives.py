"""Issue 28 / 23: a connective between tasks is read by what its words say (a sequence, a freedom, a last
step, everything before, a thing's task finished), not only from a list of phrases; a phrase whose words
say two orders, or that has a word of no order, is not read by it."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.order_phrases import leading_connective, one_last_step
from nl2hltl2plan.language.order_words import finished_words
from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"


@pytest.mark.parametrize("lead", ["From there", "Up next", "After that's done", "With that out of the way"])
def test_a_sequence_phrase_orders_after_the_clause_before(lead):
    tasks, order, unread = read(f"Put the mug in the sink. {lead}, put the apple in the fridge.")
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


@pytest.mark.parametrize("lead", ["With all of the above out of the way", "Only after everything listed"])
def test_everything_before_phrase_orders_after_every_earlier_task(lead):
    tasks, order, unread = read(
        f"Put the mug in the sink. Put the egg in the microwave. {lead}, put the apple in the fridge."
    )
    assert len(tasks) == 3 and order == {(MUG, APPLE), (EGG, APPLE)} and not unread


@pytest.mark.parametrize("lead", ["Regardless of order", "At a moment of your choosing"])
def test_a_freedom_phrase_frees_its_task_from_the_last_step(lead):
    """ "Then, lastly" is one last step: after every task not left free (ANNOTATION_GUIDE.md)."""
    tasks, order, unread = read(
        f"Put the mug in the sink. {lead}, put the apple in the fridge. Then, lastly, put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and order == {(MUG, EGG)} and not unread


def test_whenever_it_suits_you_at_the_end_frees_the_task():
    tasks, order, unread = read(
        "Put the mug in the sink whenever it suits you. Put the apple in the fridge. As a final step, put "
        "the egg in the microwave."
    )
    assert len(tasks) == 3 and order == {(APPLE, EGG)} and not unread


@pytest.mark.parametrize(
    "lead", ["With the mug done", "Whenever the mug is sorted", "With the mug out of the way"]
)
def test_a_thing_said_finished_is_a_reference_to_its_task(lead):
    tasks, order, unread = read(
        f"Put the mug in the sink. Put the egg in the microwave. {lead}, put the apple in the fridge."
    )
    assert len(tasks) == 3 and order == {(MUG, APPLE)} and not unread


def test_whenever_with_no_state_stays_a_freedom():
    """Near miss: "whenever you like" frees the task, it names no thing to wait for."""
    tasks, order, unread = read("Put the mug in the sink. Whenever you like, put the apple in the fridge.")
    assert len(tasks) == 2 and not order and not unread


@pytest.mark.parametrize(
    ("phrase", "kind"),
    [("From there", G.THEN), ("As a final step", G.FINALLY), ("At a moment of your choosing", G.FREE),
     ("From there at any point", None), ("Up next at the end", None),  # two orders: not read
     ("If possible", None), ("From the kitchen", None), ("Please", None)],  # a word of no order
)
def test_leading_connective_reads_only_order_words(phrase, kind):
    got = leading_connective(f"{phrase}, put the mug in the sink")
    assert (got[0] if got else None) == kind


def test_then_lastly_keeps_the_last_step_only():
    assert one_last_step([(G.THEN, ""), (G.FINALLY, "")]) == [(G.FINALLY, "")]
    assert one_last_step([(G.FINALLY, ""), (G.THEN, "")]) == [(G.FINALLY, ""), (G.THEN, "")]


def test_finished_words_mark_only_the_state_of_a_named_thing():
    text = "Put the vase in the safe. Whenever the vase is sorted, sort the mail."
    assert finished_words(text) == {text.index("sorted")}
    assert finished_words("Sort the mail whenever you like.") == set()


@pytest.mark.parametrize("lead", ["Ahead of that", "Before that"])
@pytest.mark.parametrize("then", ["Then", "Having done that,", "After that,"])
def test_then_after_a_step_put_before_continues_the_time_line(lead, then):
    """ "X. Ahead of that, Y. Then Z": Y, X, Z (Z after X too, not only after Y)."""
    tasks, order, unread = read(
        f"Put the mug in the sink. {lead}, put the egg in the microwave. {then} put the apple in the fridge."
    )
    assert len(tasks) == 3 and order == {(EGG, MUG), (MUG, APPLE), (EGG, APPLE)} and not unread


@pytest.mark.parametrize(
    "text",
    [
        "Put the mug in the sink. The moment the mug is in the sink, put the apple in the fridge.",
        "Put the apple in the fridge the instant you have put the mug in the sink.",
    ],
)
def test_the_moment_a_clause_holds_is_a_reference(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


def test_at_the_moment_is_no_reference():
    """Near miss: "at the moment" (now) and "the second mug" name no time."""
    from nl2hltl2plan.language.grammar.state_references import the_moment

    text = "At the moment the mug is dirty. Put the second mug in the sink, wait a minute."
    assert the_moment(text) == text
