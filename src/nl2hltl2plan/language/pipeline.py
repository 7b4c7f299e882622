"""Instruction -> HTT -> base tasks -> hierarchical LTL, with one of three backends.

`translate(instruction, world, backend)` returns a `LanguageResult`:

- `offline`: the grammar parser (`offline/`), leaf actions from the worlds' recipes
  (`BaseTask.leaf_specs(world)`); no model, deterministic;
- `local`: a llama.cpp server for a GGUF file on 127.0.0.1 (`llm/local_server.py`), through
- `openai`: any OpenAI-compatible server (`llm/client.py`): the paper's prompted stages (decomposition,
  relations per non-leaf node, action completion per leaf; optionally rephrasing + translation per
  non-leaf node), each answer validated and grounded in the scene.

The HTT follows the paper: root "1" is the whole instruction; with several base tasks each is a child
of the root (or of a group node when one sentence groups several tasks with the same relations to the
rest); a base task with two leaves (place_two) is a non-leaf whose leaves are one object each; leaves
carry the robot actions. The structured base tasks (kind, object, count, sliced, container, receptacle,
light) are kept in the result next to the HTT (`tasks`, with `task_node` / `leaf_task` linking them).
"""

from __future__ import annotations

import contextlib
import importlib
import sys
from collections.abc import Callable, Iterator
from typing import Any, Literal, Protocol

import networkx as nx
from pydantic import BaseModel, ConfigDict, Field

from nl2hltl2plan.errors import HTTError, LLMError, Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.language.grounding import AffordanceLookup, Grounder, world_lookup
from nl2hltl2plan.language.htt import HTT, HTTNode
from nl2hltl2plan.language.llm.batch import BatchCollector, PendingAnswer
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.llm.settings import LLMSettings
from nl2hltl2plan.language.tasks import BaseTaskSpec, task_letter, transitive_closure, transitive_reduction

Backend = Literal["offline", "local", "openai"]
BACKENDS: tuple[str, ...] = ("offline", "local", "openai")
LeafSpec = list[str] | str


class SceneLike(Protocol):
    name: str

    def object_types(self) -> set[str]: ...


class LanguageResult(BaseModel):
    """Everything the language stage produced for one instruction."""

    model_config = ConfigDict(arbitrary_types_allowed=True)

    backend: str
    instruction: str
    scene: str | None = None
    htt: HTT
    tasks: list[BaseTaskSpec] = Field(default_factory=list)
    before: list[tuple[str, str]] = Field(default_factory=list)  # between base-task ids
    task_node: dict[str, str] = Field(default_factory=dict)  # base-task id -> HTT node id
    leaf_task: dict[str, str] = Field(default_factory=dict)  # HTT leaf id -> base-task id
    leaf_specs: dict[str, LeafSpec] = Field(default_factory=dict)  # HTT leaf id -> actions or flat formula
    spec: Any = Field(default=None, exclude=True)  # logic.hierarchical.HierarchicalSpec when built
    spec_text: str | None = None
    ltl_checks: list[str] = Field(default_factory=list)  # LLM translations that differed from the compiler
    unparsed: list[str] = Field(default_factory=list)
    issues: list[str] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
    llm_calls: dict[str, int] = Field(default_factory=dict)

    def summary_lines(self) -> list[str]:
        out = []
        for t in self.tasks:
            out.append(f"{t.id} [{self.task_node.get(t.id, '?')}] {t.summary()}")
        return out


# ----- HTT construction from base tasks -----------------------------------------------------------------
def n_leaves(task: BaseTaskSpec) -> int:
    """Leaves of a base task: one per object (place_two, "heat a couple of slices"), as in the recipes."""
    return max(1, task.count)


