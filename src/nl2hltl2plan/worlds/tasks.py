"""Base tasks (ALFRED's seven kinds), their recipes as leaf action lists, and their goals.

`BaseTask` holds the ground-truth task fields of benchmark/alfred_test50_gt.jsonl. Its recipes are
the leaf specifications a perfect translator would give (`leaf_specs`), shared by the oracle spec
converter (planning) and the offline language stage; its goal (`goal`) is what the checker tests.
The kinds, slots, states and the `Goal` type are the shared vocabulary of `domain.task_kinds`; a
recipe's leaf formula is written by `logic.action_sequences`.

Recipes (O object, C container, R receptacle, L lamp). Leaves carry no opens and no closes: the
planner inserts `open(X)` where the state needs it and closes an open appliance before switching it
on (support actions). With `leaf_specs(..., support=True)`, for a robot that runs recipes
literally, they are written in: `[open(X)]` only when X is openable or
all instances sit in a closed openable, e.g. the demo's dishwasher racks; `acc(O)` = open(P) first
when every instance of O starts inside a closed openable P:
- place:              acc(O), pickup(O), [open(R)], put(O,R)
- place_two:          two such leaves (two distinct objects)
- place_in_container: acc(O), pickup(O), [open(C)], put(O,C), pickup(C), [open(R)], put(C,R)
- examine_in_light:   acc(O), pickup(O), toggle_on(L)
- clean_place:        acc(O), pickup(O), put(O,SinkBasin), toggle_on(Faucet), toggle_off(Faucet),
                      pickup(O), [open(R)], put(O,R)
- heat_place:         acc(O), pickup(O), open(Microwave), put(O,Microwave), close(Microwave),
                      toggle_on(Microwave), toggle_off(Microwave), open(Microwave), pickup(O),
                      [open(R)], put(O,R)        (the microwave must be closed to run; its
                      close, like the opens, is a support action: written only with support=True)
- cool_place:         acc(O), pickup(O), open(Fridge), put(O,Fridge), pickup(O), [open(R)], put(O,R)
- set_state:          the one action; a slice: pickup(K), slice(O), put(K,KR); a toast: `_state_recipe`
When R is the appliance itself (chilled tomato in the fridge), the recipe stops once the object is in
it and treated. Sliced objects: pickup(K), slice(O), put(K,KR), then the recipe on OSliced starting
at its pickup (K = Knife if the world has one, else ButterKnife; KR = the first of CounterTop,
DiningTable, SideTable, ... that accepts K). place_two on slices slices once (one object gives
several slices): the second leaf only picks and places a slice.
Where several type choices remain (object ["Cup", "Mug"]), the leaf is a flat sc-LTL formula: a
disjunction of the sequences, sharing common prefixes, with each choice bound consistently
(`F("pickup(Mug)" & F "put(Mug,CoffeeMachine)") | ...`). Type lists are first restricted to types
present (and reachable) in the world, and to combinations the receptacles accept.
"""

from __future__ import annotations

import itertools
from collections import Counter
from collections.abc import Sequence

from pydantic import BaseModel, ConfigDict, Field

from nl2hltl2plan.domain.task_kinds import (
    APPLIANCE,
    MAX_COUNT,
    STATE_FLAG,
    STATE_WORDS,
    TREATED_VERB,
    TREATMENT,
    Goal,
    Kind,
    State,
    camel_words,
)
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.logic.action_sequences import sequences_formula
from nl2hltl2plan.worlds.world import KNIFE_TYPES, World, sliced_type

KNIFE_DROP_PREFERENCE = ("CounterTop", "DiningTable", "SideTable", "Desk", "CoffeeTable", "Shelf", "Dresser")


