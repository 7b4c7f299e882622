"""Issue 24, h117 (session 20): a formal requirement in the passive with possessive places ("the three
blocks shall be moved to their opposite regions", "from its own place to its opposite region", "shall
be returned to region G") and a result clause that says the one-block rule again ("..., so there's one
block on each", "so that each of those regions ends up holding one object"). A possessive that agrees
with no block of its clause, "their own places" as a goal and a result clause that adds a goal are
refused by name. `dev89`, `dev90` and the held-out `validation22`, `validation23` are read right or
refused, never misread (the `sweep` run)."""

from __future__ import annotations

from handover_specs import round_tests

from nl2hltl2plan.language.handover_phrases import normalise

READ = {
    1: ["Requirement: each of the three blocks shall be moved from its own place to its opposite region. The "
        "red block shall be placed before the blue block."],
    2: ["Put the three blocks on H, I and J, so there's one block on each."],
    3: ["Requirement: the three pillars shall be moved away from their own places to regions E, F and G; no "
        "object shall be placed on any other region."],
    4: ["Requirement: the three blocks shall be moved to their opposite regions; the blue block shall not be "
        "touched before the red block is touched. Afterwards the yellow block shall be returned to region "
        "G."],
    5: ["Requirement: the positions of the red and blue blocks shall be exchanged, the red block being "
        "placed first; the yellow block shall be moved to its opposite region at any time."],
    6: ["Red before blue. Place the three objects on G, H and I, so that each of those regions ends up "
        "holding one object.",
        "Put the three objects on G, H and I, so that every one of those regions gets one. Red goes before "
        "blue."],
}

REFUSED = [
    # a possessive that agrees with no block of its clause: whose opposite region?
    (5, "The red and blue blocks shall be exchanged, red first; the yellow block shall be moved to their "
        "opposite region at any time."),
    (1, "Requirement: the three blocks shall be moved to its opposite region; the red block shall be placed "
        "before the blue block."),
    # where the blocks already are, as a goal
    (1, "Requirement: the three blocks shall be moved to their own places."),
    (1, "Requirement: each block shall be returned to its own place after the red block is placed."),
    # a result clause that adds a goal
    (2, "Put the three blocks on H, I and J, so there's one block on G."),
    (2, "Put the three blocks on H, I and J, so that region F ends up empty."),
]

NEAR_MISSES = [
    # the order, the guard or the return region changed under the new forms
    (4, "Requirement: the three blocks shall be moved to their opposite regions; the red block shall not be "
        "touched before the blue block is touched. Afterwards the yellow block shall be returned to region "
        "G."),
    (4, "Requirement: the three blocks shall be moved to their opposite regions; the blue block shall not be "
        "touched before the red block is touched. Afterwards the yellow block shall be returned to region "
        "H."),
    (1, "Requirement: the three blocks shall be moved to their opposite regions; the blue block shall be "
        "placed before the red block."),
    (2, "Put the three blocks on H, I and G, so there's one block on each."),
]


(
    test_new_forms_give_the_written_spec,
    test_unclear_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h117_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev89", "validation22", "dev90", "validation23"))


def test_a_possessive_before_opposite_is_the_only_where_it_agrees() -> None:
    assert "to the opposite regions" in normalise("The three blocks shall go to their opposite regions.")
    assert "to the opposite region" in normalise("The yellow block shall go to its opposite region.")
    each_of = normalise("Move each of the blocks to their opposite region.")
    assert "each of the blocks to the opposite" in each_of
    assert "their opposite" in normalise("Move the yellow block to their opposite region.")
    assert "its opposite" in normalise("Move the three blocks to its opposite region.")
    assert "each block to the opposite" in normalise("Move each block to its opposite region.")


def test_a_result_clause_is_the_one_block_rule_only_when_it_says_one_on_each() -> None:
    on_each = normalise("Put the blocks on H, I and J, so there's one block on each.")
    assert "with one block on each" in on_each
    assert "there" in normalise("Put the blocks on H, I and J, so there's one block on G.")
    assert "each region holds one" in normalise("Put them on G, H and I so each region ends up holding one.")
