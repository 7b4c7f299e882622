"""A plate that waits (`tabletop_waits`) and a frame that names nothing (`tabletop_remarks.frame_read`): read
where that is all they say, refused otherwise."""

from __future__ import annotations

import pytest

from tests.language.test_tabletop_pairs import _reading

YELLOW_THEN_BLUE = [
    (("GreenApple", "YellowPlate"), ("Carrot", "BluePlate")),
    (("Orange", "YellowPlate"), ("Carrot", "BluePlate")),
]


def _order(text: str) -> list | None:
    """The closed order by (object, plate) of a full reading; None on a refusal or a partial reading."""
    read = _reading(text)
    return None if read is None else read[1]


@pytest.mark.parametrize(
    "text",
    [
        "Don't touch the blue plate until the green apple and the orange are on the yellow plate. Then put "
        "the carrot on the blue plate.",
        "Keep the blue plate empty until the green apple and the orange are on the yellow plate; the carrot "
        "goes on the blue plate.",
        "Nothing goes onto the blue plate until the green apple and the orange are on the yellow plate, then "
        "the carrot goes on the blue plate.",
        "Put the green apple and the orange on the yellow plate before anything goes on the blue plate. Then "
        "put the carrot on the blue plate.",
        "The yellow plate gets the green apple and the orange before the blue plate gets anything; the "
        "carrot goes on the blue plate.",
    ],
)
def test_a_plate_that_waits_orders_its_placements_after_what_it_waits_for(text):
    assert _order(text) == YELLOW_THEN_BLUE


@pytest.mark.parametrize(
    "text",
    [
        # a placement after the clause on another plate: the clause does not order it
        "Don't touch the blue plate until the green apple is on the yellow plate. Then put the carrot on "
        "the blue plate and the orange on the pink plate.",
        # the placement after it names no plate ("it" could be either)
        "Nothing goes onto the blue plate until the green apple is on the yellow plate, then the carrot goes "
        "on it.",
        # what it waits for is on the waiting plate itself
        "Leave the blue plate alone until the green apple is on the blue plate, then put the carrot on the "
        "blue plate.",
        # the clause does not open the text
        "Put the orange on the pink plate. Don't touch the blue plate until the green apple is on the "
        "yellow plate, then put the carrot on the blue plate.",
    ],
)
def test_a_plate_that_waits_and_says_more_is_not_read_as_an_order(text):
    assert _order(text) is None


@pytest.mark.parametrize(
    "text",
    [
        "Helm, set the green apple on the blue plate and the orange on the yellow plate. Make it so.",
        "Ahoy matey: the green apple on the blue plate, the orange on the yellow plate.",
        "Where should things end up? The green apple on the blue plate, the orange on the yellow plate.",
        "Quick one: green apple on the blue plate, orange on the yellow plate. Off you go!",
    ],
)
def test_a_frame_that_names_and_says_nothing_is_no_part_of_the_request(text):
    """A short clause that opens the text and greets, addresses or titles, or one that urges (no word of
    check 1's and no
    word of order, place or manner), and a question heading that asks where things go."""
    assert _order(text) == []


@pytest.mark.parametrize(
    "text",
    [
        "In reverse: the green apple on the blue plate, the orange on the yellow plate.",
        "Alphabetically: the orange on the yellow plate, the carrot on the blue plate.",
        "The orange on the yellow plate, the carrot on the blue plate. By size, obviously.",
        "Where are things? The green apple on the blue plate, the orange on the yellow plate.",
    ],
)
def test_a_clause_that_could_say_more_is_no_frame(text):
    """An order, and a question about where things are: not a frame, refused."""
    assert _order(text) is None


def test_a_goal_heading_is_no_frame():
    """ "Final layout:" asks for the states listed after it (removed, they would be refused as stated)."""
    assert _order("Final layout: blue plate has the green apple, yellow plate has the orange.") == []


@pytest.mark.parametrize(
    "text",
    [
        "Quick ask: the carrot on the blue plate, the orange on the yellow plate. Just do it.",
        "carrot | blue plate\norange | yellow plate\n(ordering: up to you)",
        "the carrot on the blue plate and the orange on the yellow plate, whichever you like first",
        "Two things, in any order - the carrot on the blue plate, the orange on the yellow plate.",
        "Plan for a sorted table: carrot on the blue plate, orange on the yellow plate.",
        "Carrot on the blue plate, orange on the yellow plate. Change the order however you like.",
    ],
)
def test_announcements_order_labels_and_dash_headings_leave_the_pairs_unordered(text):
    assert _order(text) == []


def test_a_dash_heading_must_count_the_placements_after_it():
    assert _order("Three things - the carrot on the blue plate, the orange on the yellow plate.") is None


def test_a_then_between_a_named_subject_and_its_verb_opens_its_clause():
    text = "The green apple and the orange go on the yellow plate; the carrot then goes on the blue plate."
    assert _order(text) == YELLOW_THEN_BLUE


@pytest.mark.parametrize(
    "text",
    [
        "> put green apple on yellow plate\n> wait\n> put carrot on blue plate",
        "Memo: priority goes to the yellow plate (green apple); the blue plate (carrot) follows.",
        "The green apple on the yellow plate and the carrot on the blue plate. Pause.",
        "Ok: carrot on the blue plate. Orange on the yellow plate. Sequentially.",
    ],
)
def test_an_order_said_by_a_wait_a_priority_or_what_follows_is_never_dropped(text):
    """Words that say an order though check 1 lists none of them: refused, never read as no order."""
    assert _order(text) is None


@pytest.mark.parametrize(
    "text, order",
    [
        ("First the green apple and the orange go on the yellow plate. Then, and only then, the carrot goes "
         "on the blue plate.", YELLOW_THEN_BLUE),
        ("Load the yellow plate with the green apple and the orange; once it's loaded, load the blue plate "
         "with the carrot.", YELLOW_THEN_BLUE),
        ("Job card: carrot - blue plate, orange - yellow plate. Order not critical.", []),
        ("Please, in no special order: carrot to the blue plate, orange to the yellow plate.", []),
    ],
)
def test_orders_and_freedoms_said_in_other_words(text, order):
    assert _order(text) == order


@pytest.mark.parametrize(
    "text",
    [
        "Plan A: put the carrot on the blue plate. Plan B: put the orange on the yellow plate.",
        "Option 1: put the carrot on the blue plate. Option 2: put the orange on the yellow plate.",
    ],
)
def test_labels_that_name_alternatives_are_no_steps(text):
    """Which alternative is meant is not said: refused, never read as steps or as both."""
    assert _order(text) is None
