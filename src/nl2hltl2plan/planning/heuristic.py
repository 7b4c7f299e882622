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
candidate is closed in), and one open after a forced close of the microwave when the heated object
is then taken out. At the root, three cell-level bounds on the walking join them (`tour.py`: paths
out of the robots through the events' regions; events in their time order; `hands.py`: such paths
with one object in a hand at a time), and the bound is
minimised over the instance choices as well (`bounds.least_over_bindings`).

Completion time (`minmax`): `makespan.py`, from the same pending events (`relax.EventRow`); the
summed cost skips it. `Heuristic.work` counts the cells of the assignment matrices solved (plus a
fixed amount per evaluation): fast mode's A* budget is counted in it, so a large problem, whose
evaluations cost more, gets fewer of them. `Heuristic.light` keeps only the assignment (fast mode's
greedy and team beam seeds rank children with it). What depends on the objects' state alone, not on
where the robots are (the pending events, their regions and hands, the forced opens and closes, the
carries while nothing is held, the robot-independent part of the assignment matrix), is computed
once per such state (`Pending`, `Template`) and shared by every node in it.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple, TypeVar

import numpy as np

from nl2hltl2plan.planning.bounds import (
    Choice,
    least_over_bindings,
    spanning_walk,
)
from nl2hltl2plan.planning.carries import PathLegs, carry_total
from nl2hltl2plan.planning.hands import hands_walk
from nl2hltl2plan.planning.leaves import DONE, Leaf
from nl2hltl2plan.planning.makespan import leaf_chains, makespan_bound
from nl2hltl2plan.planning.navigation import INF
from nl2hltl2plan.planning.node import Node, bound
from nl2hltl2plan.planning.opens import forced_closes, forced_opens
from nl2hltl2plan.planning.per_pending import approach_legs, hand_masks, robot_hand_mask
from nl2hltl2plan.planning.relax import BIG, OTHER, PICKUP, PUT, EventRow, solve
from nl2hltl2plan.planning.state import Expander
from nl2hltl2plan.planning.tour import chain_walk, tour_walk
from nl2hltl2plan.worlds.simulator import PRESENT

EMPTY = ""  # the hand right after a put
NEAR_CACHE_LIMIT = 1_000  # per-anchor-set distance rows kept across nodes
EVAL_WORK = 200  # an evaluation's fixed cost, in assignment-matrix cells (measured: ~1.5 ms vs ~7 us a cell)
# the keys of a Pending's memo that hold its robot-independent parts (`_per_pending`)
TEMPLATE, LEGS, HANDS, TREE = "template", "legs", "hands", "tree"
PENDING_CACHE_LIMIT = 20_000  # pending work kept per object state across nodes
T = TypeVar("T")
ROOT_EVALS = 64  # bound evaluations the root's search over instance choices spends (at most)


