"""The two objectives as strategy objects, so that the search code never asks which one it runs.

`SummedCost` ("min"): moves + actions summed over robots, the paper's cost. `Makespan` ("minmax"):
the completion time, ties broken by the summed cost; it orders nodes lexicographically by folding
both into one integer, `MS_WEIGHT * makespan + summed cost`.

Every search value ("search units") is an int; `unit` turns it into objective units (summed cost,
or steps for the makespan) for bounds and reports.
"""

from __future__ import annotations

from typing import Literal

from nl2hltl2plan.planning.node import Node

MS_WEIGHT = 1 << 20  # minmax: makespan first, summed cost breaks ties (lexicographic order)
ObjectiveName = Literal["min", "minmax"]


class Objective:
    """What the search optimises; subclasses say how a node is scored."""

    name: ObjectiveName
    description: str
    solo_seeds: bool  # worth seeding with single-robot plans (one well-placed robot often wins)
    makespan_bound: bool  # does scoring read the completion-time bound (`Node.ms_lb`)?

    def cost(self, node: Node) -> int:
        """The objective of a goal node, in search units."""
        raise NotImplementedError

    def value(self, node: Node) -> tuple[int, ...]:
        """A goal node's objective as a tuple (smaller is better)."""
        raise NotImplementedError

    def reported(self, node: Node) -> int:
        """The objective of a goal node in objective units (summed cost or steps)."""
        raise NotImplementedError

    def admissible(self, node: Node) -> int:
        """g + h: a lower bound on every goal below the node (h must be evaluated)."""
        raise NotImplementedError

    def floor(self, node: Node) -> int:
        """A cheap lower bound: the cost so far."""
        raise NotImplementedError

    def weighted(self, node: Node, w: float) -> float:
        """The weighted-A* priority g + w*h."""
        raise NotImplementedError

    def weighted_guess(self, parent: Node, child: Node, w: float) -> float:
        """The priority of a child whose heuristic is not evaluated yet (the parent's, less the step)."""
        raise NotImplementedError

    def estimate(self, parent: Node, child: Node, walked: int) -> float:
        """A cheap guess of the child's f for ranking beam candidates."""
        raise NotImplementedError

    def unit(self, value: float) -> float:
        """Search units to objective units."""
        raise NotImplementedError

    def proven(self, ub: float, lb: float, w: float) -> bool:
        """Is an incumbent of cost ub proven within factor w of the optimum, given the bound lb?"""
        raise NotImplementedError

    def table(self, cap_class: list[int], n_objects: int) -> DuplicateTable:
        """The duplicate-detection table this objective needs."""
        return DuplicateTable()


class SummedCost(Objective):
    name: ObjectiveName = "min"
    description = "moves + actions summed over robots"
    solo_seeds = True
    makespan_bound = False

    def cost(self, node: Node) -> int:
        return node.g

    def value(self, node: Node) -> tuple[int, ...]:
        return (node.g,)

    def reported(self, node: Node) -> int:
        return node.g

    def admissible(self, node: Node) -> int:
        assert node.h is not None
        return node.g + node.h

    def floor(self, node: Node) -> int:
        return node.g

    def weighted(self, node: Node, w: float) -> float:
        assert node.h is not None
        return node.g + w * node.h

    def weighted_guess(self, parent: Node, child: Node, w: float) -> float:
        assert parent.h is not None
        return child.g + w * max(0, parent.h - (child.g - parent.g))

    def estimate(self, parent: Node, child: Node, walked: int) -> float:
        return parent.f + walked

    def unit(self, value: float) -> float:
        return float(value)

    def proven(self, ub: float, lb: float, w: float) -> bool:
        return ub <= w * lb


