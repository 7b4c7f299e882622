"""One list of the words that make a clause saying where a thing is asked for (`language/statements.py`,
`state_words.txt`), shared by check 1 and the tabletop reader; the reference to every task before and the
courtesy frames, each one list for every reader."""

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.courtesy import without_courtesy
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.statements import asked_before, says_where
from nl2hltl2plan.language.tabletop_wording import polite_frames, stated_not_asked
from nl2hltl2plan.language.task_specs import BaseTaskSpec

PAIRS = "I want that carrot is on blue plate, orange is on yellow plate, green apple is on green plate"
NAMES = ["carrot", "orange", "green apple", "blue plate", "yellow plate", "green plate"]


def test_a_wish_reaches_every_clause_of_its_sentence_and_no_further():
    assert asked_before(PAIRS, PAIRS.index("is on green"))
    assert stated_not_asked(PAIRS, NAMES) is None
    said = stated_not_asked("I want this. The carrot is on the blue plate.", NAMES)
    assert said == "carrot is on the blue plate"


def test_check_one_reads_a_place_under_a_far_reference_as_a_stop():
    """ "after" eight words before "are in the sink": the sink is where the tasks put things (check 1 once
    looked six words back only, and named the sink as invented)."""
    text = "after the mug, the apple and the egg are in the sink, put the bread in the fridge"
    tasks = [
        BaseTaskSpec(id=i, kind="place", object=[o], receptacle=["SinkBasin"])
        for i, o in zip("ABC", ["Mug", "Apple", "Egg"], strict=True)
    ] + [BaseTaskSpec(id="D", kind="place", object=["Bread"], receptacle=["Fridge"])]
    before = [(a, "D") for a in "ABC"]
    assert [u.words for u in account(text, tasks, before)] == []
    assert [u.words for u in account(text.replace("after", "and"), tasks, [])] != []


def test_where_verbs_are_one_list_with_the_tabletop_readers_extras():
    assert says_where("the mug has been sitting in", len("the mug has been sitting "))
    assert not says_where("put it in", len("put it "))
    assert not says_where("the carrot were set on", len("the carrot were set "))  # a placing: a stop
    said = stated_not_asked("the carrot was set on the blue plate.", NAMES)
    assert said == "carrot was set on the blue plate"


def test_references_to_every_task_before_are_one_rewrite():
    assert everyday("put A in the box, and after those two put C in the sink") == (
        "put A in the box. After those two, put C in the sink"
    )
    assert everyday("put A in the box, and after both of those put C in the sink") == (
        "put A in the box. After both of those, put C in the sink"
    )
    kept = "Put A in the box. After both are there, put C in the sink."
    assert everyday(kept) == kept


def test_courtesy_frames_and_polite_wishes_are_one_list_for_every_reader():
    assert without_courtesy("When you have time, put the mug in the sink.") == "put the mug in the sink."
    assert without_courtesy("Put the mug in the sink at your convenience.") == "Put the mug in the sink."
    assert polite_frames("it would be great if you could put the carrot on the blue plate") == (
        "please put the carrot on the blue plate"
    )
