"""Which of a word's types the text means, where the scene holds more than one (issue 28), and what a
refusal says of the word's other types.

- "towel" is ALFRED's word for its HandTowel, yet every ALFRED bathroom has a Towel too, so the reading is
  refused (`grounding.exact_name_conflict`) unless the text decides: the task can be done with one of the
  two only ("put the towel in the cabinet": ALFRED puts a Towel on a TowelHolder and nowhere else), or the
  place it comes from holds one of them only ("the towel from the hand towel holder"). `text_decides`.
- "put the basketball on the chair" where the floor plan has no ArmChair: the word's other type, ALFRED's
  Chair, holds nothing (and no floor plan's world builds one). The refusal says so and names the places
  of the scene that can hold the thing (`missing_types.other_types_note`, `note_for`).
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from functools import cache

from nl2hltl2plan.language.grounding import (
    AffordanceLookup,
    Entry,
    Mention,
    Roles,
    alfred_lookup,
    find_mentions,
    own_type,
    tokens,
)
from nl2hltl2plan.language.missing_types import listed as _listed
from nl2hltl2plan.language.missing_types import other_types_note
from nl2hltl2plan.language.task_specs import BaseTaskSpec

# words between a thing and the place it is at ("the towel from / off / on / hanging on the holder",
# "the towel that's in the drawer"); a landmark's words ("next to", "by", "near") are not among them
_AT_LINKS = frozenset(
    "from off of on in inside hanging hangs sitting lying that which is that's the a its".split()
)
# one of them says a place it is at, not one it goes to ("put the towel on the holder")
_AT_WORDS = frozenset("from off hanging hangs sitting lying that which that's".split())
_PLACES_NAMED = 4  # at most this many places that can hold the thing, in the refusal


@cache
def _look() -> AffordanceLookup | None:
    return alfred_lookup()


def text_decides(
    m: Mention,
    present: Sequence[str],
    tasks: Sequence[BaseTaskSpec],
    instruction: str,
    instances: Mapping[str, int],
    scene: str,
    look: AffordanceLookup | None = None,
) -> str | None:
    """Why the text leaves the word of mention `m` one reading among the scene's types `present` (in the
    lexicon's order, the first the one read), said as the reading's assumption, else None: every task of
    the word (`tasks`) that uses the first type could not be done with the word's own type ("towel" ->
    Towel), or the place the text says the thing is at holds the first type and not the own one. A place
    word's types that the floor plan lists and its world does not build count as places the thing could be
    meant for ("the towel holder" where only the HandTowelHolder is built: the Towel's holder is listed, so
    "hang the towel on the towel holder" stays refused). `look`: the affordances (ALFRED's when None)."""
    named = own_type(m.entry, present)
    look = look or _look()
    if named is None or look is None or not present or named == present[0]:
        return None
    first = present[0]
    read = f"{m.surface!r}: read as the {first}"
    using = [_with_unbuilt(t, scene) for t in tasks if first in t.object or first in (t.container or ())]
    if using and all(_role_rules_out(t, first, named, look) for t in using):
        places = sorted({p for t in using for p in t.receptacle or ()})
        where = f"be put in or on the {'/'.join(places)}" if places else "do what is asked"
        return f"{read}; its {named} cannot {where} in ALFRED"
    place = _place_at(m, instruction, instances, scene, look, (first, named))
    if place is not None and place[0] == first:
        return f"{read}; the {place[1]} it is at holds no {named} in ALFRED"
    return None


def _with_unbuilt(task: BaseTaskSpec, scene: str) -> BaseTaskSpec:
    """The task with its place's word's other types that the floor plan lists added to its receptacle."""
    listed = _listed(scene)
    if not task.receptacle or not listed:
        return task
    words = [m.entry for m in find_mentions(task.text) if set(m.entry.types) & set(task.receptacle)]
    more = [t for e in words for t in _unbuilt(e, task.receptacle, listed)]
    return task.model_copy(update={"receptacle": [*task.receptacle, *dict.fromkeys(more)]}) if more else task


def _unbuilt(entry: Entry, chosen: Sequence[str], listed: Collection[str]) -> list[str]:
    """The entry's types the floor plan lists that its world did not build, which the word would have
    read had they been built: every one for a word of any of its types ("towel holder"), else those
    before the one chosen ("hand towel holder" read as the HandTowelHolder: none)."""
    types = entry.types
    if not entry.all_ and chosen and chosen[0] in types:
        types = types[: types.index(chosen[0])]
    return [t for t in types if t in listed and t not in chosen]


def _role_rules_out(task: BaseTaskSpec, first: str, named: str, look: AffordanceLookup) -> bool:
    """Whether the task's roles keep `first` and drop `named` (`Roles.narrow`) where `first` stands."""
    if task.kind == "set_state":
        return False
    pair = [first, named]
    if first in task.object:
        roles = Roles(pair, task.receptacle, task.container, task.light).narrow(look, task.kind, task.sliced)
        return named not in roles.object and first in roles.object
    roles = Roles(task.object, task.receptacle, pair, task.light).narrow(look, task.kind, task.sliced)
    return named not in (roles.container or []) and first in (roles.container or [])


def _place_at(
    m: Mention,
    instruction: str,
    instances: Mapping[str, int],
    scene: str,
    look: AffordanceLookup,
    types: Sequence[str],
) -> tuple[str, str] | None:
    """The one type of `types` that the place said right after the word ("from the hand towel holder")
    can hold, and that place's type, where the scene's types of that place hold exactly one of them."""
    after = next((o for o in find_mentions(instruction) if o.char_start >= m.char_end), None)
    if after is None or after.entry.generic:
        return None
    between = [w for w, _, _ in tokens(instruction[m.char_end : after.char_start])]
    if not between or not set(between) <= _AT_LINKS or not set(between) & _AT_WORDS:
        return None
    places = [t for t in after.entry.types if instances.get(t)]
    places = places if after.entry.all_ else places[:1]
    places += _unbuilt(after.entry, places, _listed(scene))
    held = {t for t in types for p in places if (a := look(p)) is not None and t in a.accepts}
    return (held.pop(), "/".join(places)) if len(held) == 1 else None


def note_for(task: BaseTaskSpec, role: str, missing: str, built: Collection[str], scene: str) -> str:
    """`other_types_note` for a task's slot whose type `missing` the world lacks: the entry is the word of
    the task's text that reads `missing` first (the grammar keeps a word's first type where none is
    present)."""
    entry = next((m.entry for m in find_mentions(task.text) if m.entry.types[0] == missing), None)
    if entry is None or len(entry.types) < 2:
        return ""
    thing = (task.container or task.object) if role == "receptacle" else ()
    return other_types_note(entry, missing, built, scene, _look(), thing)
