"""Issue 24, sixth round (h63): a question the writer answers ("Where do the three objects go? G, H and I."),
a goal's timing said in a sentence of its own ("Yellow can go at any time.") (`language/handover_answers.py`),
a prohibition that opens with its period after "and" or without a comma ("and in the meantime put
nothing on F"), "other than these three" (regions), "right next to the arms" without their letters,
"placed one after another" after a goal and a topic said first in unpunctuated speech ("so the three
blocks i need them on ..."). Each class has sentences of our own that must give the written spec and
near misses that must be refused or give another spec (never the written one)."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.handover_answers import answered, timing_joined

READ = [
    # a question the writer answers
    (6, "Where do the three objects go? G, H and I. Which block first? Red, then blue."),
    (6, "Where should the three objects go? To G, H and I, one each. In what order? Red, then blue."),
    (2, "Where do the three blocks go? H, I and J, one per region."),
    (1, "Where do the three blocks go? To the opposite side. Which one goes down first? Red, then blue."),
    (2, "Which objects? All three blocks. Where to? Regions H, I and J. How many per region? Only one."),
    (8, "Where does the yellow block go? First to region I, then to region G. What about red and blue? Any "
     "empty region, at any time."),
    (7, "Where do the three objects go? All onto region I, one after another. The order? Red, then blue. In "
     "the meantime? Nothing on F, G or H."),
    (3, "What's the task? Move the three pillars to E, F and G beside arms a and b. Is anything allowed on "
     "the other regions? No, nothing at all."),
    (4, "What first? Move the three blocks to the opposite regions; don't touch blue until red has been "
     "touched. And then? Put yellow back on G."),
    # a goal's timing in a sentence of its own, after the clause that names the block
    (5, "Swap red and blue, red placed first. Move the yellow block to the opposite side. Yellow can go at "
     "any time."),
    (5, "Swap red and blue, red placed first. Move the yellow block to the opposite side. It doesn't matter "
     "when yellow goes."),
    (5, "Swap red and blue, red placed first, and move the yellow block to the opposite side. The yellow "
     "block can be moved whenever you like."),
    (8, "First place the yellow block on region I, then on region G. Move red and blue to any empty region. "
     "Red and blue can go at any time."),
    # a prohibition that opens with its period, after "and" or without its comma
    (7, "Place the three objects on region I one after another, red before blue, and in the meantime put "
     "nothing on F, G or H."),
    (7, "Place the three objects on region I one after another, red before blue, and meanwhile put nothing "
     "on F, G or H."),
    (7, "Place the three objects on region I one after another, red before blue. In the meantime put "
     "nothing on F, G or H."),
    # "other than these three": the regions just named, counted
    (3, "Move the three pillars to E, F and G beside arms a and b. No object may be placed on any region "
     "other than these three."),
    (3, "The three pillars shall go to regions E, F and G. Put nothing on any region other than those three "
     "regions."),
    # "next to the arms" without their letters: a landmark that the named regions lie within
    (3, "Move the three pillars to E, F and G right next to the arms. Nothing on any other region."),
    (3, "Move the three pillars to E, F and G near the robot arms; no object may be placed on any other "
     "region."),
    # a goal's manner as its participle after a comma
    (7, "The three objects should be on region I, placed one after another. Red before blue. Nothing on F, "
     "G or H during this period."),
    (7, "Put the three objects on region I, placed one by one, red before blue, nothing on F, G or H "
     "meanwhile."),
    # a topic said first in speech without punctuation, taken up by a pronoun
    (2, "so the three blocks I need them on h i and j one per region"),
    (6, "okay so the three objects we want them on g h and i red before blue"),
    # one block on each of the regions just named
    (2, "Put the three blocks on H, I and J, exactly one block in each region."),
    (6, "Place the three objects on G, H and I, one object on each of these regions, red before blue."),
]

REFUSED = [
    # a question with no answer, or an answer that is no place
    (6, "Where do the three objects go? Which block first? Red, then blue."),
    (6, "Where do the three objects go? Somewhere nice. Red before blue."),
    (2, "Which blocks? The three blocks. Where to? Somewhere."),
    (3, "Move the three pillars to E, F and G beside arms a and b. Is anything allowed on the other regions? "
     "Maybe."),
    (8, "Where does the yellow block go? First region I, then region K. And red and blue? Any empty region, "
     "at any time."),
    (2, "How many per region? Two. Put the three blocks on H, I and J."),
    # a goal that is not the last clause before, a block the clause does not name ("It can go at any time."
    # after a clause of one block is read since h114: test_handover_fourteenth_round.py)
    (5, "Move the yellow block to the opposite side. Swap red and blue, red placed first. Yellow can go at "
     "any time."),
    (8, "First place the yellow block on region I, then on region G. Move red and blue to any empty region. "
     "Red can go at any time."),
    (7, "Place the three objects on region I one after another, red before blue, and in the meantime put "
     "nothing on region K."),
    # a count that is not the regions just named
    (3, "Move the three pillars to E, F and G beside arms a and b. No object may be placed on any region "
     "other than these two."),
    # the arms without a place named beside them; "the side of the arms" (which side?)
    (3, "Move the three pillars next to the arms. Nothing on any other region."),
    (3, "Move the three pillars to the side of the arms. Nothing on any other region."),
    # a manner that is no order of the goals; a second place in the participle
    (7, "The three objects should be on region I, placed all at once. Red before blue. Nothing on F, G or "
     "H during this period."),
    (7, "The three objects should be on region I, placed one after another on region G. Red before blue. "
     "Nothing on F, G or H during this period."),
    # a pronoun of the other number, or none, after the topic
    (2, "so the three blocks I need it on h i and j one per region"),
    (2, "so the three blocks I need on h i and j one per region"),
    (2, "Put the three blocks on H, I and J, two blocks on each of those regions."),
]

OTHER = [
    # "Red." alone: red before both others
    (6, "Where do the three objects go? G, H and I. Which block first? Red."),
    # the answer's order the other way round
    (6, "Where do the three objects go? G, H and I. In what order? Blue, then red."),
    # the steps asked for the other way round: the step words are kept
    (4, "What first? Put yellow back on G. And then? Move the three blocks to the opposite regions; don't "
     "touch blue until red has been touched."),
    # something put there meanwhile
    (7, "Place the three objects on region I one after another, red before blue, and in the meantime put "
     "the yellow block on F."),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_sixth_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_sixth_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_sixth_round_forms_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Where do the blocks go? H, I and J.", "the blocks go to H, I and J."),
        ("Where does the yellow block go? On region I.", "the yellow block go On region I."),
        ("Which goes first? The red block, then the blue one.", "The red block first, then the blue one."),
        ("In which order? Red before blue.", "Red before blue."),
        ("Which blocks? Red and blue. Where to? G and H.", "Red and blue go to G and H."),
        ("And yellow? To region I.", "yellow go To region I."),
        ("What first? Move red to G. And then? Blue to H.", "first, Move red to G. then, Blue to H."),
        ("Any rules? Don't touch blue.", "Don't touch blue."),
        ("How many per region? Just one.", "one per region."),
        ("Anything allowed on F? No, nothing.", "nothing on F."),
        ("Anything allowed on F? Yes.", "Anything allowed on F? Yes."),  # not a "no"
        ("Where do they go?", "Where do they go?"),  # no answer
        ("Which block first? Maybe red.", "Which block first? Maybe red."),  # not an answer of blocks
    ],
)
def test_answered_questions_in_words(text, expected):
    assert answered(text) == expected


@pytest.mark.parametrize(
    ("sentences", "expected"),
    [
        (["Put yellow on G", "Yellow can go at any time"], ["Put yellow on G at any time"]),
        (["Put red on H and then put yellow on G", "It does not matter when yellow is moved"],
         ["Put red on H and then put yellow on G at any time"]),
        (["Put yellow on G, then red on H", "Yellow can go at any time"],  # the last clause is red's
         ["Put yellow on G, then red on H", "Yellow can go at any time"]),
        (["Put yellow on G first", "Yellow can go at any time"],  # an order word: which is meant?
         ["Put yellow on G first", "Yellow can go at any time"]),
        (["Yellow can go at any time"], ["Yellow can go at any time"]),  # no goal before it
    ],
)
def test_timing_said_apart_in_words(sentences, expected):
    assert timing_joined(sentences) == expected
