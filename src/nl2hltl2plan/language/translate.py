"""The language stage: instruction -> HTT -> base tasks -> leaf actions -> hierarchical sc-LTL.

`translate(instruction, world, backend, client)` returns a `LanguageResult`:

- `offline` (alias `learned`): the grammar parser (`grammar/`) with the slot model trained on ALFRED's
  annotations (`learned/`), which reads the clauses the grammar could not and ranks multi-type words
  (`ambiguities`); leaf actions from the worlds' recipes; deterministic;
- `grammar`: the grammar parser alone;
- `local` / `openai`: the paper's prompted stages through an OpenAI-compatible server
  (decomposition, relations per non-leaf node, action completion per leaf; optionally rephrasing +
  translation per non-leaf node), each answer validated and grounded in the scene.

Algorithm 1 (`spec_builder.build_spec`) then turns the HTT into the hierarchical spec, with the exact
relation compiler as GenerateLTL unless `ltl` asks for an LLM / learned translator.

Each step takes the result so far and returns a new one (`model_copy`); nothing is changed in place, so
a caller that keeps an earlier result (the parse before the user's choices, say) keeps it as it was.
"""

from __future__ import annotations

import contextlib
from collections import Counter
from collections.abc import Callable, Iterator, Sequence
from dataclasses import asdict
from typing import TYPE_CHECKING, Literal, Protocol, Self, TypeVar, get_args

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.domain.task_kinds import SLOTS, State
from nl2hltl2plan.errors import HTTError, LLMError, WorldError
from nl2hltl2plan.language.accounting import account, unfilled_slots
from nl2hltl2plan.language.content_words import refuse_take_backs
from nl2hltl2plan.language.contradictions import refuse_contradictions
from nl2hltl2plan.language.counts import take_every_instance
from nl2hltl2plan.language.courtesy import without_courtesy
from nl2hltl2plan.language.frame_filler import frame_note
from nl2hltl2plan.language.grounding import AffordanceLookup, Grounder, world_lookup
from nl2hltl2plan.language.headings import unlabelled
from nl2hltl2plan.language.htt_build import bound_places, build_htt
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.llm_reading import cross_check, llm_leaf_actions, read_with_llm
from nl2hltl2plan.language.ltl_generation import llm_generate_ltl, translator_client
from nl2hltl2plan.language.missing_where import named_where
from nl2hltl2plan.language.negations import (
    Negation,
    nothing_to_do,
    read_negations,
    resolve_until,
    spec_constraints,
)
from nl2hltl2plan.language.parsers import PARSERS, Parser
from nl2hltl2plan.language.place_choices import split_choices, widen
from nl2hltl2plan.language.referents import check_referents
from nl2hltl2plan.language.restated_tasks import joined_restatements
from nl2hltl2plan.language.result import Ambiguity, LanguageResult
from nl2hltl2plan.language.spec_builder import GenerateLTL, build_spec
from nl2hltl2plan.language.spelling import respelling_notes, shorthand_read
from nl2hltl2plan.language.state_tasks import (
    StateReader,
    guessed_slot,
    light_orders,
    reread,
    state_orderings,
    treated_apart,
)
from nl2hltl2plan.language.suggest import not_understood, refuse_unmovable, suggestion_text
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter
from nl2hltl2plan.language.world_readers import SharedGrammar, WorldReader, world_reader
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec, LeafOrFormula
from nl2hltl2plan.logic.relations import compile_relations
from nl2hltl2plan.worlds.tasks import can_take_state, demand_of
from nl2hltl2plan.worlds.world import World

if TYPE_CHECKING:
    from nl2hltl2plan.language.grammar import OfflineParse

LtlSource = Literal["compiler", "llm", "learned"]
MAX_INSTRUCTION_CHARS = 2000  # about 300 words, 15 times the paper's longest; bounds the parser's time
ActionSource = Literal["auto", "recipe", "llm", "none"]
Chooser = Callable[[list[Ambiguity]], dict[str, str]]  # ambiguities -> {"A.receptacle": "SideTable"}


