"""The default `offline` backend: the grammar and the structure model for structure, the slot model for
slots where the grammar fails.

The offline grammar parser segments the instruction into clauses and reads the temporal relations and
groups; the learned structure model (`structure.py`) reads them too, and its reading is taken where the
grammar's is incomplete or where they disagree and the model is sure (`structured.decide`). A clause
the grammar cannot read is read by the slot model and re-parsed (`rescue`). For each clause the slot
model predicts the task kind and ranks the scene's types for the object, container, receptacle and
lamp: it orders a word's several scene types ("table") and fills a slot the grammar found nothing for
in the scene; with the default `Policy` (chosen on the text-faithful validation, docs/learned.md) it
never replaces a kind, type or `sliced` the grammar read. A slot whose best two scene types are close is
reported as an `Ambiguity` with the candidates ranked.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from nl2hltl2plan.domain.task_kinds import slots_of
from nl2hltl2plan.errors import Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar import OfflineParse
from nl2hltl2plan.language.grammar import parse_instruction as grammar_parse
from nl2hltl2plan.language.grammar.frames import NOT_A_WHOLE_TASK
from nl2hltl2plan.language.grammar.order_relations import ORDER_LEFT_OPEN
from nl2hltl2plan.language.grammar.references import NOT_CERTAIN
from nl2hltl2plan.language.grammar.sentences import without_connective_to
from nl2hltl2plan.language.grounding import AffordanceLookup, find_mentions
from nl2hltl2plan.language.learned.ranker import TypeRanker
from nl2hltl2plan.language.learned.rescue import rewrite
from nl2hltl2plan.language.learned.slot_model import SlotModel, SlotPrediction
from nl2hltl2plan.language.learned.span_order import POINTING, sentences_left_out
from nl2hltl2plan.language.learned.structure import StructureModel, load_structure
from nl2hltl2plan.language.learned.structured import (
    StructurePolicy,
    base_form,
    combine_spans,
    complete_and_accounted,
    decide,
    order_words_kept,
    repeat_of_two,
    resolved,
    with_verb,
)
from nl2hltl2plan.language.result import Ambiguity
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter
from nl2hltl2plan.language.type_choice import note_for


@dataclass(frozen=True)
class Policy:
    """How grammar and model are combined. The defaults were chosen on the text-faithful validation of
    valid_seen (`suites.alfred.learned_validation`, docs/learned.md): every override policy measured
    within 1 point, so
    the one that overrides least was taken (the model never replaces a kind, type or `sliced` the grammar
    read); the segmentation rescue measured +4 to +5 points."""

    kind_override: float = 1.01  # the model's kind replaces the grammar's when its probability is this high
    override: float = 1.01  # the model replaces the grammar's slot type when its top scene type is this sure
    sliced_from_model: bool = False
    ambiguous_ratio: float = 0.5  # second candidate >= ratio * first -> reported as ambiguous
    rescue: bool = True  # clauses the grammar could not read: read by the model, re-parsed (`rescue`)
    rescue_kind: float = 0.5  # ... when the model's kind probability is at least this
    container_switch: bool = False  # place -> place_in_container when the model is sure and the text names it
    # a slot the grammar found nothing for is filled by the model's best type only when its probability is
    # at least this (chosen on the validation sets, results/language_trust/report.md); otherwise the
    # clause's task is dropped and the clause goes to `unparsed`
    fill: float = 0.3
    # the structure model's reading against the grammar's (`structured.py`); None: the grammar's alone
    structure: StructurePolicy | None = StructurePolicy()


DEFAULT_POLICY = Policy()  # what the `offline` backend uses

# Candidate combinations, compared on the text-faithful validation (`suites.alfred.learned_validation`).
POLICIES: dict[str, Policy] = {
    "default": Policy(),
    "no_rescue": Policy(rescue=False),
    "hybrid_v2": Policy(kind_override=0.8, override=0.9, sliced_from_model=True, rescue=False),
    "hybrid_v2_rescue": Policy(kind_override=0.8, override=0.9, sliced_from_model=True),
    "hybrid_rescue_container_0.6": Policy(
        kind_override=0.6, override=0.9, sliced_from_model=True, container_switch=True
    ),
}


class LearnedParse(OfflineParse):
    """The offline parser's result as the learned backend gives it (its `ambiguities` are ranked)."""


