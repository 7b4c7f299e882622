"""`bench smartllm`: SMART-LLM's 36 tasks, each planned for its own robot team and scored by
SMART-LLM's metrics (Kannan et al., arXiv:2309.10062; the scoring script is
`data/aithor_connect/end_thread.py` of github.com/SMARTlab-Purdue/SMART-LLM @ be42930):

- GCR (goal-condition recall): satisfied ground-truth conditions / all conditions, judged on the
  final state (a task with no condition scores 1, as in SMART-LLM's script). Each state and each
  contained object is one condition, met when some object of that name has it; the script instead
  adds 1 per matching object instance, which can exceed 1 (two items in the fridge) -- we do not.
- TC (task completion): 1 when GCR = 1.
- RU (robot utilisation): from the plan's number of sequential stages (`stages`: the longest chain
  of leaves each ordered after, done by the same robot after, or started after the previous), with
  SMART-LLM's formula on trans + 1 and max_trans + 1: 1 when stages = trans + 1 = max_trans + 1,
  0 when max_trans = trans otherwise, else (max + 1 - stages) / (max - trans), clipped to 0..1.
- Exe (executability): successful actions / attempted actions of the executed plan (0 when no
  plan was made: nothing could be executed).
- A task whose ground truth lists no condition is still planned from its instruction: with no spec
  or no plan (a refusal) it scores 0, never a vacuous success; only the oracle, which has nothing to
  plan, scores it complete.
- SR (success): TC = 1 and RU = 1; a task without a stage annotation has no RU and is left out of SR.
Each row also carries `script`: the five metrics exactly as SMART-LLM's own script computes them
(`suites.smartllm.smartllm_script`: per entry, +1 per match, no BROKEN check, RU unclipped).
A task whose team lacks a needed skill is reported infeasible with the reason, before planning; the
final state is then the initial one. The task without ground truth is listed, not scored.
"""

from __future__ import annotations

import json
import statistics
from collections.abc import Callable, Mapping, Sequence
from importlib import resources
from pathlib import Path
from typing import Any

import networkx as nx

from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.io import atomic_path, write_json, write_text
from nl2hltl2plan.language.backends import Backend
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.pipeline import PipelineOptions, planning_stage
from nl2hltl2plan.planning.objective import ObjectiveName
from nl2hltl2plan.suites.smartllm.smartllm_script import script_metrics
from nl2hltl2plan.suites.smartllm.smartllm_tasks import (
    SmartTask,
    load_tasks,
    oracle_spec,
    start_cells,
    world_for,
)
from nl2hltl2plan.worlds.checker import final_conditions
from nl2hltl2plan.worlds.effects import condition_holds
from nl2hltl2plan.worlds.simulator import Execution, SimState
from nl2hltl2plan.worlds.team import smartllm_team, spec_atoms
from nl2hltl2plan.worlds.world import CELL_M, World

METRICS = ("SR", "TC", "GCR", "RU", "Exe")
SpecMaker = Callable[[SmartTask, World], tuple[HierarchicalSpec, list[str]]]


def published() -> dict[str, Any]:
    """SMART-LLM's published numbers with their source (suites/smartllm/smartllm_published.json)."""
    text = resources.files("nl2hltl2plan.suites.smartllm").joinpath("smartllm_published.json").read_text()
    return json.loads(text)