def top_candidates(ambiguities: list[Ambiguity]) -> dict[str, str]:
    """The Chooser benchmarks use: every ambiguous word takes its most likely type (ranked first)."""
    return {f"{a.task}.{a.role}": a.candidates[0] for a in ambiguities if a.candidates}


class SceneLike(Protocol):
    """What the language stage needs of a scene: its name and object types (a `World` has both)."""

    name: str

    def object_types(self) -> set[str]: ...


def translate(
    instruction: str,
    world: SceneLike | None = None,
    backend: str = "offline",
    client: LLMClient | None = None,
    *,
    ltl: LtlSource = "compiler",
    actions: ActionSource = "auto",
    strict: bool = True,
    build: bool = True,
    choices: dict[str, str] | None = None,
    ask: Chooser | None = None,
    plurals: Plurals = "ask",
) -> LanguageResult:
    """Instruction -> LanguageResult (HTT, base tasks, leaf actions, hierarchical spec).

    `world`: a `World` (needed for recipes and specs) or anything with `name` and `object_types()`;
    `ltl`: GenerateLTL by the exact compiler (default), an LLM, or a learned translator, the latter
    two checked against the compiler; `actions`: "recipe" (worlds recipes), "llm" (action completion
    prompts), "auto" (recipe offline, llm otherwise) or "none"; `strict`: an object the scene lacks
    raises WorldError ("no Statue in FloorPlan17") instead of being reported in `issues`;
    `build`: run Algorithm 1 (off: HTT and base tasks only); `choices`: a user's pick for an
    ambiguous slot, `{"A.receptacle": "SideTable"}` (task id . role -> scene type); `ask`: called
    with the parse's ambiguities (if any) before leaf actions and specs are built, returns more choices
    (`plan --ask` asks on the terminal: the instruction is parsed once); `plurals`: a plural with no
    number of more things than the task takes ("the forks" of 3) is refused ("ask") or read by the
    world's convention ("two": ALFRED's pick-two, said in `assumptions`; `referents.plural_of_several`).
    """
    if len(instruction) > MAX_INSTRUCTION_CHARS:
        raise HTTError(
            f"the instruction is {len(instruction):,} characters long; the limit is "
            f"{MAX_INSTRUCTION_CHARS:,} (split it into several instructions)"
        )
    # each line's own spaces collapsed, its indentation kept (a nested list's sub-item says what it is under)
    indent = [line[: len(line) - len(line.lstrip())] for line in instruction.splitlines()]
    # "Goal - ...", "Condition - none": labelled lines read alike in every world (`headings`)
    # chat shorthand ("n", "&", "u", "w/") read as the words it stands for, alike in every world (`spelling`)
    lines = [
        i + shorthand_read(unlabelled(line))
        for i, line in zip(indent, instruction.splitlines(), strict=True)
        if unlabelled(line)
    ]
    said, instruction = " ".join(instruction.split()), " ".join(" ".join(lines).split())
    if not instruction:
        raise HTTError(f"nothing to do: {said!r} asks nothing" if said else "empty instruction")
    refuse_take_backs(instruction)  # "scratch that", "just kidding": every world, every backend
    types = set(world.object_types()) if world is not None else None
    scene = world.name if world is not None else None
    instances = scene_instances(world) if isinstance(world, World) else None  # once: check 1, referents
    reader = world_reader(world)  # the world's own reading around the shared grammar, if it has one
    if backend in PARSERS and (own := reader.own_reading("\n".join(lines))) is not None:
        return own  # a line break ends a step
    if backend in PARSERS:
        # the world's reading of line breaks and names; "if you don't mind": no condition, no negation
        instruction = without_courtesy(reader.as_read(lines))
        look = world_lookup(world) if isinstance(world, World) else None
        grounder = Grounder(types, scene or "the scene")
        prepared = reader.prepared(instruction)
        rest, negations = read_negations(prepared, grounder, look)
        if negations and not rest.strip(" ,.;!?"):
            raise HTTError(nothing_to_do(instruction, [n.spec for n in negations]))

        def reread() -> LanguageResult | None:  # a world's rereading reads no negation: not asked then
            return None if negations else reader.reread(instruction, backend)

        # "in the fridge or the microwave": read with the first place, then the task takes either
        choice_text, either = split_choices(rest, world, look)
        try:
            res = _parse(backend, choice_text, grounder, strict, look, world, instances)
            if either:
                res = widen(res, rest, either, world if isinstance(world, World) else None)
            if negations:
                res = _keep_negations(res, instruction, negations, grounder)
            picked = dict(choices or {})
            if ask is not None and res.ambiguities:
                picked.update(ask(res.ambiguities))
            res = account_words(apply_choices(res, picked), world, instances)
        except (HTTError, WorldError) as refused:
            # the world's rereading (checked by check 1 on the words it read), or the refusal as it was
            if (again := reread()) is None:
                raise reader.refusal(named_where(refused, instruction), instruction, prepared, rest) from None
            res = again
        else:  # the grammar's reading: the world's own reading replaces it where partial, or may doubt it
            if res.partial and (again := reread()) is not None:
                res = again
            elif not res.partial and not negations:
                res = reader.doubted(res, backend)
        res = _reader_says(res, reader, instruction)
        with _refused_as_not_understood(res, world):
            return _finish(res, world, backend, client, ltl, actions, build, instances, plurals)
    if client is None:
        raise LLMError(f"backend {backend} needs an LLM client (see backends.open_client)")
    with client.instruction():  # one deadline for every request this instruction makes
        res = read_with_llm(instruction, types, scene, client, strict)
        res = account_words(cross_check(res, types, scene), world, instances)
        with _refused_as_not_understood(res, world):
            return _finish(res, world, backend, client, ltl, actions, build, instances, plurals)


