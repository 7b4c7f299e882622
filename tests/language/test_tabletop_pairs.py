"""The tabletop world's framing-independent fallback (`language/tabletop_pairs.py`, issue 28): object and
plate paired whichever comes first, order only from "first ... then", and refusals kept for the rest."""

from __future__ import annotations

import pytest
from tabletop_readings import WORLD
from tabletop_readings import pairs_read as _reading

from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.tabletop_pairs import read_pairs
from nl2hltl2plan.language.translate import translate

TYPES = set(WORLD.object_types())




@pytest.mark.parametrize(
    "text",
    [
        "carrot: blue plate",
        "the carrot should end up on the blue plate",
        "The blue plate is where the carrot goes.",
    ],
)
def test_object_and_plate_pair_whichever_comes_first(text):
    assert _reading(text) == ([("Carrot", "BluePlate")], [])


def test_plate_first_and_object_first_sentences_mix_across_sentences():
    text = "Blue plate: carrot and orange. Green apple: pink plate. In any order."
    assert _reading(text) == (
        [("Carrot", "BluePlate"), ("GreenApple", "PinkPlate"), ("Orange", "BluePlate")],
        [],
    )


def test_first_then_orders_the_groups_and_nothing_within_them():
    pairs, order = _reading(
        "First the pink plate takes the red apple and the carrot. Once that's done, the green apple: blue "
        "plate."
    )
    assert pairs == [("Carrot", "PinkPlate"), ("GreenApple", "BluePlate"), ("RedApple", "PinkPlate")]
    assert order == [
        (("Carrot", "PinkPlate"), ("GreenApple", "BluePlate")),
        (("RedApple", "PinkPlate"), ("GreenApple", "BluePlate")),
    ]


def test_the_grammar_reading_stands_the_pairs_reading_checks_it_or_reads_what_it_refused(monkeypatch):
    from nl2hltl2plan.language import tabletop_reader

    asked: list[str] = []

    def cannot_read(text, *args):
        asked.append(text)
        return None

    monkeypatch.setattr(tabletop_reader, "tabletop_fallback", cannot_read)  # the hook asks the pairs reading
    text = "Put the carrot on the blue plate, then the orange on the yellow plate."
    assert _reading(text) == (
        [("Carrot", "BluePlate"), ("Orange", "YellowPlate")],
        [(("Carrot", "BluePlate"), ("Orange", "YellowPlate"))],
    )
    assert asked == [text]  # asked once, for a second opinion
    assert _reading("carrot: blue plate, orange: yellow plate") is None  # the grammar's refusal stands
    assert asked[1:] == ["carrot: blue plate, orange: yellow plate"]


@pytest.mark.parametrize(
    "text",
    [
        "carrot: blue plate, carrot: pink plate",  # one object, two plates
        "the carrot or the orange: blue plate",  # a choice
        "blue plate, yellow plate: carrot",  # two plates for one object
        "carrot: blue plate; before that, orange: yellow plate",  # "before" that refers back
        "carrot: blue plate before orange: yellow plate; those last two can go in any order",  # not last 2
        "the carrot should not end up on the blue plate",  # a negation
        "the carrots: blue plate",  # a plural (a count)
        "carrot near the blue plate",  # a relation that is no placement
        "green apple: blue plate; orange: yellow plate, in reverse order",  # check 1 names "reverse"
        "carrot: blue plate, banana: pink plate",  # an object the world lacks
        "carrot: blue plate, orange: yellow plate, then green apple: pink plate first",  # "first" misplaced
        "the carrot from the blue plate: yellow plate",  # a move, not a placement
        "carrot: blue plate, orange: yellow plate first",  # which one first is not said
        "the blue plate had the carrot, now the orange",  # how things were (the lead's probe), no request
        "the carrot is already on the blue plate. orange: yellow plate",  # a statement of where it is
        "put the three apples on the blue plate",  # a count the world does not have
        "Step 2: carrot: blue plate. Step 1: orange: yellow plate.",  # labels out of turn
        "1) carrot: blue plate 3) orange: yellow plate",  # list numbers out of turn
        # a remark about the order inside steps of one placement each: it frees nothing
        "Step 1: carrot: blue plate. Step 2: orange: yellow plate. Within each step, any order.",
        "If you don't mind the mess, carrot: blue plate",  # a condition, not a courtesy frame
        "Three moves: carrot: blue plate, orange: yellow plate",  # a heading's count that is not theirs
        "put the carrot next to the blue plate, then the orange on the yellow plate",  # "next to"
        # "first" before "after you put": the structure model rebuilt in session 22 read the second pair first
        "Please, first you put the green apple and the orange in the plate yellow, and after you put the "
        "carrot and the red apple in the plate blue.",
        "Put the carrot on the blue plate, but wait until the carrot is on the yellow plate.",  # named twice
        "Put the carrot on the blue plate, but wait until you are ready.",  # a wait for no placement
        # done with a plate that is not the step just said
        "Put the green apple on the yellow plate. Once you're done with the blue plate, move on to the pink "
        "plate: carrot.",
    ],
)
def test_near_misses_stay_refused(text):
    assert _reading(text) is None, text


