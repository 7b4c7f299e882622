"""Search nodes and events: the state the planner searches over (`state.Expander` makes them).

A node holds the executor's own state (`SimState`: objects, robot cells, hands), each leaf's progress
and type bindings (within a leaf a type binds to one instance), the non-leaf DFA states and the
times that make the schedule; an event is one robot walking to a region and doing one leaf action.
Children share nothing mutable with their parents.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TypeVar

from nl2hltl2plan.worlds.simulator import SimState

T = TypeVar("T")


@dataclass(slots=True, frozen=True)
class Event:
    robot: int
    leaf: int
    atom: str  # type-level atom, e.g. put(Apple,Fridge)
    verb: str
    objs: tuple[int, ...]  # object indices
    stand: int  # cell index the robot acts from
    travel: int  # cells walked to get there
    t: int  # step of the action
    k: int  # atom index in the leaf (-1: putting down an object nobody needs)
    anchor: int  # object whose interaction region the robot stands in


Binding = tuple[tuple[str, int], ...]  # a leaf's (type, object index) pairs, sorted
Reach = tuple[tuple[int, ...], tuple[int, ...]]  # cells a robot may stand on, extra cost of each (min 0)


@dataclass(slots=True, eq=False)
class Node:
    """A search state; children share nothing mutable with their parent."""

    sim: SimState  # the executor's state: objects, robot cells, hands
    cell: tuple[int, ...]  # per robot, its cell index
    clock: tuple[int, ...]  # per robot, the step of its last action
    q: tuple[int, ...]  # per leaf, its progress (trie node) or DONE
    bind: tuple[Binding, ...]  # per leaf, its type bindings
    claimed: frozenset[int]  # objects some leaf took for itself
    nq: tuple[int, ...]  # per non-leaf, its DFA state or DONE
    done_t: tuple[int, ...]  # per spec node (leaves, then non-leaves), completion step or -1
    leaf_t: tuple[int, ...]  # per leaf, the step of its last event (0: not started)
    obj_t: dict[int, int]  # object -> the last step it was touched
    last_done: int  # the latest completion step
    g: int  # moves + actions so far
    ms: int  # makespan so far
    parent: Node | None = None
    event: Event | None = None
    h: int | None = None  # heuristic (summed cost); None until evaluated
    ms_lb: int = 0  # lower bound on the final makespan
    f: int = 0  # admissible bound on the objective (objective units of the search)
    closed: bool = False
    memo: tuple[object, ...] | None = None  # the duplicate-detection key, once computed
    # free stand cells (exact summed cost): per robot, every cell of its last region with the extra
    # walking it costs to have stood there (`cell` holds the cheapest); None: nearest-cell model
    reach: tuple[Reach | None, ...] | None = None

    def events(self) -> list[Event]:
        out = []
        node: Node | None = self
        while node is not None and node.event is not None:
            out.append(node.event)
            node = node.parent
        return out[::-1]


def put(values: tuple[T, ...], i: int, value: T) -> tuple[T, ...]:
    """`values` with the i-th replaced by `value` (per-robot tuples of a child node)."""
    out = list(values)
    out[i] = value
    return tuple(out)


def with_free_stands(node: Node) -> Node:
    """The same state, searched with free stand cells from here on: every event's stand cell stays
    open among its region's cells (`Expander.walk`; the grid optimum of the summed cost)."""
    return replace(node, reach=(None,) * len(node.cell), memo=None, closed=False)


def bound(node: Node, leaf: int, type_: str) -> int:
    """The object `leaf` has bound `type_` to at `node`, or -1."""
    for bound_type, obj in node.bind[leaf]:
        if bound_type == type_:
            return obj
    return -1
