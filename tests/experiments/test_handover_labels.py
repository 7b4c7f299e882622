"""A one-word label and a dash open a line as a colon does ("Goal - ...", "Condition - ..."): the lead's
batch 24 (session 17) refused all seven such sentences. Near misses with another order or rule are never
the written spec."""

from __future__ import annotations

import pytest

from tests.experiments.handover_specs import assert_not_the_written_spec, assert_written_spec

READ = [
    (1, "Objective - three blocks to the opposite side. Constraint - red block placed before blue block."),
    (2, "Job - three blocks into regions H, I and J. Rule - one object per region."),
    (6, "Aim - the three objects separately on regions G, H and I. Order - red block before blue block."),
]
NEAR_MISSES = [
    (1, "Objective - three blocks to the opposite side. Constraint - blue block placed before red block."),
    (6, "Aim - the three objects on region I. Order - red block before blue block."),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_a_label_with_a_dash_is_a_heading(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), NEAR_MISSES)
def test_a_labelled_line_with_another_meaning_is_not_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)
