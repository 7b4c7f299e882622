"""Semantic checks of LLM answers against what they answer (the paper's stated limitation).

A schema-valid answer can still answer another question: action completion that moves mugs when
the leaf asks for plates, a decomposition that forgets the knife the instruction names, relations
that order A before B and B before A. Each check returns readable problems (empty: the answer fits);
`stages.py` re-asks the LLM with them and reports them when they persist, so a wrong answer never
turns silently into a "solved" plan.

- `action_problems(actions, task, scene_types)`: the actions of one HTT leaf must pick up the leaf's
  object, bring it (or, for place_in_container, its container) to the receptacle the task names,
  treat it in the task's appliance, switch on its lamp, and handle nothing the task does not name
  (besides a knife to slice); every type must be in the world (also checked per action by stages).
- `decomposition_problems(instruction, tasks)`: every object the instruction names must be used by
  some task (as object, container, receptacle, lamp, or implied by the task: sink for washing,
  knife for slicing ...), except places ("the lamp on the desk", "the mug from the table").
- `find_cycle(pairs)` / `cycle_problem(pairs)`: the first cycle of an ordering, named in full.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import Any, Protocol

import networkx as nx

from nl2hltl2plan.domain.task_kinds import APPLIANCE
from nl2hltl2plan.language.grounding import THOR_TYPES, find_mentions, lookup, tokens
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.worlds.world import KNIFE_TYPES, sliced_type


def _action(text: str) -> Atom | None:
    """An action on object types (letters only: no instance names) with one or two arguments, or None."""
    atom = Atom.read(text)
    ok = atom is not None and len(atom.args) <= 2 and all(x.isalpha() for x in atom.args)
    return atom if ok else None

# types a task of this kind uses without naming them as a field
IMPLIED: dict[str, tuple[str, ...]] = {
    "clean_place": ("SinkBasin", "Sink", "Faucet"),
    "heat_place": ("Microwave", "StoveBurner", "Oven"),
    "cool_place": ("Fridge",),
}
SWITCHED = {"clean_place": ("Faucet",), "heat_place": ("Microwave",)}
# words just before a mention that make it a place (where something is, or is taken from), not a thing
# the tasks must act on: "the lamp on the desk", "the mug from the table" (a missing destination is
# already refused by the schema: every task kind but examine_in_light needs a receptacle)
PLACE_WORDS = {
    "from", "off", "out", "on", "in", "at", "by", "near", "beside", "next", "under", "above", "below",
    "behind", "inside", "onto", "into", "to", "across", "around", "over", "top", "beneath", "within", "of",
}


# ----- relations ---------------------------------------------------------------------------------
def find_cycle(pairs: Iterable[tuple[str, str]]) -> list[str] | None:
    """The nodes of one cycle of the ordering, first node repeated at the end, or None."""
    pairs = list(pairs)
    if not pairs:  # no order at all (most readings): no graph to build
        return None
    g = nx.DiGraph(pairs)
    try:
        edges = nx.find_cycle(g)
    except nx.NetworkXNoCycle:
        return None
    return [a for a, _ in edges] + [edges[0][0]]


def cycle_problem(pairs: Iterable[tuple[str, str]], what: str = "the relations") -> str | None:
    cycle = find_cycle(pairs)
    if cycle is None:
        return None
    return f"{what} form a cycle: {' before '.join(cycle)} (each must come before itself)"


# ----- action completion -------------------------------------------------------------------------------
def _types(value: Any) -> set[str]:
    if value is None:
        return set()
    if isinstance(value, str):
        return {value}
    return {str(v) for v in value}


def _parse(actions: Sequence[str]) -> list[tuple[str, list[str]]]:
    out = []
    for a in actions:
        m = _action(a)
        if m is not None:
            out.append((m.verb, list(m.args)))
    return out


def action_problems(
    actions: Sequence[str], task: Mapping[str, Any], scene_types: set[str] | None = None
) -> list[str]:
    """Why these actions do not carry out `task` (fields of a base task: kind, object, sliced,
    container, receptacle, light, id); [] when they do."""
    kind = str(task.get("kind", ""))
    leaf = task.get("id", "this task")
    objects = _types(task.get("object"))
    moved = objects | {sliced_type(o) for o in objects}
    containers, receptacles, lights = (_types(task.get(k)) for k in ("container", "receptacle", "light"))
    steps = _parse(actions)
    problems: list[str] = []
    if scene_types is not None:
        missing = sorted({t for _, args in steps for t in args} - scene_types)
        problems += [f"there is no {t} in the world" for t in missing]
    allowed = moved | containers | (set(KNIFE_TYPES) if task.get("sliced") else set())
    for verb, args in steps:
        if objects and verb == "pickup" and args[0] not in allowed:
            problems.append(f"pickup({args[0]}): {leaf} is about {_names(objects)}, not {args[0]}")
    picked = [args[0] for verb, args in steps if verb == "pickup"]
    if objects and not set(picked) & moved:
        problems.append(f"nothing picks up the {_names(objects)} that {leaf} is about")
    puts = [(args[0], args[1]) for verb, args in steps if verb == "put" and len(args) == 2]
    if kind == "examine_in_light":
        if lights and not any(v == "toggle_on" and a[0] in lights for v, a in steps):
            problems.append(f"{leaf} must switch on {_names(lights)}")
    elif kind == "place_in_container":
        if containers and not any(x in moved and r in containers for x, r in puts):
            problems.append(f"{leaf} must put the {_names(objects)} into {_names(containers)}")
        last = [r for x, r in puts if x in containers]
        if receptacles and (not last or last[-1] not in receptacles):
            problems.append(f"{leaf} must end with the {_names(containers)} in/on {_names(receptacles)}")
    elif receptacles:
        last = [r for x, r in puts if x in moved]
        if not last or last[-1] not in receptacles:
            where = f"ends in/on {last[-1]}" if last else "is never put down"
            want = f"the {_names(objects)} in/on {_names(receptacles)}"
            problems.append(f"{leaf} must end with {want}; it {where}")
    problems += _treatment_problems(kind, leaf, moved, steps, puts, scene_types)
    return problems


def _treatment_problems(
    kind: str,
    leaf: object,
    moved: set[str],
    steps: list[tuple[str, list[str]]],
    puts: list[tuple[str, str]],
    scene_types: set[str] | None,
) -> list[str]:
    appliance = APPLIANCE.get(kind)
    if appliance is None or (scene_types is not None and appliance not in scene_types):
        return []
    problems = []
    if not any(x in moved and r == appliance for x, r in puts):
        problems.append(f"{leaf} ({kind}) must put the object into the {appliance}")
    for switch in SWITCHED.get(kind, ()):
        present = scene_types is None or switch in scene_types
        if present and not any(v == "toggle_on" and a[0] == switch for v, a in steps):
            problems.append(f"{leaf} ({kind}) must switch on the {switch}")
    return problems


def _names(types: Iterable[str]) -> str:
    return "/".join(sorted(types)) or "?"


# ----- decomposition -----------------------------------------------------------------------------------
class TaskWords(Protocol):
    """What the coverage check reads of a decomposed task (stages.TaskFields has these)."""

    @property
    def kind(self) -> str: ...
    @property
    def object(self) -> str: ...
    @property
    def sliced(self) -> bool: ...
    @property
    def container(self) -> str | None: ...
    @property
    def receptacle(self) -> str | None: ...
    @property
    def light(self) -> str | None: ...


def _word_types(word: str | None) -> set[str]:
    """Every type a task's field word may stand for."""
    if not word or not word.strip():
        return set()
    w = word.strip()
    exact = {t for t in THOR_TYPES if t.lower() in (w.lower(), w.lower().replace(" ", ""))}
    bare = {t[: -len("Sliced")] for t in exact if t.endswith("Sliced")}
    entry = lookup(w[:-6] if w.endswith("Sliced") else w)
    return exact | bare | (set(entry.types) if entry is not None and not entry.generic else set())


def covered_types(tasks: Iterable[TaskWords]) -> set[str]:
    covered: set[str] = set()
    for t in tasks:
        for word in (t.object, t.container, t.receptacle, t.light):
            covered |= _word_types(word)
        covered |= set(IMPLIED.get(t.kind, ()))
        if t.sliced:
            covered |= set(KNIFE_TYPES)
        if t.kind == "examine_in_light":
            covered |= {"DeskLamp", "FloorLamp"}
    return covered


def decomposition_problems(instruction: str, tasks: Sequence[TaskWords]) -> list[str]:
    """Objects the instruction names that no task uses (places taken from do not count)."""
    words = [w for w, _, _ in tokens(instruction)]
    covered = covered_types(tasks)
    problems: list[str] = []
    for m in find_mentions(instruction):
        if m.entry.generic or set(m.entry.types) & covered:
            continue
        before = set(words[max(0, m.start - 4) : m.start])
        if before & PLACE_WORDS:
            continue
        text = f"the instruction names {m.surface!r} ({_names(m.entry.types)}) but no task uses it"
        if text not in problems:
            problems.append(text)
    return problems
