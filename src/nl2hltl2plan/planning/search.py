"""Search over events: a beam-search seed, then anytime weighted A* (AWA*) with an incumbent.

- Seed: beam search over *macro* successors (a robot that picks something up carries on with that
  leaf until its hand is empty) restricted to the nearest few instances of each type. It finds a
  good plan in a few dozen expansions and gives the first upper bound UB.
- AWA* (Hansen & Zhou 2007) over the full event space (every robot, every applicable action,
  every instance): nodes are expanded in order of g + w*h, nodes with g + h >= UB are pruned, and
  every goal found lowers UB. LB = min over open nodes of g + h is a proven lower bound on the
  optimum (h is admissible), so the search can stop as soon as UB <= w_stop * LB. With w_stop = 1
  (mode `exact`) the returned plan is optimal; mode `fast` stops at w_stop = w.
- Duplicate detection on a canonical state: object states, robots sorted (interchangeable robots
  in the same situation are one state), leaf states and bindings. For `min`, a duplicate with no
  better g is dropped; for `minmax`, one whose g and every clock/ready time are no better.
"""

from __future__ import annotations

import heapq
import itertools
import time
from dataclasses import dataclass

from nl2hltl2plan.planning.heuristic import Heuristic
from nl2hltl2plan.planning.state import Expander, Node

MS_WEIGHT = 1 << 20  # minmax: makespan first, summed cost breaks ties (lexicographic order)


class Deadline(Exception):
    """The time limit ran out."""


@dataclass
class SearchStats:
    expanded: int = 0
    generated: int = 0
    seed_cost: float | None = None
    seed_time_s: float | None = None
    lns_moves: int = 0  # improving local-search moves on the seed
    lower_bound: float = 0.0  # proven lower bound on the optimal cost (objective units)
    proven_optimal: bool = False
    exhausted: bool = False
    stopped: str = ""  # why the search stopped: "bound", "exhausted", "budget", "timeout"


