"""Cooperative multi-arm planning for the handover worlds (planning engine separate from `planning.plan`).

The main planner gives every leaf task to one robot. In the handover worlds a leaf such as "move the
red block to J" needs several arms in turn: arm a puts the block on a cell it shares with arm b, b
picks it up there, and so on. This planner searches the joint state instead:

- a state is (end-effector cell per arm, block held per arm, cell per block) plus the progress of the
  hierarchical spec: the DFA state of every unfinished leaf, which tasks are complete, and the DFA
  state of non-leaves not in precedence form; leaves read *global* atoms (worlds/handover_world.py), so any
  arm may serve any leaf, and leaf formulas may use negated atoms (`!pick(Blue) U pick(Red)`) and
  region occupancy (`drop(F)`, `empty(H)`, `at(Red,@Blue)`);
- a move of the search is a macro: one arm walks a shortest path inside its reach (around the other
  end effectors) and picks a block, or puts its block on a labelled region or a shared cell, or
  retreats from a shared cell to its nearest own cell; the others wait, so no two end effectors
  ever meet. Each macro feeds the spec the "idle" letter (the state, no event) when it moved, then the
  letter of its action, exactly what the executed plan shows step by step;
- cost = end-effector moves + actions (pick/put), summed over arms; A* with an admissible transport
  bound (each block a leaf still needs at a place must be carried at least its grid distance there);
- the plan returned is executed by `worlds.handover_world.execute_handover` and checked with
  `logic.trace.check_trace` before it is returned.

A* is optimal for the macro model (arms act one at a time; a block is put only on a labelled region or
a shared cell) when the transport bound is admissible, which holds when every positive `at/put/away`
atom of a block in a leaf is required for that leaf (true of the handover task specs).
"""

from __future__ import annotations

import heapq
import itertools
import math
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, TypeVar

from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.budget import Budget, StopReason
from nl2hltl2plan.planning.coop_progress import Event, Progress, PState, leaf_targets
from nl2hltl2plan.planning.results import PlanResult, PlanStatus
from nl2hltl2plan.worlds.handover_world import (
    ARMS,
    HandoverExecution,
    HandoverWorld,
    Snap,
    check_handover,
    execute_handover,
    initial_snap,
)
from nl2hltl2plan.worlds.plan import Plan, RobotPlan, Step
from nl2hltl2plan.worlds.world import Cell

MAX_EXPANSIONS = 60_000
CACHE_LIMIT = 200_000  # cached paths / tours per search object (cleared when full)
K = TypeVar("K")
V = TypeVar("V")


@dataclass
class Macro:
    arm: int
    path: list[Cell]  # cells entered, in order
    verb: str  # "pickup" | "put" | "retreat"
    block: int = -1


@dataclass
class CoopResult:
    status: PlanStatus  # solved | infeasible | timeout (the search planner's statuses)
    reason: str = ""
    plan: Plan | None = None
    cost: int | None = None  # moves + actions
    travel: int | None = None  # end-effector cells moved
    actions: int | None = None
    steps: int | None = None
    handovers: int | None = None
    expanded: int = 0
    plan_time_s: float = 0.0
    proven_optimal: bool = False
    stopped: StopReason = StopReason.NONE
    execution: HandoverExecution | None = field(default=None, repr=False)

    @property
    def solved(self) -> bool:
        return self.status == PlanStatus.SOLVED

    def to_dict(self) -> dict[str, Any]:
        keys = (
            "status",
            "reason",
            "cost",
            "travel",
            "actions",
            "steps",
            "handovers",
            "expanded",
            "plan_time_s",
            "proven_optimal",
        )
        out = {k: getattr(self, k) for k in keys}
        out["plan"] = self.plan.model_dump(mode="json") if self.plan is not None else None
        return out


_MISSING = object()


def _bounded(cache: dict[K, V], key: K, compute: Callable[[], V]) -> V:
    """`cache[key]`, computed on first use; the cache is emptied when it holds CACHE_LIMIT entries."""
    if key not in cache:
        if len(cache) >= CACHE_LIMIT:
            cache.clear()
        cache[key] = compute()
    return cache[key]