def stages(result_events: Sequence[PlanEvent], pairs: Sequence[tuple[str, str]] = ()) -> int:
    """Sequential stages of a plan: the most leaves on a chain where each comes after the one before
    it -- ordered after it by the spec (`pairs`, leaf names), done by the same robot after it, or
    set off only once it had ended. A leaf's span runs from when its robot sets off for its first
    action (t minus the walk) to its last action; leaves on no common chain run in parallel."""
    spans: dict[str, list[float]] = {}
    robots: dict[str, set[int]] = {}
    for e in result_events:
        task = e.task
        if task is None:
            continue
        start = e.t - round(e.travel_m / CELL_M)
        span = spans.setdefault(task, [start, e.t])
        span[0], span[1] = min(span[0], start), max(span[1], e.t)
        robots.setdefault(task, set()).add(e.robot)
    ordered = set(pairs)
    graph = nx.DiGraph()
    graph.add_nodes_from(spans)
    for a, (sa, ea) in spans.items():
        for b, (sb, eb) in spans.items():
            after = (a, b) in ordered or ea < sb or (bool(robots[a] & robots[b]) and ea < eb and sa < sb)
            if a != b and after and (ea, sa, a) < (eb, sb, b):
                graph.add_edge(a, b)
    return nx.dag_longest_path_length(graph) + 1 if spans else 0


def leaf_pairs(spec: HierarchicalSpec) -> list[tuple[str, str]]:
    """The spec's "a before b" pairs between leaves (pairs of non-leaves expanded to their leaves)."""
    from nl2hltl2plan.logic import spot_backend as sb

    def under(name: str) -> list[str]:
        return [name] if spec.is_leaf(name) else [x for c in spec.children(name) for x in under(c)]

    out: list[tuple[str, str]] = []
    for name in spec.names:
        if spec.is_leaf(name):
            continue
        form = sb.precedence_form(spec.formula(name))
        for a, b in form[1] if form is not None else []:
            out += [(x, y) for x in under(a) for y in under(b)]
    return out


def robot_utilisation(n_stages: int, trans: int | None, max_trans: int | None) -> float | None:
    """SMART-LLM's RU (see the module docstring); None without trans / max_trans."""
    if trans is None or max_trans is None:
        return None
    gt, worst = trans + 1, max_trans + 1
    if worst == gt:
        return 1.0 if n_stages == gt else 0.0
    return min(1.0, max(0.0, (worst - n_stages) / (worst - gt)))


def oracle_maker(task: SmartTask, world: World) -> tuple[HierarchicalSpec, list[str]]:
    return oracle_spec(task, world)


def llm_maker(backend: Backend, client: Any = None) -> SpecMaker:
    """The instruction through the pipeline's language stage (`client`: an LLMClient for local/openai)."""

    def make(task: SmartTask, world: World) -> tuple[HierarchicalSpec, list[str]]:
        from nl2hltl2plan.errors import SpecError
        from nl2hltl2plan.pipeline import PipelineOptions, language_stage

        result = language_stage(task.text, world, PipelineOptions(backend=backend), client)
        if result.partial:  # part of the task was not understood: a conversion failure, never a plan
            raise SpecError(f"not understood: {'; '.join(result.unparsed)}")
        spec = result.spec
        if spec is None:
            why = "; ".join(result.issues or result.unparsed or ["no specification built"])
            raise SpecError(f"the language stage gave no specification: {why}")
        return spec, spec_atoms(spec)

    return make


