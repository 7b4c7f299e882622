"""Step 6, relations: the units' order markers -> `before` pairs of task ids (ANNOTATION_GUIDE), reduced."""

from __future__ import annotations

import re

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import phrase_list_pattern
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder, Tasks, Unit
from nl2hltl2plan.language.grammar.frames import IN_SENTENCE, OF_ALL
from nl2hltl2plan.language.grammar.order_conflicts import first_said_unread
from nl2hltl2plan.language.grammar.phrases import parse_np
from nl2hltl2plan.language.grammar.references import (
    NOT_CERTAIN,
    new_tasks_from_ref,
    ref_targets,
    restated_own_tasks,
    said_before,
    self_state,
    stated_tasks,
    task_word_said,
    treats_own,
    units_said_before,
)
from nl2hltl2plan.language.grammar.remark_edges import remark_edges
from nl2hltl2plan.language.grammar.sentences import RelationSentence, split_sentences
from nl2hltl2plan.language.grammar.then_steps import (
    ANY_ORDER,
    clause_before,
    leaves_order_open,
    own_clause,
    said_for_an_earlier_clause,
    says_any_order,
    sentence_steps,
)
from nl2hltl2plan.language.semantic_check import find_cycle
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_reduction

Edges = set[tuple[int, int]]
# the end of an `unparsed` message for an order the words leave open: the learned models must not choose
# one either (`learned.inference`, as for a reference whose task is `NOT_CERTAIN`)
ORDER_LEFT_OPEN = "say the order"


def relate(
    tasks: Tasks, relations: list[RelationSentence], b: TaskBuilder, text: str, instruction: str = ""
) -> list[tuple[str, str]]:
    """The `before` pairs (task ids, which this step assigns). A reference that names no task but states one
    ("after picking up the box") adds that task to `tasks`; what cannot be resolved goes to `b.unparsed`.
    `instruction`: the words as written, before `text` restated a shared verb (`then_steps.clause_before`)."""
    edges: Edges = set()
    for x, spec in enumerate(tasks.specs):  # "put the potato in the microwave last and the apple ... first"
        if left := _ORDER_WORD_LEFT.search(spec.text):
            _clause_end_said(x, left[1].lower(), tasks, text, b)
    free = {t for u in tasks.units if any(kind == G.FREE for kind, _ in u.markers) for t in u.tasks}
    # "A at any time, and B. Finally C": a clause's own "at any time" frees its task as a marker does
    free |= {t for t, spec in enumerate(tasks.specs) if _ANY_TIME.search(spec.text)}
    steps = sentence_steps(tasks.units)
    # "A and B in any order, and finally C": "finally" comes after no task whose order is left open
    # (ANNOTATION_GUIDE.md), as with "A and B in any order. Finally C."
    loose = free | _any_order_steps(tasks, steps)
    written = (text, [sentence for sentence, _ in split_sentences(text)])  # split once, for every unit
    for k in range(len(tasks.units)):
        _added_to_free(k, tasks, text, b)
        _then_also(k, tasks, text, b)
        _marker_edges(k, tasks, (free, loose), b, written, edges)
        _step_edges(k, tasks, steps, free, edges, written, instruction or text)
    if not _freed_by_a_remark(tasks.units, text):  # "First, A, B and C. Do these in any order."
        _first_edges(tasks.units, steps, loose, edges)  # not before a task whose order is left open
    _leading_last(tasks.units, steps, free, edges)
    if why := first_said_unread(tasks.units, text):  # "First A, first B": which one is first?
        b.unparsed.append(f"{why} ({ORDER_LEFT_OPEN})")
    rest = [r for r in relations if not remark_edges(r, relations, tasks, b, edges)]  # (`order_remarks`)
    _sentence_edges(rest, tasks, b, edges)
    _first_after_others(tasks, free, edges, b)
    return _order(edges, tasks)


