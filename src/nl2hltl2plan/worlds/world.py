"""The world model: a 0.25 m grid of free cells plus AI2-THOR-typed objects.

A `World` is static: it holds what never changes during an execution (grid, objects, their
affordances, where each object can be acted on, the initial state flags). The simulator keeps the
changing state (who holds what, what is open/on/clean/hot/cold, where moved objects went) itself.

Conventions:
- a cell is `(row, col)`; `col` grows with x, `row` grows with z; cell (0, 0) is the free cell grid's
  (min x, min z) corner; `World.xz(cell)` is the cell centre in metres.
- object ids are `Type_k` with k counted per type from 0 (`Apple_0`, `Apple_1`, `Fridge_0`).
- the interaction region of an object: every free cell whose centre lies within the 1.5 m AI2-THOR
  visibility distance (horizontal) of the object's (x, z), nearest first; an object with an ALFRED
  agent pose (openables) gets that pose's cell first. Objects whose region is empty are listed in
  `World.unreachable`.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, field, fields
from functools import cached_property

import numpy as np

from nl2hltl2plan.errors import WorldError

CELL_M = 0.25
VISIBILITY_M = 1.5
N_SLICES = 3  # slices created by `slice`: enough for place_two on slices, small for planners

Cell = tuple[int, int]

# AI2-THOR turns an Egg into one EggCracked; other sliceables into several `TypeSliced` pieces.
SLICED_TYPE = {"Egg": "EggCracked"}
KNIFE_TYPES = ("Knife", "ButterKnife")


def sliced_type(base: str) -> str:
    """The AI2-THOR type of the pieces `slice` makes of a `base` object (Apple -> AppleSliced)."""
    return SLICED_TYPE.get(base, base + "Sliced")


@dataclass(frozen=True)
class Affordances:
    """What can be done with an object type (AI2-THOR / ALFRED facts)."""

    pickupable: bool = False
    receptacle: bool = False
    accepts: frozenset[str] = frozenset()
    openable: bool = False
    toggleable: bool = False
    sliceable: bool = False
    heatable: bool = False
    coolable: bool = False
    cleanable: bool = False

    def names(self) -> list[str]:
        """The true flags by name (for summaries), e.g. ['pickupable', 'heatable']."""
        return [f.name for f in fields(self) if f.name != "accepts" and getattr(self, f.name)]


@dataclass
class WorldObject:
    """One object instance. `position` is AI2-THOR's (x, y, z) in metres (y up)."""

    id: str
    type: str
    position: tuple[float, float, float]
    affordances: Affordances
    interaction_cells: tuple[Cell, ...] = ()
    parent: str | None = None  # receptacle it starts in/on (None: unknown or free-standing)
    is_open: bool = False
    is_on: bool = False
    present: bool = True  # False for slices until their object is sliced
    slice_of: str | None = None  # for a slice: the object it comes from
    slices: tuple[str, ...] = ()  # for a sliceable object: the ids its slices get
    serves: str | None = None  # for a Faucet: the SinkBasin it fills
    source: str | None = None  # AI2-THOR objectId / objectName, for executing in the simulator
    approximate: bool = False  # position estimated (see `note`), not read from an id
    agent_pose: tuple[float, float] | None = None  # ALFRED pose (x, z) from which it is opened
    note: str = ""

    @property
    def xz(self) -> tuple[float, float]:
        return (self.position[0], self.position[2])

    @property
    def pickupable(self) -> bool:
        return self.affordances.pickupable

    def to_dict(self) -> dict:
        return {
            "id": self.id,
            "type": self.type,
            "position": [round(v, 3) for v in self.position],
            "affordances": self.affordances.names(),
            "accepts": sorted(self.affordances.accepts),
            "interaction_cells": [list(c) for c in self.interaction_cells],
            "parent": self.parent,
            "is_open": self.is_open,
            "is_on": self.is_on,
            "present": self.present,
            "slice_of": self.slice_of,
            "slices": list(self.slices),
            "serves": self.serves,
            "source": self.source,
            "approximate": self.approximate,
            "note": self.note,
        }