def run_task(
    task: SmartTask,
    make_spec: SpecMaker,
    timeout_s: float = 30.0,
    objective: ObjectiveName = "minmax",
    masses: Mapping[str, float] | None = None,
) -> dict[str, Any]:
    """One task: spec -> team check -> plan -> execute -> SMART-LLM's metrics (a JSON-ready row)."""
    row: dict[str, Any] = {
        "id": task.id,
        "floor_plan": task.floor_plan,
        "task": task.text,
        "robots": [f"robot{r}" for r in task.robots],
        "has_gt": task.has_gt,
        "conditions": [c.describe() for c in task.conditions],
        "notes": list(task.notes),
    }
    if not task.has_gt:
        row["status"] = "no ground truth"
        return row
    world = world_for(task)
    conds = [(c.name, c.state, c.contains) for c in task.conditions]
    team = smartllm_team(task.robots)
    execution: Execution | None = None
    if not conds and make_spec is oracle_maker:
        row.update(
            status="vacuous",
            reason="the ground truth lists no condition (scored complete, as SMART-LLM's script does)",
            stages=1 if task.trans is not None else 0,
        )
        n_stages, exe = 1, 1.0
    else:  # an instruction is planned even when the ground truth lists nothing to check
        n_stages, exe, execution = _plan_task(
            task, world, team, make_spec, (timeout_s, objective, masses), row
        )
    snap = execution.final if execution is not None else SimState(world).snapshot(0)
    met = final_conditions(execution, conds) if execution is not None else _initial(world, conds)
    # no condition: complete (as SMART-LLM's script scores it) only once a plan was made and run
    gcr = sum(met) / len(met) if met else (1.0 if execution is not None or n_stages else 0.0)
    tc = 1.0 if gcr == 1.0 else 0.0
    ru = robot_utilisation(n_stages, task.trans, task.max_trans)
    row.update(
        GCR=gcr,
        TC=tc,
        RU=ru,
        Exe=exe,
        # SR needs RU: a task without a stage annotation (trans / max_trans) is left out of SR
        SR=None if ru is None else (1.0 if tc == 1.0 and ru == 1.0 else 0.0),
        script=script_metrics(world, snap, task.entries, n_stages, task.trans, task.max_trans, exe),
        conditions_met=[c.describe() for c, ok in zip(task.conditions, met, strict=True) if ok],
        conditions_missed=[c.describe() for c, ok in zip(task.conditions, met, strict=True) if not ok],
        stages=n_stages,
        trans=task.trans,
        max_trans=task.max_trans,
    )
    return row


def _plan_task(
    task: SmartTask,
    world: World,
    team: Any,
    make_spec: SpecMaker,
    settings: tuple[float, ObjectiveName, Mapping[str, float] | None],
    row: dict[str, Any],
) -> tuple[int, float, Execution | None]:
    timeout_s, objective, masses = settings
    try:
        spec, atoms = make_spec(task, world)
    except Nl2Hltl2PlanError as exc:
        row.update(status="no spec", reason=str(exc), partial=str(exc).startswith("not understood"))
        return 0, 0.0, None
    problems = team.problems(atoms, world, masses)
    if problems:
        row.update(status="infeasible team", reason="; ".join(problems))
        return 0, 0.0, None
    starts = start_cells(world, team.size, seed=sum(map(ord, task.id)))
    caps = team.capabilities(world, masses)
    options = PipelineOptions(
        objective=objective,
        plan_timeout_s=timeout_s,
        starts=starts,
        capabilities=[sorted(c) if c is not None else None for c in caps],
    )
    try:
        result = planning_stage(world, spec, starts, options).result
    except Nl2Hltl2PlanError as exc:
        row.update(status="planning error", reason=str(exc))
        return 0, 0.0, None
    row.update(
        status=result.status,
        reason=result.reason,
        plan_time_s=round(result.plan_time_s, 3),
        travel_m=result.travel_m,
        steps=result.steps,
    )
    if not result.solved or result.execution is None:
        return 0, 0.0, None
    ex = result.execution
    row["robots_used"] = sorted({e.robot for e in result.events})
    attempted = len(ex.events) + len(ex.violation_list)
    return stages(result.events, leaf_pairs(spec)), (len(ex.events) / attempted if attempted else 1.0), ex


def _initial(world: World, conds: list[tuple[str, str | None, str | None]]) -> list[bool]:
    snap = SimState(world).snapshot(0)
    return [condition_holds(world, snap, n, s, c) for n, s, c in conds]


