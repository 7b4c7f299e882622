"""h215 (issue 24): handover messages laid out as a memo or e-mail (headers, a role's sign-off), a dialogue
of two speakers, a work order's labelled fields and a game's numbered rules (`handover_headers`). The
sentences are committed batches of handover_styles_session10.json: `dev103` (written with the held-out
`validation37` before the rules) and `validation37` (scored once at the end; read right or refused, never
misread: `sweep`). h230 adds work orders said as a title and sentences ("Work order #12 - move ... .
Constraints: red before blue; no timing requirement."): `dev_h230`, and the held-out `held_h230`.
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

from nl2hltl2plan.language.handover_headers import headed

DEV = [(int(task), text) for style in STYLES["dev103"].values() for task, text in style.items()]
HELD = [(int(task), text) for style in STYLES["validation37"].values() for task, text in style.items()]
# all of dev_h230 but one: "Red is placed first; yellow at any time." stays refused, as a time given to a goal
# that is not the last clause before is (test_handover_sixth_round.py's near misses)
DEV += [(int(task), text) for style in STYLES["dev_h230"].values() for task, text in style.items()
        if "yellow at any time" not in text]
HELD += [(int(task), text) for style in STYLES["held_h230"].values() for task, text in style.items()]
OPPOSITE = "Move the three blocks to the opposite side. Red before blue."

WRITTEN = [
    (1, STYLES["dev103"]["memo_header"]["1"]),
    (8, STYLES["dev103"]["memo_header"]["8"]),
    (4, STYLES["dev103"]["dialogue_split"]["4"]),
    (8, STYLES["dev103"]["dialogue_split"]["8"]),
    (6, STYLES["dev103"]["work_order"]["6"]),
    (7, STYLES["dev103"]["work_order"]["7"]),
    (5, STYLES["dev103"]["rules_method"]["5"]),
    # one line, turns after full stops and question marks
    (1, "A: can you move the three blocks? B: where to? A: to the opposite side, red before blue"),
    # h230: a title on the command's line, one remark line joined by semicolons
    (7, STYLES["dev_h230"]["order_title"]["7"]),
    (8, STYLES["dev_h230"]["order_title"]["8"]),  # "no timing requirement": the clause before, at any time
    (1, STYLES["dev_h230"]["numbered_order"]["1"]),  # "no other timing requirement": the order said is all
]
# a header, turn or field with a word no reader uses stays, and is refused by name
UNCLEAR = [
    (1, "Subject: swap\n" + OPPOSITE),  # the title says what the body does not
    (1, "To: arms a and b\n" + OPPOSITE),  # arms named, not people
    (1, "A: Move the three blocks.\nB: Where to?\nA: Not sure.\nB: Any order?\nA: Red before blue."),
    (2, "Task: move\nObjects: the three blocks\nDestination: H, I and J\nPriority: yellow"),
    (2, "Subject: three blocks\nPut the two blocks on H, I and J, one per region."),
    (1, "Work order: move the three blocks to the opposite side. Constraints: red first; blue at any time."),
    (8, "Work order: put yellow on I, then on G. Red and blue go to any empty region. Constraints: no timing "
     "requirement for red."),  # red alone has no goal of its own
    (2, "Work order: put the three blocks on H, I and J, then on G. Constraints: no timing requirement."),
]
# the title's words in another order than the body's: refused, never the body alone
NEAR_MISSES = [
    (1, "Subject: blue before red\n" + OPPOSITE),
    (1, "Move the three blocks to the opposite side.\n- Red first"),  # a last line that is no role
    (1, "Work order: move the three blocks to the opposite side. Constraints: blue before red."),
    (7, "Work order: stack the three blocks on region I. Constraints: red before blue; regions F and G stay "
     "empty throughout."),
]


@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_laid_out_messages_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.parametrize(("task", "text"), UNCLEAR)
def test_unread_headers_turns_and_fields_stay_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


@pytest.mark.parametrize(("task", "text"), NEAR_MISSES)
def test_near_misses_are_not_the_written_spec(task: int, text: str) -> None:
    assert_not_the_written_spec(task, text)


def test_layout_is_said_as_plain_lines() -> None:
    memo = "Subject: block moves for Tuesday\nMove the three blocks.\n- Shift lead"
    assert headed(memo) == "Move the three blocks."
    assert headed("Task: transfer\nOrder: red before blue\nObjects: the blocks\nDestination: H") == (
        "transfer the blocks to H.\nred before blue."
    )
    assert headed("Lead: Put the blocks somewhere.\nRobot: Where?\nLead: On H, I and J.") == (
        "Put the blocks on H, I and J."
    )
    assert headed("Rule 2: red before blue.") == "- red before blue."
    assert headed("Work order #12 - move the blocks to H. Constraints: red first; no block on G.") == (
        "move the blocks to H. Red first. No block on G."
    )
    record = "Blocks: red, blue, yellow\nTargets: H, I, J"  # `handover_sentences`' own record
    assert headed(record) == record


@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), DEV)
def test_development_batch_gives_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), HELD)
def test_held_out_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
