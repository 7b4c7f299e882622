"""Issue 28 (h223): a duty in the passive ("the cup has to be washed and put in the cabinet", "the bowl needs
washing and putting on a shelf", a note's "a bar of soap to be rinsed and put ..."), "would you mind V-ing",
the hedge of "could you possibly", and notes with a header from a host, landlord or carer ("Hi, it's your
host! Before you check out: ...", "Handover for the evening carer: ..."). The same words where nothing is
asked or where a header holds a word of no list are left, to be read or refused by name."""

from __future__ import annotations

import pytest
from household_readings import outcome

from nl2hltl2plan.language.courtesy import without_framing, without_greetings
from nl2hltl2plan.language.grammar.treatments_said import treatments_said
from nl2hltl2plan.language.numbered_steps import bullets_apart
from nl2hltl2plan.language.translate import translate


@pytest.mark.parametrize(
    "text, rewritten",
    [
        ("the cup has to be washed and put in the cabinet", "wash the cup and put it in the cabinet"),
        ("a slice of bread should be cooled in the fridge", "cool a slice of bread in the fridge"),
        ("the bowl needs washing and putting on a shelf", "wash the bowl and put it on a shelf"),
        ("a tomato slice needs to be heated and left on the counter",
         "heat a tomato slice and put it on the counter"),
        ("Would you mind chilling a mug and leaving it in the sink?",
         "chill a mug and leave it in the sink?"),
        ("do you mind heating an egg, then putting it away", "heat an egg, then put it away"),
    ],
)  # fmt: skip
def test_passive_duties_and_minded_requests_are_rewritten(text, rewritten):
    assert treatments_said(text) == rewritten


@pytest.mark.parametrize(
    "text",
    [
        "the mug has to be on the desk",  # a state, no treatment
        "would you mind the mess",  # no verb after "mind"
        "the idea has to be washed and put away",  # no name the lexicon knows
    ],
)
def test_the_same_words_asking_nothing_are_left(text):
    assert treatments_said(text) == text


def test_a_host_or_carer_header_goes_and_an_unknown_one_stays():
    assert without_framing("It's your landlord. Put the mug away.") == "Put the mug away."
    greeted = without_greetings("Hi, it's your host! Put the mug away.", bool)
    assert without_framing(greeted) == "Put the mug away."
    assert without_greetings("Handover for the evening carer: put the mug away.", bool) == "put the mug away."
    # "the evening cook" is in no list of who a note is for: the header stays, to be read or refused
    kept = "Handover for the evening cook: put the mug away."
    assert without_greetings(kept, bool) == kept


@pytest.mark.parametrize(
    "text, items",
    [
        ("To-do: - chill a cup - wash a pan", "To-do: chill a cup. wash a pan."),
        ("To do \u2022 wash a plate, put it away \u2022 wash the pan",
         "To do: wash a plate, put it away. wash the pan."),
        ("- [ ] put the mug in the sink - [ ] put the egg away",
         "put the mug in the sink. put the egg away."),
        ("Robot - put the mug in the sink - now", "Robot - put the mug in the sink - now"),  # no list
    ],
)
def test_to_do_lists_are_one_sentence_an_item(text, items):
    assert bullets_apart(text) == items


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan7")


@pytest.mark.data
@pytest.mark.parametrize(
    "text, read",
    [
        ("A bowl needs washing and putting on a shelf.", ["clean_place Bowl -> Shelf"]),
        ("The apple has to be chilled and left on the counter.", ["cool_place Apple -> CounterTop"]),
        ("Would you mind heating a mug and putting it on the coffee maker?",
         ["heat_place Mug -> CoffeeMachine"]),
        ("Welcome! A few things before you leave: the pan needs to go on the counter.",
         ["place Pan -> CounterTop"]),
        ("The apple is to be thrown away.", ["place Apple -> GarbageCan"]),
        # main read "check out" as an examination it could not place (partial)
        ("Before you check out: put the pan on the counter.", ["place Pan -> CounterTop"]),
        ("Handover for the evening cook: the pan needs to go on the counter.", "refused"),  # 'cook' is read
    ],
)  # fmt: skip
def test_read_in_a_kitchen(kitchen, text, read):
    assert outcome(text, kitchen) == read


@pytest.mark.data
def test_a_to_do_list_gone_through_top_to_bottom_is_a_chain(kitchen):
    said = "To-do: - chill a mug and put it in the sink - put the pan on the counter. Go top to bottom."
    res = translate(said, kitchen, "offline", build=False, actions="none")
    assert [t.summary() for t in res.tasks] == ["cool_place Mug -> SinkBasin", "place Pan -> CounterTop"]
    assert [tuple(pair) for pair in res.before] == [("A", "B")]
