"""The extra world vocabulary SMART-LLM's tasks need, with AI2-THOR's state semantics.

The simulator (`worlds/simulator.py`) calls this module for what ALFRED's vocabulary lacks; the
object-type facts are AI2-THOR's (https://ai2thor.allenai.org/ithor/documentation/objects/object-types,
"Actionable Properties" and "Contextual Interactions"):
- `break(X)` (BreakObject): a Breakable object becomes broken (kept in place, flag `broken`).
- heat sources: a Microwave, Toaster, CoffeeMachine or StoveBurner that is switched on heats what is
  in/on it (a pan on a burner passes it on to its contents): heatable objects become hot, Cookable
  ones cooked (AI2-THOR: isCooked). Putting an object into a heat source that is already on does the
  same. A Microwave must be closed to run (ALFRED / AI2-THOR); no other appliance has that rule, so a
  Laptop can be opened and switched on in either order.
- water: a Faucet that runs fills the Fillable objects in its SinkBasin (isFilledWithLiquid), as it
  already cleans them; an object put under a running faucet is filled too.
- switches, TV, laptop, cell phone, coffee machine, faucet, toaster, stove burner: toggle_on/off. A
  StoveBurner is switched directly (AI2-THOR turns it with its StoveKnob, whose position ALFRED's data
  does not give).
- books, laptops and blinds open and close (`open` / `close`).
- throwing into a garbage can is `put(X,GarbageCan)`; in SMART-LLM's worlds the can takes any
  pickupable object (AI2-THOR's ThrowObject can land anything in it).
The flags `BROKEN`, `COOKED`, `FILLED` of `domain.object_state` are set here; `condition_holds` reads a
final snapshot for SMART-LLM's ground-truth states (SLICED, ON, OFF, HOT, COOKED, OPENED, CLOSED,
PICKED, BROKEN, and "contains").
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from nl2hltl2plan.domain.object_state import BROKEN, COOKED, FILLED, HOT, ON, OPEN, PRESENT
from nl2hltl2plan.worlds.world import World

if TYPE_CHECKING:
    from nl2hltl2plan.worlds.simulator import SimState, Snapshot

EXTRA_ARITY = {"break": 1}

BREAKABLE = frozenset(
    {
        "Bottle",
        "Bowl",
        "CellPhone",
        "Cup",
        "Egg",
        "Laptop",
        "Mirror",
        "Mug",
        "Plate",
        "ShowerDoor",
        "Statue",
        "Television",
        "Vase",
        "Window",
        "WineBottle",
    }
)
COOKABLE = frozenset({"BreadSliced", "EggCracked", "Potato", "PotatoSliced"})
FILLABLE = frozenset(
    {
        "Bottle",
        "Bowl",
        "Cup",
        "HousePlant",
        "Kettle",
        "Mug",
        "Pot",
        "WateringCan",
        "WineBottle",
    }
)
HEAT_SOURCES = frozenset({"Microwave", "Toaster", "CoffeeMachine", "StoveBurner"})
RUNS_CLOSED = frozenset({"Microwave"})
TRASH_TYPE = "GarbageCan"
# what SMART-LLM's worlds add to ALFRED's affordances
EXTRA_OPENABLE = frozenset({"Book", "Laptop", "Blinds"})
EXTRA_TOGGLEABLE = frozenset({"Laptop", "CellPhone", "StoveBurner", "Television", "LightSwitch", "Toaster"})
OPEN_AT_START = frozenset({"Blinds"})  # AI2-THOR scenes start with their blinds open
ON_AT_START = frozenset({"LightSwitch"})  # and their lights on


def act(state: SimState, robot: int, verb: str, objs: list[int]) -> str | None:
    """Apply one of the extra verbs (`EXTRA_ARITY`); the reason it fails, or None."""
    c = state.c
    if verb == "break":
        (o,) = objs
        if c.types[o] not in BREAKABLE:
            return f"{state.name(o)} ({c.types[o]}) cannot be broken"
        why = state.reach_problem(robot, o)
        if why:
            return why
        state.flags[o] |= BROKEN
        return None
    return f"unknown verb {verb}"


def _heat(state: SimState, source: int) -> None:
    c = state.c
    for i in state.subtree(source)[1:]:
        if c.aff[i].heatable:
            state.flags[i] |= HOT
        if c.types[i] in COOKABLE:
            state.flags[i] |= COOKED


def _fill(state: SimState, basin: int) -> None:
    c = state.c
    for i in state.subtree(basin)[1:]:
        if c.types[i] in FILLABLE:
            state.flags[i] |= FILLED


def after_toggle_on(state: SimState, o: int) -> None:
    """Effects of switching object o on (called after the simulator's own)."""
    c = state.c
    if c.types[o] in HEAT_SOURCES:
        _heat(state, o)
    if c.serves[o] >= 0:
        _fill(state, c.serves[o])


def after_put(state: SimState, o: int, r: int) -> None:
    """Effects of putting object o into r (called after the simulator's own)."""
    c = state.c
    x = r
    while x >= 0:  # a running heat source anywhere up the chain (a pan on a lit burner)
        if c.types[x] in HEAT_SOURCES and state.flags[x] & ON:
            _heat(state, x)
            break
        x = state.parent[x]
    sink = state.in_type(o, frozenset({"SinkBasin", "BathtubBasin"}))
    if sink >= 0 and any(state.flags[f] & ON for f in c.faucets_of.get(sink, ())):
        _fill(state, sink)


def type_matches(name: str, type_: str) -> bool:
    """SMART-LLM names objects by AI2-THOR type; its checker matches names by substring, so
    `Apple` also names the AppleSliced pieces and `Sink` the SinkBasin. We match type prefixes."""
    return type_ == name or type_.startswith(name)


def condition_holds(world: World, snap: Snapshot, name: str, state: str | None, contains: str | None) -> bool:
    """Does some object named `name` satisfy `state` (SMART-LLM's upper-case state) or hold an
    object named `contains` in the snapshot?"""
    ids = world.ids
    objs = [world.objects[i] for i in ids]
    for k, obj in enumerate(objs):
        if not type_matches(name, obj.type):
            continue
        flags = snap.flags[k]
        if contains is not None:
            if flags & PRESENT and any(
                snap.parent[j] == k and snap.flags[j] & PRESENT and type_matches(contains, objs[j].type)
                for j in range(len(objs))
            ):
                return True
            continue
        if state == "SLICED":
            index = world.index
            if obj.slices and any(snap.flags[index[s]] & PRESENT for s in obj.slices):
                return True
            continue
        if not flags & PRESENT:
            continue
        if _state_holds(state, flags, snap.holder[k], HOT, ON, OPEN):
            return True
    return False


def _state_holds(state: str | None, flags: int, holder: int, hot: int, on: int, open_: int) -> bool:
    checks = {
        "ON": bool(flags & on),
        "OFF": not flags & on,
        "HOT": bool(flags & hot),
        "COOKED": bool(flags & COOKED),
        "OPENED": bool(flags & open_),
        "CLOSED": not flags & open_,
        "PICKED": holder >= 0,
        "BROKEN": bool(flags & BROKEN),
        "FILLED": bool(flags & FILLED),
    }
    return checks.get(state or "", False)


STATES = ("SLICED", "ON", "OFF", "HOT", "COOKED", "OPENED", "CLOSED", "PICKED", "BROKEN", "FILLED")
