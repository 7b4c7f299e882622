"""Near misses of the courtesy and negation readers (issue 23, h208): a sign-off's name that is also a thing,
an exclusion from a whole ("all but the mug") and a verbless swap ("Rather than the mug, the apple.") were
read as one more task at exit 0; each is now named unread (a refusal), and a sign-off with a person's name
still reads."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    from trust_sets import world_of

    return full_reading(text, world_of("FloorPlan28"))


@pytest.mark.data
@pytest.mark.parametrize(
    "text, named",
    [
        ("Put the egg in the fridge. Cheers, Mug", "Cheers, Mug"),
        ("Please put the egg in the fridge. Thank you mug!", "Thank you mug!"),
        # found by the held-out batch, mended after it was scored: "take care" was no sign-off word
        ("Put the bread on the counter. Take care - Tomato", "Take care - Tomato"),
        ("Put all but the mug in the sink", "all but"),
        ("Put every item but the apple in the fridge", "every item but"),
        ("Put the egg in the fridge. Rather than the mug, the apple.", "Rather than the mug, the apple"),
        ("Put the mug in the sink. Thanks for putting the egg in the fridge", "Thanks for putting"),
        ("Put the egg in the fridge and the apple in the sink. Actually leave the apple.", "leave the apple"),
    ],
)
def test_an_unclear_name_exclusion_or_swap_is_named(text, named):
    unread = read(text)[2]
    assert any(named in u for u in unread), unread


@pytest.mark.data
def test_a_sign_off_with_a_persons_name_still_reads():
    tasks, before, unread, forbids = read("Put the egg in the fridge. Cheers, Sam")
    assert (tasks, unread, forbids) == (["place Egg -> Fridge"], [], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, task, forbidden",
    [
        # "in the sink" was read as washing: clean_place Mug -> Fridge at exit 0
        ("Instead of putting the mug in the sink, put it in the fridge", "place Mug -> Fridge",
         "put(Mug,SinkBasin)"),
        # the heating that was to be skipped was done: heat_place Potato -> Fridge at exit 0
        ("Rather than heating the potato, put it in the fridge", "place Potato -> Fridge", "heat(Potato)"),
    ],
)
def test_instead_of_doing_is_a_negation(text, task, forbidden):
    tasks, before, unread, forbids = read(text)
    assert (tasks, unread) == ([task], [])
    assert len(forbids) == 1 and forbidden in forbids[0], forbids
