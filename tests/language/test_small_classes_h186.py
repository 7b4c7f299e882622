"""Issue 28, small wording classes left by session 28's helpers (h186, paper_h186dev.txt). Before each fix
the reading was partial, refused or wrong:

- a sentence that opens with the lamp: "By the floor lamp, examine A and then B" ("By the floor lamp"
  unread), "Under the lamp, have a look at A, then at B" (refused: "then at B" named no task);
- "look over X" as a looking verb ("over the CD" was a place: the CD lost);
- ordinal steps with the verb left out: "First put A on the shelf, second the keys, third the pencil"
  (partial), "First A. Second the keys." (B and C both after A only: wrong);
- "one more" as the thing: "a salt shaker in a drawer and one more in a cabinet" (the second task lost);
- a misspelt plural: "two candels" (no name near: refused);
- "the empty toilet paper roll": the lexicon names ToiletPaper "empty roll", so "empty" picks none;
- "when it's inside, Y": the task just said (which task it named was not told: partial).
"X or Y" and "put X away" with no place were already refused, naming "or" / "away" (kept by a test here).
The default run keeps one case per class; `-m sweep` reads the wording variants."""

from __future__ import annotations

import pytest
from grammar_readings import offline_reading

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.language.grammar.order_phrases import ordinal_steps
from nl2hltl2plan.language.spelling import spelt_name

ROOM = {
    "CreditCard", "Watch", "CD", "Pen", "Pencil", "CellPhone", "KeyChain", "Book", "Shelf", "Desk", "Drawer",
    "Cabinet", "Candle", "SaltShaker", "Mug", "Bowl", "Plate", "SinkBasin", "Sofa", "ArmChair", "FloorLamp",
    "Apple", "Fridge", "CounterTop", "ToiletPaper", "ToiletPaperHanger", "Toilet",
}  # fmt: skip
needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")
CARD, WATCH = "examine_in_light CreditCard under FloorLamp", "examine_in_light Watch under FloorLamp"
PHONE, KEYS, PENCIL = "place CellPhone -> Shelf", "place KeyChain -> Shelf", "place Pencil -> Shelf"


def read(text: str) -> tuple[list[str], set[tuple[str, str]], list[str]]:
    """(task summaries, the closure of the order as summary pairs, every unread word or clause)."""
    return offline_reading(text, ROOM)


def read_whole(text: str) -> tuple[list[str], set[tuple[str, str]]]:
    tasks, order, unread = read(text)
    assert not unread, unread
    return tasks, order


def test_a_sentence_that_opens_with_the_lamp():
    """Before: "By the floor lamp" was left unread (partial)."""
    assert read_whole("By the floor lamp, examine the credit card and then the watch.") == (
        [CARD, WATCH], {(CARD, WATCH)}
    )


def test_then_at_goes_on_with_the_looking_verb():
    """Before: refused ("then at the watch" named no task)."""
    assert read_whole("Under the floor lamp, have a look at the credit card, then at the watch.") == (
        [CARD, WATCH], {(CARD, WATCH)}
    )


def test_look_over_is_a_looking_verb():
    """Before: "over the credit card" was a place, and the credit card was lost."""
    tasks, _ = read_whole("Look over the credit card and the watch under the floor lamp.")
    assert sorted(tasks) == [CARD, WATCH]


def test_verbless_ordinal_steps_are_ordered_in_turn():
    """Before: partial ("second the keys" had no destination)."""
    tasks, order = read_whole("First put the phone on the shelf, second the keys, third the pencil.")
    assert tasks == [PHONE, KEYS, PENCIL] and order == {(PHONE, KEYS), (KEYS, PENCIL), (PHONE, PENCIL)}


def test_an_ordinal_is_a_step_only_after_a_first():
    """"the second shelf" is no step; without a clause-opening "first" nothing is rewritten."""
    assert ordinal_steps("Put the mug on the second shelf, then the bowl.") == (
        "Put the mug on the second shelf, then the bowl."
    )
    assert ordinal_steps("First put the mug in the sink. Second the bowl") == (
        "First put the mug in the sink. Second, the bowl"
    )


