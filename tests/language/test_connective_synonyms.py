"""Issue 28 / 23: connectives between tasks written in words the grammar had no rule for (found on
held-out compositions: "as soon as you've X", "only after X should you Y", "ahead of that", "with that
done", "to wrap up", "whenever convenient", "though first", courtesy openers and closers), each read
through the default offline reader and check 1. One real sentence per rule and a near miss."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder
from nl2hltl2plan.language.grammar.references import new_tasks_from_ref
from tests.language.test_unseen_classes import KITCHEN, read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"


# ----- "Y as soon as you've X", "only after X should you Y": X first -----------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge as soon as you've put the mug in the sink.",
        "As soon as you've put the mug in the sink, put the apple in the fridge.",
        "Only after you've put the mug in the sink should you put the apple in the fridge.",
        "Right after you put the mug in the sink, put the apple in the fridge.",
        "Put the apple in the fridge immediately after putting the mug in the sink.",
    ],
)
def test_after_connectives_order_the_named_task_first(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


def test_as_soon_as_possible_is_no_reference():
    """Near miss: "as soon as possible" names no task to wait for."""
    tasks, order, unread = read("Put the mug in the sink as soon as possible.")
    assert tasks == [MUG] and not order and not unread


def test_a_reference_in_the_perfect_states_its_own_task():
    """ "as soon as you've examined the keys under the lamp": the examination is a task of its own."""
    tasks, order, unread = read(
        "Put the apple in the fridge as soon as you've examined a newspaper by the light of a floor lamp."
    )
    light = "examine_in_light Newspaper under FloorLamp"
    assert sorted(tasks) == sorted([APPLE, light]) and order == {(light, APPLE)} and not unread


def test_a_perfect_reference_to_an_earlier_task_adds_none():
    """Near miss: the keys were examined by a task already stated: two tasks, not three."""
    tasks, order, unread = read(
        "Examine a newspaper under the floor lamp. After you've examined the newspaper, put the apple in the "
        "fridge."
    )
    assert len(tasks) == 2 and len(order) == 1 and not unread


# ----- sentence openers: then, before that, finally, free ------------------------------------------------
@pytest.mark.parametrize(
    "opener", ["With that done,", "Having done that,", "After you finish,", "After which,"]
)
def test_done_openers_order_after_the_sentence_before(opener):
    tasks, order, unread = read(f"Put the mug in the sink. {opener} put the apple in the fridge.")
    assert tasks == [MUG, APPLE] and order == {(MUG, APPLE)} and not unread


@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge. Ahead of that, put the mug in the sink.",
        "Put the apple in the fridge, though first put the mug in the sink.",
    ],
)
def test_ahead_of_that_and_though_first_put_the_task_before(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge, and before that put the mug in the sink.",
        "Put the apple in the fridge and before doing that, put the mug in the sink.",
    ],
)
def test_and_before_that_inside_a_sentence_puts_the_task_before(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


def test_and_then_keeps_the_written_order():
    """Near miss of "and before that": the same sentence with "and then" keeps the written order."""
    assert read("Put the apple in the fridge, and then put the mug in the sink.")[1] == {(APPLE, MUG)}


def test_then_is_still_after():
    """Near miss of "ahead of that": the same sentences with "then" keep the written order."""
    assert read("Put the apple in the fridge. Then put the mug in the sink.")[1] == {(APPLE, MUG)}


@pytest.mark.parametrize("closer", ["And to wrap up,", "To conclude,", "As a last step,"])
def test_wrap_up_orders_after_every_task_not_free(closer):
    tasks, order, unread = read(
        f"Put the mug in the sink. Whenever convenient, put the apple in the fridge. {closer} put the egg in "
        "the microwave."
    )
    assert tasks == [MUG, APPLE, EGG] and order == {(MUG, EGG)} and not unread


def test_at_whatever_point_frees_the_task():
    tasks, order, unread = read(
        "Put the mug in the sink. At whatever point suits you, put the apple in the fridge. Then put the egg "
        "in the microwave."
    )
    assert order == {(APPLE, EGG)} and not unread


# ----- courtesy: openers and closers that carry no order -------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Kindly put the mug in the sink and put the apple in the fridge, the order is up to you.",
        "Your first job: put the mug in the sink, put the apple in the fridge, the order is up to you.",
        "Alright, put the mug in the sink and put the apple in the fridge in no particular order, cheers",
    ],
)
def test_courtesy_words_are_read_and_the_order_stays_free(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and not order and not unread


def test_first_that_orders_is_still_an_order():
    """Near miss: "first" that is not a heading orders its task before the others."""
    tasks, order, unread = read("First put the mug in the sink, and put the apple in the fridge.")
    assert order == {(MUG, APPLE)} and not unread


def test_strictly_in_this_order_chains_the_tasks():
    tasks, order, unread = read(
        "Would you put the mug in the sink, put the apple in the fridge and put the egg in the microwave, "
        "strictly in this order, thanks!"
    )
    assert tasks == [MUG, APPLE, EGG] and {(MUG, APPLE), (APPLE, EGG)} <= order and not unread


def test_an_unread_ahead_is_named_by_check_1():
    """ "ahead" is an order word: left unread with the tasks unordered, check 1 names it (never a guess)."""
    _, order, unread = read("Put the mug in the sink and put the apple in the fridge ahead.")
    assert not order and any("'ahead' (order)" in u for u in unread)


# ----- "W, then X. Before that, Y": Y goes in between ------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Put the mug in the sink, then put the apple in the fridge. Before that, put the egg in the "
        "microwave.",
        "Put the mug in the sink, then put the apple in the fridge, though first put the egg in the "
        "microwave.",
    ],
)
def test_before_that_inserts_the_task_before_the_last_step(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert order == {(MUG, EGG), (EGG, APPLE), (MUG, APPLE)}


def test_before_that_with_nothing_earlier_orders_only_the_two():
    """Near miss: with no step before the one it precedes, "before that" adds no other pair."""
    assert read("Put the mug in the sink. Before that, put the egg in the microwave.")[1] == {(EGG, MUG)}


def test_ahead_of_a_named_task_is_before_it():
    """ "Ahead of the apple, Y": before the task the object names, not before the sentence just read."""
    tasks, order, unread = read(
        "Put the apple in the fridge. Then put the mug in the sink. Ahead of the apple, put the egg in the "
        "microwave."
    )
    assert (EGG, APPLE) in order and (EGG, MUG) in order and not unread


def test_a_thank_you_sentence_is_courtesy():
    tasks, order, unread = read(
        "Put the mug in the sink and put the apple in the fridge in no particular order. Thank you."
    )
    assert sorted(tasks) == sorted([MUG, APPLE]) and not order and not unread


# ----- "both" / "all" around a list names the listed things, not a count of one of them ------------------
@pytest.mark.parametrize(
    ("text", "objects"),
    [
        ("Put both the mug and the apple on the counter.", ["Mug", "Apple"]),
        ("Put the mug and the apple both on the counter.", ["Mug", "Apple"]),
        ("Put the mug, the apple and the egg all on the counter.", ["Mug", "Apple", "Egg"]),
    ],
)
def test_both_or_all_around_a_list_is_no_count(text, objects):
    tasks, _, unread = read(text)
    assert tasks == [f"place {o} -> CounterTop" for o in objects] and not unread


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("Put both mugs and the apple on the counter.", "place_two 2x Mug -> CounterTop"),
        ("Put the mug in the sink and the two apples both in the fridge.", "place_two 2x Apple -> Fridge"),
    ],
)
def test_both_before_a_plural_still_counts(text, task):
    """Near miss: "both mugs" (no article) and "the two apples both" are still two."""
    tasks, _, unread = read(text)
    assert task in tasks and not unread


@pytest.mark.parametrize(
    "text",
    [
        "Put the mug in the sink, and once it's there put the apple in the fridge.",
        "Put the mug in the sink. When that is taken care of, put the apple in the fridge.",
    ],
)
def test_the_step_before_is_in_place(text):
    tasks, order, unread = read(text)
    assert tasks == [MUG, APPLE] and order == {(MUG, APPLE)} and not unread


# ----- "A and B. Then C": after both ----------------------------------------------------------------------
def test_then_after_a_sentence_of_two_tasks_follows_both():
    tasks, order, unread = read(
        "Put the mug in the sink and put the apple in the fridge. Then put the egg in the microwave."
    )
    assert order == {(MUG, EGG), (APPLE, EGG)} and not unread


def test_then_after_a_sentence_with_a_free_task_follows_its_last_clause_only():
    """Near miss: a task the sentence frees ("at any time") is not made to precede the next step."""
    p = parse_instruction(
        "Put the mug in the sink at any time and put the apple in the fridge. Then put the egg in the "
        "microwave.",
        KITCHEN,
        "kitchen",
    )
    assert p.before == [("B", "C")] and not p.unparsed


# ----- a reference that states a placement; ordinal openers -----------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge after the mug is in the sink.",
        "Put the mug in the sink before the apple goes in the fridge.",
        "Don't put the apple in the fridge until the mug is in the sink.",
    ],
)
def test_a_reference_to_a_placed_object_states_the_placement(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


def test_a_placed_reference_to_a_stated_task_adds_none():
    """Near miss: the mug's task is stated already: the reference points at it, no third task."""
    tasks, order, unread = read(
        "Put the mug in the sink. Put the apple in the fridge after the mug is in the sink."
    )
    assert tasks == [MUG, APPLE] and order == {(MUG, APPLE)} and not unread


