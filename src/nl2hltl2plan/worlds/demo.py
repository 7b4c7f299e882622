"""The built-in "demo" kitchen: needs no data; used by the README demo and the fast tests.

A 3.5 m x 2.5 m kitchen (14 x 10 cells of 0.25 m) with a dining table in the middle, counters, a
sink with a faucet, a fridge, a microwave, a cabinet, a floor lamp, a garbage can and a dishwasher
with two racks for the paper's dishwasher example (Example 1): plates, mugs, cups, saucers and
utensils. `Dishwasher`, `DishwasherLowerRack`, `DishwasherUpperRack` and `Saucer` are our own types
(AI2-THOR has none of them); the racks are receptacles inside the openable Dishwasher, so putting
into a rack needs the dishwasher open. Everything else follows AI2-THOR/ALFRED affordances.
Plates, mugs, cups, saucers, bowls, forks and spoons are there twice (a butter knife and a knife
once each): a plural without a count word ("put the plates in the lower rack") is a two-object task
(`place_two`), as in the benchmark's annotation, so every plural of a dish or utensil can be done.
"""

from __future__ import annotations

from nl2hltl2plan.worlds.world import (
    Affordances,
    PluralConvention,
    World,
    WorldObject,
    add_slices,
    sliced_type,
)

DISHES = ("Plate", "Mug", "Cup", "Saucer", "Bowl")
UTENSILS = ("Fork", "Spoon", "ButterKnife", "Knife")
FOOD = ("Apple", "Bread", "Tomato")
SLICES = tuple(sliced_type(f) for f in FOOD)
SMALL = ("KeyChain", "Book")
MOVABLE = DISHES + UTENSILS + FOOD + SLICES + SMALL

_ACCEPTS: dict[str, tuple[str, ...]] = {
    "CounterTop": MOVABLE,
    "DiningTable": MOVABLE,
    "Dishwasher": DISHES + UTENSILS,  # "put(Plate,Dishwasher)" works too; the racks are finer targets
    "DishwasherLowerRack": DISHES + UTENSILS,
    "DishwasherUpperRack": DISHES + UTENSILS,
    "Cabinet": DISHES + ("Book",),
    "Fridge": FOOD + SLICES + ("Plate", "Mug", "Cup", "Bowl", "Saucer"),
    "Microwave": FOOD + SLICES + ("Plate", "Mug", "Cup", "Bowl"),
    "SinkBasin": DISHES + UTENSILS + FOOD + SLICES,
    "GarbageCan": FOOD + SLICES + ("Book",),
    "Bowl": FOOD + SLICES + UTENSILS + ("KeyChain",),
    "Plate": FOOD + SLICES + UTENSILS + ("Mug", "Cup", "KeyChain"),
    "Saucer": ("Cup", "Mug"),
    "Mug": ("Fork", "Spoon", "ButterKnife", "Knife"),
    "Cup": ("Fork", "Spoon", "ButterKnife"),
}
_HEATABLE = FOOD + SLICES + ("Mug", "Cup", "Plate")
_COOLABLE = FOOD + SLICES + DISHES
_CLEANABLE = DISHES + UTENSILS + ("Apple", "Tomato", "AppleSliced", "TomatoSliced")


def demo_affordances(type_: str) -> Affordances:
    """Affordances of the demo kitchen's types."""
    return Affordances(
        pickupable=type_ in MOVABLE,
        receptacle=type_ in _ACCEPTS,
        accepts=frozenset(_ACCEPTS.get(type_, ())),
        openable=type_ in ("Fridge", "Microwave", "Cabinet", "Dishwasher"),
        toggleable=type_ in ("Faucet", "Microwave", "FloorLamp"),
        sliceable=type_ in FOOD,
        heatable=type_ in _HEATABLE,
        coolable=type_ in _COOLABLE,
        cleanable=type_ in _CLEANABLE,
    )