@dataclass(frozen=True)
class PluralConvention:
    """What a plural with no number ("the forks") means in a world that holds more of the type than a
    task takes (docs/worlds.md, "Plurals"): read as the task's count (two) under this convention's name,
    said in the result's `assumptions`. `always`: read so whatever the `plurals` setting (the demo
    kitchen, built to show the paper's Example 1); else only under `plurals="two"`. `categories`: a
    category plural ("the utensils": two of any kind) takes it too; else it is refused."""

    name: str
    always: bool = False
    categories: bool = False


# ALFRED's pick-two task: two things of a type, read from "the forks" only when the user asks for it
ALFRED_PICK_TWO = PluralConvention("ALFRED's pick-two")


@dataclass
class World:
    """A grid world with objects. Build it with `World.create(...)` (computes the regions)."""

    name: str
    origin: tuple[float, float]  # (x, z) of cell (0, 0)'s centre
    shape: tuple[int, int]  # (rows, cols)
    cells: list[Cell]  # free cells, sorted
    objects: dict[str, WorldObject]
    unplaced: dict[str, str] = field(default_factory=dict)  # type -> why it has no instance
    notes: list[str] = field(default_factory=list)
    kind: str = "alfred"  # "alfred" | "demo"
    source_trials: tuple[str, ...] = ()
    default_starts: tuple[Cell, ...] = ()
    plurals: PluralConvention | None = None  # what "the forks" of more than a task takes means (None: ask)

    # ---------------------------------------------------------------- construction
    @classmethod
    def create(
        cls,
        name: str,
        free_xz: Iterable[tuple[float, float]],
        objects: Iterable[WorldObject],
        **kwargs,
    ) -> World:
        """Grid from free (x, z) positions (multiples of 0.25 m) and objects; regions computed here."""
        pts = np.asarray(list(free_xz), dtype=float).reshape(-1, 2)
        if len(pts) == 0:
            raise WorldError(f"world {name!r} has no free cells")
        ij = np.round(pts / CELL_M).astype(int)
        lo = ij.min(axis=0)
        cols, rows = (ij - lo).T
        cells = sorted({(int(r), int(c)) for r, c in zip(rows, cols, strict=True)})
        shape = (int(rows.max()) + 1, int(cols.max()) + 1)
        origin = (float(lo[0] * CELL_M), float(lo[1] * CELL_M))
        world = cls(name=name, origin=origin, shape=shape, cells=cells, objects={}, **kwargs)
        for obj in objects:
            if obj.id in world.objects:
                raise WorldError(f"duplicate object id {obj.id} in world {name!r}")
            world.objects[obj.id] = obj
        todo = [obj for obj in world.objects.values() if not obj.interaction_cells]
        for obj, region in zip(todo, world._regions([o.xz for o in todo], [o.agent_pose for o in todo]),
                               strict=True):
            obj.interaction_cells = region
        # slices act where their object is: same region
        for obj in world.objects.values():
            if obj.slice_of:
                obj.interaction_cells = world.objects[obj.slice_of].interaction_cells
        return world

    # ---------------------------------------------------------------- grid
    @cached_property
    def free(self) -> np.ndarray:
        grid = np.zeros(self.shape, dtype=bool)
        rows, cols = zip(*self.cells, strict=True)
        grid[list(rows), list(cols)] = True
        return grid

    @cached_property
    def cell_set(self) -> frozenset[Cell]:
        return frozenset(self.cells)

    @cached_property
    def _centres(self) -> np.ndarray:
        return np.array([self.xz(c) for c in self.cells], dtype=float)

    def xz(self, cell: Cell) -> tuple[float, float]:
        """Centre (x, z) in metres of a cell."""
        return (self.origin[0] + cell[1] * CELL_M, self.origin[1] + cell[0] * CELL_M)

    def cell_of(self, x: float, z: float, main: bool = False) -> Cell:
        """The free cell nearest to (x, z) metres (ties: smallest (row, col)); with `main`, the
        nearest cell of the largest connected component (robot starts: not stranded on an island)."""
        d2 = ((self._centres - (x, z)) ** 2).sum(axis=1)
        if main and len(self.components) > 1:
            d2 = np.where(self._in_main, d2, np.inf)
        return self.cells[int(np.argmin(d2))]

    @cached_property
    def _in_main(self) -> np.ndarray:
        main = self.components[0]
        return np.array([c in main for c in self.cells])

    def neighbours(self, cell: Cell) -> list[Cell]:
        """Free 4-neighbours of a cell, in a fixed order (up, down, left, right in row/col)."""
        r, c = cell
        free = self.cell_set
        return [n for n in ((r - 1, c), (r + 1, c), (r, c - 1), (r, c + 1)) if n in free]

    def region_of(self, xz: tuple[float, float], pose: tuple[float, float] | None = None) -> tuple[Cell, ...]:
        """Free cells within the visibility distance of (x, z), nearest first; `pose`'s cell first."""
        d2 = ((self._centres - xz) ** 2).sum(axis=1)
        near = np.flatnonzero(d2 <= VISIBILITY_M**2 + 1e-9)
        order = near[np.lexsort((near, d2[near]))]
        region = [self.cells[i] for i in order]
        if pose is not None:
            first = self.cell_of(*pose)
            region = [first] + [c for c in region if c != first]
        return tuple(region)

    def _regions(
        self, points: list[tuple[float, float]], poses: list[tuple[float, float] | None]
    ) -> list[tuple[Cell, ...]]:
        """`region_of` for many points at once (one numpy pass over the cells for all of them; a floor
        plan's hundred objects took a hundred passes): the same regions, in the same order."""
        if not points:
            return []
        d2 = ((self._centres[None, :, :] - np.asarray(points, dtype=float)[:, None, :]) ** 2).sum(axis=2)
        rows, near = np.nonzero(d2 <= VISIBILITY_M**2 + 1e-9)
        # per point: nearest first, ties by cell index (as region_of's lexsort)
        order = np.lexsort((near, d2[rows, near], rows))
        rows, near = rows[order], near[order]
        bounds = np.searchsorted(rows, np.arange(len(points) + 1))
        cells = self.cells
        out = []
        for k, pose in enumerate(poses):
            region = [cells[i] for i in near[bounds[k] : bounds[k + 1]].tolist()]
            if pose is not None:
                first = self.cell_of(*pose)
                region = [first] + [c for c in region if c != first]
            out.append(tuple(region))
        return out

    @cached_property
    def _bfs_cache(self) -> dict[Cell, dict[Cell, int]]:
        return {}

    def distances_from(self, cell: Cell) -> dict[Cell, int]:
        """BFS step counts from `cell` to every free cell reachable from it (cached)."""
        cached = self._bfs_cache.get(cell)
        if cached is not None:
            return cached
        if cell not in self.cell_set:
            raise WorldError(f"cell {cell} is not a free cell of {self.name}")
        dist = {cell: 0}
        queue = deque([cell])
        while queue:
            cur = queue.popleft()
            d = dist[cur] + 1
            for n in self.neighbours(cur):
                if n not in dist:
                    dist[n] = d
                    queue.append(n)
        self._bfs_cache[cell] = dist
        return dist

    def distance(self, a: Cell, b: Cell) -> int | None:
        """Steps between two free cells, None if not connected."""
        return self.distances_from(b).get(a)

    def path(self, a: Cell, b: Cell) -> list[Cell]:
        """A shortest 4-neighbour path from a to b, both included; WorldError if not connected."""
        dist = self.distances_from(b)
        if a not in dist:
            raise WorldError(f"no path from {a} to {b} in {self.name}")
        path = [a]
        cur = a
        while cur != b:
            cur = next(n for n in self.neighbours(cur) if dist.get(n) == dist[cur] - 1)
            path.append(cur)
        return path

    @cached_property
    def cell_index(self) -> dict[Cell, int]:
        return {c: i for i, c in enumerate(self.cells)}

    @cached_property
    def distance_matrix(self) -> np.ndarray:
        """All-pairs BFS steps between free cells (indexed like `cells`); -1 where not connected."""
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import shortest_path

        idx = self.cell_index
        rows, cols = [], []
        for c, i in idx.items():
            for n in self.neighbours(c):
                rows.append(i)
                cols.append(idx[n])
        size = len(self.cells)
        graph = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(size, size)).tocsr()
        dm = shortest_path(graph, method="D", unweighted=True)
        dm[np.isinf(dm)] = -1
        return dm.astype(int)

    @cached_property
    def components(self) -> list[set[Cell]]:
        """Connected components of the free cells, largest first."""
        seen: set[Cell] = set()
        comps = []
        for c in self.cells:
            if c not in seen:
                comp = set(self.distances_from(c))
                seen |= comp
                comps.append(comp)
        return sorted(comps, key=len, reverse=True)

    # ---------------------------------------------------------------- objects
    @cached_property
    def ids(self) -> list[str]:
        return list(self.objects)

    @cached_property
    def index(self) -> dict[str, int]:
        return {oid: i for i, oid in enumerate(self.objects)}

    def object_types(self) -> set[str]:
        """Types of all objects, including slice types an object can be cut into."""
        return {o.type for o in self.objects.values()}

    def instances(self, type_: str) -> list[WorldObject]:
        """Objects of one type, in id order (slices included, with present=False)."""
        return [o for o in self.objects.values() if o.type == type_]

    def get(self, oid: str) -> WorldObject:
        try:
            return self.objects[oid]
        except KeyError:
            raise WorldError(f"no object {oid!r} in world {self.name}") from None

    @property
    def unreachable(self) -> list[str]:
        """Ids of objects no free cell reaches (empty interaction region)."""
        return [o.id for o in self.objects.values() if not o.interaction_cells]

    def ancestors(self, oid: str) -> list[str]:
        """Initial parent chain of an object (nearest first)."""
        chain = []
        cur = self.objects[oid].parent
        while cur is not None and cur not in chain:
            chain.append(cur)
            cur = self.objects[cur].parent
        return chain

    def closed_ancestor(self, oid: str) -> str | None:
        """The nearest initially closed openable the object sits in, if any."""
        for a in self.ancestors(oid):
            obj = self.objects[a]
            if obj.affordances.openable and not obj.is_open:
                return a
        return None

    def types_accepting(self, type_: str) -> set[str]:
        """Receptacle types in this world that accept `type_`."""
        return {o.type for o in self.objects.values() if type_ in o.affordances.accepts and o.present}

    def summary(self) -> dict:
        """Grid size, free cells and object counts by type (what `nl2hltl2plan world` prints)."""
        by_type: dict[str, int] = {}
        for o in self.objects.values():
            if o.present:
                by_type[o.type] = by_type.get(o.type, 0) + 1
        return {
            "name": self.name,
            "kind": self.kind,
            "plurals": self.plurals.name if self.plurals else None,
            "grid": {"rows": self.shape[0], "cols": self.shape[1], "cell_m": CELL_M},
            "origin_xz": list(self.origin),
            "free_cells": len(self.cells),
            "components": [len(c) for c in self.components],
            "objects": sum(by_type.values()),
            "objects_by_type": dict(sorted(by_type.items())),
            "slice_types": sorted({o.type for o in self.objects.values() if o.slice_of}),
            "approximate": sorted(o.id for o in self.objects.values() if o.approximate),
            "unreachable": self.unreachable,
            "unplaced": dict(sorted(self.unplaced.items())),
            "source_trials": list(self.source_trials),
            "notes": list(self.notes),
        }


def add_slices(objects: list[WorldObject], affordances_of, n: int = N_SLICES) -> list[WorldObject]:
    """Append the (not yet present) slices of every sliceable object; ids numbered per slice type."""
    counters: dict[str, int] = {}
    out = list(objects)
    for obj in objects:
        if not obj.affordances.sliceable:
            continue
        stype = sliced_type(obj.type)
        count = 1 if stype == "EggCracked" else n
        ids = []
        for _ in range(count):
            k = counters.get(stype, 0)
            counters[stype] = k + 1
            sid = f"{stype}_{k}"
            ids.append(sid)
            out.append(
                WorldObject(
                    id=sid,
                    type=stype,
                    position=obj.position,
                    affordances=affordances_of(stype),
                    parent=obj.parent,
                    present=False,
                    slice_of=obj.id,
                    source=f"{obj.source}|{stype}_{len(ids)}" if obj.source else None,
                )
            )
        obj.slices = tuple(ids)
    return out
