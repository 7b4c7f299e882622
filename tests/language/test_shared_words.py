"""Issue 23, session 18: the words every world's reader shares. A take-back ("scratch that") is refused by
name in the household, tabletop and handover worlds alike; a labelled line that asks nothing ("Condition -
none") is dropped in every world; a fragment that only refers ("Hers too.") and a person, a time, a hedge
or a choice left open are named, never dropped. Near misses keep their reading."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import take_backs
from nl2hltl2plan.language.headings import unlabelled
from nl2hltl2plan.language.translate import translate
from tests.language.test_trust_corrections import _world  # one world per floor plan, shared

pytestmark = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")

# one instruction each world reads, and its tasks
READ = {
    "FloorPlan1": ("put the apple in the fridge.", ["place Apple -> Fridge"]),
    "tabletop": ("put the green apple on the yellow plate.", ["place GreenApple -> YellowPlate"]),
    "handover-square": (
        "Transfer three blocks into the opposite.",
        [f"place {c}Block -> RegionH|RegionI|RegionJ" for c in ("Red", "Blue", "Yellow")],
    ),
}


def _tasks(text: str, world: str) -> list[str]:
    res = translate(text, _world(world), build=False, actions="none")
    assert not res.partial, res.unparsed
    return [t.summary() for t in res.tasks]


def _not_understood(text: str, world: str) -> str:
    try:
        res = translate(text, _world(world), build=False, actions="none")
    except HTTError as exc:
        return str(exc)
    assert res.partial, [t.summary() for t in res.tasks]
    return "; ".join(res.unparsed)


@pytest.mark.parametrize(
    ("world", "said"),
    [
        ("FloorPlan1", "Just kidding."),
        ("tabletop", "Scratch that."),
        ("handover-square", "Forget what I said."),
    ],
)
def test_a_take_back_is_refused_by_name_in_every_world(world, said):
    text, _ = READ[world]
    with pytest.raises(HTTError, match=rf"^'{said[:-1]}' takes back part of the instruction"):
        translate(f"{text} {said}", _world(world), build=False, actions="none")


def test_words_of_a_take_back_that_take_nothing_back_are_no_take_back():
    assert take_backs("never mind the order, put the apple in the fridge") == []
    assert take_backs("and don't forget that nothing may be placed on region F") == []
    assert [u.words for u in take_backs("put it in the sink, scratch that, the fridge")] == ["scratch that"]


@pytest.mark.parametrize(
    ("world", "label"),
    [
        ("FloorPlan1", "Condition - none."),
        ("tabletop", "Notes: n/a"),
        ("handover-square", "Constraints: nothing."),
    ],
)
def test_a_labelled_line_that_asks_nothing_is_dropped_in_every_world(world, label):
    text, tasks = READ[world]
    assert _tasks(f"Goal - {text}\n{label}", world) == tasks


def test_a_label_about_order_or_with_a_value_keeps_it():
    assert unlabelled("Put A on P. Ordering: none.") == "Put A on P. Ordering: none."
    assert unlabelled("Step 1 - put A on P") == "Step 1 - put A on P"  # a number, not a label
    assert unlabelled("Note - the fridge is cold.") == "Note: the fridge is cold."
    assert "cold" in _not_understood("Put the apple in the fridge. Note: the fridge is cold.", "FloorPlan1")


@pytest.mark.parametrize(
    ("world", "fragment"),
    [("FloorPlan1", "Hers too"), ("FloorPlan1", "And the other one"), ("tabletop", "Both of them")],
)
def test_a_fragment_that_only_refers_is_named_not_dropped(world, fragment):
    text, _ = READ[world]
    assert f"{fragment!r} (fragment)" in _not_understood(f"{text} {fragment}.", world)


def test_a_fragment_that_names_a_thing_or_closes_is_left_to_the_reading():
    assert _tasks("Put the apple in the fridge. That's it.", "FloorPlan1") == ["place Apple -> Fridge"]
    assert _tasks("Put the apple in the fridge. The tomato too.", "FloorPlan1") == [
        "place Apple -> Fridge",
        "place Tomato -> Fridge",
    ]


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("put the newspaper on the table before grandpa gets home", "grandpa"),
        ("put the knife in the drawer carefully, my son is around", "son"),
        ("put the apple in the fridge tomorrow morning", "tomorrow"),
        ("maybe put the apple in the fridge", "maybe"),
        ("put the apple in a drawer, whichever", "whichever"),  # "the fridge or the sink, ...": read (h274)
        ("put the apple in the fridge when the movie ends", "when the movie ends"),
    ],
)
def test_a_person_a_time_a_hedge_or_a_choice_is_named(text, word):
    scene = "FloorPlan201" if "newspaper" in text else "FloorPlan1"
    assert word in _not_understood(text, scene)


def test_for_whom_a_polite_maybe_and_a_greeting_are_read():
    assert _tasks("put the apple in the fridge for my mom", "FloorPlan1") == ["place Apple -> Fridge"]
    polite = "could you maybe put the spatula in a drawer please"
    assert _tasks(polite, "FloorPlan15") == ["place Spatula -> Drawer"]
    assert _tasks("Good morning! Put the apple in the fridge.", "FloorPlan1") == ["place Apple -> Fridge"]


def test_one_predicate_says_what_names_content_for_every_frame_rule():
    """`content_words.names_content` (h305): the handover frame rule's notion (cautious inflections, the
    voice's nouns skipped, the world's names), the frame filler's (numbers and `frame_keeps.txt` too) and
    the request-unit classifier's (check 1's refused kinds by check 1's inflections), each by name."""
    from nl2hltl2plan.language.content_words import names_content
    from nl2hltl2plan.language.frame_filler import filler
    from nl2hltl2plan.language.handover_discourse import empty
    from nl2hltl2plan.language.learned.request_units import content

    assert names_content("called") and not names_content("noted")  # "noted" is no "not"
    assert names_content("guests") and not names_content("guests", voice=True)
    assert names_content("orange", names=frozenset({"orange"})) and not names_content("orange")
    assert names_content("too", kept=True) and names_content("3", kept=True) and not names_content("too")
    assert names_content("putting", refused_only=True) and not names_content("putting")
    # and the readers that ask it
    assert empty("Noted.") and not empty("Put it down.") and not filler(("the", "zebra", "too"), 2)
    assert content("Keep putting them away") and not content("Lovely weather today.")
