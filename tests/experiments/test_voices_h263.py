"""h263 (issue 24): the handover voices of held_h250 (seen), read by class: places closed or off limits
with the prohibition after them, a block off limits until another is touched, a period named by a noun
("that whole stretch"), the targets as a noun ("other than those targets"), the work before said done in
the voice's word ("once all of that's charted"), an exchange said of where the blocks rest, one block
resting or fitted per region, a count-in and a remark on the scene as frame - and what must stay
refused.

The batch test's sentences are the committed dev batch `dev_h263` (handover_styles_session10.json),
written with the held-out `held_h263` before the rules.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.frame_filler import count_in, filler

DEV = [(int(task), text) for style in STYLES["dev_h263"].values() for task, text in style.items()]


@pytest.mark.data
@pytest.mark.parametrize(
    ("task", "text"),
    [
        (7, STYLES["held_h250"]["park_ranger"]["7"]),  # "regions F, G and H are closed to visitors, so ..."
        # "The blue block is off limits until ...", "Once that's all laid" (without "Chisel at the ready.")
        (4, STYLES["dev_h263"]["stonemason"]["4"].split(". ", 1)[1]),
        # "swap where X and Y are sitting" (without "Wind it up.")
        (5, STYLES["dev_h263"]["watchmaker"]["5"][: -len(" Wind it up.")]),
        (2, "And five, six, seven, eight! The three blocks go onto regions H, I and J, with no more than one "
            "block resting on any of those regions. That's the map."),
        (3, "Bring the three pillars over to regions E, F and G, next to arm a and arm b. Any region other "
            "than those targets is closed: nothing gets placed there."),
    ],
)
def test_voices_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(
    ("task", "text"),
    [
        # a closure without the prohibition that says what it closes to: unread, as before
        (7, "Put the three blocks on region I one at a time, red before blue. Regions F, G, H are closed."),
        # a command on a thing no world has, and a count that is no count-in
        (2, "Stoke the forge. Put the three blocks on regions H, I and J, one block per region."),
        (2, "Five, seven, eight! Put the three blocks on regions H, I and J, one block per region."),
    ],
)
def test_what_may_name_a_thing_or_a_count_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


def test_count_ins_and_remarks() -> None:
    assert count_in("and five six seven eight") and count_in("1 2 3") and not count_in("five seven eight")
    assert filler(("clay", "s", "wedged"), 0) and filler(("that", "s", "the", "map"), 3)
    assert not filler(("smash", "that", "like", "button"), 3) and not filler(("clay",), 0)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), DEV)
def test_development_batch_is_read_right_or_refused(task: int, text: str) -> None:
    from handover_specs import assert_written_spec_or_refused

    assert_written_spec_or_refused(task, text)
