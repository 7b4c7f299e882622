"""Issue 24, h103 (session 18): voices no earlier batch used. A left-dislocated object taken up by "it" or
"them" of its number ("The yellow block, put it on region I"; "the other regions, place nothing on them"),
a pair before its exchange ("Red and blue blocks, swap places"), legal "said regions", a block's heading
before its touch state ("Blue: untouched until ..."), a bare region letter heading one block ("G: yellow,
last"), a pirate's "afore" / "ye" / "haul" / "stow", and the calls of a coach, a pirate or a kitchen
("Hustle!", "Avast!", "Heard, chef?") as frame words. A place after a comma without a verb ("Yellow,
opposite side") stays refused (where it goes, or where it is?). `dev82` and the held-out `validation19`
are read right or refused, never misread (the `sweep` run)."""

from __future__ import annotations

from handover_specs import round_tests

READ = {
    1: [
        "The three blocks, move them to the opposite side; the red one, place it before the blue "
        "one.",
        "Avast, me hearties! Haul the three blocks to the opposite side, the red block afore the blue block.",
    ],
    3: [
        "The Arms shall transfer the three pillars to regions E, F and G such that no object is placed on "
        "any region other than said regions.",
        "The three pillars, put them on regions E, F and G beside arms a and b; the other regions, place "
        "nothing on them.",
    ],
    4: [
        "Opposite regions: all three blocks. Blue: untouched until red is touched. G: yellow, last.",
    ],
    5: [
        "Red and blue blocks, swap places, red goes first. Yellow to the opposite side whenever. Heard, "
        "chef!",
        "Red and blue, just swap them, red placed first; the yellow one, drop it on the opposite side any "
        "time.",
    ],
    8: [
        "The yellow block, put it on region I, then on region G. Red and blue, drop them on any empty region "
        "at any time. Hustle!",
        "Put the yellow block on region I, then on region G, and stow the red and blue blocks on any empty "
        "region whenever ye please. Good luck!",
    ],
}

REFUSED = [
    # (a place after a comma without a verb, "Yellow, opposite side", is read since h114 as where it goes:
    # test_handover_fourteenth_round.py)
    # a pronoun of the other number takes up no object
    (5, "Red and blue, just swap it, red placed first; put the yellow block on the opposite side any time"),
    (3, "The three pillars, put them on regions E, F and G; the other regions, place nothing on it."),
    # a bare "I" is the pronoun, never a region letter
    (7, "I: all three objects, one after another, red before blue. F, G, H: nothing during this period."),
    # a threat after "or": a choice the reader does not model
    (
        3,
        "Move the three pillars to regions E, F and G, and no object on any other region, or ye walk the "
        "plank!",
    ),
    # the dislocated regions given a goal of their own: two places for one group
    (3, "The three pillars, put them on regions E, F and G; the other regions, put them on G."),
]

NEAR_MISSES = [
    # the dislocated order, the pirate's order and the heading's touch guard reversed
    (1, "The three blocks, move them to the opposite side; the blue one, place it before the red one"),
    (6, "Place the three objects separately on regions G, H and I, the blue block afore the red block."),
    (4, "Opposite regions: all three blocks. Red: untouched until blue is touched. G: yellow, last."),
    (5, "Red and blue, swap them. Blue first. Yellow to the opposite side, whenever."),
]


(
    test_new_voices_give_the_written_spec,
    test_unreadable_forms_are_refused_by_name,
    test_near_misses_are_not_the_written_spec,
    test_h103_batches_are_read_right_or_refused_never_misread,
) = round_tests(READ, REFUSED, NEAR_MISSES, ("dev82", "validation19"))
