"""Headings that count what follows in the tabletop world (`tabletop_headings`): read where the reading
makes that many placements or the labelled steps are that many stages, refused by name otherwise; the
count is never dropped."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.headings import counted_headings
from nl2hltl2plan.language.translate import translate
from tests.language.tabletop_readings import WORLD, pairs_read

TWO = (sorted([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")]), [])
STAGED = (
    sorted([("GreenApple", "YellowPlate"), ("Carrot", "BluePlate")]),
    [(("GreenApple", "YellowPlate"), ("Carrot", "BluePlate"))],
)


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("Two things: green apple goes on the blue plate; orange goes on the yellow plate. Sequence is "
         "irrelevant.", TWO),
        ("2 placements to do: the green apple on the blue plate; the orange on the yellow plate.", TWO),
        ("Two stages. Stage one: put the green apple on the yellow plate. Stage two: put the carrot on the "
         "blue plate.", STAGED),
        ("There are two steps: Step 1 - green apple onto the yellow plate; Step 2 - carrot onto the blue "
         "plate.", STAGED),
    ],
)
def test_a_heading_whose_count_the_reading_keeps_is_read(text, read):
    assert pairs_read(text) == read


@pytest.mark.parametrize(
    "text",
    [
        "Three moves: the green apple on the blue plate and the orange on the yellow plate.",
        "Two things: green apple on the blue plate, orange on the yellow plate, carrot on the pink plate.",
        "Four placements to do: carrot on the blue plate; orange on the yellow plate; green apple on the "
        "green plate.",
        "Three things: put the green apple on the blue plate. Then put the orange on the yellow plate.",
    ],
)
def test_a_count_of_things_the_reading_does_not_make_is_named(text):
    heading = text.split(":")[0]
    try:
        res = translate(text, WORLD, build=False)
    except HTTError as exc:  # the grammar leaves a clause under a heading's count unread: all refused
        assert heading in str(exc)
        return
    assert res.partial and any("(count)" in u and "it counts" in u for u in res.unparsed)


@pytest.mark.parametrize(
    "text",
    [
        "Three stages. Stage one: put the green apple on the yellow plate. Stage two: put the carrot on the "
        "blue plate.",
        "Two stages. Stage one: put the green apple on the yellow plate. Stage two: put the carrot on the "
        "blue plate. Stage three: put the orange on the pink plate.",
        "Two steps: put the green apple on the blue plate, then put the orange on the yellow plate.",
    ],
)
def test_a_count_of_stages_the_labels_do_not_keep_is_refused_by_name(text):
    with pytest.raises(HTTError, match=r"counts \w+ stages"):
        translate(text, WORLD, build=False)


def test_what_is_added_is_no_count_of_all():
    assert counted_headings("One more thing: the carrot on the blue plate.") == []
    assert counted_headings("Two last things - the carrot and the orange.") == []
    assert [h.number for h in counted_headings("Then, two last things. Three jobs - ...")] == [3]
