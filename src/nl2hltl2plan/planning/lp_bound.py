"""A linear-programming bound on the walking still needed (summed cost): robot walks as flows
through *tiles* of the events' regions, solved by HiGHS (`scipy.optimize.linprog`).

The assignment relaxation (`heuristic.py`) measures every step region to region. A region is every
cell within 1.5 m of its object (up to ~50 cells, 12 cells across), so a robot may, for free, reach
an event at one end of its region and leave it from the other: on a tight cluster of tasks the
region-level walk is a third below the true one. Here each event's candidate cells are cut into
tiles of a few cells, a step costs the fewest steps between the two tiles' cells, and flow is
conserved at every tile: a robot leaves an event from the tile it reached it in. Per pending event:

- one unit of flow enters its tiles (from a robot, a pending event or an optional alternative's
  event, over the predecessor pairs the assignment allows: same forbidden pairs, one hand, order);
- at each of its tiles, what leaves is at most what entered (the last event of a robot has no
  successor);
- each robot and each optional event precedes at most one event, and some event follows a robot or
  an optional event (not every event sits in a cycle).

Every completion's walks give a feasible point: each robot's path of pending events, each event done
from one cell of its regions, and a step between two tiles is at least the fewest steps between
their cells; so the optimum is a lower bound on the walking, and it is never below the assignment
(project the flows onto events: an assignment, with steps no shorter). The LP grows with the tiles
squared, so the tile side grows until each event has at most `MAX_TILES` tiles and the LP is skipped
beyond `MAX_ARCS` arcs; `heuristic.py` calls it where its cost pays (the root, whose bound lifts
every node's).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import networkx as nx
import numpy as np
from scipy.optimize import linprog
from scipy.sparse import csr_array, vstack

from nl2hltl2plan.planning.relax import BIG

if TYPE_CHECKING:
    from nl2hltl2plan.planning.navigation import Navigator

TILE = 3  # tile side in cells (the first try; larger when an event has too many tiles)
MAX_TILES = 10  # tiles per event
MAX_ARCS = 60_000  # beyond this many arcs the LP is not built (it would cost seconds)
CUT_ROUNDS = 6  # rounds of connectivity cuts added and the LP solved again
MAX_CUTS_PER_ROUND = 8


class Tiles:
    """One event's candidate cells, cut into tiles: `cells[k]` the cell indices of tile k."""

    def __init__(self, cells: list[np.ndarray]):
        self.cells = cells
        self.flat = np.concatenate(cells)
        self.starts = np.cumsum([0] + [len(c) for c in cells[:-1]]).astype(np.int64)
        self._field: np.ndarray | None = None

    def field(self, dm: np.ndarray) -> np.ndarray:
        """tiles x cells: the fewest steps from some cell of each tile to every cell."""
        if self._field is None:
            self._field = np.minimum.reduceat(dm[self.flat], self.starts, axis=0)
        return self._field

    def least(self, walk: np.ndarray) -> np.ndarray:
        """Per tile, the least of `walk` (a value per cell of these tiles, in `flat` order)."""
        return np.minimum.reduceat(walk, self.starts)

    def __len__(self) -> int:
        return len(self.cells)


