"""Issue 28 / 23 (h278): verbs of putting a thing somewhere that no word table knew ("prop the racket on the
nightstand", "park the laptop", "perch the clock") are a class kept in `language/placing_verbs.txt`: read as
"put", with their past and -ing forms. Before, each was refused as "an action the system has no word for". A
verb that no list holds is still refused by name. And an order remark closed by a courtesy word ("mug first
and egg last pls") reads as without it."""

from __future__ import annotations

import pytest
from grammar_readings import offline_reading

ROOM = {"Apple", "Mug", "Plate", "CounterTop", "SinkBasin", "Fridge", "Drawer", "Laptop", "Desk", "Book"}


def read(text: str):
    return offline_reading(text, ROOM, "kitchen")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("Prop the plate on the counter.", "place Plate -> CounterTop"),
        ("Park the laptop on the desk, please.", "place Laptop -> Desk"),
        ("Nestle the apple in the fridge.", "place Apple -> Fridge"),
    ],
)
def test_a_placing_verb_of_the_word_file_is_put(text, task):
    tasks, order, unread = read(text)
    assert tasks == [task] and order == set() and not unread


def test_its_past_form_names_the_task_an_order_waits_for():
    """"propped" (the doubled consonant of `doubled`) is the participle of a task a reference states."""
    tasks, order, unread = read("Put the book on the desk after you've propped the plate on the counter.")
    assert order == {("place Plate -> CounterTop", "place Book -> Desk")} and not unread


@pytest.mark.parametrize("verb", ["fluff", "polish"])
def test_a_verb_no_list_holds_is_still_refused_by_name(verb):
    _, _, unread = read(f"{verb.capitalize()} the mug and put it in the sink.")
    assert any(repr(verb) in u for u in unread)


def test_an_order_remark_closed_by_a_courtesy_word_is_read():
    """Before: "mug first and egg last pls" read the egg's task first ("'Mug first': task A is not first")."""
    text = "Put the mug in the sink, the apple in the fridge and the plate on the counter. Mug first and "
    text += "plate last pls"
    tasks, order, unread = read(text)
    mug, apple, plate = tasks
    assert order == {(mug, apple), (mug, plate), (apple, plate)} and not unread
