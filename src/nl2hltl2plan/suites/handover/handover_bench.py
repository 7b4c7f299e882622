"""`bench handover`: the paper's four-arm handover study (Section IV-C, Table III).

Each of the eight tasks has its hierarchical spec written as data (`data/handover_tasks.json`, with
the reading of the task text it encodes). For each task and each seeded instance (block placement
and arm poses), the cooperative planner (`planning.coop`, a budget in expansions) plans from the
written spec or, with a language backend, from the language stage's spec of the instruction on that
instance (the paper's whole pipeline); the plan is executed step by step by the handover simulator
and judged against the written spec. `language_equal` says whether the language stage's spec equals
the written one node by node (`specs_equivalent`: Spot equivalence). The report gives success rate,
cost and runtime per task beside the paper's Table III.
"""

from __future__ import annotations

import itertools
import json
from importlib import resources
from pathlib import Path
from typing import Any

from pydantic import BaseModel

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.io import write_json, write_text
from nl2hltl2plan.language.backends import Backend
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.coop import MAX_EXPANSIONS, CoopResult, coop_plan
from nl2hltl2plan.planning.results import PlanStatus
from nl2hltl2plan.suites.handover.handover_llm import llm_handover
from nl2hltl2plan.suites.summaries import mean_std, pm
from nl2hltl2plan.worlds.handover_world import (
    HandoverWorld,
    check_handover,
    execute_handover,
    random_instance,
)

DEFAULT_INSTANCES = 10


class HandoverTask(BaseModel):
    id: int
    config: str
    instruction: str
    placement: dict[str, list[str]]
    reading: str
    spec: list[dict[str, Any]]
    paper: dict[str, float]

    def hierarchical(self) -> HierarchicalSpec:
        return HierarchicalSpec.from_json(self.spec)


def load_tasks() -> list[HandoverTask]:
    text = resources.files("nl2hltl2plan.suites.handover").joinpath("handover_tasks.json").read_text()
    return [HandoverTask.model_validate(t) for t in json.loads(text)["tasks"]]


def instance(task: HandoverTask, seed: int, k: int) -> HandoverWorld:
    return random_instance(task.config, task.placement, seed * 100_000 + task.id * 1000 + k)


def judge(hw: HandoverWorld, spec: HierarchicalSpec, result: CoopResult) -> tuple[bool, list[str]]:
    """Re-execute a plan in the simulator and check it against the spec (independent of the planner)."""
    if not result.solved or result.plan is None:
        return False, [f"{result.status}: {result.reason}"]
    execution = execute_handover(hw, result.plan, sorted(spec.atoms()))
    verdict = check_handover(spec, execution)
    return execution.ok and verdict.ok, execution.violations[:2] + verdict.reasons[:2]


