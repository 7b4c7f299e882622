"""Issue 28 (h228): a clause the grammar leaves unread ("put a box on an armchair, order doesn't matter": read
as a list of destinations) is rewritten by the slot model's rescue (`learned/rescue.py`) with its closing
free-order remark restated as ", in any order", so the grammar still groups the sentence's clauses: "After
you're done, B, C, order doesn't matter" is [A, B] and [A, C] (ANNOTATION_GUIDE.md, "After (doing) X, Y" for
the whole group). Before, the rewrite dropped the remark and, since h213's "then" by the guide, C lost its
order after A."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.language.grammar_readings import offline_reading

TYPES = {"Watch", "Safe", "Laptop", "FloorLamp", "DeskLamp", "Box", "KeyChain", "ArmChair", "Sofa"}
HELD_OUT = Path(__file__).parent / "data" / "rescue_free_order_h228_heldout.txt"


def object_order(text: str) -> set[str]:
    """The closure of the offline reading's order as "Object<Object" (nothing unread)."""
    tasks, order, unread = offline_reading(text, TYPES)
    assert not unread and len(tasks) == len({t.split()[1] for t in tasks})
    return {f"{a.split()[1]}<{b.split()[1]}" for a, b in order}


@pytest.mark.parametrize(
    ("text", "order"),
    [
        (  # before: Watch<Laptop only
            "Place a watch inside of the safe. After you're done, look at a laptop under the lamp, put a box "
            "on an armchair, the order doesn't matter.",
            {"Watch<Laptop", "Watch<Box"},
        ),
        (  # before: Watch<Laptop only
            "Place a watch inside of the safe. After you're done, look at a laptop under the lamp, put a box "
            "on an armchair, order isn't important.",
            {"Watch<Laptop", "Watch<Box"},
        ),
        (  # near miss: read right before too
            "Put the keychain in the safe. Afterwards, examine a laptop under the lamp, put a box on the "
            "sofa, order doesn't matter.",
            {"KeyChain<Laptop", "KeyChain<Box"},
        ),
        # near miss: a clause the grammar reads ("the order is up to you" was never in a failed clause)
        (
            "Put the keychain in the safe. Once that's done, put the watch on the sofa, put a box on an "
            "armchair, the order is up to you.",
            {"KeyChain<Watch", "KeyChain<Box"},
        ),
        # near miss: a remark with nothing to order stays read, not left over
        ("Put a box on an armchair, order doesn't matter.", set()),
    ],
)
def test_a_rescued_clause_keeps_its_free_order_remark(text, order):
    assert object_order(text) == order


def test_the_generator_row_h213_broke():
    """trainstyle_unseen 60 (language_failures.py): its truth A<B, A<C, D<A (closure) again."""
    text = (
        "Ok so place a watch inside of the safe. After you're done, turn on the light while holding a "
        "laptop, put a box with a key chain in it on an armchair, order doesn't matter. Before you get to "
        "the watch, get a box to take to the lamp to examine it by light please."
    )
    tasks, order, unread = offline_reading(text, TYPES)
    a, b, c, d = tasks
    assert not unread and {(a, b), (a, c), (d, a)} <= order and (b, c) not in order and (c, b) not in order


def _held_out() -> list[tuple[str, set[str]]]:
    rows = [line.split(" | ") for line in HELD_OUT.read_text().splitlines() if not line.startswith("#")]
    return [(text, set(order.split())) for text, order in rows]


@pytest.mark.sweep
@pytest.mark.parametrize(("text", "order"), _held_out())
def test_held_out_lines(text, order):
    """Committed before the rule (6c971e3f) and scored once."""
    assert object_order(text) == order