class Heuristic:
    def __init__(self, expander: Expander, required: set[int], makespan: bool = True):
        self.x = expander
        self.makespan = makespan  # is the completion-time bound needed (objective `minmax`)?
        # work done so far, in cells of assignment matrices solved: machine-independent and
        # proportional to the evaluations' cost, so budgets in it scale with the problem's size
        self.work = 0
        # light: only the assignment of predecessors (fast mode's greedy and team beams rank
        # children with it; every bound here is admissible, the full one is only tighter)
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
        self.carry_cache: dict[tuple, int] = {}  # carry minima of legs and regions (carries.py)
        self.legs_cache: dict[tuple, PathLegs] = {}  # a leaf path's carry legs (carries.py)
        self._near_cache: dict[tuple[int, ...], np.ndarray] = {}
        self._pending_cache: dict[tuple, Pending] = {}
        self.root_evals = ROOT_EVALS

    def _near(self, anchors: tuple[int, ...]) -> np.ndarray:
        """Per cell, the walk from the nearest of `anchors`' regions: a pure function of the anchor
        set (a state's events share a few), so it is computed once per set, not once per node."""
        hit = self._near_cache.get(anchors)
        if hit is None:
            if len(self._near_cache) > NEAR_CACHE_LIMIT:
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
    def anchors_of(self, node: Node, leaf: Leaf, type_: str, verb: str, memo: dict) -> tuple[int, ...]:
        taking = verb in ("pickup", "slice")
        key = (leaf.index, type_, taking)
        hit = memo.get(key)
        if hit is not None:
            return hit
        x = self.x
        sim = node.sim
        anchor = self.nav.anchor
        bound_to = bound(node, leaf.index, type_)
        objs = [bound_to] if bound_to >= 0 else x.by_type.get(type_, [])
        if bound_to < 0 and node.claimed and (taking or type_ in leaf.taken):
            objs = [obj for obj in objs if obj not in node.claimed]
        out = set()
        for obj in objs:
            region = anchor(sim, obj)
            if region < 0 and x.slice_of[obj] >= 0:
                region = anchor(sim, x.slice_of[obj])
            if region >= 0:
                out.add(region)
        res = tuple(sorted(out))
        memo[key] = res
        return res

    def _path_events(self, node: Node, leaf: Leaf, path: tuple[int, ...], memo: dict) -> list[PathEvent]:
        """The events of one remaining action sequence of a leaf, as the bounds see them."""
        where: dict[str, tuple[int, ...]] = {}
        picked: dict[str, int] = {}
        held = {}
        sim = node.sim
        for type_, obj in node.bind[leaf.index]:
            if sim.holder[obj] >= 0:
                held[type_] = sim.holder[obj]
        hand = next(iter(held), None)  # the type this leaf's robot holds (one hand: at most one)
        out = []
        for pos, atom_k in enumerate(path):
            atom = leaf.atoms[atom_k]
            target = atom.types[-1]
            anchors = where.get(target)
            if anchors is None:
                anchors = self.anchors_of(node, leaf, target, atom.verb, memo)
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
                leaf.atoms[later].verb == "put" and leaf.atoms[later].types[0] == after
                for later in path[pos + 1:])
            out.append(PathEvent(anchors, kind, carried, holder, Hand(need, after, full)))
            if kind == PUT:
                where[atom.types[0]] = anchors
                picked.pop(atom.types[0], None)
            elif kind == PICKUP:
                picked[atom.types[0]] = pos
                where.pop(atom.types[0], None)
        return out

    def _leaf_events(self, node: Node, leaf: Leaf, memo: dict) -> tuple[list[PathEvent], list[PathEvent]]:
        """(events that must happen, events that may happen) for one leaf's remaining work."""
        q = node.q[leaf.index]
        paths = leaf.paths.get(q) or []
        if not paths:
            return [], []
        per_path = [self._path_events(node, leaf, path, memo) for path in paths]
        if len(per_path) == 1:
            return per_path[0], []
        if len({len(events) for events in per_path}) == 1:
            # alternatives of equal length: merge event by event (a relaxation)
            return [_merged(column) for column in zip(*per_path, strict=True)], []
        return [], [event for events in per_path for event in events]

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
            types = sorted({type_ for path in lf.paths.get(node.q[lf.index]) or [] for atom_k in path
                            for type_ in lf.atoms[atom_k].types})
            for type_ in types:
                objs = [obj for obj in x.by_type.get(type_, [])
                        if type_ not in lf.taken or obj not in node.claimed]
                if bound(node, lf.index, type_) >= 0 or not objs:
                    continue
                regions = [self.nav.anchor(sim, obj if x.slice_of[obj] < 0 else x.slice_of[obj])
                           for obj in objs]
                if any(region < 0 for region in regions) or any(not sim.flags[obj] & PRESENT for obj in objs):
                    continue  # held, or slices still to come: left to the relaxations
                group = type_ if type_ in lf.taken else None
                if group is not None:
                    capacity[type_] = {region: regions.count(region) for region in regions}
                choices.append(Choice(lf.index, type_, group, tuple(sorted(set(regions)))))
        choices.sort(key=lambda choice: (len(choice.regions), choice.leaf, choice.type_))
        return [choice for choice in choices if len(choice.regions) > 1 or choice.group is not None], capacity

    def _evaluate(self, node: Node, fixed: dict[tuple[int, str], int]) -> tuple[int, int]:
        """The bound with some (leaf, type) pairs fixed to one region (their instance's)."""
        pending = self._pending(node, fixed)
        rows = pending.rows
        if not rows and not pending.extra_events:
            return 0, node.ms
        carry = pending.carry
        if carry < 0:  # an object is held: the carries depend on where its holder stands
            carry = 0 if self.light else carry_total(self, node, pending.memo)
        walk = self._assignment(node, pending, carry) if rows else carry
        if node.parent is None and not fixed and not self.light:  # once at the root (tour.py, hands.py)
            walk = max(walk, tour_walk(self, node, rows), chain_walk(self, node, rows),
                       hands_walk(self, node, rows))
        total = len(rows) + pending.extra_events + walk + pending.support
        if not self.makespan:
            return total, node.ms
        chain = dict(pending.chain)
        if self.p.n_robots and (chain or rows):
            leaf_chains(self._near, self.rr, node, rows, chain)
        return total, makespan_bound(self.x, node, total, chain)

    def _pending(self, node: Node, fixed: dict[tuple[int, str], int]) -> Pending:
        """What the node has still to do, as the bounds see it: a function of the objects' state
        and the leaves' progress and bindings alone, not of where the robots are, so it is computed
        once per such state (the same event done by another robot, or independent events in
        another order, reach one) and shared by every node in it."""
        key = None
        if not fixed:
            sim = node.sim
            key = (tuple(sim.parent), tuple(sim.holder), tuple(sim.flags), tuple(sim.moved), node.q,
                   node.bind, node.claimed, self.light)
            hit = self._pending_cache.get(key)
            if hit is not None:
                return hit
        p = self.p
        memo: dict = {"fixed": fixed}
        for (li, t), region in fixed.items():
            memo[(li, t, True)] = memo[(li, t, False)] = (region,)
        rows: list[EventRow] = []
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
                optional += [event.anchors for event in may]
                chain[lf.index] = (0, lf.min_events.get(node.q[lf.index], 0))
                continue
            base = len(rows)
            for pos, event in enumerate(must):
                hand = event.hand
                rows.append(EventRow(lf.index, pos, event.anchors, event.kind,
                                     base + event.carried if event.carried >= 0 else -1, event.holder,
                                     self._hand_id(lf.index, hand.need, hands),
                                     self._hand_id(lf.index, hand.after, hands), hand.full))
        carry = 0
        if any(obj >= 0 for obj in node.sim.hand.values()):
            carry = -1  # computed per node (`_evaluate`)
        elif not self.light and (rows or extra_events):
            carry = carry_total(self, node, memo)
        support = forced_opens(self.x, self.required, node) + forced_closes(self.x, self.required, node)
        out = Pending(rows, optional, hands, extra_events, chain, carry, support, memo)
        if key is not None:
            if len(self._pending_cache) > PENDING_CACHE_LIMIT:
                self._pending_cache.clear()
            self._pending_cache[key] = out
        return out

    @staticmethod
    def _hand_id(leaf: int, type_: str | None, hands: dict[tuple[int, str], int]) -> int:
        """A robot's hand as an id: -1 unknown (anything), -2 empty, else (leaf, held type)."""
        if type_ is None:
            return -1
        if type_ == EMPTY:
            return -2
        return hands.setdefault((leaf, type_), len(hands))

    def _robot_hands(self, node: Node, rows: list[EventRow],
                     hands: dict[tuple[int, str], int]) -> list[tuple[int, bool]]:
        """Per robot (its hand id, whether it stays full until a pending put), as for events."""
        out = []
        sim = node.sim
        holders = {row.holder for row in rows if row.holder >= 0}
        for robot in range(len(node.cell)):
            held = sim.hand.get(robot, -1)
            if held < 0:
                out.append((-2, False))
                continue
            owner = [(leaf, type_) for leaf in range(len(node.q)) if node.q[leaf] != DONE
                     for type_, obj in node.bind[leaf] if obj == held]
            if not owner:
                out.append((-2, False))  # nobody needs it: put down on the way (a walk no shorter)
            elif owner[0] in hands:
                out.append((hands[owner[0]], robot in holders))
            else:
                out.append((-1, False))
        return out

    def _assignment(self, node: Node, pending: Pending, carry: int) -> int:
        """The largest of three bounds on the walking still needed: the assignment of distinct
        predecessors, the carries plus the pickups' approaches, and the spanning tree (bounds.py)."""
        rows = pending.rows
        t = _per_pending(pending, TEMPLATE, lambda: self._template(rows, pending.optional))
        n_ev, n_pred, cols, kind, pred = len(rows), len(t.cols), t.cols, t.kind, t.pred
        # rows: events (successors); columns: predecessor events (the template), then robots
        robot = np.minimum.reduceat(self.robot_walks(node, t.a_idx), t.a_starts, axis=0)  # events x robots
        walks = robot.astype(np.int64)
        if t.empty:
            walks[t.empty, :] = 0
        np.minimum(walks, BIG, out=walks)
        for i, holder in t.held_puts:  # a carried object's put: no robot's first event but its holder's
            keep = walks[i, holder] if holder >= 0 else BIG
            walks[i, :] = BIG
            if holder >= 0:
                walks[i, holder] = keep
        cost = np.concatenate((t.cost, walks), axis=1)  # (hstack of 2-D arrays, without its checks)
        robot = robot.T  # robots x events
        self.work += cost.size + EVAL_WORK
        self._hand_rules(node, pending, cost, n_ev, n_pred)
        walk = solve(_with_last(cost, n_ev))
        if self.light:
            return walk
        # pickups are never inside a carry (one hand): their approaches add to the carries'
        # binding-consistent minimum
        alone = kind == PICKUP
        approach = cost.copy()
        approach[~alone] = np.where(approach[~alone] >= BIG, BIG, 0)
        walk = max(walk, carry + solve(_with_last(approach, n_ev)))
        compound = self._approach_and_carry(node, pending, cols, cost)
        if compound is not None:
            walk = max(walk, solve(_with_last(compound, n_ev)))
        # the spanning tree over the events of one known region (an event with several candidate
        # regions would join far groups at no cost; leaving events out keeps it a bound)
        fixed, ev = _per_pending(pending, TREE, lambda: _known_region_steps(rows, pred))
        if len(fixed) > 1 or (len(fixed) and walk == 0):
            walk = max(walk, spanning_walk(ev, np.minimum(robot[:, fixed].min(axis=0), BIG)))
        return walk

    def _template(self, rows: list[EventRow], optional: list[tuple[int, ...]]) -> Template:
        """The robot-independent part of the assignment's cost matrix: events x predecessor events
        with the order and hand rules applied (computed once per pending work, `Pending`)."""
        n_ev = len(rows)
        anchor_sets = [row.anchors for row in rows]
        cols = anchor_sets + optional
        flat_a = [anchor for anchors in anchor_sets for anchor in (anchors or (-1,))]
        flat_b = [anchor for anchors in cols for anchor in (anchors or (-1,))]
        empty = [i for i, anchors in enumerate(anchor_sets) if not anchors]
        a_idx = np.array(flat_a, dtype=np.int64)
        b_idx = np.array(flat_b, dtype=np.int64)
        a_starts = np.cumsum([0] + [max(1, len(anchors)) for anchors in anchor_sets[:-1]])
        b_starts = np.cumsum([0] + [max(1, len(anchors)) for anchors in cols[:-1]])
        sub = self.rr[b_idx[:, None], a_idx]  # (plain broadcasting: np.ix_ costs more per call)
        if (b_idx < 0).any() or (a_idx < 0).any():
            sub = sub.copy()
            sub[b_idx < 0, :] = 0
            sub[:, a_idx < 0] = 0
        pred = np.minimum.reduceat(np.minimum.reduceat(sub, b_starts, axis=0), a_starts, axis=1)
        cost = pred.T.astype(np.int64)  # events x predecessors
        if empty:
            cost[empty, :] = 0
        np.minimum(cost, BIG, out=cost)
        leaf = np.array([row.leaf for row in rows])
        pos = np.array([row.pos for row in rows])
        kind = np.array([row.kind for row in rows])
        ev_cols = cost[:, :n_ev]
        # a later (or the same) event of one's own leaf cannot come before
        same = (leaf[:, None] == leaf[None, :]) & (pos[None, :] >= pos[:, None])
        # an event of a leaf that starts only after mine is complete cannot come before
        later = self.after[leaf[:, None], leaf[None, :]]
        ev_cols[same | later] = BIG
        # a carried object's put: after its pickup or a hands-full action, never another pick/put
        held_puts = []
        for i, row in enumerate(rows):
            if row.kind != PUT:
                continue
            carried, holder = row.carried, row.holder
            if carried < 0 and holder < 0:
                continue
            bad = kind != OTHER
            if carried >= 0:
                bad = bad.copy()
                bad[carried] = False
            ev_cols[i, bad] = BIG
            held_puts.append((i, -1 if carried >= 0 else holder))
        return Template(cols, empty, a_idx, a_starts, pred, cost, kind, held_puts)

    def _approach_and_carry(self, node: Node, pending: Pending, cols: list[tuple[int, ...]],
                            cost: np.ndarray) -> np.ndarray | None:
        """The assignment over the pickups of their approach and carry as one walk, from the
        predecessor through one cell of the pickup's region to the put's region (a region-level step
        may reach the object at one end of its region and leave from the other); a held object's
        put keeps the holder's walk. These walks are disjoint parts of the robots' walks (an approach
        has the hand empty, a carry full): summed, a bound. None when no pickup is carried. The
        walks from the pending events are computed once per pending work (`per_pending`)."""
        legs = _per_pending(pending, LEGS,
                            lambda: approach_legs(pending.rows, cols, self.nav.region_idx, self._near))
        if legs is None:
            return None
        robots = np.minimum(self.robot_walks_to_cells(node, legs.union), BIG)
        out = np.where(cost >= BIG, BIG, 0)
        for i in legs.held_puts:
            out[i] = cost[i]  # a held object's put: the holder's walk to it
        from_robots = np.minimum.reduceat(robots[:, legs.cells] + legs.to_put[None, :], legs.starts, axis=1)
        walks = np.minimum(np.concatenate((legs.from_cols, from_robots.T), axis=1), BIG)
        out[legs.picks] = np.where(cost[legs.picks] >= BIG, BIG, walks)
        return out

    def robot_walks_to_cells(self, node: Node, cells: np.ndarray) -> np.ndarray:
        """robots x `cells`: the fewest steps from where each robot may stand to each of them."""
        dm = self.nav.dm
        out = dm[np.array(node.cell, dtype=np.int64)[:, None], cells]
        if node.reach is not None:
            for r, reach in enumerate(node.reach):
                if reach is not None:
                    stand = np.array(reach[0], dtype=np.int64)
                    out[r] = (dm[stand[:, None], cells] + np.array(reach[1])[:, None]).min(axis=0)
        return out

    def _hand_rules(self, node: Node, pending: Pending, cost: np.ndarray, n_ev: int, n_pred: int) -> None:
        """One hand: a pickup never follows a moment the hand is full until a pending put; an event
        that needs the hand to hold X (a put of X, an action done while holding X) follows only a
        moment the hand may hold X. Optional events: hand unknown. The events' part is computed
        once per pending work (`per_pending.hand_masks`)."""
        rows = pending.rows
        masks = _per_pending(pending, HANDS, lambda: hand_masks(rows, n_pred - n_ev))
        cost[:, :n_pred][masks.events] = BIG
        cost[:, n_pred:][robot_hand_mask(masks, tuple(self._robot_hands(node, rows, pending.hands)))] = BIG

    def robot_walks(self, node: Node, a_idx: np.ndarray) -> np.ndarray:
        """anchors x robots: the fewest steps from where each robot may stand to each anchor."""
        if not len(a_idx):
            return np.zeros((0, len(node.cell)), dtype=np.int64)
        rows = a_idx[:, None]  # only the needed cells of the anchors' distance fields
        out = self.field[rows, list(node.cell)]
        if node.reach is not None:
            for robot, reach in enumerate(node.reach):
                if reach is not None:
                    walks = self.field[rows, list(reach[0])] + np.array(reach[1])[None, :]
                    out[:, robot] = walks.min(axis=1)
        return out


