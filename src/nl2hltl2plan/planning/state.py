"""The transition relation (`Expander`): the events a node (`node.Node`) allows, one robot walking
to a region and doing one leaf action, and the child each makes.

A node holds the executor's own state (`SimState`: objects, robot cells, hands), so every event the
search generates is checked by the same precondition code that later executes the plan. The times
in a node make the schedule:

- a robot's clock is the step of its last action; an event happens at
  max(clock + walking steps, ready) + 1, where `ready` is the latest step at which any object the
  event touches (reads or writes: the object, the containers around it, what is inside it, the
  faucet filling a basin) was last touched, the leaf's previous event, and, for a leaf's first
  event, the completion of every task that must precede it. Events that touch a common object are
  therefore strictly ordered in time as in the search order, and the executor, which applies the
  actions of one step in robot order, reproduces the search's state exactly.
- the waits this creates are the timed schedule ("wait where a robot depends on another's task").

Decomposition (Luo & Liu's decomposition states): a leaf can pass to another robot whenever the
robot working on it has an empty hand, because every robot may do a leaf's next action; a robot
holding a leaf's object is the only one that can put it down.
"""

from __future__ import annotations

import numpy as np

from nl2hltl2plan.planning.leaves import DONE, Leaf, LeafAtom
from nl2hltl2plan.planning.model import Problem
from nl2hltl2plan.planning.navigation import INF, Navigator
from nl2hltl2plan.planning.node import Event, Node, Reach, bound, put
from nl2hltl2plan.planning.support import blockers, support_event
from nl2hltl2plan.worlds.checker import state_events
from nl2hltl2plan.worlds.simulator import PRESENT, SimState


