"""Issue 23 (h311): what trust_h303 found read at exit 0 with nothing named, as classes. A complete
request with an adjunct that no base task keeps (a repetition "again and again", a condition "provided the
bed is made", a duration in number words "for ninety seconds") is refused by name through
`vague_words.txt`; a ban said with no negation word ("..., leaving the watches alone", "keep your hands off
the vases") is read as the "don't touch" it is, with its constraint. Plain requests near those words stay
converted."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


Reading = tuple[list[str], list[tuple[str, str]], list[str], list[str]]


def read(text: str, plan: str = "FloorPlan28") -> Reading:
    from trust_sets import world_of

    return full_reading(text, world_of(plan))


def named(text: str, plan: str = "FloorPlan28") -> list[str]:
    """What a reading leaves unread ([] where it reads completely); a refusal's message as one item."""
    from nl2hltl2plan.errors import Nl2Hltl2PlanError

    try:
        return read(text, plan)[2]
    except Nl2Hltl2PlanError as exc:
        return [str(exc)]


@pytest.mark.data
@pytest.mark.parametrize(
    "text, words",
    [
        ("put the mug in the sink time after time", "time after time"),
        ("put the bread on the table provided that it is fresh", "provided that it"),
        ("put the apple in the fridge as long as it fits", "as long as"),
        ("heat the potato in the microwave for ninety seconds", "for ninety seconds"),
        ("put the apple in the fridge for half an hour", "for half an hour"),
        ("put the mug in the sink a couple of times", "a couple of times"),
    ],
)
def test_an_adjunct_no_base_task_keeps_is_named(text: str, words: str) -> None:
    said = named(text)
    assert said and any(repr(words) in u for u in said), said


@pytest.mark.data
@pytest.mark.parametrize(
    "text, plan, ban",
    [
        ("put the cd in the drawer, leaving the watches alone", "FloorPlan301", "don't touch the watches"),
        ("put the apple in the fridge and leave the eggs alone", "FloorPlan28", "don't touch the eggs"),
        ("put the key chain in the box; hands off the vases", "FloorPlan216", "don't touch the vases"),
    ],
)
def test_a_ban_said_without_a_negation_word_is_a_constraint(text: str, plan: str, ban: str) -> None:
    tasks, _, unread, forbids = read(text, plan)
    assert len(tasks) == 1 and unread == [] and [f.split(":")[0] for f in forbids] == [ban], (tasks, forbids)


@pytest.mark.data
def test_a_sentence_of_its_own_still_only_forbids_moving() -> None:
    """h205's reading stays: "Leave the mug alone." as a sentence of its own is "don't move the mug"."""
    forbids = read("Put the egg in the fridge. Leave the mug alone.")[3]
    assert forbids == ["don't move the mug: forbids pickup(Mug)"]


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "pick up the knife provided and slice the apple, then put a slice in the fridge",  # a participle
        "put the apple in the fridge, then put the mug in the sink again",  # a bare "again"
        "put the mug in the sink. Repeat with the cup.",  # a repeat for another thing (`grammar.repeats`)
        "put a second mug in the sink",  # an ordinal, no time
    ],
)
def test_plain_requests_near_those_words_read_completely(text: str) -> None:
    assert named(text) == []


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "put the statue on the shelf again and again",
        "put the pillow on the armchair time and time again",
        "put the mug in the sink over and over again",
        "put the mug in the sink every now and then",
        "keep putting the mug in the sink",
        "put the mug in the sink all day long",
        "put the mug in the sink, and repeat",
        "put the mug in the sink eleven times",
        "put the mug in the sink assuming it's dirty",
        "put the mug in the sink providing there is room",
        "put the mug in the sink on the condition that the egg is in the fridge",
        "put the mug in the sink should it be dirty",
        "put the mug in the sink when it's dirty",
        "put the mug in the sink as needed",
        "cool the tomato in the fridge for fifteen mins",
        "put the apple in the fridge for forty-five seconds",
        "put the apple in the fridge for an hour and a half",
        "put the apple in the fridge for 90 secs",
        "put the apple in the fridge for a minute or two",
        "put the apple in the fridge for another ten minutes",
        "put the apple in the fridge for the next hour",
        "put the apple in the fridge for a little bit",
        "microwave the potato two minutes",
    ],
)
def test_adjuncts_sweep(text: str) -> None:
    assert named(text), text
