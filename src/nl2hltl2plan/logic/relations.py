"""Children + precedence relations -> one flat sc-LTL formula, and the check of other translators.

Encoding (compile_relations): for children c1..cn and the transitive reduction of the pairs
(a, b) meaning "a is done before b",

    F(a & F b) & ...  &  F c & ...        (F c for every child in no pair)

Composite propositions are *completion events*: `c` holds exactly at the step its task is first
completed, and each child completes once. On such finite traces the encoding is exact:
- `F c` holds iff c completes within the trace;
- `F(a & F b)` holds iff a completes at some step j and b at some step k >= j, i.e. (each
  completing once) iff step(a) <= step(b): "a is done no later than b". Equal steps mean two robots
  finish in the same step; the planner separates them when the order must be strict.
Every conjunct is positive (no negation), so a composite proposition can be replaced by a formula
(flattening) and the result is still sc-LTL; for one pair it is literally the paper's
F(phi1 & F phi2).
The property tests check this on random relation sets and random traces.

Other translators (an LLM, a learned model) plug in through `Translator`; `check_translation`
compares what they produce with the compiled formula under the same completion-event assumption
(each child at most once), with a distinguishing trace when they differ.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import networkx as nx

from nl2hltl2plan.errors import FormulaError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.automaton import distinguishing_word


def compile_relations(children: Sequence[str], before: Sequence[tuple[str, str]]) -> str:
    """The exact formula "every child is eventually done and each (a, b) has a done before b"."""
    names = list(dict.fromkeys(children))
    if not names:
        raise FormulaError("a non-leaf task needs at least one child")
    known = set(names)
    g = nx.DiGraph()
    g.add_nodes_from(names)
    for a, b in before:
        if a not in known or b not in known:
            raise FormulaError(f"relation ({a}, {b}) names a task that is not a child: children are {names}")
        if a == b:
            raise FormulaError(f"relation ({a}, {b}) relates a task to itself")
        g.add_edge(a, b)
    if not nx.is_directed_acyclic_graph(g):
        cycle = nx.find_cycle(g)
        raise FormulaError("cyclic ordering: " + " before ".join([a for a, _ in cycle] + [cycle[0][0]]))
    # the transitive reduction states the same order with fewest constraints (smaller automata)
    reduced = nx.transitive_reduction(g)
    pairs = sorted(reduced.edges(), key=_order(names))
    in_pair = {x for e in pairs for x in e}
    parts = [sb.eventually(sb.conj([sb.atom(a), sb.eventually(sb.atom(b))])) for a, b in pairs]
    parts += [sb.eventually(sb.atom(c)) for c in names if c not in in_pair]
    return sb.conj(parts).text


def _order(names: list[str]):  # stable, readable output: pairs in the children's order
    pos = {n: i for i, n in enumerate(names)}
    return lambda e: (pos[e[0]], pos[e[1]])


@dataclass(frozen=True)
class TranslationCheck:
    equivalent: bool
    candidate: str
    reference: str
    witness: list[list[str]] | None = None  # a trace (one list of completed tasks per step)
    witness_satisfies: str | None = None  # "candidate" or "reference": which one accepts it

    def describe(self) -> str:
        if self.equivalent:
            return f"{self.candidate} is equivalent to {self.reference}"
        steps = "; ".join("{" + ", ".join(s) + "}" for s in self.witness or [])
        other = "reference" if self.witness_satisfies == "candidate" else "candidate"
        return (
            f"{self.candidate} differs from {self.reference}: the trace [{steps}] satisfies the "
            f"{self.witness_satisfies} but not the {other}"
        )


class Translator(Protocol):
    """Turns lifted sentences (e.g. "task 1.1 before task 1.2") into one flat formula over the
    child names. The default is the compiler; LLM or learned translators implement this."""

    def translate(self, sentences: str, children: Sequence[str]) -> str: ...


def check_translation(
    candidate: str, children: Sequence[str], before: Sequence[tuple[str, str]]
) -> TranslationCheck:
    """Compare a translator's formula with the compiled one under completion-event semantics."""
    reference = compile_relations(children, before)
    f = sb.parse(candidate)
    extra = set(f.atoms) - set(children)
    if extra:
        raise FormulaError(
            f"translation {candidate!r} uses {sorted(extra)}, which are not children {list(children)}"
        )
    problems = sb.sc_ltl_problems(f)
    if problems:
        raise FormulaError(f"translation {candidate!r} is not sc-LTL: " + "; ".join(problems))
    cand_dfa, ref_dfa = sb.dfa(f), sb.dfa(sb.parse(reference))
    witness = distinguishing_word(cand_dfa, ref_dfa, once=children)
    which = None if witness is None else (0 if cand_dfa.accepts(witness) else 1)
    return TranslationCheck(
        equivalent=witness is None,
        candidate=f.text,
        reference=reference,
        witness=None if witness is None else [sorted(s) for s in witness],
        witness_satisfies=None if which is None else ("candidate" if which == 0 else "reference"),
    )