class BaseTask(BaseModel):
    """One base task: what the ground truth (alfred_test50_gt.jsonl, see ANNOTATION_GUIDE.md) and the
    language stage both describe — the kind of task, the acceptable AI2-THOR types of the object, the
    container, the destination and the lamp, how many objects, and whether they must be slices."""

    model_config = ConfigDict(extra="ignore")

    id: str = "A"
    text: str = ""
    kind: Kind
    object: list[str]
    count: int = Field(default=1, ge=1, le=MAX_COUNT)  # objects; more than a scene can hold is refused
    sliced: bool = False
    container: list[str] | None = None
    receptacle: list[str] | None = None
    light: list[str] | None = None
    state: State | None = None  # the state a set_state task brings its object into
    # "in the fridge or the microwave": the places the user allowed either of, as said (each its types);
    # `receptacle` holds those the world can take, and the leaf's disjunction lets the planner pick
    places: list[list[str]] | None = Field(default=None, exclude_if=lambda v: v is None)

    def summary(self) -> str:
        """One readable line, e.g. `clean_place Potato(sliced) -> Fridge`."""
        obj = "|".join(self.object) + ("(sliced)" if self.sliced else "")
        if self.count > 1:
            obj = f"{self.count}x {obj}"
        if self.kind == "set_state":
            return f"{self.kind} {obj} {self.state}"
        if self.kind == "examine_in_light":
            return f"{self.kind} {obj} under {'|'.join(self.light or ['?'])}"
        inner = f" in {'|'.join(self.container)}" if self.container else ""
        return f"{self.kind} {obj}{inner} -> {'|'.join(self.receptacle or ['?'])}"

    # ------------------------------------------------------------ goal
    def goal(self) -> Goal:
        objs = [sliced_type(t) for t in self.object] if self.sliced else list(self.object)
        return Goal(
            task=self.id,
            kind=self.kind,
            objects=frozenset(objs),
            containers=frozenset(self.container or ()),
            receptacles=frozenset(self.receptacle or ()),
            lights=frozenset(self.light or ()),
            count=max(1, self.count),
        )

    # ------------------------------------------------------------ what the world lacks
    def missing(self, world: World) -> list[str]:
        """Readable reasons the world cannot provide this task (empty: it can), GT `issues` style."""
        issues: list[str] = []
        roles: list[list[str]] = [self.object]
        if self.kind == "set_state":
            return self._state_missing(world)
        if why := self.unmovable(world):  # before the appliance's lack: "no Faucet" is not why
            return [f"{self.id}: {why}"]
        if self.kind == "place_in_container":
            roles.append(self.container or [])
        if self.kind != "examine_in_light":
            roles.append(self.receptacle or [])
        else:
            roles.append(self.light or [])
        if not self.receptacle and self.kind not in APPLIANCE and self.kind != "examine_in_light":
            issues.append(f"{self.id}: the task names no receptacle")
        if not self.light and self.kind == "examine_in_light":
            issues.append(f"{self.id}: the task names no lamp")
        if self.kind == "place_in_container" and not self.container:
            issues.append(f"{self.id}: the task names no container")
        if self.kind in APPLIANCE:
            roles.append([APPLIANCE[self.kind]])
            if self.kind == "clean_place":
                roles.append(["Faucet"])
        if self.sliced:
            roles.append(list(KNIFE_TYPES))
        for types in roles:
            why = _lack(world, types)
            if why:
                issues.append(f"{self.id}: {why}")
        if issues:
            return issues
        if self.sliced and not any(
            world.instances(t)[0].affordances.sliceable for t in _available(world, self.object)
        ):
            return [f"{self.id}: {' or '.join(self.object)} cannot be sliced"]
        if not self._bindings(world):
            return [f"{self.id}: {self._no_binding_reason(world)}"]
        return []

    def unmovable(self, world: World) -> str | None:
        """Why no task of this kind can pick up its object where the world has it only as fixtures ("a toilet
        cannot be picked up, so no task can wash it; things there to wash: cloth, soap bar"); None if one can
        be picked up, or the world lacks the type (`missing` names that). `set_state` acts in place (switch,
        open, break), but for a state that holds the thing ("take a bath": the BathtubBasin held)."""
        there = [o for ty in self.object for o in world.instances(ty) if o.present]
        in_place = self.kind == "set_state" and self.state != "held"
        if in_place or not there or any(o.affordances.pickupable for o in there):
            return None
        verb = "hold" if self.kind == "set_state" else TREATED_VERB.get(self.kind, "move")
        flag = TREATMENT.get(self.kind)
        able = sorted({o.type for o in world.objects.values() if o.present and o.affordances.pickupable
                       and (not flag or getattr(o.affordances, flag))})  # fmt: skip
        can = f"; things there to {verb}: {', '.join(camel_words(a) for a in able[:4])}" if able else ""
        return f"a {camel_words(there[0].type)} cannot be picked up, so no task can {verb} it{can}"

    def _state_missing(self, world: World) -> list[str]:
        knife, toaster = self.state == "sliced" or self.sliced, self.state == "toasted"
        why = _lack(world, self.object) or (_lack(world, list(KNIFE_TYPES)) if knife else None) or (
            _lack(world, ["Toaster"]) if toaster else None)
        if why:
            return [f"{self.id}: {why}"]
        if not self._bindings(world):
            done = STATE_WORDS.get(self.state or "", str(self.state))
            done += " (a slice of it can: 'toast a slice of ...')" if toaster and not self.sliced else ""
            return [f"{self.id}: no {' or '.join(sorted(self.goal().objects))} in {world.name} can be {done}"]
        return []

    # ------------------------------------------------------------ recipes
    def leaf_specs(
        self,
        world: World,
        others: Sequence[BaseTask] = (),
        support: bool = False,
        demand: Counter[str] | None = None,
    ) -> list[list[str] | str]:
        """One entry per leaf: an ordered action list, or a flat sc-LTL formula for choices.

        Leaves carry no `open(...)`: the planner opens what is in the way (support actions).
        `support=True` writes the opens into the recipe (a robot that runs recipes literally):
        `others` are the other tasks of the same instruction; they compete for objects, and when
        fewer instances of a type are free to take (not inside a closed openable) than all the
        tasks need, the recipe also offers "open the drawer/cabinet/safe holding one first".
        """
        issues = self.missing(world)
        if issues:
            raise WorldError(f"task {self.id} cannot be done in {world.name}: {'; '.join(issues)}")
        if demand is None:  # callers with many tasks pass `demand_of(all tasks)`, computed once
            demand = demand_of([self, *[t for t in others if t.id != self.id]])
        bindings = self._bindings(world)
        n_leaves = max(1, self.count)  # place_two, and "heat a couple of slices" (count 2)
        leaves: list[list[str] | str] = []
        for leaf in range(n_leaves):
            seqs: list[list[str]] = []
            for b in bindings:
                for seq in self._recipe(world, b, demand, slice_here=(leaf == 0), support=support):
                    if seq not in seqs:
                        seqs.append(seq)
            leaves.append(seqs[0] if len(seqs) == 1 else sequences_formula(seqs))
        return leaves

    def _bindings(self, world: World) -> list[dict[str, str]]:
        """Type choices (O, C, R, L) available in the world whose receptacles accept what they get."""
        objs = _available(world, self.object)
        if self.kind == "set_state":
            took = {o: sliced_type(o) if self.sliced else o for o in objs}
            return [{"O": o, "held": took[o]} for o in objs if can_take_state(world, took[o], self.state)]
        if self.sliced:
            objs = [o for o in objs if world.instances(o)[0].affordances.sliceable]
            if sliced_type_missing := [o for o in objs if not world.instances(sliced_type(o))]:
                objs = [o for o in objs if o not in sliced_type_missing]
        conts = _available(world, self.container or []) if self.kind == "place_in_container" else [None]
        # clean/heat/cool with no destination: the treated state is the whole goal
        recs = _available(world, self.receptacle or []) if self.receptacle else [None]
        lights = _available(world, self.light or []) if self.kind == "examine_in_light" else [None]
        out = []
        for o, c, r, lamp in itertools.product(objs, conts, recs, lights):
            held = sliced_type(o) if self.sliced else o
            if c is not None and not (_accepts(world, c, held) and _accepts(world, r, c)):
                continue
            if c is None and r is not None and not _accepts(world, r, held):
                continue
            if self.kind in APPLIANCE:
                app = APPLIANCE[self.kind]
                if not _accepts(world, app, held):
                    continue
                if not getattr(world.instances(held)[0].affordances, TREATMENT[self.kind]):
                    continue
            b = {"O": o, "held": held}
            if c:
                b["C"] = c
            if r:
                b["R"] = r
            if lamp:
                b["L"] = lamp
            out.append(b)
        return out

    def _no_binding_reason(self, world: World) -> str:
        objs = _available(world, self.object)
        held = [sliced_type(o) if self.sliced else o for o in objs]
        if self.kind in APPLIANCE:
            app = APPLIANCE[self.kind]
            flag = TREATMENT[self.kind]
            if not any(
                _accepts(world, app, h) and getattr(world.instances(h)[0].affordances, flag) for h in held
            ):
                return f"{' or '.join(held)} cannot be {flag[:-4]}ed in the {app}"
        if self.kind == "place_in_container":
            conts = _available(world, self.container or [])
            if not any(_accepts(world, c, h) for c in conts for h in held):
                return _refusal(world, conts, held)
            held = [c for c in conts if any(_accepts(world, c, h) for h in held)]
        return _refusal(world, _available(world, self.receptacle or []), held)

    def _recipe(
        self, world: World, b: dict[str, str], demand: Counter[str], slice_here: bool = True,
        support: bool = False,
    ) -> list[list[str]]:
        """The action sequences for one type binding (several when an `open` is optional)."""
        o, held = b["O"], b["held"]
        parts: list[list[list[str]]] = []  # each part: alternatives, each a list of atoms

        def add(*atoms: str) -> None:
            parts.append([list(atoms)])

        def opens(alternatives: list[list[str]]) -> None:
            if support:
                parts.append(alternatives)

        closes = opens  # support actions too: written only for a robot that runs recipes literally

        def put_into(obj: str, rec: str | None) -> None:
            opens(_open_for_put(world, rec, demand))
            add(f"put({obj},{rec})")

        if self.kind == "set_state":
            return [self._state_recipe(world, o, held)]
        if self.sliced and slice_here:
            knife = next(k for k in KNIFE_TYPES if _available(world, [k]))
            opens(_access(world, knife, 1))
            add(f"pickup({knife})")
            opens(_access(world, o, demand[o]))
            add(f"slice({o})")
            put_into(knife, _knife_drop(world, knife))
        if not self.sliced:
            opens(_access(world, o, demand[o]))
        add(f"pickup({held})")
        kind = self.kind
        r = b.get("R")
        if kind in ("place", "place_two"):
            put_into(held, r)
        elif kind == "place_in_container":
            c = b["C"]
            put_into(held, c)
            add(f"pickup({c})")
            put_into(c, r)
        elif kind == "examine_in_light":
            add(f"toggle_on({b['L']})")
        elif kind == "clean_place":
            add(f"put({held},SinkBasin)", "toggle_on(Faucet)", "toggle_off(Faucet)")
            if r not in (None, "SinkBasin"):
                add(f"pickup({held})")
                put_into(held, r)
        elif kind == "heat_place":
            opens([["open(Microwave)"]])
            add(f"put({held},Microwave)")
            closes([["close(Microwave)"]])  # it runs only closed: the planner closes it when it is open
            add("toggle_on(Microwave)", "toggle_off(Microwave)")
            if r not in (None, "Microwave"):
                opens([["open(Microwave)"]])
                add(f"pickup({held})")
                put_into(held, r)
        elif kind == "cool_place":
            opens([["open(Fridge)"]])
            add(f"put({held},Fridge)")
            if r not in (None, "Fridge"):
                add(f"pickup({held})")
                put_into(held, r)
        return [[a for alt in combo for a in alt] for combo in itertools.product(*parts)]

    def _state_recipe(self, world: World, o: str, held: str) -> list[str]:
        """The actions that bring an object of type o (its slice `held`) into the task's state."""
        knife = next((k for k in KNIFE_TYPES if _available(world, [k])), KNIFE_TYPES[0])
        cut = [f"pickup({knife})", f"slice({o})", f"put({knife},{_knife_drop(world, knife)})"]
        if self.state == "sliced":
            return cut
        if self.state == "toasted":  # the knife is left to the planner (a slicer may lack PutObject)
            into = [f"pickup({held})", f"put({held},Toaster)", "toggle_on(Toaster)"]
            return (cut[:2] if self.sliced else []) + into
        verb = {
            "on": "toggle_on",
            "off": "toggle_off",
            "broken": "break",
            "open": "open",
            "closed": "close",
            "held": "pickup",
        }[self.state or "held"]
        return [f"{verb}({o})"]


