"""Issue 24, h78: the form-independent reading of a handover sentence (`language/handover_cues.py`), the
fallback where the form reader refuses (h82: `dev43`, `dev44`, and the held-out `validation13` and
`validation14`, read right or refused; h86: `dev50`-`dev54` and the held-out `validation15`, and the
general cues of that round, each with a near miss). The development batch `dev38` (fronted objects and
passives, checklists, questions) must give the written specs, `dev39`-`dev42` the written spec or a
refusal; near misses that change one meaning (an order or a guard reversed, a region or a timing left out,
a scene said without a verb, a report of what was done, "and so on", a pronoun of the other number) must
be refused or give another spec.
"""

from __future__ import annotations

import pytest
from handover_session10 import STYLES
from handover_specs import (
    TASKS,
    assert_not_the_written_spec,
    assert_refused_by_name,
    assert_written_spec,
    assert_written_spec_or_refused,
)
from handover_specs import spec_of as _spec

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_cues import restate
from nl2hltl2plan.language.handover_phrases import mark
from nl2hltl2plan.language.handover_scene import Scene
from nl2hltl2plan.suites.handover.handover_bench import instance

# a whole committed batch read sentence by sentence: `python -m pytest -m sweep` (the default run leaves
# them to `scripts/bench_handover_styles.py --batch all`, which measures the same sentences)
SWEEP = pytest.mark.sweep

NEAR_MISSES = [
    # a guard or an order reversed, a touch said against a move
    (
        4,
        "All three blocks are moved to the opposite regions. The red block is touched by no arm before "
        "the blue block has been touched. After all of that, the yellow block goes back onto region G.",
    ),
    (
        4,
        "All three blocks are moved to the opposite regions. The blue block is touched by no arm before "
        "the red block has been moved. After all of that, the yellow block goes back onto region G.",
    ),
    (
        7,
        "One after another the three blocks are placed on region I, blue before red, and nothing is "
        "placed on regions F, G and H while this goes on.",
    ),
    (
        5,
        "Things to do: red and blue swap positions (blue placed first); yellow to the opposite "
        "side at any time.",
    ),
    (
        6,
        "Blue first, red after: that is the placing order. The three objects go to regions G, H "
        "and I, one apiece.",
    ),
    # a region left out or changed, a prohibition on other regions
    (
        7,
        "One after another the three blocks are placed on region I, red before blue, and nothing is "
        "placed on regions F and G while this goes on.",
    ),
    (
        3,
        "The three pillars are carried over to regions E, F and G by the side of arms a and b, and no "
        "object is ever set down on regions H and I.",
    ),
    (
        8,
        "The yellow block goes first to region I and after that to region H. The red and blue blocks go to "
        "any empty region at any time.",
    ),
    # a scene said without a verb, a report of what was done, "and so on", a condition, a relative clause
    (2, "I have put the three blocks in regions H, I and J, one block per region."),
    (6, "Red first, blue after: that is the placing order. The three objects go to regions G, H and so on."),
    (
        7,
        "Can the three blocks be placed one after another on region I, red before blue, if nothing is "
        "placed on regions F, G or H meanwhile?",
    ),
    (2, "So the three blocks we need on H, I and J, one block per region."),
    # fronted places and guards: a region left out, the guard reversed, a place with no verb of motion
    (3, "On regions H and I, nothing may be placed. Move the three pillars to regions E, F and G."),
    (
        4,
        "Not until the blue block has been touched may the red block be touched. Move the three blocks "
        "to the opposite regions, and after all of that, put the yellow block back on region G.",
    ),
    (1, "On the opposite side, the three blocks. Red before blue."),
    (5, "Swap the red and yellow blocks, red first. The blue block goes to the opposite side at any time."),
    # steps said with "begin by / with" and "finish by", legal register: the order reversed
    (
        8,
        "Begin by putting the yellow block on region G and finish by putting it on region I; the red and "
        "blue blocks go to any empty region at any time.",
    ),
    (6, "Begin with the blue block, then the red block, placing the three objects on regions G, H and I."),
    (
        4,
        "Start by moving all three blocks to the opposite regions, touching the blue block before the red "
        "block, and finish by putting the yellow block back on region G.",
    ),
    (
        1,
        "The Operator shall cause the three blocks to be transferred to the opposite side, the blue block "
        "being placed prior to the red block.",
    ),
    # "with" phrases without a verb, the second-person future: the order, the guard or a region changed
    (1, "Over to the opposite side with all three blocks, the blue one going down before the red one."),
    (
        4,
        "You will move the three blocks to the opposite regions, you will not touch the red block until you "
        "have touched the blue block, and after all of that you will put the yellow block back on region G.",
    ),
    (
        7,
        "Onto region I with the three blocks, one after another, red before blue, and regions F and H kept "
        "empty meanwhile.",
    ),
    # a completion clause "as soon as all of that is done" after a guard reversed
    (
        4,
        "Get the three blocks over to the opposite regions, without touching the red block until the blue "
        "block has been touched; as soon as all of that is done, put the yellow block back on region G.",
    ),
    # a list of blocks before a verb with no object: subject, topic or the arms addressed?
    (1, "The three blocks, move to the opposite side; the red block is put down ahead of the blue block."),
    # "first" with no clause before it nor a block after
    (6, "Red first. The three objects go to regions G, H and I, one apiece."),
    # necessity, prohibition and framing words (h82): the order, the guard or a region changed
    (1, "The idea is to move the three blocks to the opposite side, and the blue block is to be placed "
     "before the red block."),
    (4, "It is necessary to move the three blocks to the opposite regions. It is forbidden to touch the red "
     "block until the blue block has been touched. After all of that, it is necessary to put the yellow "
     "block back on region G."),
    (3, "What I need is for the three pillars to be moved to regions E, F and G; it is forbidden to place "
     "any object on regions H and I."),
    (7, "Place the three blocks on region I one after another, red before blue, and it is forbidden to place "
     "any object on regions F and G during this period."),
    (7, "What matters is that the red block is placed before the blue block. Stack the three blocks on "
     "region I one after another, but nothing may be placed on regions F and G meanwhile."),
]


