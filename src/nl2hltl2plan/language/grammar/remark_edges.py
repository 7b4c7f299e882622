"""The edges of an order remark (`order_remarks.py`): the tasks each remark names, by their object or
container ("the mug", "soap bottles"), else by their place ("the fridge stuff", "the bin one"), by their
treatment ("the washing", "the heating ones") or, for "that (one)", the task said just before the remark.
A remark whose words fit no task, or more than one where one is meant ("Do the cup first." with a cup
carried in one task and chilled in another), is unread by name: never a guess."""

from __future__ import annotations

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder, Tasks
from nl2hltl2plan.language.grammar.phrases import parse_np
from nl2hltl2plan.language.grammar.references import NOT_CERTAIN, former_or_latter, ref_targets, treated_tasks
from nl2hltl2plan.language.grammar.sentences import RelationSentence
from nl2hltl2plan.language.task_specs import BaseTaskSpec

Edges = set[tuple[int, int]]
REMARK = "remark_"  # the kinds `sentences.read_sentences` gives the relations of an order remark

_SKIP = frozenset({"the", "a", "an", "please", "do", "all"})
_TASK_NOUNS = frozenset({"one", "job", "task", "thing", "bit", "stuff", "part"})
_PLURAL_NOUNS = frozenset({"ones", "jobs", "tasks", "things", "bits", "parts"})
_ONE = frozenset({"one", "job", "task"})  # a singular task noun: "the table one" names one task
_THAT = frozenset({"that", "this", "it", "those", "these"})  # "do those first": the sentence before
_COUNTS = {"two": 2, "three": 3, "2": 2, "3": 3}
_TREATED = {"clean": "clean_place", "heat": "heat_place", "cool": "cool_place"}  # a treatment verb's task


def remark_edges(
    rel: RelationSentence, relations: list[RelationSentence], tasks: Tasks, b: TaskBuilder, edges: Edges
) -> bool:
    """Add the edges of one remark relation; False where `rel` is no remark's."""
    if rel.kind in ("first", "last"):  # the sentence rules' "Do the fork first." (`first_last_sentence`)
        return _said_first_or_last(rel, tasks, b, edges)
    if not rel.kind.startswith(REMARK):
        return False
    kind, n = rel.kind[len(REMARK) :], len(tasks.specs)
    if kind == "rest":  # "the rest in any order" says nothing beside a first / last remark
        if not any(r.kind.removeprefix(REMARK) in ("first", "last") for r in relations):
            b.unparsed.append(f"the rest in any order ({NOT_CERTAIN}: no task is said first or last)")
        return True
    if kind == "free":  # "the first two in any order": no order among them may have been said
        k = _COUNTS[rel.b]
        freed = set(range(k) if rel.a == "first" else range(n - k, n))
        if k > n or any(x in freed and y in freed for x, y in edges):
            b.unparsed.append(f"the {rel.a} {rel.b} in any order ({NOT_CERTAIN}: an order was said for them)")
        return True
    named = _named(rel.a, tasks, rel.sentence)
    if kind == "any":  # "The CD whenever.": no order of its own for a task said elsewhere (it adds none)
        if not named:
            b.unparsed.append(f"{rel.a} at any time ({NOT_CERTAIN}: no task, or more than one, fits)")
        return True
    if kind == "before":
        later = _named(rel.b, tasks, rel.sentence)
        if named and later and not set(named) & set(later):
            edges.update((x, y) for x in named for y in later)
        else:
            b.unparsed.append(f"{rel.a} before {rel.b} ({NOT_CERTAIN})")
        return True
    if not named:
        b.unparsed.append(f"{rel.a} {kind} ({NOT_CERTAIN}: no task, or more than one, fits)")
        return True
    others = [y for y in range(n) if y not in named]
    edges.update((x, y) if kind == "first" else (y, x) for x in named for y in others)
    return True


def _said_first_or_last(rel: RelationSentence, tasks: Tasks, b: TaskBuilder, edges: Edges) -> bool:
    """ "Do the fork first." as the rules read it (`references.ref_targets`), except where they find no task
    and the remark's words name one ("Do the heating first."), or where the words fit two tasks and the
    rules picked one ("Do the cup first." with a cup carried in one task and chilled in another)."""
    ta, _ = ref_targets(rel.a, tasks.specs, tasks.nps)
    fit, many = _fitting(rel.a, tasks, rel.sentence) or ([], False)
    by_thing = [i for i in fit if _moves(rel.a, tasks.specs[i])]  # a lamp or place one: the rules' reading
    one = not many and bool(_ONE.intersection(rel.a.lower().split()))  # "the table one": one task is meant
    if ta and not many and (len(by_thing) > 1 or (one and len(ta) > 1)):  # the words fit more than one task
        b.unparsed.append(f"{rel.a} {rel.kind} ({NOT_CERTAIN}: more than one task fits)")
        return True
    if ta or len(fit) != 1:
        return False
    x = fit[0]
    edges.update((x, y) if rel.kind == "first" else (y, x) for y in range(len(tasks.specs)) if y != x)
    return True


def _named(ref: str, tasks: Tasks, sentence: int) -> list[int]:
    """The tasks a remark names; [] where none or, for a singular, more than one fits."""
    fit = _fitting(ref, tasks, sentence)
    return fit[0] if fit is not None and (len(fit[0]) == 1 or fit[1]) else []


def _fitting(ref: str, tasks: Tasks, sentence: int) -> tuple[list[int], bool] | None:
    """Every task a remark's words fit, and whether they name several (a plural); None: they name no thing."""
    words = [w for w in ref.lower().split() if w not in _SKIP]
    many = bool(_PLURAL_NOUNS.intersection(words))
    words = [w for w in words if w not in _TASK_NOUNS | _PLURAL_NOUNS]
    if len(words) > 1 and (kind := _TREATED.get(G.VERBS.get(words[0], ("",))[0])):  # "rinse the soap"
        fit = _fitting(" ".join(w for w in words[1:] if w != "up"), tasks, sentence)
        return None if fit is None else ([i for i in fit[0] if tasks.specs[i].kind == kind], fit[1])
    if (position := former_or_latter(words, list(range(len(tasks.specs))))) is not None:
        return position, False  # "the former first": of two tasks
    if not words or set(words) <= _THAT:  # "That last.": the tasks of the sentence just before (one fits)
        said = [u.sentence for u in tasks.units if u.tasks and u.sentence < sentence]
        return ([t for u in tasks.units if said and u.sentence == said[-1] for t in u.tasks], False)
    specs = tasks.specs
    if len(words) == 1 and words[0].endswith("ing"):  # "the washing last"
        return treated_tasks(words, specs, list(range(len(specs)))) or [], many
    np = parse_np(" ".join(words))
    if np.entry is None:
        return None
    name = np.entry.canonical
    hit = [i for i, s in enumerate(specs) if name in s.object or name in (s.container or [])]
    if not hit:  # "the fridge stuff", "the bin one": by the place
        hit = [i for i, s in enumerate(specs) if name in (s.receptacle or []) or name in (s.light or [])]
    return hit, many or np.plural


def _moves(ref: str, spec: BaseTaskSpec) -> bool:
    """Does the task move the thing the remark names (as its object or its container)?"""
    np = parse_np(" ".join(w for w in ref.lower().split() if w not in _SKIP | _TASK_NOUNS | _PLURAL_NOUNS))
    return np.entry is not None and np.entry.canonical in [*spec.object, *(spec.container or [])]