def can_take_state(world: World, o: str, state: str | None) -> bool:
    """Whether objects of type o can take the state (AI2-THOR's affordances; a toaster cooks Cookables)."""
    from nl2hltl2plan.worlds.effects import BREAKABLE, COOKABLE

    if state == "broken":
        return o in BREAKABLE
    if state == "toasted":
        return o in COOKABLE and bool(world.instances(o)) and _accepts(world, "Toaster", o)
    flag = STATE_FLAG.get(state or "")
    return flag is not None and bool(getattr(world.instances(o)[0].affordances, flag))


class GTInstance(BaseModel):
    """One line of benchmark/alfred_test50_gt.jsonl."""

    model_config = ConfigDict(extra="ignore")

    id: str
    scene: str
    n_base: int = 0
    instruction: str = ""
    tasks: list[BaseTask]
    before: list[tuple[str, str]] = []
    feasible: bool = True
    issues: list[str] = []
    ambiguous: bool = False
    notes: list[str] = []
    source_trials: list[str] = []
    init_pos: list[list[list[float]]] = Field(default_factory=list)

    def task(self, task_id: str) -> BaseTask:
        for t in self.tasks:
            if t.id == task_id:
                return t
        raise WorldError(f"{self.id} has no task {task_id!r}")


# ---------------------------------------------------------------- helpers
def _reachable_instances(world: World, type_: str) -> list:
    return [o for o in world.instances(type_) if o.interaction_cells]


