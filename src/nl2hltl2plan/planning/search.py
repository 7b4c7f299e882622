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
from collections.abc import Callable
from dataclasses import dataclass

from nl2hltl2plan.planning.budget import StopReason
from nl2hltl2plan.planning.heuristic import Heuristic
from nl2hltl2plan.planning.leaves import DONE
from nl2hltl2plan.planning.node import Node
from nl2hltl2plan.planning.objective import DuplicateTable, Objective
from nl2hltl2plan.planning.state import Expander

BEAM_SCORED = 3  # a beam gives the full heuristic to this many children per slot (by estimate)
NODE_BYTES = 4000  # rough memory of one stored search node (SimState copy, tuples), for reporting


class Deadline(Exception):
    """The wall-clock limit ran out (a last resort: budgets are counted in expansions)."""


@dataclass
class SearchStats:
    expanded: int = 0
    generated: int = 0
    peak_nodes: int = 0  # most nodes held at once by an A* (open list + duplicate table)
    lower_bound: float = 0.0  # proven lower bound on the optimal cost (objective units)
    proven_optimal: bool = False
    exhausted: bool = False
    stopped: StopReason = StopReason.NONE  # why the search stopped
    best_cost: float | None = None  # the incumbent's cost so far (objective units; None: no plan yet)


ProgressHook = Callable[[SearchStats], None]
PROGRESS_EVERY_S = 0.25  # a progress hook hears from the search at most this often


