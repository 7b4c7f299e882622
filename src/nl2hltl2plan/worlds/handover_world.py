"""The paper's four-arm handover worlds (Section IV-C, Fig. 4, Table III): `handover-square`, `handover-line`.

Four fixed arms a, b, c, d work over a small grid of table cells. Each arm's end effector moves one
cell per step inside its *reach*: its own cells plus the cells it shares with its neighbours. A cell
holds at most one block. Blocks pass from one arm to another only by being put down on a cell both
reach (a shared cell) and picked up by the other; two end effectors never occupy the same cell at
the same step. Labelled regions: sources E, F, G near arms a and b, targets H, I, J on the far side.

square (5 x 5, centre blocked; a top-left, b top-right, c bottom-right, d bottom-left)::

        col 0   1   2   3   4
    r0    a   a:E ab  b:F  b
    r1    a   a   ab  b   b:G
    r2    da  da  ##  bc  bc
    r3    d   d   cd  c   c:J
    r4    d   d:H cd  c:I c

line (2 x 13; a, b, c, d side by side, shared columns 3, 6, 9)::

        col 0   1   2   3   4   5   6   7   8   9   10  11  12
    r0    a:E a   a   ab  b   b:G bc  c   c   cd  d   d:I d
    r1    a   a   a:F ab  b   b   bc  c:H c   cd  d   d   d:J

Atoms a task's leaf formulas may use (evaluated after every step; see docs/experiments.md):
  state: at(B,R) block B lies on region R (R a label, or @B2: where block B2 started), held(B),
         empty(R), away(B) (B lies on a labelled region other than its start);
  events (true only at the step of the action): pick(B), put(B,R), drop(R) (any block put on R);
  B is Red, Blue or Yellow. The language stage's action atoms pickup(RedBlock), put(RedBlock,RegionH)
  are read as pick(Red), put(Red,H).
"""

from __future__ import annotations

import random
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.hierarchical import HierarchicalSpec
from nl2hltl2plan.logic.trace import TraceCheck, TraceEvent, check_trace
from nl2hltl2plan.worlds.plan import Plan, Step
from nl2hltl2plan.worlds.world import CELL_M, Affordances, Cell, World, WorldObject

Config = Literal["square", "line"]
ARMS = ("a", "b", "c", "d")
BLOCKS = ("Red", "Blue", "Yellow")
REGIONS = ("E", "F", "G", "H", "I", "J")


@dataclass(frozen=True)
class Layout:
    """Cells, each arm's reach, and the labelled regions of one configuration."""

    name: str
    shape: tuple[int, int]
    reach: tuple[frozenset[Cell], ...]  # per arm
    regions: dict[str, Cell]

    @cached_property
    def cells(self) -> frozenset[Cell]:
        return frozenset().union(*self.reach)

    @cached_property
    def region_at(self) -> dict[Cell, str]:
        return {c: r for r, c in self.regions.items()}

    def arms_reaching(self, cell: Cell) -> list[int]:
        return [a for a, cells in enumerate(self.reach) if cell in cells]

    @cached_property
    def shared(self) -> frozenset[Cell]:
        return frozenset(c for c in self.cells if len(self.arms_reaching(c)) > 1)

    def own(self, arm: int) -> list[Cell]:
        return sorted(c for c in self.reach[arm] if c not in self.shared)

    def place_name(self, cell: Cell) -> str:
        """'E'..'J' for a labelled region, else 'r{row}c{col}'."""
        return self.region_at.get(cell) or f"r{cell[0]}c{cell[1]}"

    def cell_of(self, name: str) -> Cell:
        if name in self.regions:
            return self.regions[name]
        m = re.fullmatch(r"r(\d+)c(\d+)", name)
        if not m or (int(m.group(1)), int(m.group(2))) not in self.cells:
            raise WorldError(f"no place {name!r} in handover-{self.name}")
        return (int(m.group(1)), int(m.group(2)))


def _square() -> Layout:
    cells = {(r, c) for r in range(5) for c in range(5)} - {(2, 2)}
    reach = (
        frozenset(x for x in cells if x[0] <= 2 and x[1] <= 2),
        frozenset(x for x in cells if x[0] <= 2 and x[1] >= 2),
        frozenset(x for x in cells if x[0] >= 2 and x[1] >= 2),
        frozenset(x for x in cells if x[0] >= 2 and x[1] <= 2),
    )
    regions = {"E": (0, 1), "F": (0, 3), "G": (1, 4), "H": (4, 1), "I": (4, 3), "J": (3, 4)}
    return Layout("square", (5, 5), reach, regions)


