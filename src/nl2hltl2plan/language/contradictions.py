"""A constraint that forbids what a task of the same reading requires (issue 23): refused at the spec.

"Put the apple in the fridge but never open the fridge", "put the egg on the table, don't touch the
egg", "wash the mug ..., without washing it": each task is possible and so is each ban, but not both.
The planner would search and answer "infeasible" (exit 1), which says the world cannot do it; the text
itself is the problem, so the language stage refuses it (exit 2) naming the constraint's words and the
task. One check for every world and backend, where the leaf actions meet the constraints
(`translate._finish`), before the spec is built.

What a task requires: every action of its leaves (all leaves are required: an HTT orders tasks, it has
no choice), the change of state its kind makes (`heat(Mug)` for a heat_place), and the opening of a
receptacle, or of what holds the thing, that stays closed at the start for every instance (a put into
the fridge opens the fridge, one into a dishwasher's rack the dishwasher).
An until-guard ("don't open the fridge until the apple is in the fridge") is judged against the task
that lifts it and the tasks ordered before that one: each must be done while the ban holds, so what
they require, short of the lifting task's own last step (the one that lifts it), contradicts it.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.htt_build import bound_places
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec, transitive_closure
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.constraints import Constraint
from nl2hltl2plan.logic.hierarchical import LeafOrFormula
from nl2hltl2plan.worlds.world import World, sliced_type

# the change of state a task's kind brings its object into, as the plan's events name it
# (`worlds.checker.STATE_EVENTS`, the verbs a negation forbids in `negations.CONSTRAINT_VERBS`)
_KIND_STATE = {"heat_place": "heat", "cool_place": "cool", "clean_place": "clean"}


def refuse_contradictions(
    tasks: Sequence[BaseTaskSpec],
    constraints: Sequence[ConstraintSpec],
    leaf_specs: Mapping[str, LeafOrFormula],
    leaf_task: Mapping[str, str],
    world: World | None,
    before: Sequence[tuple[str, str]] = (),
) -> None:
    """Raise HTTError when a constraint forbids an action or state a task requires while it holds: a
    never-lifted one, any task; an until-guard, the task that lifts it or one ordered before that."""
    by_id = {t.id: t for t in tasks}
    earlier = transitive_closure(list(before))
    for said in constraints:
        ban = Constraint(said.text, tuple(said.forbid))
        lifter = by_id.get(said.until) if said.until is not None else None
        if said.until is not None and lifter is None:
            continue
        judged = [lifter] if lifter else list(tasks)
        judged += [t for t in tasks if lifter and (t.id, lifter.id) in earlier]
        for task in judged:
            lifting = _lifting_steps(task, leaf_specs, leaf_task) if task is lifter else set()
            for needed in _required(task, leaf_specs, leaf_task, world):
                if not set(needed) <= lifting and all(ban.forbids(atom) for atom in needed):
                    raise HTTError(_message(said, needed[0], task, lifter))


def _lifting_steps(
    task: BaseTaskSpec, leaf_specs: Mapping[str, LeafOrFormula], leaf_task: Mapping[str, str]
) -> set[str]:
    """Each leaf's last step: the one that may complete the task, so lift the guard as it happens."""
    leaves = [leaf_specs.get(k) for k, t in leaf_task.items() if t == task.id]
    return {spec[-1] for spec in leaves if isinstance(spec, list) and spec}


def _message(c: ConstraintSpec, atom: str, task: BaseTaskSpec, lifter: BaseTaskSpec | None) -> str:
    what = _named(task)
    if lifter is None:
        return (
            f"the instruction contradicts itself: {c.text!r} forbids {atom}, which the task {what} "
            "requires (say which one holds)"
        )
    needs = "that task requires it" if task is lifter else f"the task {what}, ordered before it, requires it"
    return (
        f"the instruction contradicts itself: {c.text!r} forbids {atom} until the task {_named(lifter)} "
        f"is done, but {needs} (say which one holds)"
    )


def _named(task: BaseTaskSpec) -> str:
    return repr(task.text) if task.text else task.summary()


def _required(
    task: BaseTaskSpec,
    leaf_specs: Mapping[str, LeafOrFormula],
    leaf_task: Mapping[str, str],
    world: World | None,
) -> Iterator[list[str]]:
    """What the task cannot be done without: each a list of atoms, any one of which will do (the
    object's acceptable types)."""
    alternatives = bool(bound_places(task))  # one place's leaves or the other's: no leaf is required
    for leaf in sorted(k for k, t in leaf_task.items() if t == task.id and not alternatives):
        spec = leaf_specs.get(leaf)
        if not isinstance(spec, list):  # a formula leaf: its atoms need not all happen
            continue
        for text in spec:
            yield [text]
            if (opened := _opened(text, world)) is not None:
                yield opened
    if (verb := _KIND_STATE.get(task.kind)) is not None:
        yield [f"{verb}({sliced_type(t) if task.sliced else t})" for t in task.object]


def _opened(text: str, world: World | None) -> list[str] | None:
    """The openings a step needs, any one of which will do: a put into R opens R when R is openable
    and starts closed, or the closed thing R sits in (a dishwasher's rack); a pickup opens what its
    thing sits in. None when some instance needs no opening."""
    atom = Atom.read(text)
    if world is None or atom is None or atom.verb not in ("put", "pickup") or len(atom.args) < 1:
        return None
    into = atom.verb == "put" and len(atom.args) == 2
    found = world.instances(atom.args[1] if into else atom.args[0])
    opened = set()
    for o in found:
        if into and o.affordances.openable and not o.is_open:
            opened.add(o.type)
        elif (shut := world.closed_ancestor(o.id)) is not None:
            opened.add(world.objects[shut].type)
        else:
            return None
    return [f"open({t})" for t in sorted(opened)] or None
