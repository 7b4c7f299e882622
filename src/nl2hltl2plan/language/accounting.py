"""Word accounting: every content word of an instruction is used by the parse or named as not understood.

`account(instruction, tasks, before, instances, scene)` judges the result of any backend (grammar,
learned, LLM) from the outside: it reads the instruction's content words (nouns naming objects and
places from `lexicon.txt`; verbs, counts, negations and order words from `content_words.txt`, read by
`content_words`) and renders the base tasks back to the types, kinds, counts and orderings they use
(`parse_usage`). It returns one `Unread` per content word the base tasks do not use, and per slot of a
base task that no word of the instruction names (an invented object or place). Counts the scene cannot
satisfy (zero, or more than it holds) and cyclic orders are input errors (`HTTError`), whatever the
backend made of them.

>>> from nl2hltl2plan.language.task_specs import BaseTaskSpec
>>> cup = BaseTaskSpec(kind="heat_place", object=["Cup"], receptacle=["Microwave"])
>>> [u.words for u in account("heat a cup of coffee in the microwave", [cup], [])]
['coffee']
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from functools import lru_cache

import networkx as nx

from nl2hltl2plan.domain.task_kinds import slots_of
from nl2hltl2plan.language.containers_said import held_content, unsaid_containers, vessel
from nl2hltl2plan.language.content_words import (
    COMMAND_WORDS,
    DETERMINERS,
    LOCATIVE,
    OBJECT_START,
    Unread,
    categories,
    check1_categories,
    free_order_remarks,
    stems,
    verb_places,
)
from nl2hltl2plan.language.counts import count_unread, count_value, counted, multipliers_unread
from nl2hltl2plan.language.grammar.everyday import everyday
from nl2hltl2plan.language.grounding import (
    LAMPS,
    SLICEABLE,
    Mention,
    camel_words,
    find_mentions,
    lexicon,
    tokens,
)
from nl2hltl2plan.language.it_of_two import it_of_two
from nl2hltl2plan.language.landmarks import (
    NEAR_WORDS,
    carried,
    landmark_destinations,
    listed_landmark,
    of_a_treated_thing,
    on_the_place,
    pair_start,
    posture_at,
    relative_subject,
)
from nl2hltl2plan.language.memo import reading_memo
from nl2hltl2plan.language.mention_use import either_place, lamps_off, looked_at, unused_mentions
from nl2hltl2plan.language.negations import (
    NO_CONSTRAINT,
    about_order,
    after_negation,
    unforbidden_verb,
    until_guard,
)
from nl2hltl2plan.language.order_words import check_cycles, finished_words, misordered, unordered_steps
from nl2hltl2plan.language.parse_usage import IMPLIED_TYPES, ParseUsage
from nl2hltl2plan.language.prepositions import DESTINATION, goes_to, preposition_before, source_at
from nl2hltl2plan.language.statements import asked_before, done_already, says_where
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec
from nl2hltl2plan.language.unknown_words import unread_words, unused_tools
from nl2hltl2plan.language.unsupported_steps import (
    OPENED_FOR_ITSELF,
    closed_after_placing,
    corrections,
    first_and_last,
    fragments,
    one_of_several,
    opened_for_itself,
    other_instances,
    repeated_tasks,
    repeats_for_another,
    returns_and_repeats,
    started,
    treated_after_placing,
    under_a_place,
)
from nl2hltl2plan.language.vague_words import vague_words

NAVIGATION = frozenset({"go", "walk", "head", "come", "run", "move", "turn"})  # "move to the sink", no object


@reading_memo  # asked about five times per instruction, half of them of the same reading
def account(
    instruction: str,
    tasks: Sequence[BaseTaskSpec],
    before: Sequence[tuple[str, str]],
    instances: Mapping[str, int] | None = None,
    scene: str = "the scene",
    constraints: Sequence[ConstraintSpec] = (),
) -> list[Unread]:
    """The content words of `instruction` that `tasks`/`before`/`constraints` do not use; slots no word names.

    `instances`: how many objects of each type the scene holds (None: unknown, counts are not checked
    against the scene). A negation, and the verb of its clause, count as used when a constraint's
    words (`ConstraintSpec.text`, found in the instruction) hold it and the constraint forbids that
    verb's action; the things a constraint forbids actions on count like a task's slots. Raises
    HTTError for a count of zero, a count above what the scene holds, and a cyclic order in the text."""
    # the grammar's rewriting reads a closing "each pair in either order" as ", in any order": whether the
    # text frees the order within each group only is asked of the words as written
    said = free_order_remarks(instruction)
    per_group_only = bool(said) and all(r.per_group for r in said)
    instruction = everyday(instruction)  # fillers, notation and headings that carry nothing (issue 28)
    lowered = instruction.lower()
    found = ((c, everyday(c.text).lower()) for c in constraints)  # its "dont" read as "don't", too
    spans = [(at, at + len(said), c) for c, said in found if (at := lowered.find(said)) >= 0]
    parse = ParseUsage(tasks, before, constraints, spans)
    toks = tokens(instruction)
    mentions = [
        m
        for m in find_mentions(instruction)
        if not m.entry.generic
        and not _is_verb(m, toks)
        # "my glasses" are no drinking glasses; "two glasses" are
        and ("noun_unsupported" not in categories(m.surface.lower()) or counted(m, toks))
    ]
    in_mention = {i for m in mentions for i in range(m.start, m.end)}
    out, named = _nouns(instruction, mentions, toks, parse)
    out += unused_mentions(instruction, named, parse)  # per mention: "the pencil" of a task without one
    out += _invented(instruction, mentions, toks, parse, in_mention)
    out += landmark_destinations(mentions, toks, parse)
    out += _invented_kinds(instruction, toks, mentions, parse)
    out += treated_after_placing(instruction, mentions, parse)
    out += closed_after_placing(instruction, mentions, parse) + either_place(instruction, mentions, parse)
    out += returns_and_repeats(instruction, mentions, parse) + done_already(instruction, tasks)
    out += other_instances(instruction, mentions, parse, instances)
    out += vague_words(instruction, mentions, any(t.places for t in tasks)) + started(instruction, parse)
    out += corrections(instruction, mentions, parse) + repeated_tasks(instruction, mentions, parse)
    out += one_of_several(instruction, mentions, parse, instances)
    out += under_a_place(instruction, mentions, parse) + lamps_off(toks, parse)
    out += first_and_last(instruction, mentions, parse) + fragments(instruction, mentions)
    out += repeats_for_another(instruction, mentions, parse) + it_of_two(instruction, mentions, parse.tasks)
    out += _words(instruction, toks, in_mention, mentions, parse, instances, scene)
    out += unordered_steps(
        toks, {i for i, t in enumerate(toks) if parse.constraint_at(t[1])} | in_mention, parse, per_group_only
    )
    out += misordered(instruction, toks, mentions, parse) + unread_words(instruction, toks)
    out += unused_tools(instruction, mentions, parse)
    out += unsaid_containers(instruction, mentions, parse)  # "the tomato in the fridge and the pan in ..."
    check_cycles(instruction, toks, mentions, parse)
    return out


def unfilled_slots(tasks: Sequence[BaseTaskSpec]) -> list[Unread]:
    """Each task with no object, and each placement with no destination: a word that should have named
    it was not understood ("on the tabel", "on it too"). Judged on the final result only (`translate`),
    not inside the parsers' own arbitration, which reads partial parses on purpose."""
    out = []
    for t in tasks:
        places = [r for r in slots_of(t.kind) if r != "object"] if t.kind.startswith("place") else []
        for role in ["object", *places]:
            if not getattr(t, role):
                why = f"task {t.id} has no {role}: the words that should name it were not understood"
                out.append(Unread(t.text or t.id, "object" if role == "object" else "place", why))
    return out


