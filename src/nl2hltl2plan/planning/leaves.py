"""A leaf of the spec as the search reads it: its action atoms, and its DFA compiled into the trie
of its *minimal* accepting action sequences (those containing no other accepting sequence as a
subsequence): a plan that takes a detour through the DFA only adds actions, and dropping them never
costs more (walks obey the triangle inequality). For the Cup-or-Mug recipe this turns an 81-state
DFA into two 9-action chains. The heuristic reads each state's remaining sequences (`paths`).
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from functools import cached_property

from nl2hltl2plan.errors import PlanningError
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.automaton import DEAD, Dfa
from nl2hltl2plan.worlds.plan import ACTION_ARITY
from nl2hltl2plan.worlds.world import KNIFE_TYPES

DONE = -2  # leaf / non-leaf state once its formula is satisfied
MAX_PATHS = 12  # remaining action sequences kept per leaf state for the heuristic


@dataclass(frozen=True)
class LeafAtom:
    """An action atom of one leaf, with its letter in the leaf's DFA."""

    text: str  # put(Apple,Fridge)
    verb: str
    types: tuple[str, ...]
    mask: int  # the letter of this atom alone in the leaf's DFA


def parse_atom(text: str) -> tuple[str, tuple[str, ...]] | None:
    """(verb, types) of a robot action atom with the verb's arity, or None."""
    atom = Atom.read(text)
    if atom is None or atom.verb not in ACTION_ARITY or len(atom.args) != ACTION_ARITY[atom.verb]:
        return None
    return atom.verb, atom.args


@dataclass
class Leaf:
    index: int
    name: str
    dfa: Dfa
    atoms: tuple[LeafAtom, ...]
    init: int  # DFA state, or DONE when the formula holds before any event
    moves: dict[int, list[tuple[int, int]]]  # state -> [(atom index, next state or DONE)]
    min_events: dict[int, int]  # state -> fewest events to satisfy the leaf
    paths: dict[int, list[tuple[int, ...]]]  # state -> minimal remaining atom sequences (if known)
    tools: frozenset[str]  # picked-up types used as tools (a knife that slices): shared by leaves

    def exclusive(self, verb: str, type_: str) -> bool:
        """Does this action claim its object for this leaf alone (distinct objects per task)?"""
        return verb in ("pickup", "slice") and type_ not in self.tools

    @cached_property
    def taken(self) -> frozenset[str]:
        """Types whose instance this leaf takes for itself (claimed as soon as it is bound, also
        when first used as a receptacle: the cup a knife is put into, then carried)."""
        return frozenset(a.types[0] for a in self.atoms if self.exclusive(a.verb, a.types[0]))


def compile_leaf(index: int, name: str, dfa: Dfa) -> Leaf:
    atoms = []
    for i, text in enumerate(dfa.atoms):
        parsed = parse_atom(text)
        if parsed is None:
            raise PlanningError(
                f"leaf {name}: {text!r} is not a robot action like pickup(Apple) or put(Apple,Fridge) "
                f"(verbs: {', '.join(ACTION_ARITY)})"
            )
        atoms.append(LeafAtom(text, parsed[0], parsed[1], 1 << i))
    check_stutter(name, dfa, [a.mask for a in atoms])
    moves: dict[int, list[tuple[int, int]]] = {}
    init = DONE if dfa.init in dfa.accepting else dfa.init
    queue = deque([init] if init != DONE else [])
    seen = set(queue)
    while queue:
        q = queue.popleft()
        out = []
        for k, a in enumerate(atoms):
            q2 = dfa.step_mask(q, a.mask)
            if q2 == q or dfa.is_dead(q2):
                continue  # an event that changes nothing, or one that makes the leaf unsatisfiable
            nxt = DONE if q2 in dfa.accepting else q2
            out.append((k, nxt))
            if nxt != DONE and nxt not in seen:
                seen.add(nxt)
                queue.append(nxt)
        moves[q] = out
    paths = _minimal_paths(moves)
    if init != DONE and init in paths:
        init, moves, paths = _trie(paths[init])
    min_events = _min_events(moves)
    picked = {a.types[0] for a in atoms if a.verb == "pickup"}
    slicing = any(a.verb == "slice" for a in atoms)
    tools = frozenset(t for t in picked if t in KNIFE_TYPES) if slicing else frozenset()
    return Leaf(index, name, dfa, tuple(atoms), init, moves, min_events, paths, tools)