class _Search:
    def __init__(self, hw: HandoverWorld, spec: HierarchicalSpec) -> None:
        self.hw = hw
        self.lay = hw.layout
        self.progress = Progress(spec, hw)
        self.targets = leaf_targets(spec, hw)
        self.put_cells = [
            sorted(c for c in self.lay.reach[a] if c in self.lay.shared or c in self.lay.region_at)
            for a in range(len(ARMS))
        ]
        # pure functions of their arguments, cached on this search object (and dropped with it)
        self._paths: dict[tuple[int, Cell, Cell, frozenset[Cell]], tuple[Cell, ...] | None] = {}
        self._tours: dict[tuple[Cell, tuple[frozenset[Cell], ...]], int] = {}
        self._blocked: dict[tuple[tuple[Cell, ...], int], frozenset[Cell]] = {}

    def path(self, arm: int, start: Cell, goal: Cell, blocked: frozenset[Cell]) -> tuple[Cell, ...] | None:
        """Shortest path inside the arm's reach avoiding `blocked` (cells entered, start excluded)."""
        key = (arm, start, goal, blocked)
        found = self._paths.get(key, _MISSING)  # the hottest lookup of the search: no closure per call
        if found is _MISSING:
            found = _bounded(self._paths, key, lambda: self._shortest_path(arm, start, goal, blocked))
        return found  # type: ignore[return-value]

    def _shortest_path(self, arm: int, start: Cell, goal: Cell,
                       blocked: frozenset[Cell]) -> tuple[Cell, ...] | None:
        reach = self.lay.reach[arm]
        prev: dict[Cell, Cell | None] = {start: None}
        queue = deque([start])
        while queue:
            cur = queue.popleft()
            if cur == goal:
                out = []
                while cur != start:
                    out.append(cur)
                    cur = prev[cur]  # type: ignore[assignment]
                return tuple(reversed(out))
            r, c = cur
            for n in ((r - 1, c), (r + 1, c), (r, c - 1), (r, c + 1)):
                if n in reach and n not in blocked and n not in prev:
                    prev[n] = cur
                    queue.append(n)
        return None

    def grid_dist(self, a: Cell, b: Cell) -> int:
        return self._dist[a].get(b, 10**6)

    def carry_cost(self, a: Cell, b: Cell) -> int:
        """Lower bound on carrying a block from a to b: the grid distance, plus per handover (change
        of arm) a put, a pick and the taker's move onto the cell the giver's end effector just left."""
        return self._dist[a].get(b, 10**6) + HANDOVER_COST * self._hops[a][b]

    @cached_property
    def _hops(self) -> dict[Cell, dict[Cell, int]]:
        """Fewest handovers between two cells: arm-graph distance between the arms reaching them."""
        n = len(ARMS)
        far = 10**3
        hop = [
            [0 if i == j else (1 if self.lay.reach[i] & self.lay.reach[j] else far) for j in range(n)]
            for i in range(n)
        ]
        for k in range(n):
            for i in range(n):
                for j in range(n):
                    hop[i][j] = min(hop[i][j], hop[i][k] + hop[k][j])
        arms = {c: self.lay.arms_reaching(c) for c in self.lay.cells}
        return {
            a: {b: min(hop[i][j] for i in arms[a] for j in arms[b]) for b in self.lay.cells}
            for a in self.lay.cells
        }

    @cached_property
    def _dist(self) -> dict[Cell, dict[Cell, int]]:
        """All-pairs 4-neighbour distances over the table cells (a few dozen cells)."""
        out: dict[Cell, dict[Cell, int]] = {}
        for a in self.lay.cells:
            dist = {a: 0}
            queue = deque([a])
            while queue:
                cur = queue.popleft()
                r, c = cur
                for n in ((r - 1, c), (r + 1, c), (r, c - 1), (r, c + 1)):
                    if n in self.lay.cells and n not in dist:
                        dist[n] = dist[cur] + 1
                        queue.append(n)
            out[a] = dist
        return out

    def heuristic(self, snap: Snap, p: PState) -> int:
        """Admissible bound: every block must visit one cell of each target set its unfinished leaves
        name (in some order; one put per visit, one pick per departure, `carry_cost` per leg); when
        no handover is needed, plus the empty-handed approach of the farthest such block."""
        cells, hands, blocks = snap
        sets: dict[int, list[frozenset[Cell]]] = {}
        for leaf, req in self.targets.items():
            if p[1] & self.progress.bit[leaf]:
                continue
            for b, targets in req.items():
                if blocks[b] is None or blocks[b] not in targets:
                    sets.setdefault(b, []).append(targets)
        total = approach = 0
        for b, needed in sets.items():
            held = blocks[b] is None
            src = cells[hands.index(b)] if held else blocks[b]
            assert src is not None
            tour = self._tour(src, tuple(needed))
            total += tour + 2 * len(needed) - (1 if held else 0)
            if not held and not any(self._hops[src][t] for ts in needed for t in ts):
                approach = max(
                    approach,
                    min(
                        (self.grid_dist(cells[a], src) for a in range(len(ARMS)) if src in self.lay.reach[a]),
                        default=0,
                    ),
                )
        # a block with nothing left to do that sits on the only cell another block must reach has to
        # make room: a pick, at least one move and a put
        in_way = {
            blocks.index(next(iter(ts)))
            for needed in sets.values()
            for ts in needed
            if len(ts) == 1 and next(iter(ts)) in blocks
        }
        total += 3 * len(in_way - set(sets))
        return total + approach

    def _tour(self, src: Cell, needed: tuple[frozenset[Cell], ...]) -> int:
        """Shortest walk from `src` through one cell of every set, in the best order."""
        return _bounded(self._tours, (src, needed), lambda: self._shortest_tour(src, needed))

    def _shortest_tour(self, src: Cell, needed: tuple[frozenset[Cell], ...]) -> int:
        unique = list(dict.fromkeys(needed))[:4]
        best = 10**6
        for order in itertools.permutations(unique):
            frontier = {src: 0}
            for targets in order:
                frontier = {t: min(d + self.carry_cost(c, t) for c, d in frontier.items()) for t in targets}
            best = min(best, min(frontier.values()))
        return best

    def _blocked_by(self, cells: tuple[Cell, ...], arm: int) -> frozenset[Cell]:
        """The cells the other arms stand on, one frozenset per (cells, arm): `path`'s cache keys then
        hold the same object, and a hit compares it by identity instead of element by element."""
        key = (cells, arm)
        found = self._blocked.get(key)
        if found is None:
            others = frozenset(c for i, c in enumerate(cells) if i != arm)
            found = _bounded(self._blocked, key, lambda: others)
        return found

    def macros(self, snap: Snap) -> list[Macro]:
        cells, hands, blocks = snap
        out: list[Macro] = []
        for arm in range(len(ARMS)):
            here = cells[arm]
            blocked = self._blocked_by(cells, arm)
            if hands[arm] < 0:
                for b, where in enumerate(blocks):
                    if where is not None and where in self.lay.reach[arm] and where not in blocked:
                        p = self.path(arm, here, where, blocked)
                        if p is not None:
                            out.append(Macro(arm, list(p), "pickup", b))
            else:
                for cell in self.put_cells[arm]:
                    if cell not in blocked and cell not in blocks:
                        p = self.path(arm, here, cell, blocked)
                        if p is not None:
                            out.append(Macro(arm, list(p), "put", hands[arm]))
            if here in self.lay.shared:
                options = [
                    (len(p), p)
                    for c in self.lay.own(arm)
                    if (p := self.path(arm, here, c, blocked)) is not None
                ]
                if options:
                    out.append(Macro(arm, list(min(options)[1]), "retreat"))
        return out

    def successor(self, key: tuple[Snap, PState], m: Macro) -> tuple[Snap, PState] | None:
        """The state after macro m (None when the spec can no longer be satisfied)."""
        snap, p = key
        new_snap, event = self.apply(snap, m)
        q: PState | None = p
        if m.path:
            q = self.progress.step(p, snap, None)
        if q is not None and m.verb != "retreat":
            q = self.progress.step(q, new_snap, event)
        return None if q is None else (new_snap, q)

    def commutes(
        self, before: tuple[Snap, PState], prev: Macro, m: Macro, result: tuple[Snap, PState]
    ) -> bool:
        """Partial-order reduction: True when macro m of a lower-numbered arm, done before `prev`
        from the state `before`, leads to the same state `result` (so that order is searched)."""
        if m.arm >= prev.arm or (m.block >= 0 and m.block == prev.block):
            return False
        prev_start = before[0][0][prev.arm]
        mine = set(m.path) | {before[0][0][m.arm]}
        theirs = set(prev.path) | {prev_start}
        if mine & theirs:
            return False
        first = self.successor(before, m)
        if first is None:
            return False
        if m.verb == "put" and m.path == [] and first[0][2].count(None) != before[0][2].count(None) - 1:
            return False
        second = self.successor(first, prev)
        return second == result

    def apply(self, snap: Snap, m: Macro) -> tuple[Snap, Event]:
        cells, hands, blocks = list(snap[0]), list(snap[1]), list(snap[2])
        if m.path:
            cells[m.arm] = m.path[-1]
        here = cells[m.arm]
        event: Event = None
        if m.verb == "pickup":
            hands[m.arm], blocks[m.block] = m.block, None
            event = ("pick", m.block, here)
        elif m.verb == "put":
            hands[m.arm], blocks[m.block] = -1, here
            event = ("put", m.block, here)
        return (tuple(cells), tuple(hands), tuple(blocks)), event


