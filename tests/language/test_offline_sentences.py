"""Step 1 of the offline parser: sentences and their order markers."""

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.sentences import normalize, read_sentences


def test_normalize_drops_remarks_and_spaces_sentences() -> None:
    assert normalize("Put the mug (the blue one)  in the sink.Then wash it") == (
        "Put the mug in the sink. Then wash it"
    )


def test_off_after_a_state_verb_is_dropped() -> None:
    assert normalize("Put a rinsed off knife away, cool off a pan") == "Put a rinsed knife away, cool a pan"
    assert normalize("knock the roll off of the toilet") == "knock the roll off of the toilet"


def test_back_after_a_comma_continues_the_sequence() -> None:
    assert (
        normalize("Take the cup out, put it in the fridge, back in the microwave.")
        == "Take the cup out, put it in the fridge, then back in the microwave."
    )
    assert normalize("Put the book back on the shelf.") == "Put the book back on the shelf."


def test_listed_states_stay_one_noun_phrase() -> None:
    assert normalize("put a chilled, cut slice of lettuce in the sink") == (
        "put a chilled cut slice of lettuce in the sink"
    )
    assert normalize("wash the mug, rinse the cup") == "wash the mug, rinse the cup"


def test_markers_are_stripped_and_recorded() -> None:
    read = read_sentences("Put the mug in the sink. Then, place the apple on the table at any time.")
    first, second = read.sentences
    assert (first.index, first.body, first.markers, first.trailing) == (0, "Put the mug in the sink", [], [])
    assert second.body == "place the apple on the table"
    assert second.markers == [(G.THEN, "")]
    assert second.trailing == [(G.FREE, "")]
    assert second.offset == len("Put the mug in the sink. Then, ")


def test_after_reference_keeps_its_commas() -> None:
    read = read_sentences("After washing the cup, the bowl and the plate, put the fork in the drawer.")
    (s,) = read.sentences
    assert s.markers == [(G.AFTER_REF, "washing the cup, the bowl and the plate")]
    assert s.body == "put the fork in the drawer"


def test_relation_and_no_order_sentences_state_no_tasks() -> None:
    read = read_sentences(
        "Put the bowl on the table. The bowl should be placed before the cup. Order does not matter."
    )
    assert [s.body for s in read.sentences] == ["Put the bowl on the table"]
    (rel,) = read.relations
    assert (rel.kind, rel.a, rel.b) == ("before", "The bowl", "the cup")
