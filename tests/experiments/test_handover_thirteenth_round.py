"""Issue 24, h107 (session 19): a support agent's voice, a coach's verbless orders and legal periods. A
support agent's reply words ("Thanks for reaching out!", "Happy to help!", "No problem!", "Of course!",
"To complete your request, ...", "Hope this helps!": `courtesy.txt`'s `reply`) are frame words of the
message, dropped only where their fragment names nothing else; "during such / said period" is "during
this period"; a block named as a field's label before its touch guard ("Blue: hands off till red's
touched"), "everything to ...", "none on F, G or H", "No other region, ever.", "Last: ...", a next place
alone ("Yellow to I. Then to G.") and the one-block rule as "at most one object in any region" or "one
block maximum per region" are read, and so are a support agent's wrap-ups ("As requested, ...", "Just to
confirm, you'd like the arms to ...", "The Robotics Team") and legal "upon", "thereafter", "each such
region". `dev83` to `dev87` and the held-out `validation20` are read right or refused, never misread (the
`sweep` run)."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_written_spec, round_tests

from nl2hltl2plan.language.handover_discourse import empty

READ = {
    1: [
        "Thank you for your patience! The red block goes before the blue block; move all three blocks to the "
        "opposite side.",
        "Hi there, thanks for contacting support! I'd be happy to assist. The arms will move the three "
        "blocks to the opposite side, placing the red block before the blue block. Anything else?",
        "Great news, this is doable! Move the three blocks to the opposite side, one block maximum per "
        "region, red before blue.",
    ],
    2: [
        "Glad to assist! Put the three blocks on regions H, I and J, one block per region. Let us know if "
        "you need anything else!",
        "Just to confirm, you'd like the arms to put the three blocks upon regions H, I and J, with not more "
        "than one block in each such region. Best regards, The Robotics Team",
        "Everything to H, I and J, one per region.",
    ],
    3: [
        "Of course. To process your request, move the three pillars to regions E, F and G beside arms a and "
        "b, and put nothing on any other region. I hope this helps!",
        "Pillars: E, F, G (arm a and arm b side). No other region, ever.",
    ],
    4: [
        "Everything onto the opposite regions. Blue: don't touch till red's been picked up. Last, yellow "
        "back to G.",
        "Here's how the arms will handle it: they'll move the three blocks to the opposite regions, they "
        "won't touch the blue block until the red block has been touched, and after all of that they'll put "
        "the yellow block back on region G.",
    ],
    5: ["Red, blue: swap spots, red first! Yellow: opposite side, any time! Move it!",
        "I understand. Swap the red and blue blocks, red first, and move the yellow block to the opposite "
        "side at any time. Have a lovely evening!"],
    6: ["Sure, I can help with that. Rest assured, the three objects go to G, H and I, at most one object in "
        "any region, red before blue. Kind regards, Support Team"],
    7: [
        "Three objects to I, one after another. Red before blue. No F, G or H meanwhile.",
        "The three objects go one after another onto region I, red before blue; nothing is to be placed on "
        "regions F, G or H during said period.",
        "Place the three objects one after another on region I, red before blue, and none on regions F, G "
        "or H.",
    ],
    8: [
        "The Arms shall place the yellow block upon region I and thereafter upon region G, and shall place "
        "the red and blue blocks upon any empty region at any time.",
        "Yellow to I. Then to G. Red and blue: any empty region, any time.",
        "Put yellow on I. Then on G. Red and blue to any empty region, one block tops per region, any time.",
    ],
}

REFUSED = [
    # a reply fragment that names a block or a negation says something: refused by name, never dropped
    (1, "Happy to help with the red block! Move the three blocks to the opposite side, red before blue."),
    (1, "Thanks for reaching out about the blue block! Move the three blocks to the opposite side, red "
        "before blue."),
    (1, "No problem with the blue block. Move the three blocks to the opposite side, red before blue."),
    (2, "Of course not! Put the three blocks on regions H, I and J, one block per region."),
    # a guard with no "until": what may the arms do with blue, ever?
    (4, "Everything to the opposite regions. Blue: hands off. Last: yellow back to G."),
    (2, "Just to confirm, you wouldn't like the arms to put the three blocks on regions H, I and J, one "
        "block per region."),
    (1, "Move the three blocks to the opposite side, red before blue. Best regards, The Red Team"),
    (1, "Move the three blocks to the opposite side, red before blue. Anything else on region G."),
    (1, "Thanks for contacting support about the yellow block! Move the three blocks to the opposite side, "
        "red before blue."),
    # a next place alone after two blocks: whose step is it?
    (8, "Red and yellow to I. Then to G. Blue to any empty region, any time."),
    (1, "Move the three blocks to the opposite side, at most one object in region G, red before blue."),
]

NEAR_MISSES = [
    # the order, a guard's block, a goal's block or a forbidden region changed under the new forms
    (1, "Happy to help! Move the three blocks to the opposite side, the blue block before the red block."),
    (4, "Everything to the opposite regions. Blue: hands off till yellow's touched. Last: yellow back to G."),
    (4, "Everything to the opposite regions. Red: hands off till blue's touched. Last: yellow back to G."),
    (4, "Everything to the opposite regions. Blue: hands off till red's touched. Last: red back to G."),
    (7, "Place the three objects one after another on region I, red before blue, and none on F or G during "
        "such period."),
    (3, "No problem! Move the three pillars to regions E, F and G beside arm a and arm b."),
    (7, "Three objects to I, one after another. Red before blue. No F or G meanwhile."),
    (8, "Put yellow on I. Then on H. Red and blue to any empty region, any time."),
    (2, "Put the three blocks on regions H, I and J, two blocks maximum per region."),
    (1, "We're on it! Per your request, move the three blocks to the opposite side, blue before red."),
    (2, "Just to confirm, you'd like the arms to put the three blocks on regions H and I, one block per "
        "region."),
    (8, "The Arms shall place the yellow block upon region I and thereafter upon region H, and shall place "
        "the red and blue blocks upon any empty region at any time."),
    (5, "Red, yellow: swap spots, red first! Blue: opposite side, any time!"),
    (4, "Blocks to the opposite regions. Blue: no touching till yellow's touched. Then yellow back on G."),
    (6, "Here's how the arms will handle it: they'll place the three objects on regions G, H and I, one "
        "each, blue before red."),
]

# questions and answers labelled "Q:" / "A:" (the shared `headings.answered`, wired in after h108 merged it)
QUESTIONS_READ = [
    (2, "Q: Where do the three blocks go? A: Regions H, I and J, one per region."),
    (1, "Q: Where do the blocks go? A: The opposite side. Q: Order? A: Red before blue."),
    (8, "Q: Where does the yellow block go? A: Region I, then region G. Q: And the red and blue blocks? "
        "A: Any empty region, at any time."),
]
QUESTIONS_NOT_WRITTEN = [
    (1, "Q: Where do the blocks go? A: The opposite side. Q: Order? A: Blue before red."),
    (8, "Q: Where does the yellow block go? A: Region I, then region H. Q: And the red and blue blocks? "
        "A: Any empty region, at any time."),
    # a question the shared frames do not know: refused by name
    (5, "Q: What should the arms do? A: Swap the red and blue blocks, red first. Q: And the yellow block? A: "
        "The opposite side, at any time."),
]


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), QUESTIONS_READ)
def test_labelled_questions_and_answers_give_the_written_spec(task: int, text: str) -> None:
    assert_written_spec(task, text)


@pytest.mark.data
@pytest.mark.parametrize(("task", "text"), QUESTIONS_NOT_WRITTEN)
def test_other_answers_and_unknown_questions_do_not_give_the_written_spec(task: int, text: str) -> None:
    assert_not_the_written_spec(task, text)


def test_a_reply_fragment_is_empty_only_when_it_names_nothing() -> None:
    assert empty("Thanks for reaching out") and empty("Absolutely, happy to help") and empty("No problem")
    assert empty("Let me know if there's anything else I can help with")
    assert not empty("No problem with the blue block") and not empty("Of course not")
    assert not empty("Happy to help with region G")


(
    test_new_forms_give_the_written_spec,
    test_replies_that_name_something_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h107_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev83", "dev84", "dev85", "dev86", "dev87", "validation20"))
