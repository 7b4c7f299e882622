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

Semantics used for planning and checking (`logic.trace.check_trace`): every action event is attributed to one
leaf; a leaf formula reads only its own events; a composite proposition is a *completion event*,
true exactly at the step its formula is first satisfied. A trace satisfies the specification when
every L1 formula is satisfied and it keeps the constraints beside the levels (`logic.constraints`:
G !p and until-guards, judged on every event of the trace; JSON `{"levels": [...], "constraints":
[...]}`).
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from functools import cached_property
from pathlib import Path
from typing import Any

import networkx as nx

from nl2hltl2plan.errors import DataError, FormulaError, FormulaTooLargeError, SpecError
from nl2hltl2plan.io import loads, read_text
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.automaton import Dfa
from nl2hltl2plan.logic.constraints import Constraint

LeafOrFormula = str | list[str]


def sequence_formula(actions: Sequence[str], check: bool = True) -> str:
    """F(a1 & F(a2 & ... F an)): the actions happen in this order."""
    if not actions:
        raise SpecError("an action list must not be empty")
    for a in actions:
        if check and str(Atom.read(a)) != a:  # an atom, written as the printer writes it
            raise SpecError(f"{a!r} is not an action like verb(Type) or verb(Type,Type)")
    text = f'"{actions[-1]}"'
    for a in reversed(actions[:-1]):
        text = f'"{a}" & F({text})'
    return f"F({text})"


class HierarchicalSpec:
    """A validated hierarchical sc-LTL specification, with the constraints beside it (G !p and
    until-guards over action atoms, `logic.constraints`; an until-guard names one of its nodes)."""

    def __init__(self, levels: Sequence[dict[str, LeafOrFormula]], constraints: Sequence[Constraint] = ()):
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
        self.constraints: tuple[Constraint, ...] = tuple(constraints)
        for c in self.constraints:
            if c.until is not None and c.until not in self._level_of:
                raise SpecError(f"constraint {c.text!r} waits for {c.until!r}, no formula of the spec")

    # ----- JSON ------------------------------------------------------------------------------
    @classmethod
    def from_json(cls, data: str | list[Any] | dict[str, Any]) -> HierarchicalSpec:
        if isinstance(data, str):
            try:
                data = loads(data, "specification")
            except DataError as exc:
                raise SpecError(str(exc)) from None
        constraints: list[Any] = []
        if isinstance(data, dict) and "levels" in data:  # {"levels": [...], "constraints": [...]}
            constraints = data.get("constraints") or []
            data = data["levels"]
        if not isinstance(data, list) or not isinstance(constraints, list):
            raise SpecError('a specification is a JSON list of levels, e.g. [{"task1": "F a"}], or '
                            '{"levels": [...], "constraints": [{"text": ..., "forbid": [...]}]}')
        return cls(data, [Constraint.from_json(c) for c in constraints])

    @classmethod
    def load(cls, path: str | Path) -> HierarchicalSpec:
        return cls.from_json(read_text(path, "specification file"))

    def to_json_obj(self) -> list[dict[str, LeafOrFormula]]:
        return [dict(level) for level in self.levels]

    def to_json(self, indent: int | None = 2) -> str:
        """The levels as a JSON list, or, with constraints, {"levels": [...], "constraints": [...]}."""
        if not self.constraints:
            return json.dumps(self.to_json_obj(), indent=indent)
        doc = {"levels": self.to_json_obj(), "constraints": [c.to_json() for c in self.constraints]}
        return json.dumps(doc, indent=indent)

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
                except FormulaTooLargeError as exc:  # cannot be checked at all: bad input, not "invalid"
                    raise FormulaTooLargeError(f"L{k} {name}: {exc}") from None
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
    @cached_property
    def graph(self) -> nx.DiGraph:
        """The specification hierarchy graph: one node per flat formula (attributes `level`, `text`,
        `leaf`), an edge from each formula to the composite propositions it uses."""
        g = nx.DiGraph()
        for name, k in self._level_of.items():
            g.add_node(name, level=k, text=self._formulas[name].text)
        for name, f in self._formulas.items():
            g.add_edges_from((name, a) for a in f.atoms if a in self._level_of)
        for n in g.nodes:
            g.nodes[n]["leaf"] = g.out_degree(n) == 0
        return g

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
        """The composite propositions of `name` (empty for a leaf), in formula order."""
        return [a for a in self.formula(name).atoms if a in self._level_of]

    def is_leaf(self, name: str) -> bool:
        self._check(name)
        return bool(self.graph.nodes[name]["leaf"])

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
        self._check(name)
        return next(iter(self.graph.predecessors(name)), None)

    def dfa(self, name: str, timeout_s: float = sb.DEFAULT_TIMEOUT_S) -> Dfa:
        return sb.dfa(self.formula(name), timeout_s=timeout_s)

    def _check(self, name: str) -> None:
        if name not in self._level_of:
            raise SpecError(f"no specification named {name!r}; names are {self.names}")


def format_spec(spec: HierarchicalSpec) -> str:
    """Readable hierarchical LTL, one formula per line, level by level: `L2  task1.1 = F(...)`; then
    the constraints beside it: `C   G!"open(Fridge)"  (never open the fridge)`."""
    levels = enumerate(spec.levels, start=1)
    lines = [f"L{k}  {name} = {spec.text(name)}" for k, level in levels for name in level]
    lines += [f"C   {c.formula}  ({c.text})" for c in spec.constraints]
    return "\n".join(lines)
