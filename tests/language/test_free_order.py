"""The one list of free-order phrases (`language/free_order.txt`): every reader reads the same phrases."""

import re

import pytest

from nl2hltl2plan.language.content_words import free_order_phrase
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grounding import tokens
from nl2hltl2plan.language.order_words import unordered_steps
from nl2hltl2plan.language.parse_usage import ParseUsage
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
