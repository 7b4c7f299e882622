"""h288 (issue 23): a count with a choice of places binds the whole count to ONE place, in the spec.

"put two mugs in the sink or the cabinet" gave two leaves, each `pickup & (F put(Mug,Sink) | F put(Mug,
Cabinet))`, so a plan could put one mug in each place. The task's node is now an any-of node over one
node per place (`HTTNode.any_of`, `F task1.1 | F task1.2`), each holding one leaf per object for that
place: the checker rejects a split trace however its events are attributed, and a plan still exists.
"""

from __future__ import annotations

import json

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.logic.trace import TraceEvent, check_trace
from nl2hltl2plan.suites.alfred.conversion import scenario_world

SINK, CABINET = "put(Mug,SinkBasin)", "put(Mug,Cabinet)"


def events(puts: list[tuple[str, str]]) -> list[TraceEvent]:
    """One pickup and one put per (put atom, leaf), in order."""
    out: list[TraceEvent] = []
    for put, leaf in puts:
        out += [TraceEvent(len(out) + 1, "pickup(Mug)", leaf), TraceEvent(len(out) + 2, put, leaf)]
    return out


@pytest.mark.data
def test_a_split_between_the_places_is_rejected_and_one_place_is_accepted():
    res = translate("put two mugs in the sink or the cabinet", scenario_world({"scene": "FloorPlan15"}))
    assert res.spec is not None and not res.unparsed
    (task,) = res.tasks
    assert task.count == 2 and task.receptacle == ["SinkBasin", "Cabinet"]
    assert res.spec.levels[0] == {"task1": "F task1.1 | F task1.2"}
    split_ways = [  # one mug in each place, under every attribution a planner could give
        [(SINK, "task1.1.1"), (CABINET, "task1.2.1")],
        [(SINK, "task1.1.1"), (CABINET, "task1.1.2")],
        [(SINK, "task1.2.1"), (CABINET, "task1.2.2")],
    ]
    for way in split_ways:
        assert not check_trace(res.spec, events(way)).ok, way
    for put, alt in ((SINK, "task1.1"), (CABINET, "task1.2")):
        assert check_trace(res.spec, events([(put, f"{alt}.1"), (put, f"{alt}.2")])).ok


@pytest.mark.data
def test_the_plan_puts_both_in_one_place(capsys):
    text = "put two mugs in the sink or the cabinet"
    code = main(["plan", text, "--world", "FloorPlan15", "--llm", "offline", "--json"])
    out = capsys.readouterr()
    assert code == 0, out.err
    got = json.loads(out.out)
    puts = [s for r in got["plan"]["robots"] for s in r["steps"] if s["verb"] == "put"]
    assert len(puts) == 2
    assert len({s["objects"][1].split("_")[0] for s in puts}) == 1  # one receptacle type for both
    (choice,) = got["place_choices"]
    assert choice["chosen"] in ("SinkBasin", "Cabinet")


@pytest.mark.data
def test_one_object_keeps_the_leaf_disjunction():
    """A single object needs no binding: its leaf stays the recipe's disjunction (h274)."""
    res = translate("put the egg in the fridge or the microwave", scenario_world({"scene": "FloorPlan1"}))
    assert res.spec is not None and len(res.spec.levels) == 1


@pytest.mark.data
def test_a_ban_on_one_of_the_places_is_no_contradiction():
    """A place of the choice is not required, so banning it leaves the other (the checker enforces both)."""
    text = "put two mugs in the sink or the cabinet, but never open the cabinet"
    res = translate(text, scenario_world({"scene": "FloorPlan15"}))
    assert res.spec is not None and res.spec.constraints


@pytest.mark.data
@pytest.mark.parametrize(
    "text, world, tasks",
    [  # a second mention with another everyday name is another thing, even of one type (docs/trust.md)
        ("Put a spoon in the glass and the cup in the sink.", "FloorPlan1",
         ["place Spoon -> Cup", "place Cup -> SinkBasin"]),
        ("put a fork in a cup and put the glass on the counter", "FloorPlan7",
         ["place Fork -> Cup", "place Cup -> CounterTop"]),
        # the same name, or "glass cup" (both at once), is the container said again
        ("Put a spoon in a glass and the glass in the sink.", "FloorPlan1",
         ["place_in_container Spoon in Cup -> SinkBasin"]),
        ("Put a spoon in a glass cup and put the cup in the sink.", "FloorPlan1",
         ["place_in_container Spoon in Cup -> SinkBasin"]),
    ],
)  # fmt: skip
def test_a_glass_and_then_the_cup_are_two_things(text, world, tasks):
    res = translate(text, scenario_world({"scene": world}), build=False)
    assert [t.summary() for t in res.tasks] == tasks and not res.unparsed


def test_a_landmark_builds_no_compound_name_across_its_boundary():
    """ "the table by the coffee machine": "coffee" is the machine's, no evidence for a coffee table."""
    from nl2hltl2plan.language.learned.ranker import TypeRanker

    ranker = TypeRanker({"SideTable|coffee": 2.0, "SideTable|end": 2.0, "logq": 1.0})
    even = [("DiningTable", 0.5), ("SideTable", 0.5)]
    for apart, plain in (
        ("put the mug on the table by the coffee machine", "put the mug on the table by the machine"),
        ("put the book on the table at the end of the bed", "put the book on the table at the of the bed"),
    ):
        assert ranker.order(apart, even) == ranker.order(plain, even)
    # said as one compound, the word is the name's: it still counts
    assert ranker.order("put the mug on the end table or the table", even)[0][0] == "SideTable"
