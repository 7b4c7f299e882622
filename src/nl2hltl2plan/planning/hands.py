"""The root's cell-level bound with the hands (`heuristic.py`, beside the tour of `tour.py`): the
robots' walks pass, cell by cell, through the pending events' regions, and a robot holds one object
at a time.

The tour leaves the hands out, so a robot may pick up three objects lying side by side and then
put them away one after another: the walks back from each put to the next object are free. A robot,
though, holds one object at a time: between a pickup and the put of that object (a *carry*) it does
no other pickup and no other put, and it picks nothing up while it holds something. So each robot's
walk is a sequence of cells through one cell of each of its events' regions in which every carry's
pickup is followed, before any other pickup or put, by that carry's put.

The least total walk of paths out of the robots, each obeying the hands and the known orders
(a leaf's events in their order; a leaf's events after those of the leaves it waits for), that
together visit every kept stop, is a lower bound on the walking: Held & Karp over the subsets of
stops with one state per cell of a stop's cells, where a subset may hold at most one *open* carry
(its pickup visited, its put not yet), the hand that subset's path ends with; then a split among
the robots by subsets of whole carries (one robot carries an object from its pickup to its put).

Which events to keep is free, with one care: a carry is kept whole or dropped whole, or its
pickup is kept alone as a pickup that needs an empty hand and leaves it empty (the robot may put
the object down anywhere: a relaxation), and a put kept alone needs no hand. Dropping events never
lengthens a walk (the cell-level triangle inequality), and a kept subsequence of a plan obeys
these rules, so the bound holds. It keeps the carries that walk farthest first, then the other
events farthest from the robots.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.node import Node
from nl2hltl2plan.planning.relax import PICKUP, PUT, EventRow
from nl2hltl2plan.planning.tour import MAX_CELLS, region_cells, standing_cells

if TYPE_CHECKING:
    from nl2hltl2plan.planning.heuristic import Heuristic

MAX_CARRIES = 6  # carries kept (two stops each)
MAX_FREE = 2  # other stops kept (each doubles the subsets)
FREE, TAKE, GIVE, EMPTY_TAKE = 0, 1, 2, 3  # a stop's hand rule: none, a carry's pickup or put, a lone pickup


class Stop(NamedTuple):
    """A kept event: the cells it may be done from, its hand rule, and its row (for the orders)."""

    cells: np.ndarray
    rule: int
    carry: int  # the carry it belongs to (TAKE, GIVE), else -1
    row: int


def hands_walk(h: Heuristic, node: Node, rows: list[EventRow]) -> int:
    """The least walking of paths out of the robots through the kept stops, one hand each."""
    stops = _stops(h, node, rows)
    if not stops:
        return 0
    start = h.robot_walks_to_cells(node, np.concatenate([stop.cells for stop in stops]))
    return hand_forest(h.nav.dm, stops, start, _successors(h, rows, stops))


def _stops(h: Heuristic, node: Node, rows: list[EventRow]) -> list[Stop]:
    def cells_of(row: EventRow) -> np.ndarray | None:
        if not row.anchors:
            return None
        cells = region_cells(h, row.anchors)
        return cells if 0 < len(cells) <= MAX_CELLS else None

    cells = [cells_of(row) for row in rows]
    nearest = [int(h.robot_walks_to_cells(node, c).min()) if c is not None else -1 for c in cells]
    if any(c is not None and far >= INF for c, far in zip(cells, nearest, strict=True)):
        return []  # an event no robot reaches: no claim
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
    return stops


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


def hand_forest(dm: np.ndarray, stops: list[Stop], start: np.ndarray, succ: list[int]) -> int:
    """Least summed walk of one path per robot (possibly empty), each with one hand and in the
    orders `succ` (per stop, the stops that must come after it on a path that holds both), that
    together visit every stop. `start`: robots x (the stops' cells, concatenated)."""
    n = len(stops)
    offsets = np.cumsum([0] + [len(stop.cells) for stop in stops])
    n_carry = max((stop.carry for stop in stops), default=-1) + 1
    take = [0] * n_carry
    give = [0] * n_carry
    for k, stop in enumerate(stops):
        if stop.rule == TAKE:
            take[stop.carry] = 1 << k
        elif stop.rule == GIVE:
            give[stop.carry] = 1 << k
    steps: dict[tuple[int, int], np.ndarray] = {}
    # end[mask][j]: robots x cells of stop j, the least walk through the stops of mask ending there
    end: list[dict[int, np.ndarray]] = [{} for _ in range(1 << n)]
    for j, stop in enumerate(stops):
        if stop.rule != GIVE:
            end[1 << j][j] = start[:, offsets[j]:offsets[j + 1]]
    best = np.full((len(start), 1 << n), INF, dtype=np.int64)  # robot x mask: one closed path
    best[:, 0] = 0
    for mask in range(1, 1 << n):
        if not end[mask]:
            continue
        held = next((c for c in range(n_carry) if mask & take[c] and not mask & give[c]), -1)
        if held < 0:
            best[:, mask] = np.min([walk.min(axis=1) for walk in end[mask].values()], axis=0)
        nexts = [k for k in range(n) if not mask >> k & 1 and not succ[k] & mask
                 and _hand_allows(stops[k], held)]
        for j, walk in end[mask].items():
            for k in nexts:
                step = steps.get((j, k))
                if step is None:
                    step = steps[(j, k)] = dm[np.ix_(stops[j].cells, stops[k].cells)]
                nxt = (walk[:, :, None] + step[None, :, :]).min(axis=1)
                grown = mask | 1 << k
                old = end[grown].get(k)
                end[grown][k] = nxt if old is None else np.minimum(old, nxt)
    return _split(best, stops, take, give)


def _hand_allows(stop: Stop, held: int) -> bool:
    """May a robot whose hand holds carry `held` (-1: empty) do `stop` next?"""
    if stop.rule == GIVE:
        return stop.carry == held
    if stop.rule in (TAKE, EMPTY_TAKE):
        return held < 0
    return True


def _split(best: np.ndarray, stops: list[Stop], take: list[int], give: list[int]) -> int:
    """Share the stops among the robots by whole units (a carry's two stops, or a lone stop)."""
    units = [take[c] | give[c] for c in range(len(take))]
    units += [1 << k for k, stop in enumerate(stops) if stop.carry < 0]
    u = len(units)
    as_mask = [0] * (1 << u)
    for sub in range(1, 1 << u):
        low = sub & -sub
        as_mask[sub] = as_mask[sub ^ low] | units[low.bit_length() - 1]
    paths = np.minimum(best[:, as_mask], INF)  # robot x unit subset
    # every (whole, part) pair of unit subsets with part inside whole, grouped by whole
    whole = np.repeat(np.arange(1 << u), [1 << bin(w).count("1") for w in range(1 << u)])
    part = np.concatenate([_submasks(w) for w in range(1 << u)])
    groups = np.searchsorted(whole, np.arange(1 << u))
    cover = paths[0]
    for r in range(1, len(best)):
        cover = np.minimum.reduceat(cover[whole ^ part] + paths[r, part], groups)
    full = cover[(1 << u) - 1]
    return int(full) if full < INF else 0


def _submasks(whole: int) -> np.ndarray:
    """Every subset of the bit set `whole` (itself and the empty one included)."""
    out = [whole]
    sub = whole
    while sub:
        sub = (sub - 1) & whole
        out.append(sub)
    return np.array(out, dtype=np.int64)
