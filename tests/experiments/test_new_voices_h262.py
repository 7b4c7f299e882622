"""h262 (session 32, issues 28 and 24): the tabletop voices of HELD_H250, by class. A label that announces
the list after its colon is dropped and said in the notes, unless it names a thing, an order, a negation or
a count the list does not have; a thing sent to a plate by a participle goes there; a verb the system has
no word for before "them" and a free order restates the job ("Book them in any sequence": no Book);
"who moves in first" is a freedom statement. The dev batch is swept (read right or refused)."""

from __future__ import annotations

import pytest
from rephrasings import DEV_H262
from test_tabletop import TASKS, assert_read_right_or_refused, refused, signature

from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.tabletop_world import tabletop_world

TWO = "green apple in the pink plate, orange in the yellow plate, red apple in the blue plate"


@pytest.mark.parametrize(
    ("task", "text"),
    [
        (2, f"Tonight's prep sheet: {TWO}."),
        (2, f"Okay, three tickets for you: {TWO}. Stamp them in whatever order."),
        (3, "The carrot is allocated to the blue plate, the orange to the yellow plate, the green apple to "
            "the green plate and the red apple to the pink plate. Who moves in first is entirely flexible."),
        (1, "Green apple shipped to the blue plate, orange shipped to the yellow plate. Book them in any "
            "order."),
    ],
)
def test_voice_frames_and_verbs_give_the_tasks_and_order(task: int, text: str) -> None:
    assert not refused(text)
    assert signature(text) == signature(TASKS[task].instruction)


def test_a_dropped_list_label_is_said_in_the_notes() -> None:
    notes = translate(f"Tonight's prep sheet: {TWO}.", tabletop_world()).assumptions
    assert any("Tonight's prep sheet" in note for note in notes)


@pytest.mark.parametrize(
    "text",
    [
        f"Four line items: {TWO}.",  # a count the list does not have
        f"Don't touch these: {TWO}.",  # a negation
        f"First: {TWO}.",  # an order
        "The green apple is not allocated to the pink plate.",
    ],
)
def test_a_label_or_participle_that_could_say_more_stays_refused(text: str) -> None:
    assert refused(text)


@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(DEV_H262))
def test_tabletop_development_voices_are_read_right_or_refused(style: str) -> None:
    assert_read_right_or_refused(DEV_H262[style])
