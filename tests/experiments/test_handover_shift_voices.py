"""h194 (issue 24): the Table III handover tasks in voices the earlier batches lacked (a shift note, a
checklist, a chatty request, a terse command list, the passive, conditionals). The sentences are committed
batches of handover_styles_session10.json: `dev101` (written with the held-out `validation35` before the
rules) and `validation35` (scored once at the end; read right or refused, never misread: `sweep`).

- `handover_sentences`: an open checklist box ("[ ]") below a heading is a bullet ("Checklist:\\n[ ] ...").
- `handover_spoken`: "it'd" / "that'd" (would).
- `handover_frame_words.txt`: "Checklist:" / "To check off:" / "Outstanding:" / "Pending:" / "Priority:" as
  labels, "Checklist" as a heading alone, "the incoming shift", "thanks a million".
- `handover_wishes`: "i'd love it if you could", "any chance you could"; a request's "for me"; "X need(s)
  swapping" (to be swapped); "keep the blocks out of F, G and H" (put nothing there).
- `courtesy.txt`: "if it's not too much trouble" as the handover text spells it ("it s").
- `handover_rewrites`: "at no point is an object to be put on H" (an object is never to be put there).
- `handover_registers`: a not-yet condition that restates an order or a guard ("if (as long as) red has
  not been placed yet, do not place blue", "if nobody has touched the red block yet, leave the blue block
  alone", "if red isn't down yet, blue has to wait", "..., blue stays untouched"; "the blue block may only
  be placed if the red block has been placed"); "if you need to set a block down in the meantime, don't
  use F, G or H"; "if a region is F, G or H, put nothing on it"; "if a region already has a block, put no
  second block there"; "the spot marked G"; "pillars x3"; "never drop on H, I, J"; "F, G, H: keep clear";
  "red, blue -> ..."; "..., one block being put on each region".
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

from nl2hltl2plan.language.handover_phrases import normalise

DEV = [(int(task), text) for style in STYLES["dev101"].values() for task, text in style.items()]
HELD = [(int(task), text) for style in STYLES["validation35"].values() for task, text in style.items()]
# left refused on purpose: a goal under "if" and a permission ("may go there"), as h129 keeps them
STILL_REFUSED = {STYLES["dev101"]["conditional"]["8"]}
OPPOSITE = "Move the three blocks to the opposite side. "
TOUCH = "Move the three blocks to the opposite regions. "
BACK = " When all that is done, put the yellow block back on region G."
MARKED_H = " When all that is done, put the yellow block back on the spot marked H."

WRITTEN = [
    (1, STYLES["dev101"]["checklist"]["1"]),
    (2, STYLES["dev101"]["shift_note"]["2"]),
    (5, STYLES["dev101"]["shift_note"]["5"]),
    (1, STYLES["dev101"]["chatty_request"]["1"]),
    (4, STYLES["dev101"]["conditional"]["4"]),
    (5, STYLES["dev101"]["conditional"]["5"]),
    (7, STYLES["dev101"]["conditional"]["7"]),
    (8, STYLES["dev101"]["terse_commands"]["8"]),
    (2, STYLES["dev101"]["passive"]["2"]),
    (7, "Put the three blocks on region I one after another, red before blue. Keep the blocks out of regions "
        "F, G and H in the meantime."),
    # a second round of our own: "as long as" conditions, the passive's "is ... to be", polite frames
    (4, TOUCH + "As long as red hasn't been touched, blue stays untouched. Then return the yellow block to "
        "G."),
    (6, "Put the three objects on G, H and I, one each. If the red block is not yet in place, the blue block "
        "must not be placed."),
    (3, "Move the pillars to E, F and G beside arms a and b; at no point is an object to be put on H, I or "
        "J."),
    (6, "Any chance you could put the three objects on G, H and I, one each, red before blue?"),
    (8, "If it's not too much trouble, put the yellow block on I and then on G, and move the red and blue "
        "blocks to any empty region at any time."),
    (6, "Checklist\n- red before blue\n- objects on G, H and I, one each"),
    (1, "It'd be great if you could move the three blocks to the opposite side, red before blue."),
    (8, "Pending: yellow to region I, after that to region G. Red and blue: any empty region, any time."),
    (6, "Place the three objects on G, H and I, one each; if red hasn't gone down yet, hold off on blue."),
    (4, TOUCH + "If no arm has picked up red yet, nobody touches blue. After that, yellow back to G."),
    (5, "Exchange the positions of the red and blue blocks; the blue block may only be placed if the red "
        "block has been placed. Move the yellow block to the opposite side at any time."),
]

UNCLEAR = [
    # without the period, "if you need to set a block down" is any time: which rule?
    (7, "Put the three blocks on region I one after another, red before blue. If you need to set a block "
        "down, don't use F, G or H."),
    # "stays put" after a condition of touching: not moved, or not touched? (left unread)
    (4, TOUCH + "As long as red hasn't been touched, blue stays put. Then return the yellow block to G."),
    # a goal under a condition the plan cannot test stays refused
    (1, "If the far side is free, move the three blocks there; red before blue."),
]

NEAR_MISSES = [
    # the condition the other way round orders blue first; another block is another order
    (1, OPPOSITE + "If blue has not been placed yet, do not place red."),
    (6, "Put the three objects on G, H and I, one each. If the red block hasn't been placed, don't place the "
        "yellow block."),
    (4, TOUCH + "If nobody has touched the blue block yet, leave the red block alone." + BACK),
    (5, "Exchange the red and blue blocks; the red block may only be placed if the blue block has been "
        "placed. Move the yellow block to the opposite side at any time."),
    (6, "Put the three objects on G, H and I, one each. As long as blue isn't down, red waits."),
    (1, OPPOSITE + "If blue isn't there yet, don't put red down."),
    (3, "Move the pillars to E, F and G beside arms a and b; at no point is an object to be put on H or I."),
    # a region left out of the kept-out ones
    (7, "Put the three blocks on region I one after another, red before blue. Keep the blocks out of regions "
        "F and G in the meantime."),
    # the mark names another region
    (4, TOUCH + "Don't touch blue until red has been touched." + MARKED_H),
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


def test_conditions_are_said_as_the_command_until_they_hold() -> None:
    assert normalise("If red has not been placed yet, do not place blue") == (
        "do not place blue until red has been placed"
    )
    placed = "do not place blue until red has been placed"
    assert normalise("if red isn't down yet, blue has to wait") == placed
    assert normalise("If the red block hasn't been touched, the blue block waits") == (
        "do not touch the blue block until the red block has been touched"
    )
    # a need's gerund is its passive; a request's "for me" says whom it pleases
    assert normalise("red and blue need swapping") == "red and blue must be swapped"
    assert normalise("could you move the blocks to g for me") == "could you move the blocks to g"


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
@pytest.mark.parametrize(("task", "text"), HELD)
def test_held_out_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
