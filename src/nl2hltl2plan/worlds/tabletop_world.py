"""The paper's tabletop world (Section IV-B, Table II): one arm over a 2-D grid table.

The table is a `ROWS` x `COLS` grid (one cell = `CELL_CM` cm of table; the paper converts its real
table into such a grid as well). The "robot" of the planner is the arm's end effector: it starts at
the arm's base `HOME` (middle of the near edge), moves one cell per step, picks an item from the cell
it lies on and puts it into a plate from the plate's cell. Cost = projected travel of the end effector
in grid cells, as in the paper. Items: green apple, red apple, orange, carrot; plates: blue, yellow,
pink, green. Every item and plate lies on its own cell, drawn per instance from a seed
(`tabletop_world(seed)`), so that repeated instances differ only in where things lie.

Types are our own (`GreenApple`, `BluePlate`, ...); the lexicon maps "green apple" to `GreenApple`
(falling back to `Apple` in AI2-THOR scenes) so that the normal language stage grounds them.
"""

from __future__ import annotations

import random

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.worlds.world import CELL_M, Affordances, Cell, World, WorldObject

ROWS, COLS = 15, 20
CELL_CM = 3.0  # table size 45 cm x 60 cm
HOME: Cell = (0, COLS // 2)
ITEMS = ("GreenApple", "RedApple", "Orange", "Carrot")
PLATES = ("BluePlate", "YellowPlate", "PinkPlate", "GreenPlate")
DEFAULT_SEED = 0


def tabletop_affordances(type_: str) -> Affordances:
    """Items can be picked up; plates accept every item."""
    if type_ in ITEMS:
        return Affordances(pickupable=True)
    if type_ in PLATES:
        return Affordances(receptacle=True, accepts=frozenset(ITEMS))
    raise WorldError(f"no type {type_!r} on the tabletop; types are {', '.join(ITEMS + PLATES)}")


def draw_layout(seed: int) -> dict[str, Cell]:
    """Distinct random cells for the four items and four plates (never the arm's home cell)."""
    rng = random.Random(seed)
    cells = [(r, c) for r in range(ROWS) for c in range(COLS) if (r, c) != HOME]
    chosen = rng.sample(cells, len(ITEMS) + len(PLATES))
    return {f"{t}_0": cell for t, cell in zip(ITEMS + PLATES, chosen, strict=True)}


def tabletop_world(seed: int = DEFAULT_SEED, layout: dict[str, Cell] | None = None) -> World:
    """A fresh tabletop instance: positions from `seed` (or an explicit `layout` {id: cell})."""
    seeded = layout is None
    layout = dict(layout) if layout is not None else draw_layout(seed)
    ids = [f"{t}_0" for t in ITEMS + PLATES]
    missing = [i for i in ids if i not in layout]
    if missing:
        raise WorldError(f"tabletop layout lacks {', '.join(missing)}")
    for oid, cell in layout.items():
        if not (0 <= cell[0] < ROWS and 0 <= cell[1] < COLS):
            raise WorldError(f"{oid} at {cell} is off the {ROWS}x{COLS} table")
    free = [(c * CELL_M, r * CELL_M) for r in range(ROWS) for c in range(COLS)]
    objects = []
    for oid in ids:
        type_ = oid.rsplit("_", 1)[0]
        r, c = layout[oid]
        objects.append(
            WorldObject(
                id=oid,
                type=type_,
                position=(c * CELL_M, 0.0, r * CELL_M),
                affordances=tabletop_affordances(type_),
                interaction_cells=((r, c),),  # the gripper acts on the cell the thing lies on
                parent=None,
                source=oid,
            )
        )
    return World.create(
        "tabletop",
        free,
        objects,
        kind="tabletop",
        default_starts=(HOME,),
        notes=[
            f"tabletop grid {ROWS}x{COLS} cells of {CELL_CM:g} cm; one arm, end effector starts at {HOME}; "
            + (f"positions drawn from seed {seed}" if seeded else "explicit layout")
        ],
    )


def layout_of(world: World) -> dict[str, Cell]:
    """Where each item and plate lies in a tabletop world."""
    return {oid: o.interaction_cells[0] for oid, o in world.objects.items()}
