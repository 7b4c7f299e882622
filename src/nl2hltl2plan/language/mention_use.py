"""Check 1 per mention (issue 23): a thing named twice needs a task for each naming, not one per type.

`accounting._nouns` matches the names of an instruction to the slots of its base tasks by type: two
mentions of one type ("the pencil by the lamp ... put a pencil in the cup") fill one slot together, so a
reading that drops one of them passes. Here each mention that names a slot's thing (not where something
is, not a place a treatment implies) is looked for in the words of the tasks that use its type: a
mention that lies in the words of a task that does not use it, and in those of no task that does, is
unread ("look at the box and at the pencil by the lamp": the pencil of the examining task). A mention
said again for the same thing ("put the mug in the sink, then take the mug to the table") lies in the
words of the task that uses it each time, and so does a thing with two roles ("put the pencil in the
bowl, then move the bowl to the shelf"). Where a task's words are not found in the instruction (another
backend, or words the reader rewrote), its mentions are not judged: nothing is flagged on a guess.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from nl2hltl2plan.language.content_words import Unread, categories
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grounding import Mention
from nl2hltl2plan.language.parse_usage import IMPLIED_TYPES, ParseUsage
from nl2hltl2plan.language.task_specs import BaseTaskSpec

Span = tuple[int, int]


def task_spans(instruction: str, tasks: Sequence[BaseTaskSpec]) -> dict[str, Span | None]:
    """Where each task's words are in the instruction (None: not found as written)."""
    lowered = instruction.lower()
    out: dict[str, Span | None] = {}
    for t in tasks:
        said = (t.text or "").strip(" ,.;").lower()
        at = lowered.find(said) if said else -1
        if at < 0 and said:
            said = everyday(said).strip(" ,.;").lower()
            at = lowered.find(said) if said else -1
        out[t.id] = (at, at + len(said)) if at >= 0 else None
    return out


def unused_mentions(
    instruction: str, phrases: Sequence[Sequence[Mention]], parse: ParseUsage
) -> list[Unread]:
    """The mentions (`phrases`: the names that need a slot, each a list of mentions naming one thing)
    that lie in the words of a task that does not use their type and in those of no task that does."""
    spans = task_spans(instruction, parse.tasks)
    uses: dict[str, set[str]] = {}
    for task_id, _, slot_types in parse.slots():
        uses.setdefault(task_id, set()).update(slot_types)
    out = []
    for phrase in phrases:
        types = {t for m in phrase for t in (*m.entry.types, m.entry.canonical)}
        at = phrase[0].char_start
        if any(s <= at < e for s, e, _ in parse.spans):
            continue  # a negation's thing: judged with its constraint
        users = [t for t in parse.tasks if uses.get(t.id, set()) & types]
        if not users or any(spans[t.id] is None for t in users):
            continue  # no task uses it (`_nouns` names it), or a user's words are not found: no judgement
        if any(_within(spans[t.id], at) for t in users):
            continue
        holder = next((t for t in parse.tasks if _within(spans[t.id], at)), None)
        if holder is None or types & ParseUsage([holder], []).implied():
            continue  # said in no task's words (an order's "the egg first"), or implied by its task's kind
        surface = " ".join(m.surface for m in phrase)
        why = f"said in the words of task {holder.id}, which does not use it, and of no task that does"
        out.append(Unread(surface, "object", why))
    return out


def looked_at(toks: Sequence[tuple[str, int, int]], i: int) -> bool:
    """Is word `i` the "at" of "look at" (the thing examined, not where something is), said again after
    "and" ("look at the box under the lamp and at the pencil by the lamp")?"""
    if toks[i][0] != "at" or i == 0:
        return False
    if toks[i - 1][0] == "and":
        pairs = zip(toks[: i - 1], toks[1:i], strict=True)
        return any(w == "at" and _LOOK & categories(v) for (v, _, _), (w, _, _) in pairs)
    return bool(_LOOK & categories(toks[i - 1][0]))


_LOOK = frozenset({"verb_examine_in_light"})


def _within(span: Span | None, at: int) -> bool:
    return span is not None and span[0] <= at < span[1]


def lamps_off(toks: Sequence[tuple[str, int, int]], parse: ParseUsage) -> list[Unread]:
    """A lamp said to be off right after its name ("the book under the desk lamp, light off"), where no
    task switches one off: no base task does (read before as the examination, lamp on, at exit 0, h205)."""
    if "off" in parse.states:
        return []
    pairs = zip(toks, toks[1:], strict=False)
    return [Unread(f"{w} off", "action", _NO_OFF) for (w, _, _), (o, _, _) in pairs if (w, o) in _OFF]


_OFF = frozenset((w, "off") for w in ("lamp", "lamps", "light", "lights"))
_NO_OFF = "no base task switches something off"


_OR = re.compile(r"\bor\b", re.I)
_END = re.compile(r"[.;!?]")
_CHOICE = "a choice between places: every task of the spec is done, in one place; say which"


def either_place(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """ "Put the apple in the fridge, or the sink": "or" between two places of one thing (where a task
    of it puts it, or the appliance its kind implies) offers a choice, which no HTT states (every task is
    required, each in one place); a reading of one or both places is not what was asked. A ban's "or"
    ("never open the fridge or the microwave") bans both and is the negation's."""
    out = []
    for m in _OR.finditer(instruction):
        if parse.constraint_at(m.start()) is not None:
            continue
        right = next((x for x in mentions if x.char_start >= m.end()), None)
        if right is None or _END.search(instruction, m.end(), right.char_start):
            continue
        said = [x for x in mentions if x.char_end <= m.start()]
        for x in [x for x in said if not _END.search(instruction, x.char_end, m.start())]:
            if _read_as_choice(parse, set(x.entry.types), set(right.entry.types)):
                break
            if _places_of_one_thing(parse, set(x.entry.types), set(right.entry.types)):
                out.append(Unread(instruction[x.char_start : right.char_end], "place", _CHOICE))
                break
    return out


def _places_of_one_thing(parse: ParseUsage, one: set[str], other: set[str]) -> bool:
    """Whether a thing goes to one of them and to, or is treated in, the other ("heat it in the microwave
    or on the stove" names two appliances of one treatment, which its state atom leaves open)."""
    goes = {t.id: set(t.receptacle or ()) for t in parse.tasks}
    places = {t.id: goes[t.id] | IMPLIED_TYPES.get(t.kind, set()) for t in parse.tasks}
    return any(
        one & places[a.id] and other & places[b.id] and (one & goes[a.id] or other & goes[b.id])
        and set(a.object) & set(b.object)
        for a in parse.tasks
        for b in parse.tasks
    )


def _read_as_choice(parse: ParseUsage, one: set[str], other: set[str]) -> bool:
    """Whether one task takes its thing to either place (`place_choices`: "the fridge or the microwave")."""
    return any(
        any(one & set(p) for p in t.places) and any(other & set(p) for p in t.places)
        for t in parse.tasks
        if t.places
    )
