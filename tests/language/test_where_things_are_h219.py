"""Issue 28 (h219): where a thing is now, said in people's words (results/language/h219.md).

- A room or a part of a room in the subject's place ("the laptop on the desk in the hall goes on the bed",
  "the rag in the tub at the back") or opening the sentence ("In the bedroom, ...") says where things are.
- A landmark ("between the sinks", "next to the toaster") before a plain place says where the thing is; the
  plain place after it is where it goes. A posture with a plain place ("the knife lying in the sink") too.
- A source split over two things ("both spatulas, the one by A and the one by B, go in a drawer"), or said of
  one of them ("the other knife, the one under the microwave, in a cup"), is read as sources.
- Near misses are not read as sources: a room as the only place, "leave it lying on the bed", pieces with no
  destination after them ("put two mugs, one in the sink and the other on the counter").
"""

from __future__ import annotations

import pytest
from household_readings import reading, refusal, shared_world

READ = [
    ("FloorPlan303", "The laptop on the desk in the hall goes on the bed.", ["place Laptop -> Bed"]),
    (
        "FloorPlan401",
        "Take the rag out of the tub at the back and put it on the cart.",
        ["place Cloth -> Cart"],
    ),
    (
        "FloorPlan421",
        "Put the soap from the counter between the sinks in the drawer.",
        ["place SoapBar -> Drawer"],
    ),
    (
        "FloorPlan16",
        "Both spatulas, the one next to the wine bottle and the one by the toaster, go in a drawer.",
        ["place_two 2x Spatula -> Drawer"],
    ),
]
READ_SWEEP = [
    ("FloorPlan303", "In the bedroom, the CD on the desk goes on the dresser.", ["place CD -> Dresser"]),
    ("FloorPlan303", "Put the laptop from the desk in the hallway on the bed.", ["place Laptop -> Bed"]),
    ("FloorPlan421", "Put the soap between the sinks in the drawer.", ["place SoapBar -> Drawer"]),
    (
        "FloorPlan16",
        "Put the two spatulas, one from the counter and one from the table, in a drawer.",
        ["place_two 2x Spatula -> Drawer"],
    ),
    (
        "FloorPlan421",
        "Two bars of soap: one's in the sink and the other's on the counter. Both go in the drawer.",
        ["place_two 2x SoapBar -> Drawer"],
    ),
    (
        "FloorPlan8",
        "Put the butter knife, the one under the microwave, in the sink.",
        ["place ButterKnife -> SinkBasin"],
    ),
    ("FloorPlan3", "The apple sitting on the counter goes in the fridge.", ["place Apple -> Fridge"]),
]
# each with the words its refusal names
REFUSED = [
    ("FloorPlan303", "Put the laptop in the hall.", "receptacle is not stated"),
    ("FloorPlan401", "Put the rag on the cart and then put it back.", "'back'"),
    # the drawer may be the counter's: which place it goes to is not said (frames._standing_place_first)
    (
        "FloorPlan421",
        "Put the soap on the counter between the sinks in the drawer.",
        "the counter / the drawer",
    ),
]


@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, tasks", READ)
def test_where_a_thing_is_now_is_no_destination(floor_plan: str, text: str, tasks: list[str]) -> None:
    assert reading(text, shared_world(floor_plan))[0] == tasks


@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, words", REFUSED)
def test_a_room_or_return_as_the_only_place_is_refused(floor_plan: str, text: str, words: str) -> None:
    assert words in refusal(text, shared_world(floor_plan))


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize("floor_plan, text, tasks", READ_SWEEP)
def test_more_places_where_a_thing_is_now(floor_plan: str, text: str, tasks: list[str]) -> None:
    assert reading(text, shared_world(floor_plan))[0] == tasks


def test_pieces_with_no_destination_after_them_are_not_sources() -> None:
    from nl2hltl2plan.language.landmarks import where_things_are

    said = "Put the two mugs, one in the sink and the other on the counter."
    assert where_things_are(said) == said
    assert where_things_are("Leave it lying on the bed.") == "Leave it lying on the bed."
    assert where_things_are("Leave the mug sitting on the table.") == "Leave the mug sitting on the table."