def _is_verb(m: Mention, toks: list[tuple[str, int, int]]) -> bool:
    """A lexicon word used as a verb: "switch" in "switch off the light", "switch the lamp on"; a verb
    that also names a thing, where a command starts ("spray the counter": no spray bottle is named)."""
    if m.end - m.start != 1:
        return False
    word, nxt = toks[m.start][0], toks[m.end][0] if m.end < len(toks) else ""
    if "verb_switch" in categories(word):
        return nxt in ("on", "off", "the", "it", "a")
    prev = toks[m.start - 1][0] if m.start else ""
    return "verb_unsupported" in categories(word) and nxt in OBJECT_START and prev in _COMMAND_START


_COMMAND_START = COMMAND_WORDS | {"", "to"}


def _phrases(
    instruction: str, mentions: list[Mention], toks: list[tuple[str, int, int]]
) -> list[list[Mention]]:
    """Mentions that name one thing: compounds ("dresser drawer"), "X of Y" ("two bottles of lotion";
    not a vessel and its content, `held_content`) and parts ("the shelf in the fridge"); not across a stop."""
    out: list[list[Mention]] = []
    for m in mentions:
        if out and not re.search(r"[,:;.!?()]|\s-\s", instruction[out[-1][-1].char_end : m.char_start]):
            last = out[-1][-1]
            gap = [w for w, _, _ in toks[last.end : m.start]]
            part = last.surface.lower().split()[-1] in PART_NOUNS and gap[:1] in (["in"], ["inside"])
            if not gap or (gap[0] == "of" or part) and _modifiers(gap[1:]) and not held_content(last, m):
                out[-1].append(m)
                continue
        out.append([m])
    return out


