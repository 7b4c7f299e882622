"""The task ontology every stage shares: ALFRED's seven kinds of base task plus `set_state`, the typed
slots each kind uses, the states a `set_state` task can ask for, and a task's goal.

The recipes that carry a task out in a world stay with the worlds (`worlds.tasks.BaseTask`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal

Kind = Literal[
    "place",
    "place_two",
    "place_in_container",
    "examine_in_light",
    "clean_place",
    "heat_place",
    "cool_place",
    "set_state",  # switch on/off, break, slice, open, close or pick up one object (SMART-LLM's skills)
]
KINDS: tuple[str, ...] = Kind.__args__  # type: ignore[attr-defined]
SLOTS = ("object", "container", "receptacle", "light")  # a base task's typed slots
State = Literal["on", "off", "broken", "sliced", "open", "closed", "held", "toasted"]
STATE_WORDS = {
    "on": "switched on",
    "off": "switched off",
    "broken": "broken",
    "sliced": "sliced",
    "open": "opened",
    "closed": "closed",
    "held": "picked up",
}
# a set_state task's state -> the affordance its object needs (None: see `worlds.tasks.can_take_state`)
STATE_FLAG: dict[str, str | None] = {
    "on": "toggleable",
    "off": "toggleable",
    "broken": None,
    "sliced": "sliceable",
    "open": "openable",
    "closed": "openable",
    "held": "pickupable",
}
APPLIANCE = {"clean_place": "SinkBasin", "heat_place": "Microwave", "cool_place": "Fridge"}
TREATMENT = {"clean_place": "cleanable", "heat_place": "heatable", "cool_place": "coolable"}
# what a kind does to the thing it picks up, as a refusal says it ("no task can wash it")
TREATED_VERB = {
    "clean_place": "wash", "heat_place": "heat", "cool_place": "chill", "examine_in_light": "hold"
}  # fmt: skip
MAX_COUNT = 50  # no AI2-THOR scene has more instances of one type


def camel_words(type_name: str) -> str:
    """ "GarbageCan" -> "garbage can", "TVStand" -> "tv stand", "CD" -> "cd"."""
    return " ".join(re.findall(r"[A-Z]+(?![a-z])|[A-Z][a-z]*|[a-z]+|\d+", type_name)).lower()


def slots_of(kind: str) -> tuple[str, ...]:
    """The typed slots a task of this kind uses.

    >>> slots_of("place_in_container")
    ('object', 'container', 'receptacle')
    """
    if kind == "place_in_container":
        return ("object", "container", "receptacle")
    if kind == "examine_in_light":
        return ("object", "light")
    if kind == "set_state":
        return ("object",)
    return ("object", "receptacle")


@dataclass(frozen=True)
class Goal:
    """What must hold for a task: `count` distinct objects of `objects` types in the target state."""

    task: str
    kind: str
    objects: frozenset[str]
    containers: frozenset[str]
    receptacles: frozenset[str]
    lights: frozenset[str]
    count: int

    def describe(self) -> str:
        obj = "/".join(sorted(self.objects))
        rec = "/".join(sorted(self.receptacles))
        if self.kind == "examine_in_light":
            return f"hold {obj} while a {'/'.join(sorted(self.lights))} is on"
        if self.kind == "place_in_container":
            return f"{obj} in a {'/'.join(sorted(self.containers))} in/on {rec}"
        state = {"clean_place": "clean ", "heat_place": "hot ", "cool_place": "cold "}.get(self.kind, "")
        n = f"{self.count} " if self.count > 1 else ""
        return f"{n}{state}{obj} in/on {rec}" if rec else f"{n}{state}{obj}"
