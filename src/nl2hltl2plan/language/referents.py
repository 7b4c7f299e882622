"""Which things the words of an instruction refer to, where the type-level spec cannot say it (issue 23).

A base task's atoms name types ("pickup(Kettle)"), and each leaf's objects are its own (docs/planning.md,
"The model"): two tasks cannot be kept to one instance, nor a task to every instance a word names. Three
wordings would be read otherwise than meant, so they are refused (HTTError, exit 2, one line naming them),
as is a word that is one type's name read as another type (`exact_names`: "towel", a Towel or a HandTowel;
"the cup" read as the Mug where the scene has a Cup):

- one thing moved twice: "put the kettle on the stove, then put the kettle (it) in the sink" reads two
  tasks that two different kettles satisfy (`moved_twice`). "A potato ... a potato", "another kettle",
  "the other kettle", "a second kettle" name another thing and are left as they are, and so are the
  treatments ALFRED's annotators describe as two steps ("put the plate in the sink and then in the
  cabinet", one clean_place, a single task);
- a category plural read as one kind: "wash the dishes" names several types (`category_words.txt`), never
  Plates alone (`categories_named`); "utensils", which the lexicon reads as any of its kinds (two utensils,
  each a Fork, Spoon, ButterKnife or Knife), is a plural of its kinds taken together (below);
- a plural of a type, or of a category read as any of its kinds, that the scene holds more of than the task
  takes: "the forks" where the scene has 3, or "the utensils" where it has 8. One rule for both
  (`plural_of_several`); what such a plural means is the world's convention (`World.plurals`), not the
  language's: where the world has one and it applies (the demo kitchen's Example 1 always, ALFRED's
  pick-two under `plurals="two"`), it is read as the task's two and the result's `assumptions` say so;
  otherwise it is refused ("say how many"). Category plurals take only a convention that covers them
  (the demo kitchen's). In non-excluded ALFRED training annotations of pick-two tasks, 2081 of 2419 say
  the number ("two forks", "both"), 59 a bare "the forks"; of the 71 annotations with a bare plural of a
  type their floor plan holds more than two of, 66 are pick-two trials (`scripts/plural_conventions.py`).
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping, Sequence
from functools import lru_cache

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import DETERMINERS, LOCATIVE, categories, word_categories
from nl2hltl2plan.language.counts import count_value, plural_as_one
from nl2hltl2plan.language.grammar.counted_refs import ONE_MORE, counted_references
from nl2hltl2plan.language.grammar.use_names import named_by_use
from nl2hltl2plan.language.grounding import (
    MOVABLE_RECEPTACLES,
    Mention,
    camel_words,
    exact_name_conflict,
    find_mentions,
    lookup,
    own_type,
    phrase_lines,
    role_swap_conflict,
    tokens,
)
from nl2hltl2plan.language.spelling import respelt
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.type_choice import text_decides
from nl2hltl2plan.language.unsupported_steps import PICKS_ONE
from nl2hltl2plan.worlds.world import PluralConvention

# words before a noun that say which thing it names (`referent_words.txt`, shared with `restated_tasks`):
# another thing than one named before ("another kettle", "a second one"), one named indefinitely ("a
# kettle"), one named definitely ("the kettle")
_WHICH = word_categories("referent_words.txt")
ANOTHER, INDEFINITE, DEFINITE = _WHICH["another"], _WHICH["indefinite"], _WHICH["definite"]
_NOT_NAMED_BEFORE = ANOTHER | INDEFINITE
_BACK = frozenset({"it", "them", "its"})
# words that say how many a plural is ("two forks", "all the forks", "both forks")
_HOW_MANY = frozenset(
    "all every each both pair couple few several some many half most rest".split()
)


def check_referents(
    instruction: str,
    tasks: Sequence[BaseTaskSpec],
    before: Sequence[tuple[str, str]],
    instances: Mapping[str, int] | None,
    scene: str,
    convention: PluralConvention | None = None,
    plurals: Plurals = "ask",
    forbidden: Collection[str] = (),
) -> list[str]:
    """Raise HTTError for one thing moved twice, a category plural read as one type, or a plural read as
    fewer things than the scene holds where no convention of the world reads it (see the module's
    docstring); returns the assumptions a convention made ("'the forks': read as 2 of ...").
    `forbidden`: the types the instruction's negations act on ("don't touch the towel")."""
    # as the grammar reads it: "remotes, two of them" (h185), "the cup for coffee" (h195), "the tisue boxes"
    instruction = named_by_use(counted_references(respelt(instruction)))
    scopes = mention_scopes(instruction, tasks)  # both checks below ask each word's tasks
    decided = exact_names(instruction, tasks, instances, scene, forbidden, scopes)
    moved_twice(instruction, tasks, before)
    place_then_moved(tasks, before)
    moved_then_filled(tasks, before)
    another_thing(instruction, tasks)
    categories_named(instruction, tasks, instances, scene)
    said = decided + stand_ins(instruction, tasks, instances, scene, scopes)
    said += plural_of_several(instruction, tasks, instances, scene, convention, plurals)
    return said + picked_places(instruction, tasks, instances, scene, [m for m, _ in scopes])


