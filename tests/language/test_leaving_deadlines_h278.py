"""Issue 23 / 28 (h278): a "before" whose clause names no task of the reading is a deadline, never an order
between tasks. The request's own "you" that only leaves ("Before you leave, ...", "Before you move out
(kitchen): ...", "... before you head out.") is met by doing the tasks now; "you" with a task's verb ("before
you put the mug in the sink") still orders. Before, "Before you move out (kitchen): A, and B. A first." was
refused as "contradictory ordering", blaming the user for an order the text does not contain: the colon did
not end the clause, and its reference took A as the task it waits for."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str]]:
    from trust_sets import world_of

    res = translate(text, world_of("FloorPlan1"), build=False, actions="none")
    name = {t.id: t.summary() for t in res.tasks}
    return sorted(name.values()), sorted((name[a], name[b]) for a, b in res.before), res.unparsed


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "Before you leave, put the egg in the fridge and the mug in the sink.",
        "Before you move out (kitchen): put the egg in the fridge and the mug in the sink.",
        "Put the egg in the fridge and the mug in the sink before you head out.",
    ],
)
def test_a_you_that_only_leaves_is_a_deadline_not_an_order(text: str) -> None:
    assert read(text) == ([EGG, MUG], [], [])


@pytest.mark.data
def test_its_deadline_leaves_the_orders_the_text_says() -> None:
    """paper_h269 line 30's class in another kitchen (that line was refused as "contradictory ordering")."""
    text = "Before you move out (kitchen): put the egg in the fridge, and put the mug in the sink. Mug first."
    assert read(text) == ([EGG, MUG], [(MUG, EGG)], [])


@pytest.mark.data
def test_you_with_a_tasks_verb_still_orders() -> None:
    text = "Before you put the mug in the sink: put the egg in the fridge."
    assert read(text) == ([EGG, MUG], [(EGG, MUG)], [])


@pytest.mark.data
def test_a_you_doing_something_else_is_still_left_unread() -> None:
    """Not a leaving verb: no deadline is guessed; the clause stays unread by name."""
    _, order, unread = read("Before you sing: put the egg in the fridge and the mug in the sink.")
    assert order == [] and any("you sing" in u for u in unread)