PART_NOUNS = frozenset({"shelf", "shelves"})  # "the shelf in the fridge": a part of the fridge


def _modifiers(words: list[str]) -> bool:
    """Words between "of" and a noun that only describe it: determiners, and at most two others that name
    no action or relation ("a bottle of hand soap", "a bar of white soap", "a glass of the water")."""
    others = [w for w in words if w not in DETERMINERS]
    return len(others) <= 2 and not any(categories(w) for w in others)


def _lamp_said_again(head: Mention, matched: set[frozenset[str]]) -> bool:
    """ "Take the remote to the floor lamp and turn the lamp on": "the lamp" names again the lamp a task
    already uses (a lamp word no more specific than it), not another place."""
    types = set(head.entry.types)
    return bool(types) and types <= LAMPS and any(types & key for key in matched)


def _nouns(
    instruction: str, mentions: list[Mention], toks: list[tuple[str, int, int]], parse: ParseUsage
) -> tuple[list[Unread], list[list[Mention]]]:
    """Object and place nouns: each named thing needs a slot of its own (or is implied / a location);
    and the names of the matched things that need a slot (not where something is), each said once."""
    implied, implied_words = parse.implied(), parse.implied_words()
    slots = parse.slots()
    groups: dict[frozenset[str], list[list[Mention]]] = {}
    implied_places: list[Mention] = []  # "the refrigerator" of a cooling task: still a place the task uses
    # a place a treatment implies that is also where a task puts a thing ("the heated mug into the coffee
    # maker on the counter") is matched as that place, as it is without the treatment
    destinations = {t for _, role, st in slots if role != "object" for t in st}
    for phrase in _phrases(instruction, mentions, toks):
        if any(
            m.entry.canonical in implied or m.surface.lower().split()[-1] in implied_words for m in phrase
        ) and not all(m.entry.canonical in destinations for m in phrase):
            implied_places += phrase
            continue
        groups.setdefault(frozenset(m.entry.canonical for m in phrase), []).append(phrase)
    # A phrase whose head's own type fills the slot ("coffee table" -> CoffeeTable) is matched before one
    # that only may mean it ("the table"). Nodes are numbers (groups 0.., slots after them), so that the
    # matching never depends on the run's string hashing.
    keys, g = list(groups), nx.Graph()
    for i, (key, phrases) in enumerate(groups.items()):
        types = {t for m in phrases[0] for t in m.entry.types} | key
        for k, (_, _, st) in enumerate(slots):
            head = phrases[0][-1].entry.canonical  # "glass pitcher": a pitcher, not a glass
            if head in st or head.lower() in {t.lower() for t in st}:
                g.add_edge(i, len(keys) + k, weight=3)
            elif st & types:
                g.add_edge(i, len(keys) + k, weight=2)
    lone = all(d <= 1 for _, d in g.degree)  # no group or slot with two edges: the edges are the matching
    pairs = [sorted(e) for e in (g.edges if lone else nx.max_weight_matching(g, maxcardinality=True))]
    slot_of = {i: k - len(keys) for i, k in pairs}
    matched = {keys[i] for i in slot_of}
    # a group fills one slot, but its type may be a place of another task too ("the knife to the pan on
    # the stove, move the pan into the sink ... chill a pan": the pan of the first task is a place)
    place_types = {t for _, role, st in slots if role != "object" for t in st}
    places = [
        m
        for i, k in slot_of.items()
        for p in groups[keys[i]]
        for m in p
        if slots[k][1] != "object" or m.entry.canonical in place_types
    ]
    out, named = [], []
    objects = {t for _, role, st in slots if role == "object" for t in st}
    said = (toks, places, implied_places, mentions)
    for key, phrases in groups.items():
        needing = [p for p in phrases if not _locative(instruction, p[0], *said)]
        if key in matched:
            named += needing
        if key in matched or not needing or _lamp_said_again(phrases[0][-1], matched):
            continue
        first = phrases[0][-1]
        what = "object" if any(t in objects for t in first.entry.types) else "place"
        used = "/".join(first.entry.types[:3])
        surface = " ".join(m.surface for m in phrases[0]) if len(phrases[0]) > 1 else first.surface
        out.append(Unread(surface, what, f"no base task uses it ({used})"))
    return out, named