def picked_places(
    instruction: str,
    tasks: Sequence[BaseTaskSpec],
    instances: Mapping[str, int] | None,
    scene: str,
    mentions: Sequence[Mention] | None = None,
) -> list[str]:
    """A task's place picked by position among several of its type ("put the potato in the left drawer",
    "the top shelf"): read as the type, as ALFRED's annotations and ground truth do (any drawer), and
    said in the result's assumptions, so the reading is never silent about it. A thing so picked is
    refused (`unsupported_steps.one_of_several`). `mentions`: `find_mentions(instruction)`, where the caller
    has them."""
    if not instances:
        return []
    places = {r for t in tasks for r in t.receptacle or ()}
    things = {t for task in tasks for t in (*task.object, *(task.container or ()))}
    found = find_mentions(instruction) if mentions is None else mentions
    at = {m.char_start: m for m in found}
    out = []
    for said in PICKS_ONE.finditer(instruction.lower()):
        m = at.get(said.end()) or at.get(said.start(1))  # "the top drawer": a name of its own
        picked = [t for t in m.entry.types if t in places - things] if m else []
        several = [t for t in picked if instances.get(t, 0) > 1]
        if m and several:
            out.append(
                f"'{instruction[said.start(1) : m.char_end]}': read as any {several[0]} ({scene} has"
                f" {instances[several[0]]}; the spec names types, not which one)"
            )
    return out


def exact_names(
    instruction: str,
    tasks: Sequence[BaseTaskSpec],
    instances: Mapping[str, int] | None,
    scene: str,
    forbidden: Collection[str] = (),
    scopes: Scopes | None = None,
) -> list[str]:
    """A word that is one type's own name, read as another type of the scene it is a synonym of ("towel"
    read as a HandTowel where the scene has a Towel too): refused naming both, unless another word of
    the instruction names that other type itself ("the towel ... and the hand towel"): the text decides.
    A negation's types (`forbidden`) are asked as a task's are: "don't touch the towel" that forbids only
    the HandTowel would leave the Towel free. Returns the readings the text decided, as assumptions.
    `scopes`: `mention_scopes`, where the caller has them."""
    if not instances:
        return []
    scopes = mention_scopes(instruction, tasks) if scopes is None else scopes
    mentions, said = [m for m, _ in scopes], []
    held = [(task, [*task.object, *(task.container or ())]) for task in tasks]
    things = {t for _, types in held for t in types}
    used = things | {t for task in tasks for t in task.receptacle or ()} | set(forbidden)
    places = {t: task.receptacle[0] for task, types in held if task.receptacle for t in types}
    for m, (own, meant) in scopes:
        present = [t for t in m.entry.types if instances.get(t)]
        clash = exact_name_conflict(m.entry, present, scene)
        first = present[0] if present else ""
        if clash and first in used and not any(o is not m and o.entry.types[0] == first for o in mentions):
            why = None if first in forbidden else text_decides(m, present, own, instruction, instances, scene)
            if why is None:  # the text decides where one type only can do it (`type_choice`), said
                raise HTTError(clash)
            said.append(why)
        # the thing handled read as another type than the one the word names ("the cup" as the Mug), a
        # type no other word of its task can mean ("a utensil ... not the butter knife": the utensil's)
        unnamed = {t for task in own for t in (*task.object, *(task.container or ())) if t not in meant}
        # the place of the word's own task ("the cup in the coffee maker", not the mug's cabinet)
        where = {t: task.receptacle[0] for task in own if task.receptacle for t in task.object} or places
        swap = role_swap_conflict(m.entry, present, unnamed, scene, where)
        if swap:
            raise HTTError(swap)
    return said


