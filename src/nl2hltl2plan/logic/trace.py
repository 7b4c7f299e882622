"""Judging a finished execution against a hierarchical spec (completion-event semantics).

Every action event is attributed to one leaf (or to none: it then counts for every leaf); a leaf
formula reads only its own events; a composite proposition is a *completion event*, true exactly at
the step its formula is first satisfied. The trace satisfies the spec when every L1 formula does.

>>> from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
>>> spec = HierarchicalSpec([{"t1": "F(a & F b)"}, {"a": ["pickup(Cup)"], "b": ["pickup(Mug)"]}])
>>> check_trace(spec, [TraceEvent(1, "pickup(Cup)", "a"), TraceEvent(2, "pickup(Mug)", "b")]).ok
True
>>> check_trace(spec, [TraceEvent(1, "pickup(Mug)", "b"), TraceEvent(2, "pickup(Cup)", "a")]).ok
False
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.automaton import Dfa
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec


@dataclass(frozen=True)
class TraceEvent:
    """One action at step `t`, attributed to leaf `task` (None: it counts for every leaf)."""

    t: int
    atom: str
    task: str | None = None


@dataclass
class TraceCheck:
    ok: bool
    completed: dict[str, int | None]  # name -> step of completion (None: never)
    reasons: list[str] = field(default_factory=list)


class _Run:
    """The state of every formula while a trace is read step by step."""

    def __init__(self, spec: HierarchicalSpec) -> None:
        self.spec = spec
        # non-leaves in the compiler's form (F c, F(a & F b)) are read off directly: they complete
        # with their last child when every pair is in order, which is exactly when their automaton
        # would accept; this avoids 2^n-state automata for wide conjunctions
        self.forms = {n: sb.precedence_form(spec.formula(n)) for n in spec.names if not spec.is_leaf(n)}
        self.dfas: dict[str, Dfa] = {n: spec.dfa(n) for n in spec.names if self.forms.get(n) is None}
        self.state = {n: d.init for n, d in self.dfas.items()}
        self.completed: dict[str, int | None] = {n: None for n in spec.names}
        for n, d in self.dfas.items():
            if d.init in d.accepting:
                self.completed[n] = 0
        self.broken: set[str] = set()
        self.leaf_atoms = {n: frozenset(spec.formula(n).atoms) for n in spec.leaves}

    def step(self, t: int, events: list[TraceEvent]) -> None:
        newly = self._step_leaves(t, events)
        for k in range(len(self.spec.levels), 0, -1):  # completion events go up, lowest level first
            for n in self.spec.levels[k - 1]:
                if not self.spec.is_leaf(n) and self.completed[n] is None:
                    self._step_composite(n, t, newly)

    def _step_leaves(self, t: int, events: list[TraceEvent]) -> set[str]:
        newly: set[str] = set()
        for n in self.spec.leaves:
            if self.completed[n] is not None:
                continue
            atoms = {
                e.atom for e in events if (e.task == n or e.task is None) and e.atom in self.leaf_atoms[n]
            }
            self.state[n] = self.dfas[n].step(self.state[n], atoms)
            if self.state[n] in self.dfas[n].accepting:
                self.completed[n] = t
                newly.add(n)
        return newly

    def _step_composite(self, n: str, t: int, newly: set[str]) -> None:
        form = self.forms.get(n)
        if form is not None:
            children, pairs = form
            done = {c: self.completed[c] for c in children}
            if any(_later(done[a], done[b]) for a, b in pairs):
                self.broken.add(n)
            elif all(v is not None for v in done.values()):
                self.completed[n] = t
                newly.add(n)
            return
        self.state[n] = self.dfas[n].step(self.state[n], newly)
        if self.state[n] in self.dfas[n].accepting:
            self.completed[n] = t
            newly.add(n)

    def reasons(self) -> list[str]:
        out = []
        for r in self.spec.roots:
            if self.completed[r] is not None:
                continue
            missing = [n for n in self.spec.leaves if self.completed[n] is None]
            dead = sorted(self.broken | {n for n, d in self.dfas.items() if d.is_dead(self.state[n])})
            why = f"top formula {r} ({self.spec.text(r)}) is not satisfied"
            if dead:
                why += f"; violated (can no longer be satisfied): {dead}"
            elif missing:
                why += f"; leaves never completed: {missing}"
            out.append(why)
        return out


def _later(a: int | None, b: int | None) -> bool:
    """Both completed, and `a` after `b` (an ordering "a before b" broken)."""
    return a is not None and b is not None and a > b


def _misattributed(spec: HierarchicalSpec, e: TraceEvent) -> str | None:
    if e.task is None:
        return None
    if e.task not in spec.graph:
        return f"event {e.atom} at t={e.t} is attributed to unknown task {e.task!r}"
    if not spec.is_leaf(e.task):
        return f"event {e.atom} at t={e.t} is attributed to non-leaf {e.task}"
    return None


def check_trace(spec: HierarchicalSpec, events: Iterable[TraceEvent]) -> TraceCheck:
    """Judge a finished execution under completion-event semantics (module docstring)."""
    by_step: dict[int, list[TraceEvent]] = {}
    for e in events:
        wrong = _misattributed(spec, e)
        if wrong:
            return TraceCheck(False, {}, [wrong])
        by_step.setdefault(e.t, []).append(e)
    run = _Run(spec)
    for t in range(1, max(by_step, default=0) + 1):
        run.step(t, by_step.get(t, []))
    reasons = run.reasons()
    return TraceCheck(not reasons, run.completed, reasons)
