"""Step 5 of the offline parser: references to earlier tasks."""

from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder
from nl2hltl2plan.language.grammar.phrases import NP, parse_np
from nl2hltl2plan.language.grammar.references import new_tasks_from_ref, ref_targets
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def _spec(obj: str, rec: str) -> BaseTaskSpec:
    return BaseTaskSpec(kind="place", object=[obj], receptacle=[rec], text=f"{obj} {rec}")


SPECS = [_spec("Statue", "Shelf"), _spec("Knife", "Drawer"), _spec("Apple", "Fridge")]
NPS: list[NP | None] = [parse_np("the statue"), parse_np("the knife"), parse_np("the apple")]


def test_a_reference_names_tasks_by_their_objects() -> None:
    assert ref_targets("placing the statue and moving the knife", SPECS, NPS) == ([0, 1], [])


def test_by_destination_and_unresolved_parts() -> None:
    assert ref_targets("putting things in the fridge", SPECS, NPS) == ([2], [])
    assert ref_targets("cleaning the mirror", SPECS, NPS) == ([], ["cleaning the mirror"])


def test_excluded_tasks_are_not_targets() -> None:
    assert ref_targets("placing the statue", SPECS, NPS, exclude=[0]) == ([], ["placing the statue"])


def test_a_reference_that_states_a_task_of_its_own() -> None:
    b = TaskBuilder(None, strict=False)
    (spec,) = new_tasks_from_ref("picking up the box and placing it on the armchair", b, "t")
    assert (spec.object, spec.receptacle) == (["Box"], ["ArmChair"])
    assert b.unparsed == []
