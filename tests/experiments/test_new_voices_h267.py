"""h267 (session 32, issues 24 and 28): the tabletop leftovers of HELD_H250, by class. A closing sentence
that only praises who is asked ("Thanks, you're a star.") is removed with the closing thanks; a leading
deadline by an outside event ("Before the gates open, ...") is met by doing the tasks now; task 4's stages
said with a voice's labels: a label's qualifier that names nothing ("Step one of the regimen:"), a later
label's condition said with its own verb ("Quarter two opens only after both are booked:"), an ordinal
label with a word naming the round ("First delivery round:") and "once both have arrived". The dev batch is
swept (read right or refused)."""

from __future__ import annotations

import pytest
from rephrasings import DEV_H267
from test_tabletop import TASKS, assert_read_right_or_refused, refused, signature

from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.tabletop_world import tabletop_world

A = "the green apple and the orange go in the yellow plate, in either order"
ONE = "put the green apple on the blue plate and the orange on the yellow plate."
B = "the carrot and the red apple go in the blue plate, in either order"


@pytest.mark.parametrize(
    ("task", "text"),
    [
        (1, f"{ONE} Thanks, you're a hero."),
        (1, f"Before the ferry departs, {ONE}"),
        (4, f"Part one of the plan: {A}. Once both are in, part two: {B}."),
        (4, f"Quarter one: {A}. Quarter two starts only after both are placed: {B}."),
        (4, f"First cleaning round: {A}. When both have landed, second round: {B}."),
    ],
)
def test_voice_stages_praise_and_events_give_the_tasks_and_order(task: int, text: str) -> None:
    assert not refused(text)
    assert signature(text) == signature(TASKS[task].instruction)


def test_a_met_deadline_and_a_label_qualifier_are_said_in_the_notes() -> None:
    notes = " ".join(translate(f"Before the gates open, step one of the day: {A}. Step two: {B}.",
                               tabletop_world()).assumptions)
    assert "Before the gates open" in notes and "of the day" in notes


@pytest.mark.parametrize(
    "text",
    [
        f"Step one of the blue plate: {A}. Step two: {B}.",  # the qualifier names a plate
        f"{ONE} You're a thief.",
        f"Stage one: {A}. Stage two opens only after both are not placed: {B}.",
    ],
)
def test_a_qualifier_or_closing_that_could_say_more_stays_refused(text: str) -> None:
    assert refused(text)


@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(DEV_H267))
def test_tabletop_development_voices_are_read_right_or_refused(style: str) -> None:
    assert_read_right_or_refused(DEV_H267[style])