@pytest.mark.parametrize(("batch", "style"), [("dev38", s) for s in sorted(STYLES["dev38"])])
def test_development_batches_give_the_written_specs(batch, style):
    for task, text in STYLES[batch][style].items():
        assert_written_spec(int(task), text)


@SWEEP
@pytest.mark.parametrize(
    ("batch", "style"),
    [
        (b, s)
        for b in (f"dev{k}" for k in (39, 40, 41, 42, 43, 44, 50, 51, 52, 53, 54, *range(60, 74)))
        for s in sorted(STYLES[b])
    ],
)
def test_later_development_batches_are_read_right_or_refused(batch, style):
    for task, text in STYLES[batch][style].items():
        assert_written_spec_or_refused(int(task), text)


@SWEEP
@pytest.mark.parametrize(
    ("batch", "style"),
    [(b, s) for b in (f"validation{k}" for k in (13, 14, 15, 16, 17)) for s in sorted(STYLES[b])],
)
def test_held_out_batches_are_read_right_or_refused(batch, style):
    """h78's, h82's, h86's, h93's and h95's held-out batches, each measured at first contact and at the end
    of its round."""
    for task, text in STYLES[batch][style].items():
        assert_written_spec_or_refused(int(task), text)


@pytest.mark.parametrize(("task_id", "text"), NEAR_MISSES)
def test_cue_near_misses_are_refused_or_give_another_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


def test_a_checklist_of_verbless_items_is_the_request():
    # under "Checklist:" (a label since h194) the items are things to do, as a notes-app list's are in the
    # household worlds (h199): it was a near miss, "a scene said without a verb", before the label was read
    assert_written_spec(1, "Checklist:\n* all three blocks, opposite side\n* red placed before blue")


def _restated(task_id: int, sentence: str) -> str | None:
    scene = Scene.of(instance(TASKS[task_id], 0, 0).as_world())
    return restate(mark(sentence, scene), scene)


def test_a_fronted_place_and_a_passive_guard_are_said_in_plain_words():
    assert (
        _restated(1, "To the opposite side go the three blocks")
        == "move the three blocks to the opposite side"
    )
    assert _restated(4, "The blue block is touched by no arm before the red block has been touched") == (
        "no arm may touch the blue block until the red block has been touched"
    )
    assert _restated(7, "Regions F, G and H: nothing placed meanwhile") == (
        "no object may be placed on regions F, G and H"  # a sentence of its own: it guards every goal
    )
    assert _restated(4, "Not until the red block has been touched may the blue block be touched") == (
        "no arm may touch the blue block until the red block has been touched"
    )


