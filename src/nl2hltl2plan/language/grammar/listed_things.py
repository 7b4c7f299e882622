"""Two things one clause lists: a container and its content that go together ("the spoon in the bowl and
the bowl in the fridge", "a bowl and a pencil on the desk"), two of one type ("an empty roll and a full
roll of toilet paper"), or two types that one word names ("the towel and the hand towel")."""

from __future__ import annotations

import re
from dataclasses import replace

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.draft_tasks import Draft, TaskBuilder, Unit
from nl2hltl2plan.language.grammar.frames import Item, dest_of, is_fixed, same
from nl2hltl2plan.language.grammar.phrases import NP
from nl2hltl2plan.language.grammar.sentences import Sentence
from nl2hltl2plan.language.grounding import RECEPTACLES, Grounder, camel_words


def named_apart(x: NP, y: NP, g: Grounder) -> bool:
    """ "the towel and the hand towel" where the scene has a HandTowel and a Towel: two phrases that ground
    to one type, one of them that type's name, are two objects of two types, not two of one, when the other
    phrase can stand for another type of the scene. The phrase naming the type keeps it; the other takes its
    next type in the scene (the entries are narrowed in place)."""
    assert x.entry is not None and y.entry is not None
    first = g.resolve(x.entry)
    name = camel_words(first[0]).split() if len(first) == 1 else []
    naming = [np for np in (x, y) if name and _has_words(np.text.lower().split(), name)]
    if len(naming) != 1:
        return False
    other = y if naming[0] is x else x
    assert other.entry is not None and naming[0].entry is not None
    rest = tuple(t for t in g.candidates(other.entry) if t != first[0])
    if not rest:
        return False
    naming[0].entry = replace(naming[0].entry, types=(first[0],), all_=False)
    other.entry = replace(other.entry, types=rest, all_=False)
    return True


def name_apart_across(drafts: list[Draft], g: Grounder | None) -> None:
    """`named_apart` across the tasks of an instruction, where one phrase is a compound of the other's
    head ("put the towel on the towel holder and the hand towel on the hand towel holder": a Towel and a
    HandTowel, as "the towel and the hand towel" in one clause). Two names of one type ("a clean rag",
    "a cleaned cloth") are two things of that type."""
    objs = [o for d in drafts if not d.tool and (o := d.obj) is not None and o.entry is not None]
    if g is None:
        return
    for k, x in enumerate(objs):
        for y in objs[k + 1 :]:
            assert x.entry is not None and y.entry is not None
            xs, ys = x.text.lower().split(), y.text.lower().split()
            compound = xs != ys and (xs[-1:] == ys[-1:]) and (set(xs) < set(ys) or set(ys) < set(xs))
            first = g.resolve(x.entry)
            if compound and len(first) == 1 and g.resolve(y.entry) == first and named_apart(x, y, g):
                break


def _has_words(words: list[str], sub: list[str]) -> bool:
    return any(words[k : k + len(sub)] == sub for k in range(len(words) - len(sub) + 1))


def merge_items(items: list[Item], b: TaskBuilder) -> list[Item]:
    """Two objects that one clause lists for one destination: a container and its content ("a bowl and a
    pencil"), or two objects of the same type ("an empty roll and a full roll of toilet paper")."""
    # a fixed place listed as a thing is left out; a phrase is such a place by its first type only: "bars
    # of soap" ("bar": SoapBar first, a towel bar after) is the soap, never dropped from "two bars of soap
    # in the bin and the cloth in the cabinet"
    items = [
        it
        for it in items
        if not (
            it.obj is not None
            and it.obj.entry is not None
            and it.obj.entry.canonical in RECEPTACLES
            and not it.obj.is_movable_receptacle()
            and len(items) > 1
        )
    ] or items
    if len(items) == 2 and _head_left_out(items[0].obj, items[1].obj):
        # "an empty and a full toilet paper": the first thing's noun is the second's, said once
        assert items[0].obj is not None and items[1].obj is not None
        items[0].obj = replace(items[1].obj, text=items[0].obj.text, states=set())
    if len(items) != 2 or any(it.obj is None or it.obj.pronoun or it.obj.entry is None for it in items):
        return items
    x, y = items
    xo, yo = x.obj, y.obj
    assert xo is not None and yo is not None and xo.entry is not None and yo.entry is not None
    dests = [(p, np) for p, np in y.pps if p in G.DEST_PREPS]
    # "the mug in the sink and the egg in the fridge": each goes its own way; a place said once for both
    # with where it is ("the empty roll and the full one in the cabinet under the counter") is one way
    xd, yd = dest_of(x), dest_of(y)
    if xd is not None and yd is not None and is_fixed(xd) and is_fixed(yd) and not same(xd, yd):
        return items
    own = [np for p, np in x.pps if p in G.DEST_PREPS and is_fixed(np)]
    if xd is not yd and own and any(is_fixed(np) and not same(np, own[-1]) for _, np in dests):
        return items  # each its own place phrases, the last ones differing: two tasks, as before
    if b.g is not None and set(b.g.resolve(xo.entry)) == set(b.g.resolve(yo.entry)) and b.g.resolve(xo.entry):
        if xo.count != 1 or yo.count != 1 or _holds(x) or _holds(y):
            # "a bar of soap ... and two soap ...": three things, never one pair; "a cup with a knife in it
            # and another cup with a spoon in it": each container holds its own thing (h212)
            return items
        if named_apart(xo, yo, b.g):
            return items
        xo.count = 2
        return [Item(obj=xo, pps=dests or x.pps)]
    # "two boxes and two candles": a list, as a container holds one thing here (h293)
    if xo.is_movable_receptacle() != yo.is_movable_receptacle() and xo.count == yo.count == 1:
        cont, content = (xo, yo) if xo.is_movable_receptacle() else (yo, xo)
        assert cont.entry is not None and content.entry is not None
        # "the pan and the knife": the knife in the pan; "the mug and the apple": two things (a mug holds
        # no apple)
        if b.g is None or b.can_hold(b.g.resolve(cont.entry), b.g.resolve(content.entry), content.sliced):
            sources = [(p, np) for p, np in y.pps if p == "from"]  # where both are: not where they go
            if (where := _where_both_go(x, y, cont)) is None:
                return items
            return [Item(obj=content, pps=[("containing", cont), *sources, *where])]
    return items