class Searcher:
    def __init__(self, expander: Expander, heuristic: Heuristic, objective: Objective, deadline: float,
                 on_progress: ProgressHook | None = None):
        self.x = expander
        self.h = heuristic
        self.obj = objective
        self.deadline = deadline
        self.stats = SearchStats()
        self.on_progress = on_progress
        self._next_report = 0.0
        self._beam_best: Node | None = None  # the running beam's cheapest goal so far
        self._beam_bar = float("inf")  # the cost a beam's goal must beat

    # ------------------------------------------------------------ bookkeeping
    def check_time(self) -> None:
        now = time.perf_counter()
        if now > self.deadline:
            raise Deadline
        if self.on_progress is not None and now >= self._next_report:
            self._next_report = now + PROGRESS_EVERY_S
            self.on_progress(self.stats)

    def found(self, node: Node) -> None:
        """Record a new incumbent's cost (what a progress hook reports as the best so far)."""
        self.stats.best_cost = float(self.obj.reported(node))

    def score(self, node: Node) -> None:
        h_sum, ms_lb = self.h.evaluate(node)
        node.h = h_sum
        node.ms_lb = ms_lb
        node.f = self.obj.admissible(node)

    def cost(self, node: Node) -> int:
        return self.obj.cost(node)

    def key(self, node: Node) -> tuple[object, ...]:
        memo = node.memo
        if memo is not None:
            return memo
        sim = node.sim
        hands = [sim.hand.get(r, -1) for r in range(len(node.cell))]
        reach = node.reach if node.reach is not None else (None,) * len(node.cell)
        # robots sorted: interchangeable robots in the same situation are one state; with free stand
        # cells, where a robot may stand (and at what extra cost) is part of its situation
        robots = sorted(zip(node.cell, hands, self.x.cap_class, (r or ((), ()) for r in reach), strict=True))
        k = (tuple(sim.parent), tuple(sim.flags), tuple(sim.moved), tuple(robots), node.q, node.bind, node.nq)
        node.memo = k
        return k

    # ------------------------------------------------------------ seed
    def beam(self, root: Node, width: int, limit: int, robots: frozenset[int] | None = None,
             ub: int | None = None) -> Node | None:
        """Beam search over macro successors (of `robots` only, when given); the cheapest goal
        found that costs less than `ub` (when given), or None. Children are first ranked by an
        estimate (parent's f plus the walking the step did), and only the best few get the full
        heuristic."""
        if root.h is None:
            self.score(root)
        layer = [root]
        self._beam_best = None
        self._beam_bar = float("inf") if ub is None else ub
        seen: set = set()
        while layer:
            raw: list[tuple[float, int, Node, Node]] = []
            for node in layer:
                self.check_time()
                self.stats.expanded += 1
                for child in self.x.successors(node, limit=limit, robots=robots):
                    self.stats.generated += 1
                    raw.append((self.estimate(node, child), len(raw), node, child))
            scored = []
            for child in self._best_children(raw, BEAM_SCORED * width, seen):
                self.check_time()
                self.score(child)
                if child.f >= self._beam_limit():
                    continue
                scored.append(child)
            scored.sort(key=lambda n: (n.f, -n.g))
            layer = scored[:width]
        return self._beam_best

    def _beam_limit(self) -> float:
        best = self._beam_best
        return self.cost(best) if best is not None else self._beam_bar

    def _best_children(self, raw: list[tuple[float, int, Node, Node]], k: int, seen: set) -> list[Node]:
        """The k best new children by (estimate, -g) after their macro steps (a robot that picked
        something up carries on with that leaf until its hand is empty). A macro step only adds
        walking, so the estimate before it bounds the one after it: children are carried on in
        that order and the rest are never carried on once k finished ones rank before them. A
        child that may reach the goal (at most one required leaf left) is always carried on."""
        required = self.h.required
        heap: list[tuple[float, int, Node, Node]] = []
        finished: list[tuple[float, int, int, Node]] = []
        for item in raw:
            _, _, _, child = item
            if sum(1 for li in required if child.q[li] != DONE) <= 1:
                self._finish(item, finished, seen)
            else:
                heap.append(item)
        heapq.heapify(heap)
        # the k least estimates of the finished children, negated (a max-heap: its top is the k-th)
        top = [-item[0] for item in heapq.nsmallest(k, finished)]
        heapq.heapify(top)
        while heap:
            if len(top) >= k and -top[0] < heap[0][0]:
                break
            n_finished = len(finished)
            self._finish(heapq.heappop(heap), finished, seen)
            if len(finished) > n_finished and len(top) < k:
                heapq.heappush(top, -finished[-1][0])
            elif len(finished) > n_finished:
                heapq.heappushpop(top, -finished[-1][0])
        finished.sort()
        return [child for _, _, _, child in finished[:k]]

    def _finish(self, item: tuple[float, int, Node, Node], finished: list[tuple[float, int, int, Node]],
                seen: set) -> None:
        """Carry a child on (its macro step), keep it if it is a new state, note it if a goal."""
        _, index, parent, child = item
        event = child.event
        if event is not None and event.verb == "pickup":
            child = self.x.carry_on(child, event.robot, self.x.p.leaves[event.leaf])
        if self.x.is_goal(child):
            if self.cost(child) < self._beam_limit():
                self._beam_best = child
            return
        key = self.key(child)
        if key in seen:
            return
        seen.add(key)
        finished.append((self.estimate(parent, child), -child.g, index, child))

    def estimate(self, parent: Node, child: Node) -> float:
        """A cheap guess of the child's f: the parent's, plus the walking of the step (the step's
        actions were already in the parent's bound)."""
        walked = 0
        node: Node | None = child
        while node is not None and node is not parent:
            walked += node.event.travel if node.event is not None else 0
            node = node.parent
        return self.obj.estimate(parent, child, walked)

    # ------------------------------------------------------------ AWA*
    def awa(self, root: Node, incumbent: Node | None, w_order: float, w_stop: float,
            max_expansions: int | None = None, max_nodes: int | None = None,
            max_generated: int | None = None, max_work: int | None = None,
            stall: Stall | None = None) -> Node | None:
        """Anytime weighted A* with deferred evaluation: a child enters the open list with its
        parent's bound (valid for it too) and gets its own heuristic when it is first popped.
        Stops when the incumbent is proven within w_stop, the open list is empty, `max_expansions`,
        `max_generated` or `max_work` (the heuristic's work, `Heuristic.work`) are spent, the
        proven bound has stopped rising (`stall`), or more than `max_nodes` are held (with an
        incumbent), or at the deadline."""
        stats, obj = self.stats, self.obj
        best = incumbent
        ub: float = self.cost(best) if best is not None else float("inf")
        counter = itertools.count()
        if root.h is None:
            self.score(root)
        open_heap: list[tuple[float, int, int, Node]] = [(obj.weighted(root, w_order), -root.g, 0, root)]
        lb_heap: list[tuple[int, int, Node]] = [(root.f, next(counter), root)]
        table = obj.table(self.x.cap_class, self.x.n_objects)
        table.record(self.key(root), root)
        expansions = generated = 0
        work_start = self.h.work
        work_end = None if max_work is None else work_start + max_work
        best_lb, last_rise = -1, 0  # the highest bound so far, and the work spent when it was reached
        stop = StopReason.EXHAUSTED
        while open_heap:
            self.check_time()
            lb = _lower_bound(lb_heap)
            if lb is not None:
                stats.lower_bound = max(stats.lower_bound, obj.unit(min(lb, ub)))
                if best is not None and obj.proven(ub, lb, w_stop):
                    stop = StopReason.BOUND
                    break
                if lb > best_lb:
                    best_lb, last_rise = lb, self.h.work - work_start
            if (best is not None and stall is not None
                    and stall.stalled(self.h.work - work_start, last_rise, obj.unit(ub) - obj.unit(best_lb))):
                stop = StopReason.STALLED
                break
            held = len(open_heap) + len(table)
            stats.peak_nodes = max(stats.peak_nodes, held)
            if best is not None and ((max_expansions is not None and expansions >= max_expansions)
                                     or (max_generated is not None and generated >= max_generated)
                                     or (work_end is not None and self.h.work >= work_end)):
                stop = StopReason.BUDGET
                break
            if best is not None and max_nodes is not None and held > max_nodes:
                stop = StopReason.MEMORY
                break
            node = heapq.heappop(open_heap)[3]
            if node.closed or table.stale(self.key(node), node):
                node.closed = True
                continue
            if node.h is None and self._defer(node, ub, open_heap, lb_heap, w_order, counter):
                continue
            node.closed = True
            if node.f >= ub:
                continue
            expansions += 1
            stats.expanded += 1
            for child in self.x.successors(node):
                stats.generated += 1
                generated += 1
                if self.x.is_goal(child):
                    if self.cost(child) < ub:
                        ub, best = self.cost(child), child
                        self.found(child)
                    continue
                child.ms_lb = max(node.ms_lb, child.ms)
                child.f = max(node.f, obj.floor(child))
                if child.f >= ub or not table.record(self.key(child), child):
                    continue
                key = child.f if w_order == 1.0 else obj.weighted_guess(node, child, w_order)
                heapq.heappush(open_heap, (key, -child.g, next(counter), child))
                heapq.heappush(lb_heap, (child.f, next(counter), child))
        if stop == StopReason.EXHAUSTED:
            stats.exhausted = True
            if best is not None:
                stats.lower_bound = obj.unit(ub)
        stats.stopped = stop
        stats.proven_optimal = best is not None and (stats.exhausted or stats.lower_bound >= obj.unit(ub))
        return best

    def _defer(self, node: Node, ub: float, open_heap: list[tuple[float, int, int, Node]],
               lb_heap: list[tuple[int, int, Node]], w_order: float, counter: itertools.count[int]) -> bool:
        """Deferred evaluation of a popped node: score it; True when it is pruned or goes back to
        the open list (a worse key than the next node's)."""
        estimate = node.f
        self.score(node)
        node.f = max(node.f, estimate)  # both bound the optimum below
        if node.f >= ub:
            node.closed = True
            return True
        heapq.heappush(lb_heap, (node.f, next(counter), node))
        new_key = self.obj.weighted(node, w_order)
        if open_heap and new_key > open_heap[0][0]:
            heapq.heappush(open_heap, (new_key, -node.g, next(counter), node))
            return True
        return False


@dataclass(frozen=True)
class Stall:
    """When an A* whose proven bound has stopped rising gives up: once it has spent `min_work`
    (heuristic work) and its bound last rose more than `share` of the work spent so far ago, unless
    its plan is at most `near` objective units above that bound (`gap`). On valid_seen scenarios a
    search that goes on to prove its plan raises its bound as it goes, or exhausts a small space
    with its plan one unit above the bound (docs/planning.md); a search whose bound sits still for
    most of its budget further off rarely proves it."""

    min_work: int
    share: float
    near: float

    def stalled(self, spent: int, last_rise: int, gap: float) -> bool:
        return gap > self.near and spent >= self.min_work and spent - last_rise >= self.share * spent


def _lower_bound(lb_heap: list[tuple[int, int, Node]]) -> int | None:
    while lb_heap and (lb_heap[0][2].closed or lb_heap[0][0] < lb_heap[0][2].f):
        # closed nodes no longer bound the optimum (their children are in the open list), and
        # an entry below its node's f is an old estimate of a node pushed again
        heapq.heappop(lb_heap)
    return lb_heap[0][0] if lb_heap else None


__all__ = ["Deadline", "DuplicateTable", "SearchStats", "Searcher", "Stall"]
