"""Support actions: the opens (and closes) an action needs, inserted by the planner.

Leaves say what a task is (pick the apple, put it in the fridge); whether the fridge must be opened
first depends on the state the plan reaches, so the planner inserts it: before an action whose
object sits inside a closed openable (a drawer, the fridge), or whose receptacle is closed, the
acting robot opens it (outermost first); before switching on an appliance that is open (the
microwave), it closes it. Nothing is opened twice while it stays open, because an open object no
longer blocks anything. A support event is attributed to the leaf it serves (`Event.k == SUPPORT`);
the spec's trace check ignores atoms a leaf does not mention. Replays skip support events: the
action they serve re-inserts exactly the ones the replayed state needs.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.worlds.simulator import OPEN, SimState

if TYPE_CHECKING:
    from nl2hltl2plan.planning.node import Node
    from nl2hltl2plan.planning.state import Expander

SUPPORT = -2  # Event.k of a support action (-1: putting down an object nobody needs)


def blockers(sim: SimState, verb: str, objs: tuple[int, ...]) -> list[tuple[str, int]]:
    """(verb, object) support actions needed before `verb` on `objs` can succeed, in order."""
    aff = sim.c.aff
    target = objs[-1]
    out: list[tuple[str, int]] = []
    x = sim.parent[target]
    if verb == "put" and aff[target].openable and not sim.flags[target] & OPEN:
        out.append(("open", target))  # the receptacle itself (opened after its own holders)
    while x >= 0:
        if aff[x].openable and not sim.flags[x] & OPEN and sim.holder[x] < 0:
            out.append(("open", x))
        x = sim.parent[x]
    out.reverse()  # outermost first
    if verb == "toggle_on" and aff[target].openable and sim.flags[target] & OPEN:
        out.append(("close", target))
    return out


def may_support(x: Expander, robot: int, verb: str, obj: int) -> bool:
    caps = x.p.capabilities[robot]
    return caps is None or verb in caps or f"{verb}({x.types[obj]})" in caps


def support_event(x: Expander, node: Node, robot: int, leaf: int, verb: str, obj: int,
                  stand: int | None = None) -> Node | None:
    """The child after `robot` walks to `obj` and opens / closes it for `leaf` (None if it cannot)."""
    from nl2hltl2plan.planning.node import Event, Node, put

    if not may_support(x, robot, verb, obj):
        if not any(may_support(x, r, verb, obj) for r in range(x.p.n_robots)):
            x.missing_support.add(f"{verb}({x.types[obj]})")  # named if the search finds no plan
        return None
    sim = node.sim
    anchor = x.nav.anchor(sim, obj)
    if anchor < 0:
        return None
    stand, d, reach = x.walk(node, robot, anchor, stand)
    if d >= INF:
        return None
    touched = x.touched(sim, verb, (obj,), robot)
    child_sim = sim.copy()
    child_sim.pos[robot] = x.nav.cells[stand]
    if child_sim.act(robot, verb, [obj]) is not None:
        return None
    ready = max((node.obj_t.get(o, 0) for o in touched), default=0)
    t = max(node.clock[robot] + d, ready) + 1
    if x.p.constraints and x.forbids(f"{verb}({x.types[obj]})", node, t, child_sim):
        return None
    obj_t = dict(node.obj_t)
    for o in touched:
        obj_t[o] = t
    return Node(
        sim=child_sim, cell=put(node.cell, robot, stand), clock=put(node.clock, robot, t), q=node.q,
        bind=node.bind, claimed=node.claimed, nq=node.nq, done_t=node.done_t, leaf_t=node.leaf_t,
        obj_t=obj_t, last_done=node.last_done, g=node.g + d + 1, ms=max(node.ms, t), parent=node,
        event=Event(robot, leaf, f"{verb}({x.types[obj]})", verb, (obj,), stand, d, t, SUPPORT, anchor),
        reach=reach,
    )
