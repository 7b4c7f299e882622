"""Admissible lower bounds on the remaining cost of a node (both objectives).

Summed cost (`min`): every remaining event costs 1 plus the steps its robot walks to it. In any
completion, each pending event e has exactly one immediate predecessor in its robot's sequence:
the robot's current cell (its first future event) or another pending event; and each robot / event
is the immediate predecessor of at most one event. So the walking is at least the cheapest
*assignment* of distinct predecessors to pending events, with cost dist(region(pred), region(e)):

- a pending event cannot be preceded by a later event of its own leaf, nor by an event of a leaf
  that may only start after e's leaf is complete;
- the put of an object carried since a pending pickup is preceded by that pickup or by an action
  done with a full hand (open, close, toggle, slice), never by another pickup or put;
- a robot's put-down of an object nobody needs (after examine_in_light) is not an event here; a walk
  through it is no shorter than the direct walk, so the bound stays a lower bound.
- one hand: a put of X follows only its pickup, the robot holding X, or an action after which the
  hand may hold X (any robot may do a leaf's other actions, so those say nothing about the hand); a
  pickup never follows a moment the hand is full until a pending put.
Unbound types use the nearest of their candidate instances. It is solved exactly with
`scipy.optimize.linear_sum_assignment` (the assignment relaxation of the routing problem). Two more
bounds on the walking (`bounds.py`: the carries, binding-consistent, plus the pickups' approaches;
a spanning tree from the robots) and the pickups' approach and carry as one walk through one cell
of the object's region are computed beside it and the largest is kept; every support open that every
completion needs adds 1 (also one per event, of a family with disjoint openables, whose every
candidate is closed in). At the root, the bound is minimised over the instance choices as well
(`bounds.least_over_bindings`).

Completion time (`minmax`): the largest of (a) the current makespan, (b) each leaf's chain: its
events happen one after another, the first no earlier than a robot can reach it and than the tasks
ordered before it can finish, a carried object's put no earlier than the walk from its pickup, and
(c) the work bound: all robots' clocks plus all remaining work, divided among the robots.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import linear_sum_assignment

from nl2hltl2plan.planning.bounds import (
    Choice,
    carry_legs,
    joint_min,
    least_over_bindings,
    spanning_walk,
)
from nl2hltl2plan.planning.model import DONE, Leaf
from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.opens import forced_closes, forced_opens
from nl2hltl2plan.planning.state import Expander, Node, bound
from nl2hltl2plan.worlds.simulator import PRESENT

BIG = 1 << 20  # forbidden predecessor (finite for the solver)
OTHER, PICKUP, PUT = 0, 1, 2
EMPTY = ""  # the hand right after a put
CACHE_LIMIT = 100_000  # carry minima kept across nodes
EVAL_WORK = 200  # an evaluation's fixed cost, in assignment-matrix cells (measured: ~1.5 ms vs ~7 us a cell)
ROOT_EVALS = 64  # bound evaluations the root's search over instance choices spends (at most)


class Heuristic:
    def __init__(self, expander: Expander, required: set[int], makespan: bool = True):
        self.x = expander
        self.makespan = makespan  # is the completion-time bound needed (objective `minmax`)?
        # work done so far, in cells of assignment matrices solved: machine-independent and
        # proportional to the evaluations' cost, so budgets in it scale with the problem's size
        self.work = 0
        # light: only the assignment of predecessors (the beam seeds rank children with it; every
        # bound here is admissible, the full one is only tighter)
        self.light = False
        self.p = expander.p
        self.nav = expander.nav
        self.required = required  # leaf indices every plan completes
        nav = self.nav
        n_obj = len(nav.ids)
        has_region = [len(r) > 0 for r in nav.region_idx]
        # anchor x anchor walking distances, and anchor x cell (distance fields)
        self.field = np.full((n_obj, len(nav.cells)), INF, dtype=np.int64)
        for a in range(n_obj):
            if has_region[a]:
                self.field[a] = nav.field(a)
        self.rr = np.full((n_obj, n_obj), INF, dtype=np.int64)
        for a in range(n_obj):
            if has_region[a]:
                self.rr[a] = self.field[:, nav.region_idx[a]].min(axis=1)
        np.minimum(self.rr, self.rr.T, out=self.rr)
        self.after = self._after_matrix()
        self._carry_cache: dict[tuple, int] = {}
        self._near_cache: dict[tuple[int, ...], np.ndarray] = {}
        self.root_evals = ROOT_EVALS

    def _near(self, anchors: tuple[int, ...]) -> np.ndarray:
        """Per cell, the walk from the nearest of `anchors`' regions: a pure function of the anchor
        set (a state's events share a few), so it is computed once per set, not once per node."""
        hit = self._near_cache.get(anchors)
        if hit is None:
            if len(self._near_cache) > CACHE_LIMIT // 100:
                self._near_cache.clear()
            hit = self._near_cache[anchors] = self.field[list(anchors)].min(axis=0)
        return hit

    def _after_matrix(self) -> np.ndarray:
        """after[i, j]: leaf j may only start once leaf i is complete (gates, transitively)."""
        p = self.p
        n = len(p.leaves)
        after = np.zeros((n, n), dtype=bool)
        if not p.precedence:
            return after
        under: dict[str, list[int]] = {}
        for lf in p.leaves:
            for name in [lf.name, *p.ancestors(lf.name)]:
                under.setdefault(name, []).append(lf.index)
        for j, gates in p.gates.items():
            for g in gates:
                for i in under.get(g, []):
                    after[i, j] = True
        changed = True
        while changed:  # transitive closure (tiny matrices)
            new = after | ((after.astype(np.int64) @ after.astype(np.int64)) > 0)
            changed = bool((new != after).any())
            after = new
        return after

    # ------------------------------------------------------------ symbolic regions of pending events
    def _anchors_of(self, node: Node, leaf: Leaf, type_: str, verb: str, memo: dict) -> tuple[int, ...]:
        taking = verb in ("pickup", "slice")
        key = (leaf.index, type_, taking)
        hit = memo.get(key)
        if hit is not None:
            return hit
        x = self.x
        sim = node.sim
        anchor = self.nav.anchor
        b = bound(node, leaf.index, type_)
        objs = [b] if b >= 0 else x.by_type.get(type_, [])
        if b < 0 and node.claimed and (taking or type_ in leaf.taken):
            objs = [o for o in objs if o not in node.claimed]
        out = set()
        for o in objs:
            a = anchor(sim, o)
            if a < 0 and x.slice_of[o] >= 0:
                a = anchor(sim, x.slice_of[o])
            if a >= 0:
                out.add(a)
        res = tuple(sorted(out))
        memo[key] = res
        return res

    def _path_events(self, node: Node, leaf: Leaf, path: tuple[int, ...], memo: dict) -> list[tuple]:
        """Per event: (anchors, kind, carried_from position or -1, held_by robot or -1, the type the
        robot must hold when doing it (None: any), the hand right after it (a type; EMPTY; None:
        unknown), whether that hand stays full until a later put of this path)."""
        where: dict[str, tuple[int, ...]] = {}
        picked: dict[str, int] = {}
        held = {}
        sim = node.sim
        for t, o in node.bind[leaf.index]:
            if sim.holder[o] >= 0:
                held[t] = sim.holder[o]
        hand = next(iter(held), None)  # the type this leaf's robot holds (one hand: at most one)
        out = []
        for j, k in enumerate(path):
            atom = leaf.atoms[k]
            target = atom.types[-1]
            anchors = where.get(target)
            if anchors is None:
                anchors = self._anchors_of(node, leaf, target, atom.verb, memo)
            kind = PICKUP if atom.verb == "pickup" else PUT if atom.verb == "put" else OTHER
            carried = picked.get(atom.types[0], -1) if kind == PUT else -1
            holder = held.pop(atom.types[0], -1) if kind == PUT and carried < 0 else -1
            # any robot may do a leaf's other actions (the lamp switched on while another robot
            # holds the object): only a put needs the hand, and only a pickup fills it
            need = hand if kind == PUT and hand == atom.types[0] else None
            after = atom.types[0] if kind == PICKUP else EMPTY if kind == PUT else None
            if kind == PUT and hand == atom.types[0]:
                hand = None
            elif kind == PICKUP:
                hand = atom.types[0]
            full = after not in (None, EMPTY) and any(
                leaf.atoms[k2].verb == "put" and leaf.atoms[k2].types[0] == after for k2 in path[j + 1:])
            out.append((anchors, kind, carried, holder, need, after, full))
            if kind == PUT:
                where[atom.types[0]] = anchors
                picked.pop(atom.types[0], None)
            elif kind == PICKUP:
                picked[atom.types[0]] = j
                where.pop(atom.types[0], None)
        return out

    def _leaf_events(self, node: Node, leaf: Leaf, memo: dict) -> tuple[list[tuple], list[tuple]]:
        """(events that must happen, events that may happen) for one leaf's remaining work."""
        q = node.q[leaf.index]
        paths = leaf.paths.get(q) or []
        if not paths:
            return [], []
        evs = [self._path_events(node, leaf, path, memo) for path in paths]
        if len(evs) == 1:
            return evs[0], []
        if len({len(e) for e in evs}) == 1:
            # alternatives of equal length: merge event by event (a relaxation)
            merged = []
            for pos in range(len(evs[0])):
                col = [e[pos] for e in evs]
                anchors = tuple(sorted({a for c in col for a in c[0]}))
                kinds = {c[1] for c in col}
                carried = {c[2] for c in col}
                holders = {c[3] for c in col}
                hands = {c[4:] for c in col}
                merged.append((anchors, kinds.pop() if len(kinds) == 1 else OTHER,
                               carried.pop() if len(carried) == 1 else -1,
                               holders.pop() if len(holders) == 1 else -1,
                               *(hands.pop() if len(hands) == 1 else (None, None, False))))
            return merged, []
        return [], [ev for e in evs for ev in e]

    # ------------------------------------------------------------ the bound
    def evaluate(self, node: Node) -> tuple[int, int]:
        """(lower bound on remaining summed cost, lower bound on the final makespan). At the root
        (its bound lifts every node's, a child's bound being at least its parent's), the least bound
        over the leaves' instance choices, searched best first (`bounds.least_over_bindings`)."""
        if node.parent is None and self.root_evals > 1 and not self.light:
            choices, capacity = self._binding_choices(node)
            best = least_over_bindings(choices, capacity, lambda fixed: self._evaluate(node, fixed),
                                       self.root_evals)
            if best is not None:
                return best
        return self._evaluate(node, {})

    def _binding_choices(self, node: Node) -> tuple[list[Choice], dict[str, dict[int, int]]]:
        """The (leaf, type) pairs still to bind, with their candidate regions (fewest first); types
        that several leaves take for themselves form a group of distinct instances."""
        x, sim = self.x, node.sim
        choices: list[Choice] = []
        capacity: dict[str, dict[int, int]] = {}
        for lf in self.p.leaves:
            if node.q[lf.index] == DONE or lf.index not in self.required:
                continue
            types = sorted({t for path in lf.paths.get(node.q[lf.index]) or [] for k in path
                            for t in lf.atoms[k].types})
            for t in types:
                objs = [o for o in x.by_type.get(t, []) if t not in lf.taken or o not in node.claimed]
                if bound(node, lf.index, t) >= 0 or not objs:
                    continue
                regions = [self.nav.anchor(sim, o if x.slice_of[o] < 0 else x.slice_of[o]) for o in objs]
                if any(a < 0 for a in regions) or any(not sim.flags[o] & PRESENT for o in objs):
                    continue  # held, or slices still to come: left to the relaxations
                group = t if t in lf.taken else None
                if group is not None:
                    capacity[t] = {a: regions.count(a) for a in regions}
                choices.append((lf.index, t, group, tuple(sorted(set(regions)))))
        choices.sort(key=lambda c: (len(c[3]), c[0], c[1]))
        return [c for c in choices if len(c[3]) > 1 or c[2] is not None], capacity

    def _evaluate(self, node: Node, fixed: dict[tuple[int, str], int]) -> tuple[int, int]:
        """The bound with some (leaf, type) pairs fixed to one region (their instance's)."""
        p = self.p
        memo: dict = {"fixed": fixed}
        for (li, t), region in fixed.items():
            memo[(li, t, True)] = memo[(li, t, False)] = (region,)
        rows: list[tuple] = []  # (leaf, pos, anchors, kind, carried row, holder, need, after, full)
        hands: dict[tuple[int, str], int] = {}  # (leaf, held type) -> id
        optional: list[tuple[int, ...]] = []
        extra_events = 0
        chain: dict[int, tuple[int, int]] = {}
        for lf in p.leaves:
            if node.q[lf.index] == DONE or lf.index not in self.required:
                continue
            must, may = self._leaf_events(node, lf, memo)
            if not must:
                extra_events += lf.min_events.get(node.q[lf.index], 0)
                optional += [ev[0] for ev in may]
                chain[lf.index] = (0, lf.min_events.get(node.q[lf.index], 0))
                continue
            base = len(rows)
            for pos, (anchors, kind, carried, holder, need, after, full) in enumerate(must):
                hand_ids = (self._hand_id(lf.index, need, hands), self._hand_id(lf.index, after, hands))
                rows.append((lf.index, pos, anchors, kind, base + carried if carried >= 0 else -1, holder,
                             *hand_ids, full))
        if not rows and not extra_events:
            return 0, node.ms
        carry = 0 if self.light else self._carry_total(node, memo)
        walk = self._assignment(node, rows, optional, hands, carry) if rows else carry
        support = forced_opens(self.x, self.required, node) + forced_closes(self.x, self.required, node)
        total = len(rows) + extra_events + walk + support
        if not self.makespan:
            return total, node.ms
        if p.n_robots and (chain or rows):
            self._chains(node, rows, chain)
        return total, self._makespan(node, total, chain)

    def _carry_total(self, node: Node, memo: dict) -> int:
        """The carries of all pending leaves. Leaves that each take their own instance of one type
        (two baseball bats to the bed) get distinct instances: an assignment of instances to them."""
        total = 0
        groups: dict[str, list[dict[int, int]]] = {}
        for lf in self.p.leaves:
            if node.q[lf.index] == DONE or lf.index not in self.required:
                continue
            per = self._carry_per_instance(node, lf, memo)
            if per is None:
                total += self._carries(node, lf, memo)
            else:
                groups.setdefault(per[0], []).append(per[1])
        for rows in groups.values():
            insts = sorted({o for row in rows for o in row})
            if len(rows) == 1 or len(insts) < len(rows):
                total += sum(min(row.values()) for row in rows)
                continue
            cost = np.array([[row.get(o, BIG) for o in insts] for row in rows], dtype=np.int64)
            total += _solve(cost) or sum(min(row.values()) for row in rows)
        return total

    def _carry_per_instance(self, node: Node, leaf: Leaf, memo: dict) -> tuple[str, dict[int, int]] | None:
        """(T, instance -> the leaf's least carries with it) when the leaf's one path takes an
        instance of T for itself that is not bound yet; else None."""
        paths = leaf.paths.get(node.q[leaf.index]) or []
        if len(paths) != 1:
            return None
        atoms = [leaf.atoms[k] for k in paths[0]]
        taken = sorted({a.types[0] for a in atoms if a.verb == "pickup"
                        and leaf.exclusive("pickup", a.types[0]) and bound(node, leaf.index, a.types[0]) < 0})
        if len(taken) != 1 or (leaf.index, taken[0]) in memo["fixed"]:
            return None  # a type the root's search fixed: its one region is in the memo
        t = taken[0]
        sim = node.sim
        objs = [o for o in self.x.by_type.get(t, []) if o not in node.claimed]
        if any(not sim.flags[o] & PRESENT for o in objs):
            return None  # slices still to come: no list of instances yet
        by_anchor: dict[int, int] = {}
        out = {}
        for o in objs:
            a = self.nav.anchor(sim, o)
            if a < 0:
                continue
            if a not in by_anchor:
                by_anchor[a] = self._carries(node, leaf, memo, fixed=(t, a))
            out[o] = by_anchor[a]
        return (t, out) if out else None

    def _carries(self, node: Node, leaf: Leaf, memo: dict, fixed: tuple[str, int] | None = None) -> int:
        """The least walking the leaf's remaining carries need, one instance per type (bounds.py);
        `fixed`: (type, region) of a type's instance."""
        paths = leaf.paths.get(node.q[leaf.index]) or []
        if not paths:
            return 0
        sim = node.sim
        held = {t: sim.holder[o] for t, o in node.bind[leaf.index] if sim.holder[o] >= 0}
        best = None
        for path in paths:
            atoms = [(leaf.atoms[k].verb, leaf.atoms[k].types) for k in path]
            picked = frozenset(types[0] for verb, types in atoms if verb == "pickup")

            def anchors(t: str, picked: frozenset[str] = picked) -> tuple[int, ...]:
                if fixed is not None and t == fixed[0]:
                    return (fixed[1],)
                return self._anchors_of(node, leaf, t, "pickup" if t in picked else "put", memo)

            legs = carry_legs(atoms, held)
            if not legs:
                return 0
            if held:
                val = joint_min(legs, anchors, self.rr,
                                lambda r, a: self._robot_walks(node, np.array(a, dtype=np.int64))[:, r])
            else:  # a pure function of the legs and the candidate regions: cached across nodes
                types = sorted({t for leg in legs for t in leg if isinstance(t, str)})
                key = (tuple(legs), tuple(anchors(t) for t in types))
                val = self._carry_cache.get(key, -1)
                if val < 0:
                    if len(self._carry_cache) > CACHE_LIMIT:
                        self._carry_cache.clear()
                    val = self._carry_cache[key] = joint_min(legs, anchors, self.rr, _no_robot)
            best = val if best is None else min(best, val)
            if not best:
                break
        return best or 0

    @staticmethod
    def _hand_id(leaf: int, type_: str | None, hands: dict[tuple[int, str], int]) -> int:
        """A robot's hand as an id: -1 unknown (anything), -2 empty, else (leaf, held type)."""
        if type_ is None:
            return -1
        if type_ == EMPTY:
            return -2
        return hands.setdefault((leaf, type_), len(hands))

    def _robot_hands(self, node: Node, rows: list[tuple], hands: dict[tuple[int, str], int]) -> list[tuple]:
        """Per robot (its hand id, whether it stays full until a pending put), as for events."""
        out = []
        sim = node.sim
        holders = {r[5] for r in rows if r[5] >= 0}
        for r in range(len(node.cell)):
            o = sim.hand.get(r, -1)
            if o < 0:
                out.append((-2, False))
                continue
            owner = [(lf, t) for lf in range(len(node.q)) if node.q[lf] != DONE
                     for t, o2 in node.bind[lf] if o2 == o]
            if not owner:
                out.append((-2, False))  # nobody needs it: put down on the way (a walk no shorter)
            elif owner[0] in hands:
                out.append((hands[owner[0]], r in holders))
            else:
                out.append((-1, False))
        return out

    def _assignment(self, node: Node, rows: list[tuple], optional: list[tuple[int, ...]],
                    hands: dict[tuple[int, str], int], carry: int) -> int:
        """The largest of three bounds on the walking still needed: the assignment of distinct
        predecessors, the carries plus the pickups' approaches, and the spanning tree (bounds.py)."""
        n_ev = len(rows)
        anchor_sets = [r[2] for r in rows]
        cols = anchor_sets + optional
        flat_a = [a for s in anchor_sets for a in (s or (-1,))]
        flat_b = [b for s in cols for b in (s or (-1,))]
        empty = [i for i, s in enumerate(anchor_sets) if not s]
        a_idx = np.array(flat_a, dtype=np.int64)
        b_idx = np.array(flat_b, dtype=np.int64)
        a_starts = np.cumsum([0] + [max(1, len(s)) for s in anchor_sets[:-1]])
        b_starts = np.cumsum([0] + [max(1, len(s)) for s in cols[:-1]])
        # rows: events (successors); columns: predecessor events, then robots
        sub = self.rr[np.ix_(b_idx, a_idx)]
        if (b_idx < 0).any() or (a_idx < 0).any():
            sub = sub.copy()
            sub[b_idx < 0, :] = 0
            sub[:, a_idx < 0] = 0
        pred = np.minimum.reduceat(np.minimum.reduceat(sub, b_starts, axis=0), a_starts, axis=1)
        robot = self._robot_walks(node, a_idx)
        robot = np.minimum.reduceat(robot, a_starts, axis=0).T  # robots x events
        cost = np.vstack([pred, robot]).T.astype(np.int64)  # events x (preds + robots)
        if empty:
            cost[empty, :] = 0
        np.minimum(cost, BIG, out=cost)
        leaf = np.array([r[0] for r in rows])
        pos = np.array([r[1] for r in rows])
        kind = np.array([r[3] for r in rows])
        n_pred = len(cols)
        ev_cols = cost[:, :n_ev]
        # a later (or the same) event of one's own leaf cannot come before
        same = (leaf[:, None] == leaf[None, :]) & (pos[None, :] >= pos[:, None])
        # an event of a leaf that starts only after mine is complete cannot come before
        later = self.after[leaf[:, None], leaf[None, :]]
        ev_cols[same | later] = BIG
        # a carried object's put: after its pickup or a hands-full action, never another pick/put
        for i, r in enumerate(rows):
            if r[3] != PUT:
                continue
            carried, holder = r[4], r[5]
            if carried < 0 and holder < 0:
                continue
            bad = kind != OTHER
            if carried >= 0:
                bad = bad.copy()
                bad[carried] = False
            ev_cols[i, bad] = BIG
            if n_pred > n_ev:
                pass  # optional events may be hands-full actions
            if carried >= 0:
                cost[i, n_pred:] = BIG
            else:
                keep = cost[i, n_pred + holder]
                cost[i, n_pred:] = BIG
                cost[i, n_pred + holder] = keep
        cost[:, :n_ev] = ev_cols
        self.work += cost.size + EVAL_WORK
        self._hand_rules(node, rows, cost, n_ev, n_pred, hands)
        walk = _solve(_with_last(cost, n_ev))
        if self.light:
            return walk
        # pickups are never inside a carry (one hand): their approaches add to the carries'
        # binding-consistent minimum
        alone = kind == PICKUP
        approach = cost.copy()
        approach[~alone] = np.where(approach[~alone] >= BIG, BIG, 0)
        walk = max(walk, carry + _solve(_with_last(approach, n_ev)))
        compound = self._approach_and_carry(node, rows, cols, cost)
        if compound is not None:
            walk = max(walk, _solve(_with_last(compound, n_ev)))
        # the spanning tree over the events of one known region (an event with several candidate
        # regions would join far groups at no cost; leaving events out keeps it a bound)
        fixed = [i for i, s in enumerate(anchor_sets) if len(s) == 1]
        if len(fixed) > 1 or (fixed and walk == 0):
            ev = np.minimum(pred[np.ix_(fixed, fixed)], BIG)
            walk = max(walk, spanning_walk(ev, np.minimum(robot[:, fixed].min(axis=0), BIG)))
        return walk

    def _approach_and_carry(self, node: Node, rows: list[tuple], cols: list[tuple[int, ...]],
                            cost: np.ndarray) -> np.ndarray | None:
        """The assignment over the pickups of their approach and carry as one walk, from the
        predecessor through one cell of the pickup's region to the put's region (a region-level step
        may reach the object at one end of its region and leave from the other); a held object's
        put keeps the holder's walk. These walks are disjoint parts of the robots' walks (an approach
        has the hand empty, a carry full): summed, a bound. None when no pickup is carried."""
        legs = {r[4]: i for i, r in enumerate(rows) if r[3] == PUT and r[4] >= 0 and r[2]}
        legs = {k: i for k, i in legs.items() if rows[k][3] == PICKUP and rows[k][2]}
        region_idx = self.nav.region_idx
        cells_of = {k: np.concatenate([region_idx[a] for a in rows[k][2]]) for k in legs}
        cells_of = {k: c for k, c in cells_of.items() if len(c)}  # an instance no cell reaches: no leg
        if not cells_of:
            return None
        union = np.unique(np.concatenate(list(cells_of.values())))  # only the cells the pickups use
        src = np.empty((cost.shape[1], len(union)), dtype=np.int64)
        for j, anchors in enumerate(cols):
            src[j] = self._near(anchors)[union] if anchors else 0
        src[len(cols):] = self._robot_walks_to_cells(node, union)
        np.minimum(src, BIG, out=src)
        out = np.where(cost >= BIG, BIG, 0)
        for i, r in enumerate(rows):
            if r[3] == PUT and r[4] < 0 and r[5] >= 0:
                out[i] = cost[i]  # a held object's put: the holder's walk to it
        for k, cells in cells_of.items():
            i = legs[k]
            to_put = np.minimum(self._near(rows[i][2])[cells], BIG)
            walks = (src[:, np.searchsorted(union, cells)] + to_put[None, :]).min(axis=1)
            out[k] = np.where(cost[k] >= BIG, BIG, np.minimum(walks, BIG))
        return out

    def _robot_walks_to_cells(self, node: Node, cells: np.ndarray) -> np.ndarray:
        """robots x `cells`: the fewest steps from where each robot may stand to each of them."""
        dm = self.nav.dm
        out = dm[np.ix_(np.array(node.cell, dtype=np.int64), cells)]
        if node.reach is not None:
            for r, reach in enumerate(node.reach):
                if reach is not None:
                    stand = np.array(reach[0], dtype=np.int64)
                    out[r] = (dm[np.ix_(stand, cells)] + np.array(reach[1])[:, None]).min(axis=0)
        return out

    def _hand_rules(self, node: Node, rows: list[tuple], cost: np.ndarray, n_ev: int, n_pred: int,
                    hands: dict[tuple[int, str], int]) -> None:
        """One hand: a pickup never follows a moment the hand is full until a pending put; an event
        that needs the hand to hold X (a put of X, an action done while holding X) follows only a
        moment the hand may hold X. Optional events: hand unknown."""
        robot = self._robot_hands(node, rows, hands)
        n_opt = n_pred - n_ev
        after = np.array([r[7] for r in rows] + [-1] * n_opt + [h for h, _ in robot], dtype=np.int64)
        full = np.array([r[8] for r in rows] + [False] * n_opt + [f for _, f in robot], dtype=bool)
        kind = np.array([r[3] for r in rows])
        need = np.array([r[6] for r in rows], dtype=np.int64)
        bad = (kind == PICKUP)[:, None] & full[None, :]
        bad |= (need >= 0)[:, None] & (after[None, :] != -1) & (after[None, :] != need[:, None])
        cost[bad] = BIG

    def _robot_walks(self, node: Node, a_idx: np.ndarray) -> np.ndarray:
        """anchors x robots: the fewest steps from where each robot may stand to each anchor."""
        if not len(a_idx):
            return np.zeros((0, len(node.cell)), dtype=np.int64)
        out = self.field[a_idx][:, list(node.cell)]
        if node.reach is not None:
            for r, reach in enumerate(node.reach):
                if reach is not None:
                    walks = self.field[a_idx][:, list(reach[0])] + np.array(reach[1])[None, :]
                    out[:, r] = walks.min(axis=1)
        return out

    def _chains(self, node: Node, rows: list[tuple], chain: dict[int, tuple[int, int]]) -> None:
        """Per leaf: (steps for the first robot to reach its next event, events + carry legs)."""
        cells = list(node.cell)
        by_leaf: dict[int, list[tuple]] = {}
        for r in rows:
            by_leaf.setdefault(r[0], []).append(r)
        for li, evs in by_leaf.items():
            first = evs[0][2]
            reach = int(self._near(first)[cells].min()) if first else 0
            length = 0
            for r in evs:
                length += 1
                if r[3] == PUT and r[4] >= 0 and r[2] and rows[r[4]][2]:
                    leg = self.rr[np.ix_(list(rows[r[4]][2]), list(r[2]))].min()
                    length += int(min(leg, BIG))
            chain[li] = (min(reach, BIG), length)

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


def _solve(cost: np.ndarray) -> int:
    """The cheapest assignment (0 when none avoids a forbidden pair: cannot happen when solvable)."""
    r_ind, c_ind = linear_sum_assignment(cost)
    total = int(cost[r_ind, c_ind].sum())
    return 0 if total >= BIG else total


def _with_last(cost: np.ndarray, n_ev: int) -> np.ndarray:
    """The cost matrix with one more row, "the last event": some pending event is no pending event's
    predecessor (the last of its robot's), so one event column stays free and at least one event
    follows a robot (without it, events may precede one another in cycles that no robot enters)."""
    last = np.full((1, cost.shape[1]), BIG, dtype=cost.dtype)
    last[0, :n_ev] = 0
    return np.vstack([cost, last])


def _no_robot(robot: int, anchors: tuple[int, ...]) -> np.ndarray:
    raise AssertionError("no robot holds anything for these carries")
