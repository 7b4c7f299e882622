"""The boundary to AI2-THOR: the same plans as controller actions, for users who can run the simulator.

Nothing here imports ai2thor. `scene_setup(world)` gives the floor plan and the `SetObjectPoses`
list that recreates our movable objects; `plan_actions(world, plan)` turns a plan into per-robot,
per-step controller calls (multi-agent: `agentId` = robot index). Moves become `Teleport` to the cell
centre (AI2-THOR's MoveAhead needs headings; teleporting between 4-neighbours replays the same
path). Static objects carry their real ALFRED objectId; a movable one carries its objectName and the
objectId AI2-THOR derives from its start position (`Type|+x.xx|+y.yy|+z.zz`, right for ~80 % of
ALFRED's objects; physics can shift the last digit), so resolve ids against a live scene with
`resolve_object_ids(world, event.metadata["objects"])` (same type, nearest position) and pass the
result as `ids`.
"""

from __future__ import annotations

import math

from nl2hltl2plan.worlds.plan import Plan
from nl2hltl2plan.worlds.world import World

VERB_ACTION = {
    "pickup": "PickupObject",
    "put": "PutObject",
    "open": "OpenObject",
    "close": "CloseObject",
    "toggle_on": "ToggleObjectOn",
    "toggle_off": "ToggleObjectOff",
    "slice": "SliceObject",
}


def _fmt(v: float) -> str:
    return ("+" if v >= 0 else "-") + f"{abs(v):05.2f}"


def estimated_object_id(world: World, oid: str) -> str:
    """AI2-THOR objectId of an object: the ALFRED id for static ones, derived from position otherwise."""
    obj = world.get(oid)
    if obj.slice_of:  # AI2-THOR names slices after their object: 'Apple|...|AppleSliced_1'
        parent = estimated_object_id(world, obj.slice_of)
        return f"{parent}|{obj.type}_{world.get(obj.slice_of).slices.index(oid) + 1}"
    if obj.source and "|" in obj.source and not obj.approximate:
        return obj.source  # a real ALFRED objectId (static objects)
    x, y, z = obj.position
    return f"{obj.type}|{_fmt(x)}|{_fmt(y)}|{_fmt(z)}"


def scene_setup(world: World) -> dict:
    """What to load in AI2-THOR: scene name, grid size and the movable objects' poses."""
    poses = []
    for obj in world.objects.values():
        if obj.pickupable and obj.present and obj.slice_of is None and obj.source and "|" not in obj.source:
            x, y, z = obj.position
            poses.append({"objectName": obj.source, "position": {"x": x, "y": y, "z": z}})
    return {"scene": world.name, "gridSize": 0.25, "SetObjectPoses": poses}


def resolve_object_ids(world: World, thor_objects: list[dict]) -> dict[str, str]:
    """Map our ids to a live scene's objectIds: same objectType, nearest position, each used once."""
    free = [dict(o) for o in thor_objects]
    out: dict[str, str] = {}
    for obj in world.objects.values():
        if not obj.present:
            continue
        same = [o for o in free if o.get("objectType") == obj.type]
        if not same:
            continue
        best = min(
            same,
            key=lambda o: math.dist(
                obj.position, (o["position"]["x"], o["position"]["y"], o["position"]["z"])
            ),
        )
        out[obj.id] = best["objectId"]
        free.remove(best)
    return out


def plan_actions(world: World, plan: Plan, ids: dict[str, str] | None = None) -> dict[int, list[dict]]:
    """Per robot: [{"t", "action", "agentId", ...}] controller calls, waits left out."""
    ids = ids or {}

    def oid(o: str) -> str:
        return ids.get(o) or estimated_object_id(world, o)

    out: dict[int, list[dict]] = {}
    for rp in plan.robots:
        calls = []
        x0, z0 = world.xz((rp.start[0], rp.start[1]))
        calls.append({"t": 0, "action": "Teleport", "agentId": rp.robot, "position": {"x": x0, "z": z0}})
        for s in rp.steps:
            if s.verb == "wait":
                continue
            if s.verb == "move":
                x, z = world.xz(tuple(s.cell))  # type: ignore[arg-type]
                calls.append(
                    {"t": s.t, "action": "Teleport", "agentId": rp.robot, "position": {"x": x, "z": z}}
                )
                continue
            call = {
                "t": s.t,
                "action": VERB_ACTION[s.verb],
                "agentId": rp.robot,
                "objectId": oid(s.objects[-1]),
            }
            if s.verb == "put":  # AI2-THOR 2.x (ALFRED) names the held object too
                call["objectId"] = oid(s.objects[0])
                call["receptacleObjectId"] = oid(s.objects[1])
            calls.append(call)
        out[rp.robot] = calls
    return out
