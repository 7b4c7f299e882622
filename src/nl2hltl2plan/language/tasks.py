"""Structured base tasks as the language stage produces them.

A base task is one ALFRED household task (the fields of `worlds.tasks.BaseTask` and of the benchmark's
ground truth, see `ANNOTATION_GUIDE.md`): what kind of task it is, which AI2-THOR object types are
acceptable for the manipulated object, the container, the destination and the lamp, how many objects,
and whether the object must be a slice. The language stage keeps one `BaseTaskSpec` per base task next
to the HTT (the HTT nodes carry text and actions only), and `before` pairs between base-task ids.
"""

from __future__ import annotations

import networkx as nx
from pydantic import BaseModel, Field

from nl2hltl2plan.worlds.tasks import KINDS, BaseTask, Kind

__all__ = ["KINDS", "BaseTaskSpec", "Kind", "TaskSet", "transitive_closure", "transitive_reduction"]

STATE_OF_KIND = {"clean_place": "clean", "heat_place": "hot", "cool_place": "cold"}


class BaseTaskSpec(BaseTask):
    """One base task as the language stage produces it: `worlds.tasks.BaseTask` (the ground truth's
    fields) with a default id and a readable summary."""

    id: str = "A"

    def summary(self) -> str:
        """One readable line, e.g. `clean_place Potato(sliced) -> Fridge`."""
        obj = "|".join(self.object) + ("(sliced)" if self.sliced else "")
        if self.count > 1:
            obj = f"{self.count}x {obj}"
        if self.kind == "examine_in_light":
            return f"{self.kind} {obj} under {'|'.join(self.light or ['?'])}"
        inner = f" in {'|'.join(self.container)}" if self.container else ""
        return f"{self.kind} {obj}{inner} -> {'|'.join(self.receptacle or ['?'])}"

    def to_base_task(self):  # -> worlds.tasks.BaseTask
        """The worlds' BaseTask with the same fields (needs `nl2hltl2plan.worlds.tasks`)."""
        from nl2hltl2plan.worlds.tasks import BaseTask

        return BaseTask.model_validate(self.model_dump())


class TaskSet(BaseModel):
    """Base tasks and the precedence pairs between them (ids of `tasks`)."""

    tasks: list[BaseTaskSpec] = Field(default_factory=list)
    before: list[tuple[str, str]] = Field(default_factory=list)

    def closure(self) -> set[tuple[str, str]]:
        return transitive_closure(self.before, [t.id for t in self.tasks])


def transitive_closure(
    pairs: list[tuple[str, str]] | set[tuple[str, str]], nodes: list[str] | None = None
) -> set[tuple[str, str]]:
    g = nx.DiGraph()
    g.add_nodes_from(nodes or [])
    g.add_edges_from(pairs)
    return {(a, b) for a in g.nodes for b in nx.descendants(g, a)}


def transitive_reduction(
    pairs: list[tuple[str, str]] | set[tuple[str, str]], order: list[str] | None = None
) -> list[tuple[str, str]]:
    """The fewest pairs with the same closure (pairs must be acyclic); sorted by `order` when given."""
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