def build_htt(
    instruction: str,
    tasks: list[BaseTaskSpec],
    before: list[tuple[str, str]],
    groups: list[list[str]] | None = None,
    group_texts: list[str] | None = None,
) -> tuple[HTT, dict[str, str], dict[str, str]]:
    """HTT (paper's numbering), base task -> node, leaf -> base task, from base tasks and their order.

    Groups (tasks one sentence lists together) become a node when all members relate in the same way to
    every task outside the group; the relations between siblings are the closure's, transitively reduced.
    """
    ids = [t.id for t in tasks]
    closure = transitive_closure(before, ids)
    items: list[list[str]] = []
    grouped: set[str] = set()
    item_text: dict[int, str] = {}
    for gi, g in enumerate(groups or []):
        members = [m for m in g if m in ids and m not in grouped]
        if len(members) < 2:
            continue
        outside = [t for t in ids if t not in members]
        uniform = all(
            len({(m, o) in closure for m in members}) == 1 and len({(o, m) in closure for m in members}) == 1
            for o in outside
        )
        if uniform:
            items.append(members)
            grouped.update(members)
            if group_texts and gi < len(group_texts) and group_texts[gi]:
                item_text[id(members)] = group_texts[gi]
    for t in ids:
        if t not in grouped:
            items.append([t])
    items.sort(key=lambda it: min(ids.index(m) for m in it))
    by_id = {t.id: t for t in tasks}
    nodes: list[HTTNode] = []
    relations: list[tuple[str, str]] = []
    task_node: dict[str, str] = {}
    leaf_task: dict[str, str] = {}

    def add_task(node_id: str, task: BaseTaskSpec, text: str | None = None) -> None:
        task_node[task.id] = node_id
        k = n_leaves(task)
        if k == 1:
            nodes.append(HTTNode(id=node_id, text=text or task.text))
            leaf_task[node_id] = task.id
            return
        kids = [f"{node_id}.{j}" for j in range(1, k + 1)]
        nodes.append(HTTNode(id=node_id, text=text or task.text, children=kids))
        for j, kid in enumerate(kids, 1):
            nodes.append(HTTNode(id=kid, text=f"{task.text} (object {j} of {k})"))
            leaf_task[kid] = task.id

    def add_group(node_id: str, members: list[str], text: str | None = None) -> None:
        kids = [f"{node_id}.{j}" for j in range(1, len(members) + 1)]
        nodes.append(
            HTTNode(id=node_id, text=text or "; ".join(by_id[m].text for m in members), children=kids)
        )
        for kid, m in zip(kids, members, strict=True):
            add_task(kid, by_id[m])
        inner = [(a, b) for a, b in closure if a in members and b in members]
        for a, b in transitive_reduction(inner, members):
            relations.append((task_node[a], task_node[b]))

    if not tasks:
        raise HTTError("no base task to build an HTT from")
    if len(items) == 1:
        if len(items[0]) == 1:
            add_task("1", by_id[items[0][0]], instruction)
        else:
            add_group("1", items[0], instruction)
    else:
        kids = [f"1.{k}" for k in range(1, len(items) + 1)]
        nodes.append(HTTNode(id="1", text=instruction, children=kids))
        for kid, item in zip(kids, items, strict=True):
            if len(item) == 1:
                add_task(kid, by_id[item[0]])
            else:
                add_group(kid, item, item_text.get(id(item)))
        item_rel = {
            (i, j)
            for i, a in enumerate(items)
            for j, b in enumerate(items)
            if i != j and all((x, y) in closure for x in a for y in b)
        }
        for i, j in transitive_reduction(item_rel, list(range(len(items)))):
            relations.append((kids[i], kids[j]))
    htt = HTT(instruction=instruction, nodes=nodes, relations=relations)
    htt.validate_tree()
    return htt, task_node, leaf_task


def flat_before(htt: HTT, task_node: dict[str, str]) -> list[tuple[str, str]]:
    """Base-task precedence implied by the HTT's sibling relations (reduced)."""
    node_task = {v: k for k, v in task_node.items()}
    g = htt.graph()
    under: dict[str, set[str]] = {}
    for n in htt.nodes:
        desc = (
            nx.descendants(
                nx.DiGraph([(a, b) for a, b, d in g.edges(data=True) if d["kind"] == "decomposition"]), n.id
            )
            if n.children
            else set()
        )
        under[n.id] = {node_task[x] for x in desc | {n.id} if x in node_task}
    pairs = {(a, b) for x, y in htt.relations for a in under.get(x, ()) for b in under.get(y, ())}
    order = sorted(task_node, key=lambda t: t)
    return transitive_reduction(pairs, order)


