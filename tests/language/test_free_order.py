"""The one list of free-order phrases (`language/free_order.txt`): every reader reads the same phrases."""

import re

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.content_words import free_order_phrase, free_order_remarks
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grounding import tokens
from nl2hltl2plan.language.order_words import unordered_steps
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.tabletop_wording import frees_every_step
from nl2hltl2plan.language.task_specs import BaseTaskSpec

PHRASES = [
    "in any order",
    "either order is fine",
    "in whichever order you prefer",
    "the order doesn't matter",
    "order does not matter",
    "the order is up to you",
    "in no particular order",
    "I don't care about the order",
    "it doesnt matter which goes first",
]
TWO = [BaseTaskSpec(id=i, kind="place", object=["Mug"], receptacle=["Sink"]) for i in "AB"]


@pytest.mark.parametrize("phrase", PHRASES)
def test_a_closing_remark_frees_the_request_in_the_grammar(phrase):
    text = f"Put the mug in the sink and the apple in the fridge, {phrase}."
    assert everyday(text).endswith(", in any order")


@pytest.mark.parametrize("phrase", PHRASES)
def test_check_1_reads_the_same_phrase(phrase):
    toks = tokens(f"put the mug in the sink, then the other mug in the sink, {phrase}")
    assert unordered_steps(toks, set(), ParseUsage(TWO, [])) == []  # "then" freed by the phrase
    (flag,) = unordered_steps(toks, set(), ParseUsage(TWO, [("A", "B")]))  # the phrase frees nothing
    assert flag.category == "order" and "free" in flag.reason


@pytest.mark.parametrize("text", ["the order of the mugs", "in order to", "any mug", "the order is blue"])
def test_near_misses_are_no_phrase(text):
    assert not re.search(rf"\b{free_order_phrase()}\b", text, re.I)


def test_a_sentence_that_only_says_any_order_keeps_its_question_open():
    # "Any order." alone does not say what it frees: no clause phrase, so the grammar's rules decide
    assert re.search(free_order_phrase(), "Any order", re.I)
    assert not re.search(free_order_phrase("clause"), "Any order", re.I)
    assert re.search(free_order_phrase("clause"), "The order is not important", re.I)


PER_GROUP = [
    "each pair in either order",
    "within each colour any order",
    "the order within each step doesn't matter",
    "the order within each round is up to you",
    "in any order within each pair",
]


@pytest.mark.parametrize("phrase", PER_GROUP)
def test_a_freedom_within_each_group_is_a_kind_of_its_own(phrase):
    """A per-group phrase frees no order between the groups: the order words still need one; a whole-list
    phrase at the same place frees them."""
    (remark,) = free_order_remarks(phrase)
    assert remark.per_group and remark.words == phrase.lower()
    four = [BaseTaskSpec(id=i, kind="place", object=["Mug"], receptacle=["Sink"]) for i in "ABCD"]
    toks = tokens(f"put two mugs in the sink, then two more mugs in the sink, {phrase}")
    (flag,) = unordered_steps(toks, set(), ParseUsage(four, []))
    assert flag.words == "then" and flag.reason == "the base tasks are not ordered"
    assert unordered_steps(toks, set(), ParseUsage(four, [("A", "C"), ("B", "D")])) == []
    whole = tokens("put two mugs in the sink, then two more mugs in the sink, the order doesn't matter")
    assert unordered_steps(whole, set(), ParseUsage(four, [])) == []


def test_a_per_group_remark_leaves_the_tabletop_steps_ordered():
    assert frees_every_step(["in any order"]) and frees_every_step(["the order is up to you"])
    assert not frees_every_step(["within each step, any order"])
    assert not frees_every_step(["the order within each pair does not matter"])


def test_an_order_word_between_the_steps_of_one_task_orders_no_tasks():
    """ "chill the lettuce then return it to the counter" is one task's steps: its "then" asks no order
    between the base tasks; a "then" between two tasks' words still does."""
    text = "put a mug in the sink. chill the lettuce then return it to the counter. move a mug to the sink"
    tasks = [
        BaseTaskSpec(id="A", kind="place", object=["Mug"], receptacle=["Sink"], text="put a mug in the sink"),
        BaseTaskSpec(
            id="B", kind="cool_place", object=["Lettuce"], receptacle=["CounterTop"],
            text="chill the lettuce then return it to the counter",
        ),
        BaseTaskSpec(
            id="C", kind="place", object=["Mug"], receptacle=["Sink"], text="move a mug to the sink"
        ),
    ]  # fmt: skip
    assert unordered_steps(tokens(text), set(), ParseUsage(tasks, [])) == []
    two = "put a mug in the sink then move a mug to the sink"
    (flag,) = unordered_steps(tokens(two), set(), ParseUsage([tasks[0], tasks[2]], []))
    assert flag.words == "then"


def test_check_1_reads_a_per_group_remark_as_written():
    """The grammar's rewriting reads a closing "each pair in either order" as ", in any order"; check 1 asks
    the words as written, so a reading with no order between the pairs leaves "then" unread."""
    text = "put the apple and the egg in the fridge, then the mug and the cup in the sink, "
    text += "each pair in either order"
    slots = [("A", "Apple", "Fridge"), ("B", "Egg", "Fridge"), ("C", "Mug", "SinkBasin")]
    slots += [("D", "Cup", "SinkBasin")]
    tasks = [BaseTaskSpec(id=i, kind="place", object=[o], receptacle=[r]) for i, o, r in slots]
    assert [(u.words, u.category) for u in account(text, tasks, [])] == [("then", "order")]
    assert account(text, tasks, [("A", "C"), ("A", "D"), ("B", "C"), ("B", "D")]) == []
    assert account(text.replace("each pair in either order", "in any order"), tasks, []) == []
