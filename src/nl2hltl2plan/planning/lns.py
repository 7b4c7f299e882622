"""Large-neighbourhood search on a plan: take tasks out, put them back where they cost least.

The local search of `improve.py` moves one segment at a time, either to another robot or to another
place in the order. Here, in this order until nothing improves: a whole leaf (all its events, its
put-downs included) is taken out and re-inserted as one block, done by one robot, at the cheapest
(robot, place); each segment is moved to its cheapest (robot, place); a leaf is done with another
instance of one of its objects (the plate by the side table instead of the one by the watch), at
its cheapest (robot, place); two leaves are taken out together and re-inserted one after the other,
each at its cheapest (ruin and recreate). Every candidate is replayed through the transition
relation (preconditions, bindings, orderings, schedule; support actions re-inserted where the new
order needs them), and a change is kept only if the objective improves. Candidates are tried in a
fixed order and counted in replays, so the result is the same on every machine; `plan()` validates
whatever comes out.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from itertools import combinations

from nl2hltl2plan.planning.extract import reaching, replay_from
from nl2hltl2plan.planning.improve import segments
from nl2hltl2plan.planning.node import Event, Node
from nl2hltl2plan.planning.objective import Objective
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.planning.support import SUPPORT


class _Budget:
    """Replays left (machine-independent), and the wall-clock last resort."""

    def __init__(self, evals: int, check_time: Callable[[], None]):
        self.left = evals
        self.check_time = check_time

    def take(self) -> bool:
        if self.left <= 0:
            return False
        self.check_time()
        self.left -= 1
        return True


def _as_robot(events: Sequence[Event], robot: int) -> list[Event]:
    """The events done by `robot`, at stand cells the replay chooses again."""
    return [Event(robot, e.leaf, e.atom, e.verb, e.objs, -1, 0, 0, e.k, e.anchor) for e in events]


def _prefixes(x: Expander, rest: list[Event]) -> list[Node]:
    """prefix[i]: the node after the first i events of `rest` (as long as they replay)."""
    out = [x.root()]
    for e in rest:
        node = replay_from(x, out[-1], [e], keep_stands=False)
        if node is None:
            break
        out.append(node)
    return out


def _best_insertion(x: Expander, objective: Objective, rest: list[Event], block: list[Event],
                    budget: _Budget, goal: bool,
                    beat: tuple[int, ...] | None = None) -> tuple[tuple[int, ...], list[Event]] | None:
    """The cheapest way to put `block` (done by one robot) into `rest`, at every place and for
    every robot: (value, events), or None (`goal`: only complete plans count; `beat`: only those
    cheaper than it, so a replay stops as soon as its cost so far reaches it)."""
    best: tuple[tuple[int, ...], list[Event]] | None = None
    prefix = _prefixes(x, rest)
    starts = _leaf_starts(rest)
    for r in range(x.p.n_robots):
        moved = _as_robot(block, r)
        for pos in range(len(prefix)):
            if not _may_insert(rest, pos, r, starts):
                continue
            if not budget.take():
                return best
            bar = beat if best is None else best[0]
            end = replay_from(x, prefix[pos], moved + rest[pos:], keep_stands=False,
                              cutoff=None if bar is None else reaching(objective, bar))
            if end is None or (goal and not x.is_goal(end)):
                continue
            val = objective.value(end)
            if (best is None or val < best[0]) and (beat is None or val < beat):
                best = (val, rest[:pos] + moved + rest[pos:])
    return best


def _leaf_starts(rest: list[Event]) -> set[int]:
    """The positions at which a leaf's first event stands."""
    seen: set[int] = set()
    out = set()
    for pos, e in enumerate(rest):
        if e.leaf not in seen:
            seen.add(e.leaf)
            out.add(pos)
    return out


def _may_insert(rest: list[Event], pos: int, robot: int, starts: set[int]) -> bool:
    """The places worth trying for a block done by `robot`: right before one of its own events, before
    a leaf starts (where the state other leaves leave behind, and their orderings, change) and at
    the end. Between two of the robot's events, other robots' events move its walk by nothing, so
    the other places repeat these for the summed cost."""
    return pos == len(rest) or rest[pos].robot == robot or pos in starts


def _replay(x: Expander, events: list[Event]) -> Node | None:
    return replay_from(x, x.root(), events, keep_stands=False)


def _core(events: list[Event]) -> list[Event]:
    """The events a replay needs (support actions are re-inserted by the actions they serve)."""
    return [e for e in events if e.k != SUPPORT]


