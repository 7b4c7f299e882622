"""A choice between places (h274, issues 28 and 23): "put the egg in the fridge or the microwave",
"the keys go on the desk or in the drawer", "leave the mug in the sink or on the counter, whichever".

The grammar reads one destination per task, so the second place and its "or" are cut from the text it
reads (`split_choices`), and the task that goes to the first place is then widened (`widen`): its
`receptacle` takes both places (those the world can take), `places` keeps what was said. The recipe of a
task with several receptacles is a disjunction of its action sequences (`BaseTask.leaf_specs`), so the
planner does the cheaper branch and the checker judges the plan against the disjunction. The reading
keeps the whole text: check 1 (`accounting`) judges every word of it, the second place included.

Left as they were: a choice of treatment ("heat or chill the egg") or of objects ("the egg or the
apple"), which are no places after a placing word; a ban's "or" (read by `negations` before this).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from pydantic import BaseModel

from nl2hltl2plan.domain.plan_events import PlanEvent
from nl2hltl2plan.domain.task_kinds import camel_words
from nl2hltl2plan.errors import NoPlaceError
from nl2hltl2plan.language.grounding import AffordanceLookup, Mention, alfred_lookup, find_mentions, tokens
from nl2hltl2plan.language.htt_build import bound_places, rebind
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.spec_builder import spec_name
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.worlds.world import World

_WORDS = Path(__file__).with_name("place_choice_words.txt")
_GAP = re.compile(r"[\s,]*")
_HOUSEHOLD = frozenset({"alfred", "demo"})


@dataclass(frozen=True)
class PlaceChoice:
    """One "A or B" between places: the words said, the two places' lexicon types, and the character
    spans the grammar does not read (an "either" before, the "or" and the second place)."""

    said: str
    first: tuple[str, ...]
    second: tuple[str, ...]
    read: tuple[str, ...]  # the types of the place the grammar reads (the first the world has)
    cuts: tuple[tuple[int, int], ...]


@cache
def _words() -> dict[str, tuple[tuple[str, ...], ...]]:
    out: dict[str, list[tuple[str, ...]]] = {}
    for line in _WORDS.read_text().splitlines():
        if line.startswith("@"):
            tag, phrase = line[1:].split(" ", 1)
            out.setdefault(tag, []).append(tuple(phrase.split()))
    return {k: tuple(sorted(v, key=len, reverse=True)) for k, v in out.items()}


def split_choices(text: str, world: object, look: AffordanceLookup | None) -> tuple[str, list[PlaceChoice]]:
    """The text with each choice's "or <second place>" (and a closing "whichever") cut, and the choices.
    A choice needs a placing word before the first place, the second named right after "or" (an article
    or a placing word between) and not placed itself ("or the apple in the sink" is another task), and
    both receptacles (ALFRED's facts). The grammar reads the first place the world has (`look`; None: no
    scene, no choice is read); where it has neither, NoPlaceError names them (exit 1). Household worlds
    only (`world.kind`): the tabletop and multi-arm worlds keep refusing a choice (docs/language.md)."""
    if look is None or getattr(world, "kind", None) not in _HOUSEHOLD:
        return text, []
    scene = getattr(world, "name", "the scene")
    toks = tokens(text)
    mentions = [m for m in find_mentions(text) if not m.entry.generic]
    choices: list[PlaceChoice] = []
    for i, (word, at, _) in enumerate(toks):
        left = next((m for m in reversed(mentions) if m.end <= i), None) if word == "or" else None
        right = next((m for m in mentions if m.start > i), None)
        if left is None or right is None or not _GAP.fullmatch(text[left.char_end : at]):
            continue
        start = _phrase_before(toks, left.start, "place")
        if start is None or not _only(toks, i + 1, right.start, "between"):
            continue
        if not (_a_place(left, look) and _a_place(right, look)):
            continue
        closing = _closing(toks, right.end)
        if closing is None and right.end < len(toks) and (toks[right.end][0],) in _words()["place"]:
            continue
        stop = right.char_end if closing is None else closing
        k = next(k for k, t in enumerate(toks) if t[1] == start)
        said = text[start : right.char_end]
        if _in_world(left, look):  # read "in the fridge", cut "or the microwave"
            cuts, read = [(left.char_end, stop)], left.entry.types
        elif _in_world(right, look):  # read "in the dresser", cut "the bathtub or"
            cuts, read = [(toks[k + 1][1], right.char_start), (right.char_end, stop)], right.entry.types
        else:
            lack = " or ".join(m.entry.canonical for m in (left, right))
            raise NoPlaceError(f"none of the places of {said!r} is in {scene}: no {lack} there")
        if k > 0 and toks[k - 1][0] == "either":  # "either in the fridge or ...": read with the choice
            cuts.insert(0, (toks[k - 1][1], start))
        choices.append(PlaceChoice(said, left.entry.types, right.entry.types, read, tuple(cuts)))
    if not choices:
        return text, []
    kept, last = [], 0
    for a, b in (cut for c in choices for cut in c.cuts):
        kept.append(text[last:a])
        last = b
    kept.append(text[last:])
    return "".join(kept), choices


def _in_world(m: Mention, look: AffordanceLookup) -> bool:
    return any(look(t) is not None for t in m.entry.types)


def _a_place(m: Mention, look: AffordanceLookup) -> bool:
    """Whether a type the mention names is a receptacle (the scene's, else by ALFRED's facts)."""
    facts = alfred_lookup()
    return any(
        (a := look(t) or (facts(t) if facts is not None else None)) is not None and a.receptacle
        for t in m.entry.types
    )


def _phrase_before(toks: list[tuple[str, int, int]], i: int, tag: str) -> int | None:
    """Where a placing word (and an article after it) right before token `i` starts; None if none."""
    j = i
    while j > 0 and toks[j - 1][0] in _ARTICLES:
        j -= 1
    return toks[j - 1][1] if j > 0 and (toks[j - 1][0],) in _words()[tag] else None


_ARTICLES = frozenset({"the", "a", "an", "my", "your", "that"})


def _only(toks: list[tuple[str, int, int]], i: int, j: int, tag: str) -> bool:
    """Whether tokens [i, j) are nothing but phrases of `tag` (or nothing)."""
    while i < j:
        step = next((len(p) for p in _words()[tag] if tuple(w for w, _, _ in toks[i : i + len(p)]) == p), 0)
        if not step:
            return False
        i += step
    return True


def _closing(toks: list[tuple[str, int, int]], i: int) -> int | None:
    """The end of a closing "whichever (is closer)" right after token `i`, else None."""
    for phrase in _words()["closing"]:
        got = toks[i : i + len(phrase)]
        if tuple(w for w, _, _ in got) == phrase:
            return got[-1][2]
    return None


def widen(res: LanguageResult, said: str, choices: list[PlaceChoice], world: World | None) -> LanguageResult:
    """The reading of the cut text with each choice's task given both places, and the whole text back.
    A place the world cannot take for the task is dropped, said in `assumptions`; where no place can be
    taken, NoPlaceError names them all (exit 1). A choice no task's destination holds is left to check 1."""
    tasks, notes = list(res.tasks), list(res.assumptions)
    for c in choices:
        hit = [k for k, t in enumerate(tasks) if set(t.receptacle or ()) & set(c.read)]
        if len(hit) != 1:
            continue
        task = tasks[hit[0]]
        places = [  # the place read keeps the grammar's types; the other, those the world has
            list(task.receptacle or ()) if named is c.read
            else [t for t in named if world is None or world.instances(t)] or list(named[:1])
            for named in (c.first, c.second)
        ]
        possible, why = _possible(task, places, world)
        if not possible:
            raise NoPlaceError(f"none of the places of {c.said!r} can be taken: {'; '.join(why)}")
        if why:
            notes.append(f"{c.said!r}: either place was allowed; {'; '.join(why)}, so the other is used")
        receptacle = list(dict.fromkeys(t for place in possible for t in place))
        tasks[hit[0]] = task.model_copy(update={"receptacle": receptacle, "places": places})
    htt, leaf_task = res.htt.model_copy(deep=True), dict(res.leaf_task)
    for task in tasks:  # a count takes one of the places for all its objects: the tree says so
        if bound_places(task) and task.id in res.task_node:
            htt = rebind(htt, res.task_node, leaf_task, task)
    if htt.root.text == res.instruction:
        htt.root.text = said
    htt.instruction = said
    update = {"tasks": tasks, "assumptions": notes, "instruction": said, "htt": htt, "leaf_task": leaf_task}
    return res.model_copy(update=update)