def _reader_says(res: LanguageResult, reader: WorldReader, instruction: str) -> LanguageResult:
    """The reading with what the world's reader adds, whichever reading was taken: the words it read off
    the text that no task honours ("..., tomorrow") as unparsed, and its notes as assumptions."""
    read_off = reader.read_off() if isinstance(reader, SharedGrammar) else []  # (the tabletop's: none)
    if off := [str(u) for u in read_off if str(u) not in res.unparsed]:
        res = res.model_copy(update={"unparsed": [*res.unparsed, *off]})
    # "read 'whih' as 'which'", "read 'kettle' as 'watering can'": no word silently changed
    if respelt := [*respelling_notes(instruction), *reader.notes(instruction)]:
        res = res.model_copy(update={"assumptions": [*res.assumptions, *respelt]})
    return res


def _keep_negations(
    res: LanguageResult, instruction: str, negations: list[Negation], grounder: Grounder
) -> LanguageResult:
    """The parse of the instruction without its negated clauses, given back the whole instruction and
    the constraints those clauses state (an until-guard on the task its words name)."""
    htt = res.htt.model_copy(deep=True)
    htt.instruction = instruction
    htt.root.text = instruction
    constraints = [n.spec for n in resolve_until(negations, res.tasks, grounder)]
    return res.model_copy(update={"instruction": instruction, "htt": htt, "constraint_specs": constraints})


