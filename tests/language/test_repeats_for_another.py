"""Issue 23, session 18: a sentence that repeats the task before it for another thing ("Wash the mug and
put it on the counter. The cup too.") read the cup as placed but not washed, and "Same for the cup" read
the cup as the mug again; "... and let it soak" dropped the soaking. Each exit 0. Now the whole task is
repeated for the thing (`grammar.repeats`), check 1 names a fragment no task repeats whole, and an action
left to the thing ("let it soak", "leave it to drain") that no base task does is refused by name."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar.repeats import repeated_for_another
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.language.unknown_words import unknown_verbs
from tests.language.test_trust_corrections import _refused, _world

pytestmark = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")
BOTH = pytest.mark.parametrize("backend", ["offline", "grammar"])


def _read(text: str, world: str, backend: str) -> tuple[list[tuple[object, ...]], list[tuple[str, str]]]:
    res = translate(text, _world(world), backend, build=False, actions="none")
    assert not res.partial, res.unparsed
    return [(t.kind, t.object[0], t.sliced, t.receptacle) for t in res.tasks], list(res.before)


KITCHEN = "Wash the mug and put it on the counter."


@BOTH
@pytest.mark.parametrize(
    ("text", "world", "second"),
    [
        (f"{KITCHEN} The cup too.", "FloorPlan1", ("clean_place", "Cup", False)),
        (f"{KITCHEN} Same for the cup.", "FloorPlan1", ("clean_place", "Cup", False)),
        ("Slice the apple and put it in the fridge. The tomato too.", "FloorPlan1",
         ("place", "Tomato", True)),
        ("Heat the potato and put it on the counter. And the egg as well.", "FloorPlan1",
         ("heat_place", "Egg", False)),
        ("Put the vase on the side table. Do the same with the statue.", "FloorPlan201",
         ("place", "Statue", False)),
    ],
)  # fmt: skip
def test_a_fragment_repeats_the_whole_task_for_its_thing(backend, text, world, second):
    tasks, before = _read(text, world, backend)
    assert len(tasks) == 2 and before == []
    assert tasks[1][:3] == second and tasks[1][3] == tasks[0][3]


@BOTH
@pytest.mark.parametrize(
    ("text", "named"),
    [
        # the task before is not one plain task: which part is repeated is not said
        ("Put the mug in the sink after the apple is in the fridge. The cup too.", "(fragment)"),
        (f"{KITCHEN[:-1]}, then put the apple in the fridge. The cup too.", "(fragment)"),
        # a change other than the place ("but put it in the cabinet" is read: test_paper_h180.py)
        ("Put the mug in the sink. Same for the cup, but heat it.", "'cup' (object)"),
    ],
)
def test_a_repeat_not_read_whole_is_refused_by_name(backend, text, named):
    assert named in _refused(text, "FloorPlan1", backend)


def test_check_1_names_a_fragment_read_as_another_task():
    """Check 1 judges any backend's reading: the cup only placed, or read as the mug, is named."""
    text = "Wash the mug in the sink and put it on the counter. The cup too."
    first = BaseTaskSpec(id="A", kind="clean_place", object=["Mug"], receptacle=["CounterTop"])

    def second(kind: str, obj: str) -> BaseTaskSpec:
        return BaseTaskSpec(id="B", kind=kind, object=[obj], receptacle=["CounterTop"])

    for wrong in (second("place", "Cup"), second("clean_place", "Mug")):
        assert "'The cup too' (fragment)" in [str(u).split(":")[0] for u in account(text, [first, wrong], [])]
    assert account(text, [first, second("clean_place", "Cup")], []) == []


def test_only_a_plain_one_task_sentence_is_repeated():
    assert repeated_for_another("Put the fork in the drawer. Do the same with the spoon and the knife.") == (
        "Put the fork in the drawer. Put the spoon in the drawer. Put the knife in the drawer."
    )
    plural = "Put the mug in the sink. Same for the cups."
    for text in (plural, "Put two apples in the fridge. The tomato too."):
        assert repeated_for_another(text) == text


