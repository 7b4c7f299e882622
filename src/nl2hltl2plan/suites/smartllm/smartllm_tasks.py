"""SMART-LLM's benchmark tasks: their worlds, ground-truth final states and oracle specs.

Tasks: `smartllm/final_test_all.jsonl` (36 tasks in 7 AI2-THOR floor plans: text, robot list,
ground-truth `object_states` [{name, contains, state}], trans, max_trans). Names are repaired and
the repairs recorded per task (`notes`): stray spaces/commas ("CoffeeTable,"), lower-case aliases
("trash" -> GarbageCan, "cloth" -> Cloth); an entry with neither a state nor contents
("cabinet", contains [], state null) is no condition and is dropped with a note. The task without
ground truth (FloorPlan209 "Turn off floor lamp") has `has_gt` False.

Worlds: the floor plan built from one of its ALFRED trials (`choose_trial`: the first in which the
objects the goals move lie outside closed containers, as in AI2-THOR's default scenes), plus
AI2-THOR's vocabulary (`worlds.effects`: books, laptops and blinds open; laptops, phones, burners,
toasters switch; every receptacle takes any pickupable object, because SMART-LLM executes PutObject with
`forceAction=True`, which lifts AI2-THOR's compatibility rules; blinds start open and lights on).
A type the goal needs that ALFRED's data does not place (light switches, a television, a toaster,
blinds) is added at an estimated, reachable position flagged `approximate`: next to an anchor
(Toaster at a CounterTop, Television at a TVStand, Blinds at a Window), else at the free cell
nearest the free area's centroid. Travel distances to such objects are estimates.

Oracle specs: one leaf per ground-truth condition, with precedence pairs where one condition must be
reached before another (cook before putting it away; put the mug in before switching the machine on;
slice before throwing the slices away).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cache

import numpy as np

from nl2hltl2plan.config import data_path
from nl2hltl2plan.errors import DataError, WorldError
from nl2hltl2plan.io import read_jsonl
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.logic.relations import compile_relations
from nl2hltl2plan.worlds import effects
from nl2hltl2plan.worlds.floor_plans import affordance_table, alfred_data, default_trial, load_floor_plan
from nl2hltl2plan.worlds.world import KNIFE_TYPES, Cell, World, WorldObject, sliced_type

ALIASES = {"trash": "GarbageCan", "garbage": "GarbageCan", "cloth": "Cloth", "cabinet": "Cabinet"}
ANCHORS = {
    "Toaster": "CounterTop",
    "Television": "TVStand",
    "Blinds": "Window",
    "CoffeeMachine": "CounterTop",
}
ROOT = "task1"


@dataclass(frozen=True)
class Condition:
    """One ground-truth goal condition: `name` in `state`, or `name` containing `contains`."""

    name: str
    state: str | None = None
    contains: str | None = None

    def describe(self) -> str:
        return f"{self.name} contains {self.contains}" if self.contains else f"{self.name} {self.state}"


@dataclass
class SmartTask:
    index: int
    floor_plan: str
    text: str
    robots: list[int]
    conditions: list[Condition]
    has_gt: bool
    trans: int | None
    max_trans: int | None
    notes: list[str] = field(default_factory=list)
    # the ground truth's entries as written (raw names): SMART-LLM's own script scores these
    entries: list[tuple[str, str | None, tuple[str, ...]]] = field(default_factory=list)

    @property
    def id(self) -> str:
        return f"{self.floor_plan}#{self.index}"


def _clean_name(raw: str, notes: list[str]) -> str:
    name = raw.strip().strip(",").strip()
    if name.lower() in ALIASES:
        name = ALIASES[name.lower()]
    if name != raw:
        notes.append(f"name {raw!r} read as {name!r}")
    return name


def parse_task(index: int, row: dict) -> SmartTask:
    """One line of final_test_all.jsonl."""
    try:
        fp, text, robots = row["floor_plan"], row["task"], [int(r) for r in row["robot list"]]
    except (KeyError, TypeError, ValueError) as exc:
        raise DataError(f"SMART-LLM task {index}: missing or malformed field {exc}") from None
    notes: list[str] = []
    conds: list[Condition] = []
    has_gt = "object_states" in row
    entries = [
        (str(e.get("name", "")), e.get("state"), tuple(str(c) for c in e.get("contains") or []))
        for e in row.get("object_states") or []
    ]
    for entry in row.get("object_states") or []:
        name = _clean_name(str(entry.get("name", "")), notes)
        contains = [_clean_name(str(c), notes) for c in entry.get("contains") or []]
        state = entry.get("state")
        if state is not None and state not in effects.STATES:
            raise DataError(f"SMART-LLM task {fp} {text!r}: unknown state {state!r}")
        if state is None and not contains:
            notes.append(f"{name}: no state and no contents, not a condition (dropped)")
            continue
        if state is not None:
            conds.append(Condition(name, state=state))
        conds.extend(Condition(name, contains=c) for c in contains)
    if not has_gt:
        notes.append("no ground-truth object_states in SMART-LLM's data: not scored")
    trans, max_trans = row.get("trans"), row.get("max_trans")
    return SmartTask(index, fp, text, robots, conds, has_gt, trans, max_trans, notes, entries)


@cache
def load_tasks() -> tuple[SmartTask, ...]:
    """The 36 SMART-LLM tasks, numbered per floor plan from 1 as in the published files."""
    path = data_path("smartllm", "final_test_all.jsonl")
    out: list[SmartTask] = []
    per_fp: dict[str, int] = {}
    for k, row in enumerate(read_jsonl(path, "SMART-LLM task file"), start=1):
        if not isinstance(row, dict):
            raise DataError(f"SMART-LLM task file {path}: record {k} is not a JSON object")
        fp = row.get("floor_plan", "?")
        per_fp[fp] = per_fp.get(fp, 0) + 1
        out.append(parse_task(per_fp[fp], row))
    return tuple(out)


# ---------------------------------------------------------------- worlds
def _patched(obj: WorldObject, pickupable: frozenset[str]) -> WorldObject:
    aff = obj.affordances
    if obj.type in effects.EXTRA_OPENABLE:
        aff = replace(aff, openable=True)
    if obj.type in effects.EXTRA_TOGGLEABLE:
        aff = replace(aff, toggleable=True)
    if aff.receptacle:  # SMART-LLM puts with forceAction=True: no compatibility restriction
        aff = replace(aff, accepts=aff.accepts | (pickupable - {obj.type}))
    obj.affordances = aff
    obj.is_open = obj.is_open or obj.type in effects.OPEN_AT_START
    obj.is_on = obj.is_on or obj.type in effects.ON_AT_START
    return obj


def choose_trial(floor_plan: str, movable: tuple[str, ...]) -> str:
    """The floor plan's first ALFRED trial (file order) in which every `movable` type the goals move
    exists and lies outside closed containers (AI2-THOR's default scenes, which SMART-LLM uses, keep
    such objects in the open); the first trial with object poses when none does."""
    data = alfred_data()
    first = default_trial(floor_plan)
    if not movable:
        return first
    for tid in data.by_floor_plan.get(floor_plan, []):
        if not data.trials[tid].poses:
            continue
        world = load_floor_plan(floor_plan, [tid])
        ok = all(
            any(o.interaction_cells and world.closed_ancestor(o.id) is None for o in world.instances(t))
            for t in movable
        )
        if ok:
            return tid
    return first


@cache
def smartllm_world(floor_plan: str, extra_types: tuple[str, ...] = (), trial: str | None = None) -> World:
    """A SMART-LLM floor plan (see the module docstring) with the movable objects of `trial`
    (default: its first trial); `extra_types` are added if missing."""
    base = load_floor_plan(floor_plan, [trial] if trial else None)
    objects = list(base.objects.values())
    pickupable = frozenset(o.type for o in objects if o.pickupable)
    table = affordance_table()
    free = np.array([base.xz(c) for c in base.cells])
    main = base.components[0]
    present = {o.type for o in objects}
    notes = list(base.notes)
    for typ in extra_types:
        if typ in present:
            continue
        pos, note = _estimate(base, typ, main)
        objects.append(
            WorldObject(
                id=f"{typ}_0",
                type=typ,
                position=pos,
                affordances=table(typ),
                source=f"{typ}~estimated",
                approximate=True,
                note=note,
            )
        )
        notes.append(f"{typ}: {note}")
    objects = [_patched(o, pickupable) for o in objects]
    for o in objects:
        o.interaction_cells = ()
    unplaced = {k: v for k, v in base.unplaced.items() if k not in extra_types}
    return World.create(
        base.name,
        free,
        objects,
        unplaced=unplaced,
        notes=notes,
        kind="alfred",
        source_trials=base.source_trials,
    )


def _estimate(world: World, typ: str, main: set[Cell]) -> tuple[tuple[float, float, float], str]:
    anchor = ANCHORS.get(typ)
    for o in world.objects.values():
        if anchor and o.type == anchor and o.interaction_cells:
            x, y, z = o.position
            return (x, y + 0.3, z), f"position unknown in ALFRED's data; placed at {o.id}"
    cells = sorted(main)
    centre = np.mean([world.xz(c) for c in cells], axis=0)
    x, z = world.xz(world.cell_of(float(centre[0]), float(centre[1]), main=True))
    return (x, 1.2, z), "position unknown in ALFRED's data; placed at the free area's centre"


def world_for(task: SmartTask) -> World:
    """The task's world, with every type its conditions (and their recipes) need."""
    need = {c.name for c in task.conditions} | {c.contains for c in task.conditions if c.contains}
    for c in task.conditions:
        if c.state == "COOKED" and c.name == "Bread":
            need.add("Toaster")
    table = affordance_table()
    extra = tuple(sorted(t for t in need if t in table.object_types))
    movable = tuple(
        sorted(c.contains for c in task.conditions if c.contains and c.contains in table.pickupable)
    )
    return smartllm_world(task.floor_plan, extra, choose_trial(task.floor_plan, movable))


