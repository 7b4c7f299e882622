"""Issue 28, the classes session 28's held-out set (paper_h178.txt, results/language/h178.md) found, read as
a careful reader means them (h190, paper_h190dev.txt). Before each fix the reading was partial, refused or
wrong:

- a numbered list's closing order line by bare step number ("1) A 2) B. Do 2 first.": A before B, wrong), and
  a compound one ("2 before 1, and 4 last": the numbered turn, wrong; now refused by name);
- "carry X to the lamp and switch it on, then do the same with Y, and then with Z" (Y and Z unread);
- "the floor lamp one first" (the last examination taken, whatever its lamp: wrong);
- tasks named by description in an order sentence ("The washing jobs before the potato", "do the first two
  before the lamp ones": unread);
- a place referred back to with its state: "put the bottle there too once they're on it" (refused);
- a count opening a verbless placement ("Two rags to the shelf") and "a second box" (read as a time).
The default run keeps one case per class; `-m sweep` reads the wording variants."""

from __future__ import annotations

import pytest
from grammar_readings import offline_reading
from household_readings import reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.translate import translate

ROOM = {
    "CreditCard", "Watch", "Statue", "Plate", "Pillow", "Box", "KeyChain", "Sofa", "Shelf", "FloorLamp",
    "DeskLamp", "Mug", "CoffeeMachine", "ButterKnife", "CounterTop", "Potato", "GarbageCan", "Microwave",
    "SinkBasin", "Cloth", "SoapBottle", "SprayBottle", "Toilet", "Apple", "DiningTable", "Fridge", "Egg",
}  # fmt: skip


def read(text: str) -> tuple[list[str], set[tuple[str, str]], list[str]]:
    """(task summaries, the closure of the order as summary pairs, every unread word or clause)."""
    return offline_reading(text, ROOM)


def read_whole(text: str) -> tuple[list[str], set[tuple[str, str]]]:
    tasks, order, unread = read(text)
    assert not unread, unread
    return tasks, order


def looks(*things: str, lamp: str = "FloorLamp") -> list[str]:
    return [f"examine_in_light {t} under {lamp}" for t in things]


def chain(tasks: list[str]) -> set[tuple[str, str]]:
    return {(a, b) for k, a in enumerate(tasks) for b in tasks[k + 1 :]}


MUG, KNIFE = "clean_place Mug -> CoffeeMachine", "clean_place ButterKnife -> CounterTop"
POTATO = "heat_place Potato -> GarbageCan"


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


MUG_SINK, APPLE_FRIDGE = "place Mug -> SinkBasin", "place Apple -> Fridge"


@pytest.mark.data
def test_a_bare_step_number_orders_a_numbered_list(kitchen):
    """Before: "Do 2 first." was read as nothing, and the numbers as the order (A before B: wrong)."""
    text = "1) put the apple in the fridge 2) put the mug in the sink. Do 2 first."
    assert reading(text, kitchen) == ([MUG_SINK, APPLE_FRIDGE], [("A", "B")])


@pytest.mark.data
def test_a_compound_step_order_is_refused_by_name(kitchen):
    """Before: "2 before 1, and 3 last" was left unread and the steps read in their numbered turn (wrong)."""
    steps = "1. put the apple in the fridge 2. put the mug in the sink 3. put the egg in the sink."
    text = f"{steps} 2 before 1, and 3 last."
    with pytest.raises(HTTError, match="'2 before 1, and 3 last'"):
        translate(text, kitchen, build=False, actions="none")


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "1. put the apple in the fridge 2. put the mug in the sink - do 2 first",
        "1) put the apple in the fridge 2) put the mug in the sink. 2 before 1.",
        "1. put the apple in the fridge 2. put the mug in the sink. 1 last.",
        "Here's the plan: 1) put the apple in the fridge 2) put the mug in the sink. Do number 2 first.",
    ],
)
def test_bare_step_numbers_said_otherwise(text, kitchen):
    assert reading(text, kitchen) == ([MUG_SINK, APPLE_FRIDGE], [("A", "B")])


def test_carried_to_the_lamp_and_repeated_for_two_more_things():
    """Before: "do the same with the statue, and then with a plate" found no task to repeat (partial)."""
    text = "Take a pillow to the floor lamp and turn it on,"
    text += " then do the same with the statue, and then with a plate."
    tasks, order = read_whole(text)
    assert tasks == looks("Pillow", "Statue", "Plate") and order == chain(tasks)


