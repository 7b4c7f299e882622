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

import multiprocessing as mp
from collections.abc import Callable, Iterable
from functools import lru_cache

import spot
from spot import buddy

from nl2hltl2plan.errors import FormulaError
from nl2hltl2plan.logic.automaton import Cube, Dfa

# Formulas with more atoms than this are translated in a forked child guarded by a time limit:
# Spot's C++ code cannot be interrupted from Python, and a conjunction of n `F p` has 2^n states.
IN_PROCESS_MAX_ATOMS = 8
DEFAULT_TIMEOUT_S = 30.0

_FORBIDDEN = {
    spot.op_G: "G (always) is not co-safe",
    spot.op_R: "R (release) is not allowed in sc-LTL",
    spot.op_W: "W (weak until) is not co-safe",
    spot.op_M: "M (strong release) is outside the sc-LTL fragment used here (F, U, X)",
    spot.op_Implies: "-> is not in positive normal form (write !a | b)",
    spot.op_Equiv: "<-> is not in positive normal form",
    spot.op_Xor: "xor is not in positive normal form",
}


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
        names: set[str] = set()

        def visit(g: spot.formula) -> bool:
            if g.kind() == spot.op_ap:
                names.add(g.ap_name())
            return False

        self._f.traverse(visit)
        return tuple(sorted(names))

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


def parse(text: str) -> Formula:
    """Parse Spot or paper/ltl2ba syntax (`<>`, `[]`, `&&`, `||`, `!`, `U`, `X`, `"quoted(atoms)"`,
    dotted names such as `task1.2`). Malformed input raises FormulaError with Spot's pointer."""
    if not isinstance(text, str) or not text.strip():
        raise FormulaError("empty formula")
    try:
        return Formula(spot.formula(text))
    except SyntaxError as exc:
        detail = "\n".join(line for line in str(exc).strip().splitlines() if line.strip())
        raise FormulaError(f"cannot parse formula {text!r}:\n{detail}") from None


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

    f._f.traverse(visit)
    if not problems and not f._f.is_syntactic_guarantee():
        problems.append(f"not syntactically co-safe: {f.text}")
    return problems


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
    return bool(spot.are_equivalent(a._f, b._f))


# ----------------------------------------------------------------------------------------------
# translation to DFA


def dfa(f: Formula, timeout_s: float = DEFAULT_TIMEOUT_S) -> Dfa:
    """The DFA of the good prefixes of an sc-LTL formula (see the module docstring).

    Formulas with few atoms are translated in-process ('BA', 'deterministic', 'sbacc'); larger
    ones in a forked child with `timeout_s` using 'BA', 'any', 'medium' followed by WDBA
    minimisation, so an exponential formula ends in FormulaError instead of a hang."""
    probs = sc_ltl_problems(f)
    if probs:
        raise FormulaError(f"{f.text} is not sc-LTL: " + "; ".join(probs))
    return _dfa_cached(f.text, timeout_s)


@lru_cache(maxsize=4096)
def _dfa_cached(text: str, timeout_s: float) -> Dfa:
    f = spot.formula(text)
    if len(Formula(f).atoms) <= IN_PROCESS_MAX_ATOMS:
        return _to_dfa(_translate(f, small=True))
    hoa = _in_child(_translate_to_hoa, text, timeout_s)
    return _to_dfa(spot.automaton(hoa))


def _translate(f: spot.formula, small: bool) -> spot.twa_graph:
    aut = None
    if not small:  # cheap first try; often deterministic already for conjunctions of F / U
        aut = spot.translate(f, "BA", "any", "medium")
    if aut is None or not _is_terminal_dba(aut):
        aut = spot.translate(f, "BA", "deterministic", "sbacc")
    if not _is_terminal_dba(aut):
        aut = spot.minimize_obligation(aut, f)
    if not _is_terminal_dba(aut):
        raise FormulaError(f"Spot did not give a deterministic terminal automaton for {f.to_str()}")
    spot.complete_here(aut)  # explicit rejecting sink: every letter has a transition
    return aut


def _is_terminal_dba(aut: spot.twa_graph) -> bool:
    return bool(spot.is_deterministic(aut) and spot.is_terminal_automaton(aut))


def _translate_to_hoa(text: str) -> str:
    return str(_translate(spot.formula(text), small=False).to_str("hoa"))


def automaton_size(f: Formula, timeout_s: float = DEFAULT_TIMEOUT_S) -> tuple[int, int]:
    """(states, edges) of Spot's Büchi automaton for `f` ('BA', 'any', 'medium': the smallest
    cheap translation, possibly nondeterministic), computed in a child under a time limit."""
    text = _in_child(_size_text, f.text, timeout_s)
    states, edges = text.split()
    return int(states), int(edges)


def _size_text(text: str) -> str:
    aut = spot.translate(spot.formula(text), "BA", "any", "medium")
    return f"{aut.num_states()} {aut.num_edges()}"


def _in_child(fn: Callable[[str], str], arg: str, timeout_s: float) -> str:
    ctx = mp.get_context("fork")
    parent, child = ctx.Pipe(duplex=False)

    def run() -> None:
        try:
            child.send(("ok", fn(arg)))
        except Exception as exc:  # report any failure to the parent as text
            child.send(("error", str(exc)))

    proc = ctx.Process(target=run, daemon=True)
    proc.start()
    try:
        if not parent.poll(timeout_s):
            raise FormulaError(
                f"translating {arg!r} to an automaton took longer than {timeout_s:g} s; "
                "split it into a hierarchy of smaller formulas"
            )
        status, payload = parent.recv()
    finally:
        if proc.is_alive():
            proc.kill()
        proc.join()
    if status != "ok":
        raise FormulaError(f"Spot failed on {arg!r}: {payload}")
    return str(payload)


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
    accepting = frozenset(s for s in range(n) if aut.state_is_accepting(s))
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


def hoa(f: Formula, timeout_s: float = DEFAULT_TIMEOUT_S) -> str:
    """The automaton `dfa(f)` is read from (Spot's deterministic terminal Büchi automaton, completed
    with a rejecting sink), written by Spot in HOA v1; large formulas are translated in a child with
    `timeout_s`, as `dfa` does."""
    probs = sc_ltl_problems(f)
    if probs:
        raise FormulaError(f"{f.text} is not sc-LTL: " + "; ".join(probs))
    if len(f.atoms) <= IN_PROCESS_MAX_ATOMS:
        return str(_translate(f._f, small=True).to_str("hoa"))
    return _in_child(_translate_to_hoa, f.text, timeout_s)