class Pending(NamedTuple):
    """A node's pending work as the bounds see it (`Heuristic._pending`); shared, never changed."""

    rows: list[EventRow]  # the events every completion does
    optional: list[tuple[int, ...]]  # the regions of events some completions do
    hands: dict[tuple[int, str], int]  # (leaf, held type) -> hand id
    extra_events: int  # events of leaves whose alternatives differ in length (their least count)
    chain: dict[int, tuple[int, int]]  # per leaf of `extra_events`: its makespan chain
    carry: int  # the carries' least walking, -1 when a robot holds an object (then it depends on it)
    support: int  # the support opens and closes every completion needs
    memo: dict  # the pending events' candidate regions (`anchors_of`)


class Template(NamedTuple):
    """The robot-independent part of the assignment relaxation of a `Pending` (`Heuristic._template`)."""

    cols: list[tuple[int, ...]]  # the predecessor events' regions (the pending events, then optional ones)
    empty: list[int]  # events with no region (a free first event)
    a_idx: np.ndarray  # the events' regions, flattened
    a_starts: np.ndarray  # where each event's regions start in `a_idx`
    pred: np.ndarray  # predecessors x events: the least region-to-region walk
    cost: np.ndarray  # events x predecessors, the order and hand rules applied (read-only)
    kind: np.ndarray  # per event: OTHER, PICKUP or PUT
    held_puts: list[tuple[int, int]]  # puts of a carried object: (event, its holder or -1: none)


