"""Base tasks and their order -> the paper's Hierarchical Task Tree.

Root "1" is the whole instruction; with several base tasks each is a child of the root (or of a group
node when one sentence groups several tasks with the same relations to the rest); a base task with
two objects (place_two) is a non-leaf whose leaves are one object each; with a choice of places the count
binds to one place, so its node is an any-of node over one node per place, each one leaf per object.
"""

from __future__ import annotations

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.htt import HTT, HTTNode
from nl2hltl2plan.language.task_specs import BaseTaskSpec, transitive_closure, transitive_reduction


def n_leaves(task: BaseTaskSpec) -> int:
    """Leaves of a base task: one per object (place_two, "heat a couple of slices"), as in the recipes."""
    return max(1, task.count)


def bound_places(task: BaseTaskSpec) -> list[list[str]]:
    """A count with a choice of places ("two mugs in the sink or the cabinet"): the places the world can
    take (each its types, as `receptacle` keeps them), bound to the whole count; empty for any other task."""
    if task.count < 2 or not task.places:
        return []
    took = set(task.receptacle or ())
    groups = [kept for place in task.places if (kept := [t for t in place if t in took])]
    return groups if len(groups) > 1 else []


def task_nodes(node_id: str, task: BaseTaskSpec, text: str | None = None) -> tuple[list[HTTNode], list[str]]:
    """The nodes of one base task under `node_id`, and its leaves: one leaf, one per object, or, for a
    count bound to one of several places, an any-of node over one node per place, each one leaf per object."""
    k, places = n_leaves(task), bound_places(task)
    if k == 1:
        return [HTTNode(id=node_id, text=text or task.text)], [node_id]
    if not places:
        kids = [f"{node_id}.{j}" for j in range(1, k + 1)]
        objects = [HTTNode(id=kid, text=f"{task.text} (object {j} of {k})") for j, kid in enumerate(kids, 1)]
        return [HTTNode(id=node_id, text=text or task.text, children=kids), *objects], kids
    alts = [f"{node_id}.{p}" for p in range(1, len(places) + 1)]
    nodes = [HTTNode(id=node_id, text=text or task.text, children=alts, any_of=True)]
    leaves: list[str] = []
    for alt, place in zip(alts, places, strict=True):
        kids = [f"{alt}.{j}" for j in range(1, k + 1)]
        nodes.append(HTTNode(id=alt, text=f"{task.text} (all {k} in the {'|'.join(place)})", children=kids))
        for j, kid in enumerate(kids, 1):
            nodes.append(HTTNode(id=kid, text=f"{task.text} (object {j} of {k}, {place[0]})"))
        leaves += kids
    return nodes, leaves


def rebind(htt: HTT, task_node: dict[str, str], leaf_task: dict[str, str], task: BaseTaskSpec) -> HTT:
    """The HTT with `task`'s subtree built again (its places were widened after the tree was built);
    `leaf_task` is updated in place."""
    node_id = task_node[task.id]
    old = {node_id} | {n.id for n in htt.nodes if n.id.startswith(node_id + ".")}
    for leaf in [leaf for leaf in leaf_task if leaf in old]:
        del leaf_task[leaf]
    nodes, leaves = task_nodes(node_id, task, htt.node(node_id).text)
    leaf_task.update(dict.fromkeys(leaves, task.id))
    at = next(i for i, n in enumerate(htt.nodes) if n.id == node_id)
    kept = [n for n in htt.nodes if n.id not in old]
    return htt.model_copy(update={"nodes": kept[:at] + nodes + kept[at:]})


