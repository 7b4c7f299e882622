"""Trust findings of the session-34 merges (issue 23, h299), through `plan` and `translate`.

Each class was read wrong or silently before h299:
- a sign-off only the frame rule knows before a thing's name ("Night, Mug"): read as one more item, exit 0;
- a closing chit-chat sentence the structure model's reading left out ("Go Rovers!"): dropped, unsaid;
- a name called after the request's comma ("..., Bo."): refused as "a list of destinations";
- "the remaining Xs" with no X said before: read as every X, exit 0;
- "tell / ask the robot to ...": partial on 'tell'; "rather than the pot" (no preposition): partial; "put
  the mug, rather than the pot, in the sink": the pot put there too, exit 0.
The near misses beside them must read as before. The many-case tables are trust/trust_h299dev/held.txt
(`scripts/trust_sets.py measure --sets trust_h299dev,trust_h299held`)."""

from __future__ import annotations

import pytest
from household_readings import plan_refusal, result_or_none

Reading = tuple[list[str], list[str], list[str], list[tuple[str, str]]]


def read(text: str, scene: str) -> Reading | str:
    """(the tasks' summaries, what is left unread, the assumptions, the order), or "refused"."""
    res = result_or_none(text, scene)
    if res is None:
        return "refused"
    return [t.summary() for t in res.tasks], res.unparsed, res.assumptions, list(res.before)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, named",
    [
        ("Put the egg in the fridge. Night, Mug", "FloorPlan17", "'Night, Mug' (object)"),
        ("Put the egg in the fridge. Peace, The Mug", "FloorPlan17", "'Peace, The Mug' (object)"),
        ("put the remaining apples in the fridge", "FloorPlan17", "'the remaining' (count)"),
    ],
)
def test_plan_refuses_what_it_read_wrong_naming_it(
    text: str, scene: str, named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert named in plan_refusal(text, scene, capsys)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, dropped",
    [
        ("Put the egg in the fridge, then put the mug in the sink. Go Rovers!", "'Go Rovers'"),
        ("Put the egg in the fridge, then put the mug in the sink. Miss you loads.", "'Miss you loads'"),
    ],
)
def test_a_closing_chit_chat_sentence_is_named(text: str, dropped: str) -> None:
    """The structure model's reading left the sentence out with no word said of it."""
    got = read(text, "FloorPlan17")
    assert got != "refused"
    tasks, unread, assumed, before = got
    assert tasks == ["place Egg -> Fridge", "place Mug -> SinkBasin"]
    assert not unread and before == [("A", "B")]
    assert any("dropped as frame" in a and dropped in a for a in assumed), assumed


@pytest.mark.data
def test_a_plain_thanks_stays_silent() -> None:
    got = read("Put the egg in the fridge, then put the mug in the sink. Thanks!", "FloorPlan17")
    assert got != "refused" and got[1:] == ([], [], [("A", "B")]), got


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, task, name",
    [
        ("Put the apple in the fridge, Bo.", "FloorPlan17", "place Apple -> Fridge", "'Bo'"),
        ("put the mug in the sink, Kit", "FloorPlan3", "place Mug -> SinkBasin", "'Kit'"),
    ],
)
def test_a_name_called_after_the_request_is_frame(text: str, scene: str, task: str, name: str) -> None:
    got = read(text, scene)
    assert got != "refused"
    assert got[0] == [task] and not got[1] and any(name in a for a in got[2]), got


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, task",
    [
        ("tell the robot to put the mug in the sink", "FloorPlan3", "place Mug -> SinkBasin"),
        ("ask the robot to put the tomato in the fridge", "FloorPlan3", "place Tomato -> Fridge"),
        ("put the mug in the sink rather than the pot", "FloorPlan3", "place Mug -> SinkBasin"),
        ("put the mug, rather than the pot, in the sink", "FloorPlan3", "place Mug -> SinkBasin"),
        ("put the mug, instead of the pot, in the sink", "FloorPlan3", "place Mug -> SinkBasin"),
    ],
)
def test_over_refusals_and_a_contrast_read(text: str, scene: str, task: str) -> None:
    got = read(text, scene)
    assert got != "refused" and got[0] == [task] and not got[1], got


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene",
    [
        # a writer's name that is no thing still goes with its sign-off; a robot singled out stays refused
        ("Put the egg in the fridge. Night, Sam", "FloorPlan17"),
        ("tell the second robot to put the mug in the sink", "FloorPlan3"),
        # "the remaining eggs" after an egg said before: the other eggs (h185)
        ("Put one egg in the fridge, then put the remaining eggs in the sink.", "FloorPlan17"),
    ],
)
def test_near_misses_read_as_before(text: str, scene: str) -> None:
    got = read(text, scene)
    if "second robot" in text:
        assert got == "refused" or any("'the second robot'" in u for u in got[1]), got
        return
    assert got != "refused" and not got[1], got
    if "remaining" in text:
        assert got[0] == ["place Egg -> Fridge", "place_two 2x Egg -> SinkBasin"], got
