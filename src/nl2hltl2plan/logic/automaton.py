"""Deterministic finite automata of good prefixes, as plain Python data.

Letters are sets of atomic propositions (those true at a step). A guard is a list of cubes; a cube
(pos, neg) is two bitmasks over `Dfa.atoms`: the letter must contain every `pos` atom and no `neg`
atom. Missing transitions go to an implicit rejecting sink (`DEAD`).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from functools import cached_property

Cube = tuple[int, int]
DEAD = -1


@dataclass(frozen=True)
class Dfa:
    atoms: tuple[str, ...]
    init: int
    accepting: frozenset[int]
    edges: list[list[tuple[Cube, int]]] = field(hash=False, compare=False)

    @property
    def num_states(self) -> int:
        return len(self.edges)

    @property
    def num_edges(self) -> int:
        """Number of (state, destination) pairs with a non-empty guard."""
        return sum(len({dst for _, dst in out}) for out in self.edges)

    @cached_property
    def _index(self) -> dict[str, int]:
        return {a: i for i, a in enumerate(self.atoms)}

    def letter(self, true_atoms: Iterable[str]) -> int:
        """Bitmask of the atoms of this DFA that are true; atoms it does not mention are ignored."""
        idx = self._index
        m = 0
        for a in true_atoms:
            i = idx.get(a)
            if i is not None:
                m |= 1 << i
        return m

    def step_mask(self, state: int, letter: int) -> int:
        if state == DEAD:
            return DEAD
        for (pos, neg), dst in self.edges[state]:
            if letter & pos == pos and not letter & neg:
                return dst
        return DEAD

    def step(self, state: int, true_atoms: Iterable[str]) -> int:
        return self.step_mask(state, self.letter(true_atoms))

    def run(self, word: Sequence[Iterable[str]], state: int | None = None) -> int:
        s = self.init if state is None else state
        for letter in word:
            s = self.step(s, letter)
        return s

    def accepts(self, word: Sequence[Iterable[str]]) -> bool:
        """Is the finite word a good prefix of the formula?"""
        return self.run(word) in self.accepting

    @cached_property
    def dist_to_accept(self) -> dict[int, int]:
        """Fewest letters from each state to an accepting one (states absent: cannot accept)."""
        rev: dict[int, set[int]] = {}
        for s, out in enumerate(self.edges):
            for _, dst in out:
                rev.setdefault(dst, set()).add(s)
        dist = {s: 0 for s in self.accepting}
        queue = deque(self.accepting)
        while queue:
            s = queue.popleft()
            for p in rev.get(s, ()):
                if p not in dist:
                    dist[p] = dist[s] + 1
                    queue.append(p)
        return dist

    def is_dead(self, state: int) -> bool:
        return state == DEAD or state not in self.dist_to_accept

    def mask_to_atoms(self, mask: int) -> frozenset[str]:
        return frozenset(a for i, a in enumerate(self.atoms) if mask >> i & 1)


def distinguishing_word(a: Dfa, b: Dfa, once: Iterable[str] | None = None) -> list[frozenset[str]] | None:
    """A shortest finite word that is a good prefix of exactly one of the two automata, or None.

    With `once`, only words in which each of those propositions holds at most once count (the
    completion-event semantics of composite propositions); other atoms are unrestricted.
    Breadth-first over the product; letters are enumerated as the intersections of the two
    automata's guards (every letter in such an intersection leads to the same pair of states)."""
    atoms = sorted(set(a.atoms) | set(b.atoms))
    bit = {x: 1 << i for i, x in enumerate(atoms)}
    once_mask = sum(bit[x] for x in (once or ()) if x in bit)

    def remap(d: Dfa, cube: Cube) -> Cube:
        pos = sum(bit[x] for i, x in enumerate(d.atoms) if cube[0] >> i & 1)
        neg = sum(bit[x] for i, x in enumerate(d.atoms) if cube[1] >> i & 1)
        return pos, neg

    out_a = [[(remap(a, c), t) for c, t in edges] for edges in a.edges]
    out_b = [[(remap(b, c), t) for c, t in edges] for edges in b.edges]
    start = (a.init, b.init, 0)
    parent: dict[tuple[int, int, int], tuple[tuple[int, int, int], int] | None] = {start: None}
    queue = deque([start])
    while queue:
        node = queue.popleft()
        sa, sb_, used = node
        if (sa in a.accepting) != (sb_ in b.accepting):
            word: list[frozenset[str]] = []
            cur = node
            while (link := parent[cur]) is not None:
                cur, letter = link
                word.append(frozenset(x for x in atoms if letter & bit[x]))
            return word[::-1]
        if sa == DEAD or sb_ == DEAD:
            continue
        for (pa, na), ta in out_a[sa]:
            for (pb, nb), tb in out_b[sb_]:
                pos, neg = pa | pb, na | nb
                # propositions that already happened must stay false; pos & once is a new use
                neg |= used
                if pos & neg:
                    continue
                nxt = (ta, tb, used | (pos & once_mask))
                if nxt not in parent:
                    parent[nxt] = (node, pos)
                    queue.append(nxt)
    return None