def account_words(
    res: LanguageResult, world: SceneLike | None, instances: Counter[str] | None = None
) -> LanguageResult:
    """Check 1 (`accounting.account`), the same for every backend, on the reading with each task said
    again joined to the task read before (`restated_tasks`): each content word the base tasks
    do not use, each slot no word names, each slot left empty (`unfilled_slots`) and what the world's
    reader adds (`WorldReader.unused`) goes to `unparsed` with its reason (the result is then partial).
    Counts the scene cannot satisfy and cyclic orders raise HTTError. `instances`: the world's
    `scene_instances`, when the caller has them."""
    res = joined_restatements(res)  # a task said again is the task read before (issue 23)
    if instances is None and isinstance(world, World):
        instances = scene_instances(world)
    scene = world.name if world is not None else "the scene"
    unread = account(res.instruction, res.tasks, res.before, instances, scene, res.constraint_specs)
    unread += unfilled_slots(res.tasks) + treated_apart(res.tasks) + world_reader(world).unused(res)
    words = [str(u) for u in unread]
    return res.model_copy(update={"unparsed": [*res.unparsed, *words]}) if words else res


def scene_instances(world: World) -> Counter[str]:
    """How many objects of each type the world holds (slices not yet cut left out)."""
    return Counter(o.type for o in world.objects.values() if o.present)


@contextlib.contextmanager
def _refused_as_not_understood(res: LanguageResult, world: SceneLike | None) -> Iterator[None]:
    """A task of a partly understood parse that the world cannot do is reported as what was not
    understood (the cause in brackets), not as a world error."""
    try:
        yield
    except (WorldError, HTTError) as exc:
        if not res.partial:
            raise
        raise HTTError(not_understood(res, world if isinstance(world, World) else None, str(exc))) from None


def _finish(
    res: LanguageResult,
    world: SceneLike | None,
    backend: str,
    client: LLMClient | None,
    ltl: LtlSource,
    actions: ActionSource,
    build: bool,
    instances: Counter[str] | None,
    plurals: Plurals = "ask",
) -> LanguageResult:
    """What the words refer to (`referents`: one thing moved twice, "the dishes", "the towel", "the forks"
    of more than two, read by the world's plural convention or refused), then leaf actions (recipes or LLM
    action completion), then Algorithm 1. `instances`: the world's `scene_instances` (None: a scene known
    only by its types)."""
    convention = world.plurals if isinstance(world, World) else None
    scene = world.name if world else "the scene"
    if isinstance(world, World):  # "scrub the toilet": a fixture is no thing to pick up and treat
        refuse_unmovable(res.tasks, res.instruction, world)
    # the types the negations act on: "don't touch the towel" is asked as a task's "the towel" is
    patterns = [a for c in res.constraint_specs for p in c.forbid if (a := Atom.read_pattern(p))]
    forbidden = {t for a in patterns for t in a.args}
    assumed = check_referents(
        res.instruction, res.tasks, res.before, instances, scene, convention, plurals, forbidden - {"*"}
    )
    if assumed:
        res = res.model_copy(update={"assumptions": [*res.assumptions, *assumed]})
    mode = actions if actions != "auto" else ("recipe" if backend in PARSERS else "llm")
    found = ACTION_SOURCES[mode](res, world, client)
    leaf_specs = res.leaf_specs if found is None else found
    # "put the apple in the fridge but never open the fridge": the text, not the world, says no (exit 2)
    world_ = world if isinstance(world, World) else None
    refuse_contradictions(res.tasks, res.constraint_specs, leaf_specs, res.leaf_task, world_, res.before)
    htt = res.htt.model_copy(deep=True)
    for n in htt.nodes:
        spec = leaf_specs.get(n.id)
        if isinstance(spec, list):
            n.actions = list(spec)
    res = res.model_copy(update={"backend": backend, "leaf_specs": leaf_specs, "htt": htt})
    if build and leaf_specs:
        res = _attach_spec(res, ltl, client)
    if client is not None:
        res = res.model_copy(update={"llm_calls": asdict(client.stats)})
    return res


LeafSpecs = dict[str, LeafOrFormula]
LeafActions = Callable[[LanguageResult, "SceneLike | None", LLMClient | None], LeafSpecs | None]


