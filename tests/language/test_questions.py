"""Questions and answers ("Q: Where does the mug go? A: In the sink."), read alike in every world
(`headings.answered`) and by the household reader: each answer fills its question's gap, the order answer
orders or frees the tasks, and what is unclear is refused by name."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import reading

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.questions import answered
from nl2hltl2plan.language.translate import translate


@pytest.mark.parametrize(
    "text, stated",
    [
        (  # the household wording: a follow-up asks the question before it again
            "Q: Where does the mug go? A: In the sink. "
            "Q: And the apple? A: The fridge. Q: Order? A: Mug first.",
            "put the mug in the sink, then put the apple in the fridge.",
        ),
        (  # the tabletop wording
            "Q: Where does the green apple go? A: On the blue plate.",
            "put the green apple on the blue plate.",
        ),
        (  # the handover wording: names of no task asked about stay a sentence for the reader
            "Q: Where do the blocks go? A: To the opposite side. Q: Any order? A: Red before blue.",
            "put the blocks to the opposite side. Red before blue.",
        ),
        (
            "Q: Where does the mug go? A: In the sink. "
            "Q: And the apple? A: The fridge. Q: Order? A: Doesn't matter.",
            "put the mug in the sink. put the apple in the fridge. In any order.",
        ),
        (  # "no" to "does the order matter" frees it
            "Q: Where does the mug go? A: sink. Q: What about the egg? A: It goes in the fridge. "
            "Q: Does the order matter? A: No.",
            "put the mug in sink. put the egg in the fridge. In any order.",
        ),
        (  # what goes somewhere: the gap is the object; "after" reverses the chain
            "Q: What goes in the fridge? A: The apple. "
            "Q: And in the sink? A: The mug. Q: Order? A: apple after mug.",
            "put the mug in the sink, then put the apple in the fridge.",
        ),
        (  # what to do with an object: its pronoun is the object
            "Q: What should I do with the potato? A: Heat it and put it on the counter.",
            "heat the potato and put it on the counter.",
        ),
        (  # an answer that is an instruction; "no, that's all" asks nothing more
            "Q: What do you want? A: Put the apple in the fridge. Q: Anything else? A: No, that's all.",
            "put the apple in the fridge.",
        ),
        (  # "which first" with one name; an instruction answer is named by its words
            "Q: What do you need? A: put the egg in the fridge. "
            "Q: Anything else? A: Yes, put the mug in the sink. "
            "Q: Which first? A: The mug.",
            "put the mug in the sink, then put the egg in the fridge.",
        ),
        (  # "where do you want X", "start with X"
            "Q: Where do you want the mug? A: In the sink. Q: And the egg? A: The fridge. "
            "Q: Order? A: Start with the egg.",
            "put the egg in the fridge, then put the mug in the sink.",
        ),
        ("put the apple in the fridge. A: not a question", "put the apple in the fridge. A: not a question"),
        ("Question: could you put the mug in the sink?", "Question: could you put the mug in the sink?"),
    ],
)
def test_answers_fill_their_questions_gaps(text, stated):
    assert answered(text) == stated


@pytest.mark.parametrize(
    "text, named",
    [
        ("Q: Where does the mug go? A: not sure.", "'not sure'"),
        ("Q: Where does the mug go? A: In the sink. Q: And the apple?", "has no answer"),
        ("Q: How hot is the oven? A: very", "'How hot is the oven?' is not one the reader knows"),
        ("Q: Where does the mug go? A: In the sink. "
            "Q: And the apple? A: The fridge. Q: Any order? A: No.", "'no'"),
        ("Q: Where does the mug go? A: In the sink. Q: Order? A: the bowl before the mug.", "'the bowl'"),
        (
            "Q: Where does the mug go? A: In the sink. "
            "Q: And the apple? A: The fridge. Q: And the egg? A: The "
            "microwave. Q: Order? A: mug before apple.",
            "leaves the order of the other tasks unsaid",
        ),
        ("Q: And the apple? A: The fridge.", "is not one the reader knows"),
        ("Q: Where does the mug go? A: Nowhere in particular? "
            "Q: Order? A: Any. Q: Order? A: mug first", "twice"),
        ("Q: Anything else? A: No.", "nothing to do"),
    ],
)
def test_what_is_unclear_is_refused_by_name(text, named):
    with pytest.raises(HTTError) as refused:
        answered(text)
    assert named in str(refused.value)


@pytest.mark.parametrize(
    "text, stated",
    [
        (  # a thing asked alone, its place answered alone: the tabletop, household and handover names
            "Q: Carrot? A: Blue plate. Q: Orange? A: On the yellow plate.",
            "put the carrot in blue plate. put the orange on the yellow plate.",
        ),
        ("Q: The mug? A: The sink.", "put the mug in the sink."),
        ("Q: Red block? A: Region G.", "put the red block in region G."),
        (  # "What goes where?": a list of placements, each put (a verb "goes" dropped)
            "Q: What goes where? A: Green apple on pink plate, orange on yellow plate.",
            "put green apple on pink plate. put orange on yellow plate.",
        ),
        (
            "Q: Where does everything go? A: The mug goes in the sink; the apple in the fridge.",
            "put the mug in the sink. put the apple in the fridge.",
        ),
        (  # steps asked in turn: each answer a step, chained in the order asked
            "Q: What comes first? A: The green apple and the orange on the yellow plate. "
            "Q: Then? A: The carrot and the red apple on the blue plate.",
            "put the green apple and the orange on the yellow plate, then put the carrot and the red apple "
            "on the blue plate.",
        ),
        (  # "then" after one task asked otherwise follows it; an instruction answer keeps its verb
            "Q: Where does the mug go? A: In the sink. Q: After that? A: Heat the apple. "
            "Q: Last? A: The egg in the fridge.",
            "put the mug in the sink, then heat the apple, then put the egg in the fridge.",
        ),
        (  # a constraint answered to "anything else" stays a sentence for the reader
            "Q: What first? A: The red block to region G. Q: What next? A: The blue block to region H. "
            "Q: Anything else? A: Nothing goes on F, G or H meanwhile.",
            "put the red block to region G, then put the blue block to region H. "
            "nothing goes on F, G or H meanwhile.",
        ),
        ("Q: What next? A: The egg in the fridge.", "put the egg in the fridge."),  # nothing before it
        (  # "which first" answered by a name alone is still the order question
            "Q: Where does the mug go? A: sink. Q: And the apple? A: fridge. Q: Which first? A: The apple.",
            "put the apple in fridge, then put the mug in sink.",
        ),
    ],
)
def test_new_forms_state_their_instruction(text, stated):
    assert answered(text) == stated


@pytest.mark.parametrize(
    "text, named",
    [
        ("Q: Blue plate? A: Carrot.", "'Blue plate?' is a name alone"),  # a place asked: not a thing
        ("Q: Sink? A: Mug.", "'Sink?' is a name alone"),
        ("Q: Region G? A: The red block.", "'Region G?' is a name alone"),
        ("Q: Carrot? A: Yes.", "'Carrot?' is a name alone"),
        ("Q: What goes where? A: The mug, the apple.", "'the mug'"),
        ("Q: What goes where? A: mug in the sink, then apple in the fridge", "an order inside a list"),
        ("Q: What first? A: The carrot on the blue plate. Q: What next? A: The orange.", "'the orange'"),
        (
            "Q: Where does the mug go? A: sink. Q: And the apple? A: fridge. "
            "Q: Then? A: the egg in the fridge.",
            "follows 2 tasks",
        ),
        (
            "Q: What first? A: The mug in the sink. Q: Anything else? A: the apple in the fridge. "
            "Q: Then? A: the egg in the fridge.",
            "comes after a task",
        ),
        ("Q: Where does the mug go? A: sink. Q: What first? A: the apple in the fridge.", "after tasks"),
        (
            "Q: What first? A: The mug in the sink. Q: Then? A: The apple in the fridge. Q: Order? A: any",
            "said twice",
        ),
    ],
)
def test_new_forms_refuse_what_is_unclear(text, named):
    with pytest.raises(HTTError) as refused:
        answered(text)
    assert named in str(refused.value)


@pytest.fixture(scope="module")
def kitchen(world):
    return world("FloorPlan1")


@pytest.mark.data
def test_the_household_reader_reads_the_answers(kitchen):
    text = (
        "Q: Where does the mug go? A: In the sink. "
        "Q: And the apple? A: The fridge. Q: Order? A: apple first."
    )
    assert reading(text, kitchen) == (["place Apple -> Fridge", "place Mug -> SinkBasin"], [("A", "B")])
    text = text.replace("apple first", "any")
    assert reading(text, kitchen) == (["place Mug -> SinkBasin", "place Apple -> Fridge"], [])


@pytest.mark.data
def test_the_household_reader_refuses_an_unclear_answer(kitchen):
    with pytest.raises(HTTError, match="'dunno'"):
        translate("Q: Where does the mug go? A: In the sink. Q: Order? A: dunno", kitchen, build=False)


@pytest.mark.data
@pytest.mark.parametrize("name", ["users_h108dev", "users_h108held"])
def test_the_h108_user_set_reads_nothing_wrong(name):
    """h108's user-style set (questions and answers, a verb left out, self-corrections, respectively and
    numbered recipes), read as `plan` reads it: no line is read wrong, and 90 % convert."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
    import trust_sets

    outcomes = [trust_sets.outcome(gt) for gt in trust_sets.load(name)]
    assert [why for what, why in outcomes if what == "wrong"] == []
    assert sum(what == "converted" for what, _ in outcomes) >= 0.9 * len(outcomes)


@pytest.mark.data
def test_the_household_reader_reads_the_steps_in_turn(kitchen):
    text = "Q: What first? A: The mug in the sink. Q: And then? A: The apple in the fridge. "
    text += "Q: Egg? A: Fridge."  # a thing asked alone after the steps: not ordered
    assert reading(text, kitchen) == (
        ["place Mug -> SinkBasin", "place Apple -> Fridge", "place Egg -> Fridge"],
        [("A", "B")],
    )