def _possible(
    task: BaseTaskSpec, places: list[list[str]], world: World | None
) -> tuple[list[list[str]], list[str]]:
    """The places the world can take the task to, and why each other one cannot be."""
    if world is None:
        return places, []
    keep, why = [], []
    for place in places:
        lack = task.model_copy(update={"receptacle": place, "places": None}).missing(world)
        if lack:
            why.append("; ".join(x.split(": ", 1)[-1] for x in lack))
        else:
            keep.append(place)
    return keep, why


class ChosenPlace(BaseModel):
    """Where the plan took the thing of a task the user allowed several places for."""

    task: str  # base-task id
    allowed: list[str]  # the places said, each its first type ("Fridge", "Microwave")
    possible: list[str]  # those the world can take (the leaf's disjunction)
    chosen: str | None  # the receptacle type the plan put it in (None: no plan)

    def describe(self) -> str:
        took = f"the plan uses the {camel_words(self.chosen).lower()}" if self.chosen else "no plan"
        return f"task {self.task}: {' or '.join(self.allowed)} allowed (the instruction left it open); {took}"


def chosen_places(
    tasks: list[BaseTaskSpec], leaf_task: dict[str, str], events: list[PlanEvent]
) -> list[ChosenPlace]:
    """Per task with a choice of places, which one the plan's last put of that task's leaves took.
    `leaf_task`: HTT leaf id -> base-task id; events name leaves by their spec names (`spec_name`)."""
    out = []
    for t in tasks:
        if not t.places:
            continue
        leaves = {spec_name(leaf) for leaf, tid in leaf_task.items() if tid == t.id}
        puts = [a for e in events if e.task in leaves and (a := Atom.read(e.atom)) is not None]
        took = [a.args[-1] for a in puts if a.verb == "put" and a.args[-1] in (t.receptacle or ())]
        allowed = [place[0] for place in t.places]
        out.append(ChosenPlace(task=t.id, allowed=allowed, possible=list(t.receptacle or ()),
                               chosen=took[-1] if took else None))  # fmt: skip
    return out
