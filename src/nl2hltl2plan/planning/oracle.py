"""Oracle specs: the hierarchical spec a perfect translator would produce for a benchmark instance.

Shape (as the paper's Algorithm 1 builds it from the task tree):
- L1: `task1`, the instruction: the relation compiler's formula over the base tasks with the
  instance's `before` pairs (`logic.relations.compile_relations`);
- L2: one `task1.k` per base task (k in ground-truth order). A base task with one object is a leaf:
  its recipe (`BaseTask.leaf_specs`, an action list or a formula when several types are
  acceptable). A base task with count n (place_two) is a non-leaf `F task1.k.1 & F task1.k.2`
  over n one-object leaves at L3.
"""

from __future__ import annotations

from dataclasses import dataclass

from nl2hltl2plan.domain.task_kinds import APPLIANCE
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.logic.relations import compile_relations
from nl2hltl2plan.worlds.tasks import BaseTask, GTInstance
from nl2hltl2plan.worlds.world import World, sliced_type

ROOT = "task1"


@dataclass
class OracleSpec:
    spec: HierarchicalSpec
    levels: list[dict]
    task_node: dict[str, str]  # base-task id -> spec node name
    leaf_task: dict[str, str]  # leaf name -> base-task id


def oracle_spec(gt: GTInstance | dict, world: World) -> OracleSpec:
    """The perfect translation of a ground-truth instance in `world`. A task the world cannot provide
    (no such object, a receptacle that refuses it) gets the plain recipe of its first listed types,
    as a translator that does not know the scene would write it; the planner then reports why it
    is infeasible."""
    inst = gt if isinstance(gt, GTInstance) else GTInstance.model_validate(gt)
    task_node = {t.id: f"{ROOT}.{k}" for k, t in enumerate(inst.tasks, start=1)}
    level2: dict = {}
    level3: dict = {}
    leaf_task: dict[str, str] = {}
    for task in inst.tasks:
        node = task_node[task.id]
        try:
            leaves = task.leaf_specs(world, others=inst.tasks)
        except WorldError:
            leaves = plain_recipe(task)
        if len(leaves) == 1:
            level2[node] = leaves[0]
            leaf_task[node] = task.id
            continue
        names = [f"{node}.{j}" for j in range(1, len(leaves) + 1)]
        level2[node] = compile_relations(names, [])
        for name, body in zip(names, leaves, strict=True):
            level3[name] = body
            leaf_task[name] = task.id
    before = [(task_node[a], task_node[b]) for a, b in inst.before]
    levels: list[dict] = [{ROOT: compile_relations(list(task_node.values()), before)}, level2]
    if level3:
        levels.append(level3)
    return OracleSpec(HierarchicalSpec(levels), levels, task_node, leaf_task)


def plain_recipe(task: BaseTask) -> list[list[str] | str]:
    """The recipe of a task on its first listed types, without looking at a world."""
    o = task.object[0]
    held = sliced_type(o) if task.sliced else o
    r: str | None = task.receptacle[0] if task.receptacle else None
    seq: list[str] = []
    if task.sliced:
        seq += ["pickup(Knife)", f"slice({o})", "put(Knife,CounterTop)"]
    seq.append(f"pickup({held})")
    kind = task.kind
    if kind in ("place", "place_two"):
        seq.append(f"put({held},{r})")
    elif kind == "place_in_container":
        c = (task.container or ["Bowl"])[0]
        seq += [f"put({held},{c})", f"pickup({c})", f"put({c},{r})"]
    elif kind == "examine_in_light":
        seq.append(f"toggle_on({(task.light or ['DeskLamp'])[0]})")
    else:
        app = APPLIANCE[kind]
        if kind == "clean_place":
            seq += [f"put({held},SinkBasin)", "toggle_on(Faucet)", "toggle_off(Faucet)"]
        elif kind == "heat_place":
            seq += [f"put({held},Microwave)", "toggle_on(Microwave)", "toggle_off(Microwave)"]
        else:
            seq += [f"put({held},Fridge)"]
        if r not in (None, app):
            seq += [f"pickup({held})", f"put({held},{r})"]
    seq = [a for a in seq if "None" not in a]
    return [list(seq) for _ in range(max(1, task.count))]
