"""The docstring examples are run, so they stay true."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "nl2hltl2plan.io",
    "nl2hltl2plan.logic.atom",
    "nl2hltl2plan.domain.object_state",
    "nl2hltl2plan.language.parsers",
    "nl2hltl2plan.argtypes",
    "nl2hltl2plan.pipeline",
    "nl2hltl2plan.logic.trace",
    "nl2hltl2plan.worlds.starts",
    "nl2hltl2plan.language.learned.ranker",
    "nl2hltl2plan.domain.task_kinds",
    "nl2hltl2plan.logic.action_sequences",
    "nl2hltl2plan.language.restated_tasks",
    "nl2hltl2plan.language.handover_discourse",
    "nl2hltl2plan.language.handover_narration",
    "nl2hltl2plan.language.grammar.places_again",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name: str) -> None:
    result = doctest.testmod(importlib.import_module(name))
    assert result.attempted > 0 and result.failed == 0
