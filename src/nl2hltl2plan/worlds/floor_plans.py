"""AI2-THOR floor plans from ALFRED data: grid, static objects, movable objects, benchmark worlds.

Scene construction for a floor plan plus a set of ALFRED trials:
- free cells: `alfred/layouts/FloorPlanN-layout.npy` (reachable (x, z), 0.25 m grid).
- static objects (receptacles, appliances, sinks, lamps...): every position-encoding object id
  `Type|x|y|z` found in the floor plan's `FloorPlanN-openable.json` (with the ALFRED agent pose used to
  open it) and in the `objectId` / `receptacleObjectId` of all the floor plan's expert plans
  (`Sink|x|y|z|SinkBasin` places a SinkBasin, `Bathtub|...|BathtubBasin` a BathtubBasin). Ids of the
  same type closer than 0.1 m are one object.
- Faucet: ALFRED's CleanObject never names the faucet, so when the scene lists a Faucet we put one at
  each SinkBasin (approximate position; it `serves` that basin).
- other static types the scene lists but no id places: estimated 0.8 m ahead of the expert's
  `GotoLocation` poses aimed at that type (the median distance from such a pose to the object it
  faces is 0.8 m in ALFRED's plans); estimates within 1 m are one object; flagged `approximate`.
- movable objects: the trials' `object_poses`, merged: every pose of every trial, in trial order;
  repeated names are real copies (AI2-THOR's SetObjectPoses makes a copy per repeated name), except
  that a name at the same place (within 1 cm) as in an earlier trial is that same object. So each base
  task finds the objects of its own ALFRED trial where that trial put them (the annotation guide:
  "the actual episode may hold extra copies of small objects").
- the initial parent of a movable object: the nearest receptacle that accepts its type within
  0.45 m (3-D distance between positions; static receptacles, then movable ones within 0.15 m);
  None when nothing is that close.
- object types the scene lists (`FloorPlanN-objects.json`) but we cannot place: `World.unplaced`, each
  with the reason (a movable one: no admitted ALFRED trial of the floor plan places it; FloorPlan319's
  Footstool is the only one, every other listed movable type is in every trial).
  Types only AI2-THOR 5's `alfred_multiagent/scene_info` lists (DeskLamp and Shelf in FloorPlan201;
  the language stage grounds against both lists) that the world lacks are a note, not `unplaced`:
  ALFRED's version of the scene may not hold them, and no ALFRED trajectory places them.
Without trials, `load_floor_plan` uses the floor plan's first trial (in trials.jsonl.gz order) that
has object poses and is not in `benchmark/training_exclusions.txt`. Other trials add nothing there: over
the 120 floor plans, every ALFRED object name that any admitted trial of a floor plan places is in that
first trial already (tests/worlds/test_floor_plan_lists.py).
"""

from __future__ import annotations

import math
import re
from collections import Counter
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from nl2hltl2plan.config import data_dir, data_path
from nl2hltl2plan.errors import DataError, WorldError
from nl2hltl2plan.io import iter_gzip_jsonl, load_npy, read_json, read_text
from nl2hltl2plan.worlds.affordances import AffordanceTable, alfred_affordances
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.world import ALFRED_PICK_TWO, World, WorldObject, add_slices

SAME_OBJECT_M = 0.1
SAME_POSE_M = 0.01
GOTO_AHEAD_M = 0.8
GOTO_MERGE_M = 1.0
PARENT_RADIUS_M = 0.45
MOVABLE_PARENT_RADIUS_M = 0.15
BASINS = ("SinkBasin", "BathtubBasin")
_FLOOR_PLAN = re.compile(r"^FloorPlan(\d+)$")


@dataclass
class Trial:
    """What the world builder needs from one ALFRED trajectory."""

    trial: str
    floor_plan: str
    poses: list[tuple[str, float, float, float]]  # (AI2-THOR name, x, y, z)
    object_ids: list[str]  # objectId / receptacleObjectId of the expert plan
    gotos: list[tuple[str, float, float, int]]  # (target word, agent x, agent z, rotation degrees)
    toggles: list[tuple[str, bool]]  # (object type, isOn)


