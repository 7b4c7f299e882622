"""Lock-step multi-robot executor: runs a `Plan` in a `World`, applies effects, records everything.

Semantics (docs/worlds.md has the full table):
- time t = 1..T; at each t every robot with a step at t does it; robots are applied in increasing
  robot index, so robot 0's effect at t is visible to robot 1 at the same t. A robot with no step at t
  waits. Robots may share cells (no inter-robot collisions, as in the paper's planner).
- a failed step (violated precondition) has no effect, is recorded with a readable reason, and the
  run goes on; `Execution.ok` is False when any step failed.
- open/close/toggle on an object already in that state succeed without effect, so that independent
  leaf tasks may each `open(Fridge)` (AI2-THOR would report a failed action; nothing changes).
- state effects: an object put into a Fridge becomes cold; toggling a Microwave on (it must be
  closed) heats what is inside; toggling a Faucet on cleans what is in its SinkBasin, and an object
  put into a SinkBasin whose faucet runs becomes clean. Effects reach the contents of containers (a
  mug in a bowl in the fridge gets cold) and apply only to types that afford them. As in ALFRED's
  success checks (its env keeps sets of heated / cooled / cleaned objects), the flags mean "has been
  heated / cooled / cleaned" and are never cleared: a heated apple put into the fridge stays hot.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

from nl2hltl2plan.domain.object_state import CLEAN, COLD, FLAG_NAMES, HOT, ON, OPEN, PRESENT
from nl2hltl2plan.worlds import effects
from nl2hltl2plan.worlds.plan import Plan
from nl2hltl2plan.worlds.world import CELL_M, KNIFE_TYPES, Cell, World

COOLING_TYPES = frozenset({"Fridge"})  # put into it -> cold
HEATING_TYPES = frozenset({"Microwave"})  # toggle on -> contents hot
WASHING_TYPES = frozenset({"SinkBasin"})  # contents clean while its Faucet runs


class Event(NamedTuple):
    """A successful action: (t, robot, atom, task, objects)."""

    t: int
    robot: int
    atom: str
    task: str | None
    objects: tuple[str, ...]


@dataclass(frozen=True)
class Violation:
    t: int
    robot: int
    verb: str
    objects: tuple[str, ...]
    reason: str

    def __str__(self) -> str:
        what = f"{self.verb}({','.join(self.objects)})" if self.objects else self.verb
        return f"t={self.t} robot {self.robot}: {what}: {self.reason}"


@dataclass(frozen=True)
class Snapshot:
    """Object states after step t (indexed like `world.ids`); holder/parent -1 = none."""

    t: int
    parent: tuple[int, ...]
    holder: tuple[int, ...]
    flags: tuple[int, ...]

    def has(self, i: int, flag: int) -> bool:
        return bool(self.flags[i] & flag)


@dataclass
class Execution:
    world: World
    plan: Plan
    violation_list: list[Violation]
    travel_m: float
    steps: int  # completion time: last step (other than wait) of any robot
    events: list[Event]
    state_history: list[Snapshot]  # t=0 first, then one snapshot per step at which a state changed
    trajectories: dict[int, list[Cell]]  # robot -> cell at t = 0..horizon
    cells_moved: dict[int, int] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return not self.violation_list

    @property
    def violations(self) -> list[str]:
        return [str(v) for v in self.violation_list]

    @property
    def final(self) -> Snapshot:
        return self.state_history[-1]

    def state_at(self, t: int) -> Snapshot:
        """Object states after step t."""
        best = self.state_history[0]
        for snap in self.state_history:
            if snap.t > t:
                break
            best = snap
        return best

    def first_time(self, oid: str, flag: str | None = None, inside: str | None = None) -> int | None:
        """First step after which object `oid` has `flag` ("open", "on", "clean", "hot", "cold",
        "held") and/or sits directly in `inside`; 0 if it already did at the start; None if never."""
        idx = self.world.index
        i = idx[oid]
        bit = {n: b for b, n in FLAG_NAMES.items()}.get(flag or "", 0)
        if flag and flag != "held" and not bit:
            raise ValueError(
                f"unknown state {flag!r}; expected one of {', '.join(FLAG_NAMES.values())}, held"
            )
        parent = idx[inside] if inside else -1
        for snap in self.state_history:
            if flag == "held" and snap.holder[i] < 0:
                continue
            if bit and not snap.flags[i] & bit:
                continue
            if inside and snap.parent[i] != parent:
                continue
            return snap.t
        return None

    def describe(self, snap: Snapshot | None = None) -> dict[str, dict]:
        """Readable states of present objects: {id: {"in": parent, "held_by": r, "flags": [...]}}."""
        snap = snap or self.final
        ids = self.world.ids
        out = {}
        for i, oid in enumerate(ids):
            if not snap.flags[i] & PRESENT:
                continue
            out[oid] = {
                "in": ids[snap.parent[i]] if snap.parent[i] >= 0 else None,
                "held_by": snap.holder[i] if snap.holder[i] >= 0 else None,
                "flags": [n for b, n in FLAG_NAMES.items() if b != PRESENT and snap.flags[i] & b],
            }
        return out

    def to_dict(self) -> dict:
        return {
            "world": self.world.name,
            "ok": self.ok,
            "violations": self.violations,
            "travel_m": self.travel_m,
            "steps": self.steps,
            "cells_moved": {str(k): v for k, v in self.cells_moved.items()},
            "events": [
                {"t": e.t, "robot": e.robot, "atom": e.atom, "task": e.task, "objects": list(e.objects)}
                for e in self.events
            ],
        }


class _Compiled:
    """Per-world arrays the executor reads (built once per world)."""

    def __init__(self, world: World) -> None:
        objs = list(world.objects.values())
        idx = world.index
        self.ids = world.ids
        self.index = idx
        self.types = [o.type for o in objs]
        self.aff = [o.affordances for o in objs]
        self.region = [o.interaction_cells for o in objs]
        self.region_set = [frozenset(o.interaction_cells) for o in objs]
        self.parent0 = [idx[o.parent] if o.parent in idx else -1 for o in objs]
        self.flags0 = [
            (PRESENT if o.present else 0) | (OPEN if o.is_open else 0) | (ON if o.is_on else 0) for o in objs
        ]
        self.slices = [[idx[s] for s in o.slices] for o in objs]
        self.faucets_of: dict[int, list[int]] = {}
        for i, o in enumerate(objs):
            if o.serves in idx:
                self.faucets_of.setdefault(idx[o.serves], []).append(i)
        self.serves = [idx.get(o.serves, -1) if o.serves else -1 for o in objs]
        self.free = world.cell_set


def _compiled(world: World) -> _Compiled:
    comp = world.__dict__.get("_sim_compiled")
    if comp is None:
        comp = _Compiled(world)
        world.__dict__["_sim_compiled"] = comp
    return comp


class SimState:
    """Mutable state of one execution; also usable step by step (planners, scripted plans).

    `act(robot, verb, ids)` applies one action (the robot must be placed with `place_robot` first)
    and returns the reason it fails, or None; `region(id)` is where a robot must stand now to act on
    an object (its own region until it is moved, then that of the receptacle it is in).
    """

    def __init__(self, world: World, comp: _Compiled | None = None) -> None:
        comp = comp or _compiled(world)
        self.w = world
        self.c = comp
        self.parent = list(comp.parent0)
        self.holder = [-1] * len(comp.ids)
        self.flags = list(comp.flags0)
        self.moved = [False] * len(comp.ids)
        self.hand: dict[int, int] = {}
        self.pos: dict[int, Cell] = {}

    def copy(self) -> SimState:
        new = SimState.__new__(SimState)
        new.w, new.c = self.w, self.c
        new.parent, new.holder, new.flags = list(self.parent), list(self.holder), list(self.flags)
        new.moved, new.hand, new.pos = list(self.moved), dict(self.hand), dict(self.pos)
        return new

    def place_robot(self, robot: int, cell: Cell) -> None:
        self.pos[robot] = tuple(cell)  # type: ignore[assignment]
        self.hand.setdefault(robot, -1)

    def apply(self, robot: int, verb: str, ids: list[str]) -> str | None:
        """`act` by object ids: the reason the action fails, or None when applied."""
        missing = [o for o in ids if o not in self.c.index]
        if missing:
            return f"no object {', '.join(missing)} in {self.w.name}"
        return self.act(robot, verb, [self.c.index[o] for o in ids])

    def held_by(self, robot: int) -> str | None:
        h = self.hand.get(robot, -1)
        return self.c.ids[h] if h >= 0 else None

    def region(self, oid: str) -> tuple[Cell, ...]:
        """Cells from which an object can be acted on now (empty when it is held or gone)."""
        x = self.c.index[oid]
        while x >= 0:
            if self.holder[x] >= 0:
                return ()
            if not self.moved[x] or self.parent[x] < 0:
                return self.c.region[x]
            x = self.parent[x]
        return ()

    def snapshot(self, t: int = 0) -> Snapshot:
        return Snapshot(t, tuple(self.parent), tuple(self.holder), tuple(self.flags))

    # ------------------------------------------------------------ helpers
    def name(self, i: int) -> str:
        return self.c.ids[i]

    def subtree(self, root: int) -> list[int]:
        """`root` and everything inside it, breadth first, children in index order (the scans for
        children are `list.index` calls, which run in C: one per child, plus one)."""
        parent = self.parent
        out = [root]
        k = 0
        while k < len(out):
            p = out[k]
            i = -1
            try:
                while True:
                    i = parent.index(p, i + 1)
                    out.append(i)
            except ValueError:
                pass
            k += 1
        return out

    def reach_problem(self, robot: int, o: int) -> str | None:
        """Why the robot cannot act on object o from where it stands (None: it can)."""
        if not self.flags[o] & PRESENT:
            src = self.w.objects[self.name(o)]
            if src.slice_of:
                return f"{self.name(o)} does not exist yet (slice {src.slice_of} first)"
            return f"{self.name(o)} no longer exists (it was sliced)"
        region = None
        x = o
        while x >= 0:
            h = self.holder[x]
            if x == o:
                if h >= 0:
                    return f"{self.name(o)} is held by robot {h}"
            else:
                if h >= 0:
                    return f"{self.name(o)} is inside {self.name(x)}, which robot {h} holds"
                if self.c.aff[x].openable and not self.flags[x] & OPEN:
                    return f"{self.name(o)} is inside {self.name(x)}, which is closed (open it first)"
            if region is None and (not self.moved[x] or self.parent[x] < 0):
                region = x
            x = self.parent[x]
        if region is None:
            region = o
        cell = self.pos[robot]
        if cell not in self.c.region_set[region]:
            cells = self.c.region[region]
            if not cells:
                return f"no free cell is within 1.5 m of {self.name(region)}: nobody can reach it"
            where = self.name(o) if region == o else f"{self.name(o)} (at {self.name(region)})"
            return f"robot {robot} at cell {cell} is out of reach of {where}; stand e.g. at cell {cells[0]}"
        return None

    def set_flag_tree(self, root: int, flag: int, afford: str) -> None:
        for i in self.subtree(root):
            if getattr(self.c.aff[i], afford):
                self.flags[i] |= flag

    def in_type(self, o: int, types: frozenset[str]) -> int:
        """The nearest container of o (o itself excluded) whose type is in `types`, else -1."""
        x = self.parent[o]
        while x >= 0:
            if self.c.types[x] in types:
                return x
            x = self.parent[x]
        return -1

    # ------------------------------------------------------------ actions
    def act(self, robot: int, verb: str, objs: list[int]) -> str | None:
        """Apply one action; return the reason it fails (nothing changes then)."""
        handler = {
            "pickup": self._pickup,
            "put": self._put,
            "open": self._open_close,
            "close": self._open_close,
            "toggle_on": self._toggle,
            "toggle_off": self._toggle,
            "slice": self._slice,
        }.get(verb)
        if handler is None:
            return effects.act(self, robot, verb, objs)  # break (SMART-LLM's vocabulary)
        return handler(robot, verb, objs)

    def _pickup(self, robot: int, verb: str, objs: list[int]) -> str | None:
        """pickup(O): hand empty, O pickupable and in reach; O's contents travel with it."""
        c = self.c
        hand = self.hand.get(robot, -1)
        (o,) = objs
        if hand >= 0:
            return f"robot {robot} already holds {self.name(hand)} (one object in hand)"
        if not c.aff[o].pickupable:
            return f"{self.name(o)} ({c.types[o]}) cannot be picked up"
        why = self.reach_problem(robot, o)
        if why:
            return why
        self.holder[o] = robot
        self.parent[o] = -1
        for i in self.subtree(o):  # contents travel with their container
            self.moved[i] = True
        self.hand[robot] = o
        return None

    def _put(self, robot: int, verb: str, objs: list[int]) -> str | None:
        """put(O,R): holding O, R accepts it, in reach and open; cooling and washing on arrival."""
        c = self.c
        hand = self.hand.get(robot, -1)
        o, r = objs
        if hand != o:
            held = self.name(hand) if hand >= 0 else "nothing"
            return f"robot {robot} does not hold {self.name(o)} (it holds {held})"
        if r == o:
            return f"cannot put {self.name(o)} into itself"
        if not c.aff[r].receptacle:
            return f"{self.name(r)} ({c.types[r]}) is not a receptacle"
        if c.types[o] not in c.aff[r].accepts:
            return f"{c.types[r]} does not accept {c.types[o]}"
        why = self.reach_problem(robot, r)
        if why:
            return why
        if c.aff[r].openable and not self.flags[r] & OPEN:
            return f"{self.name(r)} is closed (open it first)"
        self.holder[o] = -1
        self.parent[o] = r
        self.hand[robot] = -1
        # in_type starts at o's new parent r, so r itself counts
        if self.in_type(o, COOLING_TYPES) >= 0:
            self.set_flag_tree(o, COLD, "coolable")
        sink = self.in_type(o, WASHING_TYPES)
        if sink >= 0 and any(self.flags[f] & ON for f in c.faucets_of.get(sink, ())):
            self.set_flag_tree(o, CLEAN, "cleanable")
        effects.after_put(self, o, r)
        return None

    def _open_close(self, robot: int, verb: str, objs: list[int]) -> str | None:
        """open(O) / close(O) of an openable in reach (an appliance that runs closed must be off)."""
        c = self.c
        (o,) = objs
        if not c.aff[o].openable:
            return f"{self.name(o)} ({c.types[o]}) cannot be opened or closed"
        why = self.reach_problem(robot, o)
        if why:
            return why
        if verb == "open":
            if self.flags[o] & ON and c.types[o] in effects.RUNS_CLOSED:
                return f"{self.name(o)} is on (turn it off first)"
            self.flags[o] |= OPEN
        else:
            self.flags[o] &= ~OPEN
        return None

    def _toggle(self, robot: int, verb: str, objs: list[int]) -> str | None:
        """toggle_on / toggle_off: heating, washing and the SMART-LLM effects of switching on."""
        c = self.c
        (o,) = objs
        if not c.aff[o].toggleable:
            return f"{self.name(o)} ({c.types[o]}) cannot be switched on or off"
        why = self.reach_problem(robot, o)
        if why:
            return why
        if verb == "toggle_off":
            self.flags[o] &= ~ON
            return None
        if c.types[o] in effects.RUNS_CLOSED and self.flags[o] & OPEN:
            return f"{self.name(o)} is open (close it before turning it on)"
        self.flags[o] |= ON
        if c.types[o] in HEATING_TYPES:
            for i in self.subtree(o)[1:]:
                if c.aff[i].heatable:
                    self.flags[i] |= HOT
        sink = c.serves[o]
        if sink >= 0:
            for i in self.subtree(sink)[1:]:
                if c.aff[i].cleanable:
                    self.flags[i] |= CLEAN
        effects.after_toggle_on(self, o)
        return None

    def _slice(self, robot: int, verb: str, objs: list[int]) -> str | None:
        """slice(O) while holding a knife: O is replaced by its slices, which keep its state."""
        c = self.c
        hand = self.hand.get(robot, -1)
        (o,) = objs
        if hand < 0 or c.types[hand] not in KNIFE_TYPES:
            return f"robot {robot} must hold a Knife or ButterKnife to slice"
        if not c.aff[o].sliceable:
            return f"{self.name(o)} ({c.types[o]}) cannot be sliced"
        why = self.reach_problem(robot, o)
        if why:
            return why
        keep = self.flags[o] & (CLEAN | HOT | COLD)
        self.flags[o] &= ~PRESENT
        for s in c.slices[o]:
            self.flags[s] |= PRESENT | keep
            self.parent[s] = self.parent[o]
            self.moved[s] = self.moved[o]
        return None


