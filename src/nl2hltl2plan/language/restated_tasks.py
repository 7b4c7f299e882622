"""A task said again is the task read before, not a second one (issue 23).

A reading may hold one task twice: "put the mug on the desk before putting the pillow on the bed, and put
the pillow on the bed before putting the mug on the desk" reads four tasks where the text names two, and
its cycle is lost; "put a mug on the desk, then put the pillow on the bed after putting the mug on the
desk" moves a second mug. The offline, grammar and LLM backends' readings pass here (check 1,
`translate.account_words`; the handover reader and the tabletop's rereading do not): a later task
identical to an earlier one (kind, object, count, slice, container, destination, light, state) is

- that task, when its words name the thing definitely ("the mug", "it", "this mug") and either clause
  only refers to it ("before putting the mug ...", "once you've put the mug ...", "before the pillow
  goes on the bed, ... put the pillow on the bed") or the later words are the very words that asked for
  it ("put the mug on the desk and put the mug on the desk"): its orders join the earlier task (a cycle
  so made is refused, naming it; an order between the two is none);
- another task, when the words mark another thing ("another mug", "the other mug", "a second mug") or
  name it indefinitely ("a mug ... a mug", "after you put a mug ..."): nothing changes;
- refused by name where it cannot be told: "the mug" after two identical tasks (which one).

A task asked for again in other words ("put a mug on the desk, then put the mug on the desk", "examine the
clock by the light ... examine the clock under the desk lamp") stays two tasks: ALFRED's annotations of
two trials are written so, and the default failure sets hold such rows.

>>> _wording("putting the mug on the desk", {"Mug"})
'definite'
>>> _wording("put another mug on the desk", {"Mug"})
'another'
"""

from __future__ import annotations

import re
from typing import Literal

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grounding import find_mentions, tokens
from nl2hltl2plan.language.htt_build import build_htt
from nl2hltl2plan.language.referents import ANOTHER, DEFINITE, INDEFINITE
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.statements import REFERENCE
from nl2hltl2plan.language.task_specs import (
    BaseTaskSpec,
    task_letter,
    transitive_closure,
    transitive_reduction,
)

Wording = Literal["definite", "another", "indefinite"]
_FIELDS = ("kind", "object", "count", "sliced", "container", "receptacle", "light", "state")
# which thing a noun names, by the words before it (`referents`' list): "the mug" or "it", "another mug"
_DEFINITE = DEFINITE | {"it", "them"}
# a clause that refers to a task rather than asks for it: "before putting ...", "once you've put ..."
_REFERENCE_OPENING = re.compile(rf"\b{REFERENCE}\s+(?:you(?:'ve|\s+have)?\s+)?$", re.I)


def joined_restatements(res: LanguageResult) -> LanguageResult:
    """The reading with each task said again joined to the task read before (see the module's docstring);
    the reading itself when no task is said twice."""
    same = restated(res.instruction, res.tasks)
    if not same:
        return res
    kept = [t for t in res.tasks if t.id not in same]
    letter = {t.id: task_letter(k) for k, t in enumerate(kept)}
    letter |= {later: letter[earlier] for later, earlier in same.items()}
    tasks = [t.model_copy(update={"id": letter[t.id]}) for t in kept]
    # over the closure: a reference clause the parser put before the task it names ("A, then B after
    # putting A's thing": C<A<B) keeps its order to B; the pair's own order is no order
    closure = transitive_closure(list(res.before), [t.id for t in res.tasks])
    joined = {(letter[a], letter[b]) for a, b in closure if same.get(a, a) != same.get(b, b)}
    _refuse_cycles(sorted(joined), {t.id: t for t in tasks})
    before = transitive_reduction(sorted(joined), [t.id for t in tasks])
    groups: dict[str, list[str]] = {}
    for task_id, node in res.task_node.items():  # tasks one sentence listed together stay together
        if node.count(".") > 1 and task_id not in same:
            groups.setdefault(node.rsplit(".", 1)[0], []).append(letter[task_id])
    htt, task_node, leaf_task = build_htt(res.instruction, tasks, before, list(groups.values()))
    ambiguities = [
        a.model_copy(update={"task": letter[a.task]}) for a in res.ambiguities if a.task not in same
    ]
    constraints = [
        c.model_copy(update={"until": letter.get(c.until, c.until) if c.until else None})
        for c in res.constraint_specs
    ]
    update = {
        "tasks": tasks,
        "before": before,
        "htt": htt,
        "task_node": task_node,
        "leaf_task": leaf_task,
        "ambiguities": ambiguities,
        "constraint_specs": constraints,
    }
    return res.model_copy(update=update)