def test_read_pairs_refuses_what_check_1_would_not_see():
    assert read_pairs("orange: blue plate, then orange: blue plate", TYPES) is None  # named twice
    assert read_pairs("blue plate", TYPES) is None  # a plate and no object
    assert read_pairs("carrot: blue plate; orange", TYPES) is None  # an object with no plate
    assert read_pairs("to begin, carrot: blue plate, orange: yellow plate", TYPES) is None  # no "then"


def test_other_worlds_never_get_the_fallback():
    from nl2hltl2plan.language.tabletop_pairs import tabletop_fallback
    from nl2hltl2plan.worlds import load_world

    kitchen = load_world("FloorPlan1")
    assert tabletop_fallback("carrot: blue plate, orange: yellow plate", kitchen, "offline") is None


@pytest.mark.parametrize(
    "text",
    [
        "the carrot is on the blue plate",
        "The carrot's on the blue plate.",
        "the carrot has been put on the blue plate",
        "the carrot sits on the blue plate",
        "the carrot is on the blue plate, please put the orange on the yellow plate",  # said before the wish
        "the blue plate had the carrot, now the orange",
        "Could you put the orange on the yellow plate? The carrot is fine where it is.",
    ],
)
def test_a_statement_of_where_things_are_is_refused_by_name(text):
    with pytest.raises(HTTError, match="says where something is"):
        translate(text, WORLD, build=False)


@pytest.mark.parametrize(
    "text",
    [
        "The blue plate is for the carrot.",  # a purpose, no state
        "Make sure the carrot is on the blue plate.",
        "I want that carrot is on blue plate.",
        "Final layout: blue plate has the carrot.",
    ],
)
def test_a_state_under_a_wish_or_goal_is_a_task(text):
    assert _reading(text) == ([("Carrot", "BluePlate")], [])


@pytest.mark.parametrize(
    "text",
    [
        "put the apples on the blue plate",
        "Both apples go on the blue plate.",
        "the two apples: blue plate",
    ],
)
def test_the_plural_of_a_shared_head_noun_names_every_such_object(text):
    assert _reading(text) == ([("GreenApple", "BluePlate"), ("RedApple", "BluePlate")], [])


def test_an_object_word_that_names_several_is_refused_with_what_the_world_has():
    with pytest.raises(WorldError, match="tabletop has the green apple and the red apple"):
        translate("put the apple on the blue plate", WORLD, build=False)


@pytest.mark.parametrize(
    ("text", "pairs"),
    [
        ("put the orange on the blue plate, sorry, the yellow plate", [("Orange", "YellowPlate")]),
        ("the carrot on the pink plate. No wait, the blue plate!", [("Carrot", "BluePlate")]),
        ("put the carrot, I mean the orange, on the blue plate", [("Orange", "BluePlate")]),
    ],
)
def test_a_correction_keeps_the_second_name(text, pairs):
    assert _reading(text) == (pairs, [])



