"""Algorithm 1 of the paper: an HTT becomes a hierarchical sc-LTL specification.

Each node becomes one flat formula at the level of its depth (root: L1), named `task<id>`
(`task1`, `task1.2`, ...). A non-leaf node gets `generate_ltl(children, relations)` over its
children's names; a leaf gets `action_completion(node)`: an ordered action list or a formula over
action atoms. Both are pluggable: the defaults are the exact relation compiler and the leaf's own
`actions`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.htt import HTT, HTTNode
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec, LeafOrFormula
from nl2hltl2plan.logic.relations import compile_relations

GenerateLTL = Callable[[Sequence[str], Sequence[tuple[str, str]]], str]
ActionCompletion = Callable[[HTTNode], LeafOrFormula]


def spec_name(node_id: str) -> str:
    return f"task{node_id}"


def given_actions(node: HTTNode) -> LeafOrFormula:
    """Default ActionCompletion: the action list the HTT already carries."""
    if not node.actions:
        raise HTTError(f"leaf {node.id} ({node.text!r}) has no actions; run action completion first")
    return list(node.actions)


def build_spec(
    htt: HTT,
    generate_ltl: GenerateLTL = compile_relations,
    action_completion: ActionCompletion = given_actions,
) -> HierarchicalSpec:
    htt.validate_tree()
    levels: list[dict[str, LeafOrFormula]] = []
    by_id = {n.id: n for n in htt.nodes}  # one lookup table: linear in the tree, not quadratic
    stack = [(htt.root, 1)]  # Algorithm 1 pops a stack; levels come from depths, so order is immaterial
    while stack:
        v, k = stack.pop()  # k = GetDepth(v): the root has depth 1
        while len(levels) < k:
            levels.append({})
        if not v.children:
            levels[k - 1][spec_name(v.id)] = action_completion(v)
        else:
            children = [by_id[c] for c in v.children]
            stack.extend((c, k + 1) for c in reversed(children))
            names = [spec_name(c.id) for c in children]
            if v.any_of:  # alternatives: a disjunction, which no relation compiler writes
                levels[k - 1][spec_name(v.id)] = " | ".join(f"F {n}" for n in names)
                continue
            relations = [(spec_name(a), spec_name(b)) for a, b in htt.sibling_relations(v.id)]
            levels[k - 1][spec_name(v.id)] = generate_ltl(names, relations)
    # keep each level in node order for readable output
    order = {spec_name(n.id): i for i, n in enumerate(htt.nodes)}
    return HierarchicalSpec([dict(sorted(level.items(), key=lambda kv: order[kv[0]])) for level in levels])