def test_the_floor_lamp_one_is_the_task_under_that_lamp():
    """Before: "the floor lamp one" took the last examination (under the desk lamp): wrong."""
    text = "Look at the watch under the desk lamp. Look at the statue under the floor lamp. "
    text += "The floor lamp one first."
    tasks, order = read_whole(text)
    assert order == {(looks("Statue")[0], looks("Watch", lamp="DeskLamp")[0])}


def test_tasks_named_by_their_treatment_in_an_order_sentence():
    """Before: "The washing jobs before the potato" was unread (partial)."""
    text = (
        "Rinse a mug and put it in the coffee maker; rinse a butter knife and put it on the counter; "
        "microwave a potato and throw it in the bin. The washing jobs before the potato."
    )
    assert read_whole(text) == ([MUG, KNIFE, POTATO], {(MUG, POTATO), (KNIFE, POTATO)})


def test_a_place_referred_back_with_the_state_of_what_is_on_it():
    """Before: refused ("goes there too once they're on it" named no task)."""
    text = "Two soap bottles go on the toilet, and the spray bottle goes there too once they're on it."
    two, spray = "place_two 2x SoapBottle -> Toilet", "place SprayBottle -> Toilet"
    assert read_whole(text) == ([two, spray], {(two, spray)})


def test_a_count_opens_a_verbless_placement_and_a_second_box_is_no_time():
    """Before: "Two rags to the shelf" was refused, and "a second box" read as a time ("in a second")."""
    assert read_whole("Two rags to the shelf, please.")[0] == ["place_two 2x Cloth -> Shelf"]
    tasks, _ = read_whole("Put the keys in a second box and set that box on the sofa.")
    assert tasks == ["place_in_container KeyChain in Box -> Sofa"]


@pytest.mark.sweep
@pytest.mark.parametrize(
    ("text", "first", "then"),
    [
        ("Bring the box over to the desk lamp and switch it on. Then put the mug in the sink.",
         "examine_in_light Box under DeskLamp", "place Mug -> SinkBasin"),
        ("Carry the statue to the floor lamp and turn on the lamp, then put the box on the sofa.",
         "examine_in_light Statue under FloorLamp", "place Box -> Sofa"),
        ("Put the box on the sofa and look at the watch under the floor lamp. Do the lamp one first.",
         "examine_in_light Watch under FloorLamp", "place Box -> Sofa"),
        ("Heat an egg and put it in the fridge, and wash a mug and put it in the sink. "
         "The washing one first.",
         "clean_place Mug -> SinkBasin", "heat_place Egg -> Fridge"),
        ("Put the box on the sofa. Heat an apple and put it on the dining table, and heat an egg and put "
         "it there too once the apple is on it.",
         "heat_place Apple -> DiningTable", "heat_place Egg -> DiningTable"),
        ("Rinse a cloth and put it in the sink. Then put the mug in the same sink once the cloth is in.",
         "clean_place Cloth -> SinkBasin", "place Mug -> SinkBasin"),
        ("Put the box on the sofa and two mugs in the sink - the sink ones go first.",
         "place_two 2x Mug -> SinkBasin", "place Box -> Sofa"),
        ("Heat an egg and put it on the counter. Put the box on the sofa. Counter ones first.",
         "heat_place Egg -> CounterTop", "place Box -> Sofa"),
        ("Put the box on the sofa. Wash a mug and put it in the sink. Do the washing one before the others.",
         "clean_place Mug -> SinkBasin", "place Box -> Sofa"),
    ],
)
def test_orders_said_by_these_classes(text, first, then):
    tasks, order = read_whole(text)
    assert first in tasks and then in tasks and (first, then) in order and (then, first) not in order


@pytest.mark.sweep
@pytest.mark.parametrize(
    "text",
    [
        "Two boxes to the sofa and two mugs to the same sofa.",
        "Put the box on the sofa. Put the mug in the sink. Look at the watch under the floor lamp. Look at "
        "the statue under it too. Do the first two before the lamp ones.",
        "Put a plate on the shelf and put a box on the sofa. Look at the watch under the floor lamp, but not "
        "until both box jobs are done.",
    ],
)
def test_more_of_these_classes_read_whole(text):
    read_whole(text)