# a "with" after these opens the task a thing is in ("done with the mug"); clauses end at these words
_DONE_WORDS = frozenset({"done", "finished", "through", "over"})
_CLAUSE_BOUND = re.compile(  # "or rather" corrects the place before it (the grammar reads the correction)
    r"[.;!?]|\b(?:and|or(?! rather| better| actually| instead)|then|but|before|after|once|until|till|while"
    r"|whenever)\b"
)


def _locative(
    instruction: str,
    m: Mention,
    toks: list[tuple[str, int, int]],
    places: list[Mention],
    implied: list[Mention],
    mentions: list[Mention],
) -> bool:
    """A place named only to say where something is: "from the counter", "the bowl the mug is in", or, next
    to the place the task uses in the same clause, "the drawer by the stove", "between the sink and the
    stove"; after "next to" / "by" / "between", the place may be one a treatment implies."""
    start = pair_start(toks, m.start)  # the second place of "between A and B" is read as A is
    i = preposition_before(toks, start, LOCATIVE)
    if _walked_to(toks, m.start) or relative_subject(instruction, m, mentions):
        return True
    close_to = 0 <= i < len(toks) - 1 and toks[i][0] == "close" and toks[i + 1][0] == "to"  # as "next to"
    sliced = toks[i][0] == "of" and ("verb_sliced" in categories(toks[i - 1][0]) or vessel(toks[i - 1][0]))
    if not close_to and (i < 0 or toks[i][0] not in LOCATIVE or looked_at(toks, i) or sliced):
        return False  # "look at the box": examined; "a slice of apple", "a glass of wine": cut, held (h216)
    if re.search(r"[,;:.!?]", instruction[toks[i][2] : toks[start][1]]):
        return False  # "in the drawer, also the ladle": a preposition's phrase never reaches over punctuation
    if source_at(instruction, toks, start, relative=True):  # "from under the bed", "out of", "that's in"
        return True
    if goes_to(toks, i):
        return False  # "put it in the microwave", "the slice goes in the fridge": where it goes
    if toks[i][0] == "with" and on_the_place(toks, i, m, places):
        return True  # "the side table with the pen on it": what is on the place says which place it is
    if toks[i][0] == "with" and ((i > 0 and toks[i - 1][0] in _DONE_WORDS) or carried(m)):
        return False  # "done with the mug": a task it is in; "a pan with a tomato": a thing to move too
    clause = _clause_span(instruction, toks[start][1])
    # "look at the racket by the dresser": an examination puts nothing anywhere, so its place is where it is
    taking = {"verb_take", "verb_sliced", "verb_examine_in_light"}
    if any(taking & categories(w) for w, s, _ in toks if clause[0] <= s < clause[1]):
        return True
    if of_a_treated_thing(toks, m, clause) or listed_landmark(instruction, toks, m, mentions):
        return True  # "wash the fork next to the sink and ...", "the mug by the sink and the bowl by ..."
    near = places + implied if toks[i][0] in NEAR_WORDS else places
    return any(clause[0] <= o.char_start < clause[1] and o.start not in (m.start, start) for o in near)


