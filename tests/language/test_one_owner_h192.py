"""h192: one owner per idea in the language stage. The plural the lexicon reads (`grounding.plural_name`,
which `counted_refs` and `everyday` both write), "one more" / "another" (`counted_refs.another_said`,
`referents.another_thing`), and a fixture as the thing to treat (the world's `BaseTask.unmovable`)."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar.counted_refs import another_said, counted_references
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grounding import find_mentions, plural_name
from nl2hltl2plan.language.learned.rescue import canonical
from nl2hltl2plan.language.learned.slot_model import SlotPrediction
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.demo import demo_world


@pytest.mark.parametrize(
    "name, plural",
    [
        ("knife", "knives"),  # was "knifes" in `counted_refs`
        ("tomato", "tomatoes"),
        ("loaf of bread", "loaves of bread"),
        ("box of tissue", "boxes of tissue"),  # was "boxs of tissue" in `everyday`
        ("safe", "safes"),  # was "saves"
        ("paper towel", "paper towel rolls"),  # was "paper toweles": "paper towels" is the roll's own name
        ("keys", "key chains"),  # a name that looks plural: its type's name
        ("shelf", "shelfs"),  # "shelves" is a name of one shelf; the lexicon reads "shelfs" as several
        ("belongings", None),  # a generic name (it raised IndexError)
        ("blinds", None),
    ],
)
def test_the_plural_is_one_the_lexicon_reads_as_the_same_things(name, plural):
    assert plural_name(name) == plural
    if plural is not None:
        (m,) = find_mentions(plural)
        assert m.plural and m.entry.types == find_mentions(name)[0].entry.types


def test_both_writers_of_a_plural_write_the_same():
    said = counted_references("Put one knife in the drawer, then put the remaining two in the sink.")
    assert said == "Put one knife in the drawer, then put two other knives in the sink."
    assert everyday("Put a knife in the drawer and two more in the sink.") == (
        "Put a knife in the drawer and two more knives in the sink."
    )
    # the learned reader's sentence for a pick-two task (it wrote "knifes", "tomatos", "paper towels")
    pred = SlotPrediction([("place_two", 1.0)], {"object": [("Knife", 1.0)], "receptacle": [("Drawer", 1.0)]})
    assert canonical(pred) == "put two knives in the drawer"


def test_one_more_and_another_are_written_once():
    # "one more" said of a thing is "another"; verbless after "then" / "and", either is "one more X"
    assert another_said("Put a mug in the sink and one more in the cabinet.") == (
        "Put a mug in the sink and another in the cabinet."
    )
    assert another_said("Put an apple in the fridge, then another apple.") == (
        "Put an apple in the fridge, then one more apple."
    )
    kept = "Put an apple in the fridge and one more apple. Rinse it one more time, then another one."
    assert another_said(kept) == kept
    assert everyday("Put an apple in the fridge and one more apple.").endswith("and one more apple.")


def test_a_fixture_to_treat_is_refused_with_the_worlds_reason():
    with pytest.raises(HTTError, match=r"^'sink': a sink basin cannot be picked up, so no task can wash it"):
        translate("scrub the sink", demo_world(), build=False, actions="none")


def test_that_place_reads_a_destination_of_four_words_or_a_part_of_one():
    assert everyday("Put the pen on the small black side table, then put a mug on that table.") == (
        "Put the pen on the small black side table, then put a mug on the side table."
    )
