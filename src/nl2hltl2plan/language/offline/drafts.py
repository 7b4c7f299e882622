"""Step 4a, drafts: frames -> task drafts (consecutive clauses about one object) and temporal units."""

from __future__ import annotations

from dataclasses import dataclass, field

from nl2hltl2plan.language.offline import grammar as G
from nl2hltl2plan.language.offline.frames import Frame, Item, dest_of, same
from nl2hltl2plan.language.offline.tasks import Draft, TaskBuilder


@dataclass
class Unit:
    """The tasks of one clause (or one sentence part) and the temporal markers that apply to them."""

    tasks: list[int]
    sentence: int
    markers: list[tuple[str, str]] = field(default_factory=list)  # (kind, ref text)
    seq_after_prev: bool = False  # joined to the previous clause by "then" inside a sentence
    before_sentence: int = -1  # index of the last unit before this unit's sentence (-1: none)


# ----- text helpers ----------------------------------------------------------------------------------
def item_text(fr: Frame, it: Item) -> str:
    """Own text of one item of a list clause: verb + object + its destination ("put plates into the rack")."""
    verb = fr.text.split()[0] if fr.text.split() else ""
    parts = [verb, it.obj.text if it.obj is not None else ""]
    parts += [f"{p} {np.text}" for p, np in it.pps if p in G.DEST_PREPS and np.text]
    return " ".join(x for x in parts if x)


def joins(d: Draft, fr: Frame, it: Item) -> bool:
    """Does clause item `it` continue task draft `d` (same object, pronoun, no object, container)?"""
    o = it.obj
    last_fr = d.frames[-1][0]
    cur = d.obj
    if fr.joiner == "after" or fr.joiner == "before":
        return False
    if o is None or o.empty:
        if fr.cls == "fill" and dest_of(it, fr.cls) is not None:
            return False  # "fill water in the bathtub": not about the current object
        return fr.cls != "none" or bool(it.pps)
    if o.pronoun:
        return True
    if o.is_lamp() and (fr.cls in {"light", "examine"} or fr.light_on):
        return incomplete(d)  # "pick up the keys and turn on the lamp"; not after a placement
    if cur is None:
        # the draft so far only switched a lamp on: "turn on a lamp while holding a laptop"
        return fr.cls in {"pick", "examine"} or (fr.cls == "place" and last_fr.cls == "light")
    if same(o, cur):
        # "place the yellow block to region I, then place it... to region G": a second placement is a new task
        prev_dest = dest_of(d.frames[-1][1], last_fr.cls)
        if (
            fr.joiner in {"then", "first"}
            and fr.cls == "place"
            and last_fr.cls == "place"
            and prev_dest is not None
            and dest_of(it, fr.cls) is not None
            and (
                prev_dest.entry is None
                or prev_dest.entry.canonical not in {"SinkBasin", "Microwave", "Fridge"}
            )
        ):
            return False
        return True
    if o.sliced and o.entry is None and o.head in {"", "slice", "piece"}:
        return True
    for (
        _,
        it2,
    ) in d.frames:  # the container of the content: "put a spoon in a mug and put the mug on the table"
        dst = dest_of(it2)
        if dst is not None and same(o, dst) and o.is_movable_receptacle():
            return True
        for p, np in it2.pps:
            if p in G.WITH_PREPS and same(o, np):
                return True
    if last_fr.cls in {"slice"} and o.sliced:
        return True
    return False


def incomplete(d: Draft) -> bool:
    """A draft that only picked / changed the state of something: the next clause usually completes it."""
    for fr, it in d.frames:
        if dest_of(it, fr.cls) is not None or fr.cls in {"light", "examine", "trash"} or fr.light_on:
            return False
    return True


def merge_items(items: list[Item], b: TaskBuilder) -> list[Item]:
    """Two objects that one clause lists for one destination: a container and its content ("a bowl and a
    pencil"), or two objects of the same type ("an empty roll and a full roll of toilet paper")."""
    items = [
        it
        for it in items
        if not (
            it.obj is not None
            and it.obj.is_receptacle()
            and not it.obj.is_movable_receptacle()
            and len(items) > 1
        )
    ] or items
    if len(items) != 2 or any(it.obj is None or it.obj.pronoun or it.obj.entry is None for it in items):
        return items
    x, y = items
    assert x.obj is not None and y.obj is not None
    dests = [(p, np) for p, np in y.pps if p in G.DEST_PREPS]
    if (
        b.g is not None
        and set(b.g.resolve(x.obj.entry)) == set(b.g.resolve(y.obj.entry))
        and b.g.resolve(x.obj.entry)
    ):
        x.obj.count = 2
        return [Item(obj=x.obj, pps=dests or x.pps)]
    if x.obj.is_movable_receptacle() != y.obj.is_movable_receptacle():
        cont, content = (x, y) if x.obj.is_movable_receptacle() else (y, x)
        return [Item(obj=content.obj, pps=[("containing", cont.obj), *dests])]
    return items

