"""Step 3 of the offline parser: frames (verb class + items) and noun phrases."""

from nl2hltl2plan.language.grammar.frames import THEN_TO, dest_of, parse_frame
from nl2hltl2plan.language.grammar.phrases import parse_np


def _items(text: str) -> list[tuple[str, list[tuple[str, str]]]]:
    fr = parse_frame(text)
    return [(it.obj.text if it.obj else "", [(p, np.text) for p, np in it.pps]) for it in fr.items]


def test_verb_class_particles_and_light_switch() -> None:
    fr = parse_frame("turn on the lamp with the book")
    assert (fr.cls, fr.verb, fr.light_on) == ("light", "turn", True)
    assert _items("turn on the lamp with the book") == [("the lamp", [("with", "the book")])]
    assert parse_frame("switch the coffee machine").cls == "other"  # no on/off: not a light switch


def test_colour_words_share_the_last_noun() -> None:
    assert _items("put the red and blue blocks in the box") == [
        ("red blocks", []),
        ("blue blocks", [("in", "the box")]),
    ]


def test_a_sequence_word_adds_a_further_destination() -> None:
    fr = parse_frame("move the towel to the sink and finally the toilet")
    assert _items("move the towel to the sink and finally the toilet") == [
        ("the towel", [("to", "the sink"), (THEN_TO, "the toilet")])
    ]
    dst = dest_of(fr.items[0], fr.cls)
    assert dst is not None and dst.text == "the toilet"


def test_noun_phrase_states_counts_and_pronouns() -> None:
    np = parse_np("two washed apples")
    assert (np.key, np.count, np.plural, np.states) == ("Apple", 2, True, {"clean"})
    assert parse_np("it").pronoun
    assert parse_np("a slice of bread").sliced
    own = parse_np("the zorbs")  # no lexicon entry: its own words, "-s" a plural
    assert (own.entry, own.head, own.count) == (None, "zorbs", 2)


def test_a_compound_names_its_last_noun() -> None:
    assert parse_np("a chilled glass bowl").key == "Bowl"  # not the glass (a Cup)
    assert parse_np("the bread knife").key == "Knife"
    assert parse_np("the bowl of the glass").key == "Bowl"  # "of": the first noun is the head
    assert parse_np("a wine glass").key == "Cup"  # one lexicon entry
    assert parse_np("a soap container").key == "SoapBar"  # a container of soap
    np = parse_np("two boxes of tissue")
    assert (np.key, np.count) == ("TissueBox", 2)
