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


def _scene_tasks(text: str, types: set[str]) -> Tasks:
    from nl2hltl2plan.language.grounding import Grounder, alfred_lookup

    b = TaskBuilder(Grounder(types), strict=False, look=alfred_lookup())
    drafting = DraftBuilder(b)
    for s in read_sentences(text).sentences:
        drafting.add_sentence(s)
    return build_tasks(drafting.out.drafts, drafting.out.units, b, text)


def test_two_phrases_for_one_type_one_of_them_its_name_are_two_types() -> None:
    # FloorPlan419's types: "towel" alone is the HandTowel, but beside "the hand towel" it is another thing
    # of the scene (a Towel only hangs on its holder in ALFRED, so on a table it is the Cloth)
    types = {"HandTowel", "Towel", "Cloth", "SideTable", "SoapBar", "SoapBottle", "ToiletPaper"}
    got = _scene_tasks("put the towel and the hand towel on the side table", types)
    assert sorted((s.object[0], s.count) for s in got.specs) == [("Cloth", 1), ("HandTowel", 1)]
    got = _scene_tasks("put the soap and the soap bar on the side table", types)
    assert sorted(s.object[0] for s in got.specs) == ["SoapBar", "SoapBottle"]
    # two phrases of which neither names the type stay two of one type
    (spec,) = _scene_tasks("put an empty roll and a full roll of toilet paper on the side table", types).specs
    assert (spec.object, spec.count) == (["ToiletPaper"], 2)
