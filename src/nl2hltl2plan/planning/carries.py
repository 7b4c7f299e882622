"""The carries of the pending leaves, binding-consistent (a term of the summed-cost bound,
`heuristic.py`; the walks themselves: `bounds.carry_legs`, `bounds.joint_min`). A leaf's carries are
minimised over one joint choice of instances; leaves that each take their own instance of one type
(two baseball bats to the bed) get distinct instances, by an assignment of instances to leaves."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from nl2hltl2plan.planning.bounds import Leg, carry_legs, joint_min
from nl2hltl2plan.planning.leaves import DONE, Leaf
from nl2hltl2plan.planning.node import Node, bound
from nl2hltl2plan.planning.relax import BIG, solve
from nl2hltl2plan.worlds.simulator import PRESENT

if TYPE_CHECKING:
    from nl2hltl2plan.planning.heuristic import Heuristic

CACHE_LIMIT = 100_000  # carry minima kept across nodes


def carry_total(h: Heuristic, node: Node, memo: dict) -> int:
    """The carries of all pending leaves. Leaves that each take their own instance of one type
    (two baseball bats to the bed) get distinct instances: an assignment of instances to them."""
    total = 0
    groups: dict[str, list[dict[int, int]]] = {}
    for lf in h.p.leaves:
        if node.q[lf.index] == DONE or lf.index not in h.required:
            continue
        per = _carry_per_instance(h, node, lf, memo)
        if per is None:
            total += _carries(h, node, lf, memo)
        else:
            groups.setdefault(per[0], []).append(per[1])
    for rows in groups.values():
        insts = sorted({o for row in rows for o in row})
        if len(rows) == 1 or len(insts) < len(rows):
            total += sum(min(row.values()) for row in rows)
            continue
        cost = np.array([[row.get(o, BIG) for o in insts] for row in rows], dtype=np.int64)
        total += solve(cost) or sum(min(row.values()) for row in rows)
    return total


def _carry_per_instance(h: Heuristic, node: Node, leaf: Leaf,
                        memo: dict) -> tuple[str, dict[int, int]] | None:
    """(T, instance -> the leaf's least carries with it) when the leaf's one path takes an
    instance of T for itself that is not bound yet; else None."""
    paths = leaf.paths.get(node.q[leaf.index]) or []
    if len(paths) != 1:
        return None
    atoms = [leaf.atoms[k] for k in paths[0]]
    taken = sorted({a.types[0] for a in atoms if a.verb == "pickup"
                    and leaf.exclusive("pickup", a.types[0]) and bound(node, leaf.index, a.types[0]) < 0})
    if len(taken) != 1 or (leaf.index, taken[0]) in memo["fixed"]:
        return None  # a type the root's search fixed: its one region is in the memo
    t = taken[0]
    sim = node.sim
    objs = [o for o in h.x.by_type.get(t, []) if o not in node.claimed]
    if any(not sim.flags[o] & PRESENT for o in objs):
        return None  # slices still to come: no list of instances yet
    by_anchor: dict[int, int] = {}
    out = {}
    for o in objs:
        a = h.nav.anchor(sim, o)
        if a < 0:
            continue
        if a not in by_anchor:
            by_anchor[a] = _carries(h, node, leaf, memo, fixed=(t, a))
        out[o] = by_anchor[a]
    return (t, out) if out else None

def _carries(h: Heuristic, node: Node, leaf: Leaf, memo: dict, fixed: tuple[str, int] | None = None) -> int:
    """The least walking the leaf's remaining carries need, one instance per type (bounds.py);
    `fixed`: (type, region) of a type's instance."""
    paths = leaf.paths.get(node.q[leaf.index]) or []
    if not paths:
        return 0
    sim = node.sim
    held = {t: sim.holder[o] for t, o in node.bind[leaf.index] if sim.holder[o] >= 0}
    best = None
    for path in paths:
        legs, picked, types, holders = _path_legs(h, leaf, path, held)

        def anchors(t: str, picked: frozenset[str] = picked) -> tuple[int, ...]:
            if fixed is not None and t == fixed[0]:
                return (fixed[1],)
            return h.anchors_of(node, leaf, t, "pickup" if t in picked else "put", memo)

        if not legs:
            return 0
        # a pure function of the legs, the candidate regions and where the holders may stand (not
        # of the other robots): cached across nodes
        key = (legs, tuple(anchors(t) for t in types), _holders_at(node, holders))
        val = h.carry_cache.get(key, -1)
        if val < 0:
            if len(h.carry_cache) > CACHE_LIMIT:
                h.carry_cache.clear()
            val = h.carry_cache[key] = joint_min(list(legs), anchors, h.rr, _holders_walk(h, node))
        best = val if best is None else min(best, val)
        if not best:
            break
    return best or 0


def _holders_at(node: Node, holders: tuple[int, ...]) -> tuple[tuple[int, int, object], ...]:
    """Where each robot holding one of the leaf's objects is and may stand (its carries' start)."""
    reach = node.reach
    return tuple((r, node.cell[r], reach[r] if reach is not None else None) for r in holders)


def _holders_walk(h: Heuristic, node: Node) -> Callable[[int, tuple[int, ...]], np.ndarray]:
    """Robot r's walk to each of some regions, at `node` (only legs that start at a holder ask)."""
    return lambda r, anchors: h.robot_walks(node, np.array(anchors, dtype=np.int64))[:, r]


class PathLegs(NamedTuple):
    """The carries of one leaf path (`_path_legs`)."""

    legs: tuple[Leg, ...]
    picked: frozenset[str]  # the types the path picks up
    types: list[str]  # the types the legs join (sorted)
    holders: tuple[int, ...]  # the robots whose hands the legs start at (sorted)


def _path_legs(h: Heuristic, leaf: Leaf, path: tuple[int, ...], held: dict[str, int]) -> PathLegs:
    """The carry legs of a leaf path and the types it picks up: a pure function of the path and
    of which robots hold which of its types, so computed once per such state, not once per node."""
    key = (leaf.index, path, tuple(sorted(held.items())))
    hit = h.legs_cache.get(key)
    if hit is None:
        atoms = [(leaf.atoms[k].verb, leaf.atoms[k].types) for k in path]
        picked = frozenset(types[0] for verb, types in atoms if verb == "pickup")
        if len(h.legs_cache) > CACHE_LIMIT:
            h.legs_cache.clear()
        legs = tuple(carry_legs(atoms, held))
        types = sorted({t for leg in legs for t in leg if isinstance(t, str)})
        hit = h.legs_cache[key] = PathLegs(legs, picked, types, tuple(sorted(set(held.values()))))
    return hit
