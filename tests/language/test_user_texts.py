"""Issue 28 and 23, household user voices (h154, tests/language/data/styles/users_h154dev.txt): a text
message's trailing fillers ("and yeah", "or whatever", "k thx"), a reason after a request ("so it stays
cold"), a correction said as "actually no" or opening the next sentence, "plus" joining a list, and one
thing put in two places in sequence. Each with a near miss that must still be read or refused, never
dropped: the filler "and yeah" once became a second destination, which the learned re-read then turned into
a cooling ("put the apple in the fridge and yeah")."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from grammar_readings import sorted_reading
from household_readings import reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.courtesy import without_courtesy, without_reasons

ROOM = {"Apple", "Lettuce", "Egg", "Mug", "Book", "Pen", "Fridge", "SinkBasin", "CounterTop", "Desk", "Bed"}
ROOM |= {"Safe"}
LETTUCE, MUG = "place Lettuce -> Fridge", "place Mug -> SinkBasin"


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan2")


@pytest.mark.parametrize(
    "text",
    [
        "put the lettuce in the fridge and yeah",
        "put the lettuce in the fridge, and yeah that's it.",
        "put the lettuce in the fridge or whatever k thx",
        "put the lettuce in the fridge lol",
    ],
)
def test_a_trailing_filler_is_no_list_item(text):
    assert sorted_reading(without_courtesy(text), ROOM) == ([LETTUCE], set(), [])


@pytest.mark.parametrize(
    "text, kept",
    [
        ("put the lettuce in the fridge or whatever is left", "or whatever is left"),  # not at the end
        ("yeah, put the lettuce in the fridge", "yeah,"),  # an opener, the grammar's
        ("put the lettuce in the fridge and stuff", "and stuff"),  # may name more things: stays
    ],
)
def test_a_filler_that_does_not_end_a_sentence_stays(text, kept):
    assert kept in without_courtesy(text)


@pytest.mark.parametrize(
    "text",
    [
        "put the lettuce in the fridge so it stays cold",
        "put the lettuce in the fridge because we're out of room on the counter",
        "put the lettuce in the fridge so that nobody eats it",
        "put the lettuce in the fridge cause it keeps wilting",
        "put the lettuce in the fridge so I can slice it later",  # the speaker's own purpose
    ],
)
def test_a_reason_after_a_request_asks_for_nothing(text):
    assert sorted_reading(without_reasons(text), ROOM) == ([LETTUCE], set(), [])


def test_a_reason_ends_where_the_next_request_starts():
    text = "put the lettuce in the fridge so it stays fresh, then put the mug in the sink because it's dirty"
    assert sorted_reading(without_reasons(text), ROOM) == ([LETTUCE, MUG], {(LETTUCE, MUG)}, [])
    text = "put the mug in the sink because it's dirty and put the lettuce in the fridge"
    assert without_reasons(text) == "put the mug in the sink and put the lettuce in the fridge"


@pytest.mark.parametrize(
    "text, unread",
    [
        ("put the mug in the sink so it gets washed", ["washed"]),  # may ask for the washing
        ("put the lettuce in the fridge so that it gets cold", ["cold"]),
        ("put the mug in the sink so you can wash it later", ["wash"]),  # speaks to the one asked
    ],
)
def test_a_reason_that_may_ask_stays_and_is_named(text, unread):
    assert without_reasons(text) == text
    tasks, _, named = sorted_reading(without_reasons(text), ROOM)
    assert [w for w in unread if any(w in n for n in named)] == unread


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        ("put the egg in the fridge, actually no, the potato", ["place Potato -> Fridge"]),
        ("put the egg in the fridge. sorry, I mean the potato", ["place Potato -> Fridge"]),
        ("put the egg in the fridge, actually no, put it on the counter", ["place Egg -> CounterTop"]),
        (  # the same thing named again with a place: the place is corrected
            "put the mug in the sink, no wait, the mug in the cabinet",
            ["place Mug -> Cabinet"],
        ),
    ],
)
def test_corrections_as_people_text_them(text, tasks, kitchen):
    assert reading(text, kitchen)[0] == tasks


@pytest.mark.data
@pytest.mark.parametrize(
    "text, words",
    [
        # a bowl is a thing and a place: which word it replaces is unclear
        ("put the cup in the sink, actually no, the bowl", "'cup' or 'sink'"),
        ("put the egg in the fridge, actually no, put it on the counter too", "'too'"),  # replaces or adds
    ],
)
def test_an_unclear_correction_is_refused_by_name(text, words, kitchen):
    from nl2hltl2plan.language.translate import translate

    with pytest.raises(HTTError, match=words):
        translate(text, kitchen, build=False, actions="none")


@pytest.mark.parametrize(
    "text, tasks, order",
    [
        (
            "put the book on the bed then the pen on the desk plus the egg in the safe",
            ["place Book -> Bed", "place Egg -> Safe", "place Pen -> Desk"],
            {("place Book -> Bed", "place Pen -> Desk"), ("place Book -> Bed", "place Egg -> Safe")},
        ),
        ("put the book plus the pen on the bed", ["place Book -> Bed", "place Pen -> Bed"], set()),
    ],
)
def test_plus_joins_a_list_as_and_does(text, tasks, order):
    assert sorted_reading(text, ROOM) == (tasks, order, [])


def test_one_thing_put_in_two_places_in_sequence_is_two_tasks():
    desk, bed = "place Book -> Desk", "place Book -> Bed"
    for joiner in (", then", " and then"):
        text = f"put the book on the desk{joiner} put it on the bed"
        tasks, order, _ = sorted_reading(text, ROOM)
        assert (tasks, order) == ([bed, desk], {(desk, bed)})
    # near misses: no sequence word, or the first place the treatment's appliance, still one task
    assert sorted_reading("put the book on the desk and put it on the bed", ROOM)[0] == [bed]
    assert len(sorted_reading("put the mug in the sink, then put it on the counter", ROOM)[0]) == 1


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h154dev", "users_h154held"])
def test_the_h154_user_set_reads_nothing_wrong(name):
    """h154's user voices, read as `plan` reads them: no line is read wrong, and 80 % convert (the rest are
    refused by name: a correction that may replace two words, one thing put in two places)."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [trust_sets.outcome(gt) for gt in trust_sets.load(name)]
    assert [why for what, why in outcomes if what == "wrong"] == []
    assert sum(what == "converted" for what, _ in outcomes) >= 0.8 * len(outcomes)