def _walked_to(toks: list[tuple[str, int, int]], start: int) -> bool:
    """ "go to the counter, grab the bread ...": where the robot walks (the place's first word at
    `start`) is a step of the task, not a destination."""
    j, to = start - 1, False
    while j >= 0 and toks[j][0] in {"to", "towards", "toward", "over", "back", "up", "the", "a"}:
        to = to or toks[j][0] in {"to", "towards", "toward"}
        j -= 1
    return to and j >= 0 and bool(stems(toks[j][0]) & NAVIGATION)


def _clause_span(text: str, at: int) -> tuple[int, int]:
    """The clause around character `at`: between full stops, semicolons, "and", "or", "then", "but" and the
    order words that open another task's clause ("the cloth in the drawer before the paper goes ...")."""
    bounds = [0, *(x.start() for x in _CLAUSE_BOUND.finditer(text.lower())), len(text)]
    start = max(b for b in bounds if b <= at)
    return start, min(b for b in bounds if b > at)


def _invented(
    instruction: str,
    mentions: list[Mention],
    toks: list[tuple[str, int, int]],
    parse: ParseUsage,
    in_mention: set[int],
) -> list[Unread]:
    """Slots of base tasks that no word of the instruction names (a guess, not a reading). A word of a
    name ("standing" of "standing lamp") names it only where it names nothing as written (`in_mention`:
    the words of a named thing): the "plate" of "the yellow plate" never stands for the blue plate. A
    misspelt name names its slot once `everyday` has respelt it (`language.spelling`)."""
    verbs = [w for i, (w, _, _) in enumerate(toks) if i not in in_mention]  # "microwave the egg" (h242)
    named = {p for w in verbs for f in stems(w) if (p := verb_places().get(f))}
    if any(c.startswith("state_lights_") for w, _, _ in toks for c in categories(w)):
        named.add("LightSwitch")  # "make the kitchen dark" names the room's lights
    sources: set[str] = set()  # named only as where a thing is or comes from: "take the mug out of the sink"
    for m in mentions:
        (named if _a_stop(instruction, m, toks) else sources).update({*m.entry.types, m.entry.canonical})
    put_back = any(w in ("back", "return") for w, _, _ in toks)  # "from the cabinet, put it back / return it"
    implied = parse.implied()
    out = []
    loose = {w for i, (w, _, _) in enumerate(toks) if len(w) >= 5 and i not in in_mention}
    for task_id, role, types in parse.slots():
        said = named if role == "receptacle" and not put_back else named | sources
        lowered = {t.lower() for t in said}
        if types & said or {t.lower() for t in types} & lowered or loose & _lexicon_words(types):
            continue
        if role == "receptacle" and types & implied:
            continue
        what = "/".join(sorted(types)[:3])
        out.append(Unread(what, "invented", f"task {task_id}'s {role} is named nowhere in the instruction"))
    return out


