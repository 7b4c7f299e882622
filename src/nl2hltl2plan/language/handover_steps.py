"""Checks of the handover task tree across sentences (issue 24, h124).

- `refuse_unordered`: a block given two goals that no step order relates ("Move the three blocks to the
  opposite regions. The yellow block eventually goes back on G.") is refused: which goal comes first, and
  which place does the block end on? (A goal said "at any time" is free of order on purpose, unless it puts
  the block "back": that follows its leaving.)
- `scattered_joint`: goals of one block per clause, said across sentences ("Move the red block to the
  opposite side. Then move the blue block to the opposite side. The yellow block goes there too."), that
  together send every block of the scene to the opposite side, ask for all of them there at once, as
  "move the three blocks to the opposite side, red first" does: each goal is a lasting place that no later
  step moves its block from, so when the last one is met all of them hold together, and the opposite side
  has as many regions as there are blocks.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Protocol, TypeVar, cast

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_goals import Clause, Goal


class Node(Protocol):
    """A node of the task tree (`handover_tree.Item`)."""

    goal: Goal | None
    before: list[tuple[int, int]]

    @property
    def children(self) -> Sequence[Node]: ...

    def goals(self) -> list[Goal]: ...


N = TypeVar("N", bound=Node)


def flat_steps(children: list[N], before: list[tuple[int, int]]) -> tuple[list[N], list[tuple[int, int]]]:
    """The steps of a chain of one-goal steps ("red ..., then blue ...") set beside the other goals with their
    order, as "red before blue" sets them: the same spec, in the shape the joint leaf's siblings take when one
    clause says it. A node with its own orders is kept as it is."""
    if before:
        return children, before
    flat: list[N] = []
    for c in children:
        kids = cast(list[N], list(c.children))
        if kids and all(k.goal is not None for k in kids):
            before = before + [(len(flat) + i, len(flat) + j) for i, j in c.before]
            flat += kids
        else:
            flat.append(c)
    return flat, before


def refuse_unordered(root: Node, free: list[Goal]) -> None:
    """Refuses a block with two goals where no node orders the one before the other, unless one of them is
    said to be free of order ("put it back on G at any time": `free`)."""
    goals = root.goals()
    for k, a in enumerate(goals):
        for b in goals[k + 1 :]:
            if a.block == b.block and not (_ordered(root, a, b) or any(_free(g, free) for g in (a, b))):
                raise HTTError(
                    f"the {a.block.lower()} block is sent to two places ({_said(a)}, {_said(b)}) and nothing "
                    "orders them: say which comes first"
                )


def _said(goal: Goal) -> str:
    """Where a goal sends its block, in the user's terms (the marked text holds the reader's tokens)."""
    where = goal.where()
    return where if " " in where else "region " + " or ".join(where.split("|"))


def _free(goal: Goal, free: list[Goal]) -> bool:
    """A goal said free of order, unless it puts its block back: "back" follows the block's leaving, so
    "at some point put the yellow block back on G" beside another goal of the yellow block orders nothing
    it could mean (its start already holds it there) and is refused."""
    return goal in free and not re.search(r"\bback\b", goal.text, re.I)


def _ordered(item: Node, a: Goal, b: Goal) -> bool:
    at = [k for k, c in enumerate(item.children) if a in c.goals()]
    bt = [k for k, c in enumerate(item.children) if b in c.goals()]
    if not at or not bt:
        return False
    if at[0] == bt[0]:
        return _ordered(item.children[at[0]], a, b)
    graph = nx.DiGraph(item.before)
    graph.add_nodes_from([at[0], bt[0]])
    return nx.has_path(graph, at[0], bt[0]) or nx.has_path(graph, bt[0], at[0])


def scattered_joint(clauses: list[Clause], blocks: Sequence[str]) -> list[Goal] | None:
    """The goals to ask for at once where clauses of one goal each send every block to the opposite side
    (see the module's note); None where they do not."""
    if len(clauses) < 2 or any(len(c.goals) != 1 or c.together or c.marker == "after_all" for c in clauses):
        return None
    goals = [c.goals[0] for c in clauses]
    regions = {g.regions for g in goals}
    if any(g.place.kind != "opposite" for g in goals) or len(regions) != 1:
        return None
    said = [g.block for g in goals]
    if sorted(said) != sorted(blocks) or len(next(iter(regions))) != len(said):
        return None
    return goals