def _recipe_actions(
    res: LanguageResult, world: SceneLike | None, client: LLMClient | None
) -> LeafSpecs | None:
    """Leaf actions from the worlds' recipes (None: a scene known only by its types has none)."""
    return recipe_leaf_specs(res.tasks, world, res.leaf_task) if isinstance(world, World) else None


def _completed_actions(
    res: LanguageResult, world: SceneLike | None, client: LLMClient | None
) -> LeafSpecs | None:
    """Leaf actions by the LLM's action completion (None without a client or a scene)."""
    if client is None or world is None:
        return None
    return llm_leaf_actions(res, client, set(world.object_types()), world.name or "the scene")


# where the leaves' actions come from (`actions=`; "auto" is recipe offline, llm otherwise)
ACTION_SOURCES: dict[str, LeafActions] = {
    "recipe": _recipe_actions,
    "llm": _completed_actions,
    "none": lambda res, world, client: None,
}


def recipe_leaf_specs(
    tasks: list[BaseTaskSpec], world: World, leaf_task: dict[str, str]
) -> dict[str, LeafOrFormula]:
    """Leaf actions from the worlds' recipes (`BaseTask.leaf_specs(world, others)`), by HTT leaf id."""
    out: dict[str, LeafOrFormula] = {}
    by_task: dict[str, list[str]] = {}
    for leaf, t in leaf_task.items():
        by_task.setdefault(t, []).append(leaf)
    demand = demand_of(tasks)  # once, not once per task: linear in the number of tasks
    for task in tasks:
        leaves = sorted(by_task.get(task.id, []))
        places = bound_places(task)
        if places and len(leaves) == task.count * len(places):  # one recipe per place, all its objects
            for p, place in enumerate(places):
                specs = task.model_copy(update={"receptacle": place}).leaf_specs(world, demand=demand)
                out.update(zip(leaves[p * task.count : (p + 1) * task.count], specs, strict=False))
            continue
        out.update(zip(leaves, task.leaf_specs(world, demand=demand), strict=False))
    return out


def _parse(
    backend: str,
    instruction: str,
    grounder: Grounder,
    strict: bool,
    look: AffordanceLookup | None,
    world: SceneLike | None = None,
    instances: Counter[str] | None = None,
) -> LanguageResult:
    """A backend that needs no LLM (`parsers.PARSERS`), with the state and treatment requests it cannot
    read (`state_tasks`)."""
    types = set(grounder.types) if grounder.types is not None else None
    scene = world.name if world is not None else None
    reader = _state_reader(grounder, world, instances)
    parsed = _parsed_and_reread(PARSERS[backend], instruction, types, scene, strict, look, reader)
    if parsed.unparsed:  # clauses that change or treat one object (SMART-LLM's skills and goals)
        states, left = reader.read_unparsed(parsed.unparsed, parsed.tasks)
        parsed = _relettered(
            parsed.model_copy(update={"unparsed": left}), [[t] for t in parsed.tasks], states
        )
    if reader.counts is not None and parsed.tasks:  # "all the mugs": every instance the scene holds
        every = take_every_instance(instruction, parsed.tasks, reader.counts)
        parsed = parsed.model_copy(update={"tasks": every})
    if not parsed.tasks:
        # the words that make it so (a negation, a skill no task has, a person, a condition, a
        # repetition, a return to where a thing was), named first
        named = [
            str(u)
            for u in account(instruction, [], [])
            if u.category in ("negation", "action", "condition", "count")
            or u.reason.startswith(("a person", "no object of this world", "no base task returns"))
        ]
        why = "; ".join(named + parsed.unparsed) or "no task verb found"
        hint = suggestion_text(instruction, world if isinstance(world, World) else None)
        raise HTTError(
            f"the offline parser understood no task in {instruction!r} ({why}){hint}; rephrase it or "
            "use an LLM backend"
        )
    htt, task_node, leaf_task = build_htt(
        instruction, parsed.tasks, parsed.before, parsed.groups, parsed.group_texts
    )
    return LanguageResult(
        backend=backend,
        instruction=instruction,
        scene=scene,
        htt=htt,
        tasks=parsed.tasks,
        before=list(parsed.before),
        task_node=task_node,
        leaf_task=leaf_task,
        ambiguities=parsed.ambiguities,
        unparsed=parsed.unparsed,
        issues=parsed.issues,
        # the sentences the reading left out, which name nothing a task needs: said, never silent (h299)
        assumptions=[frame_note(parsed.frames)] if parsed.frames else [],
    )


