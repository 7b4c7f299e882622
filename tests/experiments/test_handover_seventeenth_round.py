"""Issue 24, h124 (session 21): two readings that gave another spec. "Eventually" opening a later sentence
("... Eventually the robots will put the yellow block back on G.") orders its step after what was said
before it, as "later on" does; between a clause's subject and verb ("the yellow block eventually goes to
the opposite side") it is a hedge that orders nothing, and where that leaves a block's two goals unordered
the reading is refused. Goals of one block per sentence that together send every block to the opposite
side ("Move the red block to the opposite side. Then move the blue block ... The yellow block goes ...
too.") also ask for all of them there at once, as one clause of the three blocks does. `dev93` and the
held-out `validation26` and `validation27` are read right or refused, never misread (the `sweep` run)."""

from __future__ import annotations

from handover_specs import round_tests

from nl2hltl2plan.language.handover_layout import later_read

READ = {
    1: ["Move the red block to the opposite side. Then move the blue block to the opposite side. The yellow "
        "block goes to the opposite side too.",
        # h121's dev sentence, left out of the committed batches as another spec (session 21)
        "The arms will move the red block to the opposite side. Later on the arms will move the blue block "
        "to the opposite side. At any time, move the yellow block to the opposite side."],
    2: ["Move the red block to the opposite side. Move the blue block to the opposite side. Move the yellow "
        "block to the opposite side."],
    4: ["Move the three blocks to their opposite regions. The arms must not touch the blue block until the "
        "red block has been touched. Eventually the robots will put the yellow block back on G."],
    5: ["Swap the red and blue blocks, red first. The yellow block eventually goes to the opposite side."],
    8: ["First put the yellow block on region I. Eventually put it on region G. Move the red and blue blocks "
        "to any empty region at any time."],
}

REFUSED = [
    # a hedge inside the clause leaves the yellow block's two goals unordered: which comes first?
    (4, "Move the three blocks to their opposite regions. The arms must not touch the blue block until the "
        "red block has been touched. The yellow block eventually goes back on G."),
    (4, "Move the three blocks to their opposite regions. The arms must not touch the blue block until the "
        "red block has been touched. The robots will eventually put the yellow block back on G."),
    (8, "Put the yellow block on region I. The yellow block eventually goes to region G. Move the red and "
        "blue blocks to any empty region at any time."),
    # "back" at any time beside the block's other goal: its start already holds it there (the lead; this
    # read task 4 without the return's order, exit 0)
    (4, "Move the three blocks to their opposite regions, without touching the blue block until the red "
        "block has been touched. At some point the robots will put the yellow block back on G."),
]

NEAR_MISSES = [
    # a block's place changed, a block left out, or "eventually" ordering what task 5 leaves free
    (1, "Move the red block to the opposite side. Then move the blue block to region G. The yellow block "
        "goes to the opposite side too."),
    (1, "Move the red block to the opposite side. Then move the blue block to the opposite side."),
    # a third "then" orders yellow after blue, which task 1 leaves free (held out in validation27, where it
    # was meant as a rephrasing: it says more than task 1)
    (1, "The red block goes to the opposite side. Then the blue block goes to the opposite side. Then the "
        "yellow block goes to the opposite side."),
    (5, "Swap the red and blue blocks, red first. Eventually take the yellow block to the opposite side."),
    (4, "Move the three blocks to their opposite regions. The arms must not touch the blue block until the "
        "red block has been touched. Eventually the robots will put the red block back on G."),
]


(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h124_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev93", "validation26", "validation27"))


def test_eventually_orders_only_when_it_opens_a_later_sentence() -> None:
    said = later_read(["Move the blocks", "Eventually the arms will put the yellow block on G"])
    assert said[1] == "after that, the arms will put the yellow block on G"
    assert later_read(["Eventually move the blocks"]) == ["Eventually move the blocks"]
    hedged = later_read(["Swap red and blue", "The yellow block eventually goes to H"])
    assert hedged[1] == "The yellow block goes to H"
    # after "and" the clause is not one: left to the reader (unread there)
    kept = "Put red on G and it eventually goes to H"
    assert later_read([kept]) == [kept]