@lru_cache(maxsize=2)
def load_model(path: Path | None = None) -> SlotModel:
    return SlotModel.load(path)


def _in_scene(grammar: list[str] | None, types: set[str] | None) -> list[str]:
    """The grammar's types for a slot that the scene has (all of them when the scene is unknown)."""
    return [t for t in grammar or [] if types is None or t in types]


def _choose(
    grammar: list[str] | None,
    ranked: list[tuple[str, float]],
    types: set[str] | None,
    policy: Policy,
    order: list[tuple[str, float]],
) -> list[str] | None:
    """The slot's types: the grammar's (several ordered by `order`: the type ranker's), or
    the model's best when the grammar found none in the scene."""
    in_scene = _in_scene(grammar, types)
    if ranked and (not in_scene or (ranked[0][1] >= policy.override and ranked[0][0] not in in_scene)):
        if grammar and not in_scene and types is not None:
            return grammar  # the grammar named a type the scene lacks: keep it, it is reported as missing
        return [ranked[0][0]]
    if in_scene and len(in_scene) > 1 and order:
        score = dict(order)
        return sorted(in_scene, key=lambda t: -score.get(t, 0.0))
    return grammar or None


def _order(
    task: BaseTaskSpec,
    role: str,
    ranked: list[tuple[str, float]],
    types: set[str] | None,
    ranker: TypeRanker | None,
) -> list[tuple[str, float]]:
    """The grammar's several scene types for the slot ("the table"), ordered by the type ranker; else the
    slot model's ranking."""
    in_scene = _in_scene(getattr(task, role), types)
    if ranker is None or len(in_scene) < 2:
        return ranked
    prob = dict(ranked)
    return ranker.order(task.text, [(t, prob.get(t, 0.0)) for t in in_scene])


def _ambiguity(
    task: BaseTaskSpec,
    role: str,
    chosen: list[str],
    ranked: list[tuple[str, float]],
    policy: Policy,
    order: list[tuple[str, float]],
) -> Ambiguity | None:
    """Several scene types kept for the word (e.g. "table"; confidences from `order`), or the model's best
    two close: ranked."""
    prob = dict(order)
    if len(chosen) > 1:
        total = sum(prob.get(t, 0.0) for t in chosen) or 1.0
        cands = [(t, prob.get(t, 0.0) / total) for t in chosen]
    elif len(ranked) > 1 and ranked[0][0] in chosen and ranked[1][1] >= policy.ambiguous_ratio * ranked[0][1]:
        cands = ranked[:3]
    else:
        return None
    return Ambiguity(
        task=task.id,
        role=role,
        word=_word_for(task.text, [t for t, _ in cands]),
        candidates=[t for t, _ in cands],
        confidence=[round(q, 3) for _, q in cands],
    )


def _word_for(text: str, candidates: list[str]) -> str:
    """The phrase of the clause that can mean the candidates ("the table"), else the clause itself."""
    for m in find_mentions(text):
        if set(candidates) & set(m.entry.types):
            return m.surface
    return text


def _container_named(task: BaseTaskSpec, pred: SlotPrediction, policy: Policy) -> bool:
    """The model reads a container task the grammar read as `place`, and the clause names its container."""
    if not policy.container_switch or pred.top_kind != "place_in_container" or task.kind != "place":
        return False
    if pred.kind[0][1] < policy.kind_override or not pred.slots.get("container"):
        return False
    named = {t for m in find_mentions(task.text) for t in m.entry.types}
    return pred.slots["container"][0][0] in named