def test_ordinal_openers_order_the_sentences():
    tasks, order, unread = read(
        "First, the mug goes in the sink. Second, the apple goes in the fridge. Third, the egg goes in the "
        "microwave."
    )
    assert tasks == [MUG, APPLE, EGG] and {(MUG, APPLE), (APPLE, EGG)} <= order and not unread


def test_an_ordinal_of_a_place_is_no_order():
    """Near miss: "the second drawer" names a drawer; check 1 does not ask for an order."""
    tasks, order, unread = read("Put the mug in the second drawer. Put the apple in the fridge.")
    assert len(tasks) == 2 and not order and not unread


def test_a_placed_reference_to_an_object_named_elsewhere_states_no_task():
    """Near miss: the bottle is named in a sentence of its own: the reference is to that sentence's task,
    so no placement is made up for it (an unread sentence stays unread, never a second guess)."""
    text = "Put the bottle on the shelf whenever. Once the bottle is on the shelf, put the pan on the table."
    assert new_tasks_from_ref("the bottle is on the shelf", TaskBuilder(None, False, None), text) == []
    alone = "Once the bottle is on the shelf, put the pan on the table."
    assert len(new_tasks_from_ref("the bottle is on the shelf", TaskBuilder(None, False, None), alone)) == 1


# ----- wrong readings that were reported as success (issue 23) -------------------------------------------
def test_a_trailing_reference_stops_before_then():
    """ "Y after X-ing Z, and then W": W is a task of its own after Y, not part of the reference (it was
    read "heat the apple in the egg")."""
    tasks, order, unread = read(
        "Put the mug in the sink after putting the apple in the fridge, and then the egg in the microwave."
    )
    assert sorted(tasks) == sorted([MUG, APPLE, EGG]) and not unread
    assert {(APPLE, MUG), (MUG, EGG)} <= order


