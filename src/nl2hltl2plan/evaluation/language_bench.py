"""The full pipeline on the benchmark: instruction -> language stage -> spec -> planner -> checker.

Two phases, so an LLM is asked once per instruction (not once per team size) and no worker process
has to start its own model server:
1. `translate_instances` runs the language stage on every selected instruction in the parent
   (answers cached by the LLM client), scores the conversion against the ground truth, and appends
   one record per instruction to `language.jsonl` (a rerun reuses finished records);
2. `language_job` plans every scenario (instruction x team size) from its record's spec in the
   worker processes of `runner.run_scenarios`, executes the plan and judges it with the checker.

Success is judged three ways, as in the paper's Table I: conversion (the generated base tasks match
the ground truth within the accepted types, and the orderings have the same transitive closure),
planning (a plan was found for the generated spec), overall (the executed plan meets every
ground-truth goal and order). Each failure is attributed to the first stage that went wrong, in the
order of the paper's Table IV plus planning and execution.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from pathlib import Path

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.evaluation.alfred import planned_row
from nl2hltl2plan.evaluation.runner import Row, Scenario, load_rows
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.pipeline import PipelineOptions, language_stage, planning_stage
from nl2hltl2plan.worlds.alfred import benchmark_issues, build_benchmark_world
from nl2hltl2plan.worlds.starts import start_cells
from nl2hltl2plan.worlds.tasks import GTInstance

STAGES = (
    "task decomposition",
    "temporal extraction",
    "LTL translation",
    "action completion",
    "planning",
    "execution",
)


def language_record(gt: GTInstance, options: PipelineOptions, client: LLMClient | None) -> Row:
    """Run the language stage on one instruction and score it against the ground truth."""
    world = build_benchmark_world(gt)
    rec: Row = {"key": gt.id, "instance": gt.id, "n_base": gt.n_base, "backend": options.backend}
    grounding_error = None
    lenient = options.model_copy(update={"strict": False})
    try:
        result = language_stage(gt.instruction, world, lenient, client)
    except Nl2Hltl2PlanError as exc:
        # a task this world cannot provide (no such object, a receptacle that refuses it): the
        # conversion is still scored; planning fails with this reason
        grounding_error = str(exc)
        try:
            result = language_stage(
                gt.instruction, world, lenient.model_copy(update={"actions": "none"}), client
            )
        except Nl2Hltl2PlanError as exc2:
            rec.update(
                ok=False, error=str(exc2), conversion_ok=False, stage="task decomposition", levels=None
            )
            return rec
    verdict = match(result.tasks, result.before, [t.model_dump() for t in gt.tasks], gt.before)
    rec.update(
        ok=result.spec is not None,
        error=grounding_error,
        tasks=[t.model_dump() for t in result.tasks],
        before=[list(p) for p in result.before],
        unparsed=result.unparsed,
        issues=result.issues,
        ltl_checks=result.ltl_checks,
        llm_calls=result.llm_calls,
        levels=result.spec.to_json_obj() if result.spec is not None else None,
        tasks_ok=verdict.tasks_ok,
        conversion_ok=verdict.order_ok,
        match_reasons=verdict.reasons,
    )
    if not verdict.tasks_ok:
        rec["stage"] = "task decomposition"
    elif not verdict.order_ok:
        rec["stage"] = "temporal extraction"
    elif result.spec is None and grounding_error is None:
        rec["stage"] = "LTL translation"
    else:
        rec["stage"] = None
    return rec


def translate_instances(
    gts: Iterable[GTInstance],
    options: PipelineOptions,
    client: LLMClient | None,
    out: Path,
    progress: Callable[[GTInstance], None] | None = None,
) -> dict[str, Row]:
    """Language records for every instance, reusing those already in `out` (JSON lines)."""
    records = load_rows(out)
    with out.open("a") as fh:
        for gt in gts:
            if gt.id not in records:
                rec = language_record(gt, options, client)
                records[gt.id] = rec
                fh.write(json.dumps(rec) + "\n")
                fh.flush()
            if progress:
                progress(gt)
    return records


def language_job(
    records: dict[str, Row], gts: dict[str, GTInstance], options: PipelineOptions
) -> Callable[[Scenario], Row]:
    """A `run_scenarios` job planning from the language stage's spec of the scenario's instruction."""

    def job(scenario: Scenario) -> Row:
        gt = gts[scenario.instance]
        rec = records[scenario.instance]
        world = build_benchmark_world(gt)
        issues = benchmark_issues(world, gt)
        starts = start_cells(world, scenario.robots, gt=gt, draw=scenario.draw)
        base: Row = {
            "feasible": not issues,
            "issues": issues,
            "gt_feasible": gt.feasible,
            "ambiguous": gt.ambiguous,
            "starts": [list(c) for c in starts],
            "conversion_ok": bool(rec.get("conversion_ok")),
        }
        if not rec.get("levels"):
            # no spec: either the language stage failed, or the tasks cannot be grounded in this
            # world (then the planner has nothing to plan: a planning failure, like infeasible)
            return {
                **base,
                "status": "infeasible" if rec.get("error") else "no_spec",
                "reason": rec.get("error") or "no specification",
                "success": False,
                "planning_ok": False,
                "stage": rec.get("stage") or "planning",
            }
        spec = HierarchicalSpec.from_json(rec["levels"])
        row = planned_row(planning_stage(world, spec, starts, options, gt))
        row.update(base)
        row["planning_ok"] = row.get("status") == "solved"
        row["stage"] = failure_stage(rec, row)
        return row

    return job


def failure_stage(rec: Row, row: Row) -> str | None:
    """The first stage that went wrong for a scenario (None: overall success)."""
    if row.get("success"):
        return None
    if rec.get("stage"):
        return str(rec["stage"])
    if not row.get("planning_ok"):
        return "planning"
    reasons = " ".join(row.get("check_reasons") or [])
    # a goal the plan never reached although the spec was right: the leaf actions were wrong
    return "action completion" if "never reached" in reasons else "execution"
