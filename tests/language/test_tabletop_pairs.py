"""The tabletop world's framing-independent fallback (`language/tabletop_pairs.py`, issue 28): object and
plate paired whichever comes first, order only from "first ... then", and refusals kept for the rest."""

from __future__ import annotations

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.tabletop_pairs import read_pairs
from nl2hltl2plan.language.task_specs import transitive_closure
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.tabletop_world import tabletop_world

WORLD = tabletop_world()
TYPES = set(WORLD.object_types())


def _reading(text: str) -> tuple[list, list] | None:
    """(object, plate) pairs and the closed order by pair, as translate gives them; None on a refusal."""
    try:
        r = translate(text, WORLD, build=False)
    except HTTError:
        return None
    if r.partial:
        return None
    key = {t.id: (t.object[0], t.receptacle[0]) for t in r.tasks}
    closure = transitive_closure(r.before, list(key))
    return sorted(key.values()), sorted((key[a], key[b]) for a, b in closure)


@pytest.mark.parametrize(
    "text",
    [
        "carrot: blue plate",
        "the carrot should end up on the blue plate",
        "The blue plate is where the carrot goes.",
    ],
)
def test_object_and_plate_pair_whichever_comes_first(text):
    assert _reading(text) == ([("Carrot", "BluePlate")], [])


def test_plate_first_and_object_first_sentences_mix_across_sentences():
    text = "Blue plate: carrot and orange. Green apple: pink plate. In any order."
    assert _reading(text) == (
        [("Carrot", "BluePlate"), ("GreenApple", "PinkPlate"), ("Orange", "BluePlate")],
        [],
    )


def test_first_then_orders_the_groups_and_nothing_within_them():
    pairs, order = _reading(
        "First the pink plate takes the red apple and the carrot. Once that's done, the green apple: blue "
        "plate."
    )
    assert pairs == [("Carrot", "PinkPlate"), ("GreenApple", "BluePlate"), ("RedApple", "PinkPlate")]
    assert order == [
        (("Carrot", "PinkPlate"), ("GreenApple", "BluePlate")),
        (("RedApple", "PinkPlate"), ("GreenApple", "BluePlate")),
    ]


def test_a_wording_the_grammar_reads_never_reaches_the_fallback(monkeypatch):
    from nl2hltl2plan.language import tabletop_pairs

    def refuse(*args):
        raise AssertionError("the fallback was called")

    monkeypatch.setattr(tabletop_pairs, "tabletop_fallback", refuse)
    text = "Put the carrot on the blue plate, then the orange on the yellow plate."
    assert _reading(text) == (
        [("Carrot", "BluePlate"), ("Orange", "YellowPlate")],
        [(("Carrot", "BluePlate"), ("Orange", "YellowPlate"))],
    )
    with pytest.raises(AssertionError, match="fallback"):
        _reading("carrot: blue plate, orange: yellow plate")


@pytest.mark.parametrize(
    "text",
    [
        "carrot: blue plate, carrot: pink plate",  # one object, two plates
        "the carrot or the orange: blue plate",  # a choice
        "blue plate, yellow plate: carrot",  # two plates for one object
        "carrot: blue plate before orange: yellow plate",  # an order form not in the set
        "the carrot should not end up on the blue plate",  # a negation
        "the carrots: blue plate",  # a plural (a count)
        "carrot near the blue plate",  # a relation that is no placement
        "green apple: blue plate; orange: yellow plate, in reverse order",  # check 1 names "reverse"
        "carrot: blue plate, banana: pink plate",  # an object the world lacks
        "carrot: blue plate, orange: yellow plate, then green apple: pink plate first",  # "first" misplaced
        "the carrot from the blue plate: yellow plate",  # a move, not a placement
        "carrot: blue plate, orange: yellow plate first",  # which one first is not said
        "the blue plate had the carrot, now the orange",  # how things were (the lead's probe), no request
        "the carrot is already on the blue plate. orange: yellow plate",  # a statement of where it is
    ],
)
def test_near_misses_stay_refused(text):
    assert _reading(text) is None, text


def test_read_pairs_refuses_what_check_1_would_not_see():
    assert read_pairs("orange: blue plate, then orange: blue plate", TYPES) is None  # named twice
    assert read_pairs("blue plate", TYPES) is None  # a plate and no object
    assert read_pairs("carrot: blue plate; orange", TYPES) is None  # an object with no plate
    assert read_pairs("to begin, carrot: blue plate, orange: yellow plate", TYPES) is None  # no "then"


def test_other_worlds_never_get_the_fallback():
    from nl2hltl2plan.language.tabletop_pairs import tabletop_fallback
    from nl2hltl2plan.worlds import load_world

    kitchen = load_world("FloorPlan1")
    assert tabletop_fallback("carrot: blue plate, orange: yellow plate", kitchen, "offline") is None