class Searcher:
    def __init__(self, expander: Expander, heuristic: Heuristic, objective: str, deadline: float):
        self.x = expander
        self.h = heuristic
        self.objective = objective
        self.deadline = deadline
        self.stats = SearchStats()

    # ------------------------------------------------------------ bookkeeping
    def check_time(self) -> None:
        if time.perf_counter() > self.deadline:
            raise Deadline

    def score(self, node: Node) -> None:
        h_sum, ms_lb = self.h.evaluate(node)
        node.h = h_sum
        node.ms_lb = ms_lb
        node.f = self.admissible(node)

    def admissible(self, node: Node) -> int:
        if self.objective == "min":
            return node.g + node.h
        return MS_WEIGHT * node.ms_lb + node.g + node.h

    def weighted(self, node: Node, w: float) -> float:
        if self.objective == "min":
            return node.g + w * node.h
        return MS_WEIGHT * (node.ms + w * (node.ms_lb - node.ms)) + node.g + w * node.h

    def cost(self, node: Node) -> int:
        return node.g if self.objective == "min" else MS_WEIGHT * node.ms + node.g

    def key(self, node: Node) -> tuple:
        memo = node._memo
        if memo is not None:
            return memo  # type: ignore[return-value]
        sim = node.sim
        robots = sorted(zip(node.cell, (sim.hand.get(r, -1) for r in range(len(node.cell))),
                            self.x.cap_class, strict=True))
        k = (tuple(sim.parent), tuple(sim.flags), tuple(sim.moved), tuple(robots), node.q, node.bind, node.nq)
        node._memo = k  # type: ignore[assignment]
        return k

    def times(self, node: Node) -> tuple:
        """What makes one node's future schedule no worse than another's (minmax dominance)."""
        hand = node.sim.hand
        order = sorted(range(len(node.cell)),
                       key=lambda r: (node.cell[r], hand.get(r, -1), self.x.cap_class[r], node.clock[r]))
        obj_t = node.obj_t
        touched = tuple(obj_t.get(i, 0) for i in range(self.x.n_objects))
        clocks = tuple(node.clock[r] for r in order)
        return (clocks, node.leaf_t, node.done_t, node.last_done, node.ms, touched)

    # ------------------------------------------------------------ seed
    def beam(self, root: Node, width: int, limit: int) -> Node | None:
        """Beam search over macro successors; the cheapest goal found, or None. Children are
        first ranked by an estimate (parent's f plus the walking the step did), and only the best
        few get the full heuristic."""
        if root.h is None:
            self.score(root)
        layer = [root]
        best: Node | None = None
        seen: set = set()
        while layer:
            children: list[tuple[float, int, Node]] = []
            for node in layer:
                self.check_time()
                self.stats.expanded += 1
                for child in self.x.successors(node, limit=limit, macro=True):
                    self.stats.generated += 1
                    if self.x.is_goal(child):
                        if best is None or self.cost(child) < self.cost(best):
                            best = child
                        continue
                    k = self.key(child)
                    if k in seen:
                        continue
                    seen.add(k)
                    children.append((self.estimate(node, child), -child.g, child))
            children.sort(key=lambda c: (c[0], c[1]))
            scored = []
            for _, _, child in children[: 3 * width]:
                self.check_time()
                self.score(child)
                if best is not None and child.f >= self.cost(best):
                    continue
                scored.append(child)
            scored.sort(key=lambda n: (n.f, -n.g))
            layer = scored[:width]
        return best

    def estimate(self, parent: Node, child: Node) -> float:
        """A cheap guess of the child's f: the parent's, plus the walking of the step (the step's
        actions were already in the parent's bound)."""
        walked = 0
        node: Node | None = child
        while node is not None and node is not parent:
            walked += node.event.travel if node.event is not None else 0
            node = node.parent
        if self.objective == "min":
            return parent.f + walked
        return parent.f + MS_WEIGHT * max(0, child.ms - parent.ms_lb) + walked

    # ------------------------------------------------------------ AWA*
    def awa(self, root: Node, incumbent: Node | None, w_order: float, w_stop: float,
            max_expansions: int | None = None, stop_at: float | None = None) -> Node | None:
        """Anytime weighted A* with deferred evaluation: a child enters the open list with its
        parent's bound (valid for it too) and gets its own heuristic when it is first popped."""
        stats = self.stats
        best = incumbent
        ub = self.cost(best) if best is not None else float("inf")
        counter = itertools.count()
        if root.h is None:
            self.score(root)
        open_heap: list = [(self.weighted(root, w_order), -root.g, next(counter), root)]
        lb_heap: list = [(root.f, next(counter), root)]
        table: dict = {}
        self._record(table, root)
        expansions = 0
        stop = "exhausted"
        while open_heap:
            self.check_time()
            lb = self._lower_bound(lb_heap)
            if lb is not None:
                stats.lower_bound = max(stats.lower_bound, self._unit(min(lb, ub)))
                if best is not None and self._proven(ub, lb, w_stop):
                    stop = "bound"
                    break
            if best is not None and max_expansions is not None and expansions >= max_expansions:
                stop = "budget"
                break
            if best is not None and stop_at is not None and time.perf_counter() > stop_at:
                stop = "budget"
                break
            key, _, _, node = heapq.heappop(open_heap)
            if node.closed or self._stale(table, node):
                node.closed = True
                continue
            if node.h is None:  # deferred evaluation
                estimate = node.f
                self.score(node)
                node.f = max(node.f, estimate)  # both bound the optimum below
                if node.f >= ub:
                    node.closed = True
                    continue
                heapq.heappush(lb_heap, (node.f, next(counter), node))
                new_key = self.weighted(node, w_order)
                if open_heap and new_key > open_heap[0][0]:
                    heapq.heappush(open_heap, (new_key, -node.g, next(counter), node))
                    continue
            node.closed = True
            if node.f >= ub:
                continue
            expansions += 1
            stats.expanded += 1
            for child in self.x.successors(node):
                stats.generated += 1
                if self.x.is_goal(child):
                    c = self.cost(child)
                    if c < ub:
                        ub, best = c, child
                    continue
                child.h = None
                child.ms_lb = max(node.ms_lb, child.ms)
                child.f = max(node.f, self._floor(child))
                if child.f >= ub or not self._record(table, child):
                    continue
                key = child.f if w_order == 1.0 else self._weighted_guess(node, child, w_order)
                heapq.heappush(open_heap, (key, -child.g, next(counter), child))
                heapq.heappush(lb_heap, (child.f, next(counter), child))
        if stop == "exhausted" and not open_heap:
            stats.exhausted = True
            if best is not None:
                stats.lower_bound = self._unit(ub)
        stats.stopped = stop
        stats.proven_optimal = best is not None and (stats.exhausted or stats.lower_bound >= self._unit(ub))
        return best

    def _floor(self, node: Node) -> int:
        """A cheap admissible f: cost so far (the parent's bound covers the rest)."""
        if self.objective == "min":
            return node.g
        return MS_WEIGHT * node.ms + node.g

    def _weighted_guess(self, parent: Node, child: Node, w: float) -> float:
        h_guess = max(0, parent.h - (child.g - parent.g))
        if self.objective == "min":
            return child.g + w * h_guess
        return MS_WEIGHT * max(child.ms, parent.ms_lb) + child.g + w * h_guess

    def _lower_bound(self, lb_heap: list) -> int | None:
        while lb_heap and (lb_heap[0][2].closed or lb_heap[0][0] < lb_heap[0][2].f):
            # closed nodes no longer bound the optimum (their children are in the open list), and
            # an entry below its node's f is an old estimate of a node pushed again
            heapq.heappop(lb_heap)
        return lb_heap[0][0] if lb_heap else None

    def _unit(self, value: float) -> float:
        """Objective units: summed cost for min, completion time for minmax."""
        return float(value) if self.objective == "min" else float(int(value) // MS_WEIGHT)

    def _proven(self, ub: float, lb: float, w: float) -> bool:
        if self.objective == "min":
            return ub <= w * lb
        if w <= 1.0:
            return ub <= lb
        return self._unit(ub) <= w * self._unit(lb)

    def _record(self, table: dict, node: Node) -> bool:
        """Keep the node unless a recorded node with the same state is at least as good."""
        k = self.key(node)
        entries = table.get(k)
        if self.objective == "min":
            if entries is not None and entries <= node.g:
                return False
            table[k] = node.g
            return True
        tv = self.times(node)
        if entries is None:
            table[k] = [(node.g, tv)]
            return True
        for g, other in entries:
            if g <= node.g and _leq(other, tv):
                return False
        entries[:] = [(g, o) for g, o in entries if not (node.g <= g and _leq(tv, o))]
        entries.append((node.g, tv))
        return True

    def _stale(self, table: dict, node: Node) -> bool:
        if self.objective != "min":
            return False
        best = table.get(self.key(node))
        return best is not None and best < node.g


def _leq(a, b) -> bool:
    """Elementwise a <= b over nested tuples of ints."""
    if isinstance(a, tuple):
        return all(_leq(x, y) for x, y in zip(a, b, strict=True))
    return a <= b
