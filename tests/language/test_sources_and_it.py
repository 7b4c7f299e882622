"""Session 24 (h146): one pattern for a return's unsaid place ("back in its usual place", "home"), one test
of a source (`prepositions.source_at` / `a_source`), one test of "the text frees an order"
(`order_words.frees_an_order`), and "it" named where it may be either of two things (`it_of_two`)."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar.put_back import put_back_where_taken
from nl2hltl2plan.language.grounding import find_mentions, tokens
from nl2hltl2plan.language.it_of_two import it_of_two
from nl2hltl2plan.language.learned.structured import order_not_held
from nl2hltl2plan.language.order_words import frees_an_order
from nl2hltl2plan.language.prepositions import a_source
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def place(obj: str, where: str, task_id: str = "A", kind: str = "place") -> BaseTaskSpec:
    return BaseTaskSpec(id=task_id, kind=kind, object=[obj], receptacle=[where], text="")


@pytest.mark.parametrize("where", ["in its usual place", "to its home", "in its usual spot", "in its place"])
def test_a_return_to_its_usual_place_goes_back_where_it_was_taken_from(where):
    text = f"take the mug out of the cabinet, rinse it, then put it back {where}"
    assert put_back_where_taken(text) == text.replace(f"back {where}", "back in the cabinet")
    assert account(text, [place("Mug", "Cabinet", kind="clean_place")], []) == []


def test_a_return_to_its_usual_place_with_no_source_is_named():
    text = "put the mug in the sink, then put it back in its home"
    assert put_back_where_taken(text) == text
    assert [u.words for u in account(text, [place("Mug", "SinkBasin")], [])] == ["back in its home"]


@pytest.mark.parametrize(
    "text, place_word, source",
    [
        ("take the egg out of the fridge", "fridge", True),
        ("grab the mug off of the counter", "counter", True),
        ("get the shoes from under the bed", "bed", True),
        ("take the mug from the cabinet to the table", "table", False),
        ("put the book on the second from the top shelf", "shelf", False),  # which shelf, no source
        ("get the mug from it, the cabinet", "cabinet", False),  # a source never reaches over punctuation
        ("put the egg in the fridge", "fridge", False),
    ],
)
def test_a_source_is_one_test_for_the_grammar_and_check_1(text, place_word, source):
    assert a_source(text, text.index(place_word)) is source


def test_check_1_and_the_return_both_take_a_source_off_of_a_place():
    text = "grab the mug off of the counter, rinse it, put it back"
    assert put_back_where_taken(text).endswith("put it back in the counter")
    assert account(text, [place("Mug", "CounterTop", kind="clean_place")], []) == []


def _frees(text: str) -> bool:
    toks = tokens(text)
    return frees_an_order(toks, {i for m in find_mentions(text) for i in range(m.start, m.end)})


@pytest.mark.parametrize(
    "text, free",
    [
        ("put the mug in the sink and the apple in the fridge, in any order", True),
        ("put the mug in the sink and the apple in the fridge whenever you like", True),
        ("put the mug in the sink, then the apple in the fridge", False),
        # within each group only: the groups' own order stays asked
        ("put the mugs in the sink and the apples in the fridge, each pair in either order", False),
    ],
)
def test_one_test_says_whether_the_text_frees_an_order(text, free):
    assert _frees(text) is free


def test_a_model_reading_is_not_let_off_an_order_by_a_per_group_phrase():
    tasks = [
        BaseTaskSpec(id=i, kind="place", object=[o], receptacle=[r], text=f"put the {o} in the {r}")
        for i, (o, r) in zip("AB", [("Mug", "SinkBasin"), ("Apple", "Fridge")], strict=True)
    ]
    text = "put the Mug in the SinkBasin, then the Apple in the Fridge"
    assert order_not_held(f"{text}, each pair in either order", (tasks, []), (tasks, [("A", "B")]))
    assert not order_not_held(f"{text}, in any order", (tasks, []), (tasks, [("A", "B")]))


@pytest.mark.parametrize(
    "text, two",
    [
        ("put a watch in the box, then put it on the sofa", "the watch or the box"),
        ("put the watch in the box and put it on the sofa", "the watch or the box"),
        ("get the egg from the fridge and put it in the pan, then return it", "the egg or the pan"),
        ("put the apple in the bowl. then pick it up", "the apple or the bowl"),
    ],
)
def test_it_after_a_thing_put_in_a_movable_holder_is_named(text, two):
    assert [u.reason.split(":")[0] for u in it_of_two(text, find_mentions(text))] == [f"'it' may be {two}"]


@pytest.mark.parametrize(
    "text",
    [
        "put the pencils in the mug, then put it on the desk",  # plural: "it" is the mug
        "put the watch in the box, pick up the box and put it on the sofa",  # the box named between
        "take the watch in the box and put it on the sofa",  # taken: the watch in hand
        "put the watch in the box, then put it on the sofa with the watch",  # its clause names one
        "put the box on the sofa, then put a watch in it",  # "it" is a place
        "get the egg from the fridge and put it in the pan",  # the fridge stays where it is
        "put the watch in the box, then close it",  # only the box closes
    ],
)
def test_it_english_decides_is_not_named(text):
    assert it_of_two(text, find_mentions(text)) == []


def test_check_1_names_it_of_two_unless_read_as_the_movable_container_task():
    # both readings put the watch on the sofa; ALFRED's task for it is the box with the watch in it (h177)
    text = "put a watch in the box, then put it on the sofa"
    kind = "place_in_container"
    reading = [BaseTaskSpec(id="A", kind=kind, object=["Watch"], receptacle=["Sofa"], container=["Box"])]
    assert "put it" not in [u.words for u in account(text, reading, [])]
    moved = [BaseTaskSpec(id="A", kind="place", object=["Watch"], receptacle=["Sofa"])]
    assert "put it" in [u.words for u in account(text, moved, [])]
    back = "put a watch in the box, then put it back on the sofa"  # back where the watch, or the box, was
    assert "put it" in [u.words for u in account(back, reading, [])]
    # two boxes said, one read: the reading merged them, and the question stays
    two = "put two boxes on the table, then put a watch in a box and put it on the sofa"
    assert "put it" in [u.words for u in account(two, reading, [])]