@BOTH
@pytest.mark.parametrize(
    ("text", "world", "word"),
    [
        ("put the cloth in the bathtub and let it soak", "FloorPlan402", "'soak' (action)"),
        ("put the mug in the sink and leave it to soak", "FloorPlan1", "'soak' (action)"),
        ("put the hand towel in the sink and leave it to drain", "FloorPlan402", "'drain' (action)"),
    ],
)
def test_an_action_left_to_the_thing_is_refused_by_name(backend, text, world, word):
    assert word in _refused(text, world, backend)


def test_let_it_near_misses():
    assert unknown_verbs("put the apple in the fridge and let it cool") == []  # a task does it
    assert unknown_verbs("put the mug on the counter and leave it to the robot") == []
    assert unknown_verbs("put the apple in the fridge and leave it there") == []
    rest = unknown_verbs("put the bread in the box and allow the bread to rest")
    assert [u.words for u in rest] == ["rest"]


@pytest.mark.parametrize(
    ("text", "second"),
    [
        # the fragment names its own place: a placing of its own, read as before (no repeat asked)
        ("Put the apple in the fridge. The tomato in the microwave too.",
         ("place", "Tomato", False, ["Microwave"])),
        ("Put the apple in the fridge. The tomato, too.", ("place", "Tomato", False, ["Fridge"])),
    ],
)  # fmt: skip
def test_a_fragment_near_miss_keeps_its_reading(text, second):
    tasks, _ = _read(text, "FloorPlan1", "offline")
    assert tasks[1] == second


def test_a_fragment_of_the_same_type_is_refused():
    """ "the mug ... Same for the coffee mug": one type twice, which the spec's atoms cannot keep apart."""
    assert "(fragment)" in _refused(f"{KITCHEN} Same for the coffee mug.", "FloorPlan1", "offline")


@pytest.mark.parametrize(
    ("text", "world", "second"),
    [
        # h159 (issue 28, paper-style): an order word before the repeat orders it after the task before
        ("Put the tomato in the microwave, and then do the same with the potato.", "FloorPlan5",
         ("place", "Potato", False, ["Microwave"])),
        ("Chill the potato and put it in the microwave. After that, do the same with the tomato.",
         "FloorPlan5",
         ("cool_place", "Tomato", False, ["Microwave"])),
        # an examination under a lamp is one plain task too ("the light of the lamp" is the lamp's)
        ("Look at the watch by the light of the lamp, and once you have done that, do the same with the "
         "alarm clock.", "FloorPlan301", ("examine_in_light", "AlarmClock", False, None)),
    ],
)  # fmt: skip
def test_a_repeat_after_an_order_word_follows_the_task_before(text, world, second):
    tasks, before = _read(text, world, "offline")
    assert tasks[1] == second and before == [("A", "B")]


def test_an_ordered_repeat_of_several_things_is_not_written_out():
    """ "then do the same with the potato and the apple": their own order is not said, so nothing is
    written out (check 1 names the fragment), and a split sentence is kept as written."""
    for text in (
        "Put the tomato in the microwave, and then do the same with the potato and the apple.",
        "Put the tomato in the microwave after the egg is in the fridge, then do the same with the potato.",
    ):
        assert repeated_for_another(text) == text


def test_a_repeat_of_a_task_said_after_an_order_word_copies_the_task_only():
    """h166 (issue 28, paper-style, three and four tasks): "After that, examine X ..., and then do the same
    with Y" repeats the examination, not its order word ("After that" stays with X): it was left unread."""
    text = (
        "Put two CDs in a desk drawer and two clocks on the desk. After that, examine the statue by the "
        "light of the desk lamp, and then do the same with the book."
    )
    assert repeated_for_another(text).endswith(
        "After that, examine the statue by the light of the desk lamp. Then examine the book by the light "
        "of the desk lamp."
    )
    tasks, before = _read(text, "FloorPlan304", "offline")
    assert [t[:2] for t in tasks[2:]] == [("examine_in_light", "Statue"), ("examine_in_light", "Book")]
    assert ("C", "D") in before and ("A", "C") in before and ("B", "C") in before
    unordered = "Next, wash the mug and put it on the counter. The cup too."
    assert repeated_for_another(unordered) == (
        "Next, wash the mug and put it on the counter. Wash the cup and put it on the counter."
    )