def _first_after_others(tasks: Tasks, free: set[int], edges: Edges, b: TaskBuilder) -> None:
    """ "A. Then B, and C. Put D first." / "... Before anything else, D.": a closing "first" (no task said
    after it) that leaves D unordered with a task of an earlier sentence (not freed) is unread by name, where
    other tasks are ordered: `_first_edges` orders a "first" before the tasks after it only, and the word was
    dropped (a wrong reading at exit 0). With no order at all, check 1 names the word (`unordered_steps`)."""
    units = tasks.units
    last = max((k for k, u in enumerate(units) if u.tasks), default=None)  # only it can be a closing one
    if not edges or last is None:
        return
    u, said_before = units[last], [v for v in units[:last] if v.tasks]
    if not any(kind == G.FIRST for kind, _ in u.markers) or set(u.tasks) & free:
        return
    if any(v.sentence == u.sentence for v in said_before):  # "A. First B, then C": `_first_edges`' own
        return
    earlier = [t for v in said_before for t in v.tasks if t not in free]
    closure = nx.transitive_closure(nx.DiGraph(list(edges)))  # built here only: most texts get no further
    if any(not (closure.has_edge(a, t) or closure.has_edge(t, a)) for t in earlier for a in u.tasks):
        why = f"'first' after tasks said before it: before them too? {ORDER_LEFT_OPEN}"
        b.unparsed.append(f"{tasks.specs[u.tasks[0]].text!r} ({why})")


# an order adverb that ends a task's own words: no marker read it
_ORDER_WORD_LEFT = re.compile(r"\b(first|last|lastly|finally|next|afterwards?|beforehand)\W*$", re.I)


def _clause_end_said(x: int, word: str, tasks: Tasks, text: str, b: TaskBuilder) -> None:
    """An order adverb at a task's end that no marker read is unread, except "first" on the first task right
    before "then" ("put the sponge in the sink first, then the apple in the fridge"): it says what "then"
    says."""
    said = tasks.specs[x].text
    at = text.lower().find(said.lower())
    if word == "first" and x == 0 and at >= 0 and _THEN_NEXT.match(text, at + len(said)):
        return
    b.unparsed.append(f"{said!r} ({word!r}: an order word inside a clause, not read)")


_THEN_NEXT = re.compile(r"\s*,?\s*(?:and\s+)?then\b", re.I)