def stand_ins(
    instruction: str,
    tasks: Sequence[BaseTaskSpec],
    instances: Mapping[str, int] | None,
    scene: str,
    scopes: Scopes | None = None,
) -> list[str]:
    """A word that is one type's own name, read as another type of its lexicon entry that a task uses and
    no other word of the text can mean, said as an assumption since the world, not the words alone, made
    that reading: where the scene lacks the named type and holds exactly one other ("cup" where the floor
    plan has a Mug and no Cup: the annotation guide's "cup -> Cup, else Mug"), or where the task's role
    passed over the named type present ("a wet towel" read as the Cloth: ALFRED cannot wash a Towel or a
    HandTowel). Where two other types could be meant nothing is said here (the roles decide, or
    `exact_names` refuses). `scopes`: `mention_scopes`, where the caller has them."""
    if not instances:
        return []
    said: list[str] = []
    scopes = mention_scopes(instruction, tasks) if scopes is None else scopes
    for m, (own, meant) in scopes:
        types = m.entry.types
        named = own_type(m.entry, types)
        if named is None or m.entry.all_:
            continue
        used = {t for task in own for t in (*task.object, *(task.container or ()), *(task.receptacle or ()))}
        read = [t for t in types if t != named and t in used and t not in meant]
        if len(read) != 1:
            continue
        if not instances.get(named):
            if [t for t in types if t != named and instances.get(t)] == read:
                said.append(f"{m.surface!r}: {scene} has no {named}; read as its {read[0]}")
        elif types.index(read[0]) > types.index(named):  # the role passed over the named type
            cannot = f"its {named} cannot do what is asked"
            said.append(f"{m.surface!r}: read as the {read[0]} of {scene}; {cannot}")
    return list(dict.fromkeys(said))


Scope = tuple[list[BaseTaskSpec], set[str]]
Scopes = list[tuple[Mention, Scope]]


def mention_scopes(instruction: str, tasks: Sequence[BaseTaskSpec]) -> Scopes:
    """Each word of `instruction` that names a thing, with its `_scope`."""
    mentions = find_mentions(instruction)
    return [(m, _scope(m, tasks, mentions)) for m in mentions]


def _scope(
    m: Mention, tasks: Sequence[BaseTaskSpec], mentions: Sequence[Mention]
) -> tuple[list[BaseTaskSpec], set[str]]:
    """The tasks whose text says the word `m` and the types the other words of their texts can mean: a
    type those words read is not this word's reading ("the mug" of one task does not make "the cup" of
    another the Mug's). Where no task's text says it (texts rewritten or unknown): every task, and the
    types every other word of the instruction (`mentions`) can mean."""
    words = tuple(w for w, _, _ in tokens(m.surface))
    own = [t for t in tasks if _says(t.text, words)]
    if not own:
        return list(tasks), {t for o in mentions if o.entry.phrase != m.entry.phrase for t in o.entry.types}
    texts = [o for task in own for o in find_mentions(task.text)]
    return own, {t for o in texts if o.entry.phrase != m.entry.phrase for t in o.entry.types}