def run_task(
    task: HandoverTask,
    instances: int,
    seed: int,
    client: Any = None,
    backend: Backend | None = None,
    **plan_kw: Any,
) -> dict[str, Any]:
    """Plan every instance, from the written spec or (with `backend`) from the language stage's spec of
    the instruction on that instance; a plan succeeds when it satisfies the written (reference) spec."""
    reference = task.hierarchical()
    rows: list[dict[str, Any]] = []
    llm: list[dict[str, Any]] = []
    for k in range(instances):
        hw = instance(task, seed, k)
        if client is not None:
            llm.append(llm_handover(hw, reference, task.instruction, client))
        row: dict[str, Any] = {
            "instance": k,
            "blocks": {b: hw.start_region(b) for b in hw.block_names()},
            "arm_starts": [list(c) for c in hw.arm_starts],
        }
        spec: HierarchicalSpec | None = reference
        if backend is not None:
            lang = language_check(task, hw, backend)
            row["language_equal"] = lang["language_equal"]
            row["language_why"] = lang["why"]
            spec = lang.get("spec")
        result = (
            coop_plan(hw, spec, **plan_kw)
            if spec is not None
            else CoopResult(PlanStatus.ERROR, row["language_why"])
        )
        ok, reasons = judge(hw, reference, result)
        rows.append(
            {
                **row,
                "success": ok,
                "cost": result.cost,
                "travel": result.travel,
                "handovers": result.handovers,
                "proven_optimal": result.proven_optimal,
                "runtime_s": round(result.plan_time_s, 3),
                "expanded": result.expanded,
                "reasons": reasons,
            }
        )
    good = [r for r in rows if r["success"]]
    cost_mean, cost_std = mean_std([r["cost"] for r in good])
    rt_mean, rt_std = mean_std([r["runtime_s"] for r in rows])
    travel_mean, _ = mean_std([r["travel"] for r in good])
    handovers_mean, _ = mean_std([r["handovers"] for r in good])
    return {
        "id": task.id,
        "config": task.config,
        "instruction": task.instruction,
        "reading": task.reading,
        "instances": instances,
        "success_rate": len(good) / instances if instances else 0.0,
        "cost_mean": cost_mean,
        "cost_std": cost_std,
        "travel_mean": travel_mean,
        "handovers_mean": handovers_mean,
        "proven_optimal_rate": sum(r["proven_optimal"] for r in good) / instances if instances else 0.0,
        "runtime_mean_s": rt_mean,
        "runtime_std_s": rt_std,
        "language_equal": all(r.get("language_equal", False) for r in rows) if backend else None,
        "baseline": _baseline_row(llm),
        "paper": task.paper,
        "per_instance": rows,
    }


def _baseline_row(llm: list[dict[str, Any]]) -> dict[str, Any]:
    """The LLM-as-planner baseline over the instances ("not run" without an LLM: no invented numbers)."""
    if not llm:
        return {"name": "llm-planner", "status": "not run", "reason": "no LLM configured"}
    good = [r for r in llm if r["success"]]
    errored = sum(1 for r in llm if r.get("errored"))
    ran = len(llm) - errored
    cost_mean, cost_std = mean_std([r["cost"] for r in good])
    return {
        "name": "llm-planner",
        "status": "run",
        "errored": errored,  # instances where the LLM failed: not in the success rate
        "success_rate": len(good) / ran if ran else None,
        "cost_mean": cost_mean,
        "cost_std": cost_std,
        "runtime_mean_s": mean_std([r["runtime_s"] for r in llm])[0],
        "failures": [r["reasons"][:1] for r in llm if not r["success"]][:3],
    }


def specs_equivalent(a: HierarchicalSpec, b: HierarchicalSpec) -> tuple[bool, str]:
    """Node by node: the trees have the same shape and, under some matching of each node's children,
    every leaf formula and every non-leaf formula (children renamed) is Spot-equivalent."""
    ra, rb = a.roots, b.roots
    if len(ra) != 1 or len(rb) != 1:
        return False, f"roots {ra} and {rb}"
    ok = _match_nodes(a, ra[0], b, rb[0])
    return ok, "every node is Spot-equivalent" if ok else _first_difference(a, ra[0], b, rb[0])


def _match_nodes(a: HierarchicalSpec, x: str, b: HierarchicalSpec, y: str) -> bool:
    if a.is_leaf(x) != b.is_leaf(y):
        return False
    if a.is_leaf(x):
        return sb.equivalent(a.formula(x), b.formula(y))
    cx, cy = a.children(x), b.children(y)
    if len(cx) != len(cy):
        return False
    fits = {(i, j): _match_nodes(a, p, b, q) for i, p in enumerate(cx) for j, q in enumerate(cy)}
    for perm in itertools.permutations(range(len(cy))):
        if all(fits[i, j] for i, j in enumerate(perm)):
            rename = {cy[j]: sb.atom(cx[i]) for i, j in enumerate(perm)}
            if sb.equivalent(a.formula(x), b.formula(y).substitute(rename)):
                return True
    return False