@dataclass(frozen=True)
class TrialRecord:
    """The fields of one ALFRED trial that the learned parser's examples come from (its training data).

    `task_type` and `pddl_params` are None in the test splits (no plan); `pddl_params` keeps ALFRED's
    keys (object_target, parent_target, mrecep_target, toggle_target, object_sliced)."""

    trial: str
    split: str
    floor_plan: str
    task_type: str | None
    pddl_params: dict[str, Any] | None
    annotations: tuple[dict[str, Any], ...]

    @classmethod
    def of_row(cls, row: dict[str, Any]) -> TrialRecord:
        """A trials.jsonl.gz record; KeyError / TypeError for a damaged one (the reader reports it)."""
        params, anns = row.get("pddl_params"), row["annotations"]
        if params is not None and not isinstance(params, dict):
            raise TypeError(f"pddl_params of {row['trial']} is not an object")
        if not isinstance(anns, list) or not all(isinstance(a, dict) for a in anns):
            raise TypeError(f"annotations of {row['trial']} is not a list of objects")
        task_type = row.get("task_type")
        return cls(
            str(row["trial"]),
            str(row["split"]),
            str(row["floor_plan"]),
            None if task_type is None else str(task_type),
            params,
            tuple(anns),
        )


@dataclass
class AlfredData:
    trials: dict[str, Trial]
    by_floor_plan: dict[str, list[str]] = field(default_factory=dict)
    pose_types: frozenset[str] = frozenset()
    put_pairs: frozenset[tuple[str, str]] = frozenset()  # (object type, receptacle type) experts put
    # each record's fields the learned parser's examples come from (its training data), taken in the same
    # pass: the file is parsed once per process, not again by `learned.data.load_examples` (1 s CPU)
    example_fields: tuple[TrialRecord, ...] = ()


@cache
def alfred_data() -> AlfredData:
    """All 8,051 trials, parsed once (about a second)."""
    path = data_path("alfred", "trials.jsonl.gz")
    trials: dict[str, Trial] = {}
    by_fp: dict[str, list[str]] = {}
    names: set[str] = set()  # 1,875 names in 267,477 poses: each name's type is taken once, at the end
    puts: set[tuple[str, str]] = set()
    fields: list[TrialRecord] = []
    try:
        for _n, row in iter_gzip_jsonl(path, "ALFRED trials file"):
            poses = [
                (p["name"], float(p["x"]), float(p["y"]), float(p["z"])) for p in row["object_poses"]
            ]
            ids, gotos = [], []
            for h in row.get("high_pddl") or []:
                for key in ("objectId", "receptacleObjectId"):
                    if h.get(key):
                        ids.append(h[key])
                if h.get("action") == "PutObject" and h.get("objectId") and h.get("receptacleObjectId"):
                    obj, rec = _parse_id(h["objectId"]), _parse_id(h["receptacleObjectId"])
                    if obj and rec:
                        puts.add((obj[0], rec[0]))
                if h.get("action") == "GotoLocation" and h.get("location") and h.get("args"):
                    _, x, z, rot, _hor = h["location"].split("|")
                    gotos.append((h["args"][0], int(x) * 0.25, int(z) * 0.25, int(rot) * 90))
            toggles = [(t["objectType"], bool(t["isOn"])) for t in row.get("object_toggles") or []]
            trial = Trial(row["trial"], row["floor_plan"], poses, ids, gotos, toggles)
            trials[trial.trial] = trial
            by_fp.setdefault(trial.floor_plan, []).append(trial.trial)
            names.update(n for n, *_ in poses)
            fields.append(TrialRecord.of_row(row))
        types = frozenset(map(_type_of_name, names))
    except (KeyError, ValueError, TypeError, AttributeError, IndexError) as exc:
        raise DataError(f"ALFRED trials file {path} is damaged: a record lacks or mistypes {exc}") from None
    if not trials:
        raise DataError(f"ALFRED trials file {path} holds no trial (empty or damaged)")
    return AlfredData(trials, by_fp, types, frozenset(puts), tuple(fields))


