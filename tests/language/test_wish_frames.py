"""A polite wish frame is read as what it asks (`tabletop_wording.polite_frames`): before a request as
"please", before a state as the wish "i want" (a wish of `state_words.txt`), so that every verb that says
where a thing is reads as a goal, not as a statement of where it is now."""

import pytest

from nl2hltl2plan.language.statements import asked_before
from nl2hltl2plan.language.tabletop_wording import polite_frames
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.worlds.tabletop_world import tabletop_world


@pytest.mark.parametrize("verb", ["went", "were", "were set", "ended up", "landed", "sat"])
@pytest.mark.parametrize(
    "frame", ["I'd appreciate it if", "it would please me if", "I'd be grateful if", "it would be great if"]
)
def test_a_wish_frame_before_a_state_asks_for_it(frame, verb):
    text = f"{frame} the carrot {verb} on the blue plate"
    read = polite_frames(text.lower())
    assert read.startswith("i want ") and asked_before(read, read.index("carrot"))
    result = translate(text, tabletop_world())
    assert [(t.kind, t.object, t.receptacle) for t in result.tasks] == [("place", ["Carrot"], ["BluePlate"])]


def test_a_wish_frame_before_a_request_is_please():
    frames = ("I'd be grateful if you could", "would you be so kind as to", "it would be great if you could")
    for frame in frames:
        said = polite_frames(f"{frame} put the carrot on the blue plate".lower())
        assert said == "please put the carrot on the blue plate"
