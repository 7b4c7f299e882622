"""Red-team probes of session 33's merges (issue 23, h282), through `plan` and the public reading path.

Each case was read at exit 0 with part of the text dropped before h282:
- a later time said of a one-task request ("... later", "... in a bit") or a habit ("daily", "every day");
- the other place of a choice said only next to the first ("on the sofa or under it");
- a cut's own count ("cut the bread into three slices and put them ...") and a slice of an egg;
- a ban of a list of places ("not the microwave or the sink", "never put the egg in the fridge or the
  microwave": each forbade put(Microwave,Fridge)); a slice of a thing no knife cuts ("a slice of mug");
- a pair whose sentence names a third ("two mugs: one ..., the other ..., the third ...").
The near misses beside them must read as before. The many-case tables are probes_h282dev/held.txt, swept
under `-m sweep` (`test_user_styles`)."""

from __future__ import annotations

import pytest
from household_readings import plan_refusal, result_or_none


def read(text: str, scene: str) -> tuple[list[str], list[str], list[str]] | str:
    """(the tasks' summaries, what is left unread, the constraints), or "refused"."""
    res = result_or_none(text, scene)
    if res is None:
        return "refused"
    return [t.summary() for t in res.tasks], res.unparsed, [c.describe() for c in res.constraint_specs]


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, named",
    [
        ("put the remote on the sofa later", "FloorPlan207", "'later' (time)"),
        ("put the pillow on the sofa or under it", "FloorPlan207", "'under it' (place)"),
        (
            "cut the bread into three slices and put them on the dining table",
            "FloorPlan27",
            "'into three slices'",
        ),
    ],
)
def test_plan_refuses_what_it_dropped_naming_it(
    text: str, scene: str, named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert named in plan_refusal(text, scene, capsys)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene",
    [
        ("put the remote on the sofa in a bit", "FloorPlan207"),
        ("put the apple in the fridge daily", "FloorPlan5"),
        ("put the apple in the fridge, every day", "FloorPlan5"),
        ("put a slice of egg in the microwave", "FloorPlan12"),
        ("put a slice of mug in the sink", "FloorPlan5"),
        (
            "Take two mugs: put one in the sink, the other in the cabinet, and the third on the counter.",
            "FloorPlan5",
        ),
    ],
)
def test_never_read_whole(text: str, scene: str) -> None:
    said = read(text, scene)
    assert said == "refused" or said[1], said


@pytest.mark.data
def test_a_ban_of_a_list_of_places_forbids_each_place() -> None:
    said = read("put the egg in the fridge, not the microwave or the sink", "FloorPlan5")
    assert said != "refused"
    tasks, unparsed, constraints = said
    assert unparsed == [] and len(constraints) == 1
    assert "put(Egg,Microwave), put(Egg,SinkBasin)" in constraints[0], constraints
    assert read("put the egg in the fridge, not the microwave or the apple", "FloorPlan5") == "refused"
    # with its own verb, the list after a place is of places too (a thing after it keeps its own place)
    ban = "put the apple on the counter and never put the egg in the fridge or the microwave"
    said = read(ban, "FloorPlan5")
    assert said != "refused" and said[1] == [], said
    assert "put(Egg,Fridge), put(Egg,Microwave)" in said[2][0], said


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene",
    [
        ("chill the apple and afterwards put it on the counter", "FloorPlan5"),  # a task's own steps
        ("Move the pillow from the armchair to the sofa next to it.", "FloorPlan207"),  # a landmark
        ("Take two mugs: put one in the sink and the other in the cabinet.", "FloorPlan5"),  # a pair
        ("put the egg in the fridge, not the microwave", "FloorPlan5"),
    ],
)
def test_near_misses_still_read_whole(text: str, scene: str) -> None:
    said = read(text, scene)
    assert said != "refused" and said[1] == [], said
