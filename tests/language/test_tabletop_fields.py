"""Tabletop wordings read since h104 (issue 28; `tabletop_fields`, `tabletop_dialogue`), each with what must
stay a refusal: records of labelled fields, a collective noun before "as follows", Markdown parts ordered by
"(after X)", "Don't put ... until then", an order label that any order will do ("Order: any"), a dialogue
with the robot, and a test scenario's outcome."""

from __future__ import annotations

import pytest

from nl2hltl2plan.language.tabletop_fields import fields_read
from tests.language.test_tabletop_lines import YELLOW_THEN_BLUE
from tests.language.test_tabletop_typos_and_frames import TWO_FREE, _read

KINDS = {"green apple": False, "orange": False, "blue plate": True, "yellow plate": True}
THREE_FREE = ([("GreenApple", "PinkPlate"), ("Orange", "YellowPlate"), ("RedApple", "BluePlate")], [])


@pytest.mark.parametrize(
    "text",
    [
        "Object: green apple\nTarget: blue plate\n\nObject: orange\nTarget: yellow plate",
        "Thing: green apple. Where: blue plate.\nThing: orange. Where: yellow plate.",
        "Item: the orange; Destination: the yellow plate. Item: the green apple; Destination: the blue "
        "plate.",
    ],
)
def test_a_record_of_labelled_fields_pairs_each_thing_with_its_plate(text):
    assert _read(text) == TWO_FREE


@pytest.mark.parametrize(
    "text",
    [
        # the plate's label first: which plate goes with which thing is not said by the order alone
        "Plate: blue plate. Object: green apple. Plate: yellow plate. Object: orange.",
        "Object: green apple. Target: blue plate. Object: orange.",  # a field left unpaired
        "Object: green apple. Target: not the blue plate. Object: orange. Target: yellow plate.",
        "Object: oranges. Target: blue plate.",  # a plural: how many is not said
    ],
)
def test_a_record_that_does_not_pair_up_stays_unread(text):
    assert _read(text) is None
    assert fields_read(text, KINDS) == text


def test_the_records_pairs_keep_the_order_said_after_them():
    text = "Object: green apple. Target: blue plate. Object: orange. Target: yellow plate. Order: any"
    assert _read(text) == TWO_FREE
    records = ("Object: green apple and orange. Target: yellow plate. Object: carrot and red apple. Target: "
               "blue plate.")
    assert _read(f"{records} Yellow plate first.") is None  # "first" of a plate: not read here


@pytest.mark.parametrize(
    "text",
    [
        "Sort the fruit as follows: the green apple onto the blue plate, the orange onto the yellow plate.",
        "Arrange the food as follows, in any order: green apple on the blue plate, orange on the yellow "
        "plate.",
    ],
)
def test_a_collective_noun_before_as_follows_is_the_list_after_it(text):
    assert _read(text) == TWO_FREE


def test_as_follows_keeps_the_lists_own_order():
    text = ("Sort the fruit as follows: the green apple onto the blue plate, then the orange onto the yellow "
            "plate.")
    assert _read(text) == ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")],
                           [(("GreenApple", "BluePlate"), ("Orange", "YellowPlate"))])


def test_markdown_parts_each_after_the_one_before_are_in_turn():
    for text in [
        "### Phase A\ngreen apple + orange → yellow plate\n### Phase B (after A)\ncarrot + red apple → blue "
        "plate",
        "## Part 1\nthe green apple and the orange on the yellow plate\n## Part 2 (after part 1)\nthe carrot "
        "and the red apple on the blue plate",
    ]:
        assert _read(text) == YELLOW_THEN_BLUE
    # the third part after the first, not the second: the headings' order is not read
    chained_otherwise = ("### Phase A\ngreen apple → yellow plate\n### Phase B (after A)\ncarrot → blue "
                         "plate\n### Phase C (after A)\norange → pink plate")
    assert _read(chained_otherwise) is None
    # parts with no order said between them: not read as free (main read them so, exit 0)
    assert _read("### Phase A\ngreen apple + orange → yellow plate\n### Phase B\ncarrot + red apple → blue "
                 "plate") is None


