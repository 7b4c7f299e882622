"""Issue 28 (h133): "put it back" after a place said as a source is a placing there, read by the grammar
(`grammar.put_back`); a plural name of the lexicon is read as a plural (`grounding.lexicon`)."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.grammar.put_back import put_back_where_taken
from nl2hltl2plan.language.grounding import find_mentions, phrase_lines

HOME, TOP = "Fridge", "CounterTop"
TYPES = {"Cloth", "Cabinet", "BathtubBasin", "Apple", "Fridge", "Microwave", "Mug", "CounterTop", "SinkBasin"}


@pytest.mark.parametrize(
    "text, kind, obj, place",
    [
        ("wash the cloth from the cabinet, put it back", "clean_place", "Cloth", "Cabinet"),
        ("rinse the rag from the tub then put it back", "clean_place", "Cloth", "BathtubBasin"),
        ("take the cloth out of the cabinet, wash it and return it", "clean_place", "Cloth", "Cabinet"),
        ("get the apple from the fridge, heat it in the microwave, put it back", "heat_place", "Apple", HOME),
        ("grab the mug off the counter, rinse it, put it back where it was", "clean_place", "Mug", TOP),
        ("take the apple out of the fridge, cook it, put it back in its place", "heat_place", "Apple", HOME),
    ],
)
def test_a_return_with_no_place_goes_to_the_one_source_and_every_word_is_read(text, kind, obj, place):
    p = parse_instruction(text, TYPES, "test")
    assert [(t.kind, t.object[0], t.receptacle[0]) for t in p.tasks] == [(kind, obj, place)]
    assert account(text, p.tasks, p.before) == []


@pytest.mark.parametrize(
    "text",
    [
        "take the apple out of the fridge and the mug from the sink, wash them and put them back",  # a step
        "put the mug in the sink, then put it back",  # no source
        "wash the cloth from the cabinet, put it back in the tub",  # its place is said
        "put the apple in the fridge. wash the cloth and put it back",  # the source is another sentence's
    ],
)
def test_no_single_source_before_it_or_a_place_after_it_leaves_the_text_as_written(text):
    assert put_back_where_taken(text) == text


def test_a_source_without_a_return_is_still_not_a_destination():
    """h127's guard stands: "from the cabinet" alone never names where the cloth goes."""
    p = parse_instruction("wash the cloth from the cabinet", TYPES, "test")
    assert not [t for t in p.tasks if "Cabinet" in (t.receptacle or [])]


def test_plural_names_of_the_lexicon_are_read_as_plurals():
    """ "the soap bars" and "the boxes of tissues" are several things (`: plural of` lines); "the keys"
    (the key chain) and "the tissues" (the box) are the names of one."""
    said = "the soap bars, the boxes of tissues, the keys, the tissues"
    plural = {m.surface: m.plural for m in find_mentions(said)}
    assert plural == {"soap bars": True, "boxes of tissues": True, "keys": False, "tissues": False}


# plural in form, one thing (or, as a place, any one of them): each is read as one, which is meant
ONE_THING = {
    "keys", "set of keys", "paper towels", "roll of paper towels", "tissues", "box of tissues", "boots",
    "cupboards", "shelves", "lights", "car keys",
}


def test_a_lexicon_name_plural_in_form_is_one_thing_or_a_plural_line():
    """A name listed as the plural of another name of its line is read as one thing ("soap bars" once was
    read as one bar): only the names of one thing may be so listed; other plurals are `: plural of` lines."""
    for phrases, fields in phrase_lines("lexicon.txt"):
        if len(fields) > 1 and fields[1].startswith("plural of "):
            continue
        for p in phrases:
            head, last = p.rsplit(" ", 1) if " " in p else ("", p)
            singulars = {f"{head} {last[:-k]}".strip() for k in (1, 2) if last.endswith("s")}
            singulars |= {f"{head} {last[:-3]}y".strip()} if last.endswith("ies") else set()
            singulars |= {f"{head} {last[:-3]}f".strip()} if last.endswith("ves") else set()
            if singulars & set(phrases):
                assert p in ONE_THING, p