def _state_reader(
    grounder: Grounder, world: SceneLike | None, instances: Counter[str] | None = None
) -> StateReader:
    """The reader of state and treatment requests (`state_tasks`) for this scene (its object counts,
    `instances` or the world's own, when the scene is a `World`)."""
    if not isinstance(world, World):
        return StateReader(grounder)

    def can(type_: str, state: str) -> bool:
        if state not in get_args(State):  # a treatment or a throw: any object the recipe accepts
            return True
        return bool(world.instances(type_)) and can_take_state(world, type_, state)

    return StateReader(grounder, scene_instances(world) if instances is None else instances, can)


def _parsed_and_reread(
    parse: Parser,
    instruction: str,
    types: set[str] | None,
    scene: str | None,
    strict: bool,
    look: AffordanceLookup | None,
    reader: StateReader,
) -> OfflineParse:
    """The parser's reading, or, when the whole instruction is nothing but state and treatment requests
    and the parser fails on it, leaves words unread or fills a place no word names, the requests
    (`state_tasks`); otherwise each task whose clause is read so is reread (`state_tasks.reread`). A
    scene error of the strict parse stands unless the requests replace the task that caused it."""
    from nl2hltl2plan.language.grammar import OfflineParse

    whole = reader.read(instruction)
    try:
        parsed = parse(instruction, types, scene or "the scene", strict=strict, affordances=look)
    except WorldError:
        if whole is not None:
            return _relettered(OfflineParse(instruction=instruction), [], whole)
        if not strict:
            raise
        parsed = parse(instruction, types, scene or "the scene", strict=False, affordances=look)
        parsed = _relettered(parsed, reread(parsed.tasks, instruction, reader))
        if types is not None and any(
            t not in types for x in parsed.tasks for r in SLOTS for t in getattr(x, r) or []
        ):
            raise
        return parsed.model_copy(update={"issues": []})
    loose = parsed.unparsed or not parsed.tasks or account(instruction, parsed.tasks, parsed.before)
    if whole is not None and (loose or any(guessed_slot(t, instruction) for t in parsed.tasks)):
        return _relettered(OfflineParse(instruction=instruction), [], whole)
    return _relettered(parsed, reread(parsed.tasks, instruction, reader))


def _relettered(
    parsed: OfflineParse, stand_for: list[list[BaseTaskSpec]], added: Sequence[BaseTaskSpec] = ()
) -> OfflineParse:
    """The parse with its i-th task replaced by `stand_for[i]` and the `added` tasks appended, all
    lettered afresh (A, B, ...); orders, groups and ambiguities follow the tasks (a replaced task's
    ambiguities go), a light condition comes before its task, and the new tasks are ordered by the
    instruction's sequence words (`state_tasks.state_orderings`)."""
    new_id: dict[str, list[str]] = {}
    tasks: list[BaseTaskSpec] = []
    fresh: list[BaseTaskSpec] = []
    kept: set[str] = set()  # tasks the parser read as they stand
    for old, group in [*zip(parsed.tasks, stand_for, strict=True), *((None, [t]) for t in added)]:
        renamed = [t.model_copy(update={"id": task_letter(len(tasks) + k)}) for k, t in enumerate(group)]
        tasks += renamed
        if old is None or group != [old]:
            fresh += renamed
        else:
            kept.add(old.id)
        if old is not None:
            new_id[old.id] = [t.id for t in renamed]
    before = [(x, y) for a, b in parsed.before for x in new_id.get(a, [a]) for y in new_id.get(b, [b])]
    groups = [[x for m in grp for x in new_id.get(m, [m])] for grp in parsed.groups]
    before += light_orders(tasks) + state_orderings(parsed.instruction, tasks, fresh)
    ambiguities = [
        a.model_copy(update={"task": new_id[a.task][0]}) for a in parsed.ambiguities if a.task in kept
    ]
    return parsed.model_copy(
        update={
            "tasks": tasks,
            "before": list(dict.fromkeys(before)),
            "groups": groups,
            "ambiguities": ambiguities,
        }
    )