def _says(text: str, words: tuple[str, ...]) -> bool:
    """Does `text` say `words` in a row?"""
    toks = [w for w, _, _ in tokens(text)]
    n = len(words)
    return any(tuple(toks[i : i + n]) == words for i in range(len(toks) - n + 1))


def moved_twice(
    instruction: str, tasks: Sequence[BaseTaskSpec], before: Sequence[tuple[str, str]] = ()
) -> None:
    """Two tasks that move things of one type to different places, where the later one refers back to
    the earlier one's thing by the same word ("the kettle" after "the kettle" or "a kettle") or by "it":
    the spec cannot keep both to one instance. Left: slices and pairs (many things), a task that moves
    nothing (examine, switch), one place twice (the thing ends there either way), a later task the order
    puts first ("... after you rinse the knife": no reference back in time), and a word two earlier tasks
    could have named ("the rag" after "a rag" and "a blue rag")."""
    for k, later in enumerate(tasks):
        # the thing named before: one task of one thing, else "the rag" after two rags picks neither
        # per thing, whatever its role: "the pencil into the bowl on the desk, then move the bowl to ...";
        # a container only where the later task relocates it (the two-step wording of one task with a
        # container), not where it treats it ("warm up the cup": composed sets use "the" for a new one)
        things = _carried if later.kind == "place" else _objects
        named = [t for t in tasks[:k] if things(t) & set(later.object)]
        if len(named) != 1 or not _moves(later) or not _moves(named[0]):
            continue
        earlier = named[0]
        shared = things(earlier) & set(later.object)
        if (later.id, earlier.id) in before or set(earlier.receptacle or ()) == set(later.receptacle or ()):
            continue
        said = _reference(later.text, shared, _words_for(earlier.text, shared))
        # "the cloth from the cabinet": a thing found by where it is (task texts may drop the source)
        if said is None or re.search(rf"\b{re.escape(said)}\s+from\b", instruction.lower()):
            continue
        where = " and ".join(repr(camel_words((t.receptacle or ["?"])[0])) for t in (earlier, later))
        thing = camel_words(sorted(shared)[0])
        raise HTTError(
            f"{said!r} is one {thing} put in two places ({where}), which no task can say (each task "
            f"takes any {thing} it finds): say where it ends (\"put the {thing} in …\"), or "
            f"\"another {thing}\" for a second one"
        )


def place_then_moved(tasks: Sequence[BaseTaskSpec], before: Sequence[tuple[str, str]] = ()) -> None:
    """A thing that is where one task puts something and what a later task moves, referred back to by
    the same word ("put the pencil in the mug and put the mug and the book on the desk": the mug of both
    tasks): the spec cannot keep both to one mug, so the pencil may end in another one. Said as one step
    ("put the pencil in the mug, then the mug on the desk") it is a task with the mug as its container."""
    for k, later in enumerate(tasks):
        named = [t for t in tasks[:k] if t.kind == "place" and set(t.receptacle or ()) & set(later.object)]
        if not named or not _moves(later) or (later.id, named[-1].id) in before:
            continue
        shared = set(named[-1].receptacle or ()) & set(later.object)
        # a bare noun too: "knife in mug and mug on table" (h300's line 90 split into two placings)
        said = _reference(later.text, shared, {w for t in named for w in _words_for(t.text, shared)}, True)
        if said is None or said in _BACK:
            continue
        thing = camel_words(sorted(shared)[0])
        if len(named) > 1:  # "a pen in a bowl and a pencil in a bowl, then put the bowl on ...": which one?
            which = " and ".join(t.id for t in named)
            raise HTTError(
                f"{said!r}: tasks {which} each put a thing in a {thing}, and the text does not say which one "
                f"task {later.id} moves: say where each {thing} goes (\"put X in a {thing} and the {thing} "
                "on …\")"
            )
        raise HTTError(
            f"{said!r} is where task {named[0].id} puts a thing and what task {later.id} moves, which no "
            f"two tasks can say (each takes any {thing} it finds): say it as one step (\"put X in the "
            f"{thing}, then the {thing} on …\"), or \"another {thing}\" for a second one"
        )