def test_dont_put_until_then_waits_for_the_sentence_before():
    text = ("Put the green apple and the orange on the yellow plate. Don't put the carrot and the red apple "
            "on the blue plate until then.")
    assert _read(text) == YELLOW_THEN_BLUE
    assert _read(text.replace("Don't put", "Do not start putting")) == YELLOW_THEN_BLUE
    assert _read("Don't put the orange on the yellow plate until then.") is None  # no sentence before
    # "until" a state that is no sentence before: not this reading
    assert fields_read("Put A. Don't put the orange on the yellow plate until the carrot is in.", KINDS) == (
        "Put A. Don't put the orange on the yellow plate until the carrot is in."
    )


@pytest.mark.parametrize("label", ["Order: any", "Order - whatever", "(order: any)", "Sequence: free"])
def test_an_order_label_that_frees_the_order_is_refused_beside_then(label):
    ordered = "put the green apple on the pink plate, then the orange on the yellow plate"
    assert _read(f"{ordered}. {label}") is None  # as "..., then ..., in any order" is
    free = ("put the green apple on the pink plate, the orange on the yellow plate and the red apple on the "
            "blue plate")
    assert _read(f"{free}. {label}") == THREE_FREE


def test_a_dialogue_with_the_robot_is_what_its_user_asks():
    asked = ("The green apple on the pink plate, the orange on the yellow plate and the red apple on the "
             "blue plate.")
    for answer in ("Doesn't matter.", "Either order is fine, thanks!"):  # the second: free_order.txt's
        dialogue = f"Robot: What do you need?\nMe: {asked}\nRobot: In which order?\nMe: {answer}"
        assert _read(dialogue) == THREE_FREE
    assert _read(f"Robot: What shall I do?\nUser: Put {asked[4:]}") == THREE_FREE


@pytest.mark.parametrize(
    "text",
    [
        # an answer about the order that says one: not read here
        "Robot: What shall I do?\nUser: Put the green apple on the blue plate and the orange on the yellow "
        "plate.\nRobot: Any particular order?\nUser: Yes, the orange first.",
        # a step's turn asked and answered by names alone: the order is in the questions
        "Robot: Where do I start?\nUser: With the carrot on the blue plate.\nRobot: And next?\nUser: The "
        "orange on the yellow plate.",
        # "Anything else?" / "No.": an answer that names nothing
        "Robot: What shall I do?\nUser: Put the green apple on the blue plate and the orange on the yellow "
        "plate.\nRobot: Anything else?\nUser: No.",
    ],
)
def test_a_dialogue_whose_answers_are_not_read_stays_a_refusal(text):
    assert _read(text) is None


def test_a_test_scenarios_outcome_is_what_is_asked():
    assert _read("Scenario: tidy the table. Given the robot is at its start, when I say go, then the green "
                 "apple is on the blue plate and the orange is on the yellow plate.") == TWO_FREE
    lines = ("Given three fruits and three plates\nWhen the robot tidies up\nThen the green apple is on the "
             "pink plate\nAnd the orange is on the yellow plate\nAnd the red apple is on the blue plate")
    assert _read(f"{lines}\nIn any order") == THREE_FREE
    # a context that names a thing of the world is a state, not a step: refused as before
    assert _read("Given the orange is on the yellow plate, when I say go, then the green apple is on the "
                 "blue plate.") is None


@pytest.mark.parametrize(
    "text",
    [
        "Step 1 (any order):\n-> green apple on the yellow plate\n-> orange on the yellow plate\nStep 2, "
        "after step 1 (any order):\n-> carrot on the blue plate\n-> red apple on the blue plate",
        "Stage one, in either order: the green apple and the orange on the yellow plate. Stage two (any "
        "order): the carrot and the red apple on the blue plate.",
    ],
)
def test_step_labels_that_each_free_their_own_step_order_the_steps_alone(text):
    # h229: "(any order)" on a label frees inside that step; arrows opening lines are bullets
    assert _read(text) == YELLOW_THEN_BLUE


def test_a_step_label_freeing_its_step_beside_one_that_does_not_stays_a_refusal():
    # which steps are free is said of one step only: not read as "within each step"
    assert _read("Step 1 (any order): green apple on the yellow plate. orange on the yellow plate. Step 2: "
                 "carrot on the blue plate. red apple on the blue plate.") is None