class Expander:
    """Generates successor events of a node (the planner's transition relation)."""

    def __init__(self, problem: Problem, nav: Navigator):
        self.p = problem
        self.nav = nav
        self.world = problem.world
        self.sim0 = SimState(problem.world)
        for r, c in enumerate(problem.starts):
            self.sim0.place_robot(r, c)
        self.comp = self.sim0.c
        self.types = self.comp.types
        self.n_objects = len(self.types)
        self.by_type: dict[str, list[int]] = {}
        for i, t in enumerate(self.types):
            self.by_type.setdefault(t, []).append(i)
        self.slice_of = [self.comp.index.get(o.slice_of, -1) if o.slice_of else -1
                         for o in self.world.objects.values()]
        # a Faucet fills one SinkBasin: a leaf's Faucet and SinkBasin must match
        self.serves = self.comp.serves
        # put-down surfaces for an object nobody needs in hand any more (after examine_in_light)
        self.surfaces: dict[str, list[int]] = {}
        self.slot = problem.node_slot
        self.leaf_slot = [self.slot[lf.name] for lf in problem.leaves]
        classes = list(dict.fromkeys(problem.capabilities))  # robots with equal capabilities
        self.cap_class = [classes.index(c) for c in problem.capabilities]
        self.gate_slots = {i: tuple(self.slot[g] for g in gates) for i, gates in problem.gates.items()}
        self.missing_support: set[str] = set()  # support actions (open/close) no robot may do
        self.blocked_by: set[str] = set()  # constraints that forbade some event (`forbids`)

    # ------------------------------------------------------------ root
    def root(self) -> Node:
        p = self.p
        done = [-1] * len(p.node_names)
        for lf in p.leaves:
            if lf.init == DONE:
                done[self.slot[lf.name]] = 0
        n = Node(
            sim=self.sim0.copy(), cell=tuple(self.nav.cell_index[c] for c in p.starts),
            clock=(0,) * p.n_robots, q=tuple(lf.init for lf in p.leaves), bind=tuple(() for _ in p.leaves),
            claimed=frozenset(), nq=tuple(nl.init for nl in p.nonleaves), done_t=tuple(done),
            leaf_t=(0,) * len(p.leaves), obj_t={}, last_done=0, g=0, ms=0,
        )
        # leaves satisfied from the start complete their ancestors at step 0
        for lf in p.leaves:
            if lf.init == DONE:
                res = self._propagate(n, lf.name, 0, list(n.nq), list(n.done_t))
                if res is None:
                    raise ValueError(f"{lf.name} holds from the start but breaks an ordering")
                n.nq, n.done_t = tuple(res[0]), tuple(res[1])
        return n

    def is_goal(self, node: Node) -> bool:
        slot = self.slot
        return all(node.done_t[slot[r]] >= 0 for r in self.p.roots)

    # ------------------------------------------------------------ enabling (orderings)
    def enabled(self, node: Node, leaf: Leaf) -> bool:
        """May the leaf start now? Only when completing it (and its ancestors) now would break no
        ordering: under precedence form, every task that must precede it is complete."""
        p = self.p
        if p.precedence:
            done = node.done_t
            return all(done[s] >= 0 for s in self.gate_slots[leaf.index])
        name = leaf.name
        while p.parent.get(name) is not None:
            par = p.parent[name]
            nl = p.nonleaves[p.nonleaf_index[par]]  # type: ignore[index]
            q = node.nq[nl.index]
            if q == DONE:
                return False  # the parent is already satisfied: this task is not needed
            finished = frozenset(c for c in nl.children if node.done_t[self.slot[c]] >= 0)
            q2 = p.step_parent(nl.index, q, name, finished)
            if q2 is None:
                return False
            if q2 != DONE:
                return True
            name = par  # type: ignore[assignment]
        return True

    def _propagate(self, node: Node, name: str, t: int, nq: list[int], done: list[int]):
        """Completion of `name` at step t climbs the hierarchy; None if it breaks an ordering."""
        p = self.p
        while p.parent.get(name) is not None:
            par = p.parent[name]
            nl = p.nonleaves[p.nonleaf_index[par]]  # type: ignore[index]
            q = nq[nl.index]
            if q == DONE:
                break
            finished = frozenset(c for c in nl.children if c != name and done[self.slot[c]] >= 0)
            q2 = p.step_parent(nl.index, q, name, finished)
            if q2 is None:
                return None
            nq[nl.index] = q2
            if q2 != DONE:
                break
            done[self.slot[par]] = t  # type: ignore[index]
            name = par  # type: ignore[assignment]
        return nq, done

    # ------------------------------------------------------------ candidates
    def candidates(self, node: Node, leaf: Leaf, atom: LeafAtom, pos: int) -> list[int]:
        """Instances the atom's pos-th type may bind to (the bound one if any)."""
        type_ = atom.types[pos]
        b = bound(node, leaf.index, type_)
        if b >= 0:
            return [b]
        out = self.by_type.get(type_, [])
        if node.claimed and (type_ in leaf.taken or (pos == 0 and atom.verb in ("pickup", "slice"))):
            # an object another task took for itself is off limits, also as a tool (a knife being
            # cleaned is not the one to slice with); as a mere receptacle it may still be used
            out = [o for o in out if o not in node.claimed]
        if type_ == "Faucet":
            basin = bound(node, leaf.index, "SinkBasin")
            if basin >= 0:
                out = [o for o in out if self.serves[o] == basin] or out
        elif type_ == "SinkBasin":
            faucet = bound(node, leaf.index, "Faucet")
            if faucet >= 0 and self.serves[faucet] >= 0:
                out = [self.serves[faucet]]
        return out

    def bindings(self, node: Node, leaf: Leaf, atom: LeafAtom, robot: int,
                 ordered: bool) -> list[tuple[int, ...]]:
        """Object tuples for the atom (`ordered`: nearest instances first)."""
        sim = node.sim
        lists = []
        for pos in range(len(atom.types)):
            cands = self.candidates(node, leaf, atom, pos)
            if pos == 0 and atom.verb in ("pickup", "slice"):
                cands = [o for o in cands if self._present_or_coming(sim, o)]
            if ordered and len(cands) > 1:
                cands = self._nearest_first(node, robot, cands, leaf, atom)
            lists.append(cands)
        if len(lists) == 1:
            return [(o,) for o in lists[0]]
        return [(a, b) for a in lists[0] for b in lists[1] if a != b]

    def _present_or_coming(self, sim: SimState, o: int) -> bool:
        src = self.slice_of[o]
        return bool(sim.flags[o] & PRESENT) or (src >= 0 and bool(sim.flags[src] & PRESENT))

    def _nearest_first(
        self, node: Node, robot: int, cands: list[int], leaf: Leaf, atom: LeafAtom
    ) -> list[int]:
        cell = node.cell[robot]
        nav = self.nav
        opener = atom.verb == "open" and self._opens_for(node, leaf, atom)

        def key(o: int) -> tuple[int, int, int]:
            a = nav.anchor(node.sim, o)
            d = nav.dist(cell, a) if a >= 0 else INF
            return (0 if not opener or o in opener else 1, d, o)

        return sorted(cands, key=key)

    def _opens_for(self, node: Node, leaf: Leaf, atom: LeafAtom) -> set[int]:
        """Openables of the atom's type that hold a candidate of a type the leaf picks up later."""
        sim = node.sim
        target = atom.types[0]
        out: set[int] = set()
        for a in leaf.atoms:
            if a.verb != "pickup" or bound(node, leaf.index, a.types[0]) >= 0:
                continue
            for o in self.by_type.get(a.types[0], []):
                x = sim.parent[o]
                while x >= 0:
                    if self.types[x] == target:
                        out.add(x)
                    x = sim.parent[x]
        return out

    # ------------------------------------------------------------ touching (schedule dependencies)
    def touched(self, sim: SimState, verb: str, objs: tuple[int, ...], robot: int) -> list[int]:
        def chain(x: int) -> list[int]:
            out = []
            while x >= 0:
                out.append(x)
                x = sim.parent[x]
            return out

        o = objs[0]
        if verb == "pickup":
            return chain(o) + sim.subtree(o)
        if verb == "put":
            rec = chain(objs[1])
            faucets = [f for y in rec for f in self.comp.faucets_of.get(y, ())]
            return sim.subtree(o) + rec + faucets
        if verb in ("open", "close"):
            return chain(o)
        if verb in ("toggle_on", "toggle_off"):
            out = chain(o) + sim.subtree(o)
            if self.serves[o] >= 0:
                out += sim.subtree(self.serves[o])
            return out
        if verb == "slice":
            knife = sim.hand.get(robot, -1)
            return chain(o) + list(self.comp.slices[o]) + ([knife] if knife >= 0 else [])
        return [o]

    # ------------------------------------------------------------ one event
    def apply(self, node: Node, robot: int, leaf: Leaf, atom_k: int, objs: tuple[int, ...],
              q_next: int, stand: int | None = None) -> Node | None:
        """The child after `robot` does leaf's atom on `objs` (from the nearest cell of the region, or
        from `stand`), or None if it cannot."""
        atom = leaf.atoms[atom_k]
        verb = atom.verb
        if not self.p.can_do(robot, atom):
            return None
        for pos, type_ in enumerate(atom.types):  # replays of reordered events must respect this too
            taking = type_ in leaf.taken or (pos == 0 and verb in ("pickup", "slice"))
            if taking and objs[pos] in node.claimed and bound(node, leaf.index, type_) < 0:
                return None  # another task's object
        sim = node.sim
        hand = sim.hand.get(robot, -1)
        if verb == "pickup" and hand >= 0:
            return None
        if verb == "put" and hand != objs[0]:
            return None
        if verb == "slice" and hand < 0:
            return None
        if node.leaf_t[leaf.index] == 0 and not self.enabled(node, leaf):
            return None  # replays (local search) rely on this; successors() filters it already
        needs = blockers(sim, verb, objs)
        if needs:  # open what is in the way first (support actions), then act
            cur: Node | None = node
            for s_verb, s_obj in needs:
                cur = support_event(self, cur, robot, leaf.index, s_verb, s_obj) if cur is not None else None
            return None if cur is None else self.apply(cur, robot, leaf, atom_k, objs, q_next, stand)
        if verb == "pickup" and not sim.flags[objs[0]] & PRESENT:
            return None  # a slice still to come: the action would fail (no state copied to see it)
        anchor = self.nav.anchor(sim, objs[-1])
        if anchor < 0 or not len(self.nav.region_idx[anchor]):
            return None
        child_sim = sim.copy()
        # the action's preconditions first (from some cell of the region), the walk only if it can
        child_sim.pos[robot] = self.nav.cells[int(self.nav.region_idx[anchor][0])]
        if child_sim.act(robot, verb, list(objs)) is not None:
            return None
        stand, d, reach = self.walk(node, robot, anchor, stand)
        if d >= INF:
            return None
        touched = self.touched(sim, verb, objs, robot)  # in the state before the action
        child_sim.pos[robot] = self.nav.cells[stand]
        li = leaf.index
        ready = node.leaf_t[li]
        obj_t = node.obj_t
        for x in touched:
            tx = obj_t.get(x, 0)
            if tx > ready:
                ready = tx
        if node.leaf_t[li] == 0:
            if self.p.precedence:
                for s in self.gate_slots[li]:
                    if node.done_t[s] > ready:
                        ready = node.done_t[s]
            elif node.last_done > ready:
                ready = node.last_done
        t = max(node.clock[robot] + d, ready) + 1
        if self.p.constraints and self.forbids(atom.text, node, t, child_sim):
            return None
        nq, done = node.nq, node.done_t
        last_done = node.last_done
        if q_next == DONE:
            if not self.p.precedence and t <= last_done:
                t = last_done + 1  # general formulas: one completion per step, in search order
            res = self._propagate(node, leaf.name, t, list(nq), list(done))
            if res is None:
                return None
            nq_l, done_l = res
            done_l[self.leaf_slot[li]] = t
            nq, done = tuple(nq_l), tuple(done_l)
            last_done = max(last_done, t)
        q = list(node.q)
        q[li] = q_next
        bind = node.bind[li]
        claimed = node.claimed
        for pos, type_ in enumerate(atom.types):
            if bound(node, li, type_) < 0:
                bind = tuple(sorted(bind + ((type_, objs[pos]),)))
                if type_ in leaf.taken:
                    claimed = claimed | {objs[pos]}
        binds = node.bind
        if bind is not node.bind[li]:
            binds_l = list(node.bind)
            binds_l[li] = bind
            binds = tuple(binds_l)
        leaf_t = list(node.leaf_t)
        leaf_t[li] = t
        new_obj_t = dict(obj_t)
        for x in touched:
            new_obj_t[x] = t
        return Node(
            sim=child_sim, cell=put(node.cell, robot, stand), clock=put(node.clock, robot, t), q=tuple(q),
            bind=binds, claimed=claimed, nq=nq, done_t=done, leaf_t=tuple(leaf_t), obj_t=new_obj_t,
            last_done=last_done, g=node.g + d + 1, ms=max(node.ms, t), parent=node,
            event=Event(robot, li, atom.text, verb, objs, stand, d, t, atom_k, anchor), reach=reach,
        )

    def forbids(self, atom: str, node: Node, t: int, after: SimState) -> bool:
        """Does a constraint forbid `atom` at step t after `node`, or a change of state it makes (`after`)?"""
        states = state_events(self.types, node.sim.flags, after.flags) if self.p.watches_states else []
        banned = self.p.forbidden_by([atom, *states], node.done_t, t)
        if banned is not None:
            self.blocked_by.add(banned.describe())
        return banned is not None

    def walk(self, node: Node, robot: int, anchor: int,
             stand: int | None = None) -> tuple[int, int, tuple[Reach | None, ...] | None]:
        """(stand cell, steps, the child's reach) for `robot` to act in the anchor's region: the
        nearest cell (or `stand`); with free stand cells (a node with a `reach`: `with_free_stands`),
        every region cell stays open and `steps` is the least extra walking (a layered shortest
        path, resolved when the plan is written)."""
        cell = node.cell[robot]
        if node.reach is None or stand is not None:
            if stand is None:
                stand, d = self.nav.nearest(cell, anchor)
            else:
                d = int(self.nav.dm[cell, stand])
            reach = None if node.reach is None else put(node.reach, robot, None)
            return stand, d, reach
        old = node.reach[robot] if node.reach is not None else None
        cells, offsets = old if old is not None else ((cell,), (0,))
        region = self.nav.region_idx[anchor]
        if not len(region):
            return -1, INF, None
        arrive = (self.nav.dm[np.array(cells)[:, None], region] + np.array(offsets)[:, None]).min(axis=0)
        k = int(arrive.argmin())
        d = int(arrive[k])
        if d >= INF:
            return -1, INF, None
        ok = arrive < INF
        new: Reach = (tuple(region[ok].tolist()), tuple((arrive[ok] - d).tolist()))
        base = node.reach if node.reach is not None else (None,) * len(node.cell)
        return int(region[k]), d, put(base, robot, new)

    def put_down(self, node: Node, robot: int, surface: int, leaf: int,
                 stand: int | None = None) -> Node | None:
        """Put a held object nobody needs any more on a surface (attributed to its finished leaf)."""
        sim = node.sim
        obj = sim.hand.get(robot, -1)
        anchor = self.nav.anchor(sim, surface)
        caps = self.p.capabilities[robot]
        if obj < 0 or anchor < 0 or (caps is not None and "put" not in caps):
            return None
        if leaf >= 0 and node.q[leaf] != DONE:
            return None  # held until its task is done (examine: until the lamp is on)
        stand, d, reach = self.walk(node, robot, anchor, stand)
        if d >= INF:
            return None
        objs = (obj, surface)
        touched = self.touched(sim, "put", objs, robot)
        child_sim = sim.copy()
        child_sim.pos[robot] = self.nav.cells[stand]
        if child_sim.act(robot, "put", list(objs)) is not None:
            return None
        ready = max((node.obj_t.get(x, 0) for x in touched), default=0)
        if leaf >= 0:
            ready = max(ready, node.leaf_t[leaf])  # held until its task is done (examine: lamp on)
        t = max(node.clock[robot] + d, ready) + 1
        atom = f"put({self.types[obj]},{self.types[surface]})"
        if self.p.constraints and self.forbids(atom, node, t, child_sim):
            return None
        obj_t = dict(node.obj_t)
        for x in touched:
            obj_t[x] = t
        return Node(
            sim=child_sim, cell=put(node.cell, robot, stand), clock=put(node.clock, robot, t), q=node.q,
            bind=node.bind, claimed=node.claimed, nq=node.nq, done_t=node.done_t, leaf_t=node.leaf_t,
            obj_t=obj_t, last_done=node.last_done, g=node.g + d + 1, ms=max(node.ms, t), parent=node,
            event=Event(robot, leaf, atom, "put", objs, stand, d, t, -1, anchor), reach=reach,
        )

    def surfaces_for(self, obj: int) -> list[int]:
        type_ = self.types[obj]
        hit = self.surfaces.get(type_)
        if hit is None:
            hit = [
                i for i, o in enumerate(self.world.objects.values())
                if type_ in o.affordances.accepts and not o.affordances.openable and not o.pickupable
                and o.interaction_cells and o.present
            ]
            self.surfaces[type_] = hit
        return hit

    # ------------------------------------------------------------ all successors
    def successors(self, node: Node, limit: int | None = None, macro: bool = False,
                   robots: frozenset[int] | None = None) -> list[Node]:
        """Every event any robot (of `robots`, when given: the single-robot seeds) can do next
        (`limit`: nearest instances only; `macro`: a robot that picked something up carries on
        with that leaf until its hand is empty)."""
        p = self.p
        out: list[Node] = []
        seen_robot: set[tuple] = set()
        sim = node.sim
        leaf_enabled = [
            node.q[lf.index] != DONE and (node.leaf_t[lf.index] > 0 or self.enabled(node, lf))
            for lf in p.leaves
        ]
        holder_leaf = self._held_leaves(node)
        acting = []
        for robot in range(p.n_robots):
            if robots is not None and robot not in robots:
                continue
            hand = sim.hand.get(robot, -1)
            situation = (node.cell[robot], hand, self.cap_class[robot], node.clock[robot],
                         node.reach[robot] if node.reach is not None else None)
            if hand < 0 and situation in seen_robot:
                continue  # robots in identical situations are interchangeable
            seen_robot.add(situation)
            acting.append(robot)
            if hand >= 0 and holder_leaf.get(hand, -1) < 0:
                out.extend(self._put_downs(node, robot, hand, limit))
        for leaf in p.leaves:
            if not leaf_enabled[leaf.index]:
                continue
            for atom_k, q_next in leaf.moves[node.q[leaf.index]]:
                atom = leaf.atoms[atom_k]
                able = [robot for robot in acting if p.can_do(robot, atom)]
                if limit is not None and len(able) > limit:
                    able = self._closest_robots(node, leaf, atom, able)[:limit]
                for robot in able:
                    made = 0
                    for objs in self.bindings(node, leaf, atom, robot, limit is not None):
                        child = self.apply(node, robot, leaf, atom_k, objs, q_next)
                        if child is None:
                            continue
                        if macro and atom.verb == "pickup":
                            child = self.carry_on(child, robot, leaf)
                        out.append(child)
                        made += 1
                        if limit is not None and made >= limit:
                            break  # restricted successors: the nearest few instances that work
        return out

    def _closest_robots(self, node: Node, leaf: Leaf, atom: LeafAtom, robots: list[int]) -> list[int]:
        """Robots ordered by when they could reach the atom's nearest candidate (restricted mode)."""
        sim = node.sim
        holder = {sim.hand.get(r, -1): r for r in robots}
        for _, o in node.bind[leaf.index]:
            if o in holder:
                return [holder[o]] + [r for r in robots if r != holder[o]]  # the one carrying it first
        cands = self.candidates(node, leaf, atom, len(atom.types) - 1)
        anchors = {a for o in cands if (a := self.nav.anchor(sim, o)) >= 0}
        if not anchors:
            return robots
        fields = [self.nav.field(a) for a in anchors]

        def reach(r: int) -> tuple[int, int]:
            c = node.cell[r]
            return (node.clock[r] + min(f[c] for f in fields), r)

        return sorted(robots, key=reach)

    def _held_leaves(self, node: Node) -> dict[int, int]:
        """Held object -> the unfinished leaf that bound it (absent: nobody needs it in hand)."""
        out = {}
        for lf in self.p.leaves:
            if node.q[lf.index] == DONE:
                continue
            for _, o in node.bind[lf.index]:
                out[o] = lf.index
        return out

    def _put_downs(self, node: Node, robot: int, obj: int, limit: int | None) -> list[Node]:
        leaf = next((lf.index for lf in self.p.leaves for _, o in node.bind[lf.index] if o == obj), -1)
        surfaces = self.surfaces_for(obj)
        cell = node.cell[robot]
        surfaces = sorted(surfaces, key=lambda s: (self.nav.dist(cell, s), s))
        out = []
        for s in surfaces:
            child = self.put_down(node, robot, s, leaf)
            if child is not None:
                out.append(child)
                if limit is not None and len(out) >= limit:
                    break
        return out

    def carry_on(self, node: Node, robot: int, leaf: Leaf) -> Node:
        """Macro step: while the robot holds something for this leaf, do the leaf's next action
        (nearest choice) until the hand is empty, the leaf is done or nothing applies."""
        while node.sim.hand.get(robot, -1) >= 0 and node.q[leaf.index] != DONE:
            options = [(k, q_next, objs) for k, q_next in leaf.moves[node.q[leaf.index]]
                       if self.p.can_do(robot, leaf.atoms[k])
                       for objs in self.bindings(node, leaf, leaf.atoms[k], robot, True)]
            # the first option of least cost; tried cheapest first by a lower bound on the child's
            # cost, so the options that cannot win are never applied
            order = sorted((self._least_g(node, robot, objs), i) for i, (_, _, objs) in enumerate(options))
            best: Node | None = None
            best_i = -1
            for least, i in order:
                if best is not None and (least, i) > (best.g, best_i):
                    break
                k, q_next, objs = options[i]
                child = self.apply(node, robot, leaf, k, objs, q_next)
                if child is not None and (best is None or (child.g, i) < (best.g, best_i)):
                    best, best_i = child, i
            if best is None:
                break
            node = best
        return node

    def _least_g(self, node: Node, robot: int, objs: tuple[int, ...]) -> int:
        """A lower bound on the cost of the child in which `robot` acts on `objs` (support actions
        first only add to it: a detour is never shorter, by the triangle inequality)."""
        anchor = self.nav.anchor(node.sim, objs[-1])
        if anchor < 0 or node.reach is not None:
            return node.g + 1
        return node.g + 1 + self.nav.nearest(node.cell[robot], anchor)[1]
