"""The root's cell-level bound with the hands (`heuristic.py`, beside the tour of `tour.py`): the
robots' walks pass, cell by cell, through the pending events' regions, and a robot holds one object
at a time.

The tour leaves the hands out, so a robot may pick up three objects lying side by side and then
put them away one after another: the walks back from each put to the next object are free. A robot,
though, holds one object at a time: between a pickup and the put of that object (a *carry*) it does
no other pickup and no other put, and it picks nothing up while it holds something. So each robot's
walk is a sequence of cells through one cell of each of its events' regions in which every carry's
pickup is followed, before any other pickup or put, by that carry's put.

The least total walk of paths out of the robots, each obeying the hands and the known orders (a
leaf's events in their order; a leaf's events after those of the leaves it waits for), that
together visit every kept stop, is a lower bound on the walking: Held & Karp (`stops.hand_forest`)
over the subsets of stops with one state per cell of a stop's cells, where a subset may hold at
most one *open* carry (its pickup visited, its put not yet), the hand that subset's path ends with;
then a split among the robots by subsets of whole carries (one robot carries an object from its
pickup to its put).

Which events to keep is free, with one care: a carry is kept whole or dropped whole, or its
pickup is kept alone as a pickup that needs an empty hand and leaves it empty (the robot may put
the object down anywhere: a relaxation), and a put kept alone needs no hand. Dropping events never
lengthens a walk (the cell-level triangle inequality), and a kept subsequence of a plan obeys
these rules, so the bound holds. It keeps the carries that walk farthest first, then the other
events farthest from the robots.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.node import Node
from nl2hltl2plan.planning.relax import PICKUP, PUT, EventRow
from nl2hltl2plan.planning.stops import (
    EMPTY_TAKE,
    FREE,
    GIVE,
    MAX_CELLS,
    TAKE,
    Stop,
    hand_forest,
    region_cells,
    standing_cells,
)

if TYPE_CHECKING:
    from nl2hltl2plan.planning.heuristic import Heuristic

MAX_CARRIES = 6  # carries kept (two stops each)
MAX_FREE = 2  # other stops kept (each doubles the subsets)


def hands_walk(h: Heuristic, node: Node, rows: list[EventRow]) -> int:
    """The least walking of paths out of the robots through the kept stops, one hand each."""
    stops, walks = _stops(h, node, rows)
    if not stops:
        return 0
    start = np.hstack([w for stop in stops if (w := walks[stop.row]) is not None])  # robots x stops' cells
    return hand_forest(h.nav.dm, stops, start, _successors(h, rows, stops))


def _stops(h: Heuristic, node: Node, rows: list[EventRow]) -> tuple[list[Stop], list[np.ndarray | None]]:
    """The kept stops, and per row the robots' walks to its cells (None: a row with no small region)."""
    def cells_of(row: EventRow) -> np.ndarray | None:
        if not row.anchors:
            return None
        cells = region_cells(h, row.anchors)
        return cells if 0 < len(cells) <= MAX_CELLS else None

    cells = [cells_of(row) for row in rows]
    walks = [h.robot_walks_to_cells(node, c) if c is not None else None for c in cells]
    nearest = [int(w.min()) if w is not None else -1 for w in walks]
    if any(w is not None and far >= INF for w, far in zip(walks, nearest, strict=True)):
        return [], walks  # an event no robot reaches: no claim
    carries = []  # (walk to the pickup and on to the put, pickup's row, put's row, their cells)
    for d, row in enumerate(rows):
        p = row.carried
        if row.kind != PUT or p < 0 or rows[p].kind != PICKUP:
            continue
        pick, put = cells[p], cells[d]
        if pick is not None and put is not None:
            carries.append((nearest[p] + int(h.nav.dm[np.ix_(pick, put)].min()), p, d, pick, put))
    carries.sort(key=lambda carry: (-carry[0], carry[1]))  # the carries that force the most walking first
    stops: list[Stop] = []
    in_carry: set[int] = set()
    for c, (_, p, d, pick, put) in enumerate(carries[:MAX_CARRIES]):
        stops += [Stop(pick, TAKE, c, p), Stop(put, GIVE, c, d)]
        in_carry |= {p, d}
    robot_cells = standing_cells(node)
    lone = sorted((i for i in range(len(rows)) if i not in in_carry),
                  key=lambda i: (-nearest[i], i))
    n_carry_stops = len(stops)
    for i in lone:
        here = cells[i]
        if len(stops) - n_carry_stops == MAX_FREE:
            break
        if here is None:
            continue
        row = rows[i]
        taking = row.kind == PICKUP
        as_set = set(here.tolist())
        if not taking and (robot_cells & as_set or any(set(s.cells.tolist()) <= as_set for s in stops)):
            continue  # free: a robot stands in it, or visiting a kept stop visits it
        stops.append(Stop(here, EMPTY_TAKE if taking else FREE, -1, i))
    return stops, walks


def _successors(h: Heuristic, rows: list[EventRow], stops: list[Stop]) -> list[int]:
    """Per stop, the bit set of stops that happen after it (a leaf's order; leaves that wait)."""
    out = []
    for a in stops:
        bits = 0
        for k, b in enumerate(stops):
            ra, rb = rows[a.row], rows[b.row]
            if (ra.leaf == rb.leaf and ra.pos < rb.pos) or h.after[ra.leaf, rb.leaf]:
                bits |= 1 << k
        out.append(bits)
    return out