def moved_then_filled(tasks: Sequence[BaseTaskSpec], before: Sequence[tuple[str, str]] = ()) -> None:
    """A container one task moves and a later task puts a thing in, referred back to ("put the bowl on the
    dresser. Then put the pen in the bowl"): the spec cannot keep both to one bowl (h212). Said in one
    sentence the grammar reads it as one task with the bowl as its container."""
    for k, later in enumerate(tasks):
        dest = set(later.receptacle or ())
        named = [t for t in tasks[:k] if _moves(t) and not t.container and set(t.object) & dest]
        if later.kind != "place" or len(named) != 1 or (later.id, named[0].id) in before:
            continue
        shared = set(named[0].object) & set(later.receptacle or ()) & MOVABLE_RECEPTACLES
        said = _reference(later.text, shared, _words_for(named[0].text, shared)) if shared else None
        if said is not None:
            thing = camel_words(sorted(shared)[0])
            raise HTTError(
                f"{said!r} is what task {named[0].id} moves and where task {later.id} puts a thing, which no "
                f"two tasks can say (each takes any {thing} it finds): say it as one step (\"put X in the "
                f"{thing}, then the {thing} on …\")"
            )


def _carried(task: BaseTaskSpec) -> set[str]:
    """The types of the things a task moves: its object, and the container it moves with it."""
    return set(task.object) | set(task.container or ())


def _objects(task: BaseTaskSpec) -> set[str]:
    return set(task.object)


def _moves(task: BaseTaskSpec) -> bool:
    """Does the task move one whole thing to a place?"""
    kind_moves = task.kind not in ("set_state", "examine_in_light")
    return bool(task.receptacle) and kind_moves and not task.sliced and task.count == 1


def _words_for(text: str, types: set[str]) -> set[str]:
    """The phrases a task's text names a thing of `types` by ("kettle")."""
    return {m.entry.phrase for m in find_mentions(text) if set(m.entry.types) & types}


def _reference(text: str, types: set[str], named_before: set[str], bare: bool = False) -> str | None:
    """The words of a task's text that refer back to a thing of `types` named before by one of
    `named_before` ("the kettle", "it"), None when the text names another one ("a potato", "another
    kettle", "the other kettle", "a second kettle"), one by another word or by where it is found ("the
    cloth from the cabinet"), or none at all."""
    words = [w for w, _, _ in tokens(text or "")]
    named = [m for m in find_mentions(text or "") if set(m.entry.types) & types]
    if named:
        m = named[0]
        before = words[max(0, m.start - 2) : m.start]
        definite = bool(before) and before[-1] in DEFINITE and not set(before) & _NOT_NAMED_BEFORE
        bare = bare and m.start == 1 and words[0] not in DETERMINERS and not m.plural  # "mug on table"
        if (definite or bare) and m.entry.phrase in named_before:
            return " ".join(words[m.start - definite : m.end])
        return None
    return next((w for w in words if w in _BACK), None)


# a second thing of a type said before: "the other one", "another (one)", "a second one", "the remaining one"
# or the word alone ("and then another on the counter"), its noun left out (`elided`); "another potato",
# "one more (mug)", "a second mug"; not "one another", "one after the other", "one more time"
_SECOND_THING = re.compile(
    r"\b(?:(?P<elided>(?<!after )the\s+other|(?<!after )(?<!one )another|(?:a|the)\s+second|the\s+remaining)"
    r"(?:\s+one\b|(?=\s*(?:$|[,.;!?]|(?:in|into|on|onto|inside|to|next|by|near|too|as\s+well)\b)))"
    rf"|(?:another|{ONE_MORE}|a\s+second)\b(?!\s+(?:one|time|step|thing|task|minute)s?\b)(?!\s+(?:of|after)\b)\s*)"
)
_ORDER_OTHER = re.compile(r"\bfirst,?\s+(?:and\s+)?then\s+$")
_PLACE_GAP = re.compile(r"\b(?:in|into|on|onto|inside|to|under|at|by|near|from|with|beside)\b")


