"""A misspelt word of the package's vocabulary (issue 28, `spelling.vocabulary_near`): one slip from exactly
one word of the word files is that word, and the result says so; a tie, or an order, count or negation word
that English has a near rival for, stays as written, and check 1 names it where it may be an order, count or
negation word."""

from __future__ import annotations

from importlib import resources

import pytest

from nl2hltl2plan.language.spelling import (
    VOCABULARY_FILE,
    declared_vocabulary,
    respelling_notes,
    respelt,
    vocabulary_near,
    vocabulary_words,
)
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.language.unknown_words import misspelt_words, unread_words


@pytest.mark.parametrize(
    "typed, word",
    [
        ("whih", "which"),  # a letter left out
        ("newspaaper", "newspaper"),  # a letter doubled
        ("sinl", "sink"),  # replaced by its keyboard neighbour (k, l)
        ("befoe", "before"),  # an order word: "befog" and "defoe" are 30,000 times rarer
        ("aftr", "after"),
        ("alll", "all"),  # a count word, "ally" far rarer
    ],
)
def test_one_slip_from_one_vocabulary_word_is_that_word(typed, word):
    assert vocabulary_near(typed) == (word,)
    assert respelt(f"put it {typed} now") == f"put it {word} now"


@pytest.mark.parametrize(
    "typed, near",
    [
        ("plae", ("place", "plate")),  # two vocabulary words one slip away: a tie
        ("firt", ("first", "fire", "fit")),  # "fire" is 1/6 as common as "first": no margin
        ("nevr", ("never", "near")),
        ("sinc", ()),  # c is no neighbour of k: no slip makes "sink"
        ("fist", ()),  # an English word is what it says
        ("sink", ()),  # a word the vocabulary knows
    ],
)
def test_a_tie_or_an_order_word_without_its_margin_is_left_as_written(typed, near):
    assert vocabulary_near(typed) == near
    assert respelt(typed) == typed


def test_the_vocabulary_is_the_word_files_words_not_their_comments():
    words = vocabulary_words()
    assert {"which", "before", "newspaper", "apple", "never", "two", "dozen"} <= words
    assert "recognised" not in words  # content_words.txt's header comment
    assert "sinkbasin" not in words and "bathtubbasin" not in words  # a type's name, not a word said


def test_check_one_names_a_word_that_may_misspell_a_structure_word():
    [nevr] = misspelt_words("put the soap in the cabinet, nevr on the counter")
    assert (nevr.words, nevr.category) == ("nevr", "spelling")
    assert "'never' or 'near'" in nevr.reason
    assert misspelt_words("put the bread on the plae") == []  # no order, count or negation at stake
    # an order word is named once, as an order word
    assert [u.category for u in unread_words("Firt put the mug in the sink")] == ["order"]
    assert misspelt_words("put the mug in the sink before the egg") == []


def test_the_notes_say_every_respelling():
    assert respelling_notes("put the mug in the sink befoe the aple, whih") == [
        "read 'befoe' as 'before'",
        "read 'aple' as 'apple'",
        "read 'whih' as 'which'",
    ]


def test_the_result_says_what_was_respelt():
    text = "put the mug in the sink. after whih, put the bread in the fridge"
    res = translate(text, None, build=False, actions="none")  # the reading alone: no floor plan needed
    read = [(t.object, t.receptacle) for t in res.tasks]
    assert read == [(["Mug"], ["SinkBasin"]), (["Bread"], ["Fridge"])]
    assert res.before == [("A", "B")] and not res.unparsed
    assert res.assumptions == ["read 'whih' as 'which'"]


def _package_text(name: str) -> str:
    return resources.files("nl2hltl2plan.language").joinpath(*name.split("/")).read_text()


def test_a_word_added_to_a_frame_list_changes_no_respelling():
    """Only the declared word files make the vocabulary (h289): "since" added to the frame remarks' days
    (session 33) or a word to the courtesy list leaves it as it was; one added to the order words is in it."""
    added = {"frame_remarks.txt": "day: since\n", "courtesy.txt": "greeting: zorbleth\n"}

    def read(name: str) -> str:
        return _package_text(name) + added.get(name, "")

    declared = declared_vocabulary(_package_text)
    assert declared_vocabulary(read) == declared and declared <= vocabulary_words()
    assert "since" not in vocabulary_words() and "courtesy.txt" not in _package_text(VOCABULARY_FILE)
    order = {"content_words.txt": "order: zorbleth\n"}
    ordered = declared_vocabulary(lambda name: _package_text(name) + order.get(name, ""))
    assert ordered == declared | {"zorbleth"}


@pytest.mark.parametrize(
    "typed, word",
    [("micorwave", "microwave"), ("aple", "apple"), ("befoe", "before"), ("whih", "which"), ("thwo", "two")],
)
def test_typos_of_lexicon_words_and_connectives_are_still_respelt(typed, word):
    assert respelt(f"put the mug in the sink {typed} now").split()[-2] == word
