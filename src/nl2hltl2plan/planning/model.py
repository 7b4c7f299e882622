"""The planning problem: a world, robots, and a hierarchical spec compiled into search-ready pieces.

What the search needs from the spec (CONTRACTS.md, "attributed traces"):
- every leaf as a DFA read one event at a time (its own events only), with the moves available
  from each state: (atom, next state); `leaves.py` compiles it. A leaf is done when its DFA accepts.
- the non-leaf DFAs, read on completion events of their children (each child completes once).
- when the relation compiler wrote every non-leaf (`precedence_form`), the explicit pairs
  "a before b": the planner starts every leaf under b only after a completes (strictly later), so
  the checker's strict order holds too. Otherwise ("general" structure) completions are serialised
  and a leaf starts only after every earlier completion.

Constraints beside the spec (`logic.constraints`: G !p, until-guards) become the problem's
forbidden atoms: the search generates no event that one forbids (`Problem.forbidden_by`), and a leaf
whose every action sequence needs a forbidden atom is infeasible before any search, naming the
constraint.

Static infeasibility (a type the world lacks, an object no robot can reach, a receptacle that does
not accept the object, a contradictory ordering, an action no robot may do) is found here, before
any search, with a readable reason.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from functools import cached_property

import networkx as nx

from nl2hltl2plan.errors import PlanningError, SpecError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.automaton import DEAD, Dfa
from nl2hltl2plan.logic.constraints import Constraint, breach
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.planning.leaves import DONE, Leaf, LeafAtom, check_stutter, compile_leaf, parse_atom
from nl2hltl2plan.worlds.checker import watches_states
from nl2hltl2plan.worlds.plan import ACTION_ARITY
from nl2hltl2plan.worlds.world import Cell, World


class Infeasible(Exception):
    """Raised while building a problem that provably has no plan; `reason` is readable."""

    def __init__(self, reason: str):
        super().__init__(reason)
        self.reason = reason


@dataclass
class NonLeaf:
    """A non-leaf formula. In the relation compiler's form (`pairs` set) it is satisfied when every
    child is complete and each pair (a, b) completed a no later than b; no automaton is needed (a
    conjunction of n `F c` has 2^n states). Otherwise its DFA reads completion events."""

    index: int
    name: str
    dfa: Dfa | None
    children: tuple[str, ...]
    pairs: tuple[tuple[str, str], ...] | None  # precedence form, else None

    @property
    def init(self) -> int:
        return self.dfa.init if self.dfa is not None else 0


@dataclass
class Problem:
    """Everything fixed during a search: world, robots, compiled spec."""

    world: World
    spec: HierarchicalSpec
    starts: tuple[Cell, ...]
    capabilities: tuple[frozenset[str] | None, ...]
    leaves: list[Leaf]
    nonleaves: list[NonLeaf]
    parent: dict[str, str | None]
    roots: tuple[str, ...]
    precedence: bool  # every non-leaf in the relation compiler's form
    gates: dict[int, tuple[str, ...]] = field(default_factory=dict)  # leaf -> nodes done before it starts
    constraints: tuple[Constraint, ...] = ()  # the spec's: atoms no event may be (until a node is done)

    @property
    def n_robots(self) -> int:
        return len(self.starts)

    @cached_property
    def leaf_index(self) -> dict[str, int]:
        return {lf.name: lf.index for lf in self.leaves}

    @cached_property
    def nonleaf_index(self) -> dict[str, int]:
        return {n.name: n.index for n in self.nonleaves}

    @cached_property
    def node_names(self) -> list[str]:
        """Leaves first, then non-leaves: the index space of completion times."""
        return [lf.name for lf in self.leaves] + [n.name for n in self.nonleaves]

    @cached_property
    def node_slot(self) -> dict[str, int]:
        return {name: i for i, name in enumerate(self.node_names)}

    def ancestors(self, name: str) -> list[str]:
        out = []
        p = self.parent.get(name)
        while p is not None:
            out.append(p)
            p = self.parent.get(p)
        return out

    def forbidden_by(
        self, events: Iterable[str], done_t: Sequence[int] = (), t: int = 0
    ) -> Constraint | None:
        """The constraint an event at step t breaks (None: none), given the nodes' completion steps
        `done_t` (indexed by `node_slot`, -1: not complete; empty: nothing complete)."""
        slot = self.node_slot
        done = (lambda n: done_t[slot[n]] if done_t[slot[n]] >= 0 else None) if done_t else (lambda n: None)
        return next((c for e in events if (c := breach(self.constraints, e, t, done))), None)

    @cached_property
    def watches_states(self) -> bool:
        """Does a constraint forbid a change of state (`worlds.checker.watches_states`)?"""
        return watches_states(self.constraints)

    def can_do(self, robot: int, atom: LeafAtom) -> bool:
        caps = self.capabilities[robot]
        return caps is None or atom.verb in caps or atom.text in caps

    # ------------------------------------------------------------ non-leaf progress
    def step_parent(self, nonleaf: int, state: int, child: str, done: frozenset[str]) -> int | None:
        """The non-leaf's state once `child` completes (the others in `done` are complete): DONE
        when it is satisfied, None when it no longer can be."""
        nl = self.nonleaves[nonleaf]
        if nl.dfa is None:
            if any(b == child and a not in done for a, b in nl.pairs or ()):
                return None
            return DONE if all(c in done or c == child for c in nl.children) else state
        q2 = nl.dfa.step(state, (child,))
        if q2 in nl.dfa.accepting:
            return DONE
        remaining = frozenset(c for c in nl.children if c != child and c not in done)
        return q2 if self.viable(nonleaf, q2, remaining) else None

    def viable(self, nonleaf: int, state: int, remaining: frozenset[str]) -> bool:
        """Can the non-leaf still be satisfied from `state` when each child in `remaining`
        completes at most once (one completion per step, idle steps in between)?"""
        key = (nonleaf, state, remaining)
        hit = self._viable_cache.get(key)
        if hit is not None:
            return hit
        dfa = self.nonleaves[nonleaf].dfa
        assert dfa is not None
        ok = False
        seen = {(state, remaining)}
        queue = deque([(state, remaining)])
        while queue:
            q, rem = queue.popleft()
            if q in dfa.accepting:
                ok = True
                break
            if dfa.is_dead(q):
                continue
            for child in rem:
                q2 = dfa.step(q, (child,))
                nxt = (q2, rem - {child})
                if nxt not in seen and q2 != DEAD:
                    seen.add(nxt)
                    queue.append(nxt)
        self._viable_cache[key] = ok
        return ok

    @cached_property
    def _viable_cache(self) -> dict:
        return {}


# ---------------------------------------------------------------- building
def build_problem(
    world: World,
    spec: HierarchicalSpec,
    starts: Sequence[Cell],
    capabilities: Sequence[Iterable[str] | None] | None = None,
    dfa_timeout_s: float = 30.0,
) -> Problem:
    """Compile the spec for search and run the static feasibility checks.

    Raises PlanningError for malformed input (bad start cells, unknown capability) and
    `Infeasible` when no plan can exist."""
    starts_t = tuple((int(c[0]), int(c[1])) for c in starts)
    if not starts_t:
        raise PlanningError("at least one robot is needed")
    for r, cell in enumerate(starts_t):
        if cell not in world.cell_set:
            raise PlanningError(f"robot {r} starts at {cell}, which is not a free cell of {world.name}")
    caps: list[frozenset[str] | None] = []
    for r in range(len(starts_t)):
        entry = capabilities[r] if capabilities is not None and r < len(capabilities) else None
        if entry is None:
            caps.append(None)
            continue
        allowed = frozenset(entry)
        for cap in allowed:
            if cap not in ACTION_ARITY and parse_atom(cap) is None:
                raise PlanningError(f"robot {r}: capability {cap!r} is neither a verb "
                                    f"({', '.join(ACTION_ARITY)}) "
                                    "nor an action atom like pickup(Apple)")
        caps.append(allowed)

    names = spec.names
    leaves: list[Leaf] = []
    nonleaves: list[NonLeaf] = []
    parent: dict[str, str | None] = {n: None for n in names}
    for n in names:
        for c in spec.children(n):
            parent[c] = n
    for n in names:
        if spec.is_leaf(n):
            leaves.append(compile_leaf(len(leaves), n, _dfa(spec, n, dfa_timeout_s)))
            continue
        children = tuple(spec.children(n))
        form = sb.precedence_form(spec.formula(n))
        pairs = tuple(form[1]) if form is not None and set(form[0]) == set(children) else None
        dfa = None
        if pairs is None:
            dfa = _dfa(spec, n, dfa_timeout_s)
            check_stutter(n, dfa, [1 << i for i in range(len(dfa.atoms))])
        nonleaves.append(NonLeaf(len(nonleaves), n, dfa, children, pairs))
    problem = Problem(
        world=world,
        spec=spec,
        starts=starts_t,
        capabilities=tuple(caps),
        leaves=leaves,
        nonleaves=nonleaves,
        parent=parent,
        roots=tuple(spec.roots),
        precedence=all(nl.pairs is not None for nl in nonleaves),
        constraints=spec.constraints,
    )
    _check_orderings(problem)
    _check_leaves(problem)
    if problem.precedence:
        problem.gates = {lf.index: _gates(problem, lf.name) for lf in leaves}
    return problem


def _dfa(spec: HierarchicalSpec, name: str, timeout_s: float) -> Dfa:
    try:
        return spec.dfa(name, timeout_s=timeout_s)
    except SpecError:
        raise
    except Exception as exc:  # FormulaError (too large / not sc-LTL): a user-facing problem
        raise PlanningError(f"cannot build the automaton of {name}: {exc}") from None


def _gates(problem: Problem, leaf: str) -> tuple[str, ...]:
    """Spec nodes that must be complete before `leaf` starts: for the leaf and each ancestor A,
    every a with (a, A) among the pairs of A's parent."""
    out: list[str] = []
    node = leaf
    while problem.parent.get(node) is not None:
        par = problem.parent[node]
        nl = problem.nonleaves[problem.nonleaf_index[par]]  # type: ignore[index]
        out += [a for a, b in nl.pairs or () if b == node]
        node = par  # type: ignore[assignment]
    return tuple(dict.fromkeys(out))


