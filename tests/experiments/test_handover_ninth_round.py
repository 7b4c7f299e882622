"""Issue 24, ninth round (h71): general normalisation of the discourse around the commands
(`language/handover_discourse.py`). A fragment with no content word, made only of frame words
(`handover_frame_words.txt`), is dropped; reported speech and first-person narration are read as the
commands they report. Sentences of our own must give the written spec; near misses that name something
in their frame must be refused; reports that say something else must not give the written spec.
"""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_refused_by_name, assert_written_spec

from nl2hltl2plan.language.content_words import vocabulary
from nl2hltl2plan.language.handover_discourse import MEANING, empty, frame_words, plain

READ = [
    # empty headers, acknowledgements, radio calls, fillers
    (1, "Memo. Re: today's job. Move all three blocks to the opposite side; red goes before blue."),
    (2, "Copy that. Put the three blocks on regions H, I and J, one block per region. Over and out."),
    # "no problem" is an acknowledgement, a support agent's reply word (`courtesy.txt`'s `reply`, h107);
    # refused here as a negation before
    (6, "Understood, no problem. Place the three objects on regions G, H and I separately, red before blue."),
    (6, "Okay robot, um, place the three objects on regions G, H and I separately, red before blue."),
    (8, "Update: first put the yellow block on region I, then on region G. Red and blue go to any empty "
     "region at any time. Understood?"),
    # reported speech, present and past
    (3, "Alex says to move the three pillars to regions E, F and G beside arms a and b, and says nothing may "
     "be placed on any other region."),
    (7, "The planner told the arms to place the three objects on region I one after another, red before "
     "blue, and said no object could go on regions F, G or H during this period."),
    (5, "She asked us to swap the red and blue blocks, red placed first, and to move the yellow block to the "
     "opposite side at any time."),
    # first-person narration
    (4, "Roger. I'll move the three blocks to the opposite regions, and I won't touch the blue block until "
     "I've touched the red block. After all of these, I'll put the yellow block back on region G."),
    (2, "I'm putting the three blocks on regions H, I and J, one block per region."),
    # the base reader took this "I" for region I and gave another spec (exit 0)
    (8, "I'll first put the yellow block on region I, then on region G, and I'll move the red and blue "
     "blocks to any empty region at any time."),
    # the source said first, a speaker's writing
    (1, "According to the supervisor, all three blocks go to the opposite side, and red goes before blue."),
    (3, "Word from the lead is to move the three pillars to regions E, F and G beside arms a and b, and to "
     "put nothing on any other region."),
    (1, "Boss is asking us to move all three blocks to the opposite side, and she says red goes before "
     "blue."),
    (8, "Kim's message said: first put the yellow block on region I, then on region G, and move the red and "
     "blue blocks to any empty region at any time."),
]

REFUSED = [
    # a frame fragment that names something stays, to be read or refused
    (3, "Subject: pillar move. Move the three pillars to regions E, F and G beside arms a and b, and place "
     "nothing on any other region."),
    (1, "Optional: move all three blocks to the opposite side, red before blue."),
    (1, "Done: move all three blocks to the opposite side, red before blue."),
    (2, "Tip: use arm c. Put the three blocks on regions H, I and J, one block per region."),
    # a question reported is no command; a block does not speak
    (2, "She asked whether we could put the three blocks on regions H, I and J, one block per region."),
    (1, "The red block said to move all three blocks to the opposite side, red before blue."),
    (2, "Boss is asking whether to put the three blocks on regions H, I and J, one block per region."),
    (2, "Nobody said to put the three blocks on regions H, I and J, one block per region."),
    # what is done is no command; a time to do it at is not a frame
    (2, "I have put the three blocks on regions H, I and J, one block per region."),
    (1, "Move all three blocks to the opposite side, red before blue. Tomorrow."),
    (2, "Put the red block on H, the blue block on I, and so on."),
]

OTHER = [
    # the reported order or guard the other way round
    (1, "He said to move all three blocks to the opposite side and told us the blue block had to be placed "
     "before the red block."),
    (4, "They said the three blocks had to go to the opposite regions and that nobody was to touch the red "
     "block until the blue one had been touched. After all of these, put the yellow block back on region G."),
    (6, "I'll place the three objects on regions G, H and I separately, and I'll place blue before red."),
    # "I" after a list of region letters is region I, never the pronoun
    (2, "Put the three blocks on regions G, H and I, one block per region."),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_ninth_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_ninth_round_frames_that_name_something_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_ninth_round_reports_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


def test_no_frame_word_is_a_content_word():
    content = set().union(*vocabulary().values())
    for category, words in frame_words().items():
        if category in ("address", "phrase", "alone"):  # the team; phrases, whole sentences: tested below
            continue
        for word in words:  # ("steps" names a step, but before a colon only announces them)
            assert word not in content and (category == "label" or not MEANING.search(word)), (category, word)


def test_a_fragment_is_empty_only_without_content_words():
    assert empty("Roger") and empty("Base to all arms, come in") and empty("Re: today's job")
    assert not empty("Hey arm a") and not empty("Re: regions H and I") and not empty("Trial 4")
    assert not empty("Re: this afternoon")  # a time to do the job at
    assert empty("Control to arms") and empty("Memo to the team") and empty("Attention all arms")
    assert not empty("by the arms") and not empty("to the arms")  # the arms as a place
    assert not empty("Noted, not now") and not empty("Stand by")  # a negation; words the frame does not know
    assert plain(["Roger", "Will do"]) == []
    assert plain(["Regions G, H and I will be empty"]) == ["Regions G, H and I will be empty"]
