"""The household reader's reading of an instruction as its tests compare it: the task summaries and the
order, as `translate` gives them for a floor plan's world (a partial reading fails the test)."""

from __future__ import annotations

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.alfred.conversion import scenario_world
from nl2hltl2plan.worlds.world import World


def shared_world(plan: str, trials: tuple[str, ...] | list[str] = ()) -> World:
    """`load_world(plan, trials)`, built once per test process (the `world` fixture's cache, and the
    trust sets' `world_of`): `translate` only reads a world, and many test modules read in the same few."""
    return scenario_world({"scene": plan, "source_trials": list(trials)})


def reading(text: str, world: World) -> tuple[list[str], list[tuple[str, str]]]:
    """(the tasks' summaries, the order as task-id pairs); asserts the reading is complete."""
    res = translate(text, world, build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks], res.before


def full_reading(text: str, world: World) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    """(the tasks' summaries, the order sorted, what is left unread, the prohibitions described), partial
    or not: for tests that assert what a reading leaves unread or forbids."""
    res = translate(text, world, build=False, actions="none")
    forbids = [c.describe() for c in res.constraint_specs]
    return [t.summary() for t in res.tasks], sorted(res.before), res.unparsed, forbids


def refusal(text: str, world: World) -> str:
    """Why `plan` refuses the instruction: the error's message, or a partial reading's unread parts joined;
    "" where it reads completely."""
    try:
        res = translate(text, world, build=False, actions="none")
    except Nl2Hltl2PlanError as exc:
        return str(exc)
    return "; ".join(res.unparsed) if res.partial else ""


def outcome(text: str, world: World) -> list[str] | str:
    """The tasks' summaries, or "refused" / "partial"."""
    try:
        res = translate(text, world, build=False, actions="none")
    except Nl2Hltl2PlanError:
        return "refused"
    return "partial" if res.partial else [t.summary() for t in res.tasks]


def result_or_none(text: str, plan: str) -> LanguageResult | None:
    """`translate`'s result in the floor plan's shared world, or None where it refuses (the trust probes)."""
    try:
        return translate(text, shared_world(plan), build=False, actions="none")
    except Nl2Hltl2PlanError:
        return None


def plan_refusal(text: str, plan: str, capsys: pytest.CaptureFixture[str]) -> str:
    """What `nl2hltl2plan plan TEXT --world PLAN` prints on stderr, asserting it refuses (exit 2)."""
    assert main(["plan", text, "--world", plan]) == 2
    return capsys.readouterr().err