def _check_orderings(problem: Problem) -> None:
    for nl in problem.nonleaves:
        if nl.dfa is None:
            g = nx.DiGraph(list(nl.pairs or ()))
            if not nx.is_directed_acyclic_graph(g):
                cycle = nx.find_cycle(g)
                order = " before ".join([a for a, _ in cycle] + [cycle[0][0]])
                raise Infeasible(f"{nl.name}: the ordering of its tasks has a cycle ({order})")
            continue
        if problem.viable(nl.index, nl.dfa.init, frozenset(nl.children)):
            continue
        raise Infeasible(f"{nl.name}: no order of completing its tasks satisfies "
                         f"{problem.spec.text(nl.name)}")


def _check_leaves(problem: Problem) -> None:
    """Every leaf needs at least one action sequence the world and the robots can carry out."""
    world = problem.world
    comps = [c for c in world.components if any(s in c for s in problem.starts)]
    robot_cells = set().union(*comps) if comps else set()
    reasons: dict[str, str] = {}

    def reachable(type_: str) -> bool:
        return any(
            set(o.interaction_cells) & robot_cells or (o.slice_of and _reach(world, o.slice_of, robot_cells))
            for o in world.instances(type_)
        )

    for lf in problem.leaves:
        if lf.init == DONE:
            continue
        problems = []
        for path in lf.paths.get(lf.init) or [()]:
            why = None
            for k in path:
                why = _atom_problem(problem, lf.atoms[k], reachable)
                if why:
                    break
            if not why:
                break
            problems.append(why)
        else:
            reasons[lf.name] = "; ".join(dict.fromkeys(problems)) or "it has no action sequence"
    if reasons:
        required = required_leaves(problem)
        blocking = {n: r for n, r in reasons.items() if n in required}
        if blocking:
            raise Infeasible("; ".join(f"{n}: {r}" for n, r in blocking.items()))
    _check_supply(problem, robot_cells)