# the carrot and the orange on the yellow plate in either order, then the green apple on the blue plate
CARROT_ORANGE_THEN_APPLE = (
    [("Carrot", "YellowPlate"), ("GreenApple", "BluePlate"), ("Orange", "YellowPlate")],
    [
        (("Carrot", "YellowPlate"), ("GreenApple", "BluePlate")),
        (("Orange", "YellowPlate"), ("GreenApple", "BluePlate")),
    ],
)

@pytest.mark.parametrize(
    "text",
    [
        "Phase one: carrot and orange onto the yellow plate. Phase two: green apple onto the blue plate.",
        "Part A: carrot and orange onto the yellow plate. Part B: green apple onto the blue plate.",
        "Objective I) carrot and orange on the yellow plate. Objective II) green apple on the blue plate.",
        "1st carrot & orange on yellow plate, then green apple on blue plate",
        "What I need first is the carrot and the orange on the yellow plate, and after that the green apple "
        "on the blue plate",
        "Before anything else, the carrot and the orange go on the yellow plate. When you've done that, "
        "the green apple goes on the blue plate.",
    ],
)
def test_labels_ordinals_and_first_before_the_names_order_the_groups(text):
    assert _reading(text) == CARROT_ORANGE_THEN_APPLE


@pytest.mark.parametrize(
    "text",
    [
        "1) Place the carrot on the blue plate. 2) Place the orange on the yellow plate. You may do these in "
        "any order.",
        "Here is what I need: the carrot on the blue plate, the orange on the yellow plate. The order is of "
        "no consequence.",
        "Two moves, no particular order: carrot blue plate, orange yellow plate.",
        "It would please me if the carrot were set on the blue plate and the orange on the yellow plate.",
        "Now dear, the carrot, the long one, goes on the blue plate, and the orange goes on the yellow plate",
        "Pair the carrot with the blue plate and the orange with the yellow plate.",
        "When you're finished, the table should look like this: carrot on the blue plate, orange on the "
        "yellow plate. How you get there is your call.",
        "End state: carrot on the blue plate, orange on the yellow plate. The order of the moves is of no "
        "import.",
        "Elementary: the carrot belongs on the blue plate, the orange on the yellow plate. Which you place "
        "first is immaterial.",
        "Put the carrot on the blue plate and the orange on the yellow plate; it makes no odds which goes "
        "first.",
    ],
)
def test_lists_headings_asides_and_free_order_remarks_leave_the_tasks_unordered(text):
    assert _reading(text) == ([("Carrot", "BluePlate"), ("Orange", "YellowPlate")], [])


def test_a_before_inside_a_clause_orders_what_follows_it_after_each_thing_it_names():
    pairs, order = _reading(
        "Make sure the green apple is on the yellow plate before the carrot or the orange goes on the blue "
        "plate; those last two can go in any order."
    )
    assert pairs == [("Carrot", "BluePlate"), ("GreenApple", "YellowPlate"), ("Orange", "BluePlate")]
    assert order == [
        (("GreenApple", "YellowPlate"), ("Carrot", "BluePlate")),
        (("GreenApple", "YellowPlate"), ("Orange", "BluePlate")),
    ]


def test_a_free_order_remark_that_frees_no_pair_the_thens_leave_is_not_dropped():
    # "then" orders the two; "either order is ok" says they are free: never one reading of the two in silence
    assert _reading("Green apple on blue plate, then orange on yellow plate - either order is ok.") in (
        None,
        ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], []),
    )
    # the remark frees a pair inside a group: the groups stay ordered
    pairs, order = _reading(
        "Green apple and orange on the yellow plate first, then the carrot on the blue plate, in any order"
    ) or ([], [])
    assert (("GreenApple", "YellowPlate"), ("Carrot", "BluePlate")) in order


