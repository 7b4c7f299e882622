"""Red-team probes of classes no red team had tried (issue 23, h297), through `plan` and `translate`.

Each case was read at exit 0 with part of the text dropped before h297:
- a place for each thing ("each of the three mugs in its own cabinet", "in separate drawers", "one per
  drawer"): the task named the kind of place and dropped the "each its own";
- a task given to one robot ("have the second robot put ...", "robot 2 should ..."): the name was dropped;
- a task said between two others ("between putting A ... and putting B ..., C"; "A and B, and between
  those, C"): the order was dropped (a frame rule dropped "and between those" as a filler);
- a place to fall back on ("put the apple in the fridge, failing that / else / as a fallback the
  counter"): read as a cooled apple on the counter;
- a place not wanted ("on the desk rather than on the bed", "instead of on the bed", "in place of the
  bed"): read as the task's place (on the bed);
- a share of a plural ("three quarters of the eggs": every egg) and a habit ("the way you always do");
- after the held half's one scoring: "like we did earlier", "during the evening", "one more time", "after
  every tomato goes in ...", "instead of the green one" (each read at exit 0 with the words dropped).
The near misses beside them must read as before. The many-case tables are trust/redteam_h297dev/held.txt
(`scripts/trust_sets.py measure --sets redteam_h297dev,redteam_h297held`)."""

from __future__ import annotations

import pytest
from household_readings import plan_refusal, result_or_none, shared_world

from nl2hltl2plan.language.translate import translate


def read(text: str, scene: str) -> tuple[list[str], list[str], list[tuple[str, str]]] | str:
    """(the tasks' summaries, what is left unread, the order), or "refused"."""
    res = result_or_none(text, scene)
    return "refused" if res is None else ([t.summary() for t in res.tasks], res.unparsed, list(res.before))


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, named",
    [
        ("put each of the three mugs in its own cabinet", "FloorPlan3", "'in its own cabinet' (place)"),
        ("have the second robot put the laptop on the bed", "FloorPlan309", "'the second robot' (action)"),
        ("put the apple in the fridge, failing that the counter", "FloorPlan24", "'failing that'"),
        (
            "put the egg in the fridge and the mug in the sink, and between those, put the bread on the "
            "counter",
            "FloorPlan17",
            "'between those' (order)",
        ),
    ],
)
def test_plan_refuses_what_it_dropped_naming_it(
    text: str, scene: str, named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert named in plan_refusal(text, scene, capsys)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, named",
    [
        ("put the keys and the phone in separate drawers", "FloorPlan218", "'in separate drawers' (place)"),
        ("put the two pillows on different armchairs", "FloorPlan309", "'on different armchairs' (place)"),
        ("put each pencil into a drawer of its own", "FloorPlan309", "'drawer of its own' (place)"),
        ("the robot on the left should put the mug on the desk", "FloorPlan309", "'robot on the left'"),
        ("in the middle of heating the egg, put the bread on the counter", "FloorPlan17", "'in the middle"),
        ("let robot 2 put the egg in the fridge", "FloorPlan17", "'robot 2' (action)"),
        ("put three quarters of the eggs in the fridge", "FloorPlan17", "'three quarters of the eggs'"),
        ("put the apple in the fridge the way you always do", "FloorPlan24", "'the way you always do'"),
        # classes the held half showed (mended after its one scoring)
        ("put the mug in the cabinet like we did earlier", "FloorPlan3", "'like we did earlier'"),
        ("put the tomato in the fridge during the evening", "FloorPlan3", "'during the evening' (count)"),
        ("put the mug in the sink one more time", "FloorPlan3", "'one more time' (count)"),
        ("after every tomato goes in the fridge, put a mug in the sink", "FloorPlan3", "'after every"),
        ("put the red mug in the cabinet instead of the green one", "FloorPlan3", "'instead of the green"),
        ("put the apple in the fridge, or the counter as a backup", "FloorPlan24", "'as a backup'"),
        (
            "between putting the apple in the fridge and putting the bread on the counter, put the mug in "
            "the sink",
            "FloorPlan17",
            "'between putting' (order)",
        ),
    ],
)
def test_translate_names_the_dropped_words(text: str, scene: str, named: str) -> None:
    got = read(text, scene)
    assert got == "refused" or any(named in u for u in got[1]), got


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, tasks, before",
    [
        # the near misses: a thing's own container, a robot not singled out, an order said plainly
        ("put the credit card in its box on the coffee table", "FloorPlan210", 1, []),
        ("tell the robot: put the two mugs in the cabinet", "FloorPlan3", 1, []),
        ("put the egg in the fridge, then put the bread on the counter", "FloorPlan17", 2, [("A", "B")]),
    ],
)
def test_near_misses_read_as_before(text: str, scene: str, tasks: int, before: list[tuple[str, str]]) -> None:
    got = read(text, scene)
    assert got != "refused" and not got[1], got
    assert len(got[0]) == tasks and got[2] == before


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "put the book on the desk rather than on the bed",
        "put the book on the desk instead of on the bed",
        "put the book on the desk in place of the bed",
    ],
)
def test_a_place_not_wanted_is_not_the_tasks(text: str) -> None:
    """The place after "rather than / instead of" was the task's (place Book -> Bed, exit 0)."""
    assert read(text, "FloorPlan309") == (["place Book -> Desk"], [], [])


@pytest.mark.data
def test_a_place_between_things_is_no_order() -> None:
    """ "onto the counter between them." names a place (paper_h178's line), not a task between two others."""
    trial = "train/pick_two_obj_and_place-DishSponge-None-CounterTop-421/trial_T20190908_133115_043454"
    text = "Two sponges from the sinks onto the counter between them."
    res = translate(text, shared_world("FloorPlan421", [trial]), build=False, actions="none")
    assert [t.summary() for t in res.tasks] == ["place_two 2x DishSponge -> CounterTop"] and not res.unparsed
