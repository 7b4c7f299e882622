"""Issue 28, order words of three- and four-task paper-style instructions (h179, paper_h179dev.txt). Before
each fix the reading was wrong at exit 0 (a task dropped, an order lost or added) or partial:

- "Until X, don't put Y" is the guide's "Do not Y until X" with the reference first (Y was dropped);
- a sentence of one clause closed by "to finish" is its task done last (the words were left unread);
- "The last thing (to do) is (to) X" / "The first thing is X" open their sentence as "Finally," / "First,";
- "Only after that, Y" / "Only then Y" opening a sentence ("Only, then Y": partial);
- "A, and B; those two can be done in any order, but only after X" (a clause with no task: partial);
- "As soon as it's there, Y" (which task "it's there" names: partial);
- "A whenever you like, but B only after X": the free A is not ordered after X (wrong);
- "look at X under the lamp, then the Y": the verb of "look at" is left out before the Y (Y dropped);
- "only after you've thrown the bottle in the bin" states a task, and names no task of a bar of soap.
The default run keeps one case per class; `-m sweep` reads the wording variants."""

from __future__ import annotations

import pytest

from nl2hltl2plan.config import data_dir
from nl2hltl2plan.language.grounding import Grounder
from nl2hltl2plan.language.negations import read_negations
from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"
BOWL = "place Bowl -> Cabinet"
SEQ = "Put the mug in the sink. Then put the apple in the fridge"
needs_data = pytest.mark.skipif(data_dir(required=False) is None, reason="needs ../shared/data")


def closure_of(text: str) -> tuple[list[str], set[tuple[str, str]]]:
    tasks, order, unread = read(text)
    assert not unread, unread
    return sorted(tasks), order


def test_until_first_is_no_negation_but_an_order():
    """Before: "don't put the egg in the microwave" was a constraint, and the egg's task was dropped."""
    rest, found = read_negations(
        "Put the apple in the fridge. Until the apple is in the fridge, don't put the egg in the microwave.",
        Grounder({"Apple", "Fridge", "Egg", "Microwave"}),
    )
    assert not found and "put the egg in the microwave" in rest
    tasks, order = closure_of(
        "Put the mug in the sink. Until that's done, don't put the egg in the microwave."
    )
    assert tasks == sorted([MUG, EGG]) and order == {(MUG, EGG)}


@needs_data
def test_until_first_is_read_whole_in_a_floor_plan():
    """The whole path (negations, then the grammar) in an ALFRED kitchen: two ordered tasks, no constraint."""
    from nl2hltl2plan.language.translate import translate
    from nl2hltl2plan.suites.alfred.conversion import scenario_world

    res = translate(
        "Put the apple in the fridge. Until then, don't put the mug in the sink.",
        scenario_world({"scene": "FloorPlan1", "source_trials": []}),
        "offline",
        build=False,
        actions="none",
    )
    assert not res.partial and not res.constraint_specs
    kinds = {t.id: (t.object[0], (t.receptacle or [""])[0]) for t in res.tasks}
    assert [(kinds[a], kinds[b]) for a, b in res.before] == [(("Apple", "Fridge"), ("Mug", "SinkBasin"))]


def test_one_clause_to_finish_is_last():
    """Before: "to finish" was left unread and the egg had no order (a wrong reading at exit 0)."""
    tasks, order = closure_of(f"{SEQ}. Put the egg in the microwave to finish.")
    assert tasks == sorted([MUG, APPLE, EGG]) and {(MUG, EGG), (APPLE, EGG)} <= order


def test_to_finish_near_misses_stay_as_they_were():
    """Near miss: "to finish the job" is a purpose; "A and B to finish" does not say which is last."""
    _, order, _ = read("Put the egg in the microwave to finish the job.")
    assert order == set()
    _, order, _ = read(f"{SEQ}. Put the egg in the microwave and the bowl in the cabinet to finish.")
    assert (APPLE, EGG) not in order


def test_the_last_thing_is_to():
    """Before: "The last thing is" was left unread (partial)."""
    tasks, order = closure_of(f"{SEQ}. The last thing is to put the egg in the microwave.")
    assert tasks == sorted([MUG, APPLE, EGG]) and (APPLE, EGG) in order


def test_only_after_that_opening_a_sentence():
    """Before: "Only, then put ...": 'Only' unread (partial)."""
    tasks, order = closure_of("Put the mug in the sink. Only after that, put the apple in the fridge.")
    assert order == {(MUG, APPLE)}


def test_those_two_can_be_done_in_any_order_but_only_after():
    """Before: "those two can be done" was a clause with no task, and the bowl was lost (partial)."""
    tasks, order = closure_of(
        "Put the mug in the sink, and put the apple in the fridge; those two can be done in any order, but "
        "only after you've put the bowl in the cabinet."
    )
    assert tasks == sorted([MUG, APPLE, BOWL]) and order == {(BOWL, MUG), (BOWL, APPLE)}