def build_htt(
    instruction: str,
    tasks: list[BaseTaskSpec],
    before: list[tuple[str, str]],
    groups: list[list[str]] | None = None,
    group_texts: list[str] | None = None,
) -> tuple[HTT, dict[str, str], dict[str, str]]:
    """HTT (paper's numbering), base task -> node, leaf -> base task, from base tasks and their order.

    Groups (tasks one sentence lists together) become a node when all members relate in the same way to
    every task outside the group; the relations between siblings are the closure's, transitively reduced.
    """
    ids = [t.id for t in tasks]
    closure = transitive_closure(before, ids)
    items: list[list[str]] = []
    grouped: set[str] = set()
    item_text: dict[int, str] = {}
    for gi, g in enumerate(groups or []):
        members = [m for m in g if m in ids and m not in grouped]
        if len(members) < 2:
            continue
        outside = [t for t in ids if t not in members]
        uniform = all(
            len({(m, o) in closure for m in members}) == 1 and len({(o, m) in closure for m in members}) == 1
            for o in outside
        )
        if uniform:
            items.append(members)
            grouped.update(members)
            if group_texts and gi < len(group_texts) and group_texts[gi]:
                item_text[id(members)] = group_texts[gi]
    for t in ids:
        if t not in grouped:
            items.append([t])
    items.sort(key=lambda it: min(ids.index(m) for m in it))
    by_id = {t.id: t for t in tasks}
    nodes: list[HTTNode] = []
    relations: list[tuple[str, str]] = []
    task_node: dict[str, str] = {}
    leaf_task: dict[str, str] = {}

    def add_task(node_id: str, task: BaseTaskSpec, text: str | None = None) -> None:
        task_node[task.id] = node_id
        made, leaves = task_nodes(node_id, task, text)
        nodes.extend(made)
        leaf_task.update(dict.fromkeys(leaves, task.id))

    def add_group(node_id: str, members: list[str], text: str | None = None) -> None:
        kids = [f"{node_id}.{j}" for j in range(1, len(members) + 1)]
        nodes.append(
            HTTNode(id=node_id, text=text or "; ".join(by_id[m].text for m in members), children=kids)
        )
        for kid, m in zip(kids, members, strict=True):
            add_task(kid, by_id[m])
        inner = [(a, b) for a in members for b in members if (a, b) in closure]  # not a scan of the closure
        for a, b in transitive_reduction(inner, members):
            relations.append((task_node[a], task_node[b]))

    if not tasks:
        raise HTTError("no base task to build an HTT from")
    if len(items) == 1:
        if len(items[0]) == 1:
            add_task("1", by_id[items[0][0]], instruction)
        else:
            add_group("1", items[0], instruction)
    else:
        kids = [f"1.{k}" for k in range(1, len(items) + 1)]
        nodes.append(HTTNode(id="1", text=instruction, children=kids))
        for kid, item in zip(kids, items, strict=True):
            if len(item) == 1:
                add_task(kid, by_id[item[0]])
            else:
                add_group(kid, item, item_text.get(id(item)))
        item_rel = {
            (i, j)
            for i, a in enumerate(items)
            for j, b in enumerate(items)
            if i != j and all((x, y) in closure for x in a for y in b)
        }
        for i, j in transitive_reduction(item_rel, list(range(len(items)))):
            relations.append((kids[i], kids[j]))
    htt = HTT(instruction=instruction, nodes=nodes, relations=relations)
    htt.validate_tree()
    return htt, task_node, leaf_task


def flat_before(htt: HTT, task_node: dict[str, str]) -> list[tuple[str, str]]:
    """Base-task precedence implied by the HTT's sibling relations (reduced)."""
    node_task = {v: k for k, v in task_node.items()}
    g = htt.graph()
    under: dict[str, set[str]] = {}
    for n in htt.nodes:
        desc = (
            nx.descendants(
                nx.DiGraph([(a, b) for a, b, d in g.edges(data=True) if d["kind"] == "decomposition"]), n.id
            )
            if n.children
            else set()
        )
        under[n.id] = {node_task[x] for x in desc | {n.id} if x in node_task}
    pairs = {(a, b) for x, y in htt.relations for a in under.get(x, ()) for b in under.get(y, ())}
    order = sorted(task_node, key=lambda t: t)
    return transitive_reduction(pairs, order)
