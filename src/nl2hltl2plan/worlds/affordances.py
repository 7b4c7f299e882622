"""AI2-THOR affordances per object type, from ALFRED's constants (alfred/affordances.json).

ALFRED lists only the lamps as Toggleable (its only toggle task); AI2-THOR also switches faucets,
microwaves, coffee machines, toasters, stove knobs, light switches and televisions. We add those,
because `clean` (Faucet) and `heat` (Microwave) are modelled as toggles (see docs/worlds.md).
Pickupable is not in ALFRED's constants: a type is pickupable when some receptacle accepts it, it is
a movable receptacle, or it appears in a trial's `object_poses` (ALFRED only poses movable objects).
"""

from __future__ import annotations

from functools import cache

from nl2hltl2plan.config import data_path
from nl2hltl2plan.errors import DataError
from nl2hltl2plan.io import read_json
from nl2hltl2plan.worlds.world import Affordances

EXTRA_TOGGLEABLE = frozenset(
    {"Faucet", "Microwave", "CoffeeMachine", "Toaster", "StoveKnob", "LightSwitch", "Television"}
)


class AffordanceTable:
    """Callable type -> Affordances, built from ALFRED's affordance facts."""

    def __init__(self, facts: dict, extra_pickupable: frozenset[str] = frozenset()) -> None:
        try:
            actions = facts["action_objects"]
            self.accepts = {k: frozenset(v) for k, v in facts["receptacle_accepts"].items()}
            self.receptacles = frozenset(facts["receptacles"])
            self.openable = frozenset(facts["openable"])
            self.toggleable = frozenset(actions["Toggleable"]) | EXTRA_TOGGLEABLE
            self.sliceable = frozenset(actions["Sliceable"])
            self.heatable = frozenset(actions["Heatable"])
            self.coolable = frozenset(actions["Coolable"])
            self.cleanable = frozenset(actions["Cleanable"])
            self.movable_receptacles = frozenset(facts["movable_receptacles"])
            self.object_types = frozenset(facts["object_types"])
            self.visibility_m = float(facts.get("visibility_distance_m", 1.5))
        except (KeyError, TypeError) as exc:
            raise DataError(f"alfred/affordances.json lacks the field {exc}") from None
        accepted = frozenset(t for v in self.accepts.values() for t in v)
        self.pickupable = accepted | self.movable_receptacles | extra_pickupable
        self._cache: dict[str, Affordances] = {}

    def with_pickupable(self, types: frozenset[str]) -> AffordanceTable:
        table = AffordanceTable.__new__(AffordanceTable)
        table.__dict__.update(self.__dict__)
        table.pickupable = self.pickupable | types
        table._cache = {}
        return table

    def with_accepts(self, pairs: frozenset[tuple[str, str]]) -> AffordanceTable:
        """A copy whose receptacles also accept the given (object type, receptacle type) pairs."""
        table = self.with_pickupable(frozenset())
        accepts = {k: set(v) for k, v in self.accepts.items()}
        for obj, rec in pairs:
            if rec in self.receptacles:
                accepts.setdefault(rec, set()).add(obj)
        table.accepts = {k: frozenset(v) for k, v in accepts.items()}
        return table

    def __call__(self, type_: str) -> Affordances:
        aff = self._cache.get(type_)
        if aff is None:
            aff = Affordances(
                pickupable=type_ in self.pickupable,
                receptacle=type_ in self.receptacles,
                accepts=self.accepts.get(type_, frozenset()),
                openable=type_ in self.openable,
                toggleable=type_ in self.toggleable,
                sliceable=type_ in self.sliceable,
                heatable=type_ in self.heatable,
                coolable=type_ in self.coolable,
                cleanable=type_ in self.cleanable,
            )
            self._cache[type_] = aff
        return aff


@cache
def alfred_affordances() -> AffordanceTable:
    """The table from the shared data (cached)."""
    path = data_path("alfred", "affordances.json")
    facts = read_json(path, "ALFRED affordances file")
    if not isinstance(facts, dict):
        raise DataError(f"ALFRED affordances file {path} is damaged: expected a JSON object")
    return AffordanceTable(facts)
