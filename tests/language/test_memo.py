"""The memo of a reading's pure judgements (`language.memo`): one answer per value of the arguments."""

from __future__ import annotations

from collections import Counter

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import find_mentions, tokens
from nl2hltl2plan.language.memo import reading_memo
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def _counted() -> tuple[list[tuple], object]:
    calls: list[tuple] = []

    @reading_memo
    def judged(text: str, tasks: list[BaseTaskSpec], before: object = ()) -> list[str]:
        calls.append((text, before))
        return [text, *(t.kind for t in tasks), repr(before)]

    return calls, judged


def test_an_answer_is_computed_once_per_value_and_handed_out_as_a_fresh_list() -> None:
    calls, judged = _counted()
    cup = BaseTaskSpec(kind="heat_place", object=["Cup"], receptacle=["Microwave"])
    first = judged("heat the cup", [cup])
    first.append("changed by the caller")
    again = judged("heat the cup", [cup.model_copy()])  # an equal task, another object
    assert again == ["heat the cup", "heat_place", "()"] and len(calls) == 1


def test_values_that_differ_in_a_field_or_a_type_get_answers_of_their_own() -> None:
    calls, judged = _counted()
    cup = BaseTaskSpec(kind="heat_place", object=["Cup"], receptacle=["Microwave"])
    judged("heat the cup", [cup])
    judged("heat the cup", [cup.model_copy(update={"count": 2})])
    assert judged("heat the cup", [cup], [("A", "B")])[-1] == "[('A', 'B')]"
    assert judged("heat the cup", [cup], [["A", "B"]])[-1] == "[['A', 'B']]"  # a list of lists is not tuples
    assert len(calls) == 4


def test_an_argument_without_a_value_key_is_computed_every_time() -> None:
    calls, judged = _counted()
    judged("x", [], before=object())
    judged("x", [], before=object())
    assert len(calls) == 2


def test_check_1_answers_alike_asked_again_with_the_scene_or_without() -> None:
    mug = BaseTaskSpec(id="A", kind="place", object=["Mug"], receptacle=["SinkBasin"])
    text = "put the mug in the sink and the apple in the fridge"
    bare = [str(u) for u in account(text, [mug], [])]
    counted = [str(u) for u in account(text, [mug], [], Counter({"Mug": 1, "Apple": 1}), "FloorPlan1")]
    assert bare == [str(u) for u in account(text, [mug], [])] and any("apple" in u for u in bare)
    assert counted == bare


def test_the_tokens_and_mentions_of_a_text_are_fresh_lists() -> None:
    text = "put the two forks in the drawer"
    got = tokens(text)
    got.clear()
    named = find_mentions(text)
    named.pop()
    assert [w for w, _, _ in tokens(text)][:3] == ["put", "the", "two"]
    assert [m.entry.phrase for m in find_mentions(text)] == ["fork", "drawer"]
