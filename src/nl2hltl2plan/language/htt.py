"""The Hierarchical Task Tree (HTT) of the paper (Definition of Section III-A).

An HTT is a tree T = (V, E, R): nodes carry the instruction text of their task; decomposition edges
go from a parent to its children; temporal relations R hold only between siblings, (a, b) meaning
"task a is completed before task b". Node ids follow the paper: the root is "1", its children
"1.1", "1.2", ..., their children "1.1.1", ... A leaf is a task made of sequential operations on one
object; its `actions` (filled by action completion) are an ordered list of robot API actions such
as ["pickup(Plate)", "put(Plate,Dishwasher)"].

JSON form (in and out)::

    {"instruction": "...",
     "nodes": [{"id": "1", "text": "...", "children": ["1.1", "1.2"]},
               {"id": "1.1", "text": "...", "actions": ["pickup(Plate)", "put(Plate,Dishwasher)"]}, ...],
     "relations": [["1.1", "1.2"]]}
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import networkx as nx
from pydantic import BaseModel, Field, ValidationError

from nl2hltl2plan.errors import DataError, HTTError
from nl2hltl2plan.io import loads, read_json


class HTTNode(BaseModel):
    id: str
    text: str = ""
    children: list[str] = Field(default_factory=list)
    actions: list[str] | None = None
    # the children are alternatives, the node is done when one of them is: a count bound to one of the
    # places said ("two mugs in the sink or the cabinet": both in one, never one in each)
    any_of: bool = Field(default=False, exclude_if=lambda v: not v)


class HTT(BaseModel):
    instruction: str = ""
    nodes: list[HTTNode]
    relations: list[tuple[str, str]] = Field(default_factory=list)

    # ----- construction and JSON -------------------------------------------------------------
    @classmethod
    def from_json(cls, data: str | dict[str, Any], validate: bool = True) -> HTT:
        """Parse (and by default validate) an HTT; HTTError names what is wrong."""
        try:
            raw = loads(data, "HTT") if isinstance(data, str) else data
            htt = cls.model_validate(raw)
        except DataError as exc:
            raise HTTError(str(exc)) from None
        except ValidationError as exc:
            raise HTTError(f"HTT does not have the expected fields: {_short(exc)}") from None
        if validate:
            htt.validate_tree()
        return htt

    @classmethod
    def load(cls, path: str | Path) -> HTT:
        return cls.from_json(read_json(path, "HTT file"))  # errors name the file

    def to_json(self, indent: int | None = 2) -> str:
        return self.model_dump_json(indent=indent, exclude_none=True)

    # ----- structure -------------------------------------------------------------------------
    def node(self, node_id: str) -> HTTNode:
        for n in self.nodes:
            if n.id == node_id:
                return n
        raise HTTError(f"no node {node_id!r} in the HTT")

    @property
    def root(self) -> HTTNode:
        parents = self.parents()
        roots = [n for n in self.nodes if n.id not in parents]
        if len(roots) != 1:
            raise HTTError(f"an HTT has exactly one root, found {len(roots)}: {[r.id for r in roots]}")
        return roots[0]

    def parents(self) -> dict[str, str]:
        """child id -> parent id (the first parent when a child has several; validation flags that)."""
        out: dict[str, str] = {}
        for n in self.nodes:
            for c in n.children:
                out.setdefault(c, n.id)
        return out

    def children(self, node_id: str) -> list[HTTNode]:
        return [self.node(c) for c in self.node(node_id).children]

    def is_leaf(self, node_id: str) -> bool:
        return not self.node(node_id).children

    def leaves(self) -> list[HTTNode]:
        return [n for n in self.nodes if not n.children]

    def depth(self, node_id: str) -> int:
        """GetDepth of Algorithm 1: the root has depth 1."""
        parents = self.parents()
        d = 1
        while node_id in parents:
            node_id = parents[node_id]
            d += 1
        return d

    def sibling_relations(self, parent_id: str) -> list[tuple[str, str]]:
        """GetTemporalRelations: the relations among the children of `parent_id`."""
        kids = set(self.node(parent_id).children)
        return [(a, b) for a, b in self.relations if a in kids and b in kids]

    def graph(self) -> nx.DiGraph:
        """Decomposition edges (kind='decomposition') and relations (kind='before') in one graph."""
        g = nx.DiGraph()
        for n in self.nodes:
            g.add_node(n.id, text=n.text)
        for n in self.nodes:
            for c in n.children:
                g.add_edge(n.id, c, kind="decomposition")
        for a, b in self.relations:
            g.add_edge(a, b, kind="before")
        return g

    # ----- validation ------------------------------------------------------------------------
    def problems(self) -> list[str]:
        """Everything that keeps this from being an HTT, as readable sentences (empty when valid)."""
        out: list[str] = []
        ids = [n.id for n in self.nodes]
        if not ids:
            return ["the HTT has no nodes"]
        dup = sorted({i for i in ids if ids.count(i) > 1})
        if dup:
            out.append(f"node ids used more than once: {dup}")
        known = set(ids)
        parent_of: dict[str, list[str]] = {}
        for n in self.nodes:
            for c in n.children:
                if c not in known:
                    out.append(f"node {n.id} lists child {c!r}, which is not a node")
                parent_of.setdefault(c, []).append(n.id)
        for c, ps in parent_of.items():
            if len(ps) > 1:
                out.append(
                    f"node {c} has {len(ps)} parents ({', '.join(ps)}); in a tree each task has one parent"
                )
        roots = [i for i in ids if i not in parent_of]
        if len(roots) != 1:
            out.append(f"an HTT has exactly one root (a node nobody lists as child); found {roots or 'none'}")
        tree = nx.DiGraph([(p, c) for c, ps in parent_of.items() for p in ps if c in known])
        tree.add_nodes_from(ids)
        if not nx.is_directed_acyclic_graph(tree):
            cycle = nx.find_cycle(tree)
            out.append(
                "decomposition edges form a cycle: " + " -> ".join([a for a, _ in cycle] + [cycle[0][0]])
            )
        elif len(roots) == 1 and len(nx.descendants(tree, roots[0])) + 1 != len(known):
            lost = sorted(known - nx.descendants(tree, roots[0]) - {roots[0]})
            out.append(f"nodes not reachable from the root {roots[0]}: {lost}")
        for n in self.nodes:
            for c in n.children:
                if c in known and not (c.startswith(n.id + ".") and c[len(n.id) + 1 :].isdigit()):
                    out.append(f"child id {c} of node {n.id} should be {n.id}.<k> (the paper's numbering)")
            if n.children and n.actions:
                out.append(f"node {n.id} has children and actions; only leaves carry actions")
        # relations: known nodes, siblings only, no self-loops, acyclic per parent
        rel = nx.DiGraph()
        for a, b in self.relations:
            if a not in known or b not in known:
                missing = [x for x in (a, b) if x not in known]
                out.append(f"relation ({a}, {b}) names unknown node(s) {missing}")
                continue
            if a == b:
                out.append(f"relation ({a}, {b}) relates a task to itself")
                continue
            pa, pb = parent_of.get(a, [None])[0], parent_of.get(b, [None])[0]
            if pa is None or pa != pb:
                out.append(
                    f"relation ({a}, {b}) is not between siblings (parents {pa} and {pb}); "
                    "relations hold only between children of the same task"
                )
                continue
            rel.add_edge(a, b)
        if not nx.is_directed_acyclic_graph(rel):
            cycle = nx.find_cycle(rel)
            out.append(
                "temporal relations are cyclic: " + " before ".join([a for a, _ in cycle] + [cycle[0][0]])
            )
        return out

    def validate_tree(self) -> HTT:
        probs = self.problems()
        if probs:
            raise HTTError("invalid HTT:\n  - " + "\n  - ".join(probs))
        return self


def _short(exc: ValidationError) -> str:
    return "; ".join(f"{'.'.join(str(p) for p in e['loc'])}: {e['msg']}" for e in exc.errors()[:5])
