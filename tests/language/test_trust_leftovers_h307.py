"""Session 34's trust leftovers, mended as classes (issue 23, h307), through `plan` and `translate`.

Each class was read wrong at exit 0, dropped, or over-refused before h307:
- a closing capitalised thing word after a short lead that names no thing ("Later, Pot", "Okay, Apple.")
  or alone ("Bread."): read as one more task; now taken out and refused by name;
- a lone sentence naming a thing the lexicon lacks ("The giraffe."): dropped as frame; now named;
- a vessel and what it holds ("a mug of wine", "a bowl of apples"): read as the vessel alone, the content
  silently taken for where it was; now the content is named (the world holds no liquid apart from its
  vessel);
- a cut into N pieces with one piece taken: refused as a count; now a slice of the thing.
The near misses beside them must read as before. The many-case tables are trust/trust_h307dev/held.txt
(`scripts/trust_sets.py measure --sets trust_h307dev,trust_h307held`)."""

from __future__ import annotations

import pytest
from household_readings import plan_refusal, result_or_none


def read(text: str, scene: str) -> tuple[list[str], list[str], list[str]] | str:
    """(the tasks' summaries, what is left unread, the assumptions), or "refused"."""
    res = result_or_none(text, scene)
    if res is None:
        return "refused"
    return [t.summary() for t in res.tasks], res.unparsed, res.assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, named",
    [
        ("Put the egg in the fridge. Later, Pot", "FloorPlan1", "'Later, Pot' (object)"),
        ("Put the mug in the sink. The giraffe.", "FloorPlan1", "'giraffe' (object)"),
        ("put a mug of wine in the sink", "FloorPlan17", "'wine'"),
    ],
)
def test_plan_refuses_what_it_read_wrong_naming_it(
    text: str, scene: str, named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert named in plan_refusal(text, scene, capsys)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, word",
    [
        ("Put the bread on the counter. Okay, Apple.", "FloorPlan3", "Apple"),  # (the "Okay" goes first)
        ("Put the apple in the fridge. Bread.", "FloorPlan17", "Bread"),
        ("put a bowl of apples on the dining table", "FloorPlan17", "apples"),
    ],
)
def test_one_more_thing_is_never_a_silent_task(text: str, scene: str, word: str) -> None:
    reading = read(text, scene)
    assert reading != "refused" and len(reading[0]) == 1, reading
    assert any(f"'{word}'" in u for u in reading[1]), reading


@pytest.mark.data
def test_a_writer_name_after_an_order_word_is_frame_and_said() -> None:
    tasks, unread, assumed = read("Put the potato in the pot. Later, Priya", "FloorPlan22")  # type: ignore[misc]
    assert (tasks, unread) == (["place Potato -> Pot"], [])
    assert any("Later, Priya" in a for a in assumed), assumed


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, tasks",
    [
        ("cut the apple into three slices and put a slice in the fridge", "FloorPlan1",
         ["place Apple(sliced) -> Fridge"]),
        ("cut the apple into three slices and put two slices in the fridge", "FloorPlan1",
         ["place_two 2x Apple(sliced) -> Fridge"]),
    ],
)
def test_a_cut_into_pieces_is_a_slice(text: str, scene: str, tasks: list[str]) -> None:
    assert read(text, scene) == (tasks, [], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene, reading",
    [
        # the cut's pieces taken together ("them") are a count no task keeps: still refused by name
        ("cut the bread into three slices and put them in the fridge", "FloorPlan1", "into three slices"),
        # an added thing with a lowercase article asks a task; a frame noun is frame; the guide's one
        # phrase is one thing
        ("Put the apple in the fridge. Later, the bread.", "FloorPlan17",
         ["place Apple -> Fridge", "place Bread -> Fridge"]),
        ("Put the egg in the bowl. The end.", "FloorPlan5", ["place Egg -> Bowl"]),
        ("put a bottle of wine in the fridge", "FloorPlan17", ["place WineBottle -> Fridge"]),
    ],
)
def test_near_misses_read_as_before(text: str, scene: str, reading: list[str] | str) -> None:
    got = read(text, scene)
    if isinstance(reading, str):
        assert got != "refused" and any(reading in u for u in got[1]), got
    else:
        assert got != "refused" and (got[0], got[1]) == (reading, []), got
