"""h198 (issue 24): the Table III handover tasks in a teacher's, an e-mail's, a game's rules', a recipe's
and a two-person dialogue's voice, and the content wordings h194's held-out batch left refused. The
sentences are committed batches of handover_styles_session10.json: `dev102` (written with the held-out
`validation36` before the rules) and `validation36` (scored once at the end; read right or refused, never
misread: `sweep`).

- `handover_places`: "whichever (whatever) region is empty", "somewhere empty" (a free region, as "any
  empty region"); "..., whenever there is one" after such a region (its time is free); "other than the
  same three (regions)", "other than the ones I said" (the regions named before, as "those three").
- `handover_registers`: "if a region is not one of those three, never put an object on it"; "if you need
  somewhere to set a block down meanwhile, don't use F, G or H".
- `handover_phrases`: "..., a block apiece" (one per region, as "one block each"); "they" before an active
  placing or touching verb with its object is the arms ("they may never put a pillar on ...").
- `handover_rules`: "the arms may (must, can) never put X on P" (the modal before "never").
- `handover_words`: "during the game" is the task's period; `handover_spoken`: "today the robots ...".
- `handover_frame_words.txt`: "game" and "how to win" as label words ("Game rules:", "How to win:").
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import (
    assert_not_the_written_spec,
    assert_refused_by_name,
    assert_written_spec,
    assert_written_spec_or_refused,
)

DEV102 = STYLES["dev102"]
DEV = [(int(task), text) for style in DEV102.values() for task, text in style.items()]
HELD = [(int(task), text) for style in STYLES["validation36"].values() for task, text in style.items()]
# left refused: "Right, class:" ("right" may be a side) and "Class, watch:" ("watch" is an object); the
# e-mails under a subject line the body says again and the "A: ... B: ..." dialogues read since h215
# (`handover_headers`)
STILL_REFUSED = {STYLES["dev102"]["teacher"]["2"]}  # ("4" is read the same since h296: "Class, watch:")
HEADED = [(int(t), text) for voice in ("email_subject", "dialogue") for t, text in DEV102[voice].items()]
PILLARS = "Move the three pillars to E, F and G beside arms a and b. "
YELLOW = "Put the yellow block on I and then on G. "
ON_I = "Put the three blocks on region I one after another, red before blue. "

WRITTEN = [
    (8, STYLES["dev102"]["game_rules"]["8"]),
    (6, STYLES["dev102"]["game_rules"]["6"]),
    (3, STYLES["dev102"]["teacher"]["3"]),
    (7, STYLES["dev102"]["teacher"]["7"]),
    (8, YELLOW + "The red and blue blocks go to any empty region, whenever there is one."),
    (8, YELLOW + "Move red and blue to somewhere empty at any time."),
    (3, PILLARS + "If a region is not one of those three, never put an object on it."),
    (3, PILLARS + "Please don't set any pillar down on a region other than the ones I said."),
    (3, PILLARS + "Don't put a pillar on a region other than the same regions."),
    (7, "If you need somewhere to set a block down meanwhile, don't use F, G or H. " + ON_I),
    (1, "Class, today the robots move the three blocks to the opposite side, red before blue."),
]

UNCLEAR = [
    # "whenever there is one" after a named region: there is always one; left unread
    (8, YELLOW + "Move red and blue to H, whenever there is one."),
    # the condition names the regions kept: which rule? (left unread, as before)
    (3, PILLARS + "If a region is one of those three, never put an object on it."),
    # with no regions named before, "the ones I said" names none
    (3, "Don't put a pillar on a region other than the ones I said. Move the pillars to E, F and G."),
    # a subject line's topic is not a command: one that says more than the body ("return") stays unread (a
    # subject the body says again is dropped, h215's `handover_headers`)
    (5, "Subject: swap and return\nSwap the red and blue blocks, red first. Yellow to the opposite side, any "
     "time."),
]

NEAR_MISSES = [
    # the count said is not the regions named
    (3, PILLARS + "If a region is not one of those two, never put an object on it."),
    (3, PILLARS + "Don't put a pillar on a region other than the same two."),
    # a region left out of the period's rule; an order reversed
    (7, "If you need somewhere to set a block down meanwhile, don't use F or G. " + ON_I),
    (7, ON_I + "While they do that, no block may be set down on F or G."),
    (3, PILLARS + "They may never put a pillar on H or I."),
    (1, "Move the blocks to the opposite side. They must place the blue block before the red block."),
    (6, "The three objects go to G, H and I, a block apiece. Blue must be placed before red."),
    # not a free region: a named one
    (8, YELLOW + "Move red and blue to whichever region is G at any time."),
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_new_voices_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), UNCLEAR)
def test_unclear_neighbours_stay_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), NEAR_MISSES)
def test_near_misses_are_not_the_written_spec(task: int, text: str) -> None:
    assert_not_the_written_spec(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), [case for case in DEV if case[1] not in STILL_REFUSED])
def test_development_batch_gives_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), [case for case in DEV if case[1] in STILL_REFUSED])
def test_development_sentences_left_are_refused_by_name(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), HEADED)
def test_subject_lines_and_dialogues_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), HELD)
def test_held_out_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