HANDOVER_COST = 3  # put + pick + the taker's move onto the handover cell
WEIGHTS = (2.0, 1.0)  # anytime: a weighted-A* plan first, then A* bounded by it (heavier weights wander)
FIRST_SHARE = 0.7  # of the budget, for the first search


def coop_plan(
    hw: HandoverWorld,
    spec: HierarchicalSpec | list | str,
    timeout_s: float | None = None,
    max_expansions: int = MAX_EXPANSIONS,
    use_heuristic: bool = True,
    weights: tuple[float, ...] = WEIGHTS,
) -> CoopResult:
    """Cheapest cooperative plan (moves + actions) for the four arms under a hierarchical spec.

    Anytime: weighted A* with each of `weights` in turn, every search pruned by the best plan so far;
    when the last weight is 1 and its search finishes, the plan is optimal in the macro model
    (`proven_optimal`). The budget is `max_expansions` (deterministic: the same plan on any machine,
    under any load); `timeout_s`, when given, is only a safety stop (a run it ends is load-dependent)."""
    t0 = time.perf_counter()
    if not isinstance(spec, HierarchicalSpec):
        spec = HierarchicalSpec.from_json(spec)
    s = _Search(hw, spec)
    h: Callable[[Snap, PState], int] = s.heuristic if use_heuristic else (lambda a, b: 0)
    budget = _Spend(Budget(expansions=max_expansions), t0 + timeout_s if timeout_s is not None else math.inf)
    best: tuple[int, list[Macro]] | None = None
    proven = exhausted = False
    stopped = StopReason.BUDGET
    for i, w in enumerate(weights):
        # the first (weighted) search gets most of the budget; the rest goes to the exact A*
        share = FIRST_SHARE if i == 0 and len(weights) > 1 else 1.0
        budget.stop_expanded = budget.expanded + int((budget.limit - budget.expanded) * share)
        if best is None and i > 0:
            w = (weights[0] + w) / 2  # the first search found nothing: a lighter weight, not plain A*
        found, complete = _astar(s, h, w, best[0] if best else None, budget)
        if found is not None:
            best = found
        if complete and w == 1.0 and best is not None:
            proven, stopped = True, StopReason.EXHAUSTED
        if complete and best is None:
            exhausted, stopped = True, StopReason.EXHAUSTED  # no plan at all: even this search ran out
            break
        if budget.expanded >= budget.limit:
            stopped = StopReason.BUDGET
            break
        if time.perf_counter() > budget.deadline:
            stopped = StopReason.TIMEOUT
            break
    if best is None:
        status = PlanStatus.INFEASIBLE if exhausted else PlanStatus.TIMEOUT
        reason = (
            f"no cooperative plan satisfies the specification (searched {budget.expanded} states)"
            if exhausted
            else f"no plan within {budget.expanded} expansions"
            + (f" / {timeout_s:g} s" if timeout_s is not None else "")
        )
        return CoopResult(status, reason, expanded=budget.expanded, plan_time_s=time.perf_counter() - t0,
                          stopped=stopped)
    out = _finish(hw, spec, best[1], best[0], budget.expanded, t0)
    out.proven_optimal, out.stopped = proven, stopped
    return out


