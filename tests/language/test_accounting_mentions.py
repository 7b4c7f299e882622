"""Check 1 per mention (h172, issue 23): a thing named twice needs a task for each naming. A mention in the
words of a task that does not use it, and in those of no task that does, is unread; "look at X and at Y"
examines both (its "at" is no locative); "do the same with the other X" needs a task of its own; a name
part before another name ("the tennis book") is unread. A thing said again for the same task, or with two
roles, is still read."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.referents import moved_twice, place_then_moved
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.unknown_words import unknown_modifiers


def task(kind: str, obj: str, tid: str, text: str, **kw: object) -> BaseTaskSpec:
    return BaseTaskSpec(kind=kind, object=[obj], id=tid, text=text, **kw)  # type: ignore[arg-type]


def unread(text: str, tasks: list[BaseTaskSpec], before: list[tuple[str, str]] | None = None) -> list[str]:
    return [u.words for u in account(text, tasks, before or [])]


LOOK = "look at the box under the lamp and at the pencil by the lamp, then put a pencil in the drawer"


def test_a_mention_in_the_words_of_a_task_that_does_not_use_it_is_unread():
    said = "look at the box under the lamp and at the pencil by the lamp"
    box = task("examine_in_light", "Box", "A", said)
    box.light = ["DeskLamp"]
    drawer = task("place", "Pencil", "B", "put a pencil in the drawer", receptacle=["Drawer"])
    assert unread(LOOK, [box, drawer], [("A", "B")]) == ["pencil"]
    # read with both: nothing is unread
    pencil = task("examine_in_light", "Pencil", "C", said)
    pencil.light = ["DeskLamp"]
    assert unread(LOOK, [box, pencil, drawer], [("A", "B"), ("C", "B")]) == []


def test_the_same_thing_said_again_or_with_two_roles_is_still_read():
    text = "put the pencil in the mug, then move the mug to the shelf"
    one = task("place_in_container", "Pencil", "A", text, receptacle=["Shelf"], container=["Mug"])
    assert unread(text, [one]) == []
    text = "wash the plate, then put the plate in a cabinet"
    assert unread(text, [task("clean_place", "Plate", "A", text, receptacle=["Cabinet"])]) == []
    # a kind's appliance said in another task's words ("microwave the cup ... the potato in the microwave")
    text = "microwave the cup and put it in the sink, and then put a potato in the microwave"
    heat = task("heat_place", "Cup", "A", text[:40], receptacle=["SinkBasin"])
    potato = task("place", "Potato", "B", "put a potato in the microwave", receptacle=["Microwave"])
    assert unread(text, [heat, potato], [("A", "B")]) == []


def test_the_same_with_the_other_thing_needs_a_task_of_its_own():
    text = "put a remote in the box, then look at the watch under the lamp, do the same with the other remote"
    boxed = task("place_in_container", "RemoteControl", "A", "put a remote in the box", receptacle=["Box"])
    watch = task("examine_in_light", "Watch", "B", "look at the watch under the lamp")
    watch.light = ["FloorLamp"]
    assert unread(text, [boxed, watch], [("A", "B")]) == ["remote"]
    remote = task("examine_in_light", "RemoteControl", "C", "do the same with the other remote")
    remote.light = ["FloorLamp"]
    assert unread(text, [boxed, watch, remote], [("A", "B"), ("A", "C")]) == []


def test_a_name_part_before_another_name_is_unread():
    assert [u.words for u in unknown_modifiers("put the tennis book on the bed")] == ["tennis"]
    assert unknown_modifiers("put the tennis racket on the bed") == []
    # the lead, at h172's merge: "racquet" is a name of the tennis racket too (6 of 2,083 held-out generator
    # rows were refused), and "tennis" opens a name of that same thing
    assert unknown_modifiers("turn the lamp on while carrying a tennis racquet") == []
    assert [u.words for u in unknown_modifiers("put the tennis phone on the bed")] == ["tennis"]
    assert unknown_modifiers("put the standing lamp's bulb on the bed") == []  # also a verb's form


def test_a_container_moved_on_by_a_later_task_is_one_thing_in_two_places():
    text = "put the pencil into the bowl on the desk and then move the bowl to the shelf"
    boxed = task("place_in_container", "Pencil", "A", text[:40], receptacle=["Desk"], container=["Bowl"])
    moved = task("place", "Bowl", "B", "move the bowl to the shelf", receptacle=["Shelf"])
    with pytest.raises(HTTError, match="'the bowl' is one bowl put in two places"):
        moved_twice(text, [boxed, moved], [("A", "B")])
    # "another bowl" is a second one; one task with the bowl as its container is read
    other = task("place", "Bowl", "B", "move another bowl to the shelf", receptacle=["Shelf"])
    moved_twice(text.replace("the bowl to", "another bowl to"), [boxed, other], [("A", "B")])
    one = task("place_in_container", "Pencil", "A", text, receptacle=["Shelf"], container=["Bowl"])
    moved_twice(text, [one])


def test_a_place_that_a_later_task_moves_is_one_thing_in_two_roles():
    # "put the pencil in the mug and put the mug and the book on the desk", read as two placings
    into = task("place", "Pencil", "A", "put the pencil in the mug", receptacle=["Mug"])
    moved = task("place", "Mug", "B", "put the mug on the desk", receptacle=["Desk"])
    with pytest.raises(HTTError, match="'the mug' is where task A puts a thing and what task B moves"):
        place_then_moved([into, moved])
    # "it" is the pencil, and "another mug" a second one: both read
    place_then_moved([into, task("place", "Pencil", "B", "put it on the desk", receptacle=["Desk"])])
    place_then_moved([into, task("place", "Mug", "B", "put another mug on the desk", receptacle=["Desk"])])
