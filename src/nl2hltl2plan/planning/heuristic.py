"""Admissible lower bounds on the remaining cost of a node (both objectives).

Summed cost (`min`): every remaining event costs 1 plus the steps its robot walks to it. A robot
arrives at an event's region either from its current cell or from the stand cell of another event
it did before, and that event is still pending now. So the walk to event e is at least

    min( min over robots r of dist(cell_r, region(e)),
         min over pending events e' that may precede e of dist(region(e'), region(e)) )

where e' ranges over the pending events of other leaves and the earlier events of e's own leaf.
Summing this over pending events counts every robot's walking legs at most once, so the sum is a
lower bound. Unbound types use the nearest of their candidate instances; a leaf with alternative
action sequences counts its cheapest one.

Completion time (`minmax`): the largest of (a) the current makespan, (b) each leaf's chain: its
events happen one after another, the first no earlier than a robot can reach it and than the tasks
ordered before it can finish, a carried object's put no earlier than the walk from its pickup,
and (c) the work bound: all robots' clocks plus all remaining work, divided among the robots.
"""

from __future__ import annotations

from nl2hltl2plan.planning.model import DONE, Leaf
from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.state import Expander, Node, bound


class Heuristic:
    def __init__(self, expander: Expander, required: set[int]):
        self.x = expander
        self.p = expander.p
        self.nav = expander.nav
        self.required = required  # leaf indices every plan completes

    # ------------------------------------------------------------ symbolic regions of pending events
    def _anchors_of(self, node: Node, leaf: Leaf, type_: str, verb: str, memo: dict) -> frozenset[int]:
        key = (leaf.index, type_)
        hit = memo.get(key)
        if hit is not None:
            return hit
        x = self.x
        sim = node.sim
        anchor = self.nav.anchor
        b = bound(node, leaf.index, type_)
        objs = [b] if b >= 0 else x.by_type.get(type_, [])
        if b < 0 and leaf.exclusive(verb, type_):
            objs = [o for o in objs if o not in node.claimed]
        out = set()
        for o in objs:
            a = anchor(sim, o)
            if a < 0 and x.slice_of[o] >= 0:
                a = anchor(sim, x.slice_of[o])
            if a >= 0:
                out.add(a)
        res = frozenset(out)
        memo[key] = res
        return res

    def _path_events(self, node: Node, leaf: Leaf, path: tuple[int, ...], memo: dict) -> list[tuple]:
        """[(anchors, carried_from)] per event: where it happens, and for a put of an object picked
        up earlier in the path, the anchors of that pickup (a carry leg)."""
        where: dict[str, frozenset[int]] = {}
        picked_at: dict[str, frozenset[int]] = {}
        out = []
        for k in path:
            atom = leaf.atoms[k]
            target = atom.types[-1]
            anchors = where.get(target)
            if anchors is None:
                anchors = self._anchors_of(node, leaf, target, atom.verb, memo)
            carried = picked_at.get(atom.types[0]) if atom.verb == "put" else None
            out.append((anchors, carried))
            if atom.verb == "put":
                where[atom.types[0]] = anchors
                picked_at.pop(atom.types[0], None)
            elif atom.verb == "pickup":
                picked_at[atom.types[0]] = anchors
                where.pop(atom.types[0], None)
        return out

    # ------------------------------------------------------------ the bound
    def evaluate(self, node: Node) -> tuple[int, int]:
        """(lower bound on remaining summed cost, lower bound on the final makespan)."""
        p = self.p
        nav = self.nav
        memo: dict = {}
        pending: dict[int, list[list[tuple]]] = {}
        for lf in p.leaves:
            q = node.q[lf.index]
            if q == DONE or lf.index not in self.required:
                continue
            paths = lf.paths.get(q) or []
            pending[lf.index] = [self._path_events(node, lf, path, memo) for path in paths]
        if not pending:
            return 0, node.ms
        # anchors of every pending event per leaf (union over its alternatives)
        leaf_anchors = {
            li: frozenset().union(*(a for path in paths for a, _ in path)) if paths else frozenset()
            for li, paths in pending.items()
        }
        cells = node.cell
        robot_mem: dict[int, int] = {}

        def from_robots(a: int) -> int:
            hit = robot_mem.get(a)
            if hit is None:
                f = nav.field(a)
                hit = robot_mem[a] = min(f[c] for c in cells)
            return hit

        rr = nav.rr
        total = 0
        leaf_cost: dict[int, int] = {}
        chain: dict[int, tuple[int, int]] = {}  # leaf -> (first reach steps lb, chain length lb)
        for li, paths in pending.items():
            others = frozenset().union(*(leaf_anchors[o] for o in pending if o != li)) if len(pending) > 1 else frozenset()
            best = INF
            best_chain: tuple[int, int] | None = None
            for path in paths:
                cost = 0
                earlier: set[int] = set()
                first_reach = INF
                length = 0
                for j, (anchors, carried) in enumerate(path):
                    if not anchors:
                        walk = 0
                    elif anchors & earlier or anchors & others:
                        walk = 0
                    else:
                        walk = min(from_robots(a) for a in anchors)
                        preds = earlier | others
                        if walk and preds:
                            walk = min(walk, min(rr(b, a) for b in preds for a in anchors))
                    cost += 1 + walk
                    if j == 0:
                        first_reach = min((from_robots(a) for a in anchors), default=0)
                        length = 1
                    else:
                        leg = 0
                        if carried and anchors and not carried & anchors:
                            leg = min(rr(b, a) for b in carried for a in anchors)
                        length += 1 + leg
                    earlier |= anchors
                if cost < best:
                    best = cost
                if best_chain is None or length < best_chain[1]:
                    best_chain = (first_reach, length)
            if not paths:
                best, best_chain = 0, (0, 0)
            leaf_cost[li] = best
            chain[li] = best_chain or (0, 0)
            total += best
        return total, self._makespan(node, total, chain)

    def _makespan(self, node: Node, remaining: int, chain: dict[int, tuple[int, int]]) -> int:
        p = self.p
        x = self.x
        n = p.n_robots
        work = -(-(sum(node.clock) + remaining) // n)
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
