"""The household reader's reading of an instruction as its tests compare it: the task summaries and the
order, as `translate` gives them for a floor plan's world (a partial reading fails the test)."""

from __future__ import annotations

from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.world import World


def reading(text: str, world: World) -> tuple[list[str], list[tuple[str, str]]]:
    """(the tasks' summaries, the order as task-id pairs); asserts the reading is complete."""
    res = translate(text, world, build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks], res.before
