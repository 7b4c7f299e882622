"""The ALFRED benchmark: scenarios (instance x team size), the oracle-spec job, plan + execute + check.

Every job ends with `pipeline.planning_stage`, whatever produced the spec (the oracle converter here,
the language stage with --llm): plan, execute (inside `planning.plan`, which refuses to return an
unverified plan) and judge the execution with the ground-truth goal checker (goals and strict
`before` order); `planned_row` turns that into the scenario's row.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from nl2hltl2plan.evaluation.runner import Row, Scenario
from nl2hltl2plan.pipeline import PipelineOptions, Planned, planning_stage
from nl2hltl2plan.planning import oracle_spec
from nl2hltl2plan.worlds.alfred import benchmark_issues, build_benchmark_world
from nl2hltl2plan.worlds.benchmark import gt_instance, load_gt
from nl2hltl2plan.worlds.starts import start_cells
from nl2hltl2plan.worlds.tasks import GTInstance


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


def planned_row(planned: Planned) -> Row:
    """The planner's result and the goal checker's verdict as one JSON-ready row."""
    result = planned.result
    row: Row = result.to_dict(with_plan=False)
    row["events"] = result.events
    row["success"] = planned.success
    if planned.check is not None:
        row["check_reasons"] = planned.check.reasons
        row["goal_steps"] = planned.check.goal_steps
    return row


def oracle_job(
    options: PipelineOptions | None = None, gts: dict[str, GTInstance] | None = None
) -> Callable[[Scenario], Row]:
    """A job for `run_scenarios`: oracle spec of the instance -> plan -> execute -> check."""

    def job(scenario: Scenario) -> Row:
        gt = gts[scenario.instance] if gts is not None else gt_instance(scenario.instance)
        world = build_benchmark_world(gt)
        issues = benchmark_issues(world, gt)
        spec = oracle_spec(gt, world).spec
        starts = start_cells(world, scenario.robots, gt=gt, draw=scenario.draw)
        row = planned_row(planning_stage(world, spec, starts, options, gt))
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
