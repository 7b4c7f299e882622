"""Step 4 of the offline parser: drafts (clauses about one object) and grounded tasks."""

from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder, Tasks, build_tasks
from nl2hltl2plan.language.grammar.drafts import DraftBuilder
from nl2hltl2plan.language.grammar.sentences import read_sentences


def _tasks(text: str) -> tuple[Tasks, TaskBuilder]:
    b = TaskBuilder(None, strict=False)
    drafting = DraftBuilder(b)
    for s in read_sentences(text).sentences:
        drafting.add_sentence(s)
    return build_tasks(drafting.out.drafts, drafting.out.units, b, text), b


def test_clauses_about_one_object_form_one_task() -> None:
    tasks, b = _tasks("Pick up the apple, chill it in the fridge and put it on the counter")
    (spec,) = tasks.specs
    assert (spec.kind, spec.object, spec.receptacle) == ("cool_place", ["Apple"], ["CounterTop"])
    assert b.unparsed == []


def test_a_list_of_objects_is_a_group_of_tasks() -> None:
    tasks, _ = _tasks("Put the pen and the book on the desk")
    assert [s.object for s in tasks.specs] == [["Pen"], ["Book"]]
    assert list(tasks.groups.values()) == [[0, 1]]
    assert [u.tasks for u in tasks.units] == [[0, 1]]


def test_container_and_content() -> None:
    tasks, _ = _tasks("Put a spoon in a mug and put the mug on the counter")
    (spec,) = tasks.specs
    assert (spec.kind, spec.object, spec.container) == ("place_in_container", ["Spoon"], ["Mug"])


def test_a_task_without_destination_is_reported_not_guessed() -> None:
    tasks, b = _tasks("Pick up the apple")
    assert tasks.specs == []
    assert b.unparsed == ["no destination for the 'the apple' in: Pick up the apple"]
