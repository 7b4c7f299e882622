"""The root's cell-level bounds on the walking of the summed cost (`heuristic.py`): the tour (the
robots' walks, cell by cell, pass through every pending event's region) and the chain (events that
must happen one after another, walked in that order).

The other relaxations measure walks region to region (the least distance between any cell of one
region and any cell of the next). Regions are large (every cell within 1.5 m of the object), so
that distance is no metric: a step may enter a region at one end and leave it from the other for
free, and a chain of overlapping regions crosses a room at almost no cost (FloorPlan224, valid_seen:
the sofa is 28 steps from the robot, yet region to region the robot reaches it in 5, through a
newspaper's, a box's and a dresser's overlapping regions). A robot, though, stands on one cell at a
time, and cell distances obey the triangle inequality.

So: each robot's walk is a sequence of cells that visits, for every pending event, one cell of one
of the event's candidate regions (the cell it acts from). Keeping only a few of these "stops"
(events dropped from a walk never make it longer), the least total walk of paths out of the robots
that visit every kept stop is a lower bound, computed exactly (`stops.hand_forest`, with no hands
and no orders) by dynamic programming over the subsets of stops (Held & Karp, with one state per
cell of the stop's cell set; the generalised travelling-salesman path), its paths then split among
the robots by a second dynamic programme over subsets (each robot's path starts where that robot
stands; a robot may stay put). Which stops to keep is free; it keeps the few whose cells are
farthest from every robot (the ones that force walking), after merging stops with the same cell set
and dropping a stop whose cells include a robot's cell or another kept stop's cells (visiting that
one visits it too).

The tour ignores the events' order, the hands and the instance choices across leaves (a stop may
be any candidate's cell); the chain (`chain_walk`) adds the order, `hands.py` the hands. All three
are cheap enough at the root (`Heuristic._evaluate`: once, not per node), and they lift every
node's bound (a child's bound is at least its parent's).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.node import Node
from nl2hltl2plan.planning.relax import BIG, EventRow, solve
from nl2hltl2plan.planning.stops import FREE, MAX_CELLS, Stop, hand_forest, region_cells, standing_cells

if TYPE_CHECKING:
    from nl2hltl2plan.planning.heuristic import Heuristic

MAX_STOPS = 7  # stops kept (the programme has 2^stops subsets)


def tour_walk(h: Heuristic, node: Node, rows: list[EventRow]) -> int:
    """The least walking of paths out of the robots through one cell of each kept stop."""
    kept = _stops(h, node, rows)
    if not kept:
        return 0
    start = np.hstack([walks for _, walks in kept])  # robots x the stops' cells
    return _forest(h.nav.dm, [cells for cells, _ in kept], start)


def _stops(h: Heuristic, node: Node, rows: list[EventRow]) -> list[tuple[np.ndarray, np.ndarray]]:
    """The stops kept: distinct, small, not holding a robot, farthest first; each as its cells and
    the robots' walks to them (robots x cells)."""
    by_anchors: dict[tuple[int, ...], np.ndarray] = {}
    for row in rows:
        if row.anchors and row.anchors not in by_anchors:
            by_anchors[row.anchors] = region_cells(h, row.anchors)
    robot_cells = standing_cells(node)
    scored = []
    for anchors, cells in sorted(by_anchors.items()):
        if not len(cells) or len(cells) > MAX_CELLS or robot_cells & set(cells.tolist()):
            continue
        walks = h.robot_walks_to_cells(node, cells)
        far = int(walks.min())
        if far >= INF:
            return []  # a stop no robot reaches: no claim
        scored.append((-far, anchors, cells, walks))
    scored.sort(key=lambda item: (item[0], item[1]))
    kept: list[tuple[np.ndarray, np.ndarray]] = []
    for _, _, cells, walks in scored:
        if len(kept) == MAX_STOPS:
            break
        as_set = set(cells.tolist())
        if any(set(other.tolist()) <= as_set for other, _ in kept):
            continue  # visiting that kept stop visits this one too
        kept.append((cells, walks))
    return kept


def _forest(dm: np.ndarray, stops: list[np.ndarray], start: np.ndarray) -> int:
    """Least summed walk of one path per robot (possibly empty) that together visit every stop:
    `start` robots x (the stops' cells, concatenated); no hands, no orders."""
    free = [Stop(cells, FREE, -1, k) for k, cells in enumerate(stops)]
    return hand_forest(dm, free, start, [0] * len(stops))


def chain_walk(h: Heuristic, node: Node, rows: list[EventRow]) -> int:
    """The robots' walks pass through the pending events in time order, so through any chain of
    them that must happen one after another (a leaf's events in their order; every event of a leaf
    before every event of a leaf ordered after it). The chain taken is the longest one by
    region-to-region steps. One robot walks it, cell by cell (a layered shortest path); several
    robots split it, each walking its part in the chain's order: each chain event follows a robot's
    start or an earlier chain event, each of those precedes at most one, an assignment (no cycle can
    form: predecessors come earlier), walked region to region."""
    events = [i for i, row in enumerate(rows) if row.anchors]
    if not events:
        return 0
    leaf = np.array([rows[i].leaf for i in events])
    pos = np.array([rows[i].pos for i in events])
    # before[a, b]: event a happens before event b
    before = ((leaf[:, None] == leaf[None, :]) & (pos[:, None] < pos[None, :])) | h.after[np.ix_(leaf, leaf)]
    anchors = [list(rows[i].anchors) for i in events]
    columns = [np.array(a)[:, None] for a in anchors]  # (broadcast indexing: np.ix_ costs more per call)
    step = np.array([[int(h.rr[col, b].min()) for b in anchors] for col in columns])
    flat = h.robot_walks(node, np.array([a for ax in anchors for a in ax], dtype=np.int64))
    offsets = np.cumsum([0] + [len(ax) for ax in anchors])
    reach = np.array([flat[offsets[k]:offsets[k + 1]].min(axis=0) for k in range(len(events))])  # x robots
    chain = _longest_chain(before, step, reach.min(axis=1))
    if len(node.cell) > 1:
        return _split_chain(step[np.ix_(chain, chain)], reach[chain])
    cells = [region_cells(h, anchors[k]) for k in chain]
    walk = h.robot_walks_to_cells(node, cells[0])[0]
    for prev, cur in zip(cells, cells[1:], strict=False):
        walk = (walk[:, None] + h.nav.dm[np.ix_(prev, cur)]).min(axis=0)
    return int(walk.min()) if walk.min() < INF else 0


def _longest_chain(before: np.ndarray, step: np.ndarray, reach: np.ndarray) -> list[int]:
    """The events (indices) of the chain of the most region-to-region walking, in time order."""
    order = sorted(range(len(reach)), key=lambda k: (int(before[:, k].sum()), k))  # topological
    longest = np.minimum(reach, BIG).astype(np.int64)
    back = [-1] * len(reach)
    for k in order:
        for j in order:
            if before[j, k] and longest[j] + step[j, k] > longest[k]:
                longest[k], back[k] = longest[j] + step[j, k], j
    chain = [int(np.argmax(longest))]
    while back[chain[-1]] >= 0:
        chain.append(back[chain[-1]])
    return chain[::-1]


def _split_chain(step: np.ndarray, reach: np.ndarray) -> int:
    """Least walk of robots serving a chain in order: `step` chain x chain, `reach` chain x robots."""
    n = len(step)
    earlier = np.tril(np.ones((n, n), dtype=bool), k=-1)  # [b, a]: a comes before b
    cost = np.hstack([np.where(earlier, step.T, BIG), reach]).astype(np.int64)
    return solve(np.minimum(cost, BIG))