def _invented_kinds(
    instruction: str, toks: list[tuple[str, int, int]], mentions: list[Mention], parse: ParseUsage
) -> list[Unread]:
    """A heat / cool / clean task or a slice needs a word for it: a verb or state word ("chilled"), or
    its appliance named as a stop ("put the apple in the microwave, then on the counter")."""
    cats: set[str] = set()
    in_mention = {i for m in mentions for i in range(m.start, m.end)}
    for w, _, _ in toks:
        cats |= categories(w)
    verbs = {c for i, (w, _, _) in enumerate(toks) if i not in in_mention for c in categories(w)}
    named = {m.entry.canonical for m in mentions if _a_stop(instruction, m, toks)}
    out = []
    for t in parse.tasks:
        # the appliance names the treatment as a stop on the way, not as where the thing ends ("put the
        # apple in the fridge and stuff" is no cooling)
        stops = named & IMPLIED_TYPES.get(t.kind, set()) - set(t.receptacle or ())
        word = f"verb_{t.kind}" in verbs or bool(stops)
        word = word or (t.kind == "clean_place" and _of_water(instruction, mentions, t))
        if t.kind in IMPLIED_TYPES and not word:
            out.append(
                Unread(t.kind, "invented", f"task {t.id}'s treatment is named nowhere in the instruction")
            )
        if t.sliced and "verb_sliced" not in cats:
            out.append(
                Unread("sliced", "invented", f"task {t.id}'s slice is named nowhere in the instruction")
            )
    return out


def _of_water(instruction: str, mentions: list[Mention], task: BaseTaskSpec) -> bool:
    """A rinse named by what it leaves: "a mug of water" is a mug filled with water at the sink, as "fill
    the mug with water" is (the rinse)."""
    return any(
        set(m.entry.types) & set(task.object) and _OF_WATER.match(instruction, m.char_end) for m in mentions
    )


_OF_WATER = re.compile(r"\s+(?:full\s+)?of\s+water\b", re.I)
_PREPOSITIONS = LOCATIVE | DESTINATION


def _a_stop(instruction: str, m: Mention, toks: list[tuple[str, int, int]]) -> bool:
    """An appliance named as a stop of the task ("put the mug in the sink"), not as where a thing is or
    comes from ("the mug is in the sink", "take the apple out of the fridge"): only a stop names a
    treatment."""
    i = preposition_before(toks, m.start, _PREPOSITIONS)
    if i < 0 or toks[i][0] not in _PREPOSITIONS:
        return True
    if says_where(instruction, toks[i][1]):  # "after / until the mug is in the sink": a placement it refers
        # to; "I want that the carrot is on the plate": one it asks for
        return asked_before(instruction, toks[i][1])
    return not source_at(instruction, toks, m.start)  # "on the second from the bottom shelf": which shelf


@lru_cache(maxsize=512)
def _lexicon_words(types: frozenset[str]) -> frozenset[str]:  # once per type set: it is asked per slot
    return frozenset(w for key, (e, _) in lexicon().items() if set(e.types) & types for w in key)


