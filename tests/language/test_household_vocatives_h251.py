"""h245's vocatives in the household reader (h251, issue 28): since h244 the household reader drops frame by
the one frame rule, so a single noun set off at a sentence's end addresses the listener there too ("...,
sweetheart.", said in the assumptions), while a word that leaves a choice to the robot ("whichever",
`frame_keeps.txt`) is never dropped as one: its sentence stays refused as a choice, not read as one task."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


def _read(text: str):
    from trust_sets import world_of

    return translate(text, world_of("FloorPlan28"), build=False, actions="none")


@pytest.mark.data
def test_a_single_noun_at_the_end_addresses_the_listener_and_is_said() -> None:
    res = _read("Put the egg in the fridge, then put the mug in the sink, sweetheart.")
    assert [t.summary() for t in res.tasks] == ["place Egg -> Fridge", "place Mug -> SinkBasin"]
    assert sorted(res.before) == [("A", "B")] and not res.unparsed
    assert any("'sweetheart'" in a for a in res.assumptions)


@pytest.mark.data
def test_a_choice_left_to_the_robot_is_not_dropped_as_a_vocative() -> None:
    # since h274 a choice between places is read: the "whichever" closes it (either place will do)
    res = _read("put the egg in the fridge, or the sink, whichever")
    assert [t.places for t in res.tasks] == [[["Fridge"], ["SinkBasin"]]] and not res.unparsed
    with pytest.raises(Nl2Hltl2PlanError, match="whichever"):  # a choice of objects: refused, named
        _read("put the egg or the apple in the fridge, whichever")
