"""Held-out rephrasings of the paper's tabletop (`HELD_H210`, `HELD_H233`, `HELD_H250`, `HELD_H270`,
`HELD_H286`, `HELD_H302` of rephrasings.py) and handover (`held_h210`, `held_h233`, `held_h250`, `held_h270`,
`held_h286`, `held_h302` of handover_styles_session10.json) instructions, each committed before any scoring
and scored once, unchanged: h210 (session 30; results/experiments/h210.md: tabletop 10 of 16 the same, 6
refused; handover 2 of 16 the same, 14 refused), h233 (session 31; results/experiments/h233.md: tabletop 7 of
16 read the same, 3 of them planned, 13 refused; handover 0 of 16, all refused), h250 (session 32;
results/experiments/h250.md: tabletop 3 of 16 read the same, none planned, 16 refused; handover 1 of 16 the
same, 15 refused), h270 (session 33; results/experiments/h270.md: tabletop 8 of 16 read the same, 1 of them
planned, 15 refused; handover 1 of 16 the same, 15 refused), h286 (session 34; results/experiments/h286.md:
tabletop 11 of 16 read the same, 5 of them planned, 11 refused; handover 0 of 16, all refused) and h302
(session 35; results/experiments/h302.md: tabletop 8 of 16 read the same, 5 of them planned, 11 refused;
handover 2 of 16 the same, 14 refused). None is misread. No rule was written for them; each line must stay
read right or refused, never misread (`sweep`: whole committed batches)."""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import assert_written_spec_or_refused
from rephrasings import HELD_H210, HELD_H233, HELD_H250, HELD_H270, HELD_H286, HELD_H302
from test_tabletop import TASKS, refused, signature, signature_or_none

TABLETOP = [
    (task, text)
    for batch in (HELD_H210, HELD_H233, HELD_H250, HELD_H270, HELD_H286, HELD_H302)
    for voice in batch.values()
    for task, texts in voice.items()
    for text in texts
]
HANDOVER = [
    (int(task), text)
    for batch in ("held_h210", "held_h233", "held_h250", "held_h270", "held_h286", "held_h302")
    for voice in STYLES[batch].values()
    for task, text in voice.items()
]


@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), TABLETOP)
def test_tabletop_held_out_line_is_read_right_or_refused(task: int, text: str) -> None:
    assert refused(text) or signature_or_none(text) == signature(TASKS[task].instruction), text


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), HANDOVER)
def test_handover_held_out_line_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