def _marker_edges(
    k: int,
    tasks: Tasks,
    frees: tuple[set[int], set[int]],
    b: TaskBuilder,
    written: tuple[str, list[str]],
    edges: Edges,
) -> None:
    """The edges that the markers of unit `k` state ("Then", "Finally", "after all that", "before that");
    `frees`: the tasks allowed at any time, and those with the tasks whose order is left open; `written`:
    the text and its sentences."""
    free, loose = frees
    text = written[0]
    units = tasks.units
    u = units[k]
    prev = units[k - 1] if k > 0 else None
    # sentence markers refer to the clause before the sentence, not to a sibling clause of the sentence
    cands = [v for v in units[:k] if v.sentence != u.sentence]
    outer = cands[-1] if cands else None  # the clause before the sentence
    if prev is not None and prev.sentence == u.sentence and not u.seq_after_prev:
        prev = outer
    first_of_sentence = min(t for v in units if v.sentence == u.sentence for t in v.tasks)
    earlier = [t for t in range(len(tasks.specs)) if t < first_of_sentence]
    others = [t for t in range(len(tasks.specs)) if t not in u.tasks]
    for kind, ref in u.markers:
        freed = all(t in free for t in u.tasks)
        if kind == G.THEN and said_for_an_earlier_clause((kind, ref), k, tasks, written, freed):
            continue  # "A. Then B, and C.": "then" opens B's clause, C's has no order word (the guide)
        if kind == G.THEN and prev is not None:
            after = [] if prev.sentence == u.sentence else _last_step(units, prev.sentence, free, edges, text)
            after = (after or _unfreed_clause(units, prev, free)) + _put_before(units, prev, free)
            edges.update((a, b2) for a in after for b2 in u.tasks)
        elif kind == G.FINALLY:
            # "..., and finally Y" inside a sentence: after its sibling clauses too
            scope = list(range(min(u.tasks))) if ref == IN_SENTENCE else others if ref == OF_ALL else earlier
            scope = [a for a in _with_stated(scope, tasks, edges) if a not in loose]
            # "X whenever, but put Y last" (one unit): the task its own words free is not made last
            last = [t for t in u.tasks if t not in free] or u.tasks
            edges.update((a, b2) for a in scope for b2 in last)
        elif kind == G.AFTER_ALL:  # "once all that is done" / "once everything else is done" (all others)
            scope = others if _names_the_others(ref) else _with_stated(earlier, tasks, edges)
            edges.update((a, b2) for a in scope for b2 in u.tasks)
        elif kind == G.BEFORE_PREV and (G.FINALLY, IN_SENTENCE) in u.markers:
            continue  # "X. Before that, Y, and finally Z": Z is the last step, after X too
        elif kind == G.BEFORE_PREV and outer is not None:  # "X. Before that, Y, then Z": Y, Z before X
            said = _step_said(units, outer, free)
            edges.update((b2, a) for a in said for b2 in u.tasks)
            # "W, then X. Before that, Y": Y goes in between, after what X comes after (span_order's PRE);
            # not after a clause of its own sentence ("Before that, Y and Z": both before X, in any order)
            siblings = {t for v in units if v.sentence == u.sentence for t in v.tasks}
            earlier_steps = {w for w, a in edges if a in said and w not in siblings}
            edges.update((w, b2) for w in earlier_steps for b2 in u.tasks)
            if k > 0 and units[k - 1].sentence == u.sentence:
                _added_to_before(units[k - 1], u, tasks, text, b)
        elif kind in (G.IN_ORDER, G.IN_REVERSE):  # "..., in that order" / "..., in reverse order"
            own = sorted(t for v in units if v.sentence == u.sentence for t in v.tasks)
            pairs = zip(own, own[1:], strict=False)
            edges.update(pairs if kind == G.IN_ORDER else ((b2, a) for a, b2 in pairs))
        elif kind in {G.AFTER_REF, G.BEFORE_REF} and (two := either_of(ref, u, units)) is not None:
            if not two or kind == G.AFTER_REF:  # "after either of these": after one of them, no `before` pair
                b.unparsed.append(f"could not tell which tasks {ref!r} refers to ({NOT_CERTAIN})")
            edges.update((b2, a) for a in two for b2 in u.tasks if kind == G.BEFORE_REF)
        elif kind in {G.AFTER_REF, G.BEFORE_REF} and (named := said_before(ref, u, units)) is not None:
            if not named:  # "the rest" with nothing said before it; "A and B. Before you do this, C"
                b.unparsed.append(f"could not tell which task {ref!r} refers to ({NOT_CERTAIN})")
            edges.update((a, b2) if kind == G.AFTER_REF else (b2, a) for a in named for b2 in u.tasks)
            if kind == G.BEFORE_REF:  # "W, then X. Before you do this, Y": Y after W too, as "before that"
                ahead = {w for w, a in edges if a in named and w not in u.tasks}
                edges.update((w, b2) for w in ahead for b2 in u.tasks)
        elif kind in {G.AFTER_REF, G.BEFORE_REF} and (
            named := by_position(ref, earlier, prev, others)
        ) is not None:
            # "Before any of that, Y" with nothing before it, or nothing read ("Y before anything else": no)
            if not named and not re.fullmatch(r"(?:doing\s+)?anything\s+else", _normal(ref), re.I):
                why = f" ({NOT_CERTAIN}: nothing is said before it)" if u.sentence == 0 else ""
                b.unparsed.append(f"could not tell which task {ref!r} refers to{why}")
            later = kind == G.AFTER_REF  # "Before all that, Y": Y before every task said
            edges.update((a, b2) if later else (b2, a) for a in named for b2 in u.tasks)
        elif kind in {G.AFTER_REF, G.BEFORE_REF}:
            _ref_edges(kind == G.AFTER_REF, ref, u, tasks, b, text, edges)


