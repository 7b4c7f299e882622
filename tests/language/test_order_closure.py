"""`task_specs.transitive_closure`, written by hand for speed, gives networkx's answer."""

from __future__ import annotations

import random

import networkx as nx

from nl2hltl2plan.language.task_specs import transitive_closure


def _networkx(pairs: list, nodes: list[str]) -> set[tuple[str, str]]:
    g = nx.DiGraph()
    g.add_nodes_from(nodes)
    g.add_edges_from(pairs)
    return {(a, b) for a in g.nodes for b in nx.descendants(g, a)}


def test_the_closure_of_an_order_is_networkx_s_cycles_and_self_loops_included() -> None:
    rng = random.Random(3)
    for _ in range(500):
        names = [chr(65 + i) for i in range(rng.randint(1, 6))]
        pairs = [(rng.choice(names), rng.choice(names)) for _ in range(rng.randint(0, 9))]
        assert transitive_closure(pairs, names) == _networkx(pairs, names), pairs
    assert transitive_closure([("A", "B"), ("B", "C")]) == {("A", "B"), ("B", "C"), ("A", "C")}
    assert transitive_closure([("A", "B"), ("B", "A")]) == {("A", "B"), ("B", "A")}  # never (A, A)