class Hand(NamedTuple):
    """The hand around one pending event of a leaf."""

    need: str | None  # the type the robot must hold to do it (None: any hand)
    after: str | None  # the hand right after it: a type, EMPTY, or None (unknown)
    full: bool  # the hand stays full from it until a later put of the same path


UNKNOWN_HAND = Hand(None, None, False)


class PathEvent(NamedTuple):
    """One event of a leaf's remaining action sequence, before it becomes an `EventRow`."""

    anchors: tuple[int, ...]  # the regions it may happen in
    kind: int  # OTHER, PICKUP or PUT
    carried: int  # a put: the position of the pickup of what it puts in this path, else -1
    holder: int  # a put of what a robot holds now: that robot, else -1
    hand: Hand


def _merged(column: tuple[PathEvent, ...]) -> PathEvent:
    """One event standing for the events at one position of equally long alternatives: the union
    of their regions, and each attribute where they agree (else the weakest value)."""
    kinds = {event.kind for event in column}
    carried = {event.carried for event in column}
    holders = {event.holder for event in column}
    hands = {event.hand for event in column}
    return PathEvent(tuple(sorted({a for event in column for a in event.anchors})),
                     kinds.pop() if len(kinds) == 1 else OTHER,
                     carried.pop() if len(carried) == 1 else -1,
                     holders.pop() if len(holders) == 1 else -1,
                     hands.pop() if len(hands) == 1 else UNKNOWN_HAND)


def _per_pending(pending: Pending, key: str, make: Callable[[], T]) -> T:
    """A robot-independent part of `pending`, computed by `make` once and kept in its memo (every
    node in that pending work shares it; a None kept too)."""
    if key not in pending.memo:
        pending.memo[key] = make()
    return pending.memo[key]


def _known_region_steps(rows: list[EventRow], pred: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The events of one known region (the spanning tree's), and the walks between them (at most BIG)."""
    fixed = np.array([i for i, row in enumerate(rows) if len(row.anchors) == 1], dtype=np.int64)
    return fixed, np.minimum(pred[fixed[:, None], fixed], BIG)


def _with_last(cost: np.ndarray, n_ev: int) -> np.ndarray:
    """The cost matrix with one more row, "the last event": some pending event is no pending event's
    predecessor (the last of its robot's), so one event column stays free and at least one event
    follows a robot (without it, events may precede one another in cycles that no robot enters)."""
    out = np.empty((cost.shape[0] + 1, cost.shape[1]), dtype=cost.dtype)
    out[:-1] = cost
    out[-1] = BIG
    out[-1, :n_ev] = 0
    return out