# id, (x, y, z), parent
_STATIC = [
    ("CounterTop_0", (0.5, 0.9, 2.6), None),
    ("CounterTop_1", (2.75, 0.9, 2.6), None),
    ("SinkBasin_0", (1.75, 0.85, 2.6), None),
    ("Faucet_0", (1.75, 1.05, 2.75), None),
    ("Dishwasher_0", (1.125, 0.4, 2.6), None),
    ("DishwasherLowerRack_0", (1.125, 0.2, 2.6), "Dishwasher_0"),
    ("DishwasherUpperRack_0", (1.125, 0.6, 2.6), "Dishwasher_0"),
    ("Cabinet_0", (0.25, 1.9, 2.7), None),
    ("Fridge_0", (-0.5, 0.0, 1.75), None),
    ("Microwave_0", (3.0, 1.1, 2.65), None),
    ("DiningTable_0", (1.625, 0.75, 1.125), None),
    ("GarbageCan_0", (3.6, 0.0, 0.0), None),
    ("FloorLamp_0", (3.6, 0.0, 2.25), None),
]
_MOVABLE = [
    ("Plate_0", (0.4, 0.95, 2.55), "CounterTop_0"),
    ("Plate_1", (0.7, 0.95, 2.55), "CounterTop_0"),
    ("Bread_0", (0.2, 1.0, 2.5), "CounterTop_0"),
    ("Cup_0", (2.6, 0.95, 2.55), "CounterTop_1"),
    ("Cup_1", (2.9, 0.95, 2.55), "CounterTop_1"),
    ("Saucer_0", (2.45, 0.93, 2.5), "CounterTop_1"),
    ("Saucer_1", (2.5, 0.93, 2.65), "CounterTop_1"),
    ("Knife_0", (2.3, 0.95, 2.55), "CounterTop_1"),
    ("Fork_1", (2.2, 0.95, 2.45), "CounterTop_1"),
    ("Spoon_1", (2.15, 0.95, 2.65), "CounterTop_1"),
    ("Bowl_1", (0.95, 0.95, 2.55), "CounterTop_0"),
    ("Mug_0", (1.25, 0.8, 1.0), "DiningTable_0"),
    ("Mug_1", (2.0, 0.8, 1.25), "DiningTable_0"),
    ("Fork_0", (1.4, 0.78, 1.25), "DiningTable_0"),
    ("Spoon_0", (1.6, 0.78, 1.25), "DiningTable_0"),
    ("ButterKnife_0", (1.8, 0.78, 1.0), "DiningTable_0"),
    ("Bowl_0", (1.5, 0.8, 1.0), "DiningTable_0"),
    ("Apple_0", (1.9, 0.85, 1.0), "DiningTable_0"),
    ("KeyChain_0", (1.3, 0.78, 1.25), "DiningTable_0"),
    ("Book_0", (1.7, 0.8, 1.2), "DiningTable_0"),
    ("Apple_1", (-0.5, 1.0, 1.7), "Fridge_0"),
    ("Tomato_0", (-0.5, 1.0, 1.85), "Fridge_0"),
]
_BLOCKED = {(r, c) for r in (4, 5) for c in range(5, 9)}  # the dining table's footprint
ROWS, COLS = 10, 14
DEFAULT_STARTS = ((0, 0), (0, 13), (9, 13), (2, 6))
# the paper's Example 1 ("put plates, mugs and utensils into the lower rack") reads "utensils" as two of
# any kind among the six, which this kitchen is built to show: read so without asking
EXAMPLE_1 = PluralConvention("the paper's Example 1", always=True, categories=True)


def demo_world() -> World:
    """A fresh demo kitchen (objects are mutable dataclasses: never share one between tests)."""
    free = [(c * 0.25, r * 0.25) for r in range(ROWS) for c in range(COLS) if (r, c) not in _BLOCKED]
    objects = []
    for oid, pos, parent in _STATIC + _MOVABLE:
        type_ = oid.rsplit("_", 1)[0]
        objects.append(
            WorldObject(
                id=oid,
                type=type_,
                position=pos,
                affordances=demo_affordances(type_),
                parent=parent,
                serves="SinkBasin_0" if type_ == "Faucet" else None,
                source=oid,
            )
        )
    objects = add_slices(objects, demo_affordances)
    return World.create(
        "demo",
        free,
        objects,
        kind="demo",
        plurals=EXAMPLE_1,
        default_starts=DEFAULT_STARTS,
        notes=["built-in demo kitchen (no data); Dishwasher, its racks and Saucer are demo-only types"],
    )
