"""Hierarchical sc-LTL (Definition 2.1 of the paper, after Luo & Liu).

A specification has levels L1..LK (highest first); each level maps names to flat sc-LTL formulas.
A proposition of a formula at level k that is the name of a formula at level k+1 is a *composite
proposition*; any other proposition is an *atomic proposition* (a robot action such as
`pickup(Apple)`). JSON form, as in the paper::

    [{"task1": "F(task1.1 & F task1.2)"},
     {"task1.1": "F task1.1.1 & F task1.1.2", "task1.2": ["pickup(Saucer)", "put(Saucer,UpperRack)"]},
     ...]

A leaf may be an ordered list of API actions, meaning F(a1 & F(a2 & ...)).

The three rules are checked as follows (errors name the formula at fault):
1. every formula above the lowest level is built from formulas of the next level: a non-leaf
   formula's propositions are all names of the next level;
2. every formula below L1 occurs in exactly one formula of the level above;
3. atomic propositions occur only in leaf specifications. A formula mixing composite and atomic
   propositions is an "atom above the leaf level". Leaves may sit above LK when the task tree is
   unbalanced (Algorithm 1 puts a leaf at its node's depth), as in the paper's own construction.

Semantics used for planning and checking (`check_trace`): every action event is attributed to one
leaf; a leaf formula reads only its own events; a composite proposition is a *completion event*,
true exactly at the step its formula is first satisfied. A trace satisfies the specification when
every L1 formula is satisfied.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import FormulaError, SpecError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.automaton import Dfa

ACTION_RE = re.compile(r"^[a-z_][a-z0-9_]*\([A-Za-z0-9_.]+(,[A-Za-z0-9_.]+)*\)$")
LeafOrFormula = str | list[str]


def sequence_formula(actions: Sequence[str], check: bool = True) -> str:
    """F(a1 & F(a2 & ... F an)): the actions happen in this order."""
    if not actions:
        raise SpecError("an action list must not be empty")
    for a in actions:
        if check and not ACTION_RE.match(a):
            raise SpecError(f"{a!r} is not an action like verb(Type) or verb(Type,Type)")
    text = f'"{actions[-1]}"'
    for a in reversed(actions[:-1]):
        text = f'"{a}" & F({text})'
    return f"F({text})"


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


@dataclass
class SizeReport:
    """Automaton sizes: the hierarchy (one DFA per flat formula) against the flattened formula.

    The flat formula is measured by Spot's cheapest Büchi automaton ('BA', 'any', 'medium'), which
    may be nondeterministic and so is never larger than its DFA: the comparison favours flat."""

    per_formula: dict[str, tuple[int, int]]  # name -> (states, edges)
    hierarchical_states: int
    hierarchical_edges: int
    flat_formula: str
    flat_states: int | None
    flat_edges: int | None
    flat_error: str | None = None
    flat_exact: bool = True

    def to_dict(self) -> dict[str, Any]:
        return {
            "per_formula": {k: {"states": s, "edges": e} for k, (s, e) in self.per_formula.items()},
            "hierarchical": {"states": self.hierarchical_states, "edges": self.hierarchical_edges},
            "flat": {
                "formula": self.flat_formula,
                "states": self.flat_states,
                "edges": self.flat_edges,
                "exact": self.flat_exact,
                "error": self.flat_error,
            },
        }


class HierarchicalSpec:
    """A validated hierarchical sc-LTL specification."""

    def __init__(self, levels: Sequence[dict[str, LeafOrFormula]]):
        if not isinstance(levels, Sequence) or isinstance(levels, str | bytes) or not levels:
            raise SpecError("a hierarchical specification is a non-empty list of levels")
        self.levels: list[dict[str, LeafOrFormula]] = []
        for k, level in enumerate(levels, start=1):
            if not isinstance(level, dict) or not level:
                raise SpecError(f"level L{k} must be a non-empty object {{name: formula}}")
            self.levels.append(dict(level))
        self._formulas: dict[str, sb.Formula] = {}
        self._level_of: dict[str, int] = {}
        self._validate()

    # ----- JSON ------------------------------------------------------------------------------
    @classmethod
    def from_json(cls, data: str | list[Any]) -> HierarchicalSpec:
        if isinstance(data, str):
            try:
                data = json.loads(data)
            except json.JSONDecodeError as exc:
                raise SpecError(f"specification is not valid JSON: {exc}") from None
        if isinstance(data, dict) and "levels" in data:
            data = data["levels"]
        if not isinstance(data, list):
            raise SpecError('a specification is a JSON list of levels, e.g. [{"task1": "F a"}]')
        return cls(data)

    @classmethod
    def load(cls, path: str | Path) -> HierarchicalSpec:
        try:
            text = Path(path).read_text()
        except OSError as exc:
            raise SpecError(f"cannot read specification {path}: {exc.strerror}") from None
        return cls.from_json(text)

    def to_json_obj(self) -> list[dict[str, LeafOrFormula]]:
        return [dict(level) for level in self.levels]

    def to_json(self, indent: int | None = 2) -> str:
        return json.dumps(self.to_json_obj(), indent=indent)

    # ----- validation (Definition 2.1) ---------------------------------------------------------
    def _validate(self) -> None:
        problems: list[str] = []
        for k, level in enumerate(self.levels, start=1):
            for name, body in level.items():
                if name in self._level_of:
                    problems.append(f"name {name!r} is defined at L{self._level_of[name]} and again at L{k}")
                    continue
                self._level_of[name] = k
                try:
                    text = sequence_formula(body) if isinstance(body, list) else body
                    if not isinstance(text, str):
                        raise SpecError(
                            f"must be a formula string or a list of actions, not {type(body).__name__}"
                        )
                    f = sb.parse(text)
                    reasons = sb.sc_ltl_problems(f)
                    if reasons:
                        raise FormulaError("not sc-LTL: " + "; ".join(reasons))
                    self._formulas[name] = f
                except (FormulaError, SpecError) as exc:
                    problems.append(f"L{k} {name}: {exc}")
        if problems:
            raise SpecError("invalid hierarchical specification:\n  - " + "\n  - ".join(problems))
        used_in: dict[str, list[str]] = {}
        for name, f in self._formulas.items():
            k = self._level_of[name]
            composite = [a for a in f.atoms if a in self._level_of]
            atomic = [a for a in f.atoms if a not in self._level_of]
            for c in composite:
                if self._level_of[c] != k + 1:
                    problems.append(
                        f"L{k} {name} uses {c}, which is defined at L{self._level_of[c]}; "
                        f"a formula may only use formulas of the next level L{k + 1} (rule 1)"
                    )
                used_in.setdefault(c, []).append(name)
            if composite and atomic:
                problems.append(
                    f"L{k} {name} mixes composite propositions {composite} with atomic propositions "
                    f"{atomic}: atomic propositions are allowed only in leaf specifications (rule 3)"
                )
            if isinstance(self.levels[k - 1][name], list) and composite:
                problems.append(f"L{k} {name} is an action list but names specifications {composite}")
        for name, k in self._level_of.items():
            if k == 1:
                continue
            parents = used_in.get(name, [])
            if len(parents) != 1:
                where = "no formula" if not parents else f"{len(parents)} formulas ({', '.join(parents)})"
                problems.append(
                    f"L{k} {name} occurs in {where} of L{k - 1}; each formula below L1 must occur in "
                    "exactly one formula of the level above (rule 2)"
                )
        if len(self.levels) > 1 and not any(self.children(n) for n in self.levels[0]):
            problems.append("L1 formulas use no formula of L2, so levels below L1 are unused")
        if problems:
            raise SpecError("invalid hierarchical specification:\n  - " + "\n  - ".join(problems))

    # ----- structure ---------------------------------------------------------------------------
    @property
    def names(self) -> list[str]:
        return list(self._level_of)

    @property
    def roots(self) -> list[str]:
        return list(self.levels[0])

    def level(self, name: str) -> int:
        self._check(name)
        return self._level_of[name]

    def formula(self, name: str) -> sb.Formula:
        self._check(name)
        return self._formulas[name]

    def text(self, name: str) -> str:
        return self.formula(name).text

    def children(self, name: str) -> list[str]:
        """The composite propositions of `name` (empty for a leaf)."""
        return [a for a in self.formula(name).atoms if a in self._level_of]

    def is_leaf(self, name: str) -> bool:
        return not self.children(name)

    @property
    def leaves(self) -> list[str]:
        return [n for n in self.names if self.is_leaf(n)]

    def leaf_actions(self, name: str) -> list[str] | None:
        """The ordered action list when the leaf was given as one, else None."""
        body = self.levels[self.level(name) - 1][name]
        return list(body) if isinstance(body, list) else None

    def atoms(self) -> set[str]:
        return {a for n in self.leaves for a in self.formula(n).atoms}

    def parent(self, name: str) -> str | None:
        for n in self.names:
            if name in self.children(n):
                return n
        return None

    def dfa(self, name: str, timeout_s: float = sb.DEFAULT_TIMEOUT_S) -> Dfa:
        return sb.dfa(self.formula(name), timeout_s=timeout_s)

    def _check(self, name: str) -> None:
        if name not in self._level_of:
            raise SpecError(f"no specification named {name!r}; names are {self.names}")

    # ----- flattening and sizes ----------------------------------------------------------------
    @property
    def flattens_exactly(self) -> bool:
        """True when every leaf is an action list and every non-leaf formula is in the relation
        compiler's form (conjunction of F c and F(a & F b)); then `flatten` is exact."""
        return all(self.leaf_actions(n) for n in self.leaves) and all(
            sb.precedence_form(self.formula(n)) is not None for n in self.names if not self.is_leaf(n)
        )

    def flatten(self) -> str:
        """One flat formula over atomic propositions.

        Exact case (`flattens_exactly`): atoms are *attributed* actions `"leaf:action"`, each
        happening at most once (as in every plan the planner returns). A leaf completes with its last
        action; a non-leaf completes with the last of its children, so "X no later than Y" becomes
        le(X, Y) = AND over X's children (X composite), OR over Y's children (Y composite), and
        F(last_X & F last_Y) for two leaves. The result is equivalent to the hierarchy under the
        completion-event semantics, and shows what the hierarchy saves (the paper's motivation).

        Otherwise: Luo & Liu's substitution of each composite proposition by its formula, which
        keeps every leaf requirement but may weaken orderings between composite tasks."""
        if self.flattens_exactly:
            return sb.conj(self._flat_sat(r) for r in self.roots).text
        done: dict[str, sb.Formula] = {}
        for k in range(len(self.levels), 0, -1):
            for name in self.levels[k - 1]:
                done[name] = self._formulas[name].substitute({c: done[c] for c in self.children(name)})
        return sb.conj(done[r] for r in self.roots).text

    def _flat_sat(self, name: str) -> sb.Formula:
        actions = self.leaf_actions(name)
        if actions:
            return sb.parse(sequence_formula([f"{name}:{a}" for a in actions], check=False))
        form = sb.precedence_form(self.formula(name))
        assert form is not None
        children, pairs = form
        return sb.conj([self._flat_sat(c) for c in children] + [self._flat_le(a, b) for a, b in pairs])

    def _flat_le(self, x: str, y: str) -> sb.Formula:
        if not self.is_leaf(x):
            return sb.conj(self._flat_le(c, y) for c in self.children(x))
        if not self.is_leaf(y):
            return sb.disj(self._flat_le(x, d) for d in self.children(y))
        last_x = sb.atom(f"{x}:{(self.leaf_actions(x) or [''])[-1]}")
        last_y = sb.atom(f"{y}:{(self.leaf_actions(y) or [''])[-1]}")
        return sb.eventually(sb.conj([last_x, sb.eventually(last_y)]))

    def size_report(self, flat_timeout_s: float = 30.0) -> SizeReport:
        per = {}
        for n in self.names:
            d = self.dfa(n)
            per[n] = (d.num_states, d.num_edges)
        flat = self.flatten()
        flat_states = flat_edges = None
        error = None
        try:
            flat_states, flat_edges = sb.automaton_size(sb.parse(flat), timeout_s=flat_timeout_s)
        except FormulaError as exc:
            error = str(exc)
        return SizeReport(
            per_formula=per,
            hierarchical_states=sum(s for s, _ in per.values()),
            hierarchical_edges=sum(e for _, e in per.values()),
            flat_formula=flat,
            flat_states=flat_states,
            flat_edges=flat_edges,
            flat_error=error,
            flat_exact=self.flattens_exactly,
        )

    # ----- checking a finished trace -----------------------------------------------------------
    @cached_property
    def _leaf_atoms(self) -> dict[str, frozenset[str]]:
        return {n: frozenset(self.formula(n).atoms) for n in self.leaves}

    def check_trace(self, events: Iterable[TraceEvent]) -> TraceCheck:
        """Judge a finished execution under completion-event semantics (module docstring)."""
        by_step: dict[int, list[TraceEvent]] = {}
        for e in events:
            if e.task is not None and e.task not in self._level_of:
                return TraceCheck(
                    False, {}, [f"event {e.atom} at t={e.t} is attributed to unknown task {e.task!r}"]
                )
            if e.task is not None and not self.is_leaf(e.task):
                return TraceCheck(
                    False, {}, [f"event {e.atom} at t={e.t} is attributed to non-leaf {e.task}"]
                )
            by_step.setdefault(e.t, []).append(e)
        # non-leaves in the compiler's form (F c, F(a & F b)) are read off directly: they complete
        # with their last child when every pair is in order, which is exactly when their automaton
        # would accept; this avoids 2^n-state automata for wide conjunctions
        forms = {n: sb.precedence_form(self.formula(n)) for n in self.names if not self.is_leaf(n)}
        dfas = {n: self.dfa(n) for n in self.names if forms.get(n) is None}
        state = {n: d.init for n, d in dfas.items()}
        completed: dict[str, int | None] = {n: None for n in self.names}
        for n, d in dfas.items():
            if d.init in d.accepting:
                completed[n] = 0
        broken: set[str] = set()
        last = max(by_step, default=0)
        for t in range(1, last + 1):
            step_events = by_step.get(t, [])
            newly: set[str] = set()
            for n in self.leaves:
                if completed[n] is not None:
                    continue
                atoms = {
                    e.atom
                    for e in step_events
                    if (e.task == n or e.task is None) and e.atom in self._leaf_atoms[n]
                }
                state[n] = dfas[n].step(state[n], atoms)
                if state[n] in dfas[n].accepting:
                    completed[n] = t
                    newly.add(n)
            # propagate completion events upwards, lowest level first
            for k in range(len(self.levels), 0, -1):
                for n in self.levels[k - 1]:
                    if self.is_leaf(n) or completed[n] is not None:
                        continue
                    form = forms.get(n)
                    if form is not None:
                        children, pairs = form
                        done = {c: completed[c] for c in children}
                        if any(_later(done[a], done[b]) for a, b in pairs):
                            broken.add(n)
                        elif all(v is not None for v in done.values()):
                            completed[n] = t
                            newly.add(n)
                        continue
                    state[n] = dfas[n].step(state[n], newly)
                    if state[n] in dfas[n].accepting:
                        completed[n] = t
                        newly.add(n)
        reasons = []
        for r in self.roots:
            if completed[r] is None:
                missing = [n for n in self.names if completed[n] is None and not self.children(n)]
                dead = sorted(broken | {n for n, d in dfas.items() if d.is_dead(state[n])})
                why = f"top formula {r} ({self.text(r)}) is not satisfied"
                if dead:
                    why += f"; violated (can no longer be satisfied): {dead}"
                elif missing:
                    why += f"; leaves never completed: {missing}"
                reasons.append(why)
        return TraceCheck(not reasons, completed, reasons)


def _later(a: int | None, b: int | None) -> bool:
    """Both completed, and `a` after `b` (an ordering "a before b" broken)."""
    return a is not None and b is not None and a > b


def format_spec(spec: HierarchicalSpec) -> str:
    """Readable hierarchical LTL, one formula per line, level by level: `L2  task1.1 = F(...)`."""
    return "\n".join(
        f"L{k}  {name} = {spec.text(name)}" for k, level in enumerate(spec.levels, start=1) for name in level
    )
