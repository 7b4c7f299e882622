"""Text-faithful labels, the 1-4 task synthesis, the segmentation rescue and the default combination rule."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from nl2hltl2plan.language.grammar import parse_instruction as grammar_parse
from nl2hltl2plan.language.learned import parse_instruction
from nl2hltl2plan.language.learned.data import Example
from nl2hltl2plan.language.learned.faithful import (
    FaithfulExample,
    compose_faithful,
    text_task,
    training_example,
)
from nl2hltl2plan.language.learned.inference import Policy, load_model
from nl2hltl2plan.language.learned.rescue import canonical, rewrite
from nl2hltl2plan.language.translate import apply_choices, top_candidates

ROOM = {"Apple", "Fridge", "CounterTop", "DiningTable", "SideTable", "Mug", "Cabinet", "Toilet", "SoapBar"}
ROOM |= {"SinkBasin", "Knife", "ButterKnife", "Tomato", "Microwave", "Bowl", "Spoon", "DeskLamp", "KeyChain"}


def _ex(
    text: str, kind: str = "place", obj: str = "Apple", recep: str = "SideTable", **kw: object
) -> Example:
    fields = {"container": "", "light": "", "sliced": False, "trial": "t", "floor_plan": "FloorPlan1"}
    fields.update(kw)
    return Example(
        text,
        str(fields["trial"]),
        "valid_seen",
        str(fields["floor_plan"]),
        kind,
        obj,
        str(fields["container"]),
        recep,
        str(fields["light"]),
        bool(fields["sliced"]),
    )


def test_text_wins_over_alfred_labels() -> None:
    # "table": every table of the room, not ALFRED's SideTable
    t = text_task(_ex("Put the apple on the table."), ROOM)
    assert t is not None and t.receptacle == ["DiningTable", "SideTable"] and not t.sliced
    # sliced only when the text says so
    assert text_task(_ex("Put the apple on the table.", sliced=True), ROOM).sliced is False  # type: ignore[union-attr]
    assert text_task(_ex("Put an apple slice on the table.", sliced=True), ROOM).sliced is True  # type: ignore[union-attr]
    # an unstated treatment or count: unclear, left out
    assert text_task(_ex("Put the apple on the table.", kind="cool_place"), ROOM) is None
    assert text_task(_ex("Put apples on the table.", kind="place_two"), ROOM) is None
    # an unsaid slot keeps the hint only when the text names nothing else that could be meant
    hint = text_task(_ex("Put the apple away.", recep="Cabinet"), ROOM)
    assert hint is not None and hint.receptacle == ["Cabinet"]
    assert text_task(_ex("Put the apple by the mug.", recep="Cabinet"), ROOM) is None
    # knife: both knife types present; the training label leaves a multi-type slot unlabelled
    k = text_task(_ex("Put the knife in the cabinet.", obj="Knife", recep="Cabinet"), ROOM)
    assert k is not None and k.object == ["Knife", "ButterKnife"]
    assert training_example(FaithfulExample(_ex("x", obj="Knife"), k)).object == ""


def _items() -> list[FaithfulExample]:
    out = []
    for i, (obj, rec) in enumerate([("Apple", "Fridge"), ("Mug", "Cabinet"), ("Tomato", "CounterTop")] * 2):
        e = _ex(f"Put the {obj.lower()} in the {rec.lower()}.", obj=obj, recep=rec, trial=f"t{i}")
        t = text_task(e, ROOM)
        assert t is not None
        out.append(FaithfulExample(e, t))
    return out


def test_synthesis_is_deterministic_with_one_to_four_tasks() -> None:
    items = _items()
    a, b = compose_faithful(items, 40, seed=1), compose_faithful(items, 40, seed=1)
    assert [(c.instruction, c.before) for c in a] == [(c.instruction, c.before) for c in b]
    assert [c.instruction for c in compose_faithful(items, 40, seed=2)] != [c.instruction for c in a]
    assert sorted({len(c.tasks) for c in a}) == [1, 2, 3, 4]
    for c in a:
        assert len({t for t in c.trials}) == len(c.tasks)  # never one trial twice
        assert all(t.text.lower() in c.instruction.lower() for t in c.tasks)
        if c.template == "First {0}, then {1}.":
            assert c.before == [("A", "B")]
        if "in any order" in c.template and len(c.tasks) == 2:
            assert c.before == []


def test_a_misspelt_object_is_read_but_none_is_invented() -> None:
    room = ROOM | {"Ladle"}
    text = "Put the mug in the cabinet. Meanwhile, rinse off a laddle and move it to the table."
    g = grammar_parse(text, room, "t")  # the grammar reads the misspelt name itself (language/spelling.py)
    assert [t.object for t in g.tasks] == [["Mug"], ["Ladle"]] and g.unparsed == []
    r = parse_instruction(text, room, "t")
    r = apply_choices(r, top_candidates(r.ambiguities))  # "the table": the top-ranked one
    assert [t.summary() for t in r.tasks] == ["place Mug -> Cabinet", "clean_place Ladle -> DiningTable"]
    # two letters off is not a spelling of "ladle": nothing is read into it
    r = parse_instruction("Put the mug in the cabinet. Then rinse a lapdog.", room, "t")
    assert [t.object for t in r.tasks] == [["Mug"]]
    # a destination the clause does not state is not guessed, though another clause names a place
    living = {"CellPhone", "KeyChain", "Sofa", "ArmChair", "CoffeeTable", "SideTable", "Drawer"}
    r = parse_instruction("Gather the cell phones. Then put the keychain on the couch.", living, "t")
    assert [t.object for t in r.tasks] == [["KeyChain"]] and any("cell phones" in u for u in r.unparsed)


@pytest.mark.parametrize(
    "clause",
    [
        "heat a slice of tomato and put it on the counter",
        "put a bowl with a spoon in it in the fridge",
        "examine the keys under the desk lamp",
        "put two mugs in the cabinet",
    ],
)
def test_canonical_sentences_read_back_as_the_predicted_task(clause: str) -> None:
    pred = load_model().predict([clause], ROOM)[0]
    sentence = canonical(pred)
    assert sentence is not None
    (task,) = grammar_parse(sentence, ROOM, "t").tasks
    assert task.kind == pred.top_kind and task.object == [pred.slots["object"][0][0]]


def test_grammar_reads_after_you_and_do_not_until() -> None:
    for text in (
        "After you put the mug in the cabinet, put the apple in the fridge.",
        "Put the apple in the fridge after you put the mug in the cabinet.",
        "Do not put the apple in the fridge until you put the mug in the cabinet.",
        "Once done with the task to put the mug in the cabinet, put the apple in the fridge.",
        "Once you are done putting the mug in the cabinet, put the apple in the fridge.",
        "Put the mug in the cabinet. When you are done with that, put the apple in the fridge.",
        "Put the mug in the cabinet. Once done, put the apple in the fridge.",
    ):
        r = grammar_parse(text, ROOM, "t")
        by_obj = {t.object[0]: t.id for t in r.tasks}
        assert r.before == [(by_obj["Mug"], by_obj["Apple"])], text


def test_finally_follows_the_guide_in_the_validation_templates() -> None:
    """ANNOTATION_GUIDE.md: "Finally Y" comes after every earlier task not allowed "in any order"."""
    from nl2hltl2plan.language.learned.faithful import TEMPLATES

    for text, pairs in (t for ts in TEMPLATES.values() for t in ts):
        if "in any order. Finally" in text:
            k = text.count("{") - 1  # the last clause, Y
            grouped = {int(c) for c in re.findall(r"\{(\d)\}", text.split("in any order")[0].split(". ")[-1])}
            assert all((a, k) not in pairs for a in grouped), text


# the default run checks 40 composed rows, `sweep` the 120 it checked before (docs/reliability.md, rule 3)
@pytest.mark.parametrize("rows", [40, pytest.param(120, marks=pytest.mark.sweep)])
def test_default_never_overrides_what_the_grammar_read(shared_data: Path, rows: int) -> None:
    """The chosen rule: the model orders multi-type words and fills empty slots, nothing else."""
    from nl2hltl2plan.suites.alfred.learned_validation import validation_rows

    assert Policy().kind_override > 1 and Policy().override > 1 and not Policy().sliced_from_model
    no_rescue = Policy(rescue=False)
    for row in validation_rows("valid_seen", rows, seed=5):
        from nl2hltl2plan.language.grounding import scene_types

        types = scene_types(row["scene"])
        g = grammar_parse(row["instruction"], types, row["scene"])
        r = parse_instruction(row["instruction"], types, row["scene"], strict=False, policy=no_rescue)
        if not g.tasks:
            continue  # nothing the grammar read: the model may read the whole text as one task
        # a task whose unstated slot the model is unsure of is dropped and its clause named (issue 23)
        kept = {t.id for t in r.tasks}
        dropped = [t for t in g.tasks if t.id not in kept]
        assert len(dropped) == sum("below the" in u for u in r.unparsed)
        assert r.before == [p for p in g.before if set(p) <= kept]
        for a, b in zip([t for t in g.tasks if t.id in kept], r.tasks, strict=True):
            assert (a.kind, a.sliced, a.count) == (b.kind, b.sliced, b.count)
            for role in ("object", "receptacle", "container", "light"):
                mine = [t for t in getattr(a, role) or [] if t in types]
                if mine:
                    assert sorted(getattr(b, role) or []) == sorted(mine), (row["instruction"], role)


def test_slot_model_beats_the_majority_baseline_on_held_out_scenes(shared_data: Path) -> None:
    """valid_unseen (scenes never trained on), text-faithful labels: the model's top scene type vs the
    most frequent training type present in the scene."""
    from collections import Counter

    from nl2hltl2plan.language.grounding import scene_types
    from nl2hltl2plan.suites.alfred.learned_validation import faithful_split

    items = faithful_split("valid_unseen")[::4]
    prior = Counter(it.task.object[0] for it in faithful_split("valid_seen"))
    model = load_model()
    hits = {"model": 0, "majority": 0, "kind": 0}
    for it in items:
        types = scene_types(it.example.floor_plan)
        pred = model.predict([it.text], types)[0]
        hits["model"] += pred.slots["object"][0][0] in it.task.object
        hits["kind"] += pred.top_kind == it.task.kind
        majority = max((t for t in types if t in prior), key=lambda t: prior[t])
        hits["majority"] += majority in it.task.object
    n = len(items)
    assert n > 100
    assert hits["model"] / n >= 0.85 and hits["kind"] / n >= 0.85, hits
    assert hits["majority"] / n <= 0.3, hits


def _five_placements() -> list[FaithfulExample]:
    """Five one-placement examples of different objects, the material of the reference compositions."""
    pairs = [("Apple", "Fridge"), ("Mug", "Cabinet"), ("Tomato", "CounterTop"), ("SoapBar", "Toilet")]
    items = []
    for i, (obj, rec) in enumerate(pairs + [("Bowl", "Microwave")]):
        e = _ex(f"Put the {obj.lower()} in the {rec.lower()}.", obj=obj, recep=rec, trial=f"t{i}")
        items.append(FaithfulExample(e, text_task(e, ROOM)))  # type: ignore[arg-type]
    return items


def test_reference_compositions_order_by_the_task_they_name() -> None:
    from nl2hltl2plan.language.learned.compose_refs import DEV_REFS, HELDOUT_REFS, compose_refs

    items = _five_placements()
    a = compose_refs(items, 60, DEV_REFS, seed=3)
    assert [c.instruction for c in a] == [c.instruction for c in compose_refs(items, 60, DEV_REFS, seed=3)]
    assert sorted({len(c.tasks) for c in a}) == [1, 2, 3, 4, 5]
    named = 0
    for c in a:
        assert len(set(c.trials)) == len(c.tasks)
        for m in re.finditer(r"After putting the (\w+), (\w+) the (\w+)", c.instruction):
            first = next(t.id for t in c.tasks if m.group(1) in t.text)
            then = next(t.id for t in c.tasks if f"{m.group(2)} the {m.group(3)}" in t.text)
            named += 1
            assert (first, then) in c.before
    assert named
    more = compose_refs(items, 300, DEV_REFS, seed=3)
    free = [c for c in more if re.fullmatch(r"[^.]+ at any time\. Put [^.]+\.", c.instruction)]
    assert free and all(c.before == [] for c in free)  # a free task, then a sentence with no temporal word
    b = compose_refs(items, 60, HELDOUT_REFS, seed=3)
    assert not {c.instruction for c in b if len(c.tasks) > 1} & {c.instruction for c in a}  # other phrases


def test_the_new_family_names_a_task_to_come_before_and_frees_only_by_its_phrase() -> None:
    from nl2hltl2plan.language.learned.compose_refs import NEW_REFS, compose_refs

    items = _five_placements()
    prior = sorted_ = 0
    for c in compose_refs(items, 300, NEW_REFS, seed=4):
        for m in re.finditer(r"Prior to putting the (\w+), put the (\w+)", c.instruction):
            earlier = next(t.id for t in c.tasks if f"put the {m.group(1)}" in t.text)
            new = next(t.id for t in c.tasks if f"put the {m.group(2)}" in t.text)
            prior += 1
            assert (new, earlier) in c.before  # the new task comes before the one named earlier
        for m in re.finditer(r"Whenever the (\w+) is sorted, put the (\w+)", c.instruction):
            named = next(t.id for t in c.tasks if f"put the {m.group(1)}" in t.text)
            new = next(t.id for t in c.tasks if f"put the {m.group(2)}" in t.text)
            sorted_ += 1
            assert (named, new) in c.before  # "whenever" here names a task: not free
    assert prior and sorted_


def test_the_rescue_never_reads_a_statement_of_where_a_thing_is_as_a_request():
    model = load_model()
    for clause in (
        "the knife is on the counter",
        "the tomato is in the microwave",
        "the keys are on the side table",
    ):
        assert rewrite(f"Put the apple in the fridge. {clause}.", [clause], model, ROOM) is None
    # near miss: a clause the grammar could not read that does ask for something is rewritten, never to
    # the place it names as a source (the model's receptacle is a near coin flip between the two here;
    # tests/language/test_faithful_unsaid.py holds both outcomes)
    clause = "move the mug from the counter to the sink"
    again = rewrite(f"Put the apple in the fridge. {clause}", [clause], model, ROOM)
    assert again in (None, "Put the apple in the fridge. put the mug in the sink basin")
