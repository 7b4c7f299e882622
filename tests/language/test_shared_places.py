"""Issue 23 (h218): a place said once for a list of things. Two heated things are put where "them" goes,
not left in the microwave; "plus" with no place of its own adds a thing to the placing before it; two of one
type share a destination said with a landmark. A lamp switched on after a thing is carried to a place is
refused (held under it, or left there?). A reference that says what was done to its thing ("after you've
chilled the glass") names that task."""

from __future__ import annotations

from pathlib import Path

import pytest

from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.task_specs import transitive_closure

ROOM = {
    "Apple", "Bread", "Egg", "Mug", "Cup", "Plate", "Fork", "Kettle", "SoapBar", "Candle", "KeyChain",
    "Watch", "Potato", "Pencil", "Pen", "Fridge", "Microwave", "CounterTop", "SinkBasin", "Cabinet", "Drawer",
    "Toilet", "Safe", "GarbageCan", "Desk",
}  # fmt: skip


def read(text: str) -> tuple[list[str], list[str]]:
    r = parse_instruction(text, ROOM, "room", affordances=lambda t: None)
    return [t.summary() for t in r.tasks], r.unparsed


@pytest.mark.parametrize(
    "text, tasks",
    [
        (
            "Heat an apple and a potato in the microwave and put each of them on the counter.",
            ["heat_place Apple -> CounterTop", "heat_place Potato -> CounterTop"],
        ),
        (
            "chill an apple and an egg in the fridge and put them in the sink",
            ["cool_place Apple -> SinkBasin", "cool_place Egg -> SinkBasin"],
        ),
        (  # "plus" with no place of its own: the thing goes where the one before goes
            "Throw two bars of soap into the bin, plus the candle.",
            ["place_two 2x SoapBar -> GarbageCan", "place Candle -> GarbageCan"],
        ),
        (  # "and" or "plus" with a place of its own gives the thing its own destination, as before
            "put the soap bar in the bin, plus the candle on the toilet",
            ["place SoapBar -> GarbageCan", "place Candle -> Toilet"],
        ),
        (  # one place said once for both, with where it is: one task for two of a type
            "put the red mug and the blue mug in the cabinet under the counter",
            ["place_two 2x Mug -> Cabinet"],
        ),
        (  # two places of their own: each goes its own way (the landmark is not the first one's place)
            "put a soap bar on the counter under the sink and another soap bar in the sink",
            ["place SoapBar -> CounterTop", "place SoapBar -> SinkBasin"],
        ),
    ],
)
def test_a_place_said_once_for_a_list(text, tasks):
    assert read(text) == (tasks, [])


def test_a_lamp_after_carrying_to_a_place_is_refused_naming_why():
    """ "carry X to the desk and switch on the lamp": held under the lamp, or left on the desk? (h159held)"""
    why = "the pen carried to the desk: held under the lamp, or left there"
    _, unparsed = read("carry the pen to the desk and switch on the desk lamp")
    assert any(why in u for u in unparsed), unparsed
    # "put" says it is left there; "to look at it", and a lamp carried to, say it is held
    for text in (
        "put the pen on the desk and switch on the desk lamp",
        "carry the pen to the desk and switch on the lamp to look at it",
        "carry the pen to the desk lamp and switch it on",
    ):
        assert not any("carried to" in u for u in read(text)[1]), text


@pytest.mark.parametrize(
    "text, first",
    [
        (
            "Cool a cup and put it in the sink, and put a heated cup on the counter. After you've cooled the "
            "cup, put the egg in the fridge.",
            "cool_place Cup -> SinkBasin",
        ),
        (
            "Wash a mug and put it in the cabinet. Put a warm mug on the counter. Once you've washed the "
            "mug, put the apple in the fridge.",
            "clean_place Mug -> Cabinet",
        ),
    ],
)
def test_a_reference_by_its_treatment_names_that_task(text, first):
    r = parse_instruction(text, ROOM, "room", affordances=lambda t: None)
    name = {t.id: t.summary() for t in r.tasks}
    order = {(name[a], name[b]) for a, b in transitive_closure(r.before, list(name))}
    assert order == {(first, r.tasks[-1].summary())}, order


HELD = Path(__file__).parent / "data" / "known_wrong_h218_held.txt"
# held-out lines read otherwise at the scoring: the refusal of "plus X on Y" was withdrawn before it
# (users_h154's sets read Y as X's destination), so the line reads a destination
HELD_MISSED = {"put the watch in the safe, plus the keychain on the desk"}


@pytest.mark.sweep
@pytest.mark.parametrize(
    "line", [ln for ln in HELD.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
)
def test_held_out_near_misses(line):
    text, tasks, refused = (part.strip() for part in line.split("|"))
    if text in HELD_MISSED:
        pytest.xfail("withdrawn rule (HELD_MISSED)")
    got, unparsed = read(text)
    if refused:
        assert any(refused in u for u in unparsed), unparsed
    elif not unparsed:  # a refusal is honest, never wrong (as the style sets' sweep counts it)
        assert got == [t.strip() for t in tasks.split(";")]


@pytest.mark.parametrize(
    "text, pairs, refused",
    [
        (  # h226: a closing "afterwards" of a list whose last thing has a place of its own orders that thing
            "put the mug in the sink, and the egg in the fridge afterwards",
            {("place Mug -> SinkBasin", "place Egg -> Fridge")},
            "",
        ),
        (
            "put the mug in the sink and the egg in the fridge after that",
            {("place Mug -> SinkBasin", "place Egg -> Fridge")},
            "",
        ),
        ("put the knife and the fork in the drawer afterwards", set(), ""),  # one place: the list stays whole
        (  # after a sentence with an order of its own (check 1 saw an order and passed it at exit 0)
            "put the apple on the counter. Then put the mug in the sink, and the egg in the fridge later",
            {("place Apple -> CounterTop", x) for x in ("place Mug -> SinkBasin", "place Egg -> Fridge")}
            | {("place Mug -> SinkBasin", "place Egg -> Fridge")},
            "",
        ),
    ],
)
def test_a_closing_order_word_of_a_list(text, pairs, refused):
    r = parse_instruction(text, ROOM, "room", affordances=lambda t: None)
    name = {t.id: t.summary() for t in r.tasks}
    assert {(name[a], name[b]) for a, b in transitive_closure(r.before, list(name))} == pairs
    assert any(refused in u for u in r.unparsed) if refused else r.unparsed == []
