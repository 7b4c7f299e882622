"""Step 6, relations: the order markers of the units -> `before` pairs between task ids (the
ANNOTATION_GUIDE rules), contradictions dropped, transitively reduced."""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder, Tasks, Unit
from nl2hltl2plan.language.grammar.frames import IN_SENTENCE, OF_ALL
from nl2hltl2plan.language.grammar.phrases import parse_np
from nl2hltl2plan.language.grammar.references import (
    new_tasks_from_ref,
    ref_targets,
    restated_own_tasks,
    self_state,
    stated_tasks,
    treats_own,
)
from nl2hltl2plan.language.grammar.sentences import RelationSentence, split_sentences
from nl2hltl2plan.language.semantic_check import find_cycle
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_reduction

Edges = set[tuple[int, int]]


def relate(
    tasks: Tasks, relations: list[RelationSentence], b: TaskBuilder, text: str
) -> list[tuple[str, str]]:
    """The `before` pairs (task ids, which this step assigns). A reference that names no task but states one
    ("after picking up the box") adds that task to `tasks`; what cannot be resolved goes to `b.unparsed`."""
    edges: Edges = set()
    free = {t for u in tasks.units if any(kind == G.FREE for kind, _ in u.markers) for t in u.tasks}
    for k in range(len(tasks.units)):
        _marker_edges(k, tasks, free, b, text, edges)
    _first_edges(tasks.units, free, edges)
    _sentence_edges(relations, tasks, b, edges)
    return _order(edges, tasks)


def _marker_edges(k: int, tasks: Tasks, free: set[int], b: TaskBuilder, text: str, edges: Edges) -> None:
    """The edges that the markers of unit `k` state ("Then", "Finally", "after all that", "before that")."""
    units = tasks.units
    u = units[k]
    prev = units[k - 1] if k > 0 else None
    seq_prev = prev
    # sentence markers refer to the clause before the sentence, not to a sibling clause of the sentence
    cands = [v for v in units[:k] if v.sentence != u.sentence]
    outer = cands[-1] if cands else None  # the clause before the sentence
    if prev is not None and prev.sentence == u.sentence and not u.seq_after_prev:
        prev = outer
    first_of_sentence = min(t for v in units if v.sentence == u.sentence for t in v.tasks)
    earlier = [t for t in range(len(tasks.specs)) if t < first_of_sentence]
    others = [t for t in range(len(tasks.specs)) if t not in u.tasks]
    for kind, ref in u.markers:
        if kind == G.THEN and prev is not None:
            after = [] if prev.sentence == u.sentence else _last_step(units, prev.sentence, free, edges, text)
            edges.update((a, b2) for a in after or prev.tasks for b2 in u.tasks)
        elif kind == G.FINALLY:
            # "..., and finally Y" inside a sentence: after its sibling clauses too
            scope = list(range(min(u.tasks))) if ref == IN_SENTENCE else others if ref == OF_ALL else earlier
            edges.update((a, b2) for a in scope if a not in free for b2 in u.tasks)
        elif kind == G.AFTER_ALL:  # "once all that is done" / "once everything else is done" (all others)
            scope = others if _names_the_others(ref) else earlier
            edges.update((a, b2) for a in scope for b2 in u.tasks)
        elif kind == G.BEFORE_PREV and outer is not None:  # "X. Before that, Y, then Z": Y, Z before X
            edges.update((b2, a) for a in outer.tasks for b2 in u.tasks)
            # "W, then X. Before that, Y": Y goes in between, after what X comes after (span_order's PRE)
            earlier_steps = {w for w, a in edges if a in outer.tasks and w not in u.tasks}
            edges.update((w, b2) for w in earlier_steps for b2 in u.tasks)
        elif kind in (G.IN_ORDER, G.IN_REVERSE):  # "..., in that order" / "..., in reverse order"
            own = sorted(t for v in units if v.sentence == u.sentence for t in v.tasks)
            pairs = zip(own, own[1:], strict=False)
            edges.update(pairs if kind == G.IN_ORDER else ((b2, a) for a, b2 in pairs))
        elif kind == G.AFTER_REF and (named := by_position(ref, earlier, prev, others)) is not None:
            edges.update((a, b2) for a in named for b2 in u.tasks)
        elif kind in {G.AFTER_REF, G.BEFORE_REF}:
            _ref_edges(kind == G.AFTER_REF, ref, u, tasks, b, text, edges)
    if u.seq_after_prev and seq_prev is not None:
        edges.update((a, b2) for a in seq_prev.tasks for b2 in u.tasks)


# a word that may free a task of its sentence; "any" and "whatever" only before a time or an order ("put
# any mug in the sink" frees nothing)
_FREE_WORD = re.compile(
    r"\b(?:(?:any|whatever)\s+(?:time|order|point|sequence)|anytime|whenever|meanwhile|simultaneously|parallel|"
    r"independently)\b",
    re.I,
)


def _last_step(units: list[Unit], sentence: int, free: set[int], edges: Edges, text: str) -> list[int]:
    """The tasks of a sentence that "Then" in the next sentence comes after: those no other task of the
    sentence comes after, unless free ("A and B. Then C": after both, as `span_order`'s step). Empty (the
    last clause alone) when the sentence has a `_FREE_WORD` anywhere ("A at any time and B. Then C")."""
    sentences = split_sentences(text)
    if sentence >= len(sentences) or _FREE_WORD.search(sentences[sentence][0]):
        return []
    own = {t for v in units if v.sentence == sentence for t in v.tasks}
    return sorted(t for t in own if t not in free and not any((t, o) in edges for o in own))