@cache
def excluded_trials() -> frozenset[str]:
    """ALFRED trials that nothing may be trained, tuned or validated on (benchmark/training_exclusions.txt):
    the families the evaluation instructions were composed from."""
    path = data_path("benchmark", "training_exclusions.txt")
    lines = read_text(path, "training exclusions file").splitlines()
    return frozenset(s.strip() for s in lines if s.strip() and not s.startswith("#"))


@cache
def affordance_table() -> AffordanceTable:
    """ALFRED affordances; every type in object_poses is pickupable, and a receptacle also accepts
    what ALFRED's expert plans put into it (they put knives into fridges, cabinets, microwaves and
    garbage cans after slicing, which ALFRED's goal constants leave out)."""
    data = alfred_data()
    return alfred_affordances().with_pickupable(data.pose_types).with_accepts(data.put_pairs)


def floor_plans() -> list[str]:
    """The 120 floor plans that have layouts, in numeric order."""
    folder = data_path("alfred", "layouts")
    names = {p.name.split("-")[0] for p in folder.glob("FloorPlan*-layout.npy")}
    return sorted(names, key=lambda n: int(n[9:]))


def _type_of_name(name: str) -> str:
    return name.rsplit("_", 1)[0]


def _layout_file(fp: str, suffix: str) -> Path:
    if not _FLOOR_PLAN.match(fp):
        raise WorldError(f"unknown world {fp!r}: expected 'demo' or an ALFRED floor plan such as FloorPlan17")
    folder = data_path("alfred", "layouts")  # a missing data folder is a DataError naming the setting
    path = folder / f"{fp}-{suffix}"
    if not path.exists():
        raise WorldError(
            f"no ALFRED layout for {fp}: {path} does not exist (the layouts in {folder} cover floor plans "
            "1-30, 201-230, 301-330, 401-430)"
        )
    return path


@cache
def scene_types(fp: str) -> tuple[str, ...]:
    """Object types the scene lists (FloorPlanN-objects.json)."""
    path = _layout_file(fp, "objects.json")
    types = read_json(path, "ALFRED object list")
    if not isinstance(types, list) or not all(isinstance(t, str) for t in types):
        raise DataError(f"ALFRED object list {path} is damaged: expected a JSON list of object types")
    return tuple(types)


@cache
def listed_types(fp: str) -> frozenset[str]:
    """Object types either list of the scene names: ALFRED's objects.json and AI2-THOR's scene_info
    instances (`Type_hash`; absent file: none), the Floor left out; the union the language stage grounds
    against (`language.grounding.scene_types`)."""
    found = set(scene_types(fp))
    base = data_dir(required=True)
    assert base is not None
    path = base / "alfred_multiagent" / "scene_info" / f"{fp}.json"
    if path.exists():
        info = read_json(path, "scene info file")
        objects = info.get("objects") if isinstance(info, dict) else None
        if not isinstance(objects, dict):
            raise DataError(f"scene info file {path} is damaged: expected an object with an 'objects' map")
        found.update(_type_of_name(str(name)) for name in objects)
    found.discard("Floor")
    return frozenset(found)


@cache
def _free_xz(fp: str) -> np.ndarray:
    path = _layout_file(fp, "layout.npy")
    arr = load_npy(path, "ALFRED layout")
    if arr.ndim != 2 or arr.shape[1] != 2 or not np.issubdtype(arr.dtype, np.number):
        raise DataError(
            f"ALFRED layout {path} is damaged: expected an (N, 2) array of (x, z), got shape {arr.shape}"
        )
    return arr


@dataclass
class _Static:
    type: str
    pos: tuple[float, float, float]
    source: str
    pose: tuple[float, float] | None = None
    approximate: bool = False
    note: str = ""
    serves: int | None = None  # index of the SinkBasin a Faucet serves


