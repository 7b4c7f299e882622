"""A handover sentence read for the tests: the spec it gives on an instance of its Table III task, and
the checks that compare it with the task's written spec node by node (Spot equivalence)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import pytest
from handover_session10 import STYLES

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.suites.handover.handover_bench import instance, load_tasks, specs_equivalent

TASKS = {t.id: t for t in load_tasks()}


def cases(*tables: dict[int, list[str]]) -> list[tuple[int, str]]:
    """(task, sentence) pairs of tables {task: [sentences]}, in order: the tests' parameters."""
    return [(task, text) for table in tables for task, texts in table.items() for text in texts]


def spec_of(task_id: int, text: str, k: int = 0) -> HierarchicalSpec:
    """The spec `text` gives on instance `k` of task `task_id` (HTTError when it is refused)."""
    result = translate(text, instance(TASKS[task_id], 0, k).as_world())
    assert result.spec is not None
    return result.spec


def _spec_or_refused(task_id: int, text: str) -> HierarchicalSpec | None:
    """The spec `text` gives, or None where it is refused (with a one-line error, checked here)."""
    try:
        return spec_of(task_id, text)
    except HTTError as exc:
        assert "\n" not in str(exc)
        return None


def assert_refused_by_name(task_id: int, text: str) -> None:
    """`text` is refused, with a one-line error (that names what it could not use)."""
    assert _spec_or_refused(task_id, text) is None, text


def assert_not_the_written_spec(task_id: int, text: str) -> None:
    """A near miss is refused with a one-line error, or gives another spec: never the written one."""
    spec = _spec_or_refused(task_id, text)
    if spec is not None:
        equal, _ = specs_equivalent(spec, TASKS[task_id].hierarchical())
        assert not equal


def assert_written_spec(task_id: int, text: str, k: int = 0) -> None:
    """`text` gives the task's written spec, node by node (the failure says which node differs)."""
    equal, why = specs_equivalent(spec_of(task_id, text, k), TASKS[task_id].hierarchical())
    assert equal, why


def assert_written_spec_or_refused(task_id: int, text: str) -> None:
    """A held-out or development sentence is refused with a one-line error (honest, a failure for the
    benchmark) or gives the task's written spec: never another one."""
    spec = _spec_or_refused(task_id, text)
    if spec is not None:
        equal, why = specs_equivalent(spec, TASKS[task_id].hierarchical())
        assert equal, (text, why)


Pairs = Sequence[tuple[int, str]]


def round_tests(
    read: dict[int, list[str]], refused: Pairs, near_misses: Pairs, batches: Sequence[str]
) -> tuple[Callable[..., None], ...]:
    """The four tests each round of handover wordings runs over its own tables, bound to module names
    by the round's file: its new forms give the written spec, its unclear forms are refused by name, its
    near misses never give the written spec, and (`sweep`) its committed batches are read right or
    refused, never misread."""

    @pytest.mark.data
    @pytest.mark.parametrize(("task", "text"), cases(read))
    def written(task: int, text: str) -> None:
        assert_written_spec(task, text)

    @pytest.mark.data
    @pytest.mark.parametrize(("task", "text"), refused)
    def refused_by_name(task: int, text: str) -> None:
        assert_refused_by_name(task, text)

    @pytest.mark.data
    @pytest.mark.parametrize(("task", "text"), near_misses)
    def not_written(task: int, text: str) -> None:
        assert_not_the_written_spec(task, text)

    @pytest.mark.sweep
    @pytest.mark.data
    @pytest.mark.parametrize(("batch", "style"), [(b, s) for b in batches for s in STYLES[b]])
    def batches_read(batch: str, style: str) -> None:
        for task, text in STYLES[batch][style].items():
            assert_written_spec_or_refused(int(task), text)

    return written, refused_by_name, not_written, batches_read
