"""Small worlds (helpers for tests/planning) whose optimal plans can be worked out by hand.

The corridor: one row of 40 free cells (0.25 m each, x = col * 0.25, z = 0). An object at column c
can be acted on from columns c-6 .. c+6 (1.5 m), so walking to it from column s costs
max(0, c - 6 - s, s - (c + 6)) steps. An island of 3 cells at columns 50..52 is unreachable.
"""

from __future__ import annotations

from nl2hltl2plan.worlds.tasks import BaseTask, GTInstance
from nl2hltl2plan.worlds.world import Affordances, World, WorldObject

MOVABLE = ("Apple", "Mug", "Book")
ACCEPTS = {
    "CounterTop": MOVABLE,
    "DiningTable": MOVABLE,
    "Fridge": ("Apple", "Mug"),
    "SinkBasin": ("Apple", "Mug"),
    "Shelf": ("Book",),
}


def affordances(type_: str) -> Affordances:
    return Affordances(
        pickupable=type_ in MOVABLE,
        receptacle=type_ in ACCEPTS,
        accepts=frozenset(ACCEPTS.get(type_, ())),
        openable=type_ == "Fridge",
        toggleable=type_ in ("Faucet", "DeskLamp"),
        cleanable=type_ in ("Apple", "Mug"),
        coolable=type_ in ("Apple", "Mug"),
    )


def corridor(objects: dict[str, int], parents: dict[str, str] | None = None,
             island: dict[str, int] | None = None,
             length: int = 40) -> World:
    """A corridor world with objects at the given columns (ids like Apple_0)."""
    free = [(c * 0.25, 0.0) for c in range(length)] + [(c * 0.25, 0.0) for c in range(50, 53)]
    objs = []
    for oid, col in {**objects, **(island or {})}.items():
        type_ = oid.rsplit("_", 1)[0]
        objs.append(WorldObject(
            id=oid, type=type_, position=(col * 0.25, 0.9, 0.0), affordances=affordances(type_),
            parent=(parents or {}).get(oid), serves="SinkBasin_0" if type_ == "Faucet" else None,
        ))
    return World.create("corridor", free, objs, kind="demo")


def gt(tasks: list[dict], before: list[tuple[str, str]] = ()) -> GTInstance:
    return GTInstance(id="test", scene="corridor", tasks=[BaseTask(**t) for t in tasks], before=list(before))


def two_rows() -> World:
    """Two corridors of 31 cells (rows 0 and 10, 2.5 m apart) joined at column 30 by a vertical
    corridor. Apple_0 between the rows at column 15 (region: columns 12..18 of both rows),
    CounterTop_0 above row 10 at column 2 (region: row 10, columns 0..7)."""
    free = ([(c * 0.25, 0.0) for c in range(31)] + [(c * 0.25, 2.5) for c in range(31)]
            + [(30 * 0.25, z * 0.25) for z in range(1, 10)])
    objs = [WorldObject(id="Apple_0", type="Apple", position=(15 * 0.25, 0.9, 5 * 0.25),
                        affordances=affordances("Apple")),
            WorldObject(id="CounterTop_0", type="CounterTop", position=(2 * 0.25, 0.9, 12 * 0.25),
                        affordances=affordances("CounterTop"))]
    return World.create("two_rows", free, objs, kind="demo")