def _line() -> Layout:
    spans = ((0, 3), (3, 6), (6, 9), (9, 12))
    reach = tuple(frozenset((r, c) for r in range(2) for c in range(lo, hi + 1)) for lo, hi in spans)
    regions = {"E": (0, 0), "F": (1, 2), "G": (0, 5), "H": (1, 7), "I": (0, 11), "J": (1, 12)}
    return Layout("line", (2, 13), reach, regions)


LAYOUTS = {"square": _square, "line": _line}


def layout(config: str) -> Layout:
    if config not in LAYOUTS:
        raise WorldError(f"unknown handover configuration {config!r}; use square or line")
    return LAYOUTS[config]()


@dataclass
class HandoverWorld:
    """One instance: a layout, where each block starts, where each end effector starts."""

    layout: Layout
    blocks: dict[str, Cell]  # block -> start cell
    arm_starts: tuple[Cell, ...]
    seed: int | None = None
    notes: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        lay = self.layout
        for b, cell in self.blocks.items():
            if b not in BLOCKS:
                raise WorldError(f"unknown block {b!r}; blocks are {', '.join(BLOCKS)}")
            if cell not in lay.cells:
                raise WorldError(f"block {b} at {cell} is not a cell of handover-{lay.name}")
        if len(set(self.blocks.values())) != len(self.blocks):
            raise WorldError("two blocks start on the same cell (a cell holds one block)")
        if len(self.arm_starts) != len(ARMS):
            raise WorldError(f"handover worlds have {len(ARMS)} arms, got {len(self.arm_starts)} start cells")
        for a, cell in enumerate(self.arm_starts):
            if cell not in lay.reach[a]:
                raise WorldError(f"arm {ARMS[a]} cannot reach its start cell {cell}")
        if len(set(self.arm_starts)) != len(self.arm_starts):
            raise WorldError("two end effectors start on the same cell")

    @property
    def name(self) -> str:
        return f"handover-{self.layout.name}"

    def block_names(self) -> list[str]:
        return sorted(self.blocks, key=BLOCKS.index)

    def start_region(self, block: str) -> str:
        return self.layout.place_name(self.blocks[block])

    def as_world(self) -> World:
        """The instance as a `worlds.World` (blocks and regions as objects) for the language stage
        and `world` pictures; planning on it needs the cooperative planner (planning/coop.py)."""
        lay = self.layout
        free = [(c * CELL_M, r * CELL_M) for r, c in sorted(lay.cells)]
        block_types = tuple(f"{b}Block" for b in BLOCKS)
        pickup = Affordances(pickupable=True)
        objects = [
            _grid_object(
                f"{b}Block", cell, pickup, f"Region{lay.region_at[cell]}_0" if cell in lay.region_at else None
            )
            for b, cell in self.blocks.items()
        ]
        region = Affordances(receptacle=True, accepts=frozenset(block_types))
        objects += [_grid_object(f"Region{name}", cell, region) for name, cell in lay.regions.items()]
        return World.create(
            self.name,
            free,
            objects,
            kind="handover",
            default_starts=self.arm_starts,
            notes=[f"four-arm handover world ({lay.name}); plan it with planning.coop"],
        )


def _grid_object(type_: str, cell: Cell, affordances: Affordances, parent: str | None = None) -> WorldObject:
    """The one object of `type_` standing on a grid cell (a block or a region), used from that cell."""
    r, c = cell
    return WorldObject(
        id=f"{type_}_0",
        type=type_,
        position=(c * CELL_M, 0.0, r * CELL_M),
        affordances=affordances,
        interaction_cells=(cell,),
        parent=parent,
    )


def random_instance(config: str, placement: dict[str, list[str]], seed: int) -> HandoverWorld:
    """Blocks on distinct regions drawn from `placement` (block -> allowed region labels), arm end
    effectors on random own cells: the seeded instances of the handover bench."""
    lay = layout(config)
    rng = random.Random(seed)
    for _ in range(1000):
        chosen = {b: rng.choice(options) for b, options in placement.items()}
        if len(set(chosen.values())) == len(chosen):
            break
    else:
        raise WorldError(f"no distinct placement of the blocks in {placement}")
    unknown = [r for r in chosen.values() if r not in lay.regions]
    if unknown:
        raise WorldError(f"unknown region(s) {unknown} in handover-{config}")
    blocks = {b: lay.regions[r] for b, r in chosen.items()}
    starts = tuple(rng.choice(lay.own(a)) for a in range(len(ARMS)))
    return HandoverWorld(lay, blocks, starts, seed=seed)