def _check_supply(problem: Problem, robot_cells: set[Cell]) -> None:
    """Each task takes its own object: more required leaves that must pick up a type than the world
    has reachable instances of it cannot all be done."""
    world = problem.world
    required = required_leaves(problem)
    demand: dict[str, list[str]] = {}
    for lf in problem.leaves:
        paths = lf.paths.get(lf.init)
        if lf.name not in required or lf.init == DONE or not paths:
            continue
        must = None
        for path in paths:
            taken = {lf.atoms[k].types[0] for k in path
                     if lf.exclusive(lf.atoms[k].verb, lf.atoms[k].types[0])}
            must = taken if must is None else must & taken
        for t in must or ():
            demand.setdefault(t, []).append(lf.name)
    for t, leaves in sorted(demand.items()):
        supply = sum(1 for o in world.instances(t) if _reach(world, o.slice_of or o.id, robot_cells))
        if len(leaves) > supply:
            raise Infeasible(f"{', '.join(leaves)} each need their own {t}, but the robots can reach "
                             f"{supply} {t}{'' if supply == 1 else 's'} in {world.name}")


def _reach(world: World, oid: str, cells: set[Cell]) -> bool:
    return bool(set(world.objects[oid].interaction_cells) & cells)


def _atom_problem(problem: Problem, atom: LeafAtom, reachable) -> str | None:
    world = problem.world
    verb, types = atom.verb, atom.types
    for t in types:
        if not world.instances(t):
            return f"{atom.text}: there is no {t} in {world.name}"
        if not reachable(t):
            return f"{atom.text}: no robot can reach any {t} (no free cell within 1.5 m in the robots' area)"
    first = world.instances(types[0])[0].affordances
    if verb == "pickup" and not first.pickupable:
        return f"{atom.text}: a {types[0]} cannot be picked up"
    if verb == "put":
        rec = world.instances(types[1])[0].affordances
        if not rec.receptacle:
            return f"{atom.text}: a {types[1]} is not a receptacle"
        if types[0] not in rec.accepts:
            return f"{atom.text}: a {types[1]} cannot accept a {types[0]}"
    if verb in ("open", "close") and not first.openable:
        return f"{atom.text}: a {types[0]} cannot be opened or closed"
    if verb in ("toggle_on", "toggle_off") and not first.toggleable:
        return f"{atom.text}: a {types[0]} cannot be switched on or off"
    if verb == "slice" and not first.sliceable:
        return f"{atom.text}: a {types[0]} cannot be sliced"
    if not any(problem.can_do(r, atom) for r in range(problem.n_robots)):
        return f"no robot in the team can {atom.text}"
    banned = problem.forbidden_by([atom.text])
    if banned is not None and banned.until is None:
        return f"{atom.text} is forbidden by the constraint {banned.text!r} ({banned.formula})"
    return None


def required_leaves(problem: Problem) -> set[str]:
    """Leaves every plan must complete: all of them under precedence-form specs; in general, the
    leaves without which some ancestor can no longer be satisfied."""
    if problem.precedence:
        return {lf.name for lf in problem.leaves}
    required = set()
    for lf in problem.leaves:
        node = lf.name
        needed = True
        while needed and problem.parent.get(node) is not None:
            par = problem.parent[node]
            nl = problem.nonleaves[problem.nonleaf_index[par]]  # type: ignore[index]
            rest = frozenset(nl.children) - {node}
            needed = nl.dfa is None or not problem.viable(nl.index, nl.dfa.init, rest)
            node = par  # type: ignore[assignment]
        if needed:
            required.add(lf.name)
    return required
