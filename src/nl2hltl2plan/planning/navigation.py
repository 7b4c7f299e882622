"""Navigation as macro-steps: shortest-path distances to interaction regions, precomputed once.

A robot acts on an object from any cell of the object's current interaction region (its own
region until it is moved, then that of the receptacle holding it: `SimState.region`). The object
whose static region applies is the *anchor*. The planner moves a robot along a shortest path to
the nearest cell of the anchor's region, so a search step never runs a BFS: every distance is read
from the all-pairs matrix (`World.distance_matrix`) or from a per-anchor distance field.
"""

from __future__ import annotations

import numpy as np

from nl2hltl2plan.worlds.simulator import SimState
from nl2hltl2plan.worlds.world import Cell, World

INF = 1 << 30


class Navigator:
    def __init__(self, world: World):
        self.world = world
        self.cells = world.cells
        self.cell_index = world.cell_index
        dm = world.distance_matrix.astype(np.int64)
        dm[dm < 0] = INF
        self.dm = dm
        self.ids = world.ids
        self.obj_index = world.index
        self.region_idx = [
            np.array([self.cell_index[c] for c in o.interaction_cells], dtype=np.int64)
            for o in world.objects.values()
        ]
        self._field: dict[int, np.ndarray] = {}
        self._field_list: dict[int, list[int]] = {}
        self._nearest: dict[tuple[int, int], tuple[int, int]] = {}
        self._rr: dict[tuple[int, int], int] = {}

    # ------------------------------------------------------------ anchors
    @staticmethod
    def anchor(sim: SimState, obj: int) -> int:
        """Index of the object whose static region one must stand in to act on `obj` now; -1 when
        nobody can (held by a robot). Mirrors `SimState.region`."""
        x = obj
        parent, holder, moved = sim.parent, sim.holder, sim.moved
        while x >= 0:
            if holder[x] >= 0:
                return -1
            if not moved[x] or parent[x] < 0:
                return x
            x = parent[x]
        return -1

    # ------------------------------------------------------------ distances
    def field(self, anchor: int) -> list[int]:
        """Steps from every cell (by cell index) to the nearest cell of the anchor's region."""
        f = self._field_list.get(anchor)
        if f is None:
            region = self.region_idx[anchor]
            arr = self.dm[:, region].min(axis=1) if len(region) else np.full(len(self.cells), INF)
            self._field[anchor] = arr
            f = self._field_list[anchor] = arr.tolist()
        return f

    def dist(self, cell: int, anchor: int) -> int:
        return self.field(anchor)[cell]

    def nearest(self, cell: int, anchor: int) -> tuple[int, int]:
        """(stand cell index, steps): the region cell nearest to `cell`, ties in region order."""
        key = (cell, anchor)
        hit = self._nearest.get(key)
        if hit is None:
            region = self.region_idx[anchor]
            if not len(region):
                hit = (-1, INF)
            else:
                row = self.dm[cell, region]
                k = int(np.argmin(row))
                hit = (int(region[k]), int(row[k]))
            self._nearest[key] = hit
        return hit

    def rr(self, a: int, b: int) -> int:
        """Fewest steps from some cell of a's region to b's region (0 when they overlap)."""
        key = (a, b) if a <= b else (b, a)
        hit = self._rr.get(key)
        if hit is None:
            ra = self.region_idx[a]
            if not len(ra) or not len(self.region_idx[b]):
                hit = INF
            else:
                self.field(b)
                hit = int(self._field[b][ra].min())
            self._rr[key] = hit
        return hit

    def cell(self, index: int) -> Cell:
        return self.cells[index]