@dataclass
class _Spend:
    """What the searches of one `coop_plan` call have spent of its `Budget`."""

    budget: Budget
    deadline: float  # the wall-clock last resort
    expanded: int = 0
    stop_expanded: int = 0  # end of the current search's share of the expansions

    @property
    def limit(self) -> int:
        return self.budget.expansions if self.budget.expansions is not None else 10**12

    @property
    def spent(self) -> bool:
        return self.expanded >= self.stop_expanded or time.perf_counter() > self.deadline


def _astar(
    s: _Search, h: Callable[[Snap, PState], int], weight: float, bound: int | None, budget: _Spend
) -> tuple[tuple[int, list[Macro]] | None, bool]:
    """One weighted A* (f = g + weight*h), pruning g + h >= bound; (cost, macros) and whether the
    search space was exhausted (so nothing cheaper than `bound` exists when nothing was found)."""
    root = (initial_snap(s.hw), s.progress.init())
    g: dict[Any, int] = {root: 0}
    parent: dict[Any, tuple[Any, Macro] | None] = {root: None}
    tie = itertools.count()
    heap: list[tuple[float, int, int, Any]] = [(weight * h(*root), 0, next(tie), root)]
    limit = bound if bound is not None else 10**9
    while heap:
        _, neg_cost, _, key = heapq.heappop(heap)
        cost = -neg_cost
        if cost > g[key]:
            continue
        snap, p = key
        if s.progress.finished(p):
            return (cost, _macros_to(parent, key)), True
        budget.expanded += 1
        if budget.spent:
            return None, False
        link = parent[key]
        for m in s.macros(snap):
            nkey = s.successor(key, m)
            if nkey is None:
                continue
            new_snap, q = nkey
            ncost = cost + len(m.path) + (m.verb != "retreat")
            # the cheap test first: the order reduction (two more successors) only for a new best
            if ncost >= g.get(nkey, 10**9) or (link is not None and s.commutes(link[0], link[1], m, nkey)):
                continue
            hn = h(new_snap, q)
            if ncost + hn >= limit:
                continue
            g[nkey] = ncost
            parent[nkey] = (key, m)
            heapq.heappush(heap, (ncost + weight * hn, -ncost, next(tie), nkey))
    return None, True


