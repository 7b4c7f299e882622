"""The ALFRED benchmark: scenarios (instance x team size), the oracle-spec job, plan + execute + check.

`plan_and_check(world, spec, gt, starts, ...)` is the generic step every benchmark job ends with,
whatever produced the spec (oracle converter here, the language stage with --llm): plan, execute
(done inside `planning.plan`, which refuses to return an unverified plan) and judge the execution
with the ground-truth goal checker (goals and strict `before` order).
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from nl2hltl2plan.errors import DataError
from nl2hltl2plan.evaluation.runner import Row, Scenario
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning import oracle_spec, plan
from nl2hltl2plan.worlds.alfred import benchmark_issues, build_benchmark_world, start_cells
from nl2hltl2plan.worlds.benchmark import gt_instance, load_gt
from nl2hltl2plan.worlds.checker import check
from nl2hltl2plan.worlds.model import Cell, World
from nl2hltl2plan.worlds.tasks import GTInstance


def load_gt_file(path: Path | None = None) -> dict[str, GTInstance]:
    """Ground-truth instances by id: the benchmark's file, or any JSONL file with its schema."""
    if path is None:
        return {g.id: g for g in load_gt()}
    try:
        lines = [line for line in Path(path).read_text().splitlines() if line.strip()]
    except OSError as exc:
        raise DataError(f"cannot read ground truth {path}: {exc.strerror}") from None
    out: dict[str, GTInstance] = {}
    for k, line in enumerate(lines, start=1):
        try:
            gt = GTInstance.model_validate(json.loads(line))
        except (json.JSONDecodeError, ValidationError) as exc:
            raise DataError(
                f"{path}:{k} is not a ground-truth instance: {str(exc).splitlines()[0]}"
            ) from None
        out[gt.id] = gt
    return out


def alfred_scenarios(
    robots: Sequence[int] = (1, 2, 4),
    n_base: Sequence[int] | None = None,
    limit: int | None = None,
    draw: int = 0,
    ids: Sequence[str] | None = None,
    gts: Sequence[GTInstance] | None = None,
) -> list[Scenario]:
    """Instances in file order (filtered by `n_base` / `ids`, the first `limit`) x team sizes."""
    pool = load_gt() if gts is None else gts
    insts = [g for g in pool if (n_base is None or g.n_base in n_base) and (ids is None or g.id in ids)]
    if limit is not None:
        insts = insts[:limit]
    return [Scenario(g.id, g.n_base, r, draw) for g in insts for r in robots]


def plan_and_check(
    world: World,
    spec: HierarchicalSpec,
    gt: GTInstance,
    starts: Sequence[Cell],
    **planner: Any,
) -> Row:
    """Plan, then judge the executed plan with the goal checker; one JSON-ready row."""
    result = plan(world, spec, starts, **planner)
    row: Row = result.to_dict(with_plan=False)
    row["events"] = result.events
    row["success"] = False
    if result.solved and result.execution is not None:
        verdict = check(result.execution, gt)
        row["success"] = verdict.success
        row["check_reasons"] = verdict.reasons
        row["goal_steps"] = verdict.goal_steps
    return row


def oracle_job(
    objective: str = "min",
    mode: str = "fast",
    timeout_s: float = 300.0,
    gts: dict[str, GTInstance] | None = None,
    **planner: Any,
):
    """A job for `run_scenarios`: oracle spec of the instance -> plan -> execute -> check."""

    def job(scenario: Scenario) -> Row:
        gt = gts[scenario.instance] if gts is not None else gt_instance(scenario.instance)
        world = build_benchmark_world(gt)
        issues = benchmark_issues(world, gt)
        spec = oracle_spec(gt, world).spec
        starts = start_cells(world, gt, scenario.robots, scenario.draw)
        row = plan_and_check(
            world, spec, gt, starts, objective=objective, mode=mode, timeout_s=timeout_s, **planner
        )
        row["feasible"] = not issues
        row["issues"] = issues
        row["gt_feasible"] = gt.feasible
        # a perfect translation: conversion succeeds by construction; the rest is the planner's
        row["conversion_ok"] = True
        row["planning_ok"] = row.get("status") == "solved"
        row["stage"] = None if row["success"] else ("execution" if row["planning_ok"] else "planning")
        row["ambiguous"] = gt.ambiguous
        row["starts"] = [list(c) for c in starts]
        return row

    return job


def preload() -> None:
    """Load the ground truth and ALFRED data once in the parent (workers are forked from it)."""
    from nl2hltl2plan.worlds.alfred import alfred_data

    load_gt()
    alfred_data()