def _available(world: World, types: list[str]) -> list[str]:
    """The listed types the world has reachable instances of (order kept)."""
    return [t for t in types if _reachable_instances(world, t)]


def _lack(world: World, types: list[str]) -> str | None:
    if not types:
        return None
    if _available(world, types):
        return None
    name = " or ".join(types)
    if any(world.instances(t) for t in types):
        return f"{name} is out of reach in {world.name}"
    unplaced = [t for t in types if t in world.unplaced]
    if unplaced:
        return f"{' or '.join(unplaced)} is in {world.name} but the data gives no position for it"
    return f"no {name} in {world.name}"


def _refusal(world: World, targets: list[str], held: list[str]) -> str:
    not_recep = [t for t in targets if not world.instances(t)[0].affordances.receptacle]
    if not_recep and len(not_recep) == len(targets):
        return f"{' or '.join(not_recep)} is not a receptacle"
    return f"{' or '.join(t for t in targets if t not in not_recep)} does not accept {' or '.join(held)}"


def _accepts(world: World, receptacle: str | None, type_: str) -> bool:
    if receptacle is None:
        return False
    insts = world.instances(receptacle)
    return bool(insts) and type_ in insts[0].affordances.accepts


def demand_of(tasks: Sequence[BaseTask]) -> Counter[str]:
    """How many instances of each type the tasks take (object x count, container); knives are shared."""
    need: Counter[str] = Counter()
    for t in tasks:
        for typ in t.object:
            need[typ] += max(1, t.count)
        for typ in t.container or []:
            need[typ] += 1
    return need