def start_cells(world: World, n: int, seed: int) -> list[Cell]:
    """Robot starts: SMART-LLM teleports each robot to a random reachable position; we draw cells
    of the largest connected component with a fixed seed (reproducible)."""
    cells = sorted(world.components[0])
    rng = np.random.default_rng(seed)
    return [cells[int(i)] for i in rng.choice(len(cells), size=n, replace=len(cells) < n)]


# ---------------------------------------------------------------- oracle specs
def _resolve(world: World, name: str) -> str:
    """The world's object type for a ground-truth name (exact type first, then prefix)."""
    types = sorted(t for t in world.object_types() if any(o.interaction_cells for o in world.instances(t)))
    if name in types:
        return name
    cands = [t for t in types if effects.type_matches(name, t)]
    if not cands:
        raise WorldError(f"no {name} within reach in {world.name}")
    return cands[0]


def _receptacle(world: World, name: str, obj: str) -> str:
    """The receptacle type for `name` holding `obj`: one ALFRED lets hold it first (Sink -> SinkBasin)."""
    alfred = affordance_table()
    cands = sorted(
        (
            t
            for t in world.object_types()
            if effects.type_matches(name, t)
            and world.instances(t)[0].affordances.receptacle
            and any(o.interaction_cells for o in world.instances(t))
        ),
        key=lambda t: (obj not in alfred(t).accepts, t != name, t),
    )
    if not cands:
        raise WorldError(f"no receptacle {name} within reach in {world.name}")
    return cands[0]


