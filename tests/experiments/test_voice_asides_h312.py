"""h312 (issue 24): a handover voice's reassurance, plea for patience or apology about nothing of the scene
("Nothing to worry about.", "Don't mind the draught.", "Bear with us.", "Won't take a minute.", "Sorry
about the racket.") is frame at the message's edges, as is a sentence whose comma parts are each such a
remark or empty ("Mind the glue, it's still tacky.", "Straw everywhere today, sorry about that."), one
that ends in "then" after other words ("Nearly bound, then.") and a tag question with a word of praise
("..., aren't they lovely?"). An apology or a reassurance about a thing of the scene stays read or
refused, and "sorry" before a correction is still a correction.

The sentences are the committed batch `dev_h312` (handover_styles_session10.json), written with the
held-out `held_h312` before the rules.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.voice_remarks import aside_of, clauses, commanded

DEV = STYLES["dev_h312"]
PLACEMENT = "Put the three blocks into regions H, I and J, one block in each region."

WRITTEN = [
    (1, DEV["organist"]["1"]),  # "Bear with us, the hymn's nearly over." ... "Sorry about the racket."
    (7, DEV["organist"]["7"]),  # "Don't mind the draught, love." ... "Lovely, aren't they?"
    (2, DEV["bookbinder"]["2"]),  # "Mind the glue, it's still tacky." ... "Won't take a minute."
    (4, DEV["bookbinder"]["4"]),  # ... "Nearly bound, then."
    (6, DEV["bookbinder"]["6"]),  # "No need to worry, the spine's drying." ... "Sorry about the smell ..."
]

KEPT = [
    (2, "Sorry about the red block. " + PLACEMENT),  # an apology about a thing of the scene
    (2, "Don't worry about region K. " + PLACEMENT),  # a reassurance about a place of the scene
    (2, "One more thing, then we're off. " + PLACEMENT),  # "then" before a clause may order what follows
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), WRITTEN)
def test_a_voices_asides_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), KEPT)
def test_an_aside_about_the_scene_stays_refused(task: int, text: str) -> None:
    assert_refused_by_name(task, text)


def test_asides_and_parts() -> None:
    assert aside_of("Bear with me.") == "" and aside_of("Don't mind the draught") == "the draught"
    assert aside_of("Put the red block on G") is None
    assert clauses("Mind the glue, it's still tacky.") == ["Mind the glue", "'s still tacky."]
    assert not commanded("let's be neat about this") and commanded("Bring the mug")