def _parse_id(oid: str) -> tuple[str, tuple[float, float, float]] | None:
    parts = oid.split("|")
    try:
        pos = (float(parts[1]), float(parts[2]), float(parts[3]))
    except (IndexError, ValueError):
        return None
    if len(parts) == 4:
        return parts[0], pos
    if len(parts) == 5 and parts[4] in BASINS:
        return parts[4], pos
    return None  # slices and other sub-objects


@cache
def _statics(fp: str) -> tuple[tuple[_Static, ...], dict[str, str]]:
    """Static objects of a floor plan and the static types it lists but we cannot place."""
    table = affordance_table()
    movable = table.pickupable
    openable_path = _layout_file(fp, "openable.json")
    openable = read_json(openable_path, "ALFRED openable-object file")
    if not isinstance(openable, dict):
        raise DataError(f"ALFRED openable-object file {openable_path} is damaged: expected a JSON object")
    data = alfred_data()
    trial_ids = data.by_floor_plan.get(fp, [])
    found: list[_Static] = []

    def add(oid: str, pose: tuple[float, float] | None) -> None:
        parsed = _parse_id(oid)
        if parsed is None:
            return
        typ, pos = parsed
        if typ in movable:
            return
        for s in found:
            if s.type == typ and math.dist(s.pos, pos) < SAME_OBJECT_M:
                if s.pose is None and pose is not None:
                    s.pose = pose
                return
        found.append(_Static(typ, pos, oid, pose))
        if len(oid.split("|")) == 5:  # the Sink / Bathtub that holds the basin
            add("|".join(oid.split("|")[:4]), None)

    for oid, pose in sorted(openable.items()):
        add(oid, (float(pose[0]), float(pose[1])))
    for tid in trial_ids:
        for oid in data.trials[tid].object_ids:
            add(oid, None)

    listed = scene_types(fp)
    if "Faucet" in listed:
        for i, s in enumerate(list(found)):
            if s.type == "SinkBasin":
                found.append(
                    _Static(
                        "Faucet",
                        s.pos,
                        f"Faucet@{s.source}",
                        approximate=True,
                        note=f"placed at its sink basin {s.source} (ALFRED never names the faucet)",
                        serves=i,
                    )
                )
    placed = {s.type for s in found}
    unplaced: dict[str, str] = {}
    for typ in listed:
        if typ in placed or typ in movable:
            continue
        estimates = _goto_estimates(fp, typ)
        if not estimates:
            unplaced[typ] = f"no object id, openable pose or GotoLocation for it in {fp}'s trajectories"
            continue
        for (x, z), (ax, az), n in estimates:
            found.append(
                _Static(
                    typ,
                    (x, 0.0, z),
                    f"{typ}~{x:+.2f}|{z:+.2f}",
                    pose=(ax, az),
                    approximate=True,
                    note=f"estimated {GOTO_AHEAD_M} m ahead of {n} ALFRED GotoLocation pose(s) facing it",
                )
            )
    return tuple(found), unplaced


def _goto_estimates(fp: str, typ: str) -> list[tuple[tuple[float, float], tuple[float, float], int]]:
    """Clusters of (estimated x, z), a representative agent pose, and the number of poses."""
    data = alfred_data()
    word = typ.lower()
    clusters: list[list[tuple[float, float, float, float]]] = []
    for tid in data.by_floor_plan.get(fp, []):
        for target, ax, az, rot in data.trials[tid].gotos:
            if target != word:
                continue
            x = ax + GOTO_AHEAD_M * math.sin(math.radians(rot))
            z = az + GOTO_AHEAD_M * math.cos(math.radians(rot))
            for cl in clusters:
                cx = sum(p[0] for p in cl) / len(cl)
                cz = sum(p[1] for p in cl) / len(cl)
                if math.hypot(cx - x, cz - z) < GOTO_MERGE_M:
                    cl.append((x, z, ax, az))
                    break
            else:
                clusters.append([(x, z, ax, az)])
    out = []
    for cl in clusters:
        cx = round(sum(p[0] for p in cl) / len(cl), 3)
        cz = round(sum(p[1] for p in cl) / len(cl), 3)
        out.append(((cx, cz), (cl[0][2], cl[0][3]), len(cl)))
    return out