def test_as_soon_as_it_is_there():
    """Before: "could not tell which task \"it's there\" refers to" (partial)."""
    tasks, order = closure_of(
        "Put the mug in the sink. As soon as it's there, put the apple in the fridge. Put the egg in the "
        "microwave whenever you like."
    )
    assert order == {(MUG, APPLE)}


def test_a_free_task_before_but_is_not_ordered_by_the_reference_after_it():
    """Before: "A whenever you want, but B only after X" put A after X too (wrong at exit 0)."""
    tasks, order = closure_of(
        "Put the mug in the sink. Put the apple in the fridge whenever you want, but put the egg in the "
        "microwave only after the mug is in the sink."
    )
    assert order == {(MUG, EGG)}


def test_look_at_with_the_verb_left_out_after_then():
    """Before: "look at the mug under the lamp, then the bowl" read one task (the bowl dropped)."""
    tasks, order, unread = read("Look at the mug under the desk lamp, then the bowl.")
    assert [t.split()[1] for t in tasks] == ["Mug", "Bowl"] and len(order) == 1 and not unread


def test_a_thrown_thing_is_a_task_of_its_own():
    """Before: "only after you've thrown the cloth in the bin" named no task (the past participle) or the
    other task that goes in the bin."""
    tasks, order = closure_of(
        "Put the mug in the sink, but only after you've thrown the tissue box in the garbage can. Wash the "
        "apple and throw it in the garbage can last."
    )
    box = "place TissueBox -> GarbageCan"
    assert box in tasks and (box, MUG) in order


# ----- the wording variants (sweep) -------------------------------------------------------------------------
@pytest.mark.sweep
@pytest.mark.parametrize(
    "until",
    ["Until that's done, don't", "Until that is done, do not", "Until then, don't",
     "Until the mug is in the sink, don't", "Until you've put the mug in the sink, please don't"],
)
def test_until_first_variants(until):
    tasks, order = closure_of(f"Put the mug in the sink. {until} put the egg in the microwave.")
    assert tasks == sorted([MUG, EGG]) and order == {(MUG, EGG)}


@pytest.mark.sweep
@pytest.mark.parametrize(
    "fin", ["to finish", "to finish up", "to wrap up", "to wrap things up", "to conclude"]
)
def test_to_finish_variants(fin):
    tasks, order = closure_of(f"{SEQ}. Put the egg in the microwave {fin}.")
    assert {(MUG, EGG), (APPLE, EGG)} <= order


@pytest.mark.sweep
@pytest.mark.parametrize(
    ("lead", "last"),
    [("The last thing is to", True), ("The last thing to do is", True), ("The very last step is to", True),
     ("The final task is to", True), ("The last thing you need to do is", True)],
)
def test_the_nth_thing_variants(lead, last):
    tasks, order = closure_of(f"{SEQ}. {lead} put the egg in the microwave.")
    assert ((APPLE, EGG) in order) is last


@pytest.mark.sweep
@pytest.mark.parametrize(
    "lead", ["Only after that,", "Only then", "Only then,", "Only once that's done,", "Just after that,"]
)
def test_focus_opener_variants(lead):
    tasks, order = closure_of(f"Put the mug in the sink. {lead} put the apple in the fridge.")
    assert order == {(MUG, APPLE)}


@pytest.mark.sweep
@pytest.mark.parametrize(
    "free", ["those two can be done in any order", "these can be done in either order",
             "the two tasks can happen in any order", "both can be done in whichever order"],
)
def test_those_can_be_done_variants(free):
    tasks, order = closure_of(
        f"Put the mug in the sink and put the apple in the fridge; {free}, but only after you've put the "
        "bowl in the cabinet."
    )
    assert order == {(BOWL, MUG), (BOWL, APPLE)}


@pytest.mark.sweep
@pytest.mark.parametrize(
    "there", ["As soon as it's there,", "Once it is there,", "When it's in place,", "Once they're there,"]
)
def test_it_is_there_variants(there):
    tasks, order = closure_of(f"Put the mug in the sink. {there} put the apple in the fridge.")
    assert order == {(MUG, APPLE)}


@pytest.mark.sweep
@pytest.mark.parametrize("free", ["whenever you want", "whenever you like", "at any point", "at any time"])
def test_free_but_variants(free):
    tasks, order = closure_of(
        f"Put the mug in the sink. Put the apple in the fridge {free}, but put the egg in the microwave only "
        "after the mug is in the sink."
    )
    assert order == {(MUG, EGG)}


@pytest.mark.sweep
@pytest.mark.parametrize(
    "tail", ["then the bowl", "and then the bowl", "and finally the bowl", "and last of all, the bowl"]
)
def test_look_at_gap_variants(tail):
    tasks, order, unread = read(f"Look at the mug under the desk lamp, {tail}.")
    assert [t.split()[1] for t in tasks] == ["Mug", "Bowl"] and len(order) == 1 and not unread