def _slice_seq(world: World, obj: str) -> list[str]:
    """Take a knife and slice. Putting the knife back is no goal of SMART-LLM's (and a slicer may
    lack PutObject); the planner puts it down when that robot's hand is needed again."""
    knife = next((k for k in KNIFE_TYPES if world.instances(k)), KNIFE_TYPES[0])
    return [f"pickup({knife})", f"slice({obj})"]


def _leaf(world: World, cond: Condition, task: SmartTask) -> tuple[list[str], list[str]]:
    """(atoms, tags): the leaf's action sequence; tags say what it does to which type
    ("slice:Apple", "move:Potato", "heat:Mug", "place:Mug@CoffeeMachine") for the orderings."""
    if cond.contains is not None:
        sliced_goal = any(c.state == "SLICED" and c.name == cond.contains for c in task.conditions)
        obj = sliced_type(cond.contains) if sliced_goal else _resolve(world, cond.contains)
        name = _receptacle(world, cond.name, obj)
        seq = (
            _take(world, obj) + ([f"open({name})"] if _openable(world, name) else []) + [f"put({obj},{name})"]
        )
        return seq, [f"place:{obj}@{name}", f"move:{obj}"]
    state = cond.state
    name = _resolve(world, cond.name)
    if state == "SLICED":
        return _slice_seq(world, name), [f"slice:{name}"]
    if state in ("ON", "OFF"):
        return [f"toggle_{state.lower()}({name})"], [f"switch:{name}"]
    if state in ("OPENED", "CLOSED"):
        return [f"{'open' if state == 'OPENED' else 'close'}({name})"], [f"open:{name}"]
    if state == "PICKED":
        return _take(world, name), [f"hold:{name}"]
    if state == "BROKEN":
        return [f"break({name})"], [f"break:{name}"]
    if state in ("HOT", "COOKED"):
        return _heat_leaf(world, name, state, task)
    raise WorldError(f"no recipe for {cond.describe()}")