class _Choosable(Protocol):
    tasks: list[BaseTaskSpec]
    ambiguities: list[Ambiguity]

    def model_copy(self, *, update: dict | None = None, deep: bool = False) -> Self: ...


C = TypeVar("C", bound=_Choosable)  # a LanguageResult or a parser's OfflineParse


def apply_choices(res: C, choices: dict[str, str]) -> C:
    """A user's pick for an ambiguous slot (`plan --ask`): that slot becomes exactly the chosen type.
    Returns the result with the picked slots set and their ambiguities gone."""
    if not choices:
        return res
    by_id = {t.id: t for t in res.tasks}
    picks: dict[str, dict[str, list[str]]] = {}  # task id -> {role: [type]}
    for key, chosen in choices.items():
        task_id, _, role = key.partition(".")
        if by_id.get(task_id) is None or role not in SLOTS:
            raise HTTError(f"cannot apply the choice {key}={chosen}: no task {task_id!r} with a {role!r}")
        picks.setdefault(task_id, {})[role] = [chosen]
    tasks = [t.model_copy(update=picks[t.id]) if t.id in picks else t for t in res.tasks]
    ambiguities = [a for a in res.ambiguities if f"{a.task}.{a.role}" not in choices]
    return res.model_copy(update={"tasks": tasks, "ambiguities": ambiguities})


def _attach_spec(res: LanguageResult, ltl: LtlSource, client: LLMClient | None) -> LanguageResult:
    """Algorithm 1 with our leaf specs and the chosen GenerateLTL."""
    missing = [n.id for n in res.htt.leaves() if n.id not in res.leaf_specs]
    if missing:
        warning = f"hierarchical spec not built: no actions for leaves {missing}"
        return res.model_copy(update={"warnings": [*res.warnings, warning]})
    if ltl not in LTL_SOURCES:
        raise LLMError(f"unknown LTL generator {ltl!r}: compiler, llm or learned")
    checks = list(res.ltl_checks)  # the LLM translations that differed from the compiler, appended
    generate = LTL_SOURCES[ltl](client, checks)
    leaf_specs = res.leaf_specs
    spec = build_spec(res.htt, generate_ltl=generate, action_completion=lambda node: leaf_specs[node.id])
    update: dict[str, object] = {"spec": spec, "ltl_checks": checks}
    if res.constraint_specs:  # the negations, beside the nodes (G !p, until-guards)
        spec = HierarchicalSpec(spec.levels, spec_constraints(res.constraint_specs, res.task_node))
        update |= {"spec": spec, "constraints": sorted(c.describe() for c in spec.constraints)}
    return res.model_copy(update=update)


def _llm_ltl(client: LLMClient | None, checks: list[str]) -> GenerateLTL:
    if client is None:
        raise LLMError("--ltl llm needs an LLM backend (or use --ltl learned with a translator server)")
    return llm_generate_ltl(client, client, checks)


# GenerateLTL of Algorithm 1 (`ltl=`): the exact compiler, the LLM, or a learned translator server
LTL_SOURCES: dict[str, Callable[[LLMClient | None, list[str]], GenerateLTL]] = {
    "compiler": lambda client, checks: compile_relations,
    "llm": _llm_ltl,
    "learned": lambda client, checks: llm_generate_ltl(client, translator_client(), checks),
}