def tiles_of(nav: Navigator, cells: np.ndarray) -> Tiles:
    """The cells cut into square tiles of side TILE (doubled until at most MAX_TILES of them)."""
    xy = np.array([nav.cells[c] for c in cells], dtype=np.int64).reshape(-1, 2)
    side = TILE
    while True:
        keys = (xy[:, 0] // side) * 100_003 + (xy[:, 1] // side)
        uniq, inverse = np.unique(keys, return_inverse=True)
        if len(uniq) <= MAX_TILES:
            return Tiles([cells[inverse == k] for k in range(len(uniq))])
        side *= 2


def tile_flow_bound(dm: np.ndarray, tiles: list[Tiles | None], allowed: np.ndarray,
                    source_walks: list[list[np.ndarray]]) -> int | None:
    """The LP's optimum, rounded up (None when it is too large to build, or not solved).

    dm: cell x cell steps. tiles[i]: event i's tiles (None: an event with no region, which every
    step reaches for free). allowed[i, j]: event j may directly precede event i (n_ev x n_ev).
    source_walks[s][i]: per source s (robots, optional events), the walk to each tile of event i
    (an empty array when s may not precede i)."""
    n_ev = len(tiles)
    sizes = [len(t) if t is not None else 1 for t in tiles]
    start = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    n_nodes = int(start[-1])
    pairs = [(i, j) for i in range(n_ev) for j in range(n_ev) if allowed[i, j]]
    n_arcs = sum(sizes[i] * sizes[j] for i, j in pairs) + sum(
        len(w) for walks in source_walks for w in walks)
    if n_arcs > MAX_ARCS:
        return None
    heads: list[np.ndarray] = []  # per arc block: the tile node it enters
    tails: list[np.ndarray] = []  # the tile node it leaves (-1 - s for source s)
    costs: list[np.ndarray] = []
    for i, j in pairs:
        walk = _tile_steps(dm, tiles[j], tiles[i])
        head = np.repeat(start[i] + np.arange(sizes[i]), sizes[j])
        tail = np.tile(start[j] + np.arange(sizes[j]), sizes[i])
        heads.append(head)
        tails.append(tail)
        costs.append(walk.T.reshape(-1))
    for s, walks in enumerate(source_walks):
        for i, walk in enumerate(walks):
            if len(walk):
                heads.append(start[i] + np.arange(len(walk)))
                tails.append(np.full(len(walk), -1 - s, dtype=np.int64))
                costs.append(np.asarray(walk, dtype=np.int64))
    if not heads:
        return None
    head = np.concatenate(heads)
    tail = np.concatenate(tails)
    cost = np.minimum(np.concatenate(costs), BIG).astype(float)
    n = len(head)
    arc = np.arange(n)
    event_of = np.repeat(np.arange(n_ev), sizes)
    from_source = tail < 0
    # equalities: one unit enters each event's tiles
    a_eq = csr_array((np.ones(n), (event_of[head], arc)), shape=(n_ev, n))
    # inequalities: out - in <= 0 at each tile; each source's out <= 1; -(arcs from sources) <= -1
    inner = ~from_source
    n_src = len(source_walks)
    rows = np.concatenate([tail[inner], head, n_nodes + (-1 - tail[from_source]),
                           np.full(int(from_source.sum()), n_nodes + n_src)])
    cols = np.concatenate([arc[inner], arc, arc[from_source], arc[from_source]])
    vals = np.concatenate([np.ones(int(inner.sum())), -np.ones(n), np.ones(int(from_source.sum())),
                           -np.ones(int(from_source.sum()))])
    a_ub = csr_array((vals, (rows, cols)), shape=(n_nodes + n_src + 1, n))
    b_ub = np.concatenate([np.zeros(n_nodes), np.ones(n_src), [-1.0]])
    tail_event = np.where(from_source, -1, event_of[np.maximum(tail, 0)])
    head_event = event_of[head]
    cuts: list[np.ndarray] = []
    value = None
    for _ in range(CUT_ROUNDS + 1):
        if cuts:
            a_cut = csr_array(-np.array(cuts, dtype=float))
            a_all = vstack([a_ub, a_cut], format="csr")
            b_all = np.concatenate([b_ub, -np.ones(len(cuts))])
        else:
            a_all, b_all = a_ub, b_ub
        res = linprog(cost, A_ub=a_all, b_ub=b_all, A_eq=a_eq, b_eq=np.ones(n_ev), bounds=(0, 1),
                      method="highs")
        if res.status != 0 or res.fun >= BIG:
            return value
        value = int(np.ceil(res.fun - 1e-6))
        found = _violated_cuts(res.x, head_event, tail_event, n_ev)
        if not found:
            break
        cuts += [np.isin(head_event, sorted(events)) & ~np.isin(tail_event, sorted(events))
                 for events in found]
    return value


def _violated_cuts(flow: np.ndarray, head_event: np.ndarray, tail_event: np.ndarray,
                   n_ev: int) -> list[frozenset[int]]:
    """Sets S of events that the flow enters by less than one unit from outside S (every
    completion enters each S: the first of its events some robot reaches has its predecessor
    outside), found as minimum cuts from the sources to each event."""
    graph = nx.DiGraph()
    graph.add_nodes_from(range(-1, n_ev))
    used = flow > 1e-9
    arcs = zip(tail_event[used].tolist(), head_event[used].tolist(), flow[used].tolist(), strict=True)
    for tail, head, amount in arcs:
        if tail != head:
            old = graph.get_edge_data(tail, head, {"capacity": 0.0})["capacity"]
            graph.add_edge(tail, head, capacity=old + amount)
    out: list[frozenset[int]] = []
    for event in range(n_ev):
        if any(event in cut for cut in out):
            continue
        cut_value, (_, sink_side) = nx.minimum_cut(graph, -1, event)
        if cut_value < 1.0 - 1e-6:
            out.append(frozenset(sink_side) - {-1})
        if len(out) >= MAX_CUTS_PER_ROUND:
            break
    return out


def _tile_steps(dm: np.ndarray, a: Tiles | None, b: Tiles | None) -> np.ndarray:
    """len(a) x len(b): the fewest steps from some cell of a tile of `a` to some cell of one of `b`
    (0 when either event has no region)."""
    if a is None or b is None:
        return np.zeros((len(a) if a else 1, len(b) if b else 1), dtype=np.int64)
    return np.minimum.reduceat(a.field(dm)[:, b.flat], b.starts, axis=1)


def tiled_walk(nav: Navigator, near: Callable[[tuple[int, ...]], np.ndarray],
               robot_walks: Callable[[np.ndarray], np.ndarray], anchor_sets: list[tuple[int, ...]],
               optional: list[tuple[int, ...]], cost: np.ndarray) -> int | None:
    """The LP bound for one node's pending events: `anchor_sets` their candidate regions,
    `optional` the optional events' regions, `cost` the assignment's events x (events, optional
    events, robots) matrix, whose forbidden pairs (>= BIG) the LP keeps. `near(anchors)` is the walk
    from the nearest of some regions to every cell, `robot_walks(cells)` robots x cells."""
    n_ev = len(anchor_sets)
    n_pred = n_ev + len(optional)
    tiles: list[Tiles | None] = []
    for anchors in anchor_sets:
        cells = np.unique(np.concatenate([nav.region_idx[a] for a in anchors])) if anchors else None
        tiles.append(tiles_of(nav, cells) if cells is not None and len(cells) else None)
    allowed = cost[:, :n_ev] < BIG
    n_robots = cost.shape[1] - n_pred
    sources: list[list[np.ndarray]] = [[] for _ in range(len(optional) + n_robots)]
    none = np.zeros(0, dtype=np.int64)
    for i, t in enumerate(tiles):
        from_robots = robot_walks(t.flat) if t is not None else None
        for s in range(len(sources)):
            col = n_ev + s
            if cost[i, col] >= BIG:
                sources[s].append(none)
            elif t is None:
                sources[s].append(np.zeros(1, dtype=np.int64))
            elif s < len(optional):
                walk = near(optional[s])[t.flat] if optional[s] else np.zeros(len(t.flat), dtype=np.int64)
                sources[s].append(t.least(walk))
            else:
                assert from_robots is not None
                sources[s].append(t.least(from_robots[s - len(optional)]))
    return tile_flow_bound(nav.dm, tiles, allowed, sources)