# ----- leaf actions ---------------------------------------------------------------------------------------
def recipe_leaf_specs(
    tasks: list[BaseTaskSpec], world: Any, leaf_task: dict[str, str]
) -> dict[str, LeafSpec]:
    """Leaf actions from the worlds' recipes (`BaseTask.leaf_specs(world)`), keyed by HTT leaf id."""
    out: dict[str, LeafSpec] = {}
    by_task: dict[str, list[str]] = {}
    for leaf, t in leaf_task.items():
        by_task.setdefault(t, []).append(leaf)
    base = [t.to_base_task() for t in tasks]
    for task, bt in zip(tasks, base, strict=True):
        try:
            specs = bt.leaf_specs(world, others=[o for o in base if o.id != bt.id])
        except TypeError:  # older signature without `others`
            specs = bt.leaf_specs(world)
        leaves = sorted(by_task.get(task.id, []))
        for leaf, spec in zip(leaves, specs, strict=False):
            out[leaf] = spec
    return out


# ----- LTL generation for non-leaf nodes -----------------------------------------------------------------
def _spec_builder() -> Callable[..., Any] | None:
    try:
        m = importlib.import_module("nl2hltl2plan.language.spec_builder")
    except ModuleNotFoundError:
        return None
    return getattr(m, "build_spec", None)


# ----- backends --------------------------------------------------------------------------------------------
def resolve_backend(requested: str | None, settings: LLMSettings) -> tuple[str, str | None]:
    """The backend to use and a note for stderr (None: nothing to say)."""
    if requested in (None, "", "auto"):
        if settings.configured:
            return "openai", None
        return "offline", (
            "no LLM configured (NL2HLTL2PLAN_LLM_BASE_URL / NL2HLTL2PLAN_LLM_API_KEY): using the "
            "offline grammar parser"
        )
    if requested not in BACKENDS:
        raise LLMError(f"unknown LLM backend {requested!r}; choose one of {', '.join(BACKENDS)}")
    return requested, None


@contextlib.contextmanager
def open_client(
    backend: str,
    settings: LLMSettings,
    batch: BatchCollector | None = None,
    on_request: Callable[[str], None] | None = None,
) -> Iterator[LLMClient | None]:
    """An `LLMClient` for the backend (None for offline); the local backend runs its server meanwhile."""
    if backend == "offline":
        yield None
        return
    if backend == "openai":
        if not settings.configured and batch is None:
            raise LLMError(
                "no LLM configured: set NL2HLTL2PLAN_LLM_BASE_URL and/or NL2HLTL2PLAN_LLM_API_KEY "
                "(or --base-url / --api-key), or use --llm local / --llm offline"
            )
        yield LLMClient(settings, batch=batch, on_request=on_request)
        return
    from nl2hltl2plan.language.llm.local_server import LocalServer, smollm2_path

    gguf = settings.gguf or smollm2_path()
    local = settings.model_copy(update={"model": gguf.name, "api_key": "none"})
    if batch is not None:  # batch mode answers from the cache only: no server needed
        yield LLMClient(local, batch=batch, on_request=on_request)
        return
    with LocalServer(gguf, threads=settings.threads, ctx=settings.ctx) as server:
        yield LLMClient(local.model_copy(update={"base_url": server.base_url}), on_request=on_request)