def _unfreed_clause(units: list[Unit], prev: Unit, free: set[int]) -> list[int]:
    """The tasks "Then" comes after: the clause before it, or where a time phrase frees that clause alone ("A,
    and B whenever you like. Then C"), the last clause of its sentence that nothing frees."""
    said = units[: units.index(prev) + 1]
    kept = [v for v in said if v.sentence == prev.sentence and not set(v.tasks) <= free]
    return kept[-1].tasks if kept and set(prev.tasks) <= free else prev.tasks


def _with_stated(scope: list[int], tasks: Tasks, edges: Edges) -> list[int]:
    """`scope` and the tasks that a reference of its clauses states ("Before you put X in A, Y. Finally Z":
    X is said before Z, though its task is added after every clause's): a task no clause states goes with
    the clause whose reference states it, the one it is ordered with."""
    said = {t for v in tasks.units for t in v.tasks}
    stated = [
        t for t in range(len(tasks.specs))
        if t not in said and t not in scope and any((t, a) in edges or (a, t) in edges for a in scope)
    ]
    return scope + stated


def _step_edges(
    k: int, tasks: Tasks, steps: list[int], free: set[int], edges: Edges, written: tuple[str, list[str]],
    instruction: str,
) -> None:
    """ "A and B, then C": unit `k` after the step before its own, inside one sentence: after every task of
    that step that no word lets happen at any time ("A at any time and B, then C": after B; after the
    last clause when every task is so and "then" joins them)."""
    units, u, step = tasks.units, tasks.units[k], steps[k]
    opener = steps.index(step)
    if opener == 0 or units[opener - 1].sentence != u.sentence:  # the sentence's first step
        return
    if (G.FINALLY, IN_SENTENCE) in units[opener].markers:  # "finally" states its own order
        return
    # "A, then B, and C too": C's clause has no order word (ANNOTATION_GUIDE.md)
    text, sentences = written
    apart = own_clause(k, tasks, text) and not leaves_order_open(u, sentences)
    if k != opener and (apart or any(t in free for t in u.tasks)):
        return
    before = [t for t in clause_before(tasks, steps, opener, (text, instruction)) if t not in free] or [
        t for j in range(opener) if steps[j] == step - 1 for t in units[j].tasks
    ]
    after = [t for t in before if t not in free and not _ANY_TIME.search(tasks.specs[t].text)]
    if not after and units[opener].seq_after_prev:  # "A at any time, then B": after A all the same
        after = units[opener - 1].tasks
    edges.update((a, b2) for a in after for b2 in u.tasks)


def _any_order_steps(tasks: Tasks, steps: list[int]) -> set[int]:
    """The tasks of the steps whose words leave their order open ("A, and B in any order, and ...")."""
    units = tasks.units
    open_steps = {
        steps[k] for k, u in enumerate(units) if any(ANY_ORDER.search(tasks.specs[t].text) for t in u.tasks)
    }
    return {t for k, u in enumerate(units) if steps[k] in open_steps for t in u.tasks}


# words that let one task happen at any time ("in any order" frees an order, not a task)
_ANY_TIME = re.compile(
    r"\b(?:(?:any|whatever)\s+(?:time|point)|anytime|whenever|meanwhile|simultaneously|parallel|independently|"
    r"at\s+(?:some|your)\s+(?:point|convenience|leisure))\b",
    re.I,
)


# a word that may free a task of its sentence; "any" and "whatever" only before a time or an order ("put
# any mug in the sink" frees nothing)
_FREE_WORD = re.compile(
    r"\b(?:(?:any|whatever)\s+(?:time|order|point|sequence)|anytime|whenever|meanwhile|simultaneously|parallel|"
    r"independently)\b",
    re.I,
)