def merged_poses(trials: list[str]) -> list[tuple[str, float, float, float]]:
    """Object poses of several trials merged (see the module docstring): all poses in trial order;
    a name at the same place (within 1 cm) in an earlier trial is that same object, not a copy."""
    data = alfred_data()
    out: list[tuple[str, float, float, float]] = []
    for k, tid in enumerate(trials):
        earlier = out[:]
        for pose in data.trials[tid].poses:
            if k and any(p[0] == pose[0] and math.dist(p[1:], pose[1:]) < SAME_POSE_M for p in earlier):
                continue
            out.append(pose)
    return out


def default_trial(fp: str) -> str:
    """The floor plan's first trial with object poses that no exclusion names (FloorPlan229's first
    is an excluded train trial)."""
    data, banned = alfred_data(), excluded_trials()
    for tid in data.by_floor_plan.get(fp, []):
        if data.trials[tid].poses and tid not in banned:
            return tid
    raise WorldError(f"no ALFRED trial with object poses for {fp} outside benchmark/training_exclusions.txt")


def _why_unplaced(fp: str, typ: str) -> str:
    """Why a movable type objects.json lists is not in the world: this world's trials lack it, or no
    admitted trial of the floor plan places one (FloorPlan319's Footstool)."""
    data, banned = alfred_data(), excluded_trials()
    for tid in data.by_floor_plan.get(fp, []):
        if tid not in banned and any(_type_of_name(n) == typ for n, *_ in data.trials[tid].poses):
            return "not in the trials' object_poses"
    return f"no ALFRED trial of {fp} places one in its object_poses"


def unbuilt_reason(fp: str, typ: str) -> str | None:
    """Why a world of the floor plan that lacks `typ` has none though the scene's lists name it (None:
    they do not, or the data places one); WorldError for a name that is no floor plan."""
    if typ not in listed_types(fp):
        return None
    if typ not in scene_types(fp):
        return f"only AI2-THOR 5's scene_info lists it, not ALFRED's {fp}-objects.json"
    static = _statics(fp)[1].get(typ)
    if static is not None or typ not in affordance_table().pickupable:
        return static
    return _why_unplaced(fp, typ)


def instance_counts(fp: str, trials: list[str] | None = None) -> Counter[str]:
    """How many objects of each type `load_floor_plan(fp, trials)` holds, none sliced yet (its static
    objects and the trials' merged movable ones), without building it (a world takes a numpy pass over
    its cells): check 1's counts for a benchmark-style row."""
    statics, _ = _statics(fp)
    poses = merged_poses(list(trials) if trials else [default_trial(fp)])
    return Counter(s.type for s in statics) + Counter(_type_of_name(name) for name, *_ in poses)


def check_trial(fp: str, tid: str) -> None:
    """WorldError naming `tid` where it is no ALFRED trial, or a trial of another floor plan than `fp`."""
    trial = alfred_data().trials.get(tid)
    if trial is None:
        raise WorldError(f"no ALFRED trial {tid!r} in alfred/trials.jsonl.gz")
    if trial.floor_plan != fp:
        raise WorldError(f"trial {tid} is in {trial.floor_plan}, not {fp}")


