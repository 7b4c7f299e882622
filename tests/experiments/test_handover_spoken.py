"""The spoken and instructor styles (`language.handover_spoken`): the sentences of
`handover_spoken_cases.READ` give the written specs; the near misses, in which a filler, hedge or
correction carries a meaning, never do; a self-correction that says something else is refused; the dev14
batch is read right or refused by name, never misread."""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import TASKS, assert_not_the_written_spec, assert_written_spec, cases
from handover_specs import spec_of as _spec
from handover_spoken_cases import CORRECTIONS_REFUSED, NEAR_MISSES, READ

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_spoken import unspoken
from nl2hltl2plan.suites.handover.handover_bench import specs_equivalent


@pytest.mark.parametrize(("task_id", "text"), cases(READ))
def test_spoken_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), cases(NEAR_MISSES))
def test_a_filler_that_carries_a_meaning_is_never_dropped(task_id, text):
    assert_not_the_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), cases(CORRECTIONS_REFUSED))
def test_a_correction_that_says_something_else_is_refused(task_id, text):
    with pytest.raises(HTTError, match="self-correction"):
        _spec(task_id, text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("um , so , just move the blocks , okay", "move the blocks"),
        ("just the red block", "just the red block"),  # "just": only
        ("put it on i , er , region i", "put it on region i"),
        ("put the three , uh , the three blocks on g", "put the three blocks on g"),
        ("put them on g , h and , uh , i", "put them on g , h and i"),
        ("you'll place the red block first", "place the red block first"),
        ("you're not allowed to touch the blue block", "do not touch the blue block"),
        ("you do not have to put red first", "you do not have to put red first"),  # not a command
        ("maybe the red block first", "maybe the red block first"),  # a hedge on a choice: kept
        ("oh , and never put anything on g", "and never put anything on g"),
        # "'s" before a participle: "has" after somebody, "is" after what is done (a passive)
        ("until somebody s touched the red one", "until somebody has touched the red one"),
        ("once that s done , put yellow on g", "once that is done , put yellow on g"),
    ],
)
def test_unspoken_drops_only_words_without_a_meaning(text, expected):
    assert unspoken(text) == expected


@pytest.mark.parametrize("style", sorted(STYLES["dev14"]))
def test_dev14_is_read_right_or_refused_never_misread(style):
    for task, text in STYLES["dev14"][style].items():
        try:
            spec = _spec(int(task), text)
        except HTTError as exc:
            assert "\n" not in str(exc)
            continue
        equal, why = specs_equivalent(spec, TASKS[int(task)].hierarchical())
        assert equal, (text, why)
