"""The handover clause reader (session 11): the sentences of `handover_session11.READ` and the dev11 batch
give the written specs; the near misses, each one meaning away from a read sentence, never do."""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_session11 import (
    NEAR_MISSES,
    NEAR_MISSES_DEV12,
    NEAR_MISSES_DEV13,
    OUT_OF_ORDER,
    READ,
    READ_DEV12,
    READ_DEV13,
)
from handover_specs import TASKS, assert_not_the_written_spec, assert_written_spec, cases
from handover_specs import spec_of as _spec

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.suites.handover.handover_bench import specs_equivalent


@pytest.mark.parametrize(
    ("task_id", "text"),
    cases(READ, READ_DEV12, READ_DEV13),
)
def test_clause_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(
    ("task_id", "text"),
    cases(NEAR_MISSES, NEAR_MISSES_DEV12, NEAR_MISSES_DEV13),
)
def test_near_misses_of_the_clause_forms_are_refused_or_give_another_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


@pytest.mark.parametrize("style", sorted(STYLES["dev11"]))
def test_dev11_styles_give_the_written_specs(style):
    for task, text in STYLES["dev11"][style].items():
        equal, why = specs_equivalent(_spec(int(task), text), TASKS[int(task)].hierarchical())
        assert equal, (text, why)


def test_a_scene_statement_the_world_contradicts_is_refused_by_name():
    with pytest.raises(HTTError, match="does not hold in this scene"):
        _spec(3, "The pillars sit on E, F and G now. Move them to regions E, F and G.")


@pytest.mark.parametrize(("task_id", "text"), cases(OUT_OF_ORDER))
def test_steps_said_out_of_order_are_refused_by_name(task_id, text):
    with pytest.raises(HTTError, match="say the steps in order"):
        _spec(task_id, text)