def another_thing(instruction: str, tasks: Sequence[BaseTaskSpec]) -> None:
    """ "Put the apple in the fridge and put the other one on the counter", "heat a potato and put it on the
    counter, then another potato", "put a mug in the sink, then one more in the cabinet": the words name a
    second thing of a type said before (the noun said, else the last thing a task moves before them), so a
    reading whose tasks take one thing of it (one apple chilled, then put on the counter, as "it" would say)
    has dropped one of them: refused. With no thing moved before, the words name a second thing where the
    reading acts on one of each type. Not a place ("... and the cup in the other one"); "put another pillow
    on the bed" with no pillow before it is one more than the scene's, and stays."""
    lowered = instruction.lower()
    moved = {t for task in tasks for t in (*task.object, *(task.container or ()))}
    for m in _SECOND_THING.finditer(lowered):
        if _after_preposition([w for w, _, _ in tokens(lowered[: m.start()])]):
            continue
        if _ORDER_OTHER.search(lowered[: m.start()]) and not lowered[m.end() :].strip(" .!"):
            continue  # "the statue first, then the other one": the other task (an order remark)
        before = [x for x in find_mentions(lowered[: m.start()]) if set(x.entry.types) & moved]
        rest = lowered[m.end() :]
        # "one more mug", not "one more in the cabinet" (the cabinet is where it goes)
        near = [] if m["elided"] else [x for x in find_mentions(rest) if x.char_start <= 12]
        after = [x for x in near if not _PLACE_GAP.search(rest[: x.char_start])][:1]
        said = lowered[m.start() : m.end() + (after[0].char_end if after else 0)].strip()
        thing = after[0] if after else (before[-1] if before else None)  # said alone: the last thing moved
        if thing is None and m["elided"] and max((_taken(tasks, {o}) for o in moved), default=0) < 2:
            raise HTTError(
                f"{said!r} names a second thing, and the reading acts on one thing of each type: name it "
                f"(\"the apple ... the other apple\")"
            )
        if thing is None or not any(set(x.entry.types) & set(thing.entry.types) for x in before):
            continue
        same = [x for x in before if set(x.entry.types) & set(thing.entry.types)]
        adds = not re.match(r"the\s+(?:other|remaining|second)|a\s+second", m[0])  # "another", "one more"
        had = max(_said_count(lowered, x) for x in same) if adds else 1
        if had >= _taken(tasks, set(thing.entry.types)):
            name, one = thing.surface, "one" if thing.plural else thing.surface
            more = f"a second {name}" if had == 1 else f"one more than the {had} {name} said"
            taken = {1: "one", 2: "two", 3: "three"}.get(had, had)
            raise HTTError(f"{said!r} names {more}, and the reading takes {taken}: say what to do with it "
                           f"(\"put another {one} in ...\")")


def _said_count(lowered: str, m: Mention) -> int:
    """How many things a mention names: the count up to three words before it ("two mugs"), else 1."""
    for w, _, _ in tokens(lowered[: m.char_start])[-3:][::-1]:
        if (n := count_value(categories(w), w)) is not None:
            return n
    return 1


def _taken(tasks: Sequence[BaseTaskSpec], types: set[str]) -> int:
    """How many things of these types the tasks take, as objects (their count) and as containers."""
    return sum(t.count for t in tasks if types & set(t.object)) + sum(
        1 for t in tasks if types & set(t.container or ())
    )


@lru_cache(maxsize=1)
def category_words() -> dict[str, tuple[str, ...]]:
    """Category word -> the types it covers (`category_words.txt`)."""
    return {p: tuple(f[0].split()) for ps, f in phrase_lines("category_words.txt") for p in ps}