def load_floor_plan(fp: str, trials: list[str] | None = None) -> World:
    """The world of a floor plan with the movable objects of `trials` (default: its first trial)."""
    _layout_file(fp, "layout.npy")
    data = alfred_data()
    trials = list(trials) if trials else [default_trial(fp)]
    for tid in trials:
        check_trial(fp, tid)
    table = affordance_table()
    statics, cannot_place = _statics(fp)
    unplaced = dict(cannot_place)  # this world's own: the floor plan's (cached) stays as it is
    objects: list[WorldObject] = []
    counters: dict[str, int] = {}

    def new_id(typ: str) -> str:
        k = counters.get(typ, 0)
        counters[typ] = k + 1
        return f"{typ}_{k}"

    static_objs = []
    for s in statics:
        static_objs.append(
            WorldObject(
                id=new_id(s.type),
                type=s.type,
                position=s.pos,
                affordances=table(s.type),
                source=s.source,
                approximate=s.approximate,
                agent_pose=s.pose,
                note=s.note,
            )
        )
    for s, obj in zip(statics, static_objs, strict=True):
        if s.serves is not None:
            obj.serves = static_objs[s.serves].id
    objects.extend(static_objs)

    poses = merged_poses(trials)
    movables = []
    for name, x, y, z in poses:
        typ = _type_of_name(name)
        movables.append(
            WorldObject(id=new_id(typ), type=typ, position=(x, y, z), affordances=table(typ), source=name)
        )
    _infer_parents(static_objs, movables)
    objects.extend(movables)
    for tid in trials:
        for typ, on in data.trials[tid].toggles:
            for obj in objects:
                if obj.type == typ and obj.affordances.toggleable:
                    obj.is_on = on
    listed = set(scene_types(fp))
    present = {o.type for o in objects}
    for typ in sorted(listed - present):
        if typ not in unplaced:
            unplaced[typ] = _why_unplaced(fp, typ)
    objects = add_slices(objects, table)
    notes = []
    extra = sorted(present - listed)
    if extra:
        notes.append(f"types found in the trials but not listed in {fp}-objects.json: {', '.join(extra)}")
    newer = sorted(listed_types(fp) - listed - present)
    if newer:  # not `unplaced`: ALFRED's version of the scene may well not hold them
        notes.append(
            f"types only AI2-THOR 5's scene_info lists (not ALFRED's {fp}-objects.json), absent from this "
            f"world: {', '.join(newer)}"
        )
    return World.create(
        fp,
        _free_xz(fp),
        objects,
        unplaced=dict(unplaced),
        notes=notes,
        kind="alfred",
        plurals=ALFRED_PICK_TWO,
        source_trials=tuple(trials),
    )


def _infer_parents(statics: list[WorldObject], movables: list[WorldObject]) -> None:
    """Nearest accepting receptacle close enough (see PARENT_RADIUS_M); else None."""
    recs = [o for o in statics if o.affordances.receptacle]
    mrecs = [o for o in movables if o.affordances.receptacle]
    for obj in movables:
        best, best_d = None, PARENT_RADIUS_M
        for r in recs:
            if obj.type in r.affordances.accepts:
                d = math.dist(obj.position, r.position)
                if d <= best_d:
                    best, best_d = r, d
        for r in mrecs:
            if r is not obj and obj.type in r.affordances.accepts:
                d = math.dist(obj.position, r.position)
                if d <= MOVABLE_PARENT_RADIUS_M and (best is None or d < best_d):
                    best, best_d = r, d
        obj.parent = best.id if best else None


# ---------------------------------------------------------------- benchmark
def build_benchmark_world(gt: GTInstance | dict) -> World:
    """The world of one benchmark instance: its floor plan with its source trials' movable objects."""
    inst = gt if isinstance(gt, GTInstance) else GTInstance.model_validate(gt)
    data = alfred_data()
    trials = [t for t in inst.source_trials if t in data.trials]
    if len(trials) != len(inst.source_trials):
        missing = sorted(set(inst.source_trials) - set(trials))
        raise DataError(f"{inst.id}: source trials not in alfred/trials.jsonl.gz: {', '.join(missing)}")
    return load_floor_plan(inst.scene, trials or None)


def benchmark_issues(world: World, gt: GTInstance | dict) -> list[str]:
    """What the world cannot provide for the instance's tasks, in the GT `issues` style."""
    inst = gt if isinstance(gt, GTInstance) else GTInstance.model_validate(gt)
    return [issue for task in inst.tasks for issue in task.missing(world)]
