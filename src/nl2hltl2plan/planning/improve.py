"""Local search on a plan's events: give a segment to another robot, or move it in the order.

A *segment* is what one robot does for one leaf between two empty-hand moments (pick the apple,
open the fridge, put it in), or a single empty-handed action. The beam search decides segments one
at a time and can leave a poor allocation (two robots swapping halves of their tasks); these moves
repair that. Every candidate is evaluated by replaying the whole event list through the planner's
transition relation (preconditions, bindings, orderings and the schedule are all re-checked, stand
cells re-chosen), and kept only if the objective improves: first improvement, until no move helps
or the budget of evaluated candidates (machine-independent, so the result is deterministic) is spent.
"""

from __future__ import annotations

from collections.abc import Callable

from nl2hltl2plan.planning.extract import reaching, replay_from
from nl2hltl2plan.planning.node import Event, Node
from nl2hltl2plan.planning.objective import Objective
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.planning.support import SUPPORT


def segments(x: Expander, events: list[Event]) -> list[list[int]]:
    """Indices of the events of each segment, in order of their first event."""
    node: Node | None = x.root()
    open_seg: dict[int, list[int]] = {}  # robot -> the segment it is in while holding something
    out: list[list[int]] = []
    for i, e in enumerate(events):
        if e.k == SUPPORT:
            continue  # re-inserted by the action it serves
        seg = open_seg.get(e.robot)
        if seg is not None and events[seg[0]].leaf == e.leaf and e.k >= 0:
            seg.append(i)
        else:
            seg = [i]
            out.append(seg)
        node = replay_from(x, node, [e], keep_stands=False) if node is not None else None
        if node is None:
            return []
        if node.sim.hand.get(e.robot, -1) >= 0 and e.k >= 0:
            open_seg[e.robot] = seg
        else:
            open_seg.pop(e.robot, None)
    return out


def improve(x: Expander, goal: Node, objective: Objective, max_evals: int,
            check_time: Callable[[], None]) -> Node:
    """A goal node at least as good as `goal`, after at most `max_evals` candidate replays
    (`check_time` raises when the wall-clock last resort runs out)."""
    best = goal
    best_val = objective.value(goal)
    evals = 0
    improved = True
    while improved and evals < max_evals:
        improved = False
        events = best.events()
        path = _path(best)  # path[i]: the node after the first i events
        segs = segments(x, events)
        for seg in segs:
            if evals >= max_evals:
                break
            if any(events[i].k < 0 for i in seg):
                continue
            for start, cand in _candidates(x, events, segs, seg):
                if evals >= max_evals:
                    break
                check_time()
                evals += 1
                end = replay_from(x, path[start], cand[start:], keep_stands=False,
                                  cutoff=reaching(objective, best_val))
                if end is None or not x.is_goal(end):
                    continue
                val = objective.value(end)
                if val < best_val:
                    best, best_val = end, val
                    improved = True
                    break
            if improved:
                break
    return best


def _candidates(x: Expander, events: list[Event], segs: list[list[int]],
                seg: list[int]) -> list[tuple[int, list[Event]]]:
    """(first changed index, events) for the segment given to each other robot, then moved to
    each other place in the order (nearest first)."""
    owner = events[seg[0]].robot
    first = seg[0]
    candidates: list[tuple[int, list[Event]]] = []  # (first changed index, events)
    for r in range(x.p.n_robots):  # the same events, done by another robot
        if r != owner:
            moved = list(events)
            for i in seg:
                e = moved[i]
                moved[i] = Event(r, e.leaf, e.atom, e.verb, e.objs, -1, 0, 0, e.k, e.anchor)
            candidates.append((first, moved))
    inside = set(seg)
    rest = [e for i, e in enumerate(events) if i not in inside]
    block = [events[i] for i in seg]
    # the segment earlier or later in the order: before another segment, nearest first
    starts = sorted({len(rest)} | {sum(1 for i in range(s2[0]) if i not in inside)
                                   for s2 in segs if s2 is not seg}, key=lambda p: (abs(p - first), p))
    for pos in starts:
        if pos != first:
            candidates.append((min(pos, first), rest[:pos] + block + rest[pos:]))
    return candidates


def _path(goal: Node) -> list[Node]:
    nodes = []
    node: Node | None = goal
    while node is not None:
        nodes.append(node)
        node = node.parent
    return nodes[::-1]