def categories_named(
    instruction: str, tasks: Sequence[BaseTaskSpec], instances: Mapping[str, int] | None, scene: str
) -> None:
    """A category word ("the dishes", "the utensils") that a task reads as objects of its types: which
    things and how many is not said."""
    toks = tokens(instruction)
    words = [w for w, _, _ in toks]
    taken = {t for task in tasks for t in task.object}
    for i, w in enumerate(words):
        covers = category_words().get(w)
        if covers is None or not taken & set(covers) or _counted(words[max(0, i - 2) : i]):
            continue
        if _as_category(w, covers, tasks):  # the paper's "utensils": any of the kinds, not one of them
            continue
        if _after_preposition(words[:i]):  # "next to the other food": a landmark, no task's object
            continue
        held = instances or {}
        present = [f"{t} ({held[t]})" for t in covers if held.get(t)] or [t for t in covers if t in taken]
        raise HTTError(
            f"{w!r} names several kinds of thing ({', '.join(present)} in {scene}): name which and how "
            f"many (\"the plates\", \"two forks\", \"all the bowls\")"
        )


def _as_category(word: str, covers: tuple[str, ...], tasks: Sequence[BaseTaskSpec]) -> bool:
    """Does a task read the category as such: a word the lexicon reads as any of its kinds ("utensils": a
    Fork, Spoon, ButterKnife or Knife, an ambiguity the user may settle), for several things (the paper's
    dishwasher task: two utensils)? Not "dishes" as Plates, nor "the silverware" as one knife."""
    entry = lookup(word)
    several = any(set(t.object) & set(covers) and t.count > 1 for t in tasks)
    return entry is not None and entry.all_ and several


def _after_preposition(before: list[str]) -> bool:
    """Is the nearest word before a noun, past its determiners ("the", "other"), a preposition?"""
    rest = [w for w in before if w not in DETERMINERS and w != "other"]
    return bool(rest) and rest[-1] in LOCATIVE | {"to", "into", "onto"}


def plural_of_several(
    instruction: str,
    tasks: Sequence[BaseTaskSpec],
    instances: Mapping[str, int] | None,
    scene: str,
    convention: PluralConvention | None = None,
    plurals: Plurals = "ask",
) -> list[str]:
    """A plural with no number ("put the forks in the drawer") read as a task of fewer things than the
    scene holds of its type: two of three is a guess, refused unless the world's `convention` applies
    (its `always`, or `plurals="two"`); returns what the convention read. Unknown scene (`instances`
    None): not judged."""
    if not instances:
        return []
    applies = convention is not None and (convention.always or plurals == "two")
    said: list[str] = []
    plurals_said = bare_plurals(instruction)
    for m in plurals_said:
        if _counted_before(instruction, m, tasks) or _both_after(instruction, m, plurals_said, tasks):
            continue
        covers = category_words().get(m.surface.lower())
        if covers and _as_category(m.surface.lower(), covers, tasks):
            # a category read as such counts every instance of its kinds, as a type counts its own
            group = [t for t in tasks if set(t.object) & set(covers)]
            ok = applies and convention is not None and convention.categories
            said += _not_several(instruction, m, group, covers, instances, scene, convention if ok else None)
            continue
        for task in tasks:
            types = set(task.object) & set(m.entry.types)
            said += _not_several(instruction, m, [task], types, instances, scene, (None, convention)[applies])
        plural_as_one(instruction, m, tasks, instances, scene)
    return list(dict.fromkeys(said))


def bare_plurals(instruction: str) -> list[Mention]:
    """The plurals of the text with no word saying how many ("the forks", not "two forks", "all the
    forks" or "both forks")."""
    words = [w for w, _, _ in tokens(instruction)]
    return [
        m
        for m in find_mentions(instruction)
        if m.plural and not m.entry.generic and not _counted(words[max(0, m.start - 3) : m.start])
        and not _partitive(words[max(0, m.start - 5) : m.start])
    ]