def _min_events(moves: dict[int, list[tuple[int, int]]]) -> dict[int, int]:
    best: dict[int, int] = {}
    changed = True
    while changed:  # Bellman-Ford on a small graph
        changed = False
        for q, out in moves.items():
            for _, nxt in out:
                cand = 1 if nxt == DONE else (best[nxt] + 1 if nxt in best else None)
                if cand is not None and cand < best.get(q, 1 << 30):
                    best[q] = cand
                    changed = True
    return best


def _minimal_paths(moves: dict[int, list[tuple[int, int]]]) -> dict[int, list[tuple[int, ...]]]:
    """Per state, the *minimal* atom sequences to acceptance: those containing no other accepting
    sequence as a subsequence. Every accepting sequence contains one of them (drop repeated
    states and useless events), which is what the heuristic needs to stay a lower bound. A state
    whose set is unknown (a cycle, or more than MAX_PATHS sequences) gets no entry."""
    memo: dict[int, list[tuple[int, ...]] | None] = {}
    on_stack: set[int] = set()

    def solve(q: int) -> list[tuple[int, ...]] | None:
        if q in memo:
            return memo[q]
        if q in on_stack:
            return None
        on_stack.add(q)
        cands: list[tuple[int, ...]] | None = []
        for k, nxt in moves.get(q, []):
            if nxt == DONE:
                cands.append((k,))  # type: ignore[union-attr]
                continue
            rest = solve(nxt)
            if rest is None:
                cands = None
                break
            cands.extend((k,) + r for r in rest)  # type: ignore[union-attr]
        on_stack.discard(q)
        result = None
        if cands is not None:
            cands = sorted(set(cands), key=len)
            kept: list[tuple[int, ...]] = []
            for c in cands:
                if not any(_is_subsequence(m, c) for m in kept):
                    kept.append(c)
            result = kept if len(kept) <= MAX_PATHS else None
        memo[q] = result
        return result

    for q in moves:
        solve(q)
    return {q: v for q, v in memo.items() if v is not None}


Moves = dict[int, list[tuple[int, int]]]


def _trie(sequences: list[tuple[int, ...]]) -> tuple[int, Moves, dict[int, list[tuple[int, ...]]]]:
    """Progress along the leaf's minimal action sequences as a trie (node 0 = nothing done): a
    leaf never does an action that a shorter way of satisfying it would skip (e.g. switching from
    the Mug to the Cup alternative half-way). Dropping such actions never costs more, since walks
    obey the triangle inequality. Returns (root, moves, remaining sequences per node)."""
    moves: dict[int, list[tuple[int, int]]] = {0: []}
    rest: dict[int, list[tuple[int, ...]]] = {0: list(sequences)}
    for seq in sequences:
        node = 0
        for j, k in enumerate(seq):
            if j == len(seq) - 1:
                if (k, DONE) not in moves[node]:
                    moves[node].append((k, DONE))
                break
            nxt = next((n for kk, n in moves[node] if kk == k and n != DONE), None)
            if nxt is None:
                nxt = len(moves)
                moves[nxt] = []
                rest[nxt] = []
                moves[node].append((k, nxt))
            rest[nxt].append(seq[j + 1:])
            node = nxt
    return 0, moves, rest


def _is_subsequence(small: tuple[int, ...], big: tuple[int, ...]) -> bool:
    it = iter(big)
    return all(x in it for x in small)


def check_stutter(name: str, dfa: Dfa, letters: list[int]) -> None:
    """Idle steps (empty letters) must not move the DFA: the planner leaves a task idle between its
    events, and the executor's time steps are not the planner's events. True for F/U formulas."""
    seen = {dfa.init}
    queue = deque([dfa.init])
    while queue:
        q = queue.popleft()
        if q in dfa.accepting or dfa.is_dead(q):
            continue
        if dfa.step_mask(q, 0) != q:
            raise PlanningError(
                f"{name}: the formula changes state on idle steps (it uses X, 'next'); the planner needs "
                "formulas whose truth does not depend on how many idle steps pass (F, U, &, |)"
            )
        for m in letters:
            q2 = dfa.step_mask(q, m)
            if q2 != DEAD and q2 not in seen:
                seen.add(q2)
                queue.append(q2)
