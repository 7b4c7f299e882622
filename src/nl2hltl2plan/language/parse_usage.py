"""What a parse uses, for the word-accounting check (`accounting.account`): its base tasks and
constraints rendered back to the kinds, states and typed slots they fill, and the places and words their
kinds imply ("heat" implies the microwave, a slice a knife).

>>> from nl2hltl2plan.language.task_specs import BaseTaskSpec
>>> used = ParseUsage([BaseTaskSpec(id="A", kind="heat_place", object=["Cup"], receptacle=["Microwave"])], [])
>>> sorted(used.kinds), "StoveBurner" in used.implied()
(['heat_place'], True)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from nl2hltl2plan.domain.task_kinds import APPLIANCE, slots_of
from nl2hltl2plan.language.content_words import vocabulary
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.worlds.world import KNIFE_TYPES

# the appliances a kind of task implies, beyond the destination ("heat it on the stove")
IMPLIED_TYPES = {
    "clean_place": {APPLIANCE["clean_place"], "Faucet", "BathtubBasin", "Sink"},
    "heat_place": {APPLIANCE["heat_place"], "StoveBurner", "Toaster", "CoffeeMachine"},
    "cool_place": {APPLIANCE["cool_place"]},
}


LAMPS = frozenset({"DeskLamp", "FloorLamp"})


@dataclass
class ParseUsage:
    """The base tasks (and constraints) rendered back to what they use: kinds, states, filled slots, the
    places and words their kinds imply."""

    tasks: Sequence[BaseTaskSpec]
    before: Sequence[tuple[str, str]]
    constraints: Sequence[ConstraintSpec] = ()
    spans: Sequence[tuple[int, int, ConstraintSpec]] = ()  # where each constraint's words are

    @property
    def kinds(self) -> set[str]:
        """The kinds of task, a toast counting as heating (in the toaster), and a container left in the
        fridge or the microwave ("refrigerate the slice in a bowl") as cooling or heating its content."""
        in_appliance = {
            k for t in self.tasks for k in ("heat_place", "cool_place")
            if t.kind == "place_in_container" and t.receptacle == [APPLIANCE[k]]
        }  # fmt: skip
        toasted = {"heat_place" for t in self.tasks if t.state == "toasted"}
        return {t.kind for t in self.tasks} | toasted | in_appliance

    @property
    def sliced(self) -> bool:
        return any(t.sliced or t.state == "sliced" for t in self.tasks)

    @property
    def states(self) -> set[str]:
        return {str(t.state) for t in self.tasks if t.kind == "set_state"}

    @property
    def light_states(self) -> set[str]:
        """The states set_state tasks switch a room's light switch or a lamp into."""
        lights = LAMPS | {"LightSwitch"}
        on = {"on"} if "examine_in_light" in self.kinds else set()  # its lamp is switched on
        return on | {str(t.state) for t in self.tasks if t.kind == "set_state" and set(t.object) & lights}

    def slots(self) -> list[tuple[str, str, frozenset[str]]]:
        """(task id, role, types) for every filled slot."""
        out = []
        for t in self.tasks:
            for role in slots_of(t.kind):
                if role == "receptacle" and t.places:  # "the fridge or the microwave": a slot per place said
                    out += [(t.id, role, frozenset(place)) for place in t.places]
                    continue
                types = set(getattr(t, role) or [])
                if "LightSwitch" in types:
                    types |= LAMPS  # "the light(s)" of a room is its light switch
                if types:
                    out.append((t.id, role, frozenset(types)))
        for k, c in enumerate(self.constraints, 1):  # a negation's things: one slot per type it forbids on
            named = {a for p in c.forbid for a in (Atom.read_pattern(p) or Atom("", ())).args if a != "*"}
            out += [(f"constraint {k}", "constraint", frozenset({t})) for t in sorted(named)]
        return out

    def constraint_at(self, char: int) -> ConstraintSpec | None:
        """The constraint whose words hold character `char` of the instruction."""
        return next((c for a, b, c in self.spans if a <= char < b), None)

    def implied(self) -> set[str]:
        out: set[str] = set()
        for k in self.kinds:
            out |= IMPLIED_TYPES.get(k, set())
        if self.sliced:
            out |= set(KNIFE_TYPES)
        return out

    def implied_words(self) -> set[str]:
        v = vocabulary()
        out: set[str] = set()
        for k in self.kinds:
            out |= v.get(f"implied_{k}", frozenset())
        if self.sliced:
            out |= v["implied_sliced"]
        return out
