"""The LLM backends' reading of an instruction (`local`, `openai`): the paper's prompted stages
(`stages`: decomposition into tasks and constraints, relations per non-leaf node, action completion per
leaf), grounded in the scene's types, as a `LanguageResult`; and the learned parser's cross-check of
what the LLM read. `translate` runs them and then the checks every backend shares.
"""

from __future__ import annotations

from nl2hltl2plan.errors import HTTError, LLMError, Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.language import stages
from nl2hltl2plan.language.grounding import Grounder
from nl2hltl2plan.language.htt_build import build_htt
from nl2hltl2plan.language.llm.batch import PendingAnswer
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.negations import nothing_to_do, patterns
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec, task_letter, transitive_reduction
from nl2hltl2plan.logic.hierarchical import LeafOrFormula


def _ground_fields(f: stages.TaskFields, g: Grounder | None, issues: list[str], strict: bool) -> BaseTaskSpec:
    def one(word: str | None, role: str) -> list[str] | None:
        if word is None or not str(word).strip():
            return None
        w = str(word).strip()
        if g is None:
            return [w]
        try:
            return g.ground(w[:-6] if w.endswith("Sliced") else w, role)
        except WorldError as exc:
            if strict:
                raise
            issues.append(str(exc))
            return [w]

    sliced = bool(f.sliced) or str(f.object).endswith("Sliced")
    kind = f.kind
    return BaseTaskSpec(
        kind=kind,
        text=f.text,
        object=one(f.object, "object") or [],
        count=2 if kind == "place_two" else f.count,
        sliced=sliced,
        container=one(f.container, "container") if kind == "place_in_container" else None,
        receptacle=one(f.receptacle, "receptacle") if kind not in ("examine_in_light", "set_state") else None,
        light=one(f.light, "light") if kind == "examine_in_light" else None,
        state=f.state if kind == "set_state" else None,
    )


def read_with_llm(
    instruction: str, types: set[str] | None, scene: str | None, client: LLMClient, strict: bool
) -> LanguageResult:
    """The paper's prompted stages: decomposition (tasks and constraints), relations per non-leaf node,
    grounded in the scene's types; an object the scene lacks raises WorldError when `strict`."""
    objects = sorted(t for t in (types or set()) if not t.endswith("Sliced"))
    dec = stages.decompose(client, instruction, objects)
    g = Grounder(types, scene or "the scene") if types is not None else None
    issues: list[str] = []
    tasks: list[BaseTaskSpec] = []
    groups: list[list[str]] = []
    node_of: dict[str, str] = {}  # decomposition id -> base task id
    for node in dec.tasks:
        members = node.subtasks or [node.as_task()]
        gm = []
        for f in members:
            spec = _ground_fields(f, g, issues, strict)
            spec.id = task_letter(len(tasks))
            tasks.append(spec)
            node_of[f.id] = spec.id
            gm.append(spec.id)
        if node.subtasks:
            groups.append(gm)
    constraints = _llm_constraints(dec.constraints, g, node_of, issues)
    if not tasks and constraints:
        raise HTTError(nothing_to_do(instruction, constraints))
    before = _llm_relations(client, instruction, dec, node_of)
    red = transitive_reduction(before, [t.id for t in tasks])
    htt, task_node, leaf_task = build_htt(instruction, tasks, red, groups)
    return LanguageResult(
        constraint_specs=constraints,
        backend="llm",
        instruction=instruction,
        scene=scene,
        htt=htt,
        tasks=tasks,
        before=red,
        task_node=task_node,
        leaf_task=leaf_task,
        issues=issues,
    )


def _llm_constraints(
    stated: list[stages.ConstraintWords], g: Grounder | None, node_of: dict[str, str], issues: list[str]
) -> list[ConstraintSpec]:
    """The LLM's constraints over scene types; one on a thing the scene lacks, or waiting for a task
    that does not exist, is left out (with the reason in `issues`), so its negation stays unread."""
    out = []
    for c in stated:
        try:
            objects = g.ground(c.object, "object") if g is not None else [c.object]
            places = [] if not c.receptacle else g.ground(c.receptacle, "receptacle") if g else [c.receptacle]
        except WorldError as exc:
            issues.append(f"constraint {c.text!r} not kept: {exc}")
            continue
        if c.until is not None and c.until not in node_of:
            issues.append(f"constraint {c.text!r} not kept: it waits for an unknown task {c.until!r}")
            continue
        forbid = patterns("any" if c.verb == "use" else c.verb, objects, places)
        until = node_of[c.until] if c.until is not None else None
        out.append(ConstraintSpec(text=c.text, forbid=forbid, until=until))
    return out


def _llm_relations(
    client: LLMClient, instruction: str, dec: stages.Decomposition, node_of: dict[str, str]
) -> set[tuple[str, str]]:
    """Relations asked once per non-leaf node of the LLM's tree (the root, and each group)."""
    before: set[tuple[str, str]] = set()
    top = [(n.id, n.text or (n.subtasks and "; ".join(s.text for s in n.subtasks)) or "") for n in dec.tasks]
    if len(top) > 1:
        rel = stages.relations(client, instruction, "1", "the whole instruction", top)
        under = {n.id: [node_of[s.id] for s in n.subtasks] or [node_of[n.id]] for n in dec.tasks}
        before |= {(a, b) for x, y in rel for a in under[x] for b in under[y]}
    for n in dec.tasks:
        if len(n.subtasks) > 1:
            rel = stages.relations(client, instruction, n.id, n.text, [(s.id, s.text) for s in n.subtasks])
            before |= {(node_of[x], node_of[y]) for x, y in rel}
    return before


def llm_leaf_actions(
    res: LanguageResult, client: LLMClient, types: set[str] | None, scene: str
) -> dict[str, LeafOrFormula]:
    by_id = {t.id: t for t in res.tasks}
    out: dict[str, LeafOrFormula] = {}
    for leaf in res.htt.leaves():
        task = by_id[res.leaf_task[leaf.id]]
        details = {k: v for k, v in task.model_dump().items() if v not in (None, False, "") and k != "text"}
        details["id"] = leaf.id
        try:
            out[leaf.id] = stages.complete_actions(client, leaf.text, details, types, scene)
        except PendingAnswer:
            raise
        except LLMError as exc:
            raise LLMError(f"action completion for {leaf.id} ({leaf.text!r}) failed: {exc}") from None
    return out


def cross_check(res: LanguageResult, types: set[str] | None, scene: str | None) -> LanguageResult:
    """The learned parser reads the instruction too; where its base tasks or orderings differ from the
    LLM's, the difference is reported (a warning: either may be the one that is wrong)."""
    from nl2hltl2plan.language import learned

    try:
        own = learned.parse_instruction(res.instruction, types, scene or "the scene", strict=False)
    except Nl2Hltl2PlanError:
        return res
    if not own.tasks:
        return res
    verdict = match(res.tasks, res.before, [t.model_dump() for t in own.tasks], own.before, strict=False)
    if verdict.order_ok:
        return res
    why = "; ".join(verdict.reasons[:2]) or "different base tasks"
    warning = f"the learned parser reads this instruction differently from the LLM: {why}"
    return res.model_copy(update={"warnings": [*res.warnings, warning]})