# ----- the pipeline -----------------------------------------------------------------------------------------
def translate(
    instruction: str,
    world: SceneLike | None = None,
    backend: str = "offline",
    client: LLMClient | None = None,
    *,
    ltl: str = "compiler",
    actions: str = "auto",
    strict: bool = True,
    build_spec: bool = True,
) -> LanguageResult:
    """Instruction -> LanguageResult (HTT, base tasks, leaf actions, hierarchical spec when available).

    `world`: anything with `name` and `object_types()` (a `worlds.World` for leaf recipes and specs);
    `ltl`: "compiler" (exact, default) or "llm" (rephrase + translate per non-leaf node, each checked
    against the compiler and re-asked once with the discrepancy); `actions`: "recipe" (worlds recipes),
    "llm" (action completion prompts) or "auto" (recipe offline, llm otherwise); `strict`: unknown
    objects raise WorldError ("no Statue in FloorPlan17") instead of being reported in `issues`.
    """
    instruction = " ".join(instruction.split())
    if not instruction:
        raise HTTError("empty instruction")
    types = set(world.object_types()) if world is not None else None
    scene = world.name if world is not None else None
    if backend == "offline":
        res = _offline(instruction, types, scene, strict, world_lookup(world) if world is not None else None)
    else:
        if client is None:
            raise LLMError(f"backend {backend} needs an LLM client (see open_client)")
        res = _llm(instruction, types, scene, client, strict)
    res.backend = backend
    mode = actions if actions != "auto" else ("recipe" if backend == "offline" else "llm")
    if mode == "none":
        pass
    elif world is not None and hasattr(world, "objects"):
        if mode == "recipe":
            res.leaf_specs = recipe_leaf_specs(res.tasks, world, res.leaf_task)
        else:
            assert client is not None
            res.leaf_specs = _llm_actions(res, client, types, scene or "the scene")
        for n in res.htt.nodes:
            spec = res.leaf_specs.get(n.id)
            if isinstance(spec, list):
                n.actions = list(spec)
    elif mode == "llm" and client is not None and types is not None:
        res.leaf_specs = _llm_actions(res, client, types, scene or "the scene")
    if build_spec and res.leaf_specs:
        _attach_spec(res, ltl, client)
    if client is not None:
        st = client.stats
        res.llm_calls = {
            "requests": st.requests,
            "sent": st.sent,
            "cached": st.cached,
            "reasks": st.reasks,
            "retries": st.retries,
        }
    return res


def _offline(
    instruction: str,
    types: set[str] | None,
    scene: str | None,
    strict: bool,
    look: AffordanceLookup | None = None,
) -> LanguageResult:
    from nl2hltl2plan.language.offline import parse_instruction

    parsed = parse_instruction(instruction, types, scene or "the scene", strict=strict, affordances=look)
    if not parsed.tasks:
        why = "; ".join(parsed.unparsed) or "no task verb found"
        raise HTTError(
            f"the offline parser understood no task in {instruction!r} ({why}); rephrase it or use an "
            "LLM backend"
        )
    htt, task_node, leaf_task = build_htt(
        instruction, parsed.tasks, parsed.before, parsed.groups, parsed.group_texts
    )
    return LanguageResult(
        backend="offline",
        instruction=instruction,
        scene=scene,
        htt=htt,
        tasks=parsed.tasks,
        before=list(parsed.before),
        task_node=task_node,
        leaf_task=leaf_task,
        unparsed=parsed.unparsed,
        issues=parsed.issues,
    )


def _ground_fields(f: Any, g: Grounder | None, issues: list[str], strict: bool) -> BaseTaskSpec:
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
        receptacle=one(f.receptacle, "receptacle") if kind != "examine_in_light" else None,
        light=one(f.light, "light") if kind == "examine_in_light" else None,
    )


