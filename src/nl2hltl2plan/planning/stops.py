"""Cell-level paths through stops, shared by the root's bounds of `tour.py` and `hands.py`.

A *stop* is an event as a robot's walk sees it: the cells it may be done from (the union of its
candidate regions) and its hand rule. `hand_forest` finds the least summed walk of one path per
robot that together visit every stop: Held & Karp over the subsets of stops, one state per cell
of a stop's cells (the generalised travelling-salesman path), then a split of the stops among the
robots by subsets. With every stop FREE and no orders it is the tour; with carries, the hands.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.node import Node

if TYPE_CHECKING:
    from nl2hltl2plan.planning.heuristic import Heuristic

MAX_CELLS = 160  # a stop with more candidate cells says little (it is near everything): left out
FREE, TAKE, GIVE, EMPTY_TAKE = 0, 1, 2, 3  # a stop's hand rule: none, a carry's pickup or put, a lone pickup


class Stop(NamedTuple):
    """A kept event: the cells it may be done from, its hand rule, and its row (the caller's
    index of the event, for the orders)."""

    cells: np.ndarray
    rule: int
    carry: int  # the carry it belongs to (TAKE, GIVE), else -1
    row: int


def region_cells(h: Heuristic, anchors: Sequence[int]) -> np.ndarray:
    """The cells of the union of `anchors`' regions (sorted)."""
    return np.unique(np.concatenate([h.nav.region_idx[a] for a in anchors]))


def standing_cells(node: Node) -> set[int]:
    """The cells the robots stand on, or may stand on (free stand cells: `node.reach`)."""
    cells = set(node.cell)
    if node.reach is not None:
        cells |= {c for reach in node.reach if reach is not None for c in reach[0]}
    return cells


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
