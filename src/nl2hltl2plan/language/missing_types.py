"""What a refusal for a type the world lacks says of the word's other types (issue 28): "put the
basketball on the chair" where the floor plan has no ArmChair is refused, and the word's other type,
ALFRED's Chair, holds nothing (and no floor plan's world builds one), so the refusal says so and names the
places of the scene that can hold the thing. Asked by `grounding.Grounder.missing` and, knowing the thing,
by `type_choice.note_for`; it imports no language module, so that the grounding can ask it."""

from __future__ import annotations

from collections.abc import Collection, Sequence
from functools import cache
from typing import TYPE_CHECKING

from nl2hltl2plan.errors import Nl2Hltl2PlanError

if TYPE_CHECKING:
    from nl2hltl2plan.language.grounding import AffordanceLookup, Entry

_PLACES_NAMED = 4  # at most this many places that can hold the thing, in the refusal


@cache
def listed(scene: str) -> frozenset[str]:
    """The types the floor plan's object lists name (none where it is not an ALFRED floor plan)."""
    from nl2hltl2plan.worlds.floor_plans import listed_types

    try:
        return frozenset(listed_types(scene))
    except Nl2Hltl2PlanError:  # tabletop, demo kitchen: the world is all there is
        return frozenset()


def other_types_note(
    entry: Entry,
    missing: str,
    built: Collection[str],
    scene: str,
    look: AffordanceLookup | None,
    thing: Sequence[str] = (),
) -> str:
    """What a refusal "no ArmChair in FloorPlan326" adds of the word's other types that the floor plan's
    object lists name and that cannot stand in: " ('chair' also names its Chair, which holds nothing in
    ALFRED, and which its world does not build; what there can hold the BasketBall: Bed, DiningTable,
    SideTable)". `built`: the world's types; `thing`: the types of what the place is to hold ("" unless a
    type of the word is asked as a place); `look`: the affordances (`grounding.alfred_lookup`). The empty
    string where nothing more is true to say."""
    names = listed(scene)
    if not names:  # not an ALFRED floor plan (tabletop, demo): nothing more to say
        return ""
    others = [t for t in entry.types if t != missing and t in names | set(built)]
    if look is None or not others:
        return ""
    said = []
    for other in others:
        a = look(other)
        if a is None:
            continue
        if not a.receptacle and entry.types[0] in _receptacle_types(look, entry):
            why = "which holds nothing in ALFRED"
        elif thing and not any(t in a.accepts for t in thing):
            why = f"which cannot hold the {thing[0]} in ALFRED"
        else:
            continue
        unbuilt = "" if other in built else ", and which its world does not build"
        said.append(f"{entry.phrase!r} also names its {other}, {why}{unbuilt}")
    if not said:
        return ""
    if thing:
        able = sorted(t for t in built if (a := look(t)) is not None and any(x in a.accepts for x in thing))
        able.sort(key=lambda t: _unlike_a_seat(t, look))
        if able:
            said.append(f"what there can hold the {thing[0]}: {', '.join(able[:_PLACES_NAMED])}")
    return f" ({'; '.join(said)})"


def _unlike_a_seat(type_: str, look: AffordanceLookup) -> tuple[bool, bool]:
    """How far a place is from an open surface such as a chair or a table (the nearest kind of place named
    first): a thing that is itself carried (a bowl), then one that opens (a fridge), come last."""
    a = look(type_)
    return a is not None and a.pickupable, a is not None and a.openable


def _receptacle_types(look: AffordanceLookup, entry: Entry) -> set[str]:
    """The entry's types that ALFRED lets hold things (a word for a place, not for a thing)."""
    return {t for t in entry.types if (a := look(t)) is not None and a.receptacle}