class Makespan(Objective):
    name: ObjectiveName = "minmax"
    description = "completion time (steps), ties broken by moves + actions summed over robots"
    solo_seeds = False
    makespan_bound = True

    def cost(self, node: Node) -> int:
        return MS_WEIGHT * node.ms + node.g

    def value(self, node: Node) -> tuple[int, ...]:
        return (node.ms, node.g)

    def reported(self, node: Node) -> int:
        return node.ms

    def admissible(self, node: Node) -> int:
        assert node.h is not None
        return MS_WEIGHT * node.ms_lb + node.g + node.h

    def floor(self, node: Node) -> int:
        return MS_WEIGHT * node.ms + node.g

    def weighted(self, node: Node, w: float) -> float:
        assert node.h is not None
        return MS_WEIGHT * (node.ms + w * (node.ms_lb - node.ms)) + node.g + w * node.h

    def weighted_guess(self, parent: Node, child: Node, w: float) -> float:
        assert parent.h is not None
        h_guess = max(0, parent.h - (child.g - parent.g))
        return MS_WEIGHT * max(child.ms, parent.ms_lb) + child.g + w * h_guess

    def estimate(self, parent: Node, child: Node, walked: int) -> float:
        return parent.f + MS_WEIGHT * max(0, child.ms - parent.ms_lb) + walked

    def unit(self, value: float) -> float:
        return float(int(value) // MS_WEIGHT)

    def proven(self, ub: float, lb: float, w: float) -> bool:
        if w <= 1.0:
            return ub <= lb
        return self.unit(ub) <= w * self.unit(lb)

    def table(self, cap_class: list[int], n_objects: int) -> DuplicateTable:
        return DominanceTable(cap_class, n_objects)


OBJECTIVES: dict[str, Objective] = {"min": SummedCost(), "minmax": Makespan()}


def objective_for(name: str) -> Objective:
    """The strategy object for "min" or "minmax" (KeyError-free: the caller validates the name)."""
    return OBJECTIVES[name]


# ---------------------------------------------------------------- duplicate detection
class DuplicateTable:
    """Best recorded cost per canonical state (summed cost: a duplicate with no better g is dropped)."""

    def __init__(self) -> None:
        self.best: dict[tuple[object, ...], int] = {}

    def __len__(self) -> int:
        return len(self.best)

    def record(self, key: tuple[object, ...], node: Node) -> bool:
        """Keep the node unless a recorded node with the same state is at least as good."""
        old = self.best.get(key)
        if old is not None and old <= node.g:
            return False
        self.best[key] = node.g
        return True

    def stale(self, key: tuple[object, ...], node: Node) -> bool:
        """Was a cheaper node with the same state recorded after this one was queued?"""
        old = self.best.get(key)
        return old is not None and old < node.g


class DominanceTable(DuplicateTable):
    """For the makespan a duplicate is dropped only if its cost and every clock and ready time are no
    better than those of a recorded node (the schedule's future depends on them)."""

    def __init__(self, cap_class: list[int], n_objects: int) -> None:
        super().__init__()
        self.cap_class = cap_class
        self.n_objects = n_objects
        self.entries: dict[tuple[object, ...], list[tuple[int, tuple[object, ...]]]] = {}
        self.count = 0  # entries in all lists, kept as they change: the search asks after every expansion

    def __len__(self) -> int:
        return self.count

    def times(self, node: Node) -> tuple[object, ...]:
        """What makes one node's future schedule no worse than another's."""
        hand = node.sim.hand
        order = sorted(range(len(node.cell)),
                       key=lambda r: (node.cell[r], hand.get(r, -1), self.cap_class[r], node.clock[r]))
        touched = tuple(node.obj_t.get(i, 0) for i in range(self.n_objects))
        clocks = tuple(node.clock[r] for r in order)
        return (clocks, node.leaf_t, node.done_t, node.last_done, node.ms, touched)

    def record(self, key: tuple[object, ...], node: Node) -> bool:
        tv = self.times(node)
        entries = self.entries.get(key)
        if entries is None:
            self.entries[key] = [(node.g, tv)]
            self.count += 1
            return True
        for g, other in entries:
            if g <= node.g and _leq(other, tv):
                return False
        kept = [(g, o) for g, o in entries if not (node.g <= g and _leq(tv, o))]
        self.count += len(kept) + 1 - len(entries)
        entries[:] = kept
        entries.append((node.g, tv))
        return True

    def stale(self, key: tuple[object, ...], node: Node) -> bool:
        return False


def _leq(a: object, b: object) -> bool:
    """Elementwise a <= b over nested tuples of ints."""
    if isinstance(a, tuple) and isinstance(b, tuple):
        return all(_leq(x, y) for x, y in zip(a, b, strict=True))
    return a <= b  # type: ignore[operator]
