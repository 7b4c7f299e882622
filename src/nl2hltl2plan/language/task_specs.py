"""Structured base tasks as the language stage produces them.

A base task is one ALFRED household task (the fields of `worlds.tasks.BaseTask` and of the benchmark's
ground truth, see `ANNOTATION_GUIDE.md`): what kind of task it is, which AI2-THOR object types are
acceptable for the manipulated object, the container, the destination and the lamp, how many objects,
and whether the object must be a slice. The language stage keeps one `BaseTask` per base task next
to the HTT (the HTT nodes carry text and actions only), and `before` pairs between base-task ids.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable, Sequence
from typing import TypeVar

import networkx as nx
from pydantic import BaseModel, Field

from nl2hltl2plan.domain.task_kinds import KINDS, Kind
from nl2hltl2plan.worlds.tasks import BaseTask

N = TypeVar("N", bound=Hashable)

__all__ = [
    "KINDS",
    "BaseTaskSpec",
    "ConstraintSpec",
    "Kind",
    "task_letter",
    "transitive_closure",
    "transitive_reduction",
]


# The one base-task model lives in worlds (the ground truth uses it too); the old name stays for callers.
BaseTaskSpec = BaseTask


class ConstraintSpec(BaseModel):
    """A constraint as the language stage states it: the instruction's words, the forbidden action
    patterns over scene types, and the base task whose completion lifts it (None: never lifted)."""

    text: str
    forbid: list[str] = Field(min_length=1)
    until: str | None = None  # a base-task id

    def describe(self) -> str:
        guard = f" until task {self.until} is done" if self.until else ""
        return f"{self.text}: forbids {', '.join(self.forbid)}{guard}"


def transitive_closure(
    pairs: list[tuple[str, str]] | set[tuple[str, str]], nodes: list[str] | None = None
) -> set[tuple[str, str]]:
    """Every (a, b) where b is reachable from a, never (a, a) (networkx's `descendants`); `nodes` adds
    none. By hand: a graph of a few tasks costs networkx ~0.2 ms, asked several times per reading."""
    after: dict[str, set[str]] = {}
    for a, b in pairs:
        after.setdefault(a, set()).add(b)
    out: set[tuple[str, str]] = set()
    for a, nxt in after.items():
        seen, todo = {a}, list(nxt)
        while todo:
            if (b := todo.pop()) not in seen:
                seen.add(b)
                out.add((a, b))
                todo += after.get(b, ())
    return out


def transitive_reduction(
    pairs: Iterable[tuple[N, N]], order: Sequence[N] | None = None
) -> list[tuple[N, N]]:
    """The fewest pairs with the same closure (pairs must be acyclic); sorted by `order` when given."""
    pairs = list(pairs)
    # no pair, or one between two tasks, is its own reduction: most readings, asked several times each,
    # and networkx's graph costs ~0.15 ms
    if not pairs or (len(pairs) == 1 and pairs[0][0] != pairs[0][1]):
        return [(a, b) for a, b in pairs]
    g = nx.DiGraph()
    g.add_nodes_from(order or [])
    g.add_edges_from(pairs)
    red = nx.transitive_reduction(g)
    rank = {n: i for i, n in enumerate(order or sorted(g.nodes))}
    return sorted(red.edges, key=lambda e: (rank.get(e[0], 0), rank.get(e[1], 0)))


def task_letter(i: int) -> str:
    """0 -> A, 25 -> Z, 26 -> AA ..."""
    s = ""
    i += 1
    while i:
        i, r = divmod(i - 1, 26)
        s = chr(65 + r) + s
    return s