def execute(world: World, plan: Plan) -> Execution:
    """Run the plan in lock step; see the module docstring for the semantics."""
    comp = _compiled(world)
    run = SimState(world, comp)
    violations: list[Violation] = []
    order = sorted(plan.robots, key=lambda r: r.robot)
    for rp in order:
        start = tuple(rp.start)
        if start not in comp.free:
            violations.append(Violation(0, rp.robot, "start", (), f"start cell {start} is not a free cell"))
        run.place_robot(rp.robot, start)  # type: ignore[arg-type]
    horizon = plan.horizon
    moves: dict[int, list[tuple[int, Cell]]] = {rp.robot: [] for rp in order}
    cells_moved = {rp.robot: 0 for rp in order}
    steps = sorted(((s.t, rp.robot, s) for rp in order for s in rp.steps), key=lambda x: (x[0], x[1]))
    events: list[Event] = []
    history = [run.snapshot(0)]
    last_active = 0
    index = comp.index
    k = 0
    while k < len(steps):
        t = steps[k][0]
        changed = False
        while k < len(steps) and steps[k][0] == t:
            _, robot, step = steps[k]
            k += 1
            verb = step.verb
            if verb == "wait":
                continue
            last_active = t
            if verb == "move":
                cell = tuple(step.cell)  # type: ignore[arg-type]
                cur = run.pos[robot]
                if cell not in comp.free:
                    why = f"cell {cell} is not a free cell"
                elif abs(cell[0] - cur[0]) + abs(cell[1] - cur[1]) != 1:
                    why = f"cell {cell} is not a 4-neighbour of the robot's cell {cur}"
                else:
                    run.pos[robot] = cell  # type: ignore[assignment]
                    moves[robot].append((t, cell))  # type: ignore[arg-type]
                    cells_moved[robot] += 1
                    continue
                violations.append(Violation(t, robot, "move", (), why))
                continue
            unknown = [o for o in step.objects if o not in index]
            if unknown:
                why = f"no object {', '.join(unknown)} in {world.name}"
                violations.append(Violation(t, robot, verb, tuple(step.objects), why))
                continue
            objs = [index[o] for o in step.objects]
            failed = run.act(robot, verb, objs)
            if failed:
                violations.append(Violation(t, robot, verb, tuple(step.objects), failed))
                continue
            changed = True
            atom = f"{verb}({','.join(comp.types[i] for i in objs)})"
            events.append(Event(t, robot, atom, step.task, tuple(step.objects)))
        if changed:
            history.append(run.snapshot(t))
    trajectories: dict[int, list[Cell]] = {}
    for rp in order:
        here: Cell = (rp.start[0], rp.start[1])
        traj = [here] * (horizon + 1)
        last = 0
        for t, cell in moves[rp.robot]:
            for tt in range(last + 1, t):
                traj[tt] = here
            traj[t] = cell
            here, last = cell, t
        for tt in range(last + 1, horizon + 1):
            traj[tt] = here
        trajectories[rp.robot] = traj  # type: ignore[assignment]
    return Execution(
        world=world,
        plan=plan,
        violation_list=violations,
        travel_m=round(sum(cells_moved.values()) * CELL_M, 6),
        steps=last_active,
        events=events,
        state_history=history,
        trajectories=trajectories,
        cells_moved=cells_moved,
    )