def restated(instruction: str, tasks: list[BaseTaskSpec]) -> dict[str, str]:
    """Later task id -> the id of the earlier identical task it says again; HTTError for "the mug" after
    two identical tasks (which one). How a thing is named is judged on words the instruction holds as
    they stand (a task text the reader rewrote says nothing of it), or on one text read twice."""
    said = _plain(instruction)
    same: dict[str, str] = {}
    for k, later in enumerate(tasks):
        text = _plain(later.text)
        if not text or _wording(later.text, set(later.object)) != "definite":
            continue  # "another mug", "a mug ... a mug", "after you put a mug ...": another one
        # a clause that refers to the task (either of the two), or the very words that asked for it;
        # ALFRED's annotations of two trials say "the soap" in each of two wordings, and so stay two
        refers = _refers(text, said)
        earlier = [
            t
            for t in tasks[:k]
            if t.id not in same
            and _key(t) == _key(later)
            and (refers or _plain(t.text) == text or _refers(_plain(t.text), said))
        ]
        if len(earlier) > 1:
            which = " or ".join(repr(t.text) for t in earlier)
            raise HTTError(
                f"{later.text!r} may be the task {which} said again: say which (\"the other "
                f"{_noun(later)}\"), or say the task once"
            )
        if earlier:
            same[later.id] = earlier[0].id
    return same


def _plain(text: str) -> str:
    """Lower case, "you've" as "you have", one space between words, no punctuation at the ends."""
    text = re.sub(r"\byou've\b", "you have", text.lower())
    return " ".join(text.split()).strip(" ,.;!?")


def _key(task: BaseTaskSpec) -> tuple[object, ...]:
    return tuple(str(getattr(task, f)) for f in _FIELDS)


def _noun(task: BaseTaskSpec) -> str:
    return re.sub(r"(?<!^)(?=[A-Z])", " ", task.object[0]).lower() if task.object else "thing"


def _wording(text: str, types: set[str]) -> Wording:
    """How a task's words name its thing: definitely ("the mug", "it"), as another one ("another mug",
    "the other mug"), or indefinitely ("a mug", "mug", or not at all)."""
    words = [w for w, _, _ in tokens(text)]
    named = [m for m in find_mentions(text) if set(m.entry.types) & types]
    if not named:
        return "definite" if set(words) & {"it", "them"} else "indefinite"
    said = words[max(0, named[0].start - 3) : named[0].start]
    if set(said) & ANOTHER:
        return "another"
    determiner = next((w for w in reversed(said) if w in _DEFINITE | INDEFINITE), None)
    return "definite" if determiner in _DEFINITE else "indefinite"


def _refers(text: str, instruction: str) -> bool:
    """Is the task's clause (`_plain` words, as the `_plain` instruction holds them) one that refers to a
    task, said right after "before", "after", "once" ... ("before putting the mug ...", "once you have
    put the mug ...", "before the pillow goes ..."), rather than asks for it ("begin by putting ...")?"""
    places = _places(text, instruction) if text else []
    return any(_REFERENCE_OPENING.search(instruction[:at]) for at in places)


def _places(text: str, instruction: str) -> list[int]:
    """Where `text` (not empty) starts in `instruction`, each place after the last one's end: as
    `re.finditer(re.escape(text), ...)`, without compiling a pattern per text (which also pushed the
    readers' own patterns out of `re`'s cache)."""
    found, at = [], instruction.find(text)
    while at >= 0:
        found.append(at)
        at = instruction.find(text, at + len(text))
    return found


def _refuse_cycles(before: list[tuple[str, str]], tasks: dict[str, BaseTaskSpec]) -> None:
    """An order that the joined tasks make cyclic ("X before Y, and Y before X"): an input error."""
    g = nx.DiGraph(before)
    try:
        cycle = nx.find_cycle(g)
    except nx.NetworkXNoCycle:
        return
    names = [repr(tasks[a].text) for a, _ in cycle] + [repr(tasks[cycle[0][0]].text)]
    raise HTTError(
        f"cyclic order in the instruction: {' before '.join(names)} (a task said again is the same task)"
    )
