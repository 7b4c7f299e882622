"""Issue 28, h138 (session 23): tabletop rephrasings in four voices (a non-native speaker, a voice transcript
with fillers, a checklist pasted from an e-mail, a terse note in mixed case without punctuation) give the
original wording's tasks and closed order: the development batch `DEV_H138` (one voice by default, every
voice in the `sweep` run); the held-out `VALID_H138` is read right or refused, never misread (`sweep`). A
non-native speaker's end of a step with no subject ("When is finish, ...", "After finish this, ...") closes
the step; where "finish" has an object ("After finishing the orange, ...") it is not read as that."""

from __future__ import annotations

import pytest
from rephrasings import DEV_H138, DEV_H142, VALID_H138, VALID_H142
from test_tabletop import TASKS, refused, signature, signature_or_none

from nl2hltl2plan.language.tabletop_steps import order_confirmed_dropped
from nl2hltl2plan.language.tabletop_wording import _UNSAID_DONE


def _check(batch: dict[str, dict[int, list[str]]], style: str) -> None:
    for task_id, texts in batch[style].items():
        reference = signature(TASKS[task_id].instruction)
        for text in texts:
            assert signature(text) == reference, text


# the voice the new rule was written for in the default run; every voice in the `sweep` run (a style is about
# two seconds of reading)
@pytest.mark.parametrize(
    "style", [s if s == "nonnative" else pytest.param(s, marks=pytest.mark.sweep) for s in sorted(DEV_H138)]
)
def test_h138_development_voices_give_the_tasks_and_order(style: str) -> None:
    _check(DEV_H138, style)



@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(VALID_H138))
def test_h138_held_out_voices_are_read_right_or_refused(style: str) -> None:
    """Held out: each wording gives the tasks and order, or the command refuses it; never another plan."""
    for task_id, texts in VALID_H138[style].items():
        reference = signature(TASKS[task_id].instruction)
        for text in texts:
            assert refused(text) or signature_or_none(text) == reference, text



def test_a_step_finished_without_a_subject_is_a_step_done() -> None:
    assert _UNSAID_DONE.sub(r"\g<when> that is done", "when is finish, place") == "when that is done, place"
    assert _UNSAID_DONE.sub(r"\g<when> that is done", "after finish this.") == "after that is done."
    # with an object "finish" names a task: left as said
    said = "after finishing the orange, place the carrot"
    assert _UNSAID_DONE.sub(r"\g<when> that is done", said) == said


# h142 (session 24): a hurried supervisor, a teacher, a spec sheet and a phone message; the spec sheet's voice
# in the default run (its labelled steps and the remark that restates their order), every voice in `sweep`
@pytest.mark.parametrize(
    "style", [s if s == "spec_sheet" else pytest.param(s, marks=pytest.mark.sweep) for s in sorted(DEV_H142)]
)
def test_h142_development_voices_give_the_tasks_and_order(style: str) -> None:
    for task_id, texts in DEV_H142[style].items():
        reference = signature(TASKS[task_id].instruction)
        for text in texts:
            assert refused(text) or signature(text) == reference, text


@pytest.mark.sweep
@pytest.mark.parametrize("style", sorted(VALID_H142))
def test_h142_held_out_voices_are_read_right_or_refused(style: str) -> None:
    for task_id, texts in VALID_H142[style].items():
        reference = signature(TASKS[task_id].instruction)
        for text in texts:
            assert refused(text) or signature_or_none(text) == reference, text


def test_a_remark_that_keeps_the_steps_order_is_dropped_only_beside_steps() -> None:
    steps = "first a on p. then b on q."
    assert order_confirmed_dropped("1. a on p. 2. b on q. Please keep that sequence.", False).split() == [
        "1.", "a", "on", "p.", "2.", "b", "on", "q."
    ]
    restated = "Step 1: a on p. Step 2: b on q. Constraint: step 2 starts after step 1 is done."
    assert "Constraint" not in order_confirmed_dropped(restated, False)
    # no steps: nothing to keep; a list freed as a whole: the remark says the opposite; a step said after
    # another than the one before it: each stays, to be refused
    assert "sequence" in order_confirmed_dropped(steps + " Please keep that sequence.", False)
    assert "sequence" in order_confirmed_dropped("1. a on p. 2. b on q. Please keep that sequence.", True)
    backwards = "Step 1: a on p. Step 2: b on q. Step 1 starts after step 2 is done."
    assert order_confirmed_dropped(backwards, False) == backwards


def test_numbered_goals_are_no_steps() -> None:
    """A spec sheet's "Goal 1: ... Goal 2: ..." (h142's held-out VALID_H142, where it was read as two ordered
    steps on first contact) lists: never read as first / then; "Step 1: ... Step 2: ..." still orders."""
    goals = "Goal 1: green apple -> blue plate\nGoal 2: orange -> yellow plate"
    assert refused(goals) or signature(goals) == signature(TASKS[1].instruction)
    steps = "Step 1: green apple -> blue plate\nStep 2: orange -> yellow plate"
    assert signature(steps) != signature(TASKS[1].instruction)