def combine(
    task: BaseTaskSpec,
    pred: SlotPrediction,
    types: set[str] | None,
    policy: Policy,
    ambiguities: list[Ambiguity],
    ranker: TypeRanker | None = None,
    guesses: list[str] | None = None,
) -> BaseTaskSpec:
    """One base task from the grammar's reading of a clause and the model's prediction for it; a slot the
    model fills below `policy.fill` is reported in `guesses`."""
    kind = pred.top_kind if pred.kind[0][1] >= policy.kind_override else task.kind
    if (
        "place_in_container" in (kind, task.kind)
        and kind != task.kind
        and not _container_named(task, pred, policy)
    ):
        kind = task.kind  # a container needs a second object the text names (annotators often omit it)
    values: dict[str, list[str] | None] = {
        "object": None,
        "container": None,
        "receptacle": None,
        "light": None,
    }
    for role in slots_of(kind):
        ranked = pred.slots.get(role, [])
        order = _order(task, role, ranked, types, ranker)
        values[role] = _choose(getattr(task, role), ranked, types, policy, order)
        filled = ranked and not getattr(task, role) and values[role] == [ranked[0][0]]
        if filled and guesses is not None and ranked[0][1] < policy.fill:
            guesses.append(
                f"{task.text!r}: its {role} is not stated (the model's guess {ranked[0][0]} at "
                f"{ranked[0][1]:.0%} is below the {policy.fill:.0%} threshold)"
            )
        amb = _ambiguity(task, role, values[role] or [], ranked, policy, order)
        if amb is not None:
            ambiguities.append(amb)
    sliced = pred.sliced >= 0.5 if policy.sliced_from_model else task.sliced
    return BaseTaskSpec(
        id=task.id,
        text=task.text,
        kind=kind,  # type: ignore[arg-type]
        object=values["object"] or task.object,
        count=task.count if kind == task.kind else (2 if kind == "place_two" else 1),
        sliced=sliced,
        container=values["container"],
        receptacle=values["receptacle"],
        light=values["light"],
    )


def parse_instruction(
    instruction: str,
    types: set[str] | frozenset[str] | None = None,
    scene: str = "the scene",
    strict: bool = True,
    affordances: AffordanceLookup | None = None,
    *,
    policy: Policy | None = None,
    model: SlotModel | None = None,
    structure: StructureModel | None = None,
) -> LearnedParse:
    """Parse one instruction (the offline parser's contract, plus `ambiguities`).

    `strict=True`: a slot whose types the scene lacks raises `WorldError`; otherwise it is listed in `issues`.
    """
    policy = policy or DEFAULT_POLICY
    scene_types = set(types) if types is not None else None
    ctx = ParseContext(scene_types, scene, affordances, policy, model or load_model())
    parse = _read_once(instruction, ctx)
    if policy.structure is not None:
        parse = _arbitrated(parse, instruction, ctx, structure or load_structure())
    issues = _missing(parse.tasks, scene_types, scene)
    if strict and issues:
        raise WorldError(issues[0])
    return parse.model_copy(update={"issues": issues})


@dataclass(frozen=True)
class ParseContext:
    """What every reading of one instruction shares: the scene, and the policy and model that read it."""

    scene_types: set[str] | None
    scene: str
    affordances: AffordanceLookup | None
    policy: Policy
    model: SlotModel
    # the grammar-first readings made so far, by text: a span of one task is often the whole instruction
    read: dict[str, LearnedParse] = field(default_factory=dict, compare=False, repr=False)


def _read_once(text: str, ctx: ParseContext) -> LearnedParse:
    """The grammar-first reading of `text`, made once per parse (a pure function of the text and `ctx`)."""
    if (kept := ctx.read.get(text)) is None:
        kept = ctx.read[text] = grammar_first_reading(text, ctx)
    return kept


