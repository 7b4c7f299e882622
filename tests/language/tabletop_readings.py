"""The tabletop reader's reading of an instruction as its tests compare it: the (object, plate) pairs
and the closure of the order by pair, as `translate` gives them; None on a refusal or a partial reading."""

from __future__ import annotations

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.task_specs import transitive_closure
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.tabletop_world import tabletop_world

WORLD = tabletop_world()
Pair = tuple[str, str]


def pairs_read(text: str) -> tuple[list[Pair], list[tuple[Pair, Pair]]] | None:
    """(object, plate) pairs sorted and the closed order by pair; None on a refusal or a partial reading."""
    try:
        r = translate(text, WORLD, build=False)
    except Nl2Hltl2PlanError:  # a refusal of the text or of the world's objects: exit 2 either way
        return None
    if r.partial:
        return None
    key = {t.id: (t.object[0], t.receptacle[0]) for t in r.tasks}
    closure = transitive_closure(r.before, list(key))
    return sorted(key.values()), sorted((key[a], key[b]) for a, b in closure)