def _llm(
    instruction: str, types: set[str] | None, scene: str | None, client: LLMClient, strict: bool
) -> LanguageResult:
    from nl2hltl2plan.language import stages

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
    # relations: once per non-leaf node of the LLM's tree (the root, and each group)
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
    ids = [t.id for t in tasks]
    red = transitive_reduction(before, ids)
    htt, task_node, leaf_task = build_htt(instruction, tasks, red, groups)
    return LanguageResult(
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


def _llm_actions(
    res: LanguageResult, client: LLMClient, types: set[str] | None, scene: str
) -> dict[str, LeafSpec]:
    from nl2hltl2plan.language import stages

    by_id = {t.id: t for t in res.tasks}
    out: dict[str, LeafSpec] = {}
    for leaf in res.htt.leaves():
        task = by_id[res.leaf_task[leaf.id]]
        details = {k: v for k, v in task.model_dump().items() if v not in (None, False, "") and k != "text"}
        details["id"] = leaf.id
        try:
            out[leaf.id] = stages.complete_actions(client, leaf.text, details, types, scene)
        except LLMError as exc:
            if isinstance(exc, PendingAnswer):
                raise
            raise LLMError(f"action completion for {leaf.id} ({leaf.text!r}) failed: {exc}") from None
    return out


def _attach_spec(res: LanguageResult, ltl: str, client: LLMClient | None) -> None:
    """Algorithm 1 (`spec_builder.build_spec`) with our leaf specs and the chosen GenerateLTL."""
    builder = _spec_builder()
    if builder is None:
        res.warnings.append("hierarchical spec not built: language.spec_builder is not available yet")
        return
    missing = [n.id for n in res.htt.leaves() if n.id not in res.leaf_specs]
    if missing:
        res.warnings.append(f"hierarchical spec not built: no actions for leaves {missing}")
        return
    kwargs: dict[str, Any] = {"action_completion": lambda node: res.leaf_specs[node.id]}
    if ltl == "llm":
        if client is None:
            raise LLMError("--ltl llm needs an LLM backend (or use --ltl learned with a translator server)")
        kwargs["generate_ltl"] = _llm_generate_ltl(res, client, client)
    elif ltl == "learned":
        kwargs["generate_ltl"] = _llm_generate_ltl(res, client, translator_client())
    elif ltl != "compiler":
        raise LLMError(f"unknown LTL generator {ltl!r}: compiler, llm or learned")
    spec = builder(res.htt, **kwargs)
    res.spec = spec
    res.spec_text = spec_lines(spec)


def spec_lines(spec: Any) -> str:
    """Readable hierarchical LTL: one line per formula, level by level (`L2  task1.1 = F(...)`)."""
    from nl2hltl2plan.logic.hierarchical import sequence_formula

    out = []
    for k, level in enumerate(getattr(spec, "levels", []), start=1):
        for name, f in level.items():
            text = sequence_formula(f, check=False) if isinstance(f, list) else f
            out.append(f"L{k}  {name} = {text}")
    return "\n".join(out) if out else str(spec)


def translator_client() -> LLMClient:
    """The learned translator (the paper's fine-tuned model over lifted sentences), served by any
    OpenAI-compatible server: NL2HLTL2PLAN_TRANSLATOR_BASE_URL / _MODEL / _API_KEY."""
    import os

    url = os.environ.get("NL2HLTL2PLAN_TRANSLATOR_BASE_URL")
    if not url:
        raise LLMError(
            "--ltl learned needs NL2HLTL2PLAN_TRANSLATOR_BASE_URL (a server for the fine-tuned translator)"
        )
    settings = LLMSettings.from_env(
        base_url=url,
        model=os.environ.get("NL2HLTL2PLAN_TRANSLATOR_MODEL", "translator"),
        api_key=os.environ.get("NL2HLTL2PLAN_TRANSLATOR_API_KEY", "none"),
    )
    return LLMClient(settings)


def lifted_sentences(children: list[str], relations: list[tuple[str, str]]) -> list[str]:
    """Deterministic rephrasing of children + relations into lifted sentences (no LLM needed)."""
    out = [f"task {a} must be completed before task {b}" for a, b in relations]
    free = [c for c in children if not any(c in r for r in relations)]
    out += [f"task {c} can be completed at any time" for c in free]
    return out or [f"complete task {children[0]}"]


def _node_id(name: str) -> str:
    return name[4:] if name.startswith("task") else name


def _llm_generate_ltl(
    res: LanguageResult, client: LLMClient | None, translator: LLMClient
) -> Callable[..., str]:
    """GenerateLTL of Algorithm 1 by an LLM or learned translator (rephrase + translate), each answer
    checked against the exact compiler; a difference is reported and re-asked once with the witness
    trace, then the compiler's formula is used (the closed loop the paper lists as missing)."""
    from nl2hltl2plan.errors import FormulaError
    from nl2hltl2plan.language import stages
    from nl2hltl2plan.logic.relations import check_translation, compile_relations

    def generate(children: list[str], relations: list[tuple[str, str]]) -> str:
        names = list(children)
        ids = [_node_id(c) for c in names]
        rels = [(_node_id(a), _node_id(b)) for a, b in relations]
        lifted = {stages.prop_name(i): n for i, n in zip(ids, names, strict=True)}
        sentences = stages.rephrase(client, ids, rels) if client is not None else lifted_sentences(ids, rels)
        feedback = None
        for attempt in range(2):
            text = stages.translate(translator, sentences, ids, feedback=feedback)
            candidate = _unlift(text, lifted)
            try:
                check = check_translation(candidate, names, list(relations))
            except FormulaError as exc:
                res.ltl_checks.append(f"{'/'.join(ids)}: translation {text!r} rejected: {exc}")
                feedback = f"Your formula {text} is not valid sc-LTL over the given propositions: {exc}"
                continue
            if check.equivalent:
                return check.candidate
            res.ltl_checks.append(f"{'/'.join(ids)}: {check.describe()}")
            feedback = (
                f"Your formula {text} does not match the constraints {rels}: {check.describe()}. "
                "Give a corrected formula."
            )
            if attempt == 1:
                break
        res.ltl_checks.append(f"{'/'.join(ids)}: using the compiler's formula")
        return compile_relations(names, list(relations))

    return generate


def _unlift(text: str, names: dict[str, str]) -> str:
    import re

    return re.sub(r"task\d+(?:_\d+)*", lambda m: f'"{names.get(m.group(0), m.group(0))}"', text)


# ----- measurement hook ------------------------------------------------------------------------------------
@contextlib.contextmanager
def llm_generator(backend: str, argv: list[str]) -> Iterator[Callable[..., Any]]:
    """For `measure`: a generator function (instruction, types, scene) -> (tasks, before, unparsed)."""
    import argparse

    ap = argparse.ArgumentParser()
    add_llm_arguments(ap)
    args = ap.parse_args(argv)
    settings = settings_from_args(args)
    batch = BatchCollector() if args.batch_out else None
    if args.batch_answers:
        load_batch_answers(args.batch_answers, settings)

    class _Scene:
        def __init__(self, name: str, types: set[str]) -> None:
            self.name, self._types = name, types

        def object_types(self) -> set[str]:
            return self._types

    with open_client(backend, settings, batch=batch) as client:

        def generate(instruction: str, types: set[str], scene: str):
            try:
                r = translate(
                    instruction,
                    _Scene(scene, types),
                    backend,
                    client,
                    strict=False,
                    build_spec=False,
                    actions="none",
                )
            except PendingAnswer:
                return [], [], ["pending (batch mode)"]
            return r.tasks, r.before, r.unparsed + r.issues

        yield generate
    if batch is not None and len(batch):
        n = batch.write(args.batch_out)
        print(f"{n} requests pending, written to {args.batch_out}", file=sys.stderr)


# ----- shared CLI options -----------------------------------------------------------------------------------
def add_llm_arguments(p: Any) -> None:
    g = p.add_argument_group("LLM backend (environment: NL2HLTL2PLAN_LLM_*)")
    g.add_argument(
        "--base-url", default=None, help="OpenAI-compatible endpoint (vLLM, Ollama, llama.cpp ...)"
    )
    g.add_argument("--model", default=None, help="model name")
    g.add_argument("--api-key", default=None, help="API key (better: NL2HLTL2PLAN_LLM_API_KEY)")
    g.add_argument("--temperature", type=float, default=None)
    g.add_argument("--timeout", type=float, default=None, help="seconds per request")
    g.add_argument("--retries", type=int, default=None, help="retries of failed requests")
    g.add_argument(
        "--gguf", default=None, help="GGUF model file for --llm local (default: SmolLM2 test model)"
    )
    g.add_argument("--threads", type=int, default=None, help="CPU threads of the local server (default 1)")
    g.add_argument("--cache", default=None, help="answer cache folder, or 'off'")
    g.add_argument(
        "--batch-out", default=None, help="batch mode: write pending requests (OpenAI Batch JSONL) here"
    )
    g.add_argument("--batch-answers", default=None, help="load a Batch API output file into the cache first")


def settings_from_args(args: Any) -> LLMSettings:
    return LLMSettings.from_env(
        base_url=args.base_url,
        model=args.model,
        api_key=args.api_key,
        temperature=args.temperature,
        timeout=args.timeout,
        max_retries=args.retries,
        gguf=args.gguf,
        threads=args.threads,
        cache_dir=args.cache,
    )


def load_batch_answers(path: str, settings: LLMSettings) -> int:
    from nl2hltl2plan.language.llm.batch import read_answers
    from nl2hltl2plan.language.llm.cache import AnswerCache

    if settings.cache_dir is None:
        raise LLMError("--batch-answers needs the answer cache (do not combine it with --cache off)")
    n, errors = read_answers(path, AnswerCache(settings.cache_dir))
    for e in errors[:5]:
        print(f"warning: batch answer {e}", file=sys.stderr)
    return n


__all__ = [
    "BACKENDS",
    "LanguageResult",
    "Nl2Hltl2PlanError",
    "build_htt",
    "open_client",
    "resolve_backend",
    "translate",
]
