"""h294 (issue 28): a household list's rows and items, and three plain references. A row's or an item's label
("Row 1 -", "item 3 -", "hack number two:", "(a)") is a heading, never a count or an order; "x2" counts the
things; "same" / "ditto" repeats the item before; a row that only picks a thing up is continued by the next;
"X first" said after X orders it first; "goes on there too" is the place named before; "do the same with A,
and then with B" is two examinations in turn."""

from __future__ import annotations

import pytest
from household_readings import full_reading, reading

from nl2hltl2plan.language.grammar.sentences import normalize
from nl2hltl2plan.language.headings import row_labels_dropped
from nl2hltl2plan.language.household_forms import counts_before, items_said

MUG_SINK, APPLE_FRIDGE = "place Mug -> SinkBasin", "place Apple -> Fridge"


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


def test_a_count_written_after_the_things_is_read_before_them():
    text = "candles x2 - drawer; 2x spray bottles -> sink; soap bars (2) - cabinet"
    said = "two candles - drawer; two spray bottles -> sink; two soap bars - cabinet"
    assert counts_before(text) == said
    assert counts_before("Van at 9. Box 7 x 12") == "Van at 9. Box 7 x 12"  # no count of things


def test_row_labels_are_headings_and_an_order_word_keeps_its_label():
    dropped: list[str] = []
    said = row_labels_dropped("Row 1 - A. Row 2 - B. Work the rows in order.", dropped)
    assert (said, dropped) == ("A. B. Do them in that order.", ["Row 1", "Row 2"])
    kept = "Next item: put the mug in the sink."
    assert row_labels_dropped(kept, []) == kept


def test_labels_give_no_order_and_the_rows_in_order_give_one(kitchen):
    rows = "Row 1 - put the mug in the sink. Row 2 - put the apple in the fridge."
    assert reading(rows, kitchen) == ([MUG_SINK, APPLE_FRIDGE], [])
    assert reading(rows + " Work the rows in order.", kitchen) == ([MUG_SINK, APPLE_FRIDGE], [("A", "B")])
    hacks = (
        "bathroom hack number one: put the mug in the sink. Hack number two: rinse an apple and put it in "
        "the fridge."
    )
    assert reading(hacks, kitchen) == ([MUG_SINK, "clean_place Apple -> Fridge"], [])


def test_an_item_names_its_thing_first_and_same_repeats_the_one_before(kitchen):
    assert items_said("cloth - rinse well, then leave in the bathtub") == (
        "rinse the cloth well and leave it in the bathtub"
    )
    said = reading("item 1 - mug, wash, into the sink; item 2 - apple, same", kitchen)
    assert said == (["clean_place Mug -> SinkBasin", "clean_place Apple -> SinkBasin"], [])


def test_a_row_that_only_picks_up_is_continued_by_the_next(kitchen):
    text = "Row 1 - pick up the egg. Row 2 - chill it and put it on the counter."
    assert reading(text, kitchen) == (["cool_place Egg -> CounterTop"], [])


def test_first_said_after_the_thing_orders_its_task_first(kitchen):
    text = "Put the mug in the sink. Heat an apple first and put it in the fridge."
    assert reading(text, kitchen) == ([MUG_SINK, "heat_place Apple -> Fridge"], [("B", "A")])


def test_goes_on_there_too_is_the_place_named_before_not_the_source(kitchen):
    text = "Put the mug on the counter. The apple from the fridge goes on there too."
    tasks = ["place Mug -> CounterTop", "place Apple -> CounterTop"]
    assert full_reading(text, kitchen)[:3] == (tasks, [], [])


def test_the_same_with_one_and_then_another_is_two_examinations_in_turn():
    said = normalize(
        "Turn the desk lamp on and look at the mug under it. "
        "Then do the same with a pen, and then with the box."
    )
    assert "Then look at a pen under the desk lamp. Then look at the box under the desk lamp" in said