def _words(
    instruction: str,
    toks: list[tuple[str, int, int]],
    in_mention: set[int],
    mentions: list[Mention],
    parse: ParseUsage,
    instances: Mapping[str, int] | None,
    scene: str,
) -> list[Unread]:
    """Verbs, counts, negations and unsupported nouns outside the lexicon's mentions."""
    out: list[Unread] = []
    words = [w for w, _, _ in toks]
    finished = finished_words(instruction)  # "whenever the vase is sorted,": a step done, no request
    for i, w in enumerate(words):
        if i in in_mention or toks[i][1] in finished:
            continue
        cats = categories(w) | check1_categories(w)
        if not cats and not w.isdigit():
            continue
        guard = parse.constraint_at(toks[i][1])
        if posture_at(instruction, toks, i):
            continue  # "the apple should be sitting on the plate": where it is, not the action of sitting
        if guard is None:
            # what an "it" after the verb may be: the last thing named before it that is opened for itself
            said = [m.surface for m in mentions if m.end <= i and set(m.entry.types) & OPENED_FOR_ITSELF]
            unread = _verb(w, cats, words, i, parse, said[-1] if said else "")
        else:
            unread = unforbidden_verb(w, cats, words, i, guard)
        if unread is None and not _locative_word(instruction, i, toks, mentions):
            unread = None if _beneficiary(instruction, toks, i, mentions, parse) else _noun(w, cats)
        if w == "no" and words[i + 1 : i + 2] == ["wait"]:
            continue  # "no wait, the cup": a correction's marker, judged by `corrections`
        if (
            "negation" in cats
            and guard is None
            and not until_guard(instruction, toks[i], bool(parse.before))
            and not about_order(instruction, toks[i])
        ):
            unread = Unread(w, "negation", NO_CONSTRAINT)
        elif count_value(cats, w) is not None or cats & {"quantifier_all", "quantifier_vague"}:
            unread = count_unread(instruction, toks, i, cats, mentions, parse, instances, scene)
        elif "repetition" in cats:
            unread = Unread(w, "count", "no base task is done more than once: say each time as its own task")
        elif "condition" in cats and guard is None and not after_negation(instruction, toks[i]):
            unread = Unread(w, "condition", "no base task waits on a condition: say what to do")
        elif "time" in cats:
            unread = Unread(w, "time", "no base task waits for a time: say what to do now")
        elif "hedge" in cats and not (i >= 2 and words[i - 1] == "you" and words[i - 2] in _ASKING):
            unread = Unread(w, "condition", "a hedge: say whether it is to be done")
        if unread is not None:
            out.append(unread)
    return out + multipliers_unread(toks, mentions, parse)  # "pillows x2" (h295)


def _locative_word(
    instruction: str, i: int, toks: list[tuple[str, int, int]], mentions: list[Mention]
) -> bool:
    """A word after a locative preposition that follows a named thing in its clause ("next to the other
    food", "by the door"); not past a "for" or a punctuation mark ("on the table for grandpa", "in the
    drawer, my son is around": a person)."""
    j = i - 1
    while j >= 0 and i - j <= 4 and toks[j][0] not in LOCATIVE | {"for"} and not categories(toks[j][0]):
        j -= 1
    if j < 0 or toks[j][0] not in LOCATIVE - {"of", "with"}:  # "a cup of coffee" names its contents
        return False
    if re.search(r"[,;:.!?]", instruction[toks[j][2] : toks[i][1]]):
        return False
    clause = _clause_span(instruction, toks[i][1])
    return any(clause[0] <= m.char_start < toks[j][1] for m in mentions)


def _beneficiary(
    instruction: str, toks: list[tuple[str, int, int]], i: int, mentions: list[Mention], parse: ParseUsage
) -> bool:
    """The person of "get me the salt and put it on the table": for whom, not where to, when a task
    places the thing named right after it (with no such task, "get me the salt" is unread as it was); the
    person of "for my mom", "for me" (for whom: the task is done all the same) and of "from mum" (who
    asks), and one set apart by punctuation, who is addressed or signs ("Mom, put ...", "Love, Grandma")."""
    apart = _PUNCT.split(instruction[: toks[i][1]])[-1] + _PUNCT.split(instruction[toks[i][1] :])[0]
    if set(apart.lower().split()) <= {*DETERMINERS, toks[i][0]} and check1_categories(toks[i][0]):
        return True
    before = [w for w, _, _ in toks[max(i - 3, 0) : i]]
    if before and before[-1] != "for" and before[-1] in DETERMINERS:
        before = before[:-1]  # "for my mom", "from mum"; "away from the kids" is where the thing goes
    said_by = before[-1:] == ["from"] and before[-2:-1] != ["away"] and check1_categories(toks[i][0])
    if before[-1:] == ["for"] or said_by:
        return True
    if toks[i][0] not in ("me", "us") or i == 0 or toks[i - 1][0] not in _GET_FOR:
        return False
    after = next((m for m in mentions if m.start > i), None)
    gap = [w for w, _, _ in toks[i + 1 : after.start]] if after else ["-"]
    objects = {o for _, role, st in parse.slots() if role == "object" for o in st}
    return after is not None and set(gap) <= DETERMINERS and bool(set(after.entry.types) & objects)


