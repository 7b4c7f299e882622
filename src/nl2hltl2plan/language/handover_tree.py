"""The task tree of a handover instruction and its `LanguageResult` (`handover_reading` gathers the
clauses): one leaf per goal, a joint ("at once") leaf where a clause asks for its blocks there together,
"first ..., then ..." as one node of steps in order, "after all of these" as a node of everything said
before it; orders between blocks become the tree's relations and the base tasks' `before`, and the guards
and joint goals its `constraints`, as text, sorted."""

from __future__ import annotations

from dataclasses import dataclass, field

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_goals import Clause, Goal
from nl2hltl2plan.language.htt import HTT, HTTNode
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_reduction


@dataclass
class Item:
    """A node of the task tree being built: a goal leaf, a joint ('at once') leaf, or a group."""

    text: str
    goal: Goal | None = None
    joint: list[Goal] | None = None
    children: list[Item] = field(default_factory=list)
    before: list[tuple[int, int]] = field(default_factory=list)

    def goals(self) -> list[Goal]:
        if self.goal is not None:
            return [self.goal]
        return [g for c in self.children for g in c.goals()]



def _items(c: Clause) -> list[Item]:
    items = [Item(f"{g.block.lower()} block to {g.where()}", goal=g) for g in c.goals]
    return items + ([joint_item(c.goals)] if c.together else [])


def joint_item(goals: list[Goal]) -> Item:
    said = ", ".join(f"{g.block.lower()} on {g.where()}" for g in goals)
    return Item(f"at once: {said}", joint=list(goals))


def _unit(c: Clause) -> Item:
    items = _items(c)
    return items[0] if len(items) == 1 else Item(c.text, children=items)


def build_tree(clauses: list[Clause]) -> Item:
    root = Item("")
    chain: Item | None = None
    prev: Clause | None = None
    closed = False  # the last step was ordered after all before it
    for c in clauses:
        if c.marker == "then" and prev is not None:
            if chain is None:
                n_prev = len(_items(prev))
                root.children = root.children[:-n_prev]
                chain = Item(prev.text, children=[_unit(prev)])
                root.children.append(chain)
            chain.children.append(_unit(c))
            chain.before.append((len(chain.children) - 2, len(chain.children) - 1))
            chain.text += "; " + c.text
        elif c.marker == "after_all" and root.children:
            if any(d.anytime for d in clauses[: clauses.index(c)]):  # "after all of these" would order them
                raise HTTError("'after all of these' ('once that is done') orders goals said 'at any time'")
            old = root.children[0] if len(root.children) == 1 else root
            root = Item("", children=[old])
            root.children += _items(c)
            root.before += [(0, k) for k in range(1, len(root.children))]
            chain = None
            closed = True
        else:
            if closed:  # a goal said after the steps that "after all of these" ordered: beside them, as one
                root = Item("", children=[root])
                closed = False
            root.children += _items(c)
            chain = None
        prev = c
    return root


def order_goals(root: Item, a: Goal, b: Goal) -> None:
    def visit(item: Item) -> bool:
        kids = [c.goal for c in item.children]
        if a in kids and b in kids:
            item.before.append((kids.index(a), kids.index(b)))
            return True
        return any(visit(c) for c in item.children)

    if not visit(root):
        raise HTTError(f"cannot order {a.text!r} before {b.text!r}: they belong to different steps")


def language_result(
    scene: str, instruction: str, root: Item, goals: list[Goal], notes: list[str]
) -> LanguageResult:
    if len(root.children) == 1:
        root = root.children[0]
    nodes: list[HTTNode] = []
    relations: list[tuple[str, str]] = []
    leaf_specs: dict[str, str] = {}
    goal_leaf: dict[int, str] = {}  # id(goal) -> its HTT leaf

    def add(item: Item, node_id: str, text: str) -> None:
        if not item.children:
            nodes.append(HTTNode(id=node_id, text=text))
            if item.goal is not None:
                goal_leaf[id(item.goal)] = node_id
                leaf_specs[node_id] = item.goal.leaf()
            else:
                leaf_specs[node_id] = "F(" + " & ".join(g.state() for g in item.joint or []) + ")"
            return
        kids = [f"{node_id}.{k}" for k in range(1, len(item.children) + 1)]
        nodes.append(HTTNode(id=node_id, text=text, children=kids))
        relations.extend((kids[i], kids[j]) for i, j in item.before)
        for kid, child in zip(kids, item.children, strict=True):
            add(child, kid, child.text)

    add(root, "1", instruction)
    htt = HTT(instruction=instruction, nodes=nodes, relations=relations)
    letter = {id(g): task_letter(k) for k, g in enumerate(goals)}
    tasks = [
        BaseTaskSpec(
            id=letter[id(g)],
            text=g.text,
            kind="place",
            object=[f"{g.block}Block"],
            receptacle=[f"Region{r}" for r in g.regions] or [g.where()],
        )
        for g in goals
    ]
    task_node = {letter[id(g)]: goal_leaf[id(g)] for g in goals}
    return LanguageResult(
        backend="offline",
        instruction=instruction,
        scene=scene,
        htt=htt,
        tasks=tasks,
        before=transitive_reduction(_task_pairs(root, letter), [t.id for t in tasks]),
        task_node=task_node,
        leaf_task={v: k for k, v in task_node.items()},
        leaf_specs=dict(leaf_specs),
        spec=build_spec(htt, action_completion=lambda node: leaf_specs[node.id]),
        constraints=_constraints(root, goals, notes),
    )


def _task_pairs(item: Item, letter: dict[int, str]) -> set[tuple[str, str]]:
    """Base-task precedence: every goal under an earlier sibling before every goal under a later one."""
    out = {
        (letter[id(a)], letter[id(b)])
        for i, j in item.before
        for a in item.children[i].goals()
        for b in item.children[j].goals()
    }
    return out.union(*(_task_pairs(c, letter) for c in item.children))


def _constraints(root: Item, goals: list[Goal], notes: list[str]) -> list[str]:
    """The guards and joint goals as text, sorted (the canonical order of `plan --json`)."""
    out = set(notes) | set(_joint_texts(root))
    for g in goals:
        out.update(f"{g.block.lower()} is not picked up before {y.lower()} is" for y in g.touch_guard)
        if g.drop_guard:
            out.add(f"until {g.block.lower()} is on {g.where()}: none of {', '.join(sorted(g.drop_guard))}")
    return sorted(out)


def _joint_texts(item: Item) -> list[str]:
    own = [item.text] if item.joint else []
    return own + [t for c in item.children for t in _joint_texts(c)]  # `_constraints` sorts them
