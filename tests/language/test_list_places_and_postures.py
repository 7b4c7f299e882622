"""The lead's held-out sets and probes of session 16: readings found wrong or refused.

- "put the apple and the egg in the fridge, and the mug in the sink" put the apple in the sink (an item
  without a place took the list's last place, not the next one said), reported solved;
- "the green apple should be sitting on the blue plate" was refused ("sitting" read as the action of sitting);
- "..., with the yellow plate's two placed before the blue plate's two, each pair in either order" was read
  with no order: a phrase that frees the order within each group excused the order word between them.
"""

from __future__ import annotations

import pytest
from household_readings import shared_world

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.world import World

BOTH = pytest.mark.parametrize("backend", ["offline", "grammar"])
needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def _world(name: str) -> World:
    return shared_world(name)


def _summaries(text: str, world: str, backend: str = "offline") -> list[str]:
    res = translate(text, _world(world), backend)
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks]


@needs_data
@BOTH
def test_an_item_without_a_place_takes_the_next_place_said(backend):
    text = "put the apple and the egg in the fridge, and the mug in the sink"
    assert _summaries(text, "FloorPlan14", backend) == [
        "place Apple -> Fridge",
        "place Egg -> Fridge",
        "place Mug -> SinkBasin",
    ]
    assert _summaries("put the apple, the egg and the mug in the fridge", "FloorPlan14", backend) == [
        "place Apple -> Fridge",
        "place Egg -> Fridge",
        "place Mug -> Fridge",
    ]


@BOTH
@pytest.mark.parametrize("posture", ["sitting", "lying", "resting"])
def test_a_posture_after_should_be_says_where_the_thing_ends(backend, posture):
    text = f"When you're done, the green apple should be {posture} on the blue plate."
    assert _summaries(text, "tabletop", backend) == ["place GreenApple -> BluePlate"]


@needs_data
def test_sitting_as_an_action_stays_refused():
    res = translate("put the newspaper on the sofa and then sit on it", _world("FloorPlan211"))
    assert res.partial and any("sit" in u for u in res.unparsed)


def test_a_freedom_within_each_group_leaves_the_order_between_groups_to_be_read():
    text = (
        "put the green apple and the orange on the yellow plate, and the carrot and the red apple on the "
        "blue plate, with the yellow plate's two placed before the blue plate's two, each pair in either "
        "order."
    )
    try:
        res = translate(text, _world("tabletop"))
    except HTTError:
        return
    assert res.partial and any("before" in u for u in res.unparsed), [t.summary() for t in res.tasks]


# the lead's probes of session 16: "the salt and pepper shakers" was a salt shaker and two pepper shakers
@needs_data
@BOTH
def test_a_plural_head_shared_by_a_list_names_one_of_each(backend):
    assert _summaries("put the salt and pepper shakers in a cabinet", "FloorPlan14", backend) == [
        "place SaltShaker -> Cabinet",
        "place PepperShaker -> Cabinet",
    ]
    # FloorPlan14 has 3 pepper shakers: "the pepper shakers" is not two of them (language/referents.py)
    with pytest.raises(HTTError, match="'pepper shakers': FloorPlan14 has 3 of them"):
        _summaries("put the salt shaker and the pepper shakers in a cabinet", "FloorPlan14", backend)


# the lead's held-out tabletop set K: "I'd appreciate it if the green apple went on the blue plate" was
# refused ("if" read as a condition); a wish's past subjunctive is its placing, and outside a wish "went"
# stays a statement of where a thing was
def test_a_wish_in_the_past_subjunctive_is_its_placing():
    text = "I'd appreciate it if the green apple went on the blue plate and the orange went on the yellow one"
    assert _summaries(text, "tabletop") == ["place GreenApple -> BluePlate", "place Orange -> YellowPlate"]
    with pytest.raises(HTTError):
        translate("The green apple went on the blue plate.", _world("tabletop"))
