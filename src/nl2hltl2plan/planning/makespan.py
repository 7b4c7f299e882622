"""The completion-time (`minmax`) bound of a node: the largest of the current makespan, each leaf's
chain (its events one after another, the first no earlier than a robot can reach it and than the
tasks ordered before it can finish, a carried object's put no earlier than the walk from its
pickup) and the work bound (all robots' clocks plus all remaining work, divided among the robots)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from nl2hltl2plan.planning.node import Node
from nl2hltl2plan.planning.relax import BIG, PUT, EventRow
from nl2hltl2plan.planning.state import Expander

Chains = dict[int, tuple[int, int]]  # leaf -> (steps for the first robot to reach it, events + carry legs)


def leaf_chains(near: Callable[[tuple[int, ...]], np.ndarray], rr: np.ndarray, node: Node,
                rows: list[EventRow], chain: Chains) -> None:
    """Per leaf with pending events: (steps for the first robot to reach its next event, events +
    carry legs); `near(anchors)` is the walk from the anchors' regions to each cell, `rr` the
    region-to-region walks."""
    cells = list(node.cell)
    by_leaf: dict[int, list[EventRow]] = {}
    for r in rows:
        by_leaf.setdefault(r.leaf, []).append(r)
    for li, evs in by_leaf.items():
        first = evs[0].anchors
        reach = int(near(first)[cells].min()) if first else 0
        length = 0
        for r in evs:
            length += 1
            if r.kind == PUT and r.carried >= 0 and r.anchors and rows[r.carried].anchors:
                leg = rr[np.array(rows[r.carried].anchors)[:, None], list(r.anchors)].min()  # (no np.ix_)
                length += int(min(leg, BIG))
        chain[li] = (min(reach, BIG), length)


def makespan_bound(x: Expander, node: Node, remaining: int, chain: Chains) -> int:
    """A lower bound on the final makespan, given `remaining` (a bound on the summed work left)."""
    p = x.p
    work = -(-(sum(node.clock) + remaining) // p.n_robots)
    min_clock = min(node.clock)
    done_lb: dict[str, int] = {}

    def node_done(name: str) -> int:
        hit = done_lb.get(name)
        if hit is not None:
            return hit
        slot = x.slot[name]
        if node.done_t[slot] >= 0:
            val = node.done_t[slot]
        elif name in p.leaf_index:
            li = p.leaf_index[name]
            first_reach, length = chain.get(li, (0, 0))
            start = node.leaf_t[li]
            if start == 0:
                if p.precedence:
                    start = max([node_done(g) for g in p.gates[li]], default=0)
                else:
                    start = node.last_done
                start = max(start, min_clock + first_reach)
            val = start + length
        else:
            nl = p.nonleaves[p.nonleaf_index[name]]
            val = max((node_done(c) for c in nl.children), default=0) if nl.pairs is not None else 0
        done_lb[name] = val
        return val

    best = max(node.ms, work)
    for li in chain:
        best = max(best, node_done(p.leaves[li].name))
    return best
