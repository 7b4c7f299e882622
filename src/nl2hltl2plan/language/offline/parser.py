"""A deterministic grammar-based parser: instruction -> base tasks + temporal relations.

Pipeline (no model involved):

1. sentences: split on `.`, `;`, `!`, `?`; strip leading markers ("Then,", "Finally,", "After placing the
   statue,", "In any order,", "First,") and trailing ones ("at any time", "first", "afterwards", "after
   moving the X") and record them;
2. clauses: split a sentence before each verb that follows a joiner ("and", ",", "then", "to", ...);
3. frames: per clause the verb class and its noun phrases with their prepositions (object, destination,
   source, "with X in it", "by the light of a lamp"), the state words (washed, heated, chilled, sliced),
   counts ("two", plurals);
4. tasks: consecutive clauses about the same object ("it", "them", the same noun, the container)
   form one base task; several objects sharing one verb ("the phone and the bat") form a group;
5. relations: the ANNOTATION_GUIDE rules ("Then Y" after the previous clause, "Finally Y" after every
   earlier task not allowed at any time, "After X-ing the Z, Y" after the task about Z, "first",
   "prior to that", "after completing the previous tasks"), transitively reduced.

Whatever cannot be read this way is listed in `unparsed` instead of being guessed.
"""

from __future__ import annotations

from pydantic import BaseModel, Field

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.grounding import (
    AffordanceLookup,
    Grounder,
    alfred_lookup,
)
from nl2hltl2plan.language.offline import grammar as G
from nl2hltl2plan.language.offline.clauses import expand_gapping, split_clauses
from nl2hltl2plan.language.offline.drafts import Unit, incomplete, item_text, joins, merge_items
from nl2hltl2plan.language.offline.frames import IN_SENTENCE, dest_of, parse_frame
from nl2hltl2plan.language.offline.phrases import NP, parse_np, tokens
from nl2hltl2plan.language.offline.references import new_tasks_from_ref, ref_targets, self_state
from nl2hltl2plan.language.offline.sentences import after_ref, normalize, split_sentences
from nl2hltl2plan.language.offline.tasks import Draft, TaskBuilder
from nl2hltl2plan.language.tasks import BaseTaskSpec, task_letter, transitive_closure, transitive_reduction


# ----- result ----------------------------------------------------------------------------------------
class OfflineParse(BaseModel):
    """What the offline parser understood: base tasks, `before` pairs, groups, and what it could not read."""

    instruction: str
    tasks: list[BaseTaskSpec] = Field(default_factory=list)
    before: list[tuple[str, str]] = Field(default_factory=list)
    groups: list[list[str]] = Field(default_factory=list)
    group_texts: list[str] = Field(default_factory=list)  # the words that state each group
    unparsed: list[str] = Field(default_factory=list)
    issues: list[str] = Field(default_factory=list)