@pytest.mark.parametrize(
    "text",
    [
        "1) carrot and orange on the yellow plate 2) green apple on the blue plate",
        "1. carrot and orange -> yellow plate\n2. green apple -> blue plate",
        "1) carrot and orange on the yellow plate 2) green apple on the blue plate. Within each step, any "
        "order.",
        "Step 1: carrot, orange -> yellow plate. Step 2: green apple -> blue plate. Within each step, any "
        "order.",
    ],
)
def test_a_numbered_list_orders_its_steps_unless_a_remark_frees_the_whole_list(text):
    assert _reading(text) == CARROT_ORANGE_THEN_APPLE


@pytest.mark.parametrize(
    "text",
    [
        "If it isn't too much trouble, put the carrot on the blue plate and, while you're at it, the orange "
        "on the yellow plate.",
        "If you don't mind, carrot: blue plate, orange: yellow plate.",
        "When you get a chance, put the orange on the yellow plate and the carrot on the blue plate, if "
        "that's okay.",
        "Carrot must go in blue plate, orange in yellow plate. Which order, is not important.",
        "the carrot on the blue plate, the orange on the yellow plate. Order you can choose.",
        "the carrot on the blue plate and, lastly, the orange on the yellow plate. The order doesn't matter.",
        "1) carrot on the blue plate 2) orange on the yellow plate, in any order",
    ],
)
def test_courtesy_frames_and_free_order_remarks_in_other_shapes_leave_the_tasks_unordered(text):
    assert _reading(text) == ([("Carrot", "BluePlate"), ("Orange", "YellowPlate")], [])


def test_a_name_read_as_a_landmark_is_not_understood_in_the_tabletop_world():
    # nothing lies on a plate at the start: "the green apple on the pink plate" can only be a placement
    from nl2hltl2plan.language.world_readers import world_reader

    text = "green apple on the pink plate orange on the yellow plate red apple on the blue plate"
    one = translate("put the green apple on the blue plate", WORLD, build=False)
    landmarks = one.model_copy(update={"instruction": text})
    assert {u.words for u in world_reader(WORLD).unused(landmarks)} == {
        "pink plate", "orange", "yellow plate", "red apple"
    }
    assert _reading(text) == (
        [("GreenApple", "PinkPlate"), ("Orange", "YellowPlate"), ("RedApple", "BluePlate")],
        [],
    )


def test_courtesy_frames_are_no_condition_or_negation_in_any_world():
    from nl2hltl2plan.worlds.demo import demo_world

    frames = ["If you don't mind, put the apple in the fridge.", "Put the apple in the fridge, if you can."]
    for text in frames:
        res = translate(text, demo_world(), build=False)
        assert not res.unparsed and not res.constraint_specs, text
        assert [(t.object, t.receptacle) for t in res.tasks] == [(["Apple"], ["Fridge"])]


def test_a_full_reading_the_pairs_reading_contradicts_is_not_taken():
    from nl2hltl2plan.language.tabletop_reader import TabletopReader

    reader = TabletopReader(WORLD)
    text = "First put the carrot on the blue plate, then the orange on the yellow plate."
    res = translate(text, WORLD, build=False)
    assert reader.doubted(res, "offline") is res  # the two readings agree
    plates = [t.receptacle for t in res.tasks][::-1]
    swapped = [t.model_copy(update={"receptacle": p}) for t, p in zip(res.tasks, plates, strict=True)]
    crossed = res.model_copy(update={"tasks": swapped})  # paired across: check 1 finds no word left unused
    doubted = reader.doubted(crossed, "offline")
    assert doubted.partial and "read two ways" in doubted.unparsed[-1]
    assert "A before B" in doubted.unparsed[-1]