def summarize(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """The five metrics (means over scored tasks, fractions 0..1) overall and per floor plan."""
    scored = [r for r in rows if r.get("has_gt")]

    def block(rs: list[dict[str, Any]], key: str | None = None) -> dict[str, Any]:
        out: dict[str, Any] = {"tasks": len(rs)}
        for m in METRICS:
            scores = [(r.get(key) or {}) if key else r for r in rs]
            vals = [float(x[m]) for x in scores if x.get(m) is not None]
            out[m] = round(statistics.fmean(vals), 4) if vals else None
        return out

    per_fp: dict[str, list[dict[str, Any]]] = {}
    for r in scored:
        per_fp.setdefault(r["floor_plan"], []).append(r)
    return {
        "overall": block(scored),
        "overall_script": block(scored, "script"),
        "left_out_of_SR": [r["id"] for r in scored if r.get("SR") is None],
        "per_floor_plan": {fp: block(rs) for fp, rs in sorted(per_fp.items())},
        "not_scored": [
            {"id": r["id"], "task": r["task"], "why": r.get("status")} for r in rows if not r.get("has_gt")
        ],
        "failed": [
            {
                "id": r["id"],
                "task": r["task"],
                "status": r.get("status"),
                "reason": r.get("reason", ""),
                "missed": r.get("conditions_missed", []),
            }
            for r in scored
            if r.get("TC") != 1.0
        ],
    }


def run_bench(
    out: Path,
    make_spec: SpecMaker,
    label: str,
    timeout_s: float = 30.0,
    progress: Callable[[dict[str, Any]], None] | None = None,
    objective: ObjectiveName = "minmax",
    masses: Mapping[str, float] | None = None,
) -> dict[str, Any]:
    """Run every task, write DIR/rows.jsonl, DIR/summary.json and DIR/report.md; return the summary."""
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    with atomic_path(out / "rows.jsonl", "rows file") as tmp, tmp.open("w") as sink:  # all rows or the old
        for task in load_tasks():
            row = run_task(task, make_spec, timeout_s, objective, masses)
            rows.append(row)
            sink.write(json.dumps(row) + "\n")
            if progress:
                progress(row)
    summary = {"specs": label, "objective": objective, "masses": dict(masses or {}), **summarize(rows)}
    write_json(out / "summary.json", summary, "summary file", indent=2)
    write_text(out / "report.md", report_md(summary, rows), "report")
    return summary


def _fmt(v: Any) -> str:
    return "-" if v is None else f"{v:.2f}"


def report_md(summary: dict[str, Any], rows: list[dict[str, Any]]) -> str:
    pub = published()
    lines = [
        f"# SMART-LLM benchmark ({summary['specs']} specs)",
        "",
        "Metrics as SMART-LLM defines them (suites/smartllm/smartllm_bench.py has the exact definitions).",
        "",
        "| | tasks | SR | TC | GCR | RU | Exe |",
        "|---|---|---|---|---|---|---|",
    ]
    o = summary["overall"]
    lines.append(
        f"| ours, all floor plans | {o['tasks']} | " + " | ".join(_fmt(o[m]) for m in METRICS) + " |"
    )
    sc = summary["overall_script"]
    lines.append(
        f"| ours, scored by SMART-LLM's script | {sc['tasks']} | "
        + " | ".join(_fmt(sc[m]) for m in METRICS)
        + " |"
    )
    for fp, b in summary["per_floor_plan"].items():
        lines.append(f"| ours, {fp} | {b['tasks']} | " + " | ".join(_fmt(b[m]) for m in METRICS) + " |")
    for entry in pub.get("rows", []):
        lines.append(
            f"| SMART-LLM {entry['label']} | {entry.get('tasks', '-')} | "
            + " | ".join(_fmt(entry.get(m)) for m in METRICS)
            + " |"
        )
    lines += ["", f"SMART-LLM's numbers: {pub.get('source', '')}", ""]
    lines += _scoring_notes(summary, rows)
    if pub.get("note"):
        lines += [pub["note"], ""]
    lines += ["## Not scored", ""] + [f'- {r["id"]} "{r["task"]}": {r["why"]}' for r in summary["not_scored"]]
    lines += ["", "## Tasks not completed (TC = 0)", ""]
    lines += [
        f'- {f["id"]} "{f["task"]}": {f["status"]}; {f["reason"]} missed: {", ".join(f["missed"])}'
        for f in summary["failed"]
    ] or ["- none"]
    lines += ["", "## Tasks not successful (SR = 0), and why", ""]
    lines += [f'- {r["id"]} "{r["task"].strip()}": {_why_not(r)}' for r in rows if r.get("SR") == 0.0] or [
        "- none"
    ]
    lines += [
        "",
        "## Per task",
        "",
        "| task | robots | status | SR | TC | GCR | RU | Exe | notes |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['id']} {r['task'].strip()} | {','.join(r['robots'])} | {r.get('status')} | "
            + " | ".join(_fmt(r.get(m)) for m in METRICS)
            + f" | {'; '.join(r.get('notes', []))} |"
        )
    return "\n".join(lines) + "\n"


def _why_not(row: dict[str, Any]) -> str:
    """Why a task scores SR 0: not completed (its status and reason), or completed in another number
    of sequential stages than SMART-LLM's annotation (RU < 1)."""
    if row.get("TC") != 1.0:
        missed = ", ".join(row.get("conditions_missed", [])) or "nothing to check, but no plan"
        why = f": {row['reason']}" if row.get("reason") else ""
        return f"{row.get('status')}{why}; missed: {missed}"
    want = (
        f"{row['trans'] + 1}"
        if row["trans"] == row["max_trans"]
        else f"{row['trans'] + 1}..{row['max_trans'] + 1}"
    )
    ru = _fmt(row.get("RU"))
    return f"complete, in {row.get('stages')} sequential stage(s) where the annotation has {want}: RU {ru}"


def _scoring_notes(summary: dict[str, Any], rows: list[dict[str, Any]]) -> list[str]:
    """Why the two scorings differ, task by task (suites/smartllm/smartllm_script.py has the script's
    rules)."""
    left_out = summary.get("left_out_of_SR", [])
    lines = [
        "Two scorings: *ours* follows SMART-LLM's definitions (one condition per state and per contained "
        "object, met by some object; BROKEN checked; RU clipped to 0..1); *SMART-LLM's script* computes "
        "them as `end_thread.py` does (one task per ground-truth entry with raw names, +1 per matching "
        "object, no BROKEN or FILLED check, GCR may exceed 1 and then TC = 0, RU unclipped; our plan's "
        "sequential stages stand for the script's top-level code blocks).",
        "",
        f"Left out of SR (no stage annotation trans / max_trans): {', '.join(left_out) or 'none'}.",
        "",
        "| task | ours TC / GCR / RU | script TC / GCR / RU | why they differ |",
        "|---|---|---|---|",
    ]
    for r in rows:
        s = r.get("script")
        if not s or all(_fmt(r.get(m)) == _fmt(s.get(m)) for m in ("TC", "GCR", "RU")):
            continue
        lines.append(
            f"| {r['id']} | {_fmt(r.get('TC'))} / {_fmt(r.get('GCR'))} / {_fmt(r.get('RU'))} | "
            f"{_fmt(s.get('TC'))} / {_fmt(s.get('GCR'))} / {_fmt(s.get('RU'))} | {_why_differ(r, s)} |"
        )
    return lines + [""]


def _why_differ(row: dict[str, Any], script: dict[str, Any]) -> str:
    reasons = []
    conditions = " ".join(row.get("conditions", []))
    if script.get("GCR") is not None and script["GCR"] > 1:
        reasons.append("+1 per matching object and per content, 1 task per entry: GCR > 1, so TC = 0")
    if "BROKEN" in conditions or "FILLED" in conditions:
        reasons.append("the script never checks BROKEN / FILLED")
    if any("read as" in n or "dropped" in n for n in row.get("notes", [])):
        reasons.append("raw ground-truth names (repaired in ours) or an empty entry")
    if row.get("RU") != script.get("RU"):
        reasons.append("RU unclipped in the script")
    if not reasons and (row.get("GCR") or 0) != (script.get("GCR") or 0):
        reasons.append("per-entry counting (an entry with a state and contents is one task)")
    return "; ".join(reasons) or "-"