def _macros_to(parent: dict[Any, tuple[Any, Macro] | None], key: Any) -> list[Macro]:
    macros: list[Macro] = []
    cur = key
    while (link := parent[cur]) is not None:
        cur, m = link
        macros.append(m)
    macros.reverse()
    return macros


def macros_to_plan(hw: HandoverWorld, macros: list[Macro]) -> Plan:
    """Macros one after another on a common clock (the other arms wait)."""
    steps: dict[int, list[Step]] = {a: [] for a in range(len(ARMS))}
    names = hw.block_names()
    t = 0
    for m in macros:
        for cell in m.path:
            t += 1
            steps[m.arm].append(Step(t=t, verb="move", cell=cell))
        if m.verb == "pickup":
            t += 1
            steps[m.arm].append(Step(t=t, verb="pickup", objects=[names[m.block]]))
        elif m.verb == "put":
            t += 1
            here = m.path[-1] if m.path else _cell_before(hw, macros, m)
            steps[m.arm].append(Step(t=t, verb="put", objects=[names[m.block], hw.layout.place_name(here)]))
    return Plan(robots=[RobotPlan(robot=a, start=hw.arm_starts[a], steps=steps[a]) for a in range(len(ARMS))])


def _cell_before(hw: HandoverWorld, macros: list[Macro], m: Macro) -> Cell:
    """Where an arm's end effector is when macro `m` (with an empty path) starts."""
    cell = hw.arm_starts[m.arm]
    for x in macros:
        if x is m:
            return cell
        if x.arm == m.arm and x.path:
            cell = x.path[-1]
    return cell