def _first_difference(a: HierarchicalSpec, x: str, b: HierarchicalSpec, y: str) -> str:
    if a.is_leaf(x) or b.is_leaf(y) or len(a.children(x)) != len(b.children(y)):
        return f"{x} = {a.text(x)} against {y} = {b.text(y)}"
    for p in a.children(x):
        if not any(_match_nodes(a, p, b, q) for q in b.children(y)):
            return f"no node of the reference matches {p} = {a.text(p)}"
    return f"the relations of {x} differ: {a.text(x)} against {b.text(y)}"


def language_check(task: HandoverTask, hw: HandoverWorld, backend: Backend = "offline") -> dict[str, Any]:
    """The language stage's spec of the instruction on this instance, and whether it equals the written
    one node by node (`specs_equivalent`)."""
    from nl2hltl2plan.pipeline import PipelineOptions, language_stage

    try:
        language = language_stage(task.instruction, hw.as_world(), PipelineOptions(backend=backend))
    except Nl2Hltl2PlanError as exc:
        return {"converted": False, "language_equal": False, "why": f"language stage: {exc}"}
    if language.partial:  # part of the instruction was not understood: not a conversion
        why = f"not understood: {'; '.join(language.unparsed)}"
        return {"converted": False, "language_equal": False, "why": why}
    if language.spec is None:
        why = "; ".join(language.warnings) or "no spec"
        return {"converted": False, "language_equal": False, "why": why}
    equal, why = specs_equivalent(language.spec, task.hierarchical())
    return {
        "converted": True,
        "language_equal": equal,
        "why": why,
        "spec": language.spec,
        "spec_text": language.spec_text,
        "tasks": [t.summary() for t in language.tasks],
        "before": [list(p) for p in language.before],
        "constraints": language.constraints,
    }


def run_bench(
    out: Path,
    instances: int = DEFAULT_INSTANCES,
    seed: int = 0,
    task_ids: list[int] | None = None,
    picture: bool = True,
    client: Any = None,
    backend: Backend | None = None,
    max_expansions: int = MAX_EXPANSIONS,
) -> dict[str, Any]:
    """Run the handover bench; write DIR/summary.json, DIR/report.md and the plan pictures.

    `backend`: plan each instance from the language stage's spec of the instruction (the paper's whole
    pipeline) instead of the written spec; `language_equal` says whether it equals the written one."""
    tasks = [t for t in load_tasks() if task_ids is None or t.id in task_ids]
    rows = []
    for task in tasks:
        row = run_task(task, instances, seed, client, backend, max_expansions=max_expansions)
        lang = language_check(task, instance(task, seed, 0), backend or "offline")
        lang.pop("spec", None)
        row["language"] = lang
        if backend is None:
            row["language_equal"] = lang["language_equal"]
        rows.append(row)
    summary = {
        "bench": "handover",
        "instances": instances,
        "seed": seed,
        "specs": f"language stage ({backend}) per instance" if backend else "written (suites/data)",
        "planner_budget": f"{max_expansions} expansions per instance (deterministic)",
        "cost_unit": "end-effector moves + pick/put actions, summed over the four arms",
        "runtime": "planning wall time per instance (s)",
        "llm_planner": "run" if client is not None else "not run (no LLM configured)",
        "tasks": rows,
    }
    out.mkdir(parents=True, exist_ok=True)
    write_json(out / "summary.json", summary, "summary file")
    pictures = []
    if picture and tasks:
        pictures = draw_pictures(tasks, seed, out)
    write_text(out / "report.md", handover_markdown(summary, pictures), "report")
    return summary


def draw_pictures(tasks: list[HandoverTask], seed: int, out: Path) -> list[str]:
    """Both layouts, and a plan with its handovers for the first task of each configuration."""
    from nl2hltl2plan.present.handover_pictures import draw_handover
    from nl2hltl2plan.worlds.handover_world import handover_world

    names = []
    for config in ("square", "line"):
        draw_handover(handover_world(config), out / f"layout_{config}.png")
        names.append(f"layout_{config}.png")
    for config in ("square", "line"):
        task = next((t for t in tasks if t.config == config), None)
        if task is None:
            continue
        hw = instance(task, seed, 0)
        result = coop_plan(hw, task.hierarchical())
        if result.execution is not None:
            name = f"plan_task{task.id}.png"
            draw_handover(
                hw,
                out / name,
                result.execution,
                title=f"task {task.id} ({config}), cost {result.cost}, {result.handovers} handovers",
            )
            names.append(name)
    return names


