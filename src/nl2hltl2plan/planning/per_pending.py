"""The parts of the bound's hand rules and approach-and-carry assignment (`heuristic.py`) that depend
on a node's pending work alone (its events and their regions), not on where the robots are: computed
once per pending work and kept in its memo (`heuristic._per_pending`), so a node computes only its
robots' columns."""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from nl2hltl2plan.planning.relax import BIG, PICKUP, PUT, EventRow


class HandMasks(NamedTuple):
    """The hand rules' part that the robots do not change (`Heuristic._hand_rules`)."""

    events: np.ndarray  # events x predecessor events (then optional ones): forbidden pairs
    pickup: np.ndarray  # per event: a pickup (never after a moment the hand stays full)
    need: np.ndarray  # per event: the hand id it needs, -1 any
    robots: dict[tuple[tuple[int, bool], ...], np.ndarray]  # per robots' hands: their part (memo)


def hand_masks(rows: list[EventRow], n_opt: int) -> HandMasks:
    """One hand: a pickup never follows a moment the hand is full until a pending put; an event that
    needs the hand to hold X follows only a moment the hand may hold X (optional events: unknown)."""
    after = np.array([row.after for row in rows] + [-1] * n_opt, dtype=np.int64)
    full = np.array([row.full for row in rows] + [False] * n_opt, dtype=bool)
    pickup = np.array([row.kind == PICKUP for row in rows], dtype=bool)
    need = np.array([row.need for row in rows], dtype=np.int64)
    return HandMasks(_forbidden(pickup, need, after, full), pickup, need, {})


def robot_hand_mask(masks: HandMasks, robots: tuple[tuple[int, bool], ...]) -> np.ndarray:
    """events x robots: the pairs the hand rules forbid, for the robots' hands (per robot: the hand
    id, whether it stays full until a pending put); computed once per such tuple."""
    hit = masks.robots.get(robots)
    if hit is None:
        after = np.array([hand for hand, _ in robots], dtype=np.int64)
        full = np.array([stays for _, stays in robots], dtype=bool)
        hit = masks.robots[robots] = _forbidden(masks.pickup, masks.need, after, full)
    return hit


def _forbidden(pickup: np.ndarray, need: np.ndarray, after: np.ndarray, full: np.ndarray) -> np.ndarray:
    bad = pickup[:, None] & full[None, :]
    bad |= (need >= 0)[:, None] & (after[None, :] != -1) & (after[None, :] != need[:, None])
    return bad


class ApproachLegs(NamedTuple):
    """The pickups' approaches and carries, through one cell of their regions (`approach_legs`)."""

    union: np.ndarray  # the cells the pickups' regions hold (sorted)
    picks: np.ndarray  # the pickups' event rows
    cells: np.ndarray  # their cells (positions in `union`), pickup after pickup
    starts: np.ndarray  # where each pickup's cells start in `cells`
    to_put: np.ndarray  # per cell of `cells`: the walk on to the put's regions (at most BIG)
    from_cols: np.ndarray  # pickups x predecessor events (the template's columns): the least such walk
    held_puts: list[int]  # puts of what a robot holds now: they keep the holder's walk


def approach_legs(rows: list[EventRow], cols: list[tuple[int, ...]], region_idx: list[np.ndarray],
                  near: Callable[[tuple[int, ...]], np.ndarray]) -> ApproachLegs | None:
    """The robot-independent part of `Heuristic._approach_and_carry`; None when no pickup is
    carried (or no cell reaches one)."""
    puts = {row.carried: i for i, row in enumerate(rows)
            if row.kind == PUT and row.carried >= 0 and row.anchors}
    puts = {pick: put for pick, put in puts.items() if rows[pick].kind == PICKUP and rows[pick].anchors}
    cells_of = {pick: np.concatenate([region_idx[a] for a in rows[pick].anchors]) for pick in puts}
    cells_of = {pick: cells for pick, cells in cells_of.items() if len(cells)}  # an instance no cell reaches
    if not cells_of:
        return None
    union = np.unique(np.concatenate(list(cells_of.values())))  # only the cells the pickups use
    src = np.empty((len(cols), len(union)), dtype=np.int64)
    for j, anchors in enumerate(cols):
        src[j] = near(anchors)[union] if anchors else 0
    np.minimum(src, BIG, out=src)
    picks = list(cells_of)
    cells = np.searchsorted(union, np.concatenate([cells_of[pick] for pick in picks]))
    to_put = np.concatenate([np.minimum(near(rows[puts[pick]].anchors)[cells_of[pick]], BIG)
                             for pick in picks])
    starts = np.cumsum([0] + [len(cells_of[pick]) for pick in picks[:-1]])
    from_cols = np.minimum.reduceat(src[:, cells] + to_put[None, :], starts, axis=1).T
    held = [i for i, row in enumerate(rows) if row.kind == PUT and row.carried < 0 and row.holder >= 0]
    return ApproachLegs(union, np.array(picks, dtype=np.int64), cells, starts, to_put, from_cols, held)