def test_a_full_reading_that_check_1_rejects_on_the_words_paired_gives_way_to_the_pairs_reading():
    from nl2hltl2plan.language.tabletop_reader import TabletopReader

    reader = TabletopReader(WORLD)
    text = "First put the carrot on the blue plate, then the orange on the yellow plate."
    res = translate(text, WORLD, build=False)
    unordered = res.model_copy(update={"before": []})  # lost the "then": check 1 finds "first", "then" unused
    taken = reader.doubted(unordered, "offline")
    assert not taken.partial and [(t.object, t.receptacle) for t in taken.tasks] == [
        (t.object, t.receptacle) for t in res.tasks
    ]
    assert taken.before == res.before == [("A", "B")]


APPLE_BLUE_ORANGE_YELLOW = ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])


@pytest.mark.parametrize(
    "text",
    [
        "Please sort these: - green apple: blue plate - orange: yellow plate",
        "could you organise this for me - orange - yellow plate, green apple - blue plate",
        "hey, whenever you're free, the green apple to the blue plate and the orange to the yellow plate",
        "yo, mind doing me a favour? green apple on blue plate, orange on yellow plate. no rush",
        "green apple on the blue plate, orange on the yellow plate. The order you do them in is irrelevant.",
        "green apple on the blue plate, orange on the yellow plate; it makes no difference which comes first",
        "Orange: yellow plate. Green apple: blue plate. None of these depends on another.",
    ],
)
def test_clauses_that_name_nothing_are_read_by_their_words(text):
    """Courtesy, a list's heading and a freedom statement, whatever their phrasing (`remarks_read`)."""
    assert _reading(text) == APPLE_BLUE_ORANGE_YELLOW


def test_a_freedom_statement_about_each_group_leaves_the_groups_ordered():
    text = (
        "sort these: green apple - yellow plate, orange - yellow plate. then: carrot - blue plate, red apple "
        "- blue plate. the order inside each pair is up to you."
    )
    pairs, order = _reading(text)
    first, second = pairs[1:3], [pairs[0], pairs[3]]
    assert first == [("GreenApple", "YellowPlate"), ("Orange", "YellowPlate")]
    assert order == sorted((a, b) for a in first for b in second)


@pytest.mark.parametrize(
    "text",
    [
        "the order matters: the orange on the yellow plate, the green apple on the blue plate",
        "green apple on the blue plate and orange on the yellow plate; the order is not up to you",
        "the green apple on the blue plate must precede the orange on the yellow plate",
        "where is the green apple? on the blue plate. put the orange on the yellow plate",
    ],
)
def test_order_words_no_reading_takes_are_refused(text):
    """An order that is said but not which one, a relation verb, a question about where a thing is:
    refused, never read as no order. ("hey, when you're done, put A and B" is read as "when you're done,
    put A and B", with no order, as in every world: test_tabletop_chat, issue 23's one greeting policy.)"""
    assert _reading(text) is None


@pytest.mark.parametrize(
    "text",
    [
        "green apple -> blue, orange -> yellow",
        "Put the green apple on the blue plate and the orange on the yellow.",
        "Where does the green apple go? On the blue plate. And the orange? On the yellow plate.",
        "Sort the green apple onto the blue plate and the orange onto the yellow plate.",
        "put the green apple on the blue plate and the orange on the pink, no wait, the yellow",
        "I want that green apple is on blue plate, carrot is not needed, orange is on yellow plate.",
    ],
)
def test_plates_by_colour_answers_and_wishes_far_from_their_verb(text):
    """A plate named by its colour alone, a question about where an object goes answered by a plate,
    "sort" before an object, and a state under a wish said more than six words before it."""
    expected = None if "not needed" in text else APPLE_BLUE_ORANGE_YELLOW
    assert _reading(text) == expected


def test_a_colour_after_a_word_of_place_is_a_plate_even_before_and():
    """ "on the green and the red apple on the pink": the green plate, not the green and red apples."""
    text = "Put the carrot on the blue plate and the green apple on the green and the red apple on the pink."
    assert _reading(text) == (
        [("Carrot", "BluePlate"), ("GreenApple", "GreenPlate"), ("RedApple", "PinkPlate")],
        [],
    )


