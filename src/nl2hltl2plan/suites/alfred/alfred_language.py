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

from collections.abc import Callable, Iterable
from pathlib import Path

from nl2hltl2plan.errors import LLMError, Nl2Hltl2PlanError
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.translate import top_candidates
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.pipeline import PipelineOptions, language_stage, planning_stage
from nl2hltl2plan.suites.alfred.alfred_bench import instance_fields
from nl2hltl2plan.suites.rows import LanguageRecord, ScenarioRow
from nl2hltl2plan.suites.runner import Row, Scenario, load_rows
from nl2hltl2plan.worlds.floor_plans import build_benchmark_world
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


def language_record(gt: GTInstance, options: PipelineOptions, client: LLMClient | None) -> LanguageRecord:
    """Run the language stage on one instruction and score it against the ground truth."""
    world = build_benchmark_world(gt)
    rec = LanguageRecord(key=gt.id, instance=gt.id, n_base=gt.n_base, backend=options.backend)
    lenient = options.model_copy(update={"strict": False})
    try:
        result = language_stage(gt.instruction, world, lenient, client, ask=top_candidates)
    except LLMError as exc:  # a dead LLM is an error of the run, not an answer about the instruction
        return rec.model_copy(update={"error": str(exc), "errored": True, "stage": "task decomposition"})
    except Nl2Hltl2PlanError as exc:
        # a task this world cannot provide (no such object, a receptacle that refuses it): the
        # conversion is still scored; planning fails with this reason
        rec.error = str(exc)
        try:
            result = language_stage(
                gt.instruction,
                world,
                lenient.model_copy(update={"actions": "none"}),
                client,
                ask=top_candidates,
            )
        except LLMError as exc2:
            return rec.model_copy(update={"error": str(exc2), "errored": True, "stage": "task decomposition"})
        except Nl2Hltl2PlanError as exc2:
            return rec.model_copy(update={"error": str(exc2), "stage": "task decomposition"})
    verdict = match(result.tasks, result.before, [t.model_dump() for t in gt.tasks], gt.before)
    rec = rec.model_copy(
        update={
            "ok": result.spec is not None,
            "tasks": [t.model_dump() for t in result.tasks],
            "before": [list(p) for p in result.before],
            "unparsed": result.unparsed,
            "issues": result.issues,
            "assumptions": result.assumptions,
            "ltl_checks": result.ltl_checks,
            "llm_calls": result.llm_calls,
            "levels": result.spec.to_json_obj() if result.spec is not None else None,
            "constraints": [c.to_json() for c in result.spec.constraints] if result.spec is not None else [],
            "tasks_ok": verdict.tasks_ok,
            "partial": result.partial,
            "conversion_ok": verdict.order_ok and not result.partial,
            "match_reasons": verdict.reasons,
        }
    )
    if not verdict.tasks_ok or result.partial:
        rec.stage = "task decomposition"
    elif not verdict.order_ok:
        rec.stage = "temporal extraction"
    elif result.spec is None and rec.error is None:
        rec.stage = "LTL translation"
    return rec


def translate_instances(
    gts: Iterable[GTInstance],
    options: PipelineOptions,
    client: LLMClient | None,
    out: Path,
    progress: Callable[[GTInstance], None] | None = None,
) -> dict[str, LanguageRecord]:
    """Language records for every instance, reusing those already in `out` (JSON lines)."""
    # records of a failed LLM are not answers: they run again
    records = {
        k: rec for k, v in load_rows(out).items() if not (rec := LanguageRecord.model_validate(v)).errored
    }
    with out.open("a") as fh:
        for gt in gts:
            if gt.id not in records:
                rec = language_record(gt, options, client)
                records[gt.id] = rec
                fh.write(rec.model_dump_json() + "\n")
                fh.flush()
            if progress:
                progress(gt)
    return records


def language_job(
    records: dict[str, LanguageRecord], gts: dict[str, GTInstance], options: PipelineOptions
) -> Callable[[Scenario], Row]:
    """A `run_scenarios` job planning from the language stage's spec of the scenario's instruction."""

    def job(scenario: Scenario) -> Row:
        gt = gts[scenario.instance]
        rec = records[scenario.instance]
        world = build_benchmark_world(gt)
        starts = start_cells(world, scenario.robots, gt=gt, draw=scenario.draw)
        base = {
            **instance_fields(world, gt, starts),
            "conversion_ok": rec.conversion_ok,
            "partial": rec.partial,
        }
        if rec.errored:  # the LLM failed: the scenario errored (the run exits 1, a resume reruns it)
            return ScenarioRow.model_validate(
                {**base, "status": "error", "reason": f"LLM failed: {rec.error}", "planning_ok": False}
            ).to_json()
        if not rec.levels:
            # no spec: either the language stage failed, or the tasks cannot be grounded in this
            # world (then the planner has nothing to plan: a planning failure, like infeasible)
            return ScenarioRow.model_validate(
                {
                    **base,
                    "status": "infeasible" if rec.error else "no_spec",
                    "reason": rec.error or "no specification",
                    "planning_ok": False,
                    "stage": rec.stage or "planning",
                }
            ).to_json()
        spec = HierarchicalSpec.from_json({"levels": rec.levels, "constraints": rec.constraints})
        row = ScenarioRow.from_planned(planning_stage(world, spec, starts, options, gt), **base)
        row.planning_ok = row.status == "solved"
        row.stage = failure_stage(rec, row)
        return row.to_json()

    return job


def failure_stage(rec: LanguageRecord, row: ScenarioRow) -> str | None:
    """The first stage that went wrong for a scenario (None: overall success)."""
    if row.success:
        return None
    if rec.stage:
        return rec.stage
    if not row.planning_ok:
        return "planning"
    # a goal the plan never reached although the spec was right: the leaf actions were wrong
    return "action completion" if "never reached" in " ".join(row.check_reasons) else "execution"