# ----- main entry ----------------------------------------------------------------------------------------
def parse_instruction(
    instruction: str,
    types: set[str] | frozenset[str] | None = None,
    scene: str = "the scene",
    strict: bool = False,
    affordances: AffordanceLookup | None = None,
) -> OfflineParse:
    """Parse one instruction. `types`: the scene's object types (None: keep the words, no grounding).

    With `strict=True` a word whose type is not in the scene raises `WorldError` ("no Statue in
    FloorPlan17"); otherwise it is kept with its most plausible type and listed in `issues`.
    `affordances` (type -> `Affordances` or None when unknown; default: ALFRED's facts when the shared data
    is there) narrows a word with several types to those that can play their role (`grounding.Roles`).
    """
    text = normalize(instruction)
    grounder = Grounder(types, scene) if types is not None else None
    if types is not None and affordances is None:
        affordances = alfred_lookup()
    b = TaskBuilder(grounder, strict, affordances)
    drafts: list[Draft] = []
    units: list[Unit] = []
    extra_rel: list[tuple[str, int, str]] = []  # relation sentences between objects
    next_group = [-1]
    group_text: dict[int, str] = {}
    gap_groups: dict[int, int] = {}  # Clause.gap -> group
    last_verb, last_dest = "", ""
    for s_idx, (sentence, s_start) in enumerate(split_sentences(text)):
        body = sentence
        markers: list[tuple[str, str]] = []
        changed = True
        while changed:
            changed = False
            split = after_ref(body)
            if split is not None:
                markers.append((G.AFTER_REF, split[0]))
                body = split[1]
                changed = True
                continue
            for pat, kind in G.LEADING:
                m = pat.match(body)
                if m and m.end() > 0:
                    ref = m.groupdict().get("ref") or ""
                    if kind:
                        markers.append((kind, ref))
                    body = body[m.end() :]
                    changed = True
                    break
        rel = G.REL_SENTENCE.match(body)
        if rel and not any(w in G.VERBS for w, _, _ in tokens(rel.group("a"))[:1]):
            # "The red block should be placed before the blue block": relation between tasks named by objects
            extra_rel.append((rel.group("rel").lower(), -1, rel.group("a") + "|" + rel.group("b")))
            continue
        trailing: list[tuple[str, str]] = []
        changed = True
        while changed and body:
            changed = False
            for pat, kind in G.TRAILING:
                m = pat.search(body)
                if m and m.start() > 0:
                    if kind == "ref":
                        rel = m.group("rel").lower()
                        trailing.append((G.BEFORE_REF if rel == "before" else G.AFTER_REF, m.group("ref")))
                    else:
                        trailing.append((kind, ""))
                    body = body[: m.start()]
                    changed = True
                    break
        body = body.strip(" ,")
        if not body:
            continue
        rel = G.REL_SENTENCE.match(body)
        if rel and not any(w in G.VERBS for w, _, _ in tokens(rel.group("a"))[:1]):
            # "The red block should be placed before the blue block."
            extra_rel.append((rel.group("rel").lower(), -1, rel.group("a") + "|" + rel.group("b")))
            continue
        if G.NO_ORDER_SENTENCE.search(body) and not any(w in G.VERBS for w, _, _ in tokens(body)[:1]):
            continue
        offset = s_start + sentence.index(body) if body in sentence else s_start
        clauses = expand_gapping(split_clauses(body), last_verb, last_dest, gap_base=100 * s_idx)
        first_unit = len(units)
        sentence_drafts: list[int] = []
        prev_clause_tasks: list[int] = []
        # "put things into the upper rack, first X, then Y": a shared destination for the clauses that follow
        context: list[tuple[str, NP]] = []
        context_group = -1
        pending_joiner = ""
        for clause in clauses:
            c_text, c_start, joiner = clause.text, clause.start, clause.joiner
            fr = parse_frame(c_text, offset + c_start, joiner)
            if fr.cls not in {"none", "other"}:
                last_verb = c_text.split()[0]
                for it in fr.items:
                    dst = dest_of(it, fr.cls)
                    last_dest = next((f"{p} {np.text}" for p, np in it.pps if np is dst), last_dest)
            joiner = joiner or pending_joiner
            pending_joiner = ""
            if fr.cls == "none":
                if not sentence_drafts or any(
                    it.obj is not None and not it.obj.empty and not it.obj.pronoun for it in fr.items
                ):
                    b.unparsed.append(c_text)
                    continue
            if any(it.obj is not None and it.obj.count > 2 for it in fr.items):
                b.unparsed.append(
                    f"{c_text} (more than two objects of one kind in one task is not supported)"
                )
                continue
            if fr.ambiguous:
                b.unparsed.append(f"{c_text} (a list of destinations)")
                continue
            if fr.cls == "light" and not any(
                (it.obj is not None and it.obj.is_lamp()) or any(np.is_lamp() for _, np in it.pps)
                for it in fr.items
            ):
                if not any(it.obj is not None and it.obj.pronoun for it in fr.items):
                    fr.cls = "other"  # "switch on the coffee machine": no lamp, no task of ours
            if fr.cls == "other":
                real = [
                    it.obj
                    for it in fr.items
                    if it.obj is not None and not it.obj.empty and not it.obj.pronoun
                ]
                noise = (
                    fr.verb in {"open", "close", "shut"}
                    and sentence_drafts
                    and all(o.is_receptacle() or "door" in o.text.lower() for o in real)
                )
                if real and not noise:
                    b.unparsed.append(c_text)
                continue  # "close the refrigerator door", "while doing so"
            if all(it.obj is not None and it.obj.generic for it in fr.items):
                # a heading about generic things ("place items into the dishwasher"): its destination is the
                # context of the clauses that follow in this sentence, which form a group
                context = [(p, np) for it in fr.items for p, np in it.pps if p in G.DEST_PREPS]
                next_group[0] += 1
                context_group = next_group[0]
                group_text[context_group] = fr.text
                pending_joiner = joiner
                continue
            if context:
                for it in fr.items:
                    if it.obj is not None and not any(p in G.DEST_PREPS for p, _ in it.pps):
                        it.pps.extend(context)
            # multi-object clause items sharing one destination at the end: copy it to the others
            if len(fr.items) > 1:
                shared = [(p, np) for p, np in fr.items[-1].pps if p in G.DEST_PREPS]
                for it in fr.items[:-1]:
                    if not any(p in G.DEST_PREPS for p, _ in it.pps):
                        it.pps.extend(shared)
                fr.items = merge_items(fr.items, b)
            new_tasks: list[int] = []
            if clause.gap >= 0:
                if clause.gap not in gap_groups:
                    next_group[0] += 1
                    gap_groups[clause.gap] = next_group[0]
                    group_text[next_group[0]] = clause.whole
                group = gap_groups[clause.gap]
            elif context_group >= 0:
                group = context_group
            elif len(fr.items) > 1:
                next_group[0] += 1
                group = next_group[0]
                group_text[group] = fr.text
            else:
                group = -1
            for it in fr.items:
                d = drafts[sentence_drafts[-1]] if sentence_drafts else None
                if (
                    d is not None
                    and len(fr.items) == 1
                    and joiner not in {"first", "finally"}
                    and (
                        joins(d, fr, it)
                        or (
                            incomplete(d)
                            and fr.cls not in {"pick"}
                            and it.obj is not None
                            and (it.obj.pronoun or it.obj.empty)
                        )
                    )
                ):
                    d.frames.append((fr, it))
                    d.end = fr.end
                    continue
                if d is not None and len(fr.items) == 1 and incomplete(d) and d.obj is None:
                    d.frames.append((fr, it))
                    d.end = fr.end
                    continue
                label = clause.label if len(fr.items) == 1 else ""
                if len(fr.items) > 1 or context:
                    label = item_text(fr, it)
                drafts.append(
                    Draft(
                        frames=[(fr, it)],
                        sentence=s_idx,
                        start=fr.start,
                        end=fr.end,
                        group=group,
                        label=label,
                    )
                )
                sentence_drafts.append(len(drafts) - 1)
                new_tasks.append(len(drafts) - 1)
            if new_tasks:
                unit = Unit(tasks=new_tasks, sentence=s_idx, before_sentence=first_unit - 1)
                if joiner == "then" and prev_clause_tasks:
                    unit.seq_after_prev = True
                if joiner == "first":
                    unit.markers.append((G.FIRST, ""))
                if joiner == "finally":
                    unit.markers.append((G.FINALLY, IN_SENTENCE))
                units.append(unit)
                prev_clause_tasks = new_tasks
        sentence_units = units[first_unit:]
        if not sentence_units:
            continue
        for kind, ref in markers:
            for u in sentence_units:
                u.markers.append((kind, ref))
        for kind, ref in trailing:
            if kind in {G.THEN, G.FINALLY} and len(sentence_units) > 1:
                sentence_units[-1].markers.append((kind, IN_SENTENCE if kind == G.FINALLY else ref))
                sentence_units[-1].before_sentence = len(units) - 2
            elif kind == G.FREE and len(sentence_units) == 1 and len(sentence_units[0].tasks) > 1:
                pass  # "move the phone and the bat to the bed in any order": order inside the group is free
            elif (
                kind == G.FREE
                and len(sentence_units) > 1
                and sentence_units[0].markers == []
                and all(drafts[t].group >= 0 for u in sentence_units for t in u.tasks)
            ):
                pass
            else:
                for u in sentence_units:
                    u.markers.append((kind, ref))

    # drafts -> specs (drop drafts that are not tasks)
    specs: list[BaseTaskSpec | None] = []
    for d in drafts:
        t = d.label or text[d.start : d.end]
        try:
            specs.append(b.spec(d, t))
        except WorldError:
            raise
    keep = [i for i, s in enumerate(specs) if s is not None]
    index = {old: new for new, old in enumerate(keep)}
    final_specs: list[BaseTaskSpec] = [specs[i] for i in keep]  # type: ignore[misc]
    nps = [drafts[i].obj for i in keep]
    lights = [s.kind == "examine_in_light" for s in final_specs]
    for u in units:
        u.tasks = [index[t] for t in u.tasks if t in index]
    units = [u for u in units if u.tasks]

    # relations --------------------------------------------------------------------------------------------
    edges: set[tuple[int, int]] = set()
    free: set[int] = set()
    for u in units:
        kinds = {kind for kind, _ in u.markers}
        if G.FREE in kinds:
            free.update(u.tasks)
    for k, u in enumerate(units):
        prev = units[k - 1] if k > 0 else None
        seq_prev = prev
        # sentence markers refer to the clause before the sentence, not to a sibling clause of the sentence
        if prev is not None and prev.sentence == u.sentence and not u.seq_after_prev:
            cands = [v for v in units[:k] if v.sentence != u.sentence]
            prev = cands[-1] if cands else None
        first_of_sentence = min(t for v in units if v.sentence == u.sentence for t in v.tasks)
        earlier = [t for t in range(len(final_specs)) if t < first_of_sentence]
        for kind, ref in u.markers:
            if kind == G.THEN and prev is not None:
                edges.update((a, b2) for a in prev.tasks for b2 in u.tasks)
            elif kind == G.FINALLY:
                # "..., and finally Y" inside a sentence: after its sibling clauses too
                scope = [t for t in range(min(u.tasks))] if ref == IN_SENTENCE else earlier
                edges.update((a, b2) for a in scope if a not in free for b2 in u.tasks)
            elif kind == G.AFTER_ALL:
                edges.update((a, b2) for a in earlier for b2 in u.tasks)
            elif kind == G.BEFORE_PREV and prev is not None:
                edges.update((b2, a) for a in prev.tasks for b2 in u.tasks)
            elif kind in {G.AFTER_REF, G.BEFORE_REF}:
                targets, missing = ref_targets(ref, final_specs, nps, lights, None, exclude=u.tasks)
                own, _ = ref_targets(ref, final_specs, nps, lights, None)
                if not targets and own and all(t in u.tasks for t in own):
                    self_state(ref, [final_specs[t] for t in u.tasks])
                    continue
                targets = [t for t in targets if t not in u.tasks]
                for t in targets:
                    for b2 in u.tasks:
                        edges.add((t, b2) if kind == G.AFTER_REF else (b2, t))
                if missing and not targets:
                    # "after refrigerating the pan" about the task itself: a state, not an order
                    self_ref = any(
                        parse_np(p).key
                        and any(parse_np(p).key == (nps[t].key if nps[t] else None) for t in u.tasks)
                        for p in missing
                    )
                    if not self_ref:
                        new = new_tasks_from_ref(ref, b, text)
                        for spec in new:
                            final_specs.append(spec)
                            nps.append(None)
                            lights.append(spec.kind == "examine_in_light")
                            t = len(final_specs) - 1
                            for b2 in u.tasks:
                                edges.add((t, b2) if kind == G.AFTER_REF else (b2, t))
                        if not new:
                            b.unparsed.append(f"could not tell which task {ref!r} refers to")
        if u.seq_after_prev and seq_prev is not None:
            edges.update((a, b2) for a in seq_prev.tasks for b2 in u.tasks)
    # "First X" with no sequencing word right after: X before every later task not allowed at any time
    for k, u in enumerate(units):
        if any(kind == G.FIRST for kind, _ in u.markers):
            nxt = units[k + 1] if k + 1 < len(units) else None
            if nxt is not None and (
                nxt.seq_after_prev
                or any(kind in {G.THEN, G.AFTER_ALL, G.AFTER_REF} for kind, _ in nxt.markers)
            ):
                continue
            later = [t for v in units[k + 1 :] for t in v.tasks if t not in free]
            edges.update((a, b2) for a in u.tasks for b2 in later)
    # relation sentences between objects ("the red block should be placed before the blue block")
    for rel_kind, _, payload in extra_rel:
        if "|" not in payload:
            continue
        a_txt, b_txt = payload.split("|", 1)
        ta, _ = ref_targets(a_txt, final_specs, nps, lights, None)
        tb, _ = ref_targets(b_txt, final_specs, nps, lights, None)
        if not ta or not tb:
            b.unparsed.append(f"{a_txt} {rel_kind} {b_txt}")
        for x in ta:
            for y in tb:
                if x != y:
                    edges.add((x, y) if rel_kind == "before" else (y, x))

    # ids, acyclicity, reduction
    ids = [task_letter(i) for i in range(len(final_specs))]
    for i, s in enumerate(final_specs):
        s.id = ids[i]
    pairs = {(ids[a], ids[b2]) for a, b2 in edges if a != b2}
    closure = transitive_closure(pairs, ids)
    cyc = [(a, b2) for a, b2 in pairs if (b2, a) in closure]
    if cyc:
        b.unparsed.append(
            f"contradictory order words (cycle among {sorted({x for p in cyc for x in p})}); dropped"
        )
        pairs -= set(cyc)
    before = transitive_reduction(pairs, ids)
    groups: dict[int, list[str]] = {}
    for old, new in index.items():
        g = drafts[old].group
        if g >= 0:
            groups.setdefault(g, []).append(ids[new])
    return OfflineParse(
        instruction=instruction,
        tasks=final_specs,
        before=[(a, b2) for a, b2 in before],
        groups=[v for v in groups.values() if len(v) > 1],
        group_texts=[group_text.get(k, "") for k, v in groups.items() if len(v) > 1],
        unparsed=b.unparsed,
        issues=b.issues,
    )