def _finish(
    hw: HandoverWorld, spec: HierarchicalSpec, macros: list[Macro], cost: int, expanded: int, t0: float
) -> CoopResult:
    plan = macros_to_plan(hw, macros)
    execution = execute_handover(hw, plan, sorted(spec.atoms()))
    verdict = check_handover(spec, execution)
    if not execution.ok or not verdict.ok:
        why = "; ".join(execution.violations[:2] + verdict.reasons[:2])
        raise PlanningError(f"internal error: the cooperative plan failed its own check: {why}")
    return CoopResult(
        PlanStatus.SOLVED,
        "",
        plan,
        cost,
        execution.travel,
        execution.actions,
        execution.steps,
        len(execution.handovers),
        expanded,
        time.perf_counter() - t0,
        execution=execution,
    )


# ----- entry point for the pipeline's planning stage on a handover world ------------------------------
def plan_world(
    world: Any, spec: HierarchicalSpec | list | str, starts: Any = None, **options: Any
) -> PlanResult:
    """Plan on a handover `worlds.World` (from `load_world("handover-square")`) and answer in the main
    planner's `PlanResult` shape: blocks where the world has them, end effectors at `starts` when four
    cells are given (else the world's). Options other than timeout_s (a last-resort stop) are ignored
    (the cooperative planner minimises moves + actions). `execution` stays None: the handover
    simulator's run is in `coop_plan`'s own result."""
    from nl2hltl2plan.worlds.handover_world import HandoverWorld, layout
    from nl2hltl2plan.worlds.world import CELL_M

    if getattr(world, "kind", "") != "handover":
        raise PlanningError(f"{getattr(world, 'name', world)} is not a handover world")
    lay = layout(world.name.split("-", 1)[1])
    blocks = {o.type[:-5]: o.interaction_cells[0] for o in world.objects.values() if o.type.endswith("Block")}
    given = [tuple(c) for c in starts] if starts is not None else []
    arm_starts = tuple(given) if len(given) == len(ARMS) else tuple(world.default_starts)
    hw = HandoverWorld(lay, blocks, arm_starts)  # type: ignore[arg-type]
    timeout = options.get("timeout_s")  # the pipeline's last-resort wall clock; the budget is expansions
    coop = coop_plan(hw, spec, timeout_s=None if timeout is None else float(timeout))
    return PlanResult(
        status=coop.status,
        reason=coop.reason,
        objective="min",
        mode="coop",
        plan=coop.plan,
        travel_m=None if coop.travel is None else coop.travel * CELL_M,
        steps=coop.steps,
        total_cost=coop.cost,
        cost=None if coop.cost is None else float(coop.cost),
        proven_optimal=coop.proven_optimal,
        optimality="proven optimal" if coop.proven_optimal else "no bound proven",
        model="cooperative macro model (planning/coop.py)",
        plan_time_s=coop.plan_time_s,
        expanded=coop.expanded,
        stopped=coop.stopped,
        stop_reason=coop.stopped.sentence,
    )