@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge, but not before putting the mug in the sink.",
        "Put the apple in the fridge, but only after you put the mug in the sink.",
    ],
)
def test_not_before_is_only_after(text):
    tasks, order, unread = read(text)
    assert sorted(tasks) == sorted([MUG, APPLE]) and order == {(MUG, APPLE)} and not unread


def test_in_reverse_order_reverses_the_named_order():
    tasks, order, unread = read(
        "Put the apple in the fridge, the mug in the sink and the egg in the microwave, in reverse order."
    )
    assert order == {(EGG, MUG), (MUG, APPLE), (EGG, APPLE)} and not unread


def test_reverse_order_against_then_is_a_contradiction():
    """Near miss: "then" and "in reverse order" in one sentence contradict each other: exit 2, no guess."""
    with pytest.raises(HTTError, match="contradictory"):
        read(
            "Put the apple in the fridge, then the mug in the sink, then the egg in the microwave, in "
            "reverse order."
        )


@pytest.mark.parametrize(
    "text",
    [
        "Put the apple in the fridge. The mug is in the sink.",
        # ("The moment the mug is in the sink, Y" is "as soon as": test_order_connectives.py)
        "The mug is in the sink, put the apple in the fridge.",
    ],
)
def test_a_clause_that_says_where_a_thing_is_states_no_task(text):
    """ "The mug is in the sink" was read as "put the mug in the sink" by the grammar: a statement is no
    request. (The offline backend's learned rescue may still read the unread clause; that is its policy.)"""
    p = parse_instruction(text, KITCHEN, "kitchen")
    assert "place Mug -> SinkBasin" not in [t.summary() for t in p.tasks]
    assert any("mug is in the sink" in u for u in p.unparsed)


@pytest.mark.parametrize(
    "text",
    ["Put the mug that is on the counter in the sink.", "Put the mug which is on the counter into the sink."],
)
def test_where_the_object_is_now_is_no_destination(text):
    """ "the mug that is on the counter" was read as a mug put on the counter; near miss: "into" was right."""
    tasks, _, unread = read(text)
    assert tasks == [MUG] and not unread


def test_and_last_mid_sentence_puts_the_task_after_every_other():
    tasks, order, unread = read(
        "Put the egg in the microwave, then the mug in the sink, and last the apple in the fridge."
    )
    assert order == {(EGG, MUG), (MUG, APPLE), (EGG, APPLE)} and not unread


def test_the_last_as_an_adjective_is_no_order_word():
    """Near miss of "and last": "the last" names a thing, and the sentence's order stays free."""
    assert read("Put the egg in the microwave and the mug in the last cabinet.")[1] == set()


@pytest.mark.parametrize(
    "text",
    [
        "Put the egg in the microwave, the mug in the sink and the apple in the fridge, one after the other.",
        "put the egg in the microwave, the mug in the sink and the apple in the fridge one after another",
    ],
)
def test_one_after_the_other_after_a_list_is_the_order_of_mention(text):
    assert read(text)[1:] == ({(EGG, MUG), (MUG, APPLE), (EGG, APPLE)}, [])


def test_after_the_other_mug_orders_nothing():
    """Near miss of "one after the other": "after the other mug" names a thing, not a sequence."""
    assert read("Put the egg in the microwave after the other mug.")[2]
