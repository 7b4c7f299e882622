"""Two more lower bounds on the walking a node still needs (summed cost), used beside the
assignment relaxation of `heuristic.py` (the bound is the largest of them):

- **Carries, binding-consistent.** Within a leaf each type binds to one instance, so the walks the
  leaf's carries need (the key chain from where it lies to the box, then the box to the armchair)
  are one sum over a *joint* choice of instances, not a sum of separate nearest choices. While a
  robot carries a leaf's object to its put it holds it (one hand), so the carries of all leaves
  are disjoint parts of the robots' walks: their summed minima bound the walking from below, and a
  pickup's approach (its hand is empty) is disjoint from every carry, so an assignment over the
  pickups (and the actions done holding an object no put of the leaf takes back) adds to it.
- **Connection (spanning tree).** Every pending event is reached along some robot's walk, so the
  walks, with all robots merged into one root, connect the events: their length is at least a
  minimum spanning tree over the root and the events (region-to-region distances). Unlike the
  assignment, it cannot close a group of events far from every robot into a cycle of short steps.

Both use the cell-level triangle inequality: dropping events a bound does not model (support
opens, put-downs, optional alternatives) from a robot's walk never makes it longer.
"""

from __future__ import annotations

import heapq
from collections.abc import Callable, Sequence
from typing import NamedTuple

import numpy as np

_NO_EDGE = np.iinfo(np.int64).max  # an event already in the tree
JOINT_LIMIT = 4096  # instance combinations enumerated per leaf; beyond it each leg takes its own minimum

Leg = tuple[object, str]  # (where the carry starts: a type of the leaf or ("robot", r), the type it ends at)


def spanning_walk(ev: np.ndarray, root: np.ndarray) -> int:
    """Minimum spanning tree over a root and n events: `ev` (n x n) the event-to-event walks,
    `root` (n) the walk from the nearest robot to each event."""
    n = len(root)
    # Prim's algorithm on the dense matrix (tens of events: cheaper than a sparse-graph solver); a
    # walk joins two events in either direction, so an edge costs the shorter of the two
    ev = np.minimum(ev, ev.T)
    link = np.array(root, dtype=np.int64)  # each event's cheapest edge into the tree so far
    out = np.zeros(n, dtype=bool)
    total = 0
    for _ in range(n):
        j = int(np.where(out, _NO_EDGE, link).argmin())
        total += int(link[j])
        out[j] = True
        np.minimum(link, ev[j], out=link)
    return total


def carry_legs(atoms: Sequence[tuple[str, tuple[str, ...]]], held: dict[str, int]) -> list[Leg]:
    """The carries of one leaf path, as legs between the places of its types: `atoms` the path's
    (verb, types), `held` the leaf's types a robot holds now (type -> robot)."""
    inside: dict[str, str] = {}  # type -> the type it was put into (its place follows that one)
    start: dict[str, object] = {t: ("robot", r) for t, r in held.items()}
    legs: list[Leg] = []

    def place(t: str) -> str:
        seen = set()
        while t in inside and t not in seen:
            seen.add(t)
            t = inside[t]
        return t

    for verb, types in atoms:
        if verb == "pickup":
            start[types[0]] = place(types[0])
            inside.pop(types[0], None)
        elif verb == "put" and len(types) == 2:
            obj, rec = types
            origin = start.pop(obj, None)
            if origin is not None and origin != place(rec):
                legs.append((origin, place(rec)))
            inside[obj] = rec
    return legs


def joint_min(legs: list[Leg], anchors: Callable[[str], tuple[int, ...]], rr: np.ndarray,
              robot_walk: Callable[[int, tuple[int, ...]], np.ndarray]) -> int:
    """The least summed walk of `legs` over one instance per type (each type's candidate regions:
    `anchors`); `robot_walk(r, anchors)` is robot r's walk to each of them."""
    if not legs:
        return 0
    types = sorted({t for leg in legs for t in leg if isinstance(t, str)})
    sets = {t: anchors(t) for t in types}
    if any(not sets[t] for t in types):
        return 0  # a type without a known region: no claim
    axis = {t: i for i, t in enumerate(types)}
    shape = [len(sets[t]) for t in types]
    if int(np.prod(shape)) > JOINT_LIMIT:
        return sum(int(_leg_matrix(leg, sets, rr, robot_walk).min()) for leg in legs)
    total = np.zeros(shape, dtype=np.int64)
    for leg in legs:
        m = _leg_matrix(leg, sets, rr, robot_walk)
        src, dst = leg
        view = [1] * len(types)
        if isinstance(src, str):
            view[axis[src]] = m.shape[0]
            view[axis[dst]] = m.shape[1]
            if axis[src] > axis[dst]:
                m = m.T
        else:
            view[axis[dst]] = m.shape[1]
        total = total + m.reshape(view)
    return int(total.min())


def _leg_matrix(leg: Leg, sets: dict[str, tuple[int, ...]], rr: np.ndarray,
                robot_walk: Callable[[int, tuple[int, ...]], np.ndarray]) -> np.ndarray:
    src, dst = leg
    if isinstance(src, str):
        return rr[np.ix_(list(sets[src]), list(sets[dst]))]
    assert isinstance(src, tuple)
    return robot_walk(int(src[1]), sets[dst]).reshape(1, -1)


class Choice(NamedTuple):
    """A (leaf, type) pair still to bind, with its candidate regions."""

    leaf: int
    type_: str
    group: str | None  # the group of leaves that take distinct instances of the type, or None
    regions: tuple[int, ...]


def least_over_bindings(choices: Sequence[Choice], capacity: dict[str, dict[int, int]],
                        evaluate: Callable[[dict[tuple[int, str], int]], tuple[int, int]],
                        budget: int) -> tuple[int, int] | None:
    """The least bound over the instances the pending leaves may bind (their regions), searched
    best first: a partial choice's bound (`evaluate` with those (leaf, type) fixed to one region)
    bounds every completion that binds them so, so the least bound over the frontier is a bound at
    any moment. Instances a group of leaves each take for themselves are distinct (`capacity`: per
    group, region -> unclaimed instances there). Spends at most `budget` evaluations (a node is
    expanded with all its children or not at all); (summed bound, makespan bound), or None when
    nothing was searched."""
    if not choices:
        return None
    counter = 0
    s0, m0 = evaluate({})
    heap: list[tuple[int, int, int, tuple[int, ...]]] = [(s0, m0, counter, ())]
    spent = 1
    while heap:
        s, m, _, chosen = heap[0]
        if len(chosen) == len(choices):
            break  # the least complete choice: nothing on the frontier is below it
        group, regions = choices[len(chosen)].group, choices[len(chosen)].regions
        if spent + len(regions) > budget:
            break
        heapq.heappop(heap)
        for region in regions:
            if group is not None:
                used = sum(1 for choice, taken in zip(choices, chosen, strict=False)
                           if choice.group == group and taken == region)
                if used >= capacity[group].get(region, 0):
                    continue
            child = (*chosen, region)
            fixed = {(choice.leaf, choice.type_): taken
                     for choice, taken in zip(choices, child, strict=False)}
            s2, m2 = evaluate(fixed)
            spent += 1
            counter += 1
            heapq.heappush(heap, (max(s, s2), max(m, m2), counter, child))
    if not heap:
        return None  # no consistent choice (cannot happen for a solvable node): no claim
    return heap[0][0], min(entry[1] for entry in heap)


