"""The ALFRED benchmark: scenarios (instance x team size), the oracle-spec job, plan + execute + check.

Every job ends with `pipeline.planning_stage`, whatever produced the spec (the oracle converter here,
the language stage with --llm): plan, execute (inside `planning.plan`, which refuses to return an
unverified plan) and judge the execution with the ground-truth goal checker (goals and strict
`before` order); `ScenarioRow.from_planned` turns that into the scenario's row.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from nl2hltl2plan.pipeline import PipelineOptions, planning_stage
from nl2hltl2plan.planning import oracle_spec
from nl2hltl2plan.suites.alfred.ground_truth import gt_instance, load_gt
from nl2hltl2plan.suites.rows import ScenarioRow
from nl2hltl2plan.suites.runner import Row, Scenario
from nl2hltl2plan.worlds.floor_plans import benchmark_issues, build_benchmark_world
from nl2hltl2plan.worlds.starts import start_cells
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.world import Cell, World


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


def instance_fields(world: World, gt: GTInstance, starts: list[Cell]) -> dict[str, Any]:
    """What every row says about its instance: can this world do it, how the annotators judged it."""
    issues = benchmark_issues(world, gt)
    return {
        "feasible": not issues,
        "issues": issues,
        "gt_feasible": gt.feasible,
        "ambiguous": gt.ambiguous,
        "starts": [list(c) for c in starts],
    }


def oracle_job(
    options: PipelineOptions | None = None, gts: dict[str, GTInstance] | None = None
) -> Callable[[Scenario], Row]:
    """A job for `run_scenarios`: oracle spec of the instance -> plan -> execute -> check."""

    def job(scenario: Scenario) -> Row:
        gt = gts[scenario.instance] if gts is not None else gt_instance(scenario.instance)
        world = build_benchmark_world(gt)
        starts = start_cells(world, scenario.robots, gt=gt, draw=scenario.draw)
        spec = oracle_spec(gt, world).spec
        # a perfect translation: conversion succeeds by construction; the rest is the planner's
        row = ScenarioRow.from_planned(
            planning_stage(world, spec, starts, options, gt),
            conversion_ok=True,
            **instance_fields(world, gt, starts),
        )
        row.planning_ok = row.status == "solved"
        row.stage = None if row.success else ("execution" if row.planning_ok else "planning")
        return row.to_json()

    return job


def preload() -> None:
    """Load the ground truth and ALFRED data once in the parent (workers are forked from it)."""
    from nl2hltl2plan.worlds.floor_plans import alfred_data

    load_gt()
    alfred_data()