def test_a_sentence_final_then_orders_its_own_sentence_after_the_one_before():
    pairs, order = _reading(
        "The green apple goes on the blue plate first. The orange goes on the yellow plate after that."
    )
    assert order == [(("GreenApple", "BluePlate"), ("Orange", "YellowPlate"))]


@pytest.mark.parametrize(
    "text, ordered",
    [
        ("Do the yellow plate before the blue plate: green apple and orange on the yellow plate, carrot "
         "and red apple on the blue plate.", True),
        ("The blue plate after the yellow plate. Carrot and red apple on the blue plate, green apple and "
         "orange on the yellow plate.", True),
        ("Do the yellow plate before the blue plate: green apple and orange on the yellow plate, carrot on "
         "the blue plate, red apple on the pink plate.", None),
        ("Do the yellow plate before the blue plate: first green apple and orange on the yellow plate, then "
         "carrot and red apple on the blue plate.", True),
    ],
)
def test_an_order_said_of_plates_orders_their_placements(text, ordered):
    """Every placement on the first plate before every one on the second (the same order said again of
    the placements is read by the grammar); a plate the order leaves out is refused."""
    reading = _reading(text)
    if ordered is None:
        assert reading is None
        return
    pairs, order = reading
    yellow = [p for p in pairs if p[1] == "YellowPlate"]
    blue = [p for p in pairs if p[1] == "BluePlate"]
    assert len(pairs) == 4 and order == sorted((a, b) for a in yellow for b in blue)


def test_make_it_so_is_a_wish():
    text = "Can you make it so the green apple is on the blue plate and the orange is on the yellow plate?"
    assert _reading(text) == APPLE_BLUE_ORANGE_YELLOW


@pytest.mark.parametrize(
    "text",
    [
        "Once the green apple and the orange are in the yellow plate, put the carrot and the red apple in "
        "the blue plate.",
        "Green apple and orange on the yellow plate. Once they're there, carrot and red apple on the blue "
        "plate.",
        "Green apple and orange on the yellow plate. Only when that's done do the carrot and the red apple "
        "go on the blue plate.",
        "Priority 1: green apple and orange on the yellow plate. Priority 2: carrot and red apple on the "
        "blue plate. Within a priority, any order.",
        "hey, when you get a sec: yellow plate gets green apple and orange first, blue plate gets carrot and "
        "red apple after, any order within each",
        "Put the carrot and the red apple on the blue plate, but hold off until the green apple and the "
        "orange are on the yellow plate.",
        "Batch one: green apple and orange on the yellow plate. Batch two, after batch one: carrot and red "
        "apple on the blue plate.",
        "Fill the yellow plate with the green apple and the orange. Once you're through with the yellow "
        "plate, move on to the blue plate and fill it with the carrot and the red apple.",
        "Checklist: 1. green apple and orange - yellow plate. 2. carrot and red apple - blue plate.",
    ],
)
def test_the_order_of_two_steps_whatever_words_say_it(text):
    """A clause waiting for placements it states, a pronoun for the step before, any noun numbered in
    turn as a label, a "first" / "after" closing each step's clause, a wait said after the placements
    that wait, and a label that names the label before it."""
    pairs, order = _reading(text)
    yellow = [p for p in pairs if p[1] == "YellowPlate"]
    blue = [p for p in pairs if p[1] == "BluePlate"]
    assert len(yellow) == len(blue) == 2 and order == sorted((a, b) for a in yellow for b in blue)


@pytest.mark.parametrize(
    "text",
    [
        "Part 2: green apple on the blue plate. Part 1: orange on the yellow plate.",
        "Part B: green apple on the blue plate. Part A: orange on the yellow plate.",
    ],
)
def test_steps_numbered_out_of_turn_are_refused(text):
    assert _reading(text) is None


def test_respectively_pairs_the_nth_object_with_the_nth_plate():
    text = "The green apple and the orange go on the blue and yellow plates respectively."
    assert _reading(text) == APPLE_BLUE_ORANGE_YELLOW
    three = "The green apple, the orange and the carrot go on the blue and yellow plates respectively."
    assert _reading(three) is None