def _names_the_others(ref: str) -> bool:
    """ "everything else", "the other tasks": every other task, also those written after the reference."""
    return re.search(r"\b(?:else|other)\b", ref, re.I) is not None


def by_position(ref: str, earlier: list[int], prev: Unit | None, others: list[int]) -> list[int] | None:
    """The tasks a reference by position names ("the first tasks", "the previous task", "everything
    else": `G.GENERIC_REF`); None when it names tasks another way (by their objects). "Everything else" /
    "the other tasks" are all `others`, those written after it too."""
    m = G.GENERIC_REF.match(_normal(ref))
    if m is None:
        return None
    if _names_the_others(ref):
        return others
    which, noun = (m.groupdict().get("which") or "").lower(), (m.groupdict().get("noun") or "").lower()
    singular = bool(noun) and not noun.endswith("s")
    if singular and which in G.ORDINALS:
        k = G.ORDINALS[which]
        return [earlier[k]] if k < len(earlier) else []
    if singular and which in {"previous", "last", "preceding", "prior", "former"} and prev is not None:
        return list(prev.tasks)
    return list(earlier)


def _normal(ref: str) -> str:
    """A reference without the "you are done with" around it: "you've finished the first tasks"."""
    ref = re.sub(r"^(?:you(?:'ve|'re|\s+are|\s+have)?\s+)?(?:done|finished|completed|through)\s+(?:with\s+)?",
                 "", ref.strip(), flags=re.I)
    return re.sub(r"^(?:completing|finishing|doing)\s+", "", ref, flags=re.I).strip()


def _ref_edges(after: bool, ref: str, u: Unit, tasks: Tasks, b: TaskBuilder, text: str, edges: Edges) -> None:
    """ "After placing the statue, Y" / "Y before moving the knife": edges to the named tasks."""
    specs, nps = tasks.specs, tasks.nps
    targets, missing = ref_targets(ref, specs, nps, exclude=u.tasks)
    own, _ = ref_targets(ref, specs, nps)
    stated = stated_tasks(ref, [specs[t] for t in own], b, text)
    if stated:  # "a clean mug under the coffee maker before you put a warm mug in the cabinet"
        _add_ref_tasks(stated, after, u, tasks, edges)
        return
    if not targets and own and all(t in u.tasks for t in own):
        if again := restated_own_tasks(ref, b, text):
            _add_ref_tasks(again, after, u, tasks, edges)
        else:
            self_state(ref, [specs[t] for t in u.tasks])
        return
    targets = [t for t in targets if t not in u.tasks]
    for t in targets:
        edges.update((t, b2) if after else (b2, t) for b2 in u.tasks)
    if not missing or targets:
        return
    # "after refrigerating the pan" about the task itself: a state, not an order
    keys = [parse_np(p).key for p in missing]
    if any(
        key and any(key == (np.key if (np := nps[t]) is not None else None) for t in u.tasks) for key in keys
    ):
        return
    if len(u.tasks) == 1 and treats_own(ref):
        self_state(ref, [specs[t] for t in u.tasks])
        return
    new = new_tasks_from_ref(ref, b, text)
    _add_ref_tasks(new, after, u, tasks, edges)
    if not new:
        b.unparsed.append(f"could not tell which task {ref!r} refers to")


def _add_ref_tasks(new: list[BaseTaskSpec], after: bool, u: Unit, tasks: Tasks, edges: Edges) -> None:
    """Tasks a reference states, ordered before (after=True) or after the tasks of unit `u`."""
    for spec in new:
        tasks.specs.append(spec)
        tasks.nps.append(None)
        t = len(tasks.specs) - 1
        edges.update((t, b2) if after else (b2, t) for b2 in u.tasks)


def _first_edges(units: list[Unit], free: set[int], edges: Edges) -> None:
    """ "First X" with no sequencing word right after: X before every later task not allowed at any time."""
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


def _sentence_edges(relations: list[RelationSentence], tasks: Tasks, b: TaskBuilder, edges: Edges) -> None:
    """Relation sentences between objects ("the red block should be placed before the blue block")."""
    for rel in relations:
        ta, _ = ref_targets(rel.a, tasks.specs, tasks.nps)
        if rel.kind in ("first", "last"):  # "Do the fork first.": the fork's task before every other one
            if not ta:
                b.unparsed.append(f"{rel.a} {rel.kind}")
            others = [y for y in range(len(tasks.specs)) if y not in ta]
            edges.update((x, y) if rel.kind == "first" else (y, x) for x in ta for y in others)
            continue
        tb, _ = ref_targets(rel.b, tasks.specs, tasks.nps)
        if not ta or not tb:
            b.unparsed.append(f"{rel.a} {rel.kind} {rel.b}")
        for x in ta:
            for y in tb:
                if x != y:
                    edges.add((x, y) if rel.kind == "before" else (y, x))


def _order(edges: Edges, tasks: Tasks) -> list[tuple[str, str]]:
    """Give the tasks their ids and reduce the order transitively; a contradiction (a cycle) is
    refused with the cycle named, never dropped: the user must say which comes first."""
    ids = [task_letter(i) for i in range(len(tasks.specs))]
    for i, s in enumerate(tasks.specs):
        s.id = ids[i]
    pairs = {(ids[a], ids[b2]) for a, b2 in edges if a != b2}
    cycle = find_cycle(sorted(pairs))  # sorted: the same cycle named on every run
    if cycle is not None:
        text = {s.id: s.text for s in tasks.specs}
        steps = " before ".join(f"{t} ({text[t]!r})" for t in cycle)
        raise HTTError(f"contradictory ordering in the instruction: {steps}; say which comes first")
    return list(transitive_reduction(pairs, ids))
