"""Issue 24, h121 (session 21): a heading that says only the verb over bullets of blocks and places ("Please
move the following:" / "- the red block to the opposite side" / ...), a count per place under a heading
of places after a step without one ("Move the three blocks. Into regions H, I and J: exactly one each."),
a result clause about "each of them" right after the regions ("... so that each of them ends up holding
one"), and a later sentence opened by a bare time adverb ("Later on the arms will put ..."). Another count,
a clause that adds a goal and a first sentence's "later on" are refused by name. `dev91` and the held-out
`validation24` are read right or refused, never misread (the `sweep` run)."""

from __future__ import annotations

from handover_specs import round_tests

from nl2hltl2plan.language.handover_layout import later_read, places_then_count_read, verb_heading_read

READ = {
    1: ["Please transfer the following:\n- the red block to the opposite side\n- the blue block to the "
        "opposite side\n- the yellow block to the opposite side\nThe red block goes before the blue block."],
    2: ["Place the three blocks. On regions H, I and J: one apiece.",
        "Set the red, blue and yellow blocks down.\nRegions H, I and J: a single block per region.",
        "Put the three blocks into regions H, I and J, so that all of them end up with one."],
    3: ["The arms should carry the following:\n* the three pillars to regions E, F and G\nNothing may be "
        "placed on any other region.",
        "Carry the three pillars.\nOnto regions E, F and G: just one each.\nNo object may go on any other "
        "region."],
    4: ["Move the three blocks to the opposite regions. The arms must not touch the blue block until the "
        "red block has been touched. At a later stage the robots will return the yellow block to region G.",
        # "after that they will ...": the team after a step's phrase with no comma (the lead, session 21)
        "The arms will move the three blocks to their opposite regions without touching the blue block until "
        "the red block has been touched, and after that they will put the yellow block back on region G."],
    6: ["Red before blue. Move the three objects to G, H and I so each of them ends up holding one."],
    8: ["The robots should move:\n- first, the yellow block to region I\n- then, the yellow block to region "
        "G\n- at any time, the red and blue blocks to any empty region",
        "The robots will first put the yellow block on region I. Later on they will put it on region G. The "
        "red and blue blocks go to any empty region at any time.",
        # refused by h114 (session 20) as a "later on" that may mean "then": it does, after a first sentence
        "First put the yellow block on region I. Later on, put it on region G. Move the red and blue blocks "
        "to any empty region at any time.",
        "Yellow to region I, then to region G. Any time: move the red and blue blocks. Into any unoccupied "
        "regions: one each.",
        # "do the following" after the team and a modal is a frame, as after "please"
        "The robots must do the following:\n- first, the yellow block to region I\n- then, the yellow block "
        "to region G\n- at any time, the red and blue blocks to any empty region"],
}

REFUSED = [
    # a count per place that is not one
    (2, "Move the three blocks. Into regions H, I and J: two each."),
    (8, "Put the yellow block on region I, then on region G. At any time, move the red and blue blocks. Into "
        "the free regions: two each."),
    # a result clause that adds a goal, or a count other than one
    (2, "Move the three blocks to regions H, I and J so that each of them ends up on region G."),
    (2, "Move the three blocks to regions H, I and J so that each of them ends up holding two."),
    # "later on" opening the first sentence follows nothing: the second sentence's "first" cannot hold
    (8, "Later on put the yellow block on region I. First put it on region G. Move the red and blue blocks "
        "to any empty region at any time."),
]

NEAR_MISSES = [
    # a bullet's place, the heading's places, a count's places or the later step changed under the new forms
    (1, "Please move the following:\n- the red block to the opposite side\n- the blue block to region G\n"
        "- the yellow block to the opposite side\nRed before blue."),
    (2, "Move the three blocks. Into regions H, I and G: exactly one each."),
    (2, "Move the three blocks.\nRegions H, I and G: one apiece."),
    (2, "Move the three blocks to regions G, I and J so that each of them ends up holding one."),
    # "later on" orders: the yellow block after the exchange is not task 5's "at any time"
    (5, "The arms will swap the red and blue blocks, red first. Later on the arms will take the yellow block "
        "to the opposite side."),
    (8, "The robots will first put the yellow block on region G. Later on they will put it on region I. The "
        "red and blue blocks go to any empty region at any time."),
    (4, "The arms will move the three blocks to their opposite regions without touching the blue block "
        "until the red block has been touched, and after that they will put the red block back on region G."),
]


(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h121_batches_are_read_right_or_refused_never_misread,
) = round_tests(
    READ, REFUSED, NEAR_MISSES, ("dev91", "validation24", "dev92", "validation25")
)


def test_a_verb_heading_takes_its_bullets_as_one_clause_or_as_steps() -> None:
    same_place = verb_heading_read("Move the following:\n- the red block to G\n- the blue block to G")
    assert same_place == "Move the red block and the blue block to G"
    other_places = verb_heading_read("Move the following:\n- the red block to G\n- the blue block to H")
    assert other_places == "Move the red block to G and the blue block to H"
    steps = verb_heading_read("Arms should move:\n- first, the red block to G\n- then, the red block to H")
    said = "- first, Arms should move the red block to G\n- then, Arms should move the red block to H"
    assert steps == said
    # one bullet, a bullet without a place, or steps mixed with plain goals: left to the colon's joining
    for text in ("Move the following:\n- the red block to G",
                 "Move the following:\n- the red block to G\n- the blue block",
                 "Move:\n- first, the red block to G\n- the blue block to H"):
        assert verb_heading_read(text) == text


def test_a_count_per_place_joins_only_a_step_without_a_place() -> None:
    joined = places_then_count_read("Move the three blocks. Into regions H, I and J: exactly one each.")
    assert joined == "Move the three blocks Into regions H, I and J, one per region."
    kept = "Move the three blocks to region G. Into regions H, I and J: one each."
    assert places_then_count_read(kept) == kept
    free = places_then_count_read("Move the red and blue blocks down.\nThe free regions: one each.")
    assert free == "Move the red and blue blocks to The free regions, one per region."


def test_a_bare_later_orders_only_after_a_first_sentence_and_not_an_added_step() -> None:
    said = later_read(["Move the blocks", "Later on the arms will put the yellow block on G"])
    assert said[1] == "after that, the arms will put the yellow block on G"
    assert later_read(["Later on move the blocks"]) == ["Later on move the blocks"]
    added = "Later on, they will also take the yellow block"
    assert later_read(["Swap red and blue", added])[1] == added
    said_after = "Later on, once that is done, put yellow on G"
    assert later_read(["Move the blocks", said_after])[1] == said_after
