"""Leaf formulas that are "one of these action sequences, in order", as text and back.

`sequences_formula` writes the alternatives as a trie of `F(a & F(...))` terms (the recipes' leaves);
`formula_sequences` reads such a text back into its sequences (scripted plans follow them).

>>> sequences_formula([["a", "b"], ["a", "c"]])
'F("a" & (F "b" | F "c"))'
>>> formula_sequences('F("a" & (F "b" | F "c"))')
[['a', 'b'], ['a', 'c']]
"""

from __future__ import annotations

import re

from nl2hltl2plan.errors import WorldError


def sequences_formula(seqs: list[list[str]]) -> str:
    """Flat sc-LTL for "one of these action sequences, in order": a trie of F(a & F(...)) terms."""
    trie: dict = {}
    for seq in seqs:
        node = trie
        for atom in seq:
            node = node.setdefault(atom, {})
        node[None] = {}  # end marker: a shorter sequence makes longer ones with its prefix redundant

    def emit(node: dict) -> str | None:
        if None in node:
            return None
        parts = []
        for atom, child in node.items():
            inner = emit(child)
            parts.append(f'F "{atom}"' if inner is None else f'F("{atom}" & {inner})')
        return parts[0] if len(parts) == 1 else "(" + " | ".join(parts) + ")"

    text = emit(trie)
    assert text is not None
    return text[1:-1] if text.startswith("(") and _balanced_outer(text) else text


def formula_sequences(formula: str) -> list[list[str]]:
    """The action sequences of a `sequences_formula` text (its inverse), in order."""
    tokens = re.findall(r'"[^"]*"|F|&|\||\(|\)', formula)
    pos = 0

    def peek() -> str | None:
        return tokens[pos] if pos < len(tokens) else None

    def take(expected: str | None = None) -> str:
        nonlocal pos
        tok = peek()
        if tok is None or (expected is not None and tok != expected):
            raise WorldError(f"not a recipe formula (at token {pos}: {tok!r}): {formula}")
        pos += 1
        return tok

    def expr() -> list[list[str]]:
        seqs = term()
        while peek() == "|":
            take("|")
            seqs += term()
        return seqs

    def term() -> list[list[str]]:
        if peek() == "(":
            take("(")
            seqs = expr()
            take(")")
            return seqs
        take("F")
        if peek() != "(":
            return [[take().strip('"')]]
        take("(")
        atom = take().strip('"')
        take("&")
        rest = term()
        take(")")
        return [[atom, *r] for r in rest]

    seqs = expr()
    if pos != len(tokens):
        raise WorldError(f"not a recipe formula (trailing text): {formula}")
    return seqs


def _balanced_outer(text: str) -> bool:
    depth = 0
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if depth == 0 and i < len(text) - 1:
            return False
    return True