def _head_left_out(x: NP | None, y: NP | None) -> bool:
    """Is `x` a determiner and a word of how a thing is, with no noun ("an empty", "one full"), before a
    thing `y` of the scene with no treatment of its own? (A treatment word, "a clean and a dirty mug", is
    not read as one pair, nor "a slice", a part of a thing named elsewhere.)"""
    return (
        x is not None
        and y is not None
        and x.empty
        and not x.states
        and not x.sliced
        and len(x.text.split()) > 1
        and y.entry is not None
        and not y.states
        and not y.pronoun
    )


def _where_both_go(x: Item, y: Item, cont: NP) -> list[tuple[str, NP]] | None:
    """Where a container and its content, listed in one clause, go together: the one destination said
    ("a bowl and a pencil on the desk"), or the container's own when the content's is the container
    ("the plate on the counter and the fork on the plate", "the fork on the plate and the plate on the
    counter"); None when each has a destination of its own ("the fork in the bowl and the plate on the
    counter": two tasks, never the one content put in the other's place)."""
    xd = [(p, np) for p, np in x.pps if p in G.DEST_PREPS]
    yd = [(p, np) for p, np in y.pps if p in G.DEST_PREPS]
    if not xd or not yd or all(any(a is b or same(a, b) for _, b in yd) for _, a in xd):
        return yd  # one destination said (for both)
    if x.obj is cont and all(same(np, cont) for _, np in yd):
        return xd
    if y.obj is cont and all(same(np, cont) for _, np in xd):
        return yd
    return None


def _holds(it: Item) -> bool:
    """Does the item say what its container holds ("a cup with a knife in it")?"""
    return any(p in G.WITH_PREPS and np.entry is not None for p, np in it.pps)


def split_last_own_place(sentence: Sentence, unit: Unit, drafts: list[Draft]) -> Unit | None:
    """ "put the mug in the sink, and the egg in the fridge afterwards": a closing sequence word of a
    one-clause list whose last thing has a place of its own orders that thing after the ones before it, as
    "A, and put B afterwards" does. The last task leaves `unit` as a unit of its own (returned); a list that
    shares its place ("the knife and the fork in the drawer afterwards") stays whole (None)."""
    kinds = {k for k, _ in sentence.trailing}
    if len(unit.tasks) < 2 or G.THEN not in kinds or G.FREE in kinds:  # not "in any order, afterwards"
        return None
    fr, last = drafts[unit.tasks[-1]].frames[-1]
    place = dest_of(last, fr.cls)
    before = [dest_of(it, f.cls) for t in unit.tasks[:-1] for f, it in drafts[t].frames]
    if place is None or any(p is place or same(p, place) for p in before):
        return None
    rest = Unit(tasks=[unit.tasks[-1]], sentence=unit.sentence, joiner="and")
    unit.tasks = unit.tasks[:-1]
    return rest


# "the first one", "the second one": one thing of a list said before, picked by its place in the list
_ORDINAL_ONE = re.compile(r"^(?:the\s+)?(?:first|second|third)\s+one$", re.I)


def ordinal_of_a_list(it: Item, drafts: list[Draft], mine: list[int], b: TaskBuilder, text: str) -> bool:
    """ "heat the potato and the egg ... and put the first one on the counter": an ordinal that picks one
    thing of a list (or of a count: "two mugs") said before in the sentence. The reader continued the last
    thing said (the egg), which drops the ordinal (a wrong reading at exit 0); it is refused by name."""
    if it.obj is None or not _ORDINAL_ONE.match(" ".join(it.obj.text.split())):
        return False
    last = drafts[mine[-1]].obj if mine else None
    counted = last is not None and last.count >= 2  # "two mugs"
    if len([k for k in mine if drafts[k].group >= 0]) < 2 and not counted:
        return False
    b.unparsed.append(f"{text} ({it.obj.text!r}: which of the things listed? name it)")
    return True