def handover_world(config: str = "square") -> HandoverWorld:
    """The default instance: red on E, blue on F, yellow on G; end effectors on their first own cell."""
    lay = layout(config)
    blocks = {"Red": lay.regions["E"], "Blue": lay.regions["F"], "Yellow": lay.regions["G"]}
    return HandoverWorld(lay, blocks, tuple(lay.own(a)[0] for a in range(len(ARMS))), seed=None)


# ----- atoms ------------------------------------------------------------------------------------------
# A snapshot: (end-effector cell per arm, block index held per arm or -1, cell per block or None if held)
Snap = tuple[tuple[Cell, ...], tuple[int, ...], tuple[Cell | None, ...]]
Event = tuple[str, int, Cell] | None  # ("pick" | "put", block index, cell) at this step, or None
AtomFn = Callable[[Snap, Event], bool]


def _block_index(hw: HandoverWorld, name: str) -> int:
    base = name[:-5] if name.endswith("Block") else name
    names = hw.block_names()
    if base not in names:
        raise WorldError(f"no block {name!r} in {hw.name}; blocks are {', '.join(names)}")
    return names.index(base)


def _place(hw: HandoverWorld, name: str) -> Cell:
    if name.startswith("@"):
        b = name[1:]
        return hw.blocks[hw.block_names()[_block_index(hw, b)]]
    return hw.layout.cell_of(name[6:] if name.startswith("Region") else name)


def compile_atom(hw: HandoverWorld, atom: str) -> AtomFn:
    """A leaf atom -> a test on (snapshot, event); WorldError for an atom the world cannot read."""
    parsed = Atom.read(atom)
    if parsed is None or len(parsed.args) > 2:
        raise WorldError(
            f"cannot read atom {atom!r} in {hw.name} (see worlds/handover_world.py for the atoms)"
        )
    verb, x, y = parsed.verb, parsed.args[0], (parsed.args[1] if len(parsed.args) == 2 else None)
    labelled = frozenset(hw.layout.regions.values())
    if verb in ("at", "put") and y is not None:
        b, cell = _block_index(hw, x), _place(hw, y)
        if verb == "at":
            return lambda s, e: s[2][b] == cell
        return lambda s, e: e is not None and e[0] == "put" and e[1] == b and e[2] == cell
    if verb in ("held", "pick", "pickup", "away") and y is None:
        b = _block_index(hw, x)
        if verb == "held":
            return lambda s, e: s[2][b] is None
        if verb == "away":
            start = hw.blocks[hw.block_names()[b]]
            return lambda s, e: s[2][b] in labelled and s[2][b] != start
        return lambda s, e: e is not None and e[0] == "pick" and e[1] == b
    if verb in ("empty", "occupied", "drop") and y is None:
        cell = _place(hw, x)
        if verb == "drop":
            return lambda s, e: e is not None and e[0] == "put" and e[2] == cell
        if verb == "empty":
            return lambda s, e: cell not in s[2]
        return lambda s, e: cell in s[2]
    raise WorldError(f"cannot read atom {atom!r} in {hw.name} (see worlds/handover_world.py for the atoms)")


def initial_snap(hw: HandoverWorld) -> Snap:
    return (tuple(hw.arm_starts), (-1,) * len(ARMS), tuple(hw.blocks[b] for b in hw.block_names()))


# ----- executing a plan -------------------------------------------------------------------------------
@dataclass
class Handover:
    block: str
    giver: int
    taker: int
    cell: Cell
    t_put: int
    t_pick: int


@dataclass
class HandoverExecution:
    ok: bool
    violations: list[str]
    travel: int  # end-effector cells moved, summed over arms
    actions: int
    steps: int
    letters: list[set[str]]  # letters[t-1]: atoms (of those asked for) true after step t
    handovers: list[Handover]
    paths: dict[int, list[Cell]]  # arm -> cell at t = 0..T
    final: Snap


