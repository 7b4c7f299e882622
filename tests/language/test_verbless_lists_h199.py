"""Issue 28, lists with the verb left out and noun-phrase requests, read as a careful reader means them (h199,
paper_h199dev.txt; `grammar/verbless_items.py`). Before each fix the reading was refused, partial or wrong:

- state words opening a verbless item ("a cold tomato in the bin, a heated egg in the fridge": refused);
- a list mixing placements and examinations ("the bowl under the desk lamp, two keychains in the drawer":
  refused; with "look at" said first, the keychains were looked at, wrong at exit 0);
- "the soap bottle to the cart and two sponges as well" (refused: a list of destinations);
- "two books - desk, pencil - shelf" (refused), a container's pair in a list ("a fork in a bowl with the bowl
  on the counter, and a clean pan on the dining table": the counter dropped at exit 0);
- "For the kitchen:" as a list's heading (refused).
The default run keeps one case per class; `-m sweep` reads the wording variants."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.learned.inference import parse_instruction
from nl2hltl2plan.language.task_specs import transitive_closure

ROOM = {
    "Tomato", "Egg", "Potato", "GarbageCan", "Fridge", "Microwave", "Bowl", "KeyChain", "Drawer", "Pencil",
    "DeskLamp", "FloorLamp", "SoapBottle", "DishSponge", "Cart", "Book", "Desk", "Shelf", "AlarmClock",
    "Fork", "CounterTop", "Pan", "DiningTable", "Pot", "StoveBurner", "Spoon", "RemoteControl", "CellPhone",
    "Sofa", "Watch", "SideTable", "SinkBasin", "Cloth", "BathtubBasin", "Plate",
}  # fmt: skip


def read_whole(text: str) -> tuple[list[str], set[tuple[str, str]]]:
    """(task summaries, the closure of the order as summary pairs); nothing may be left unread."""
    p = parse_instruction(text, ROOM, "room", strict=False)
    name = {t.id: t.summary() for t in p.tasks}
    unread = list(p.unparsed) + [str(u) for u in account(text, p.tasks, p.before)]
    assert not unread, unread
    order = {(name[a], name[b]) for a, b in transitive_closure(p.before, list(name))}
    return [t.summary() for t in p.tasks], order


TOMATO, EGG = "cool_place Tomato -> GarbageCan", "heat_place Egg -> Fridge"
BOWL, KEYS = "examine_in_light Bowl under DeskLamp", "place_two 2x KeyChain -> Drawer"
PENCIL = "examine_in_light Pencil under DeskLamp"


def test_state_words_open_verbless_items_and_give_the_treatment():
    assert read_whole("a cold tomato in the bin, a heated egg in the fridge") == ([TOMATO, EGG], set())


def test_each_item_of_a_mixed_list_gets_the_verb_its_preposition_says():
    text = "the bowl under the desk lamp, two keychains in the drawer, then the pencil under the desk lamp"
    assert read_whole(text) == ([BOWL, KEYS, PENCIL], {(KEYS, PENCIL)})


def test_a_verb_said_first_is_not_carried_to_an_item_of_the_other_kind():
    """Before: the keychains were examined under the lamp (wrong at exit 0)."""
    text = "look at the bowl under the desk lamp, two keychains in the drawer"
    assert read_whole(text) == ([BOWL, KEYS], set())


def test_too_carries_the_place_and_its_absence_does_not():
    tasks, _ = read_whole("The soap bottle to the cart and two sponges as well.")
    assert tasks == ["place SoapBottle -> Cart", "place_two 2x DishSponge -> Cart"]
    p = parse_instruction("The soap bottle to the cart and two sponges.", ROOM, "room", strict=False)
    assert p.unparsed or account("The soap bottle to the cart and two sponges.", p.tasks, p.before)


def test_a_dash_and_a_container_pair_are_list_items():
    tasks, _ = read_whole("two books - desk, pencil - shelf, alarm clock - desk")
    assert tasks == ["place_two 2x Book -> Desk", "place Pencil -> Shelf", "place AlarmClock -> Desk"]
    text = "For the kitchen: a fork in a bowl with the bowl on the counter, and a clean pan on the stove"
    tasks, _ = read_whole(text)
    assert tasks == ["place_in_container Fork in Bowl -> CounterTop", "clean_place Pan -> StoveBurner"]


@pytest.mark.sweep
@pytest.mark.parametrize(
    ("text", "tasks", "order"),
    [
        ("a cold tomato in the bin, a heated egg in the fridge, a washed potato in the microwave",
         [TOMATO, EGG, "clean_place Potato -> Microwave"], set()),
        ("One washed cloth, in the tub.", ["clean_place Cloth -> BathtubBasin"], set()),
        ("The remote under the floor lamp, the phone under the floor lamp, the watch on the sofa.",
         ["examine_in_light RemoteControl under FloorLamp", "examine_in_light CellPhone under FloorLamp",
          "place Watch -> Sofa"], set()),
        ("Two watches: side table. The remote under the floor lamp, light on.",
         ["place_two 2x Watch -> SideTable", "examine_in_light RemoteControl under FloorLamp"], set()),
        ("the watch on the sofa; the remote under the floor lamp",
         ["place Watch -> Sofa", "examine_in_light RemoteControl under FloorLamp"], set()),
        ("The remote under the floor lamp, then the phone under it too.",
         ["examine_in_light RemoteControl under FloorLamp", "examine_in_light CellPhone under FloorLamp"],
         {("examine_in_light RemoteControl under FloorLamp", "examine_in_light CellPhone under FloorLamp")}),
        ("the remote - sofa", ["place RemoteControl -> Sofa"], set()),
        ("cloth in the tub and two books too",
         ["place Cloth -> BathtubBasin", "place_two 2x Book -> BathtubBasin"], set()),
        ("a heated egg on the dining table, and a sponge on a plate, the plate on the dining table too",
         ["heat_place Egg -> DiningTable", "place_in_container DishSponge in Plate -> DiningTable"], set()),
        ("the alarm clock on the desk and the pencil too, then the book under the desk lamp",
         ["place AlarmClock -> Desk", "place Pencil -> Desk", "examine_in_light Book under DeskLamp"],
         {("place AlarmClock -> Desk", "examine_in_light Book under DeskLamp"),
          ("place Pencil -> Desk", "examine_in_light Book under DeskLamp")}),
        ("one cold egg, on the dining table", ["cool_place Egg -> DiningTable"], set()),
        ("the pencil on the shelf, then two more books on the desk",
         ["place Pencil -> Shelf", "place_two 2x Book -> Desk"],
         {("place Pencil -> Shelf", "place_two 2x Book -> Desk")}),
    ],
)  # fmt: skip
def test_verbless_lists_said_otherwise(text, tasks, order):
    assert read_whole(text) == (tasks, order)