def _step_said(units: list[Unit], outer: Unit, free: set[int]) -> list[int]:
    """The tasks "before that" puts a clause before: the last step of the sentence before it, not only its
    last clause ("X; also Y, though first Z" / "X and Y. Before that, Z": Z before both; "W, then X. Before
    that, Y": before X), leaving out the tasks allowed at any time."""
    steps = sentence_steps(units)
    k = units.index(outer)
    said = [t for j, v in enumerate(units) if v.sentence == outer.sentence and steps[j] == steps[k]
            for t in v.tasks]
    return [t for t in said if t not in free or t in outer.tasks]


# a clause added to a "before that" clause by one of these words ("Before that, Y; also Z")
_ADDITIVE = re.compile(
    rf"^\W*(?:and\s+)?(?P<word>{phrase_list_pattern('order_scope.txt', 'additive')})\b", re.I
)


def _added_to_before(prev: Unit, u: Unit, tasks: Tasks, text: str, b: TaskBuilder) -> None:
    """ "X. Before that, Y; also Z": is Z before X too, or does it go with X? The words leave it open
    (`order_scope.txt`'s `additive`), so the clause is refused by name rather than guessed; "Before that, Y
    and Z" (both before X) and "Before that, Y, then Z" are read."""
    said, own = tasks.specs[prev.tasks[-1]].text, tasks.specs[u.tasks[0]].text
    if (word := _additive_between(said, own, text)) is None:
        return
    b.unparsed.append(f"{own!r} ({word!r} after a 'before that' clause: before that too? {ORDER_LEFT_OPEN})")


def _added_to_free(k: int, tasks: Tasks, text: str, b: TaskBuilder) -> None:
    """ "Whenever convenient, Y; also Z. Finally W": is Z at any time too, or does "finally" come after it?
    The additive word leaves it open, so Z is refused by name where a later "then" / "finally" asks;
    "Whenever convenient, Y and Z" frees both."""
    units = tasks.units
    u = units[k]
    if k == 0 or units[k - 1].sentence != u.sentence or not u.tasks:
        return
    if not any(kind == G.FREE for kind, _ in u.markers):
        return
    if not any(kind in {G.THEN, G.FINALLY} for v in units[k + 1 :] if v.sentence != u.sentence
               for kind, _ in v.markers):
        return
    said, own = tasks.specs[units[k - 1].tasks[-1]].text, tasks.specs[u.tasks[0]].text
    if (word := _additive_between(said, own, text)) is not None:
        why = f"after a clause allowed at any time: at any time too? {ORDER_LEFT_OPEN}"
        b.unparsed.append(f"{own!r} ({word!r} {why})")


def _additive_between(said: str, own: str, text: str) -> str | None:
    """The additive word (`order_scope.txt`) that joins the clause `own` to the clause `said` before it."""
    low = text.lower()
    at = low.find(said.lower())
    end = low.find(own.lower(), at + len(said)) if at >= 0 else -1
    if end < 0 or (m := _ADDITIVE.match(text[at + len(said) : end])) is None:
        return None
    return m["word"].lower()


# "A and then also B": "then" may order B after A or only add it ("and then also, there is B")
_THEN_ALSO = re.compile(r"\bthen\s*,?\s+(?:also|additionally|as\s+well)\b", re.I)


def _then_also(k: int, tasks: Tasks, text: str, b: TaskBuilder) -> None:
    """ "Put A and then also put B": whether B comes after A or is one more task is not said, so B is
    refused by name, unless "first" / "start by" already puts A first ("Start by A and then also B")."""
    units = tasks.units
    u = units[k]
    if k == 0 or not u.seq_after_prev or units[k - 1].sentence != u.sentence or not u.tasks:
        return
    if any(kind == G.FIRST for kind, _ in units[k - 1].markers):
        return
    said, own = tasks.specs[units[k - 1].tasks[-1]].text, tasks.specs[u.tasks[0]].text
    low = text.lower()
    at = low.find(said.lower())
    end = low.find(own.lower(), at + len(said)) if at >= 0 else -1
    if end >= 0 and _THEN_ALSO.search(text[at + len(said) : end]):
        b.unparsed.append(f"{own!r} ('then also': after it, or one more task? {ORDER_LEFT_OPEN})")