def _access(world: World, type_: str, demand: int = 1) -> list[list[str]]:
    """Alternatives to do before taking an instance of `type_`: [[]] (nothing), [["open(P)"]] when
    every instance starts inside a closed openable P, or [[], ["open(P)"]] when fewer instances than
    `demand` are free to take (one alternative per holder type, the most common first)."""
    src = [o for o in world.instances(type_) if o.interaction_cells and o.present]
    closed = [world.closed_ancestor(o.id) for o in src]
    holders = Counter(world.objects[c].type for c in closed if c)
    if not holders:
        return [[]]
    openers = [[f"open({t})"] for t in sorted(holders, key=lambda t: (-holders[t], t))]
    free = sum(1 for c in closed if c is None)
    if free == 0:
        return openers
    if free < demand:
        return [[], *openers]
    return [[]]


def _open_for_put(world: World, type_: str | None, demand: Counter[str] | None = None) -> list[list[str]]:
    """open(R) for an openable receptacle type, or its closed openable holder (dishwasher racks, a
    cup in a cabinet used as a container)."""
    if type_ is None:
        return [[]]
    insts = world.instances(type_)
    if insts and insts[0].affordances.openable:
        return [[f"open({type_})"]]
    return _access(world, type_, (demand or Counter())[type_] or 1)


def _knife_drop(world: World, knife: str) -> str:
    """Where a recipe puts the knife down after slicing: a nearby-kind surface that accepts it."""
    for t in KNIFE_DROP_PREFERENCE:
        if _available(world, [t]) and _accepts(world, t, knife):
            return t
    for t in sorted(world.types_accepting(knife)):
        if _available(world, [t]) and not world.instances(t)[0].affordances.pickupable:
            return t
    raise WorldError(f"no receptacle in {world.name} accepts a {knife}")