def _partitive(before: list[str]) -> bool:
    """ "two of the grey spray bottles": the count before "of the" (and a describing word) says how many."""
    at = before.index("of") if "of" in before else -1
    near = len(before) - at <= 3  # "of the" and at most one describing word
    return at > 0 and before[at + 1 : at + 2] == ["the"] and near and _counted(before[at - 1 : at])


def _both_after(
    instruction: str, m: Mention, plurals: Sequence[Mention], tasks: Sequence[BaseTaskSpec]
) -> bool:
    """Does a later "them both" or "both of them" say how many the plural is ("pick up the spoons, put
    them both on the counter": two), with no other plural between them to refer to, and the one task of
    its type takes two?"""
    said = _BOTH_OF_THEM.search(instruction.lower(), m.char_end)
    takes = [t.count for t in tasks if set(t.object) & set(m.entry.types)]
    return (
        said is not None
        and takes == [2]
        and not any(m.char_end <= o.char_start < said.start() for o in plurals)
    )


# "take the spoons. put them in the sink": a task of one thing said with a plural's pronoun read the plural
# as one
_PLURAL_PRONOUN = re.compile(r"\b(?:them|these|those)\b(?!\s+(?:one|first|last)\b)")
_BOTH_OF_THEM = re.compile(r"\b(?:them|these|those)\s+both\b|\bboth\s+of\s+(?:them|these|those)\b")


def _counted_before(instruction: str, m: Mention, tasks: Sequence[BaseTaskSpec]) -> bool:
    """Does a bare plural name again the things one task took by a count said before ("put two forks in
    the drawer; once the forks are in ...": those two)? Not after a part ("two of the forks"), nor where
    two tasks take that type ("put two forks in the drawer, then the forks on the table": which)."""
    words = [w for w, _, _ in tokens(instruction)]
    types = set(m.entry.types)
    said = [
        o
        for o in find_mentions(instruction)
        if o.start < m.start and o.plural and set(o.entry.types) & types
        and _counted(before := words[max(0, o.start - 3) : o.start]) and "of" not in before
    ]
    return bool(said) and sum(bool(set(t.object) & types) for t in tasks) == 1


def _not_several(
    instruction: str,
    m: Mention,
    tasks: Sequence[BaseTaskSpec],
    types: Collection[str],
    instances: Mapping[str, int],
    scene: str,
    convention: PluralConvention | None,
) -> list[str]:
    """A task of the plural `m` that takes fewer of `types` than the scene holds: read by `convention`
    (the assumption it makes, said), else refused."""
    held = {t: instances[t] for t in sorted(types) if instances.get(t)}
    total = sum(held.values())
    fewer = [task for task in tasks if 1 < task.count < total]
    as_one = [t for t in tasks if t.count == 1 < total and _PLURAL_PRONOUN.search((t.text or "").lower())]
    if not fewer and not as_one:
        return []
    if convention is not None and not as_one:
        words = _said(instruction, m)
        return [f"{words!r}: read as {fewer[0].count} of {scene}'s {total}, {convention.name}"]
    kinds = f" ({', '.join(f'{t} {n}' for t, n in held.items())})" if len(held) > 1 else ""
    one = f"\"the {m.entry.phrase}\" for one" if len(held) == 1 else "name which kind"
    took = (fewer or as_one)[0].count
    raise HTTError(
        f"{m.surface!r}: {scene} has {total} of them{kinds} and the task would take {took}: say "
        f"how many (\"two {m.surface}\", \"all the {m.surface}\"), or {one}"
    )


def _said(instruction: str, m: Mention) -> str:
    """The plural's words as written, with its determiner ("the forks")."""
    head = instruction[: m.char_start].split()
    return f"{head[-1]} {m.surface}" if head and head[-1].lower() in DEFINITE else m.surface


def _counted(before: list[str]) -> bool:
    """Do the words before a noun say how many ("two", "all the", "both")?"""
    return any(w in _HOW_MANY or count_value(categories(w), w) is not None for w in before)