_PUNCT = re.compile(r"[,.;:!?()]")
_ASKING = frozenset({"could", "would", "can", "will"})  # "could you maybe ...": asked politely, no hedge
_GET_FOR = frozenset({"get", "grab", "fetch"})  # never "bring", "hand", "give": to the person


def _verb(
    w: str, cats: frozenset[str], words: list[str], i: int, parse: ParseUsage, last_named: str = ""
) -> Unread | None:
    if "verb_switch" in cats:
        after = words[i + 1 : i + 5]
        if "off" in after and "off" not in parse.states:
            return Unread(f"{w} off", "action", "no base task switches something off")
        if "on" in after and "examine_in_light" not in parse.kinds and "on" not in parse.states:
            return Unread(f"{w} on", "action", "no base task switches something on")
        return None
    if "verb_break" in cats and "broken" not in parse.states:
        return Unread(w, "action", "no base task breaks something")
    after = words[i + 1 : i + 4]
    if after[:1] in (["it"], ["them"]) and last_named:
        after = last_named.split()  # "put the laptop on the table and open it": the laptop
    if w in ("open", "close", "shut") and (thing := opened_for_itself(after, parse)):
        return Unread(f"{w} the {camel_words(thing).lower()}", "action", f"no base task {w}s it")
    for state in ("off", "on"):
        if f"state_lights_{state}" in cats and state not in parse.light_states:
            return Unread(w, "state", f"no base task switches the lights {state}")
    if "verb_unsupported" in cats and any(
        c.startswith("state_lights_") for x in words[i + 1 : i + 5] for c in categories(x)
    ):
        return None  # "make the kitchen dark": the state word is the request, judged on its own
    if "verb_seek" in cats and not {"and", ","} & set(words[i + 1 : i + 8]):
        return Unread(w, "action", "finding is not a task: say what to do with it")
    if "verb_unsupported" in cats and not cats & {"verb_any", "verb_step"}:
        return Unread(w, "action", "no base task does this")
    if "verb_unsupported_before_object" in cats and words[i + 1 : i + 2] and words[i + 1] in DETERMINERS:
        return Unread(w, "action", "no base task does this")
    if words[i + 1 : i + 2] == ["up"] and "verb_clean_place" in cats:
        return None  # "clean up the pencils": tidy them away, not wash them
    for c in cats:
        kind = c.removeprefix("verb_")
        if c.startswith("verb_") and kind in ("heat_place", "cool_place", "clean_place", "examine_in_light"):
            if kind not in parse.kinds:
                return Unread(w, "action", f"no {kind} task")
    if "verb_sliced" in cats and not parse.sliced and not _piece_of_whole(words, i):
        return Unread(w, "action", "no task takes a slice")
    return None


def _piece_of_whole(words: list[str], i: int) -> bool:
    """ "both pieces of soap": a piece of something no knife slices is the whole thing."""
    if words[i + 1 : i + 2] != ["of"] or words[i] in ("slice", "slices"):  # "a slice of mug" is no whole
        return False
    named = find_mentions(" ".join(words[i + 2 : i + 6]))
    return bool(named) and not set(named[0].entry.types) & SLICEABLE


def _noun(w: str, cats: frozenset[str]) -> Unread | None:
    if cats & {"person", "person_relation"}:
        return Unread(w, "place", "a person: no base task hands things to people")
    if "noun_unsupported" in cats:
        return Unread(w, "object", "no object of this world is called so")
    return None