def _put_before(units: list[Unit], prev: Unit, free: set[int]) -> list[int]:
    """ "X. Ahead of that, Y. Then Z": Z continues the time line (Y, X, Z), so it comes after X too, the
    clauses that Y was put before (the last step of X's sentence, as `_step_said`: "W, plus X. Ahead of
    that, Y. After which, Z": after W too); nothing when `prev` is not a "before that" sentence."""
    if not any(kind == G.BEFORE_PREV for kind, _ in prev.markers):
        return []
    outer = [v for v in units[: units.index(prev)] if v.sentence != prev.sentence]
    return _step_said(units, outer[-1], free) if outer else []


def _last_step(units: list[Unit], sentence: int, free: set[int], edges: Edges, text: str) -> list[int]:
    """The tasks of a sentence that "Then" in the next sentence comes after: those no other task of the
    sentence comes after, unless free ("A and B. Then C": after both, as `span_order`'s step). Empty (the
    last clause alone) when the sentence has a `_FREE_WORD` anywhere ("A at any time and B. Then C"),
    except where all it frees is the order of its own tasks ("A and B in any order. Then C": after both;
    `span_order`'s ANY step)."""
    sentences = split_sentences(text)
    if sentence >= len(sentences):
        return []
    said = sentences[sentence][0]
    order_only = ANY_ORDER.search(said) is not None and _ANY_TIME.search(said) is None
    if _FREE_WORD.search(said) and not order_only:
        return []
    own = {t for v in units if v.sentence == sentence for t in v.tasks}
    # "Before you X, Y. After that, Z": X, which the sentence's reference states, is done after Y (Z after
    # X, not only after Y)
    in_clauses = {t for v in units for t in v.tasks}
    own |= {t for a, t in edges if a in own and t not in in_clauses and t not in free}
    return sorted(t for t in own if (order_only or t not in free) and not any((t, o) in edges for o in own))


def _names_the_others(ref: str) -> bool:
    """ "everything else", "the other tasks": every other task, also those written after the reference."""
    return re.search(r"\b(?:else|other)\b", ref, re.I) is not None


# "Before either of these, C" / "before both of those" / "before you do either": the two tasks just said
_EITHER_OF = re.compile(
    r"(?:(?:you\s+)?do\s+)?(?:either|both|each)"
    r"(?:\s+of\s+(?:these|those|them|the\s+two)(?:\s+two)?(?:\s+(?:tasks|steps|things|jobs))?)?",
    re.I,
)


def either_of(ref: str, u: Unit, units: list[Unit]) -> list[int] | None:
    """The two tasks "either of these" / "both of those" names: the sentence before when it holds two, else
    every task said before when there are two ("A. Then B. Before either of these, C": C before A and B);
    [] where that is not certain (three said before, one sentence of one); None: not such a reference."""
    if not u.tasks or not _EITHER_OF.fullmatch(_normal(ref)):
        return None
    said = units_said_before(u, units)
    if not said:
        return []
    last = [t for v in said if v.sentence == said[-1].sentence for t in v.tasks]
    every = [t for v in said for t in v.tasks]
    return last if len(last) == 2 else every if len(every) == 2 else []


