"""Flattening a hierarchical spec into one formula, and the automaton sizes of both (what the hierarchy
saves: the paper's motivation). Functions over a `HierarchicalSpec`."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from nl2hltl2plan.errors import FormulaError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec, sequence_formula


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


def flattens_exactly(spec: HierarchicalSpec) -> bool:
    """True when every leaf is an action list and every non-leaf formula is in the relation
    compiler's form (conjunction of F c and F(a & F b)); then `flatten` is exact."""
    return all(spec.leaf_actions(n) for n in spec.leaves) and all(
        sb.precedence_form(spec.formula(n)) is not None for n in spec.names if not spec.is_leaf(n)
    )


def flatten(spec: HierarchicalSpec) -> str:
    """One flat formula over atomic propositions.

    Exact case (`flattens_exactly`): atoms are *attributed* actions `"leaf:action"`, each
    happening at most once (as in every plan the planner returns). A leaf completes with its last
    action; a non-leaf completes with the last of its children, so "X no later than Y" becomes
    le(X, Y) = AND over X's children (X composite), OR over Y's children (Y composite), and
    F(last_X & F last_Y) for two leaves. The result is equivalent to the hierarchy under the
    completion-event semantics, and shows what the hierarchy saves (the paper's motivation).

    Otherwise: Luo & Liu's substitution of each composite proposition by its formula, which
    keeps every leaf requirement but may weaken orderings between composite tasks."""
    if flattens_exactly(spec):
        return sb.conj(_flat_sat(spec, r) for r in spec.roots).text
    done: dict[str, sb.Formula] = {}
    for k in range(len(spec.levels), 0, -1):
        for name in spec.levels[k - 1]:
            done[name] = spec.formula(name).substitute({c: done[c] for c in spec.children(name)})
    return sb.conj(done[r] for r in spec.roots).text


def _flat_sat(spec: HierarchicalSpec, name: str) -> sb.Formula:
    actions = spec.leaf_actions(name)
    if actions:
        return sb.parse(sequence_formula([f"{name}:{a}" for a in actions], check=False))
    form = sb.precedence_form(spec.formula(name))
    assert form is not None
    children, pairs = form
    return sb.conj([_flat_sat(spec, c) for c in children] + [_flat_le(spec, a, b) for a, b in pairs])


def _flat_le(spec: HierarchicalSpec, x: str, y: str) -> sb.Formula:
    if not spec.is_leaf(x):
        return sb.conj(_flat_le(spec, c, y) for c in spec.children(x))
    if not spec.is_leaf(y):
        return sb.disj(_flat_le(spec, x, d) for d in spec.children(y))
    last_x = sb.atom(f"{x}:{(spec.leaf_actions(x) or [''])[-1]}")
    last_y = sb.atom(f"{y}:{(spec.leaf_actions(y) or [''])[-1]}")
    return sb.eventually(sb.conj([last_x, sb.eventually(last_y)]))


def size_report(spec: HierarchicalSpec, flat_timeout_s: float = 30.0) -> SizeReport:
    per = {}
    for n in spec.names:
        d = spec.dfa(n)
        per[n] = (d.num_states, d.num_edges)
    flat = flatten(spec)
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
        flat_exact=flattens_exactly(spec),
    )