def grammar_first_reading(instruction: str, ctx: ParseContext) -> LearnedParse:
    """The grammar's structure, its clauses' slots filled and ordered by the slot model."""
    scene_types, policy, model = ctx.scene_types, ctx.policy, ctx.model
    g = grammar_parse(instruction, scene_types, ctx.scene, strict=False, affordances=ctx.affordances)
    if policy.rescue and g.unparsed:
        g = _rescued(g, instruction, ctx)
    drafts = list(g.tasks)
    unparsed = list(g.unparsed)
    # no clause the grammar reads: the whole text may still be one task, unless the grammar found two
    # places it could go ("on the desk ... in the safe": which one is a guess the model must not make)
    whole = not drafts and bool(instruction.strip()) and not any(
        why in u for u in g.unparsed for why in NOT_A_WHOLE_TASK
    )
    if whole:
        drafts = [BaseTaskSpec(id=task_letter(0), text=instruction.strip(), kind="place", object=[])]
    preds = model.predict([d.text or instruction for d in drafts], scene_types)
    ambiguities: list[Ambiguity] = []
    tasks, before, guessed = [], list(g.before), []
    for d, p in zip(drafts, preds, strict=True):
        guesses: list[str] = []
        t = combine(d, p, scene_types, policy, ambiguities, model.ranker, guesses)
        if guesses:  # an unstated slot the model is not sure of: the clause is not understood
            unparsed += guesses
            guessed.append(t.id)
        else:
            tasks.append(t)
    before = [(a, b) for a, b in before if a not in guessed and b not in guessed]
    ambiguities = [a for a in ambiguities if a.task not in guessed]
    if whole and tasks and not (_names_its_types(tasks[0]) and not account(instruction, tasks, [])):
        tasks, ambiguities = [], []  # the model would invent a task ("hello there"): keep what is unparsed
    elif whole and tasks:
        unparsed = []
    return LearnedParse(
        instruction=instruction,
        tasks=tasks,
        before=before,
        groups=[[t for t in grp if t not in guessed] for grp in g.groups],
        group_texts=g.group_texts,
        unparsed=unparsed,
        ambiguities=ambiguities,
    )


def structure_reading(
    instruction: str, ctx: ParseContext, structure: StructureModel
) -> tuple[LearnedParse, float, bool] | None:
    """The structure model's spans, each read by the grammar + slot model, its confidence and whether a
    span points back at an earlier one; None when a span does not read completely or the whole does not
    pass the word accounting."""
    said = without_connective_to(instruction)
    reading = structure.read(said)
    if not reading.spans:
        return None
    parsed, ambiguities = [], []
    previous: tuple[str, BaseTaskSpec] | None = None
    for k, span in enumerate(reading.spans):
        text = with_verb(base_form(span.text), previous[0] if previous else None)
        try:
            p = _read_once(text, ctx)
            if repeat_of_two(said, reading.spans, k):
                return None
            if p.unparsed and (again := resolved(text, previous)) != text:
                text = again
                p = _read_once(text, ctx)
        except Nl2Hltl2PlanError:
            return None
        if p.unparsed or not p.tasks:
            return None
        previous = (text, p.tasks[-1])
        parsed.append((p.tasks, p.before))
        ambiguities.append(p.ambiguities)
    tasks, before, groups = combine_spans(reading, parsed, said)
    if not complete_and_accounted(instruction, tasks, before):
        return None
    renamed = _renamed_ambiguities(ambiguities, parsed, tasks)
    left = sentences_left_out(said, [(s.start, s.end) for s in reading.spans])
    parse = LearnedParse(
        instruction=instruction, tasks=tasks, before=before, groups=groups, ambiguities=renamed, frames=left
    )
    return parse, reading.confidence, any(x.relation in POINTING for x in reading.spans)


def _renamed_ambiguities(
    per_span: list[list[Ambiguity]],
    parsed: list[tuple[list[BaseTaskSpec], list[tuple[str, str]]]],
    tasks: list[BaseTaskSpec],
) -> list[Ambiguity]:
    out, offset = [], 0
    for ambs, (span_tasks, _) in zip(per_span, parsed, strict=True):
        new = {t.id: tasks[offset + i].id for i, t in enumerate(span_tasks)}
        out += [a.model_copy(update={"task": new[a.task]}) for a in ambs if a.task in new]
        offset += len(span_tasks)
    return out


def _arbitrated(
    g: LearnedParse, instruction: str, ctx: ParseContext, structure: StructureModel
) -> LearnedParse:
    """The grammar's reading or the structure model's, by `structured.StructurePolicy`."""
    rule = ctx.policy.structure
    assert rule is not None
    s = structure_reading(instruction, ctx, structure)
    if s is not None and _grounds_otherwise(s[0], g, ctx.scene_types):
        s = None
    complete = grammar_complete(g)
    model = (s[0].tasks, s[0].before, s[1]) if s else None
    uncertain = any(NOT_CERTAIN in u or ORDER_LEFT_OPEN in u for u in g.unparsed)  # words leave it open
    choice = decide(
        (g.tasks, g.before, complete), model, rule, instruction, points=bool(s and s[2]), uncertain=uncertain
    )
    if choice == "model" and s is not None:
        return s[0]
    if choice == "neither" and s is not None:
        why = (
            f"the grammar and the structure model read this differently ({len(g.tasks)} vs "
            f"{len(s[0].tasks)} tasks), and the model is only {s[1]:.0%} sure"
        )
        return g.model_copy(update={"tasks": [], "before": [], "groups": [], "unparsed": [why]})
    return g


