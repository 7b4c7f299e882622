"""h220 (issues 24, 28): the frames of new voices around the handover and tabletop instructions. The
sentences of the batch tests are committed batches: `dev104` (handover_styles_session10.json) and
`DEV_H220` (rephrasings.py), written with the held-out `validation38` and `VALID_H220` before the rules;
the held-out ones are read right or refused, never misread (`sweep`).

- a group addressed ("Ladies and gentlemen,", "..., darlings.", "Patrol, ..."): `courtesy.txt`'s `address`;
- a label naming the document ("Puzzle #3:", "Exercise 4.", "Agenda item 2 -", "Rules of play:"): the
  frame lists' `record` and `title` (`handover_frame_words.txt`), also the tabletop reader's
  (`tabletop_chat`) where the label opens the text and labels nothing else;
- chatty asides ("Nice and steady.", "It's going to be perfect.", "Good luck!", "Can you solve it?",
  "Thank you for your cooperation.", "What I'd love is for you to ..."): `handover_frame_words.txt`,
  `courtesy.txt` (`urging`, `wish`), the grammar's wish;
- a chatty remark that frees the order ("Start wherever you like."): `free_order.txt`, read as "in any
  order";
- a later stage label's condition on the group before ("Stage two, only when both of those are in:"), and
  a second stage label after an unlabelled first step: `tabletop_steps`.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import assert_refused_by_name, assert_written_spec, assert_written_spec_or_refused
from rephrasings import DEV_H220, VALID_H220
from test_tabletop import TASKS, refused, signature, signature_or_none

DEV = [(int(task), text) for style in STYLES["dev104"].values() for task, text in style.items()]
HELD = [(int(task), text) for style in STYLES["validation38"].values() for task, text in style.items()]

WRITTEN = [
    (7, STYLES["dev104"]["coach_team"]["7"]),  # vocatives at a sentence's start and end
    (4, STYLES["dev104"]["document_label"]["4"]),  # a game's title
    (6, STYLES["dev104"]["document_label"]["6"]),  # an agenda item with its number and a dash
    (8, STYLES["dev104"]["chatty_aside"]["8"]),  # "It's going to be perfect, thank you!"
    (5, STYLES["dev104"]["chatty_aside"]["5"]),  # "What I'd love is for you to ..."
]

# a frame word beside a word that may name something: the fragment is read or refused by name, never
# dropped (h235: "sing along" alone, a verb with no object, is general filler; with an object it stays)
UNCLEAR = [
    (1, "Ladies and gentlemen, juggle the three blocks to the opposite side, red before blue."),
    (2, "Put the three blocks on H, I and J, one block per region. Nice and steady, sing a song."),
    (6, "Puzzle pieces: place the three objects on G, H and I, one per region. Red should be placed before "
        "blue."),
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_new_voice_frames_give_the_written_handover_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), UNCLEAR)
def test_a_frame_beside_another_word_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.parametrize(
    ("task_id", "text"),
    [
        (4, DEV_H220["coach"][4][0]),  # stage labels, the second with a condition on the group before
        (4, DEV_H220["chatty"][4][0]),  # "Stage two:" after an unlabelled first step
        (1, DEV_H220["document_label"][1][0]),  # "Puzzle #1: ... Can you solve it?"
    ],
)
def test_tabletop_frames_and_stage_labels_give_the_tasks_and_order(task_id: int, text: str) -> None:
    assert signature(text) == signature(TASKS[task_id].instruction)
    assert not refused(text)


def test_a_chatty_leave_to_start_anywhere_is_in_any_order_never_a_negation() -> None:
    base = "Put the green apple on the pink plate, the orange on the yellow plate and the red apple on the "
    base += "blue plate"
    freed = signature(base + ", in any order.")
    assert signature(base + ". Start wherever you like.") == freed
    assert signature(base + ". It's all the same to me which goes first.") == freed


def test_a_record_label_that_labels_other_steps_is_no_title() -> None:
    # "Task 1: ... Task 2: ...": the labels order the steps; only a label alone is the document's title
    text = "Task 1: put the orange on the yellow plate. Task 2: put the green apple on the blue plate."
    (_, before) = signature(text)
    assert len(before) == 1


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), DEV)
def test_development_batch_gives_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), HELD)
def test_held_out_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)


@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(DEV_H220))
def test_tabletop_development_voices_give_the_tasks_and_order(style: str) -> None:
    for task_id, texts in DEV_H220[style].items():
        for text in texts:
            assert signature(text) == signature(TASKS[task_id].instruction), text


@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(VALID_H220))
def test_tabletop_held_out_voices_are_read_right_or_refused(style: str) -> None:
    for task_id, texts in VALID_H220[style].items():
        for text in texts:
            reference = signature(TASKS[task_id].instruction)
            assert refused(text) or signature_or_none(text) == reference, text