def lns(x: Expander, goal: Node, objective: Objective, max_evals: int,
        check_time: Callable[[], None]) -> Node:
    """A goal node at least as good as `goal`, after at most `max_evals` candidate replays."""
    budget = _Budget(max_evals, check_time)
    best, best_val = goal, objective.value(goal)
    improved = True
    while improved and budget.left > 0:
        improved = False
        for step in (_leaf_moves, _segment_moves, _rebind_moves, _pair_moves):
            found = step(x, objective, best, best_val, budget)
            if found is not None:
                best, best_val = found, objective.value(found)
                improved = True
                break
    return best


def _leaves_of(events: list[Event]) -> list[int]:
    return sorted({e.leaf for e in events if e.leaf >= 0})


def _leaf_moves(x: Expander, objective: Objective, best: Node, best_val: tuple[int, ...],
                budget: _Budget) -> Node | None:
    events = _core(best.events())
    for leaf in _leaves_of(events):
        rest = [e for e in events if e.leaf != leaf]
        block = [e for e in events if e.leaf == leaf]
        found = _best_insertion(x, objective, rest, block, budget, goal=True, beat=best_val)
        if found is not None and found[0] < best_val:
            return _replay(x, found[1])
        if budget.left <= 0:
            break
    return None


def _pair_moves(x: Expander, objective: Objective, best: Node, best_val: tuple[int, ...],
                budget: _Budget) -> Node | None:
    """Ruin and recreate: two leaves out, back in one after the other (each at its cheapest)."""
    events = _core(best.events())
    for a, b in combinations(_leaves_of(events), 2):
        rest = [e for e in events if e.leaf not in (a, b)]
        first = _best_insertion(x, objective, rest, [e for e in events if e.leaf == a], budget, goal=False)
        if first is None:
            if budget.left <= 0:
                break
            continue  # the other leaf gates what remains: no partial plan replays
        found = _best_insertion(x, objective, first[1], [e for e in events if e.leaf == b], budget, goal=True,
                                 beat=best_val)
        if found is not None and found[0] < best_val:
            return _replay(x, found[1])
        if budget.left <= 0:
            break
    return None


def _segment_moves(x: Expander, objective: Objective, best: Node, best_val: tuple[int, ...],
                   budget: _Budget) -> Node | None:
    all_events = best.events()
    segs = segments(x, all_events)
    for seg in segs:
        if any(all_events[i].k < 0 for i in seg):
            continue
        inside = set(seg)
        rest = _core([e for i, e in enumerate(all_events) if i not in inside])
        found = _best_insertion(x, objective, rest, [all_events[i] for i in seg], budget, goal=True,
                                 beat=best_val)
        if found is not None and found[0] < best_val:
            return _replay(x, found[1])
        if budget.left <= 0:
            break
    return None


REBIND_INSTANCES = 3  # other instances tried per type (nearest to the one in the plan first)


def _rebind_moves(x: Expander, objective: Objective, best: Node, best_val: tuple[int, ...],
                  budget: _Budget) -> Node | None:
    """A leaf done with another instance of one of its types (the plate by the side table instead
    of the one by the watch), as one block at its cheapest (robot, place)."""
    events = _core(best.events())
    nav = x.nav
    for leaf in _leaves_of(events):
        rest = [e for e in events if e.leaf != leaf]
        block = [e for e in events if e.leaf == leaf]
        used = sorted({o for e in block for o in e.objs})
        for o in used:
            here = nav.anchor(best.sim, o)
            others = [o2 for o2 in x.by_type.get(x.types[o], []) if o2 != o and o2 not in used]
            others.sort(key=lambda o2: (nav.rr(here, a) if here >= 0 and (a := nav.anchor(best.sim, o2)) >= 0
                                        else 1 << 30, o2))
            for o2 in others[:REBIND_INSTANCES]:
                swapped = [_swap(e, o, o2) for e in block]
                found = _best_insertion(x, objective, rest, swapped, budget, goal=True, beat=best_val)
                if found is not None and found[0] < best_val:
                    return _replay(x, found[1])
                if budget.left <= 0:
                    return None
    return None


def _swap(e: Event, old: int, new: int) -> Event:
    objs = tuple(new if o == old else o for o in e.objs)
    anchor = new if e.anchor == old else e.anchor
    return Event(e.robot, e.leaf, e.atom, e.verb, objs, e.stand, e.travel, e.t, e.k, anchor)
