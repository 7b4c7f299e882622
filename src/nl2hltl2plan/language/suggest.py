"""The closest supported tasks for a request the system did not understand ("bring me the remote" ->
"put the remote control on the sofa").

>>> from nl2hltl2plan.worlds.demo import demo_world
>>> suggestions("bring me a mug", demo_world())[0]
'put the mug in/on the cabinet'
"""

from __future__ import annotations

from collections.abc import Sequence

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grounding import camel_words, find_mentions
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.worlds.world import World

MAX_SUGGESTIONS = 3


def suggestions(instruction: str, world: World) -> list[str]:
    """Tasks the world supports on the objects the instruction names (at most MAX_SUGGESTIONS)."""
    out: list[str] = []
    types = world.object_types()
    lamps = sorted(t for t in ("DeskLamp", "FloorLamp") if t in types)
    for m in find_mentions(instruction):
        present = [t for t in m.entry.types if t in types]
        objs = [o for t in present for o in world.instances(t) if o.affordances.pickupable and o.present]
        if not objs:
            continue
        obj = objs[0]
        name = camel_words(obj.type)
        places = sorted(
            {o.type for o in world.objects.values() if obj.type in o.affordances.accepts and o.present}
        )
        out += [f"put the {name} in/on the {camel_words(p)}" for p in places[:2]]
        for flag, verb in (("heatable", "heat"), ("coolable", "chill"), ("cleanable", "wash")):
            if getattr(obj.affordances, flag) and places:
                out.append(f"{verb} the {name} and put it in/on the {camel_words(places[0])}")
        if lamps:
            out.append(f"examine the {name} under the {camel_words(lamps[0])}")
    return list(dict.fromkeys(out))[:MAX_SUGGESTIONS]


def suggestion_text(instruction: str, world: World | None) -> str:
    """ "; closest supported tasks: ..." (empty when there is nothing to suggest)."""
    found = suggestions(instruction, world) if isinstance(world, World) else []
    return f"; closest supported tasks: {' | '.join(found)}" if found else ""


def not_understood(lang: LanguageResult, world: World | None, cause: str = "") -> str:
    """The refusal of a partly understood instruction: the words, the reasons, the closest tasks."""
    why = f" ({cause})" if cause else ""
    return (
        f"not understood in {lang.instruction!r}: {'; '.join(lang.unparsed)}{why}"
        f"{suggestion_text(lang.instruction, world)} (--partial plans the rest)"
    )


def refuse_unmovable(tasks: Sequence[BaseTaskSpec], instruction: str, world: World) -> None:
    """A task that picks up a thing the world has only as fixtures ("scrub the toilet": a Toilet cannot be
    picked up, so it cannot be washed in the sink) is no task: HTTError naming the word, with the world's
    own reason (`BaseTask.unmovable`, which `BaseTask.missing` gives first). Judged on every backend's
    reading; a `set_state` task that holds the thing is asked too ("take a bath": the BathtubBasin held)."""
    for t in tasks:
        if why := t.unmovable(world):
            said = (m.surface for m in find_mentions(t.text or instruction) if {*m.entry.types} & {*t.object})
            word = next(said, camel_words(t.object[0]))
            raise HTTError(f"{word!r}: {why}")
