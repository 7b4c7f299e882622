"""h281 (issue 24): a voice's opening and closing sentences that ask for nothing. The runs of sentences at
either end of a handover instruction that name no thing of the scene, no action the world has and no
order or count are frame (`handover_discourse._voice_edges`): there any noun English knows is filler
("Glove on, hood off.", "Here's the combination.", "Lanes are oiled and ready."), and so are a verb on the
listener's own things ("Grab your partners!") and the readers' words for things and actions no world has
("Correct answer."). They are dropped and said in the result's assumptions. A sentence between two
commands, a noun after a demonstrative ("Smash that like button."), an order or count ("Follow me down,
in single file."), a world's verb on a thing ("Take a bow.") and a word no English list knows ("Bullseye.")
keep the strict rule. "Now" said after a block's place ("where the red block is at present") is the
block's start, as "currently" is.

The sentences are the committed batch `dev_h281` (handover_styles_session10.json), written with the
held-out `held_h281` before the rules.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import TASKS as HANDOVER
from handover_specs import assert_refused_by_name, assert_written_spec, assert_written_spec_or_refused

from nl2hltl2plan.language.handover_discourse import empty
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.handover.handover_bench import instance

DEV = STYLES["dev_h281"]
PLACEMENT = "Put the three blocks on H, I and J, one block per region."

WRITTEN = [
    (3, DEV["bowling_captain"]["3"]),  # "Lace up your shoes. ... Strike!"
    (4, DEV["astronaut"]["4"]),  # "Houston, we have a visual. ... where the red block is at present. ..."
    (2, "Glove on, hood off. " + PLACEMENT + " Grab your partners!"),
]

# an opening or closing that may ask for something, and a frame between two commands
KEPT = [
    (2, PLACEMENT + " Take a bow."),  # a world's verb on a thing
    (2, "Follow me down, in single file. " + PLACEMENT),  # an order
    (2, "Put the three blocks on H, I and J. Hood off. One block per region."),  # between two commands
    (2, PLACEMENT + " Smash that like button."),  # a thing pointed at
    (2, DEV["quizmaster"]["2"]),  # "... Correct answer.": "correct" may be a command on a thing (lead's mend)
    (2, PLACEMENT + " Nice and steady, stoke the forge."),  # a verb with an object (h235, h220, h263)
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_a_voices_opening_and_closing_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), KEPT)
def test_a_sentence_that_may_ask_for_something_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


def test_only_a_voices_edge_may_hold_any_noun() -> None:
    assert empty("Glove on, hood off", whole=True, voice=True) and not empty("Glove on, hood off", whole=True)
    assert empty("Grab your partners", whole=True, voice=True)
    assert empty("All hands on deck", whole=True, voice=True)  # "all" of a noun that names nothing
    assert not empty("Grab your block", whole=True, voice=True)  # a scene's thing
    assert not empty("Take a bow", whole=True, voice=True)  # a world's verb on a thing
    assert not empty("Follow me down, in single file", whole=True, voice=True)  # an order


@pytest.mark.data
def test_what_the_voice_rule_drops_is_said_in_the_result() -> None:
    result = translate("Glove on, hood off. " + PLACEMENT, instance(HANDOVER[2], 0, 0).as_world())
    assert any("'Glove on, hood off'" in a and "dropped as frame" in a for a in result.assumptions)


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), [(int(t), s) for v in DEV.values() for t, s in v.items()])
def test_development_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