def test_a_cue_is_a_whole_word():
    # "never" is a negation, not "n" and "ever"; "however" and "still" hold no cue ("ever", "till")
    assert (
        _restated(7, "Never put anything on regions F, G and H")
        == "no object may be placed on regions F, G and H"
    )
    assert _restated(7, "However, put nothing on regions F, G and H") is None
    assert _restated(7, "Still put nothing on regions F, G and H") is None


def test_words_that_carry_a_meaning_the_cues_do_not_model_are_refused():
    assert _restated(1, "3 blocks, opposite side") is None  # where they go, or where they are?
    assert _restated(1, "Move the three blocks to the opposite side unless red is there") is None
    assert _restated(2, "Put the red block on H, the blue block on I, and so on") is None


def test_necessity_and_prohibition_words_are_modals_and_negations():
    assert _restated(1, "It is necessary that the three blocks go to the opposite side") == (
        "move the three blocks to the opposite side"
    )
    assert _restated(7, "It is forbidden to place any object on regions F, G and H") == (
        "no object may be placed on regions F, G and H"
    )
    assert _restated(1, "It is not necessary to move the three blocks to the opposite side") is None
    assert _restated(7, "Put any object on regions F, G and H") is None  # "any object" is no goal


def test_but_adds_a_prohibition_only():
    said = _restated(3, "Move the three pillars to regions E, F and G, but no object may go elsewhere")
    assert said == (
        "move the three blocks to regions E, F and G, and no object may be placed on any other region during "
        "this period"
    )
    assert _restated(1, "Move the three blocks to the opposite side, but the red block first") is None


@pytest.mark.parametrize(
    ("task_id", "text"),
    [
        (8, "First put the yellow block on region I, and finally put it on region G. Move the red and blue "
         "blocks to any empty region at any time."),
        (4, "First move the three blocks to the opposite regions, and finally put the yellow block back on "
         "region G. No arm may touch the blue block until the red block has been touched."),
    ],
)
def test_first_and_finally_with_nothing_between_are_two_steps(task_id, text):
    assert_written_spec(task_id, text)  # the nested tree of "first X, then Y" (was a flat tree for task 8)


def test_a_region_kept_clear_of_objects_or_of_one_block():
    start = "The red block should be placed before the blue block. Place the three blocks on region I one "
    empty_of_new = "after another, and keep regions F, G and H empty of new objects while we do that."
    assert_written_spec(7, start + empty_of_new)
    # of one block only: a prohibition on that block (was read as one on every object)
    clear_of_red = "after another, and keep regions F, G and H clear of the red block meanwhile."
    assert_not_the_written_spec(7, start + clear_of_red)


def test_the_other_regions_as_a_heading_wait_for_their_prohibition():
    assert _restated(3, "Other regions: no objects placed") == "no object may be placed on any other region"
    assert _restated(3, "Other regions: the three pillars go there") is None  # no place a block can go to


def test_it_is_forbidden_to_is_a_prohibition_before_it_is_read_as_a_block():
    assert_written_spec(
        7,
        "Place the three blocks on region I one after another, red before blue, and it is forbidden to place "
        "any object on regions F, G and H during this period.",
    )


def test_an_arm_named_with_with_and_an_exchange_said_with_with():
    # "with any arm" names who touches (not a chunk of its own); "swap X with Y" names the exchange's pair
    assert _restated(4, "Not touching the blue block with any arm until the red block has been touched") == (
        "no arm may touch the blue block until the red block has been touched"
    )
    swapped = "swap the positions of the red and blue blocks"
    assert _restated(5, "swap the red block with the blue block") == swapped
    assert _restated(5, "swap red <-> blue") == swapped
    # the guard reversed, or a block of the exchange changed: not the written spec
    assert_not_the_written_spec(
        4,
        "Moving the three blocks to the opposite regions. Not touching the red block with any arm until the "
        "blue block has been touched. Finally, putting the yellow block back on region G.",
    )
    assert_not_the_written_spec(5, "red before blue; swap red <-> yellow; anytime: blue -> opposite side")


