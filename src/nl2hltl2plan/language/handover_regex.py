"""Fast rewriting for the handover reader: a rewrite pattern whose match must contain one of a few literal
strings is skipped, without running it, on a text that holds none of them.

The reader rewrites each sentence with some hundreds of patterns, and most of them cannot match a given
sentence; `re` still tries each at every position (a pattern that opens with `\\s*,?\\s*\\b` cannot use
its literal prefix to jump ahead). `required(pattern)` reads the pattern's parse tree (`sre_parse`, the
parser `re` itself uses) for a set of literals one of which every match contains; `sub` and `apply` test
them with `in` first. The test only ever skips a pattern that cannot match, so every reading is the same
as with plain `re.sub` (a test checks this against `re` on the committed sentences)."""

from __future__ import annotations

import re
import warnings
from collections.abc import Callable, Iterable
from functools import cache
from typing import Any

with warnings.catch_warnings():  # `re`'s own parser; its old public name warns on import since 3.11
    warnings.simplefilter("ignore", DeprecationWarning)
    import sre_constants as c
    import sre_parse

Replacement = str | Callable[[re.Match[str]], str]
Literals = frozenset[str]
Requirement = tuple[Literals, ...]  # every set must have a literal in the text

_REPEATS = (c.MAX_REPEAT, c.MIN_REPEAT, getattr(c, "POSSESSIVE_REPEAT", c.MAX_REPEAT))
_ZERO_WIDTH = (c.AT,)  # \b, ^, $: they consume nothing, so the literals on either side are adjacent


def required(pattern: re.Pattern[str]) -> Requirement:
    """Sets of literals such that every match of `pattern` contains one literal of each set; empty where
    nothing is known (an empty match is possible, a case-insensitive pattern)."""
    if pattern.flags & re.IGNORECASE:
        return ()
    parsed = sre_parse.parse(pattern.pattern, pattern.flags)
    if parsed.state.flags & re.IGNORECASE:
        return ()
    # the sets with fewest literals first: they fail soonest
    return tuple(sorted(_sequence(parsed.data), key=lambda s: (len(s), -min(map(len, s)))))


def _sequence(items: Iterable[tuple[Any, Any]]) -> list[Literals]:
    """What a sequence requires: each run of literals (kept across zero-width anchors) and what each of
    its parts requires (a group, a branch, a repeat of at least one)."""
    sets: list[Literals] = []
    run = ""
    for op, arg in items:
        if op is c.LITERAL:
            run += chr(arg)
        elif op in _REPEATS and arg[0] >= 1 and _one_literal(arg[2]):
            # "u+h+": the first "u" follows the run and the last one opens the next ("uh" is in every match)
            char = chr(arg[2][0][1])
            sets.append(frozenset([run + char]))
            run = char
        elif op not in _ZERO_WIDTH:
            if run:
                sets.append(frozenset([run]))
                run = ""
            sets += _part(op, arg)
    if run:
        sets.append(frozenset([run]))
    return sets


def _one_literal(sub: Any) -> bool:
    return len(sub) == 1 and sub[0][0] is c.LITERAL


def _part(op: Any, arg: Any) -> list[Literals]:
    if op is c.SUBPATTERN:
        _group, add_flags, _del_flags, sub = arg
        return [] if add_flags & re.IGNORECASE else _sequence(list(sub))
    if op is c.BRANCH:  # one literal of each alternative's most selective set
        best = [max(_sequence(list(alt)), key=_selective, default=None) for alt in arg[1]]
        return [] if any(s is None for s in best) else [frozenset().union(*best)]  # type: ignore[arg-type]
    if op in _REPEATS:
        low, _high, sub = arg
        return _sequence(list(sub)) if low >= 1 else []
    if op is c.ASSERT:  # a lookahead or lookbehind: what it requires is in the text too
        return _sequence(list(arg[1]))
    return []  # a class, a backreference, a negative lookaround: no literal known


def _selective(literals: Literals) -> tuple[int, int]:
    return min(map(len, literals)), -len(literals)


Checks = tuple[tuple[str, ...], ...]  # a requirement as tuples: they iterate faster than frozensets


def _checks(requirement: Requirement) -> Checks:
    """The requirement as tuples, each set's shortest literals first (the likeliest to be found)."""
    return tuple(tuple(sorted(literals, key=lambda lit: (len(lit), lit))) for literals in requirement)


@cache
def compiled(pattern: str) -> tuple[re.Pattern[str], Checks]:
    """The pattern compiled once, with its required literals (the reader has more patterns than `re`'s
    own cache holds)."""
    regex = re.compile(pattern)
    return regex, _checks(required(regex))


def sub(pattern: str | re.Pattern[str], replacement: Replacement, text: str) -> str:
    """`re.sub(pattern, replacement, text)`, skipping a pattern that cannot match `text` (the literal test is
    written out here and in `apply`, not called: a call costs more than the test, a million times a batch)."""
    regex, requirement = compiled(pattern) if isinstance(pattern, str) else _compiled_of(pattern)
    for literals in requirement:
        for literal in literals:
            if literal in text:
                break
        else:
            return text
    return regex.sub(replacement, text)


@cache
def _compiled_of(pattern: re.Pattern[str]) -> tuple[re.Pattern[str], Checks]:
    return pattern, _checks(required(pattern))


Table = tuple[tuple[re.Pattern[str], Replacement, Checks], ...]


def rewrite_table(rewrites: Iterable[tuple[re.Pattern[str], Replacement]]) -> Table:
    """A table of rewrites with each pattern's required literals, for `apply`."""
    return tuple((pattern, replacement, _checks(required(pattern))) for pattern, replacement in rewrites)


def apply(rewrites: Table, text: str) -> str:
    """The rewrites in order, each skipped where its literals are absent from the text so far."""
    for pattern, replacement, requirement in rewrites:
        for literals in requirement:
            for literal in literals:
                if literal in text:
                    break
            else:
                break
        else:
            text = pattern.sub(replacement, text)
    return text
