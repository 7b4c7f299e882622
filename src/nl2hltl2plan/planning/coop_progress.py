"""Progress of a hierarchical sc-LTL spec under global letters, and the block targets its leaves name
(for the cooperative planner, planning/coop.py).

`Progress` follows the semantics of `logic.trace.check_trace`: a leaf's DFA reads every letter
until the leaf first accepts (its completion event); a non-leaf in precedence form completes when
all children have and no "a before b" pair was broken; other non-leaves step their DFA on the set
of children completing at that step. Letters here are global (any arm may serve any leaf).
"""

from __future__ import annotations

import re
from typing import Any

from nl2hltl2plan.errors import PlanningError, WorldError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.automaton import DEAD, Dfa
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.worlds.handover_world import HandoverWorld, Snap, compile_atom
from nl2hltl2plan.worlds.world import Cell

Event = tuple[str, int, Cell] | None
PState = tuple[tuple[int, ...], int, tuple[int, ...]]  # leaf DFA states, completed mask, non-leaf DFA states


class Progress:
    """The hierarchical spec's progress under global letters (the semantics of `check_trace`)."""

    def __init__(self, spec: HierarchicalSpec, hw: HandoverWorld) -> None:
        self.spec = spec
        self.names = spec.names
        self.bit = {n: 1 << i for i, n in enumerate(self.names)}
        self.leaves = spec.leaves
        self.leaf_dfa: list[Dfa] = [spec.dfa(n) for n in self.leaves]
        try:
            self.leaf_tests = [[compile_atom(hw, a) for a in d.atoms] for d in self.leaf_dfa]
        except WorldError as exc:
            raise PlanningError(f"the spec cannot be planned in {hw.name}: {exc}") from None
        self.order: list[str] = [
            n for k in range(len(spec.levels), 0, -1) for n in spec.levels[k - 1] if not spec.is_leaf(n)
        ]
        self.forms = {n: sb.precedence_form(spec.formula(n)) for n in self.order}
        self.dfa_nodes = [n for n in self.order if self.forms[n] is None]
        self.node_dfa = {n: spec.dfa(n) for n in self.dfa_nodes}
        self.roots_mask = sum(self.bit[r] for r in spec.roots)
        self._letters: dict[Any, tuple[int, ...]] = {}
        self._steps: dict[Any, PState | None] = {}

    def init(self) -> PState:
        done = 0
        states = []
        for n, d in zip(self.leaves, self.leaf_dfa, strict=True):
            states.append(d.init)
            if d.init in d.accepting:
                done |= self.bit[n]
        return tuple(states), done, tuple(self.node_dfa[n].init for n in self.dfa_nodes)

    def finished(self, p: PState) -> bool:
        return p[1] & self.roots_mask == self.roots_mask

    def step(self, p: PState, snap: Snap, event: Event) -> PState | None:
        """Feed one letter; None when the spec can no longer be satisfied (memoised: the search
        feeds the same letters to the same progress states very often)."""
        lkey = (snap[2], event)
        masks = self._letters.get(lkey)
        if masks is None:
            masks = tuple(
                sum(1 << k for k, test in enumerate(tests) if test(snap, event)) for tests in self.leaf_tests
            )
            self._letters[lkey] = masks
        skey = (p, masks)
        out = self._steps.get(skey, self)  # `self`: not yet computed (None is a computed answer)
        if out is self:
            out = self._steps[skey] = self._step(p, masks)
        return out  # type: ignore[return-value]

    def _step(self, p: PState, masks: tuple[int, ...]) -> PState | None:
        states, done, nstates = list(p[0]), p[1], list(p[2])
        newly = 0
        for i, (n, d) in enumerate(zip(self.leaves, self.leaf_dfa, strict=True)):
            if done & self.bit[n]:
                continue
            states[i] = d.step_mask(states[i], masks[i])
            if states[i] == DEAD:
                return None
            if states[i] in d.accepting:
                newly |= self.bit[n]
        done |= newly
        for n in self.order:
            if done & self.bit[n]:
                continue
            form = self.forms[n]
            if form is not None:
                children, pairs = form
                if any(done & self.bit[b] and not done & self.bit[a] for a, b in pairs):
                    return None
                if all(done & self.bit[c] for c in children):
                    done |= self.bit[n]
                    newly |= self.bit[n]
                continue
            j = self.dfa_nodes.index(n)
            d = self.node_dfa[n]
            nstates[j] = d.step(nstates[j], [c for c in self.names if newly & self.bit[c]])
            if nstates[j] == DEAD:
                return None
            if nstates[j] in d.accepting:
                done |= self.bit[n]
                newly |= self.bit[n]
        return tuple(states), done, tuple(nstates)


_POSITIVE = re.compile(
    r'(!?)"?((?:at|put)\(([A-Za-z]+?)(?:Block)?,([A-Za-z@]+)\)|away\(([A-Za-z]+?)(?:Block)?\))"?'
)


def leaf_targets(spec: HierarchicalSpec, hw: HandoverWorld) -> dict[str, dict[int, frozenset[Cell]]]:
    """Per leaf: block index -> cells it must reach (from the leaf's positive at/put/away atoms)."""
    names = hw.block_names()
    labelled = set(hw.layout.regions.values())
    out: dict[str, dict[int, frozenset[Cell]]] = {}
    for leaf in spec.leaves:
        need: dict[int, set[Cell]] = {}
        for neg, _, b1, place, b2 in _POSITIVE.findall(spec.text(leaf)):
            block = b1 or b2
            if neg or block not in names:
                continue
            b = names.index(block)
            if b2:
                cells = labelled - {hw.blocks[block]}
            else:
                place = place[6:] if place.startswith("Region") else place
                cells = {hw.blocks[place[1:]] if place.startswith("@") else hw.layout.cell_of(place)}
            need.setdefault(b, set()).update(cells)
        out[leaf] = {b: frozenset(c) for b, c in need.items()}
    return out