def test_the_arms_addressed_as_you_and_steps_said_initially_and_subsequently():
    assert _restated(4, "None of you touches the blue block until one of you has touched the red block") == (
        "no arm may touch the blue block until the red block has been touched"
    )
    assert _restated(8, "Initially put the yellow block on region I, subsequently on region G") == (
        "first move the yellow block to region I, and then move the yellow block to region G"
    )
    assert _restated(8, "The yellow block is initially on region I") is None  # a scene, not a step
    assert_not_the_written_spec(
        4,
        "Arms, take the three blocks to the opposite regions. None of you touches the red block until one of "
        "you has touched the blue block. After all that, put the yellow block back on region G.",
    )
    assert_not_the_written_spec(
        8,
        "Initially put the yellow block on region G, subsequently on region I. Whenever convenient, send the "
        "red and blue blocks to any empty region.",
    )


def test_hedges_and_intensifiers_carry_no_meaning_but_a_hedged_negation_is_refused():
    assert_written_spec(
        1,
        "I think the three blocks should probably go to the opposite side, and ideally the red block gets "
        "placed before the blue block.",
    )
    assert_not_the_written_spec(
        6,
        "Ideally the blue block is placed before the red block. I'd put the three objects on regions G, H "
        "and I, one each.",
    )
    assert_written_spec(
        3,
        "Move the three pillars to regions E, F and G, on the side of arms a and b, and it is very important "
        "that no object is placed on any other region.",
    )
    with pytest.raises(HTTError, match="perhaps"):
        _spec(1, "Move the three blocks to the opposite side, perhaps not the red block first.")


def test_the_courtesy_words_are_one_list_for_the_handover_reader():
    from nl2hltl2plan.language.handover_discourse import frame_words

    # `courtesy.txt`'s words are read as "please" anywhere and are frame words of a message
    assert {"please", "kindly", "pls", "plz", "thx", "thanks", "thank"} <= frame_words()["thanks"]
    assert_written_spec(
        1,
        "Kindly move the three blocks to the opposite side, thx. The red block should be placed before the "
        "blue block pls. Thank you!",
    )


def test_a_pictograph_ends_a_sentence_and_a_hashtag_is_a_label():
    assert_written_spec(
        5,
        "Red block before blue block 🔴🔵 Swap the red and blue blocks 🔄 Yellow block to the opposite "
        "side at any time ⏰ #handover",
    )
    # the order reversed, or a pictograph inside a clause (it ends the clause there): not the written spec
    assert_not_the_written_spec(
        5, "Blue before red 🔵🔴 Swap the red and blue blocks 🔄 Yellow block to the opposite side anytime"
    )
    assert_not_the_written_spec(1, "Move the three blocks 🙂 to the opposite side. Red before blue.")


def test_be_so_good_as_to_is_a_polite_request():
    assert_written_spec(
        1,
        "Would you be so good as to move the three blocks to the opposite side, placing the red block before "
        "the blue block?",
    )
    assert_not_the_written_spec(
        1,
        "Would you be so good as to move the three blocks to the opposite side, placing the blue block "
        "before the red block?",
    )


def test_the_one_block_per_region_rule_said_alone_with_its_verb():
    assert _restated(2, "Keeping to one block per region") == "one block per region"
    assert_written_spec(
        2, "(a) Place the three blocks on regions H, I and J. (b) Place no more than one block on each region"
    )
    # with an order beside it, the rule is not dropped: refused
    assert _restated(6, "Red before blue, one block per region") is None
    assert_not_the_written_spec(2, "Putting the three blocks on H and I. Keeping to one block per region")


def test_hesitations_are_the_shared_list():
    from nl2hltl2plan.language.handover_discourse import frame_words

    # `grammar.everyday.HESITATION` is the one list: the frame words keep none of their own, and a long
    # "ummm" or "errr" is a hesitation as "um" is
    assert not {"um", "uh", "er", "erm", "hmm"} & frame_words()["filler"]
    assert_written_spec(1, "Ummm. Move the three blocks to the opposite side. Errr, red before blue.")


