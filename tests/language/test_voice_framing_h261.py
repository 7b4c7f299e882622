"""The voice a household request is framed in (issue 28, h261; `courtesy.txt`): a letter's "Dearest X," and
its closing ("Fondly, Aunt Jo", "All my love, Nana"), farewells ("Love you, bye.", "Over and out."), a radio
call ("Kitchen unit, do you read?"), a voicemail's opening, the caller naming themself ("hiya, it's me.") and
an apology for the message ("Sorry to bother you again!") ask for nothing and are dropped; a bare "sorry"
and thanks for a step stay. The dev set's lines (users_h261dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"
REQUEST = "Put the egg in the fridge and put the mug in the sink."


def read(text: str) -> tuple[list[str], list[str]]:
    """(the tasks' summaries, what is left unread)."""
    from trust_sets import world_of

    res = translate(text, world_of("FloorPlan28"), build=False, actions="none")
    return [t.summary() for t in res.tasks], res.unparsed


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        f"Dearest Lily, {REQUEST.lower()} All my love, Grandpa",
        f"Kitchen unit, do you read? {REQUEST} Over and out.",
        f"Message after the beep: hiya, it's me. {REQUEST} Love you, bye.",
        f"Sorry to bother you again! {REQUEST} Fondly, Aunt Jo",
        f"Voicemail: hi sweetheart, it's Mum again, sorry for the long message. {REQUEST} Bye!",
    ],
)
def test_voice_framing_is_dropped(text: str) -> None:
    assert read(text) == ([EGG, MUG], [])


@pytest.mark.data
def test_the_place_of_a_topic_before_a_dash_is_where_it_is() -> None:
    tasks, unparsed = read("The apple in the microwave - slice it, chill a piece and put it on the counter.")
    assert (tasks, unparsed) == (["cool_place Apple(sliced) -> CounterTop"], [])


@pytest.mark.data
def test_thanks_for_a_step_still_stays_unread() -> None:
    _, unparsed = read(f"Thanks for putting the apple away. {REQUEST}")
    assert any("Thanks for putting" in u for u in unparsed), unparsed


@pytest.mark.sweep
@pytest.mark.data
def test_h261_dev_set() -> None:
    """Every line of h261's dev set converts."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("users_h261dev")]
    assert [gt.instruction for gt, what in rows if what != "converted"] == []
