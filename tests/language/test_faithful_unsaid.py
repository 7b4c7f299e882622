"""Issue 28: a composed label never names what its text does not. An annotation that leaves a slot unsaid
("turn on the desk lamp" of an examine-a-CD trial) is under-specified: the slot model does not learn that
slot from it and no composed instruction holds it; a place said only as a source is not the destination;
"soap dispenser" labels the SoapBottle (the lexicon)."""

from __future__ import annotations

from dataclasses import replace

from nl2hltl2plan.language.learned.compose import TRAIN_STYLE, Synth, synthesise
from nl2hltl2plan.language.learned.compose_refs import DEV_REFS, compose_refs
from nl2hltl2plan.language.learned.data import Composition, Example
from nl2hltl2plan.language.learned.faithful import (
    FaithfulExample,
    composable,
    compose_faithful,
    text_label,
    text_task,
    training_example,
)
from nl2hltl2plan.language.learned.rescue import rewrite
from nl2hltl2plan.language.learned.slot_model import SlotPrediction

ROOM = {"Apple", "Fridge", "CounterTop", "DiningTable", "CoffeeTable", "Mug", "Cabinet", "Toilet", "SoapBar"}
ROOM |= {"SoapBottle", "SinkBasin", "Microwave", "DeskLamp", "CD", "Shelf", "Tomato", "Bowl", "Lettuce"}


def _ex(text: str, kind: str = "place", obj: str = "Apple", recep: str = "CounterTop", **kw: str) -> Example:
    return Example(
        text, kw.get("trial", "t"), "valid_seen", "FloorPlan1", kind, obj, kw.get("container", ""), recep,
        kw.get("light", ""), False,
    )  # fmt: skip


def test_an_unsaid_slot_makes_the_annotation_under_specified() -> None:
    lamp = text_label(_ex("Turn on the desk lamp.", "examine_in_light", "CD", "", light="DeskLamp"), ROOM)
    assert lamp is not None and lamp[1] == ("object",)
    e = _ex("Turn on the desk lamp.", "examine_in_light", "CD", "", light="DeskLamp")
    item = FaithfulExample(e, lamp[0], lamp[1])
    assert not item.said and not composable([item])
    # the slot model learns the lamp from it, never the CD the text does not name
    trained = training_example(item)
    assert trained.object == "" and trained.light == "DeskLamp"
    # the destination never said ("chill the lettuce") is unsaid too
    chill = text_label(_ex("Chill the lettuce.", "cool_place", "Lettuce", "SinkBasin"), ROOM)
    assert chill is not None and chill[1] == ("receptacle",)
    # near miss: every slot named
    said = text_label(_ex("Put the apple on the counter."), ROOM)
    assert said is not None and said[1] == () and composable([FaithfulExample(_ex("x"), said[0])])


def test_a_place_said_only_as_a_source_is_not_the_destination() -> None:
    # the sink is where the apple comes from: the destination is unsaid (the annotation stays in the pool
    # it was in, so that the other draws do not move, and no composition holds it)
    text = "Get an apple from the sink and heat it up in the microwave."
    heat = text_label(_ex(text, "heat_place", recep="SinkBasin"), ROOM)
    assert heat is not None and heat[1] == ("receptacle",)
    # the destination is the later table, not the one it is taken from
    move = text_task(
        _ex("Move a bowl from the table to the coffee table.", obj="Bowl", recep="CoffeeTable"), ROOM
    )
    assert move is not None and move.receptacle == ["CoffeeTable"]
    out = text_task(_ex("Take the apple out of the fridge and put it on the counter."), ROOM)
    assert out is not None and out.receptacle == ["CounterTop"]
    # near miss: "the second from the bottom shelf" is where the thing goes
    second = _ex("Put the mug on the second from the bottom shelf.", obj="Mug", recep="Shelf")
    shelf = text_label(second, ROOM)
    assert shelf is not None and shelf[0].receptacle == ["Shelf"] and shelf[1] == ()


def test_the_soap_dispenser_labels_the_soap_bottle() -> None:
    t = text_task(_ex("Place a soap dispenser on the toilet.", obj="SoapBottle", recep="Toilet"), ROOM)
    assert t is not None and t.object == ["SoapBottle"]
    # near miss: "soap" alone is the guide's SoapBar
    bar = text_task(_ex("Place the soap on the toilet.", obj="SoapBar", recep="Toilet"), ROOM)
    assert bar is not None and bar.object == ["SoapBar"]


def _items() -> list[FaithfulExample]:
    """Seven placements of different objects; the lettuce's is the one a test marks under-specified."""
    out = []
    pairs = [("Apple", "Fridge"), ("Mug", "Cabinet"), ("Tomato", "CounterTop"), ("Bowl", "Microwave")]
    pairs += [("Lettuce", "Fridge"), ("SoapBar", "Toilet"), ("CD", "Shelf")]
    for i, (obj, rec) in enumerate(pairs):
        e = _ex(f"Put the {obj.lower()} in the {rec.lower()}.", obj=obj, recep=rec, trial=f"t{i}")
        t = text_task(e, ROOM)
        assert t is not None
        out.append(FaithfulExample(e, t))
    return out


def _text(c: Composition | Synth) -> str:
    return c.instruction if isinstance(c, Composition) else c.text


def test_a_composition_holding_an_under_specified_annotation_is_left_out_and_the_others_kept() -> None:
    items = _items()
    marked = [replace(it, unsaid=("receptacle",)) if it.task.object == ["Lettuce"] else it for it in items]
    made = {
        "faithful": (compose_faithful(items, 60, seed=5), compose_faithful(marked, 60, seed=5)),
        "refs": (compose_refs(items, 60, DEV_REFS, seed=5), compose_refs(marked, 60, DEV_REFS, seed=5)),
        "synth": (synthesise(items, 60, TRAIN_STYLE, seed=5), synthesise(marked, 60, TRAIN_STYLE, seed=5)),
    }
    for name, (every, kept) in made.items():
        without = [c for c in every if all(t.object != ["Lettuce"] for t in c.tasks)]
        # the same draws: exactly the rows that do not hold the marked annotation, in the same order
        assert len(every) == 60 and 0 < len(kept) < 60, name
        assert [_text(c) for c in kept] == [_text(c) for c in without], name
    # the structure model's training keeps them (spans and order, not the unsaid slot)
    every = made["synth"][0]
    assert [_text(c) for c in synthesise(marked, 60, TRAIN_STYLE, seed=5, said_only=False)] == [
        _text(c) for c in every
    ]


class _Reads:
    """A slot model stand-in that reads every clause as putting the mug in `place` (confidently)."""

    def __init__(self, place: str) -> None:
        self.place = place

    def predict(self, texts: list[str], types: set[str] | None) -> list[SlotPrediction]:
        slots = {"object": [("Mug", 0.9)], "receptacle": [(self.place, 0.6)]}
        return [SlotPrediction([("place", 0.9)], dict(slots)) for _ in texts]


def test_the_rescue_never_takes_a_place_said_as_a_source_for_the_destination() -> None:
    clause = "move the mug from the counter to the sink"
    text = f"Put the apple in the fridge. {clause}"
    assert rewrite(text, [clause], _Reads("CounterTop"), ROOM) is None  # type: ignore[arg-type]
    # near miss: the place it goes to
    again = rewrite(text, [clause], _Reads("SinkBasin"), ROOM)  # type: ignore[arg-type]
    assert again == "Put the apple in the fridge. put the mug in the sink basin"