def test_a_when_clause_gives_the_goal_the_rest_constrains_or_the_first_step():
    moved = "the three blocks to the opposite side"
    said = _restated(1, f"When you move {moved}, place the red block before the blue block")
    assert said == f"move {moved}. the red block should be placed before the blue block"
    assert _restated(8, "When you have put the yellow block on region I, put it on region G") == (
        "first move the yellow block to region I, and then move the yellow block to region G"
    )
    # two goals in a present "when" clause and its main clause: when is the second one done? refused
    assert _restated(6, "When you move the red block to region G, move the blue block to region H") is None
    assert_not_the_written_spec(
        8,
        "When you have put the yellow block on region G, put it on region I. Move the red and blue blocks to "
        "any empty region at any time.",
    )


def test_slashes_list_letters_and_separate_clauses_the_form_reader_refuses():
    assert_written_spec(6, "red before blue / three objects to G/H/I, one each")
    assert_written_spec(2, "blocks (x3) to H/I/J, one per region")
    assert_not_the_written_spec(6, "blue before red / three objects to G/H/I, one each")
    assert_not_the_written_spec(2, "blocks (x2) to H/I/J, one per region")


def test_dont_forget_as_a_heading_is_a_note_label_not_a_negation():
    said = "the three blocks go to the opposite side, and the {} block goes before the {} block."
    assert_written_spec(1, "Don't forget: " + said.format("red", "blue"))
    assert_not_the_written_spec(1, "Don't forget: " + said.format("blue", "red"))


def test_a_command_label_asks_for_what_follows():
    said = "Execute: transfer three blocks to opposite side. Constraint: {} block before {} block."
    assert_written_spec(1, said.format("red", "blue"))
    assert_not_the_written_spec(1, said.format("blue", "red"))
    assert_refused_by_name(1, "Do not " + said.format("red", "blue").lower())


def test_a_preamble_that_names_nothing_is_dropped_but_a_condition_is_not():
    rest = "the three blocks need to end up on regions H, I and J, and each region should hold one block."
    preamble = "What we are trying to achieve here is quite simple really: "
    assert_written_spec(2, preamble + rest)
    assert_not_the_written_spec(2, preamble + rest.replace("H, I and J", "H and I"))
    assert_refused_by_name(2, "Unless somebody objects by the time you read this: " + rest)


def test_would_you_mind_is_read_from_its_cues():
    # no rewrite of its own (the modal and "mind" carry no task): the gerund is the placing verb
    assert_written_spec(
        7,
        "The red block should be placed before the blue block. Would you mind placing the three blocks on "
        "region I one after another, and not placing anything on regions F, G and H meanwhile?",
    )
    assert_not_the_written_spec(
        7,
        "The red block should be placed before the blue block. Would you mind placing the three blocks on "
        "region I one after another, and not placing anything on regions F and G meanwhile?",
    )


@pytest.mark.parametrize(
    ("task_id", "text"),
    [
        # forms whose own rewrites are gone (h86): the general reading gives the written spec
        (
            1,
            "I would like you to move the three blocks to the opposite side. I would like the "
            "red block placed before the blue block.",
        ),
        (
            5,
            "The red block should be placed before the blue block. Swap the red and blue "
            "blocks. The yellow block goes to the opposite side, whenever is ok.",
        ),
        (
            1,
            "Here, the three blocks go to the opposite side, and the red block is placed "
            "before the blue block.",
        ),
        (
            2,
            "put the three blocks on regions H, I and J one block per region okay",
        ),
        (
            1,
            "The transfer of the three blocks to the opposite side, with the red block placed "
            "before the blue block.",
        ),
        (
            7,
            "The red block should be placed before the blue block. Place the three blocks on "
            "region I one after another, and put no objects on regions F, G and H meanwhile.",
        ),
        (
            8,
            "Yellow block: region I, then region G. The red and blue blocks go to any empty "
            "region at any time.",
        ),
    ],
)
def test_forms_without_a_rewrite_of_their_own_are_read_in_general(task_id, text):
    assert_written_spec(task_id, text)


def test_forms_without_a_rewrite_of_their_own_near_misses():
    assert_not_the_written_spec(
        7,
        "The red block should be placed before the blue block. Place the three blocks on "
        "region I one after another, and put no objects on regions F and G meanwhile.",
    )
    assert_not_the_written_spec(
        8,
        "Yellow block: region G, then region I. The red and blue blocks go to any empty "
        "region at any time.",
    )
