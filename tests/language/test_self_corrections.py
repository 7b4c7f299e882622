"""The household reader's forms of issue 28 (h108): self-corrections ("in the sink, no wait, in the
cabinet"), "... respectively" lists, a verb left out after a casual verb ("pop the tomato in the fridge and
then the pan in the sink") and a numbered recipe whose steps may come in either order. Each correction
replaces what it corrects; what is unclear is refused by name; nothing is read half."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.translate import translate


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


MUG_CABINET, APPLE_FRIDGE = "place Mug -> Cabinet", "place Apple -> Fridge"


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        ("put the mug in the sink, no wait, in the cabinet", [MUG_CABINET]),
        ("put the mug in the sink... I mean the cabinet", [MUG_CABINET]),
        ("put the mug on the counter, sorry, I mean in the cabinet", [MUG_CABINET]),
        ("put the mug in the sink, make that the cabinet", [MUG_CABINET]),
        ("put the egg in the fridge, I mean the apple", [APPLE_FRIDGE]),  # a thing for a thing
        ("hang the apple... actually put it in the fridge", [APPLE_FRIDGE]),  # a clause: the grammar's
        ("put the egg, no wait, the apple in the fridge", [APPLE_FRIDGE]),  # the name; the place stays
        ("what I mean is put the apple in the fridge", [APPLE_FRIDGE]),  # no correction
        ("put the egg in the fridge, sorry, I mean the microwave", ["place Egg -> Microwave"]),
        # the name said again in a whole clause: the clause replaces the one corrected (h147's voices)
        ("put the spoon in the drawer, no wait, the cup, put the cup in the drawer", ["place Cup -> Drawer"]),
    ],
)
def test_a_correction_replaces_what_it_corrects(kitchen, text, tasks):
    assert reading(text, kitchen) == (tasks, [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, named",
    [
        ("put the mug in the sink, no wait", "'no wait' says nothing in place"),
        ("put the pan in the sink, I mean the pot", "is unclear ('pan' or 'sink')"),  # a pot is both
        ("put the mug in the sink, sorry, the apple and the egg", "names not one thing or place"),
        ("put the spoon in the drawer, I mean the cup, put the cup in the drawer too", "replaces or adds"),
        ("put the spoon in the drawer, no wait, the cup, put the mug in the sink", "is unclear ('spoon' or"),
    ],
)
def test_an_unclear_correction_is_refused_by_name(kitchen, text, named):
    with pytest.raises(HTTError) as refused:
        translate(text, kitchen, build=False, actions="none")
    assert named in str(refused.value)


@pytest.mark.data
def test_respectively_pairs_things_and_places_in_turn(kitchen):
    text = "put the mug, the egg and the apple in the sink, the microwave and the fridge respectively"
    assert reading(text, kitchen)[0] == ["place Mug -> SinkBasin", "place Egg -> Microwave", APPLE_FRIDGE]
    text = "put the mug and apple on the counter and in the fridge, respectively, then the egg in the sink"
    assert reading(text, kitchen) == (
        ["place Mug -> CounterTop", APPLE_FRIDGE, "place Egg -> SinkBasin"],
        [("A", "C"), ("B", "C")],
    )
    with pytest.raises(HTTError, match="pairs 2 things with 3 places"):
        translate("put the mug and the apple in the sink, the fridge and the cabinet respectively", kitchen)


@pytest.mark.data
@pytest.mark.parametrize("verb", ["pop", "plonk", "shove", "stick", "chuck", "toss", "drop", "set", "leave"])
def test_a_verb_left_out_after_a_casual_verb(kitchen, verb):
    text = f"{verb} the tomato in the fridge and then the mug in the sink"
    assert reading(text, kitchen) == (["place Tomato -> Fridge", "place Mug -> SinkBasin"], [("A", "B")])


@pytest.mark.data
def test_a_numbered_recipe_whose_steps_may_come_in_either_order(kitchen):
    text = "Method: 1. put the apple in the fridge. 2. put the mug in the cabinet. Either may come first."
    assert reading(text, kitchen) == ([APPLE_FRIDGE, MUG_CABINET], [])


@pytest.mark.data
@pytest.mark.parametrize(
    "said", ["Step 2 comes first.", "Do step 2 first.", "The first step goes last.", "Step 1 after step 2."]
)
def test_an_order_said_by_step_number(kitchen, said):
    """The steps' numbers are no order of their own: "step 2 comes first" puts step 2 first (the grammar
    read it as step 1 before step 2)."""
    text = f"Step 1: put the apple in the fridge. Step 2: put the mug in the cabinet. {said}"
    assert reading(text, kitchen) == ([MUG_CABINET, APPLE_FRIDGE], [("A", "B")])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, named",
    [
        (
            # (an order between two of three steps now orders those two, h292; one against itself is refused)
            "1. put the apple in the fridge 2. put the mug in the sink 3. put the egg in the microwave. "
            "Step 2 before step 2.",
            "orders a step against itself",
        ),
        ("put the apple in the fridge and the mug in the sink. Step 1 first.", "does not number"),
        # (a step outside the list; "Do it." names nothing and is dropped as frame since h244)
        (
            "Put the mug in the cabinet. 1. put the apple in the fridge 2. put the egg in the sink. "
            "Step 2 first.",
            "outside the",
        ),
    ],
)
def test_an_order_by_step_number_that_cannot_be_read_is_refused(kitchen, text, named):
    with pytest.raises(HTTError) as refused:
        translate(text, kitchen, build=False, actions="none")
    assert named in str(refused.value)


# h118 (issues 23 and 28): "no", "nope", "actually" or "scratch that part" after a pause, then a clause
@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks",
    [
        ("hang the apple... no, put it in the fridge", [APPLE_FRIDGE]),  # "it": the apple
        ("hang the apple - nope, put it in the fridge", [APPLE_FRIDGE]),
        ("hang the apple -- scratch that part, put it in the fridge", [APPLE_FRIDGE]),
        ("heat the apple and hang it, no, put it in the fridge", ["heat_place Apple -> Fridge"]),  # "hang it"
        ("put the egg in the sink... no, put the apple in the fridge", [APPLE_FRIDGE]),  # the whole phrase
        ("put the mug in the sink -- scratch that part, in the cabinet", [MUG_CABINET]),  # a place
        ("put the egg in the fridge... nope, the apple", [APPLE_FRIDGE]),  # a thing
    ],
)
def test_a_clause_after_a_pause_marker_replaces_the_verb_phrase_before_it(kitchen, text, tasks):
    assert reading(text, kitchen) == (tasks, [])


@pytest.mark.data
@pytest.mark.parametrize(
    "text, named",
    [
        ("put the mug in the sink and the egg in the fridge, no, put the apple in the fridge", "is unclear"),
        ("don't put the mug in the sink... no, put it in the fridge", "follows a negated request"),
        ("never hang the apple - nope, put it in the fridge", "follows a negated request"),
        ("hang the apple and the egg... no, put them in the fridge", "is unclear"),
        ("put the mug on the counter... no, put the apple next to it", "which thing"),  # "it": not the mug
        ("put the mug in the sink -- scratch that part", "says nothing in place"),
        ("no, don't put the mug in the sink", "'no' (negation)"),  # a negation, no correction
        ("put the apple in the fridge, no, put the mug in the sink too", "replaces or adds ('too')"),
        ("put the apple in the fridge, nope, heat it first", "replaces or adds ('first')"),
    ],
)
def test_a_clause_correction_whose_part_is_unclear_is_refused_by_name(kitchen, text, named):
    with pytest.raises(HTTError) as refused:
        translate(text, kitchen, build=False, actions="none")
    assert named in str(refused.value)


@pytest.mark.data
@pytest.mark.parametrize(
    "text, quoted",
    [
        # a second correction after a first one rewrote "it": the phrase as typed, not "put the mug in ..."
        (
            "put the mug in the sink... no, put it in the cabinet and the fork in the drawer, no, put it in "
            "the sink",
            "('put it in the cabinet and the fork in the drawer')",
        ),
        # the grammar's refusal of a corrected clause: the user's words, not "chill the apple, ..."
        ("heat the apple... no, chill it, and then dance", "no task in 'heat the apple... no, chill it, and"),
    ],
)
def test_a_refusal_after_a_correction_quotes_the_words_typed(kitchen, text, quoted):
    with pytest.raises(HTTError) as refused:
        translate(text, kitchen, build=False, actions="none")
    assert quoted in str(refused.value)
    assert "'put the mug in the cabinet" not in str(refused.value)
    assert "'chill the apple" not in str(refused.value)


def test_in_own_words_quotes_only_what_was_rewritten():
    from nl2hltl2plan.language.self_corrections import in_own_words

    said, read = "hang the apple... no, put it in the frdige", "put the apple in the frdige"
    assert in_own_words("'frdige' is no place", read, said) == "'frdige' is no place"  # typed as quoted
    swaps = [("put the apple in the frdige", "put it in the frdige")]
    assert in_own_words("no task in 'put the apple in the frdige'", read, said, swaps) == (
        "no task in 'put it in the frdige'"
    )
    assert in_own_words("no task in 'put the apple in the frdige'", read, said) == f"no task in {said!r}"
    assert in_own_words("'put the apple'", said, said) == "'put the apple'"  # nothing rewritten


@pytest.mark.data
def test_a_no_inside_the_sentence_stays_a_negation_and_actually_may_add(kitchen):
    """("actually put the mug in the sink too" adds: its clause stays the grammar's, and check 1 names it)"""
    for text in (
        "put no mug in the sink",
        "put the apple in the fridge... no, don't put it in the sink",
        "put the apple in the fridge, actually put the mug in the sink too",
    ):
        assert translate(text, kitchen, build=False, actions="none").partial


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h118dev", "users_h118held"])
def test_the_h118_user_set_reads_nothing_wrong(name):
    """h118's user-style set of self-corrections, read as `plan` reads it: no line is read wrong."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [trust_sets.outcome(gt) for gt in trust_sets.load(name)]
    assert [why for what, why in outcomes if what == "wrong"] == []