@pytest.mark.parametrize(
    "text",
    [
        "The blue plate comes first: the green apple goes on it. Then the orange on the yellow plate.",
        "Start with the blue plate: put the green apple on that plate. Then the orange on the yellow plate.",
    ],
)
def test_a_plate_said_again_as_it_is_the_plate_named_before(text):
    """ "on it" / "on that plate" after a plate names that plate (only plates hold things here), and a
    plate said before and after its objects is one topic."""
    assert _reading(text) == (
        [("GreenApple", "BluePlate"), ("Orange", "YellowPlate")],
        [(("GreenApple", "BluePlate"), ("Orange", "YellowPlate"))],
    )


def test_a_plate_said_again_after_its_objects_is_the_same_topic_in_a_longer_text():
    """A plate named again right after its objects ("... with the green apple on it") is the topic said
    again, also when another plate and its objects follow; a text that starts with an object pairs as it
    always did ("the orange on the blue plate" is a second placing on it)."""
    text = "Make sure the blue plate ends up with the green apple on it and the yellow plate with the orange."
    assert _reading(text) == ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])
    same_plate = ([("GreenApple", "BluePlate"), ("Orange", "BluePlate")], [])
    assert _reading("The blue plate gets the green apple and the blue plate gets the orange.") == same_plate
    assert _reading("put the green apple on the blue plate, the orange on the blue plate") == same_plate


_ORANGE_GREEN = ([("GreenApple", "BluePlate"), ("Orange", "YellowPlate")], [])


@pytest.mark.parametrize(
    "text",
    [
        "Re: tidying\nPlease put the orange on the yellow plate and the green apple on the blue plate.",
        "Please put the orange on the yellow plate and the green apple on the blue plate. Regards,\nKim",
        "Don't forget to put the orange on the yellow plate and the green apple on the blue plate.",
        "If you could move the orange to the yellow plate and the green apple to the blue plate, "
        "that would be "
        "lovely.",
        "The orange lives on the yellow plate and the green apple lives on the blue plate, can you fix that?",
        "The orange lives on the yellow plate and the green apple on the blue plate. Tidy them up "
        "in any order.",
    ],
)
def test_a_letters_frame_a_reminder_and_a_polite_condition_carry_no_task(text):
    assert _reading(text) == _ORANGE_GREEN


@pytest.mark.parametrize(
    "text",
    [
        # a subject line that says an order, or a sign-off whose "name" is an object, is no frame
        "Re: first the yellow plate\nPut the orange on the yellow plate and the green apple on the "
        "blue plate.",
        # a condition that is no courtesy ("if you can X, Y"): not read as a request
        "If you can put the orange on the yellow plate, put the green apple on the blue plate.",
    ],
)
def test_frames_that_say_more_than_courtesy_are_not_dropped(text):
    assert _reading(text) is None


def test_a_colour_with_one_names_the_only_thing_of_that_colour():
    text = "could you sort out the plates - orange goes to the yellow one, green apple to the blue one"
    assert _reading(text) == _ORANGE_GREEN
    # "the green one": the green apple or the green plate, never guessed where a thing is named ...
    assert _reading("Put the green one on the blue plate and the orange on the yellow one.") is None
    # ... but after a word of place it is where something goes, and only plates hold things here
    on_the_green_one = "Put the orange on the yellow one and the carrot on the green one."
    assert _reading(on_the_green_one) == ([("Carrot", "GreenPlate"), ("Orange", "YellowPlate")], [])


def test_one_thing_per_plate_is_a_heading_the_pairs_must_keep():
    text = "Each plate gets one thing: yellow plate the orange, blue plate the green apple. Any order."
    assert _reading(text) == _ORANGE_GREEN
    two_on_one = "Each plate gets one thing: yellow plate the orange, yellow plate the green apple."
    assert _reading(two_on_one) is None
