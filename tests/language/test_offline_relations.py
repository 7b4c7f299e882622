"""Step 6 of the offline parser: order markers -> `before` pairs."""

import pytest

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder, build_tasks
from nl2hltl2plan.language.grammar.drafts import DraftBuilder
from nl2hltl2plan.language.grammar.order_relations import relate
from nl2hltl2plan.language.grammar.parser import parse_instruction
from nl2hltl2plan.language.grammar.sentences import read_sentences


def _before(text: str) -> tuple[list[tuple[str, str]], list[str], list[str]]:
    b = TaskBuilder(None, strict=False)
    read = read_sentences(text)
    drafting = DraftBuilder(b)
    for s in read.sentences:
        drafting.add_sentence(s)
    tasks = build_tasks(drafting.out.drafts, drafting.out.units, b, text)
    before = relate(tasks, read.relations, b, text)
    return before, [s.id for s in tasks.specs], b.unparsed


def test_then_and_finally() -> None:
    before, ids, _ = _before(
        "Put the pen on the desk. Then put the book on the shelf. Put the cup in the sink at any time. "
        "Finally, put the apple in the fridge."
    )
    assert ids == ["A", "B", "C", "D"]
    assert before == [("A", "B"), ("B", "D")]  # the free task C stays unordered


def test_after_a_reference_and_a_relation_sentence() -> None:
    before, _, _ = _before(
        "After placing the book on the shelf, put the pen on the desk. Put the book on the shelf."
    )
    assert before == [("B", "A")]
    before, _, _ = _before(
        "Put the pen on the desk. Put the book on the shelf. The book should be placed before the pen."
    )
    assert before == [("B", "A")]


def test_contradictory_order_is_refused_naming_the_cycle() -> None:
    text = "Put the pen on the desk. Then put the book on the shelf. The book should be placed before the pen"
    with pytest.raises(HTTError, match=r"contradictory ordering in the instruction: (A|B) .* before"):
        _before(text)


def _parsed(text: str) -> tuple[list[tuple[str, str]], list[str]]:
    p = parse_instruction(text, None, strict=False)
    return sorted(p.before), p.unparsed


def test_a_reference_by_position_names_tasks_by_their_place_in_the_text() -> None:
    pre = "Put the pen on the desk at any time. Put the book on the shelf. "
    assert _parsed(pre + "Once done with the first tasks, put the cup in the sink.") == (
        [("A", "C"), ("B", "C")],
        [],
    )
    assert _parsed(pre + "After the previous task is done, put the cup in the sink.") == ([("B", "C")], [])
    assert _parsed(pre + "After the first task, put the cup in the sink.") == ([("A", "C")], [])
    assert _parsed(pre + "When everything else is finished, put the cup in the sink.") == (
        [("A", "C"), ("B", "C")],
        [],
    )


def test_a_sentence_that_starts_with_followed_by_comes_after_the_one_before() -> None:
    text = "Put the pen on the desk. Followed by placing the book on the shelf."
    assert _parsed(text) == ([("A", "B")], [])


def test_done_with_a_named_task_is_a_reference_not_then() -> None:
    for text in (
        "put the apple in the microwave when you're done putting the plate in the sink",
        "put the apple in the microwave after you are done putting the plate in the sink",
    ):
        assert _parsed(text) == ([("B", "A")], [])
    assert _parsed("put the apple in the microwave, and once that's done put the plate in the sink") == (
        [("A", "B")],
        [],
    )


def test_a_shelf_inside_the_fridge_is_the_fridge() -> None:
    p = parse_instruction("Put the apple on the middle shelf in the fridge.", {"Apple", "Fridge", "Shelf"})
    assert [(t.object, t.receptacle) for t in p.tasks] == [(["Apple"], ["Fridge"])] and p.unparsed == []
    p = parse_instruction("Put the apple on the shelf.", {"Apple", "Fridge", "Shelf"})
    assert [t.receptacle for t in p.tasks] == [["Shelf"]]


def test_after_that_inside_a_sentence_is_then() -> None:
    text = "put the orange and the apple on the plate, and after that put the mug in the sink"
    p = parse_instruction(text, None, strict=False)
    assert [(t.object, t.receptacle) for t in p.tasks] == [
        (["Orange"], ["Plate"]),
        (["Apple"], ["Plate"]),
        (["Mug"], ["SinkBasin"]),
    ]
    assert sorted(p.before) == [("A", "C"), ("B", "C")]