def by_position(ref: str, earlier: list[int], prev: Unit | None, others: list[int]) -> list[int] | None:
    """The tasks a reference by position names ("the first tasks", "the previous task", "everything
    else": `G.GENERIC_REF`); None when it names tasks another way (by their objects). "Everything else" /
    "the other tasks" are all `others`, those written after it too."""
    if re.fullmatch(r"(?:doing\s+)?anything\s+else", _normal(ref), re.I):  # "Y before anything else"
        return others
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
    done_before = min(u.tasks) if after and u.tasks else None  # "when you're done moving the soap, ..."
    targets, missing = ref_targets(ref, specs, nps, exclude=u.tasks, done_before=done_before)
    own, _ = ref_targets(ref, specs, nps)
    stated = stated_tasks(ref, [specs[t] for t in own], b, text)
    if stated:  # "a clean mug under the coffee maker before you put a warm mug in the cabinet"
        _add_ref_tasks(stated, after, u, tasks, edges)
        return
    if not targets and own and all(t in u.tasks for t in own):
        if again := restated_own_tasks(ref, b, text):
            _add_ref_tasks(again, after, u, tasks, edges)
        else:  # a state of the task itself, or (its place said done) unread
            self_state(ref, [specs[t] for t in u.tasks], b, [nps[t] for t in u.tasks])
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
    if task_word_said(missing):  # "after the lamp one" with two lamp tasks
        b.unparsed.append(f"could not tell which task {ref!r} refers to ({NOT_CERTAIN}: more than one fits)")
        return
    new = new_tasks_from_ref(ref, b, text)
    _add_ref_tasks(new, after, u, tasks, edges)
    if not new:
        b.unparsed.append(f"could not tell which task {ref!r} refers to")


def _add_ref_tasks(new: list[BaseTaskSpec], after: bool, u: Unit, tasks: Tasks, edges: Edges) -> None:
    """Tasks a reference states, ordered before (after=True) or after the tasks of unit `u`. A task that the
    same words already stated for another clause is that task ("A and B, but only after you've put X":
    one X, before both), not a second one."""
    said = {t for v in tasks.units for t in v.tasks}
    for spec in new:
        again = [t for t in range(len(tasks.specs)) if t not in said and tasks.specs[t] == spec]
        if again:
            t = again[0]
        else:
            tasks.specs.append(spec)
            tasks.nps.append(None)
            t = len(tasks.specs) - 1
        edges.update((t, b2) if after else (b2, t) for b2 in u.tasks)


_ADDING = frozenset({"and", "also", "plus"})  # joiners that add a clause to a step, no order of their own


def _freed_by_a_remark(units: list[Unit], text: str) -> bool:
    """Does a sentence that states no task say "in any order" ("Do these in any order")? It frees the
    order of the tasks said before it, a leading "first" too (paper_h188dev)."""
    said = {u.sentence for u in units if u.tasks}
    return any(k not in said and says_any_order(s[0]) for k, s in enumerate(split_sentences(text)))