def _take(world: World, obj: str) -> list[str]:
    """pickup(obj), after opening the container when every reachable instance sits in a closed one."""
    holders = [world.closed_ancestor(o.id) for o in world.instances(obj) if o.present and o.interaction_cells]
    if holders and all(holders):
        return [f"open({world.objects[holders[0]].type})", f"pickup({obj})"]  # type: ignore[index]
    return [f"pickup({obj})"]


def _openable(world: World, typ: str) -> bool:
    insts = world.instances(typ)
    return bool(insts) and insts[0].affordances.openable


def _heat_leaf(world: World, name: str, state: str, task: SmartTask) -> tuple[list[str], list[str]]:
    # already going into a heat source (mug into the coffee machine): switch that on afterwards
    for c in task.conditions:
        src = (
            _receptacle(world, c.name, name) if c.contains and effects.type_matches(c.contains, name) else ""
        )
        if src in effects.HEAT_SOURCES:
            return [f"toggle_on({src})"], [f"heat:{name}", f"after-place:{name}@{src}"]
    obj = name
    seq: list[str] = []
    if state == "COOKED" and name not in effects.COOKABLE and sliced_type(name) in effects.COOKABLE:
        seq += _slice_seq(world, name)  # bread is toasted as slices
        obj = sliced_type(name)
    src = (
        "Toaster"
        if world.instances("Toaster") and obj in world.instances("Toaster")[0].affordances.accepts
        else "Microwave"
    )
    take = [f"pickup({obj})"] if seq else _take(world, obj)
    if src == "Microwave":
        seq += take + [
            "open(Microwave)",
            f"put({obj},Microwave)",
            "close(Microwave)",
            "toggle_on(Microwave)",
            "toggle_off(Microwave)",
            "open(Microwave)",
        ]
    else:
        seq += take + [f"put({obj},{src})", f"toggle_on({src})"]
    return seq, [f"heat:{name}", f"move:{name}"]


def oracle_spec(task: SmartTask, world: World) -> tuple[HierarchicalSpec, list[str]]:
    """The spec a perfect translator would write for the task's ground truth: L1 over one leaf per
    condition (precedence pairs as in the module docstring); also returns all leaf atoms."""
    leaves: dict[str, list[str]] = {}
    tags: dict[str, list[str]] = {}
    for k, cond in enumerate(task.conditions, start=1):
        name = f"{ROOT}.{k}"
        leaves[name], tags[name] = _leaf(world, cond, task)
    before = _orderings(tags)
    if not leaves:
        raise WorldError(f"{task.id}: no goal condition to plan for")
    levels: list[dict[str, str | list[str]]] = [
        {ROOT: compile_relations(list(leaves), before)},
        {n: _flat(s) for n, s in leaves.items()},
    ]
    atoms = [a for s in leaves.values() for a in s]
    return HierarchicalSpec(levels), atoms


def _flat(seq: list[str]) -> str:
    from nl2hltl2plan.logic.action_sequences import sequences_formula

    return sequences_formula([seq])


def _orderings(tags: dict[str, list[str]]) -> list[tuple[str, str]]:
    pairs = []
    for a, ta in tags.items():
        for b, tb in tags.items():
            if a == b:
                continue
            for x in ta:
                kind, _, what = x.partition(":")
                if kind == "slice" and any(
                    y.startswith("place:") and y[6:].startswith(sliced_type(what)) for y in tb
                ):
                    pairs.append((a, b))  # slice before throwing the slices away
                if (
                    kind == "heat"
                    and f"move:{what}" in tb
                    and not any(y.startswith("after-place") for y in ta)
                ):
                    pairs.append((a, b))  # cook, then put it away
                if kind == "place" and any(y == f"after-place:{what}" for y in tb):
                    pairs.append((a, b))  # put the mug in, then switch the machine on
    return list(dict.fromkeys(pairs))
