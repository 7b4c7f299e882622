"""The pending events as the lower bounds see them (`heuristic.py`, `makespan.py`): one typed row
per event that every completion of a node must still do."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy.optimize import linear_sum_assignment

BIG = 1 << 20  # a forbidden pair, or no walk (finite for the solvers)
OTHER, PICKUP, PUT = 0, 1, 2  # event kinds


class EventRow(NamedTuple):
    """One pending event of a leaf's remaining minimal sequence."""

    leaf: int
    pos: int  # its place in the leaf's remaining sequence
    anchors: tuple[int, ...]  # the regions (anchor objects) it may happen in
    kind: int  # OTHER, PICKUP or PUT
    carried: int  # a put: the row of the pickup of what it puts, else -1
    holder: int  # a put of what a robot holds now: that robot, else -1
    need: int  # the hand it needs (-1 any, else a hand id)
    after: int  # the hand right after it (-1 unknown, -2 empty, else a hand id)
    full: bool  # the hand stays full after it until a later put of this leaf


def solve(cost: np.ndarray) -> int:
    """The cheapest assignment (0 when none avoids a forbidden pair: cannot happen when solvable)."""
    r_ind, c_ind = linear_sum_assignment(cost)
    total = int(cost[r_ind, c_ind].sum())
    return 0 if total >= BIG else total
