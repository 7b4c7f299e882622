"""Issues 28 / 23 (h160): where a household task's object and source are read. "with X" after a movable
receptacle makes X its content only when a hand picks X up and the receptacle takes it ("the mug on the
dresser with the television" read a Television in the Mug); a possessive is a source ("the drawer's
spoon" is the spoon from the drawer), and one whose owner an ordinal picks ("the second drawer's spoon")
is refused by name, never read as any spoon."""

from __future__ import annotations

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import alfred_lookup
from nl2hltl2plan.language.learned.inference import parse_instruction
from nl2hltl2plan.worlds.world import Affordances

BEDROOM = {
    "Mug", "Bowl", "Box", "Pencil", "Pen", "Laptop", "Dresser", "Desk", "Bed", "Drawer", "CounterTop",
    "Spoon", "SinkBasin", "Fridge", "Apple", "Pillow", "ArmChair", "DeskLamp",
}  # fmt: skip


def read(text: str, lacking: str = "") -> tuple[list[str], list[str]]:
    """(task summaries, every unread word or clause); `lacking`: a type the world's affordances do not
    know, as a floor plan whose object list names a thing its built world lacks."""
    alfred = alfred_lookup()
    assert alfred is not None

    def look(t: str) -> Affordances | None:
        return None if t == lacking else alfred(t)

    p = parse_instruction(text, BEDROOM, "bedroom", strict=False, affordances=look)
    unread = list(p.unparsed) + [str(u) for u in account(text, p.tasks, p.before)]
    return sorted(t.summary() for t in p.tasks), unread


def test_with_a_thing_no_hand_picks_up_names_the_place():
    """The television is ALFRED's and not pickupable, also where the world built none."""
    for lacking in ("", "Television"):
        tasks, unread = read("Put the mug on the dresser with the television.", lacking)
        assert tasks == ["place Mug -> Dresser"] and not unread, (lacking, tasks, unread)


def test_with_a_thing_the_receptacle_holds_is_its_content():
    """Near misses: what a mug takes, said with "with ... in it" or "with" alone."""
    tasks, unread = read("Put the mug with a pencil in it on the dresser.")
    assert tasks == ["place_in_container Pencil in Mug -> Dresser"] and not unread
    tasks, unread = read("Put the bowl with the apple in the fridge.")
    assert tasks == ["place_in_container Apple in Bowl -> Fridge"] and not unread


def test_with_a_thing_the_receptacle_does_not_take_is_no_content():
    """A mug takes no laptop: never a Laptop in the Mug (the laptop is left to check 1)."""
    tasks, unread = read("Put the mug on the dresser with the laptop.")
    assert not any("in Mug" in t for t in tasks), tasks
    assert tasks == ["place Mug -> Dresser"] or unread, (tasks, unread)


def test_a_possessive_owner_picked_by_an_ordinal_is_refused_by_name():
    for text in ("Put the second drawer's spoon on the counter.", "Put the 3rd drawer's spoon in the sink."):
        tasks, unread = read(text)
        assert not tasks and any("drawer's" in u and "one of several" in u for u in unread), (tasks, unread)
    tasks, unread = read("Put the apple in the fridge and put the first armchair's pillow on the bed.")
    assert tasks == ["place Apple -> Fridge"] and any("armchair's" in u for u in unread), (tasks, unread)


def test_a_possessive_owner_is_the_source():
    """Near miss: no ordinal, read as "the spoon from the drawer" is."""
    for text in ("Put the drawer's spoon on the counter.", "Put the spoon from the drawer on the counter."):
        tasks, unread = read(text)
        assert tasks == ["place Spoon -> CounterTop"] and not unread, (text, tasks, unread)


def test_a_part_of_a_thing_is_not_the_thing():
    """ "the lid of the bowl" was read as the bowl, the lid dropped with no word unread."""
    for text in ("Put the lid of the bowl in the sink.", "Put the mug cap in the sink."):
        tasks, unread = read(text)
        assert any("lid" in u or "cap" in u for u in unread), (text, tasks, unread)
    tasks, unread = read("Put the bowl in the sink.")  # near miss
    assert tasks == ["place Bowl -> SinkBasin"] and not unread


def test_with_a_lamp_after_a_placing_says_which_place():
    """ "put the box on the dresser with the lamp" was read as examining the box under the lamp, the
    dresser dropped; near miss: "examine the box with the lamp" is the light."""
    tasks, _ = read("Put the box on the dresser with the lamp.")
    assert tasks == ["place Box -> Dresser"], tasks
    tasks, unread = read("Examine the box with the lamp.")
    assert len(tasks) == 1 and tasks[0].startswith("examine_in_light Box") and not unread, (tasks, unread)
