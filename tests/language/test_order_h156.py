"""Issue 28, connectives on held-out compositions (h156): an added clause ("; also Y") stays in its step
before a later "then", a clause's own "at any time" frees it from "finally", a task added to a clause
allowed at any time is refused by name where a later order asks about it, and "..., and finally Y" after
a state reference opens the last step."""

from __future__ import annotations

from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"
BREAD = "place Bread -> CounterTop"


def test_also_then_keeps_the_added_task_in_its_step():
    """Before: "B, also C, then D" read the comma-joined C as a step of its own, after B (B < C < D)."""
    tasks, order, unread = read(
        "Put the apple in the fridge. Then put the mug in the sink; also put the egg in the microwave, and "
        "when finished put the bread on the counter."
    )
    assert len(tasks) == 4 and not unread
    assert (MUG, EGG) not in order and (EGG, MUG) not in order
    assert {(APPLE, MUG), (APPLE, EGG), (MUG, BREAD), (EGG, BREAD)} <= order


def test_comma_list_before_then_orders_the_last_clause():
    """Near miss: "A, B, then C" (no additive word): C after B, the clause before "then" (the guide); A and B
    in no order (before h213: the sequence A < B < C)."""
    _, order, unread = read(
        "Put the apple in the fridge, put the mug in the sink, then put the egg in the microwave."
    )
    assert not unread and order == {(MUG, EGG)}


def test_own_any_time_is_free_of_finally():
    """Before: "B at any time, and C. Finally D" put B before D."""
    tasks, order, unread = read(
        "Put the apple in the fridge. Put the mug in the sink at any time, and put the egg in the microwave. "
        "Finally put the bread on the counter."
    )
    assert len(tasks) == 4 and not unread
    assert (MUG, BREAD) not in order and {(APPLE, BREAD), (EGG, BREAD)} <= order


def test_added_to_a_free_clause_is_refused_by_name():
    """Before: the egg was read free of "to finish" (the generator's truth puts it before): a guess."""
    _, _, unread = read(
        "Put the apple in the fridge. Whenever convenient, put the mug in the sink, plus put the egg in the "
        "microwave. To finish, put the bread on the counter."
    )
    assert any("put the egg in the microwave' ('plus' after a clause allowed" in u for u in unread)


def test_free_clauses_joined_by_and_are_read():
    """Near miss: "and" frees both, and with no later order the added task is read."""
    for text in (
        "Put the apple in the fridge. Whenever convenient, put the mug in the sink and put the egg in the "
        "microwave. To finish, put the bread on the counter.",
        "Put the apple in the fridge. Whenever convenient, put the mug in the sink, plus put the egg in the "
        "microwave.",
    ):
        tasks, order, unread = read(text)
        assert len(tasks) >= 3 and not unread
        assert (MUG, BREAD) not in order and (EGG, BREAD) not in order


def test_finally_after_a_state_reference_opens_the_last_step():
    """Before: "B when the apple is in the fridge, and finally D" took "finally D" into the reference (D
    before B)."""
    tasks, order, unread = read(
        "Put the apple in the fridge. Put the mug in the sink when the apple is in the fridge, and finally "
        "put the bread on the counter."
    )
    assert len(tasks) == 3 and not unread
    assert {(APPLE, MUG), (MUG, BREAD)} <= order and (BREAD, MUG) not in order