def _apply(
    hw: HandoverWorld, snap: Snap, arm: int, step: Step, prev_cells: tuple[Cell, ...]
) -> tuple[Snap, Event, str]:
    """One arm's step on a snapshot -> (new snapshot, event, violation or '')."""
    cells, hands, blocks = list(snap[0]), list(snap[1]), list(snap[2])
    lay = hw.layout
    here = cells[arm]
    if step.verb == "move":
        cell: Cell = (step.cell[0], step.cell[1]) if step.cell is not None else here
        if abs(cell[0] - here[0]) + abs(cell[1] - here[1]) != 1:
            return snap, None, f"move to {cell} is not a neighbour of {here}"
        if cell not in lay.reach[arm]:
            return snap, None, f"{cell} is out of arm {ARMS[arm]}'s reach"
        pairs = enumerate(zip(cells, prev_cells, strict=True))
        if any(i != arm and cell in (c, p) for i, (c, p) in pairs):
            return snap, None, f"{cell} is occupied by another arm's end effector"
        cells[arm] = cell
        return (tuple(cells), tuple(hands), tuple(blocks)), None, ""
    if step.verb == "pickup":
        b = _block_index(hw, step.objects[0])
        if hands[arm] >= 0:
            return snap, None, "the gripper is not empty"
        if blocks[b] != here:
            return snap, None, f"block {step.objects[0]} is not at {here}"
        hands[arm], blocks[b] = b, None
        return (tuple(cells), tuple(hands), tuple(blocks)), ("pick", b, here), ""
    if step.verb == "put":
        b = _block_index(hw, step.objects[0])
        if hands[arm] != b:
            return snap, None, f"arm {ARMS[arm]} does not hold {step.objects[0]}"
        if lay.cell_of(step.objects[1]) != here:
            return snap, None, f"the end effector is at {here}, not at {step.objects[1]}"
        if here in blocks:
            return snap, None, f"{lay.place_name(here)} already holds a block"
        hands[arm], blocks[b] = -1, here
        return (tuple(cells), tuple(hands), tuple(blocks)), ("put", b, here), ""
    if step.verb == "wait":
        return snap, None, ""
    return snap, None, f"verb {step.verb!r} is not available to a handover arm"


def execute_handover(hw: HandoverWorld, plan: Plan, atoms: Sequence[str] = ()) -> HandoverExecution:
    """Run a `Plan` (robots = arms 0..3) step by step; `letters` records which `atoms` hold after each."""
    tests = {a: compile_atom(hw, a) for a in atoms}
    snap = initial_snap(hw)
    by_t: dict[int, list[tuple[int, Step]]] = {}
    for rp in plan.robots:
        if not 0 <= rp.robot < len(ARMS):
            raise WorldError(f"robot {rp.robot} is not an arm of {hw.name}")
        if tuple(rp.start) != hw.arm_starts[rp.robot]:
            raise WorldError(
                f"arm {ARMS[rp.robot]} starts at {hw.arm_starts[rp.robot]}, the plan says {rp.start}"
            )
        for st in rp.steps:
            by_t.setdefault(st.t, []).append((rp.robot, st))
    horizon = max(by_t, default=0)
    violations: list[str] = []
    letters: list[set[str]] = []
    paths = {a: [hw.arm_starts[a]] for a in range(len(ARMS))}
    travel = actions = 0
    last_put: dict[int, tuple[int, Cell, int]] = {}  # block -> (arm, cell, t) of its last put
    handovers: list[Handover] = []
    for t in range(1, horizon + 1):
        prev_cells = snap[0]
        events: list[Event] = []
        for arm, st in sorted(by_t.get(t, []), key=lambda x: x[0]):
            new, event, why = _apply(hw, snap, arm, st, prev_cells)
            if why:
                violations.append(f"t={t} arm {ARMS[arm]}: {st.verb}({','.join(st.objects)}): {why}")
                continue
            travel += st.verb == "move"
            actions += st.verb in ("pickup", "put")
            snap = new
            if event is not None:
                events.append(event)
                verb, b, cell = event
                if verb == "put":
                    last_put[b] = (arm, cell, t)
                elif b in last_put and last_put[b][0] != arm and last_put[b][1] == cell:
                    giver, _, t_put = last_put[b]
                    handovers.append(Handover(hw.block_names()[b], giver, arm, cell, t_put, t))
        for a in range(len(ARMS)):
            paths[a].append(snap[0][a])
        letters.append({a for a, fn in tests.items() if any(fn(snap, e) for e in (events or [None]))})
    return HandoverExecution(
        not violations, violations, travel, actions, horizon, letters, handovers, paths, snap
    )


def check_handover(spec: HierarchicalSpec, execution: HandoverExecution) -> TraceCheck:
    """Judge an execution against a hierarchical spec over handover atoms (`logic.trace.check_trace`)."""
    events = [TraceEvent(t, a) for t, letter in enumerate(execution.letters, start=1) for a in sorted(letter)]
    return check_trace(spec, events)