def test_one_more_is_a_second_thing_of_the_type():
    """Before: "one more in a cabinet" named no object, and its task was lost (partial)."""
    tasks, _ = read_whole("Put a salt shaker in a drawer and one more in a cabinet.")
    assert tasks == ["place SaltShaker -> Drawer", "place SaltShaker -> Cabinet"]


def test_a_misspelt_plural_is_the_plural_of_its_name():
    assert spelt_name("candels") == "candles"
    assert spelt_name("candles") is None  # a name as written is never respelt
    tasks, _ = read_whole("Put two candels in the cabinet.")
    assert tasks == ["place_two 2x Candle -> Cabinet"]


def test_it_is_inside_names_the_task_just_said():
    """Before: partial ('could not tell which task "it's inside" refers to')."""
    tasks, order = read_whole("Put an apple in the fridge and when it's inside, put a mug in the sink.")
    assert order == {("place Apple -> Fridge", "place Mug -> SinkBasin")}


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("Put the salt shaker or the mug on the desk.", "a choice between objects"),
        ("Put the mug on the desk, then put the pen away.", "a vague place"),
    ],
)
def test_a_choice_or_a_place_left_out_is_refused(text, word):
    """What the spec cannot say is named, never guessed: "or" (no "either" in the spec), "away" (no place)."""
    _, _, unread = read(text)
    assert any(word in u for u in unread), unread


@needs_data
def test_the_empty_toilet_paper_roll_is_toilet_paper():
    """Before: "empty" picked one roll of several (refused as a state the spec cannot check)."""
    from nl2hltl2plan.language.translate import translate
    from nl2hltl2plan.suites.alfred.conversion import scenario_world

    world = scenario_world({"scene": "FloorPlan426", "source_trials": []})
    res = translate("Put the empty toilet paper roll on the holder.", world, "offline", build=False,
                    actions="none")
    assert not res.partial, res.unparsed
    assert [t.summary() for t in res.tasks] == ["place ToiletPaper -> ToiletPaperHanger"]


# ----- the wording variants (sweep) -------------------------------------------------------------------------
@pytest.mark.sweep
@pytest.mark.parametrize(
    "lead",
    ["By the floor lamp,", "Beside the floor lamp,", "Next to the floor lamp,", "Near the floor lamp,",
     "Under the floor lamp,", "Using the floor lamp,", "In the light of the floor lamp,"],
)
@pytest.mark.parametrize(
    "verb", ["look at", "examine", "have a look at", "take a close look at", "look over", "check out"]
)
def test_lamp_opener_variants(lead, verb):
    text = f"{lead} {verb} the credit card and then the watch."
    assert read_whole(text) == ([CARD, WATCH], {(CARD, WATCH)})


@pytest.mark.sweep
@pytest.mark.parametrize(
    "text",
    [
        "First put the phone on the shelf, second the keys, third the pencil.",
        "First, put the phone on the shelf, second, the keys, third, the pencil.",
        "First put the phone on the shelf; second the keys; third the pencil.",
        "First put the phone on the shelf. Second the keys. Third the pencil.",
        "Firstly, put the phone on the shelf, secondly the keys, and thirdly the pencil.",
        "First put the phone on the shelf, second put the keys on the shelf, third the pencil.",
    ],
)
def test_ordinal_step_variants(text):
    tasks, order = read_whole(text)
    assert tasks == [PHONE, KEYS, PENCIL] and {(PHONE, KEYS), (KEYS, PENCIL)} <= order


@pytest.mark.sweep
@pytest.mark.parametrize(
    "text",
    [
        "Put a mug in the sink and one more in the cabinet.",
        "Put a mug in the sink, then put one more mug in the cabinet.",
        "Put a mug in the sink and another one in the cabinet.",
        "Put a mug in the sink. After that, put one more in the cabinet.",
    ],
)
def test_one_more_variants(text):
    tasks, _ = read_whole(text)
    assert tasks == ["place Mug -> SinkBasin", "place Mug -> Cabinet"]


@pytest.mark.sweep
@pytest.mark.parametrize(
    "there",
    ["once it's in,", "when it's inside,", "once it's in there,", "as soon as it's in,", "once it's there,"],
)
def test_it_is_there_variants(there):
    _, order = read_whole(f"Put an apple in the fridge, and {there} put a mug in the sink.")
    assert order == {("place Apple -> Fridge", "place Mug -> SinkBasin")}