def _grounds_otherwise(s: LearnedParse, g: LearnedParse, types: set[str] | None) -> bool:
    """Whether a structure-model task grounds a slot that the whole instruction's reading grounded (a scene
    type, in the same clause) to another type: a span read alone loses what the rest of the sentence says of
    a noun ("the towel ... then the hand towel": Towel, not ALFRED's HandTowel), so such a re-read does not
    stand against the whole reading and its verdict; the span only fills what the whole left open."""
    said = {t.text.strip().lower(): t for t in g.tasks}
    for t in s.tasks:
        whole = said.get(t.text.strip().lower())
        if whole is None or whole.kind != t.kind:
            continue
        for role in slots_of(t.kind):
            grounded = set(_in_scene(getattr(whole, role), types))
            if grounded and not set(getattr(t, role) or []) <= grounded:
                return True
    return False


def grammar_complete(g: LearnedParse) -> bool:
    """Whether the grammar-first reading is whole: tasks, nothing unread, and every content word used
    (check 1: a reading that leaves "the orange" out is refused anyway, so it cannot outweigh the model's)."""
    return bool(g.tasks) and not g.unparsed and complete_and_accounted(g.instruction, g.tasks, g.before)


def _rescued(g: OfflineParse, instruction: str, ctx: ParseContext) -> OfflineParse:
    """The grammar's parse with its unread clauses rewritten, when that reads more tasks."""
    text = rewrite(instruction, list(g.unparsed), ctx.model, ctx.scene_types, ctx.policy.rescue_kind)
    if text is None:
        return g
    again = grammar_parse(text, ctx.scene_types, ctx.scene, strict=False, affordances=ctx.affordances)
    if len(again.tasks) <= len(g.tasks) or account(instruction, again.tasks, again.before):
        return g  # a re-reading must read more and pass the word accounting (check 1) of the original
    if not order_words_kept(instruction, again.tasks, again.before):
        return g  # nor drop what an order word says ("A. Put the book on the bed, both before C")
    return again.model_copy(update={"instruction": instruction})


def _names_its_types(task: BaseTaskSpec) -> bool:
    """Whether the text names (a lexicon phrase for) the type chosen for every slot of the task."""
    named = {t for m in find_mentions(task.text) for t in m.entry.types}
    return all(set(getattr(task, r) or []) & named for r in slots_of(task.kind))


def _missing(tasks: list[BaseTaskSpec], types: set[str] | None, scene: str) -> list[str]:
    if types is None:
        return []
    out = []
    for t in tasks:
        for role in slots_of(t.kind):
            vals = getattr(t, role) or []
            if not vals:
                out.append(f"task {t.id} ({t.text!r}): no {role} found in {scene}")
            elif not any(v in types for v in vals):
                # what is true of the word's other types ("chair": ALFRED's Chair holds nothing)
                other = note_for(t, role, vals[0], types, scene)
                out.append(f"no {vals[0]} in {scene}" + _listed_not_built(vals[0], scene) + other)
    return out


def _listed_not_built(type_: str, scene: str) -> str:
    """Why a type the floor plan's object lists name is missing: the world built from them has none."""
    from nl2hltl2plan.language.grounding import scene_types
    from nl2hltl2plan.worlds.floor_plans import unbuilt_reason

    try:
        listed = type_ in scene_types(scene)
        why = unbuilt_reason(scene, type_) if listed else None
    except Nl2Hltl2PlanError:  # not an ALFRED floor plan (tabletop, demo): nothing more to say
        return ""
    if not listed:
        return ""
    because = f": {why}" if why else ""  # the world's side: what the data lacks to place it
    return f" (its object list names {type_}, but the world built from it has none{because})"