def _llm_cell(baseline: dict[str, Any]) -> str:
    if baseline.get("status") != "run":
        return "not run"
    rate = baseline["success_rate"]
    return f"errored ({baseline['errored']})" if rate is None else f"{100 * rate:.0f}"


def handover_markdown(summary: dict[str, Any], pictures: list[str]) -> str:
    """report.md in the layout of the paper's Table III, with the paper's numbers."""
    tasks = summary["tasks"]
    ids = " | ".join(str(t["id"]) for t in tasks)
    sep = "|---" * (len(tasks) + 1) + "|"
    lines = [
        "# Four-arm handover study (paper Table III)",
        "",
        f"{summary['instances']} seeded instances per task (seed {summary['seed']}); tasks 1-5 on "
        "`handover-square`, 6-8 on `handover-line`. Cost = " + summary["cost_unit"] + ".",
        "",
        f"| Success rate (%) | {ids} |",
        sep,
        "| Ours (this repo) | " + " | ".join(f"{100 * t['success_rate']:.0f}" for t in tasks) + " |",
        "| Ours (paper) | " + " | ".join(f"{t['paper']['ours_pct']:g}" for t in tasks) + " |",
        "| LLM (paper) | " + " | ".join(f"{t['paper']['llm_pct']:g}" for t in tasks) + " |",
        "| LLM planner (this repo) | " + " | ".join(_llm_cell(t["baseline"]) for t in tasks) + " |",
        "",
        "| Task | cost | end-effector travel | handovers | proven optimal | runtime s |",
        "|---|---|---|---|---|---|",
    ]
    for t in tasks:
        travel = "—" if t["travel_mean"] is None else f"{t['travel_mean']:.1f}"
        handovers = "—" if t["handovers_mean"] is None else f"{t['handovers_mean']:.1f}"
        lines.append(
            f"| {t['id']} | {pm(t['cost_mean'], t['cost_std'])} | {travel} | {handovers} | "
            f"{100 * t['proven_optimal_rate']:.0f} % | {pm(t['runtime_mean_s'], t['runtime_std_s'])} |"
        )
    conv = [t for t in tasks if t["language_equal"]]
    lines += [
        "",
        f"Specs planned: {summary['specs']}; planner budget: {summary['planner_budget']}.",
        "",
        f"Language stage → a spec equal to the written one, node by node (Spot equivalence): {len(conv)} of "
        f"{len(tasks)} instructions.",
        "",
        "| Task | converted | language_equal | why | constraints |",
        "|---|---|---|---|---|",
    ]
    for t in tasks:
        lang = t["language"]
        why = str(lang.get("why", "")).replace("|", "/").replace("\n", " ")[:160]
        constraints = "; ".join(lang.get("constraints", [])).replace("|", "/")
        lines.append(
            f"| {t['id']} | {'yes' if lang['converted'] else 'no'} | "
            f"{'yes' if t['language_equal'] else 'no'} | {why} | {constraints} |"
        )
    lines += [
        "",
        "LLM-as-planner baseline (suites/handover/handover_llm.py: the instance's coordinates, the arms' "
        "reach, "
        "the API and the instruction; the answer is executed and checked like our plans): "
        + summary["llm_planner"]
        + ".",
        "",
        "## Tasks and readings",
        "",
    ]
    for t in tasks:
        lines.append(f"{t['id']}. {t['instruction']}  \n   *reading:* {t['reading']}")
    for pic in pictures:
        lines += ["", f"![{pic}]({pic})"]
    return "\n".join(lines) + "\n"
