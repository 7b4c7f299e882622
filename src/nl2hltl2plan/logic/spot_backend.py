"""Every call into Spot lives here (parsing, syntactic classes, translation, equivalence).

The rest of the package sees `Formula` (an immutable wrapper) and `Dfa` (our own plain data), so
Spot can be swapped or mocked in one place.

Why a DFA is exact for sc-LTL
------------------------------
A syntactically co-safe formula phi is a *guarantee* property: every infinite word that satisfies
it has a finite *good prefix* after which every continuation satisfies it, and an infinite word
satisfies phi iff it has a good prefix. The finite traces a robot team produces are therefore judged
by "is this prefix good?". Spot translates a guarantee formula into a deterministic *terminal*
Büchi automaton (weak, with accepting states closed under every letter). In such an automaton the
accepting states are exactly the states whose residual language is universal, so a finite word is a
good prefix iff its run ends in an accepting state. Reading the automaton as a DFA (same states and
edges, accepting = the terminal states) thus recognises exactly the good prefixes: the DFA is exact,
not an approximation. When Spot's output is not terminal (large formulas translated with
'any'/'medium'), we minimise it into the minimal weak DBA (WDBA), which is terminal for guarantee
formulas, and refuse anything that still is not.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from functools import lru_cache
from typing import Any

import spot
from spot import buddy

from nl2hltl2plan.deadline import ChildError, run_with_deadline
from nl2hltl2plan.errors import FormulaError, FormulaTooLargeError
from nl2hltl2plan.logic.automaton import Cube, Dfa

# Formulas with more temporal operators than this are translated in a forked child under time,
# memory and size limits: Spot's C++ code cannot be interrupted from Python, and automata can be
# exponential in the number of temporal operators (a conjunction of n `F p` has 2^n states, and
# F(a & X^n b) has 2^n + 1 whatever its atom count). Up to 8 operators stay below a few hundred states.
IN_PROCESS_MAX_TEMPORAL = 8
DEFAULT_TIMEOUT_S = 30.0
MAX_STATES = 20_000  # a DFA beyond this makes the planner's product search hopeless anyway
MEMORY_MB = 2048.0  # address space a translation child may add to what it inherited

_FORBIDDEN = {
    spot.op_G: "G (always) is not co-safe",
    spot.op_R: "R (release) is not allowed in sc-LTL",
    spot.op_W: "W (weak until) is not co-safe",
    spot.op_M: "M (strong release) is outside the sc-LTL fragment used here (F, U, X)",
    spot.op_Implies: "-> is not in positive normal form (write !a | b)",
    spot.op_Equiv: "<-> is not in positive normal form",
    spot.op_Xor: "xor is not in positive normal form",
}


_TEMPORAL = {spot.op_F, spot.op_G, spot.op_U, spot.op_X, spot.op_R, spot.op_W, spot.op_M}


class Formula:
    """An immutable LTL formula (Spot's), printed in Spot syntax with quoted atoms where needed."""

    __slots__ = ("_f",)

    def __init__(self, f: spot.formula):
        self._f = f

    @property
    def text(self) -> str:
        return str(self._f.to_str())

    @property
    def atoms(self) -> tuple[str, ...]:
        return _atoms(self._f)

    def substitute(self, mapping: dict[str, Formula]) -> Formula:
        """Replace atoms by formulas (used to flatten a hierarchical spec)."""

        def sub(g: spot.formula) -> spot.formula:
            if g.kind() == spot.op_ap and g.ap_name() in mapping:
                return mapping[g.ap_name()]._f
            return g.map(sub)

        return Formula(sub(self._f))

    def size(self) -> int:
        return int(self._f.size())

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"Formula({self.text!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Formula) and self._f == other._f

    def __hash__(self) -> int:
        return hash(self.text)


# Caches keyed by Spot formulas: these are immutable and hash-consed (equal formulas hash alike), a
# cached key stays alive (so its id is never reused), and every cached answer is immutable.
@lru_cache(maxsize=8192)
def _atoms(f: spot.formula) -> tuple[str, ...]:
    names: set[str] = set()

    def visit(g: spot.formula) -> bool:
        if g.kind() == spot.op_ap:
            names.add(g.ap_name())
        return False

    f.traverse(visit)
    return tuple(sorted(names))


def parse(text: str) -> Formula:
    """Parse Spot or paper/ltl2ba syntax (`<>`, `[]`, `&&`, `||`, `!`, `U`, `X`, `"quoted(atoms)"`,
    dotted names such as `task1.2`). Malformed input raises FormulaError with Spot's pointer."""
    if not isinstance(text, str) or not text.strip():
        raise FormulaError("empty formula")
    try:
        return Formula(spot.formula(text))
    except SyntaxError as exc:
        raise FormulaError(f"cannot parse formula {_short(text)!r}: {_first_parse_error(str(exc))}") from None
    except (RuntimeError, MemoryError, RecursionError) as exc:  # e.g. more than 65,535 operands in one &
        raise FormulaTooLargeError(f"formula {_short(text)!r} is too large for Spot ({exc})") from None


def _first_parse_error(spot_message: str) -> str:
    """Spot's first complaint in one line: "syntax error, unexpected ... at character 5"."""
    lines = [line for line in spot_message.splitlines() if line.strip()]
    for k, line in enumerate(lines):
        if line.lstrip().startswith("^") and k + 1 < len(lines):
            return f"{lines[k + 1].strip()} at character {line.index('^') - 3}"
    return " ".join(" ".join(lines).split())[:200] or "syntax error"


def atom(name: str) -> Formula:
    return Formula(spot.formula.ap(name))


def conj(parts: Iterable[Formula]) -> Formula:
    return Formula(spot.formula.And([p._f for p in parts]))


def disj(parts: Iterable[Formula]) -> Formula:
    return Formula(spot.formula.Or([p._f for p in parts]))


def eventually(f: Formula) -> Formula:
    return Formula(spot.formula.F(f._f))


def until(a: Formula, b: Formula) -> Formula:
    return Formula(spot.formula.U(a._f, b._f))


def negate_atom(name: str) -> Formula:
    return Formula(spot.formula.Not(spot.formula.ap(name)))


def true() -> Formula:
    return Formula(spot.formula.tt())


def sc_ltl_problems(f: Formula) -> list[str]:
    """Why `f` is not sc-LTL (positive normal form over F, U, X, &, |; negation on atoms only)."""
    return list(_sc_ltl_problems(f._f))


@lru_cache(maxsize=8192)
def _sc_ltl_problems(f: spot.formula) -> tuple[str, ...]:
    problems: list[str] = []

    def visit(g: spot.formula) -> bool:
        k = g.kind()
        if k in _FORBIDDEN:
            problems.append(f"{_FORBIDDEN[k]}: {g.to_str()}")
        elif k == spot.op_Not and g[0].kind() != spot.op_ap:
            problems.append(f"negation is only allowed on atomic propositions: {g.to_str()}")
        elif k not in (
            spot.op_ap,
            spot.op_tt,
            spot.op_ff,
            spot.op_Not,
            spot.op_And,
            spot.op_Or,
            spot.op_F,
            spot.op_U,
            spot.op_X,
        ):
            problems.append(f"operator {g.kindstr()} is not part of sc-LTL: {g.to_str()}")
        return False

    f.traverse(visit)
    if not problems and not f.is_syntactic_guarantee():
        problems.append(f"not syntactically co-safe: {f.to_str()}")
    return tuple(problems)


def precedence_form(f: Formula) -> tuple[list[str], list[tuple[str, str]]] | None:
    """(children, pairs) when `f` is a conjunction of `F c` and `F(a & F b)` (the relation
    compiler's output), else None."""
    terms = list(f._f) if f._f.kind() == spot.op_And else [f._f]
    children: list[str] = []
    pairs: list[tuple[str, str]] = []
    for t in terms:
        if t.kind() != spot.op_F:
            return None
        body = t[0]
        if body.kind() == spot.op_ap:
            children.append(body.ap_name())
            continue
        if body.kind() != spot.op_And or body.size() != 2:
            return None
        aps = [g for g in body if g.kind() == spot.op_ap]
        fs = [g for g in body if g.kind() == spot.op_F and g[0].kind() == spot.op_ap]
        if len(aps) != 1 or len(fs) != 1:
            return None
        a, b = aps[0].ap_name(), fs[0][0].ap_name()
        pairs.append((a, b))
        children += [a, b]
    return list(dict.fromkeys(children)), pairs


def equivalent(a: Formula, b: Formula) -> bool:
    """LTL language equivalence (for sc-LTL formulas: same good prefixes)."""
    return _equivalent(a._f, b._f)


@lru_cache(maxsize=4096)  # comparing many readings with one written spec repeats the same pairs
def _equivalent(a: spot.formula, b: spot.formula) -> bool:
    return bool(spot.are_equivalent(a, b))


# ----------------------------------------------------------------------------------------------
# translation to DFA


def dfa(
    f: Formula,
    timeout_s: float = DEFAULT_TIMEOUT_S,
    max_states: int = MAX_STATES,
    memory_mb: float = MEMORY_MB,
) -> Dfa:
    """The DFA of the good prefixes of an sc-LTL formula (see the module docstring).

    Bounded for every formula: a linear sequence F(a1 & F(a2 & ...)) is built directly (any length,
    no Spot); a formula with at most `IN_PROCESS_MAX_TEMPORAL` temporal operators is translated
    in-process (its automaton is small by construction); any other one in a forked child limited
    to `timeout_s` seconds and `memory_mb` MiB, whose automaton must have at most `max_states`
    states. A limit reached is a one-line FormulaError naming it."""
    probs = sc_ltl_problems(f)
    if probs:
        raise FormulaError(f"{_short(f.text)} is not sc-LTL: " + "; ".join(probs))
    return _dfa_cached(f.text, timeout_s, max_states, memory_mb)


@lru_cache(maxsize=4096)
def _dfa_cached(text: str, timeout_s: float, max_states: int, memory_mb: float) -> Dfa:
    f = spot.formula(text)
    steps = linear_sequence(f)
    if steps is not None:
        return sequence_dfa(steps)
    if temporal_size(f) <= IN_PROCESS_MAX_TEMPORAL:
        return _to_dfa(_translate(f, small=True))
    hoa = _guarded(_translate_to_hoa, (text, max_states), text, timeout_s, memory_mb)
    return _to_dfa(spot.automaton(hoa))


def temporal_size(f: spot.formula) -> int:
    """Number of temporal operators (F, U, X, G, R, W, M) in the formula."""
    count = 0

    def visit(g: spot.formula) -> bool:
        nonlocal count
        if g.kind() in _TEMPORAL:
            count += 1
        return False

    f.traverse(visit)
    return count


def linear_sequence(f: spot.formula) -> list[str] | None:
    """[a1, ..., an] when `f` is F(a1 & F(a2 & ... F an)) over atoms, else None."""
    steps: list[str] = []
    g = f
    while True:
        if g.kind() != spot.op_F:
            return None
        body = g[0]
        if body.kind() == spot.op_ap:
            return steps + [body.ap_name()]
        if body.kind() != spot.op_And or body.size() != 2:
            return None
        aps = [h for h in body if h.kind() == spot.op_ap]
        rest = [h for h in body if h.kind() == spot.op_F]
        if len(aps) != 1 or len(rest) != 1:
            return None
        steps.append(aps[0].ap_name())
        g = rest[0]


def sequence_dfa(steps: Sequence[str]) -> Dfa:
    """The DFA of F(s1 & F(s2 & ... F sn)), built directly: state k = the first k steps happened.

    F includes the present, so one letter may complete several steps at once: from state k the run
    moves to k + m for the largest m with s(k+1) ... s(k+m) all in the letter (greedy matching is
    optimal for a subsequence). Cubes with the same atom required and forbidden are dropped."""
    atoms = tuple(sorted(set(steps)))
    bit = {a: 1 << i for i, a in enumerate(atoms)}
    n = len(steps)
    edges: list[list[tuple[Cube, int]]] = []
    for k in range(n):
        out: list[tuple[Cube, int]] = []
        pos = 0
        for m in range(0, n - k + 1):
            if m:
                pos |= bit[steps[k + m - 1]]
            neg = bit[steps[k + m]] if k + m < n else 0
            if not pos & neg:
                out.append(((pos, neg), k + m))
        edges.append(out)
    edges.append([((0, 0), n)])
    return Dfa(atoms=atoms, init=0, accepting=frozenset({n}), edges=edges)


def _translate(f: spot.formula, small: bool) -> spot.twa_graph:
    aut = None
    if not small:  # cheap first try; often deterministic already for conjunctions of F / U
        aut = spot.translate(f, "BA", "any", "medium")
    if aut is None or not _is_terminal_dba(aut):
        aut = spot.translate(f, "BA", "deterministic", "sbacc")
    if not _is_terminal_dba(aut):
        aut = spot.minimize_obligation(aut, f)
    if not _is_terminal_dba(aut):
        raise FormulaError(f"Spot did not give a deterministic terminal automaton for {_short(f.to_str())}")
    spot.complete_here(aut)  # explicit rejecting sink: every letter has a transition
    return aut


def _is_terminal_dba(aut: spot.twa_graph) -> bool:
    return bool(spot.is_deterministic(aut) and spot.is_terminal_automaton(aut))


def _translate_to_hoa(job: tuple[str, int]) -> str:
    text, max_states = job
    aut = _translate(spot.formula(text), small=False)
    if aut.num_states() > max_states:
        raise FormulaError(
            f"its automaton has {aut.num_states()} states, more than the limit of {max_states}"
        )
    return str(aut.to_str("hoa"))


def automaton_size(
    f: Formula, timeout_s: float = DEFAULT_TIMEOUT_S, memory_mb: float = MEMORY_MB
) -> tuple[int, int]:
    """(states, edges) of Spot's Büchi automaton for `f` ('BA', 'any', 'medium': the smallest
    cheap translation, possibly nondeterministic), computed in a child under time and memory limits."""
    text = _guarded(_size_text, f.text, f.text, timeout_s, memory_mb)
    states, edges = text.split()
    return int(states), int(edges)


def _size_text(text: str) -> str:
    aut = spot.translate(spot.formula(text), "BA", "any", "medium")
    return f"{aut.num_states()} {aut.num_edges()}"


def _short(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _guarded(fn: Callable[[Any], str], arg: Any, text: str, timeout_s: float, memory_mb: float) -> str:
    """`fn(arg)` in a child with the limits; FormulaError naming the formula and the limit reached."""
    try:
        return str(run_with_deadline(fn, arg, timeout_s, memory_mb=memory_mb, quiet=True))
    except ChildError as exc:
        advice = "; split it into a hierarchy of smaller formulas"
        if exc.kind == "timeout":
            why = f"took longer than the time limit of {timeout_s:g} s"
        elif exc.kind in ("memory", "died"):
            why = f"needed more than the memory limit of {memory_mb:g} MiB ({exc})"
        else:
            why = f"failed: {exc}"
            advice = "" if "limit of" not in str(exc) else advice
        raise FormulaError(f"translating {_short(text)} to an automaton {why}{advice}") from None


def _to_dfa(aut: spot.twa_graph) -> Dfa:
    d = aut.get_dict()
    atoms = tuple(sorted(p.ap_name() for p in aut.ap()))
    index = {name: i for i, name in enumerate(atoms)}
    var_to_bit = {d.varnum(p): 1 << index[p.ap_name()] for p in aut.ap()}
    n = aut.num_states()
    edges: list[list[tuple[Cube, int]]] = [[] for _ in range(n)]
    for e in aut.edges():
        for cube in _cubes(e.cond, var_to_bit):
            edges[e.src].append((cube, e.dst))
    # the accepting SCCs of a terminal automaton are closed under every letter: reaching one is a good
    # prefix (works for state- and transition-based marks alike; a mark on a transient edge is no goal)
    scc = spot.scc_info(aut)
    accepting = frozenset(s for s in range(n) if scc.is_accepting_scc(scc.scc_of(s)))
    return Dfa(atoms=atoms, init=aut.get_init_state_number(), accepting=accepting, edges=edges)


def _cubes(cond: object, var_to_bit: dict[int, int]) -> list[Cube]:
    """A BDD as an irredundant sum of products, each product as (positive mask, negative mask)."""
    out: list[Cube] = []
    isop = spot.minato_isop(cond)
    c = isop.next()
    while c != buddy.bddfalse:
        pos = neg = 0
        while c != buddy.bddtrue:
            bit = var_to_bit[buddy.bdd_var(c)]
            if buddy.bdd_low(c) == buddy.bddfalse:
                pos |= bit
                c = buddy.bdd_high(c)
            else:
                neg |= bit
                c = buddy.bdd_low(c)
        out.append((pos, neg))
        c = isop.next()
    return out


# HOA output (the Hanoi Omega-Automata format, for other tools)


def hoa(
    f: Formula,
    timeout_s: float = DEFAULT_TIMEOUT_S,
    max_states: int = MAX_STATES,
    memory_mb: float = MEMORY_MB,
) -> str:
    """`f`'s deterministic terminal Büchi automaton (completed with a rejecting sink; the language of
    `dfa(f)`), written by Spot in HOA v1. Bounded as `dfa` is: small formulas in-process, others in
    a child under the time, memory and state limits (FormulaError naming the limit reached)."""
    probs = sc_ltl_problems(f)
    if probs:
        raise FormulaError(f"{_short(f.text)} is not sc-LTL: " + "; ".join(probs))
    if temporal_size(f._f) <= IN_PROCESS_MAX_TEMPORAL:
        return str(_translate(f._f, small=True).to_str("hoa"))
    return _guarded(_translate_to_hoa, (f.text, max_states), f.text, timeout_s, memory_mb)
