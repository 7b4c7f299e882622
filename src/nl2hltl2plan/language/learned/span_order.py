"""Span relations (`compose.RELATIONS`) -> `before` pairs between spans, by text position.

The spans are read left to right into chains of steps. START opens the first chain; SEQ opens a new
step after the current one; PAR joins the current step (no order inside a step: "X and Y", "X. Also
Y", two sentences with no temporal word); ANY joins it too, with the order explicitly left open ("X and
Y in any order"); PRE opens a new step just before the current one ("before you X, Y": Y first); FREE
opens a chain of its own (no order with anything so far). Every span of a step comes before every span
of a later step of its chain. LAST ("finally Y", the benchmark's annotation guide) comes after every
earlier span that is not allowed in any order or at any time: after every span of the last step of each
chain that has no ANY span and is not FREE (the earlier steps are before it already).

>>> before_pairs(["START", "SEQ", "PAR", "SEQ"])
[(0, 1), (0, 2), (1, 3), (2, 3)]
>>> before_pairs(["START", "PRE"])
[(1, 0)]
>>> before_pairs(["START", "ANY", "LAST"])
[]
>>> before_pairs(["START", "PAR", "LAST"])
[(0, 2), (1, 2)]
>>> before_pairs(["FREE", "PAR", "LAST"])
[(1, 2)]
"""

from __future__ import annotations


def before_pairs(relations: list[str]) -> list[tuple[int, int]]:
    """The transitively reduced `before` pairs (span indices) that the relations state."""
    chains: list[list[list[int]]] = []
    current = 0  # the current step's index in the last chain
    free = {i for i, rel in enumerate(relations) if rel == "FREE"}  # allowed at any time
    any_order = {i for i, rel in enumerate(relations) if rel == "ANY"}  # its step in any order
    last: list[int] = []
    for i, rel in enumerate(relations):
        if rel == "LAST" and chains:
            last.append(i)
        elif not chains or rel in ("START", "FREE", "LAST"):
            chains.append([[i]])
            current = 0
        elif rel in ("PAR", "ANY"):
            chains[-1][current].append(i)
        elif rel == "PRE":
            chains[-1].insert(current, [i])
            current += 1  # the step read so far stays the current one
        else:  # SEQ
            chains[-1].insert(current + 1, [i])
            current += 1
    pairs = []
    for steps in chains:
        for a, b in zip(steps, steps[1:], strict=False):
            pairs += [(x, y) for x in a for y in b]
    for y in last:
        for steps in chains:
            # a step with an ANY span is open as a whole; in the others the spans that are not FREE are firm
            firm = [[x for x in s if x not in free] for s in steps if s[0] < y and not any_order & set(s)]
            firm = [s for s in firm if s]
            if firm:  # the chain's last firm step: the earlier ones are before it already
                pairs += [(x, y) for x in firm[-1]]
    return sorted(set(pairs))
