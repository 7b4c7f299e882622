"""h296 (issue 24): a voice's remarks around a handover instruction (`language/voice_remarks.py`). At a
voice's opening or closing, a warning of nothing the scene has ("Mind the dog.", "Keep back from the
grate.") and a farewell ("Ta-ra.") are frame; a tag question or an endearment after a comma at a sentence's
end ("..., there's a dear.", "..., isn't it, pet?") is dropped; a heading of the voice's own words over a
command ("Today's special: put ...", "Warm-up set: ...") and a record's kind with a number said in words
("Lane two, listen.") are frame. Goal words of a voice: "ferry ... over to", "are headed for", "dances
to", "outside that target area". A warning of a scene's thing, a heading that hedges or says when
("Optional:", "Done:") and a command with an object (h235) stay refused.

The sentences are the committed batch `dev_h296` (handover_styles_session10.json), written with the
held-out `held_h296` before the rules.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import TASKS as HANDOVER
from handover_specs import assert_refused_by_name, assert_written_spec, assert_written_spec_or_refused

from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.language.voice_remarks import caution_of, closing_tags, commanded, heading_words
from nl2hltl2plan.suites.handover.handover_bench import instance

DEV = STYLES["dev_h296"]
PLACEMENT = "Put the three blocks on H, I and J, one block per region."

WRITTEN = [
    (5, DEV["milkman"]["5"]),  # "Mind the dog. ... Ta-ra, love."
    (1, DEV["milkman"]["1"]),  # "..., there's a dear."
    (2, DEV["butcher"]["2"]),  # "Today's special: put ... Anything else, sweetheart?"
    (2, "Lane two, listen. " + PLACEMENT + " Lovely, wasn't it, pet?"),
    (2, "The three blocks are headed for regions H, I and J, with only one block allowed in each region."),
    (8, "First the yellow block dances to region I, then it dances on to region G. The red block and the blue"
     " block can each go to any empty region at any time."),
    (3, "Ferry the three pillars over to the placement area beside arm a and arm b, namely regions E, F and"
     " G; no pillar is to be placed on any region outside that target area."),
]

KEPT = [
    (2, "Mind the red block. " + PLACEMENT),  # a warning of a scene's thing
    (2, "Optional: " + PLACEMENT),  # a heading that hedges
    (2, PLACEMENT + " Please sing a song."),  # a command with an object (h235)
    (2, PLACEMENT + " Not bad, eh?"),  # a negation stays read
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_a_voices_remarks_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), KEPT)
def test_a_remark_that_may_ask_for_something_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


def test_warnings_tags_and_headings() -> None:
    assert caution_of("Keep back from the grate.") == "the grate"
    assert caution_of("Put the dog away") is None
    assert closing_tags("Move it, won't you, love?") == ("Move it", ["won't you", "love"])
    assert closing_tags("Love.") == ("Love.", [])  # a tag alone stays whole
    assert heading_words("Warm-up set") and not heading_words("Done") and not heading_words("Top shelf")
    assert not commanded("Mind the soot") and commanded("Stoke the forge") and commanded("Please sing a song")


@pytest.mark.data
def test_what_the_remark_rule_drops_is_said_in_the_result() -> None:
    result = translate("Mind the dog. " + PLACEMENT + " Ta-ra, love.", instance(HANDOVER[2], 0, 0).as_world())
    notes = " ".join(a for a in result.assumptions if "dropped as frame" in a)
    assert "'Mind the dog'" in notes and "'love'" in notes and "'Ta-ra'" in notes


@pytest.mark.data
@pytest.mark.sweep
@pytest.mark.parametrize(("task", "text"), [(int(t), s) for v in DEV.values() for t, s in v.items()])
def test_development_batch_is_read_right_or_refused(task: int, text: str) -> None:
    assert_written_spec_or_refused(task, text)