def _first_edges(units: list[Unit], steps: list[int], free: set[int], edges: Edges) -> None:
    """ "First X" with no sequencing word right after: X before every later task not allowed at any time,
    and not stated before X ("First X. Before all that, Y": Y first). In a sentence of several steps it is
    about the first step, and not before the other tasks of that step ("first A and B, then C": A and B
    first, in any order; "first A, then B and C": B not before C)."""
    stated: nx.DiGraph | None = None  # built at the first "first" only: most texts have none
    for k, u in enumerate(units):
        own = [steps[j] for j, v in enumerate(units) if v.sentence == u.sentence]  # its sentence's steps
        if steps[k] != own[0] or not any(kind == G.FIRST for kind, _ in u.markers):
            continue
        # a sentence's "first" is on each of its clauses: read once, at the step's first ("First A, and B,
        # and also C": A before B and C, not B before C)
        if any(steps[j] == steps[k] and units[j].sentence == u.sentence and (G.FIRST, "") in units[j].markers
               for j in range(k)) and (G.FIRST, "") in u.markers:
            continue
        nxt = units[k + 1] if k + 1 < len(units) else None
        if nxt is not None and (
            nxt.seq_after_prev or any(kind in {G.THEN, G.AFTER_ALL, G.AFTER_REF} for kind, _ in nxt.markers)
        ):
            # "A - do that first. Then B, rinse C": first before all of the next sentence, which its "then"
            # no longer orders as a whole
            then = [t for v in units[k + 1 :] if v.sentence == nxt.sentence != u.sentence for t in v.tasks]
            edges.update((a, b2) for a in u.tasks for b2 in then if b2 not in free)
            continue
        # "Begin by A; also B. Then C" / "First A, plus B. To finish, C": a list its adding word closes is
        # the first step where a later step follows ("First A, and B" alone: A first, the only other task B)
        same = [j for j, s in enumerate(steps) if s == steps[k]][1:]  # the step's units after its first
        listed = any(units[j].joiner in _ADDING for j in same) and any(s > steps[k] for s in steps)
        step = steps[k] if own[-1] != own[0] or listed else -1
        firsts = [t for j in range(k, len(units)) if steps[j] == step for t in units[j].tasks] or u.tasks
        later = [t for j in range(k + 1, len(units)) if steps[j] != step for t in units[j].tasks]
        stated = nx.transitive_closure(nx.DiGraph(list(edges))) if stated is None else stated
        later = [t for t in later if t not in free and not any(stated.has_edge(t, a) for a in firsts)]
        edges.update((a, b2) for a in firsts for b2 in later)


def _leading_last(units: list[Unit], steps: list[int], free: set[int], edges: Edges) -> None:
    """ "Last, A; first B" / "Finally A. Then B": a "last" on the first task said has no task before it to
    come after (`_marker_edges` reads "finally" of the tasks said before); the writer said the order in
    reverse, and A comes after every task of a later sentence not allowed at any time ("finally A and B"
    says nothing of B). "Last A, then B" in one sentence: B after A too, a cycle refused by name."""
    said = [k for k, u in enumerate(units) if u.tasks]
    if not said or not any(kind == G.FINALLY for kind, _ in units[said[0]].markers):
        return
    head, at = units[said[0]].tasks, units[said[0]].sentence
    later = [
        t for j in range(said[0] + 1, len(units)) if units[j].sentence != at or steps[j] != steps[said[0]]
        for t in units[j].tasks if t not in free
    ]
    edges.update((t, a) for t in later for a in head)


_OTHERS = re.compile(r"(?:the\s+others|the\s+rest|everything\s+else|all\s+the\s+others)$", re.I)


def _sentence_edges(relations: list[RelationSentence], tasks: Tasks, b: TaskBuilder, edges: Edges) -> None:
    """Relation sentences between objects ("the red block should be placed before the blue block")."""
    for rel in relations:
        if rel.kind in (G.IN_ORDER, G.IN_REVERSE):  # "Do them in that order.": the tasks stated before
            told = sorted(t for u in tasks.units if u.sentence < rel.sentence for t in u.tasks)
            pairs = list(zip(told, told[1:], strict=False))
            edges.update(pairs if rel.kind == G.IN_ORDER else ((b2, a) for a, b2 in pairs))
            continue
        ta, _ = ref_targets(rel.a, tasks.specs, tasks.nps)
        if rel.kind in ("first", "last"):  # "Do the fork first.": the fork's task before every other one
            if not ta:  # "Do the lamp one first" with two lamp tasks: the model must not pick one either
                why = f" ({NOT_CERTAIN}: more than one task fits)" if task_word_said([rel.a]) else ""
                b.unparsed.append(f"{rel.a} {rel.kind}{why}")
            others = [y for y in range(len(tasks.specs)) if y not in ta]
            edges.update((x, y) if rel.kind == "first" else (y, x) for x in ta for y in others)
            continue
        tb, _ = ref_targets(rel.b, tasks.specs, tasks.nps)
        if _OTHERS.match(rel.b.strip()):  # "Do the roll ones before the others": every task not named first
            tb = [y for y in range(len(tasks.specs)) if y not in ta]
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
