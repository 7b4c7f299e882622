"""A pronoun with two candidates: "put a watch in the box, then put it on the sofa" may move the watch or the
box with the watch in it, two different tasks; "get the egg from the fridge and put it in the pan, then
return it" may return the egg or the pan. The words are named (check 1, `accounting.account`) where
English does not decide between them (`it_of_two`).

>>> from nl2hltl2plan.language.grounding import find_mentions
>>> text = "put a watch in the box, then put it on the sofa"
>>> [(u.words, u.reason) for u in it_of_two(text, find_mentions(text))]
[('put it', "'it' may be the watch or the box: name the one you mean")]
>>> text = "put the pencils in the mug, then put it on the desk"
>>> it_of_two(text, find_mentions(text))
[]
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from nl2hltl2plan.language.content_words import Unread, categories
from nl2hltl2plan.language.grounding import MOVABLE_RECEPTACLES, Mention, find_mentions
from nl2hltl2plan.language.prepositions import a_source
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def it_of_two(
    instruction: str, mentions: list[Mention], tasks: Sequence[BaseTaskSpec] = ()
) -> list[Unread]:
    """ "Put a watch in the box, then put it on the sofa": "it" may be the watch or the box that holds it
    (two different tasks), so a verb that moves "it" right after a thing is put into a movable receptacle is
    named. English decides, and nothing is named, where "it" can stand for one of them only: another thing
    named between ("..., pick up the box and put it on the sofa"), a plural thing or holder ("the pencils in
    the mug, then put it on the desk": the mug), a thing taken, not put ("take the watch in the box and put
    it ...": the watch), or the clause of "it" naming one of them ("put it on the sofa with the watch").
    Nor where `tasks` (the reading) hold ALFRED's movable-container task that both readings come to: "put a
    pen in a mug and set it on the table" puts the pen on the table either way, the mug holding it
    (pick_and_place_with_movable_recep); "return it" or "pick it up" still differ."""
    lowered, out = instruction.lower(), []
    for verb in _VERB_IT.finditer(lowered):
        two = _just_put_in(lowered, [x for x in mentions if x.char_end <= verb.start(2)])
        if two is None or "verb_any" not in categories(verb.group(1)):
            continue
        thing, holder = two
        clause = _CLAUSE_END.split(lowered[verb.end() :], maxsplit=1)[0]
        named = {x.entry.canonical for x in find_mentions(clause)}
        if named & {thing.entry.canonical, holder.entry.canonical}:
            continue
        if _carried_in_holder(thing, holder, clause, tasks) and _holders_read(holder, mentions, tasks):
            continue
        why = f"'it' may be the {thing.surface} or the {holder.surface}: name the one you mean"
        out.append(Unread(verb.group(0), "object", why))
    return out


def _carried_in_holder(thing: Mention, holder: Mention, clause: str, tasks: Sequence[BaseTaskSpec]) -> bool:
    """Is "it" moved on to a place its clause names ("set it on the dining table", "move it from the
    nightstand to the desk"), and read as the task of the thing in the holder at that place?"""
    if _BACK.search(clause):  # "put it back": back where the thing, or the holder, was
        return False
    places = {t for x in find_mentions(clause) for t in x.entry.types}
    return any(
        t.kind == "place_in_container"
        and set(t.object) & set(thing.entry.types)
        and set(t.container or ()) & set(holder.entry.types)
        and set(t.receptacle or ()) & places
        for t in tasks
    )


def _holders_read(holder: Mention, mentions: list[Mention], tasks: Sequence[BaseTaskSpec]) -> bool:
    """Does every mention of the holder's kind have a task slot of its own ("put two boxes on the table, then
    put the keys in a box and put it on the dresser": two mentions, and a reading with one box task has
    merged them, which the question about "it" must not hide)?"""
    kinds = set(holder.entry.types)
    said = sum(1 for x in mentions if x.entry.canonical == holder.entry.canonical)
    roles = ("object", "container", "receptacle")
    slots = sum(bool(set(getattr(t, role) or ()) & kinds) for t in tasks for role in roles)
    return said <= slots


def _just_put_in(lowered: str, before: list[Mention]) -> tuple[Mention, Mention] | None:
    """(the thing, the movable receptacle) where the last thing named in `before` is a receptacle that one
    thing was just put into ("put a watch in the box"; "put it in the pan": the "it" before, the last thing
    named that is no source); None otherwise."""
    holder = before[-1] if before else None
    if holder is None or holder.plural or holder.entry.canonical not in MOVABLE_RECEPTACLES:
        return None
    into = _INTO.search(lowered[: holder.char_start])
    if into is None:
        return None
    if (it := _VERB_BEFORE_IT.search(lowered[: into.start()])) is not None:
        earlier = [x for x in before[:-1] if not a_source(lowered, x.char_start)]
        thing, verb = (earlier[-1] if earlier else None), it.group(1)
    else:
        thing = next((x for x in before[:-1] if x.char_end == into.start()), None)
        said = _VERB_BEFORE.search(lowered[: thing.char_start]) if thing is not None else None
        verb = said.group(1) if said is not None else ""
    # "take the watch in the box": the box is where the watch is, and "it" is the watch in hand
    placing = "verb_any" in categories(verb) and "verb_take" not in categories(verb)
    if thing is None or not placing or thing.plural or set(thing.entry.types) & set(holder.entry.types):
        return None
    return thing, holder


# a verb and the "it" it moves ("put it on the sofa", "return it", "pick it up")
_VERB_IT = re.compile(r"\b([a-z]+)\s+(it)\b(?!')")
# a thing put into a holder: "... in the box", "... into a pan" (the text before the holder's name ends so)
_INTO = re.compile(r"\s+(?:in|into|inside|on|onto)\s+(?:the|a|an|your|my|that|this)\s+$")
# the placing of the thing: "put it", "put a watch", "put the small watch" (the text before "in the box",
# before the thing's name)
_VERB_BEFORE_IT = re.compile(r"\b([a-z]+)\s+it$")
_VERB_BEFORE = re.compile(r"\b([a-z]+)\s+(?:(?:the|a|an|your|my|that|this|one)\s+)?(?:[a-z]+\s+)?$")
_BACK = re.compile(r"\b(?:back|again)\b")
_CLAUSE_END = re.compile(r"[.;!?,]|\b(?:and|then)\b")
