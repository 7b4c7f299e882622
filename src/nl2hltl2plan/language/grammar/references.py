"""Step 5, references: "after placing the statue" -> the tasks it names (or new ones it states)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from nl2hltl2plan.domain.task_kinds import APPLIANCE, Kind
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.clauses import split_clauses
from nl2hltl2plan.language.grammar.draft_tasks import Draft, TaskBuilder, Unit
from nl2hltl2plan.language.grammar.drafts import incomplete, joins
from nl2hltl2plan.language.grammar.frames import Frame, parse_frame, two_places, two_places_unread
from nl2hltl2plan.language.grammar.listed_things import merge_items
from nl2hltl2plan.language.grammar.phrases import NP, parse_np, tokens
from nl2hltl2plan.language.task_specs import BaseTaskSpec

# "once the rest is finished", "when the rest is done": every task said before the clause
_THE_REST = re.compile(
    r"^the\s+rest(?:\s+(?:is|are|has\s+been|have\s+been|gets|get)\s+"
    r"(?:done|finished|complete|completed|over|through|sorted|handled))?$",
    re.I,
)
# "once both of them are done", "after both are there": the tasks said before, where they are two
_BOTH_DONE = re.compile(
    r"^(?:both(?:\s+of\s+(?:them|those|these))?|them\s+both)(?:\s+(?:are|have\s+been)\s+"
    r"(?:done|finished|complete|completed|there))?$",
    re.I,
)
# "before you do this", "after you've done that", "once you finish this": the task just said
_DO_THIS = re.compile(
    r"^(?:you(?:'ve|\s+have|'re|\s+are)?\s+)?(?:do|did|done|finish|finished|complete|completed)\s+"
    r"(?:with\s+)?(?:this|that)$",
    re.I,
)

# "after putting those away", "once you've placed them all": the things of a list placed just before, by a
# placing verb and a plural pronoun (the list's tasks, `_listed_just_before`)
_PLACED_THEM = re.compile(
    r"^(?:you(?:'ve|\s+have)?\s+)?(?:having\s+)?(?:putting|put|placing|placed|moving|moved|setting|set|storing|"
    r"stored)\s+(?:them|those|these|all\s+of\s+(?:them|those|these)|them\s+all|each\s+of\s+them)"
    r"(?:\s+(?:away|down|in|there|in\s+place))?$",
    re.I,
)


# why a reference to what was said is refused: the words fit several readings, which the structure model must
# not choose between either (`learned.structured.decide`)
NOT_CERTAIN = "what it names is not certain"


def said_before(ref: str, u: Unit, units: list[Unit]) -> list[int] | None:
    """The tasks a reference to what was said names, where that is certain: "the rest" (is done) is every
    task said before the clause; "do this" / "done that" is the task just said, where it is the only task
    of its sentence or said in the reference's own sentence ("put A, and before you do that, B"). None:
    not such a reference; []: such a reference whose tasks are not certain (nothing said before it, or
    "A and B. Before you do this, C": A and B or B alone)."""
    ref = " ".join(ref.split())
    if u.tasks and _PLACED_THEM.match(ref):
        return _listed_just_before(u, units)
    said = units_said_before(u, units)
    if u.tasks and _BOTH_DONE.match(ref):  # "Y once both (of them) are done": the two tasks said before Y
        two = [t for v in said for t in v.tasks]
        return two if len(two) == 2 else None  # else left to the other readings of "both"
    if not u.tasks or not (_THE_REST.match(ref) or _DO_THIS.match(ref)):
        return None
    if _THE_REST.match(ref):
        return [t for v in said for t in v.tasks]
    if not said:
        return []
    last = said[-1]
    alone = [v for v in said if v.sentence == last.sentence] == [last]
    return list(last.tasks) if len(last.tasks) == 1 and (alone or last.sentence == u.sentence) else []


def _listed_just_before(u: Unit, units: list[Unit]) -> list[int] | None:
    """The tasks of a list said in the clause just before `u` ("put a fork, a spoon and a ladle in a drawer");
    None where that clause states one task (the plural names no list: left to the other readings)."""
    said = units_said_before(u, units)
    return list(said[-1].tasks) if said and len(said[-1].tasks) > 1 else None


def units_said_before(u: Unit, units: list[Unit]) -> list[Unit]:
    """The units with tasks that all come before `u`'s first task (what a reference in `u` can name)."""
    return [v for v in units if v is not u and v.tasks and max(v.tasks) < min(u.tasks)]


def _ref_parts(ref: str) -> list[str]:
    return [p.strip() for p in re.split(r",|\band\b|\bas well as\b|\bplus\b", ref, flags=re.I) if p.strip()]


def ref_targets(
    ref: str,
    specs: list[BaseTaskSpec],
    nps: list[NP | None],
    exclude: list[int] | None = None,
    done_before: int | None = None,
) -> tuple[list[int], list[str]]:
    """Task indices a reference ("placing the statue and moving the knife") names; unresolved parts.
    `done_before`: the first task of the clause that a finished reference orders ("when you're done moving
    the soap, ..."); a task stated before it is meant rather than a later one the words fit as well."""
    found: list[int] = []
    missing: list[str] = []
    candidates = [i for i in range(len(specs)) if i not in (exclude or [])]
    for part in _ref_parts(ref):
        words = [w for w, _, _ in tokens(part)]
        if (described := _described(words, specs, candidates)) is not None:
            found.extend(described)
            if not described:
                missing.append(part)
            continue
        np = _ref_np(words)
        hit: list[int] = []
        if (
            np.entry is not None
            and np.is_lamp()
            or (not np.entry and any(w in {"lamp", "light"} for w in words))
        ):
            hit = [i for i in candidates if specs[i].kind == "examine_in_light"]
            if np.entry is not None and np.entry.canonical in {"DeskLamp", "FloorLamp"}:
                # "the floor lamp one": the tasks under that lamp, the one said for it alone first (h190)
                lit = [i for i in hit if (specs[i].light or []) == [np.entry.canonical]]
                hit = lit or [i for i in hit if np.entry.canonical in (specs[i].light or [])] or hit
            if (held := _held_np(words)) is not None:  # "turn on the lamp with the newspaper at hand"
                hit = _hits_by_object(held, specs, nps, hit)
        elif np.entry is not None or np.head:
            hit = _hits_by_object(np, specs, nps, candidates, done_before)
            if not hit and np.entry is not None and not _names_a_thing_before_place(words):
                # "after putting items to the lower rack": by destination
                hit = [i for i in candidates if np.entry.canonical in (specs[i].receptacle or [])]
                found.extend(hit)
            if not hit and np.head:
                head = np.head.replace(" ", "")
                hit = [
                    i
                    for i in candidates
                    if head in "".join(specs[i].object).lower()
                    or any(head in r.lower() for r in (specs[i].receptacle or []))
                ]
        if len(hit) > 1:  # "after you've chilled the glass": the task that chills it, not a heated one
            said = {KIND_WORDS[w] for w in words if w in KIND_WORDS}
            hit = [i for i in hit if specs[i].kind in said] or hit
        many = np.plural or _PLURAL_TASK_WORDS.intersection(words) or words[0] == "both"
        if len(hit) > 1 and not many and _TASK_WORDS.intersection(words):
            missing.append(part)  # "the lamp one" with two tasks under the lamp: which one is not said
        elif hit:
            found.append(hit[-1])
            # "the lamp ones", "both pen jobs (are done)": each
            if many and len(hit) > 1:
                found.extend(hit)
        else:
            missing.append(part)
    return sorted(set(found)), missing


# tasks named by what is done to their things ("the washing jobs", "the heating ones"; h190)
_KIND_SAID: dict[Kind, str] = {
    "clean_place": "wash washing washed rinse rinsing rinsed clean cleaning cleaned",
    "heat_place": "heat heating heated microwave microwaving microwaved warm warming cook cooked",
    "cool_place": "chill chilling chilled cool cooling cooled fridge",
}
KIND_WORDS: dict[str, Kind] = {w: kind for kind, said in _KIND_SAID.items() for w in said.split()}
_LOOKING = frozenset({"looking", "examining", "reading", "inspecting"})  # "the looking last": no other word


def treated_tasks(words: list[str], specs: list[BaseTaskSpec], candidates: list[int]) -> list[int] | None:
    """The tasks a reference names by what is done to their things: "the washing (jobs)", "the heating
    ones", "the looking": every candidate of that one kind, in the order said. None: its words name no one
    treatment (the one reader of `_described` here and of `remark_edges`' remarks)."""
    kinds = {KIND_WORDS[w] for w in words if w in KIND_WORDS}
    if set(words) - {"the"} and set(words) - {"the"} <= _LOOKING:
        kinds = {"examine_in_light"}
    return [i for i in candidates if specs[i].kind in kinds] if len(kinds) == 1 else None
_TASK_WORDS = frozenset({"one", "ones", "job", "jobs", "task", "tasks", "chore", "chores", "part", "parts"})
_PLURAL_TASK_WORDS = frozenset({"ones", "jobs", "tasks", "chores", "parts"})
_COUNTS = {"two": 2, "three": 3}
_DONE_AFTER = re.compile(r"\s+(?:is|are|have\s+been|has\s+been)\s+(?:done|finished|complete|completed|over)$")


def task_word_said(parts: list[str]) -> bool:
    """Does an unresolved reference name a task by a task noun ("the lamp one")? Then which task it means
    is not said (two fit it), and the order it gives must not be dropped."""
    return any((_TASK_WORDS - _PLURAL_TASK_WORDS).intersection(w for w, _, _ in tokens(p)) for p in parts)


def _described(words: list[str], specs: list[BaseTaskSpec], candidates: list[int]) -> list[int] | None:
    """Tasks a reference names by position ("the first two": the two said first) or by their treatment with a
    task noun ("the washing jobs"); every such task, in the order said. None: no such reference."""
    if (position := former_or_latter(words, candidates)) is not None:
        return position
    if len(words) == 3 and words[0] == "the" and words[1] in {"first", "last"} and words[2] in _COUNTS:
        n = _COUNTS[words[2]]
        return candidates[:n] if words[1] == "first" else candidates[-n:]
    words = _DONE_AFTER.sub("", " ".join(words)).split()  # "both pen jobs are done"
    if not words or words[-1] not in _TASK_WORDS:
        return None
    if (treated := treated_tasks(words[:-1], specs, candidates)) is not None:
        return treated
    if words[0] not in {"both", "all"}:
        return None
    # "both pen jobs": every task on that thing, as its object or its container ("both bowl jobs": two bowls
    # placed and a pen put in a third bowl; h212)
    np = parse_np(" ".join(w for w in words[1:-1] if w != "the"))
    key = np.entry.canonical if np.entry is not None else None
    return [i for i in candidates if key in specs[i].object or key in (specs[i].container or [])]


_POSITION = {"former": 0, "latter": -1}


def former_or_latter(words: list[str], candidates: list[int]) -> list[int] | None:
    """ "the former" / "the latter": the first / second of the two tasks it may name; [] where more than two
    may be meant (which two is not said: never a guess). None: no such reference."""
    said = [w for w in words if w != "the"]
    if len(said) != 1 or said[0] not in _POSITION:
        return None
    return [candidates[_POSITION[said[0]]]] if len(candidates) == 2 else []


def _names_a_thing_before_place(words: list[str]) -> bool:
    """Does a reference name a thing of its own before its place ("put the tray in the fridge": a tray no
    task moves), so that the place alone must not say which task is meant?"""
    k = next((k for k, w in enumerate(words) if w in _PLACE_PREPS), None)
    if k is None:
        return False
    np = _ref_np(words[:k])
    return bool(np.head) and not np.generic and not np.pronoun


_PLACE_PREPS = frozenset({"in", "into", "on", "onto", "to", "inside"})


def _held_np(words: list[str]) -> NP | None:
    """The thing held in a reference to a lamp ("turning on the lamp while holding the keys", "... with the
    newspaper at hand"): it says which task under a lamp is meant."""
    k = next((k for k, w in enumerate(words) if w in {"with", "holding", "carrying"}), None)
    if k is None:
        return None
    np = _ref_np(words[k + 1 :])
    return np if np.entry is not None and not np.is_lamp() else None


def _ref_np(words: list[str]) -> NP:
    """The noun phrase of a reference part, past its verbs ("having been washed", "placing")."""
    k = 0
    while k < len(words) and (
        words[k] in G.VERBS
        or words[k] in G.VERB_PAST
        or words[k] in G.PARTICLES
        or words[k] in {"having", "have", "has", "had", "been", "is", "are", "was", "you"}
    ):
        k += 1
    return parse_np(
        " ".join(
            w for w in words[k:] if w not in {"is", "are", "was", "were", "been"} and w not in G.VERB_PAST
        )
    )


def _hits_by_object(
    np: NP,
    specs: list[BaseTaskSpec],
    nps: list[NP | None],
    candidates: list[int],
    done_before: int | None = None,
) -> list[int]:
    """Tasks about the same word, else about a word of a shared type, else with it as object or container;
    with `done_before`, the first of these tiers that holds a task stated before that one wins ("move the
    hand soap ... when you're done moving the soap, ... after all of that, put the bar of soap away": the
    hand soap, not the later bar that the word names exactly)."""
    key = np.key
    tiers = [[i for i in candidates if (other := nps[i]) is not None and other.key == key]]
    if np.entry is not None:
        types = set(np.entry.types)
        tiers.append([i for i in candidates if _shares_a_type(types, nps[i], specs[i])])
        tiers.append(
            [
                i
                for i in candidates
                if np.entry.canonical in (specs[i].container or []) or np.entry.canonical in specs[i].object
            ]
        )
    if done_before is not None:
        for tier in tiers:
            if earlier := [i for i in tier if i < done_before]:
                return earlier
    return next((tier for tier in tiers if tier), [])


def _shares_a_type(types: set[str], other: NP | None, spec: BaseTaskSpec) -> bool:
    """Does a task's word share a type with the reference's, among the types the task took where its word
    has several ("the pump bottle" is no "bar of soap" read as SoapBar, though the word may be SoapBottle)?"""
    if other is None or other.entry is None:
        return False
    shared = types & set(other.entry.types)
    took = set(spec.object) & set(other.entry.types)
    return bool(shared) and (not took or bool(shared & took))


_STATE_KINDS: dict[str, Kind] = {
    "clean": "clean_place",
    "heat": "heat_place",
    "cool": "cool_place",
    "fill": "clean_place",
}


def self_state(
    ref: str, specs: list[BaseTaskSpec], b: TaskBuilder | None = None, nps: Sequence[NP | None] = ()
) -> None:
    """ "After refrigerating the pan, pick up a pan ... and put it on the table": the reference is a state
    change of the task itself, not an order. "Once the bed is sorted, put the pillow on it" (h254's "sorted"
    read as done) names the task only by its place, a thing of no task said done: unread (h264)."""
    words = _treatment_words(ref)
    cls = G.VERBS.get(words[0], ("", ""))[0] if words else ""
    kind = _STATE_KINDS.get(cls)
    done = _PLACE_DONE.fullmatch(ref.strip())
    if b is not None and not kind and done and parse_np(done["np"]).key not in {n.key for n in nps if n}:
        b.unparsed.append(f"could not tell which task {ref!r} refers to ({NOT_CERTAIN}: no task moves it)")
    for s in specs:
        if kind and s.kind in {"place", "place_two"} and s.count == 1:
            s.kind = kind


_PLACE_DONE = re.compile(r"(?:the|that|this|your|my)\s+(?P<np>[a-z ]+?)\s+(?:is|are)\s+done", re.I)


def treats_own(ref: str) -> bool:
    """ "when done heating in the microwave", "once you finish washing it": a treatment that names no object
    (a pronoun, or only the appliance it is done in) is one of the clause's own task."""
    words = _treatment_words(ref)
    if not words or _STATE_KINDS.get(G.VERBS.get(words[0], ("", ""))[0]) is None:
        return False
    rest = [w for w in words[1:] if w not in G.PARTICLES]
    if not rest or rest[0] in G.PRONOUNS:
        return True
    np = parse_np(" ".join(rest[1:]))
    appliance = np.entry is not None and np.entry.canonical in APPLIANCE.values()
    return rest[0] in {"in", "inside", "at"} and appliance


def _treatment_words(ref: str) -> list[str]:
    """The words of a reference from its verb on ("you finish heating it" -> heating it)."""
    words = [w for w, _, _ in tokens(_YOU.sub("", ref))]
    while words and words[0] in {"finish", "finished", "done", "through", "with"}:
        words = words[1:]
    return words


_YOU = re.compile(r"^\s*you\s+(?:have\s+|had\s+)?", re.I)


# "after the mug is in the sink", "before the apple goes in the fridge" ("goes" is gone by then,
# `sentences.supply_put`): the placement that state needs. The verb may be missing only where no other
# verb follows: "the mug on the counter is removed" states no placement.
_STATE_VERB = r"(?:is|are|was|were|goes|go|gets|get|got|has\s+been|have\s+been|ends\s+up)"
_PLACED_STATE = re.compile(
    rf"^(?P<np>(?:the|a|an|your|my)\s+[^,]+?)\s+(?:{_STATE_VERB}\s+(?:(?:put|placed|set)\s+)?|(?:put|placed|set)\s+|"
    rf"(?![^,]*\b(?:{_STATE_VERB}|been|removed|taken)\b))"
    r"(?P<place>(?:in|into|on|onto|inside)\s+(?:the|a|an|your|my)\s)",
    re.I,
)


_LOCATED = re.compile(r"\s(?:in|on|inside|at|from|near|by|beside|under|next\s+to)\s", re.I)


def _placement(m: re.Match[str], text: str) -> str:
    """ "the mug is in the sink" -> "put the mug in the sink", unless the object is named elsewhere in the
    instruction too: then the reference is to that mention's task (a clause that may be unread)."""
    head = m["np"].split()[-1]
    if len(re.findall(rf"\b{re.escape(head)}\b", text, re.I)) > 1:
        return m[0]
    if _LOCATED.search(m["np"]):  # "the mug on the counter is in the sink": the sink is where it goes
        return f"move {m['np']} to {m['place'].split(maxsplit=1)[1]}"
    return f"put {m['np']} {m['place']}"


def new_tasks_from_ref(ref: str, b: TaskBuilder, text: str) -> list[BaseTaskSpec]:
    """A reference that names no earlier task but states one ("after picking up the box and placing it on
    the armchair", "after the mug is in the sink"): parse it as clauses of its own."""
    drafts: list[Draft] = []
    unread: list[str] = []
    ref = _PLACED_STATE.sub(lambda m: _placement(m, text), ref.strip())
    # "after you put ...": a clause of its own (a run-on in it may be the main clause: not split)
    for c_text, _s, _e, _j in split_clauses(_YOU.sub("", ref), run_ons=False):
        words = [w for w, _, _ in tokens(c_text)]
        if words and words[0] not in G.VERBS and words[0] in G.VERB_PAST:
            # "after you have examined the keys under the lamp": the clause "examine the keys ..."
            c_text = G.VERB_PAST[words[0]][1] + c_text.lstrip()[len(words[0]) :]
        elif words and words[0] not in G.VERBS:
            continue
        fr = parse_frame(c_text, 0, "")
        if places := next((w for it in fr.items if (w := two_places(it))), ""):
            unread.append(two_places_unread(c_text, places))
            continue
        _share_listed_destination(fr, c_text, b)
        for k, it in enumerate(fr.items):
            if k == 0 and drafts and (joins(drafts[-1], fr, it) or incomplete(drafts[-1])):
                drafts[-1].frames.append((fr, it))
            else:
                drafts.append(Draft(frames=[(fr, it)], start=0, end=0))
    out = []
    saved = list(b.unparsed)
    for d in drafts:
        spec = b.spec(d, ref)
        if spec is not None:
            out.append(spec)
    b.unparsed = saved + unread
    return out


def _share_listed_destination(fr: Frame, clause: str, b: TaskBuilder) -> None:
    """ "before you put the apple and the carrot on the plate": each listed object is a task of its own,
    with the destination stated after the last one, as in a clause of the instruction (`merge_items`: a
    container and its content stay one); not "the mug or the cup" (which one is not said) nor a list
    with a knife and something sliced (the knife is the tool)."""
    if len(fr.items) < 2 or re.search(r"\bor\b", clause, re.I):
        return
    names = {it.obj.entry.canonical for it in fr.items if it.obj is not None and it.obj.entry is not None}
    if names & set(G.KNIVES) and names & set(G.SLICEABLE):
        return
    shared = [(p, np) for p, np in fr.items[-1].pps if p in G.DEST_PREPS]
    for it in fr.items[:-1]:
        if it.obj is not None and not any(p in G.DEST_PREPS for p, _ in it.pps):
            it.pps.extend(shared)
    fr.items = merge_items(fr.items, b)


_STATES = {"clean_place", "heat_place", "cool_place"}


def _differ(new: BaseTaskSpec, old: BaseTaskSpec) -> bool:
    """Can a whole task stated by a reference not be `old`: another destination, another state?"""
    if (new.kind == "examine_in_light") != (old.kind == "examine_in_light"):
        return True
    if new.receptacle and old.receptacle and not set(new.receptacle) & set(old.receptacle):
        return True
    if new.receptacle and (new.kind == "place_two") != (old.kind == "place_two"):
        return True  # "after you put two bars of soap in a cabinet" is not "put a bar of soap in a cabinet"
    return new.kind in _STATES and old.kind in _STATES and new.kind != old.kind


def restated_own_tasks(ref: str, b: TaskBuilder, text: str) -> list[BaseTaskSpec]:
    """A reference that names only its own clause's task but states a whole task ("put the soap on the
    toilet before you put wet soap on the toilet"): a task cannot come before itself, so the reference
    is a second task. A reference that only treats the object ("after refrigerating the pan", "after
    heating it in the microwave") states no task of its own: none."""
    new = new_tasks_from_ref(ref, b, text)
    if any(APPLIANCE.get(n.kind) in (n.receptacle or []) or not (n.receptacle or n.light) for n in new):
        return []  # a place the words do not name in the scene ("on the flusher") is no second task
    return new


def stated_tasks(ref: str, named: list[BaseTaskSpec], b: TaskBuilder, text: str) -> list[BaseTaskSpec]:
    """The whole tasks a reference states when they cannot be the tasks its object names ("before you put
    a warm mug in the cabinet" next to "put a clean mug under the coffee maker"); else none."""
    if not named:
        return []
    # a task the reference states has a destination or a lamp (`TaskBuilder.spec` drops the others), though
    # the scene may not know its word ("put a cold cup on a stand"): the learned filler may ground it
    new = new_tasks_from_ref(ref, b, text)
    if not new:
        return []
    # "after you put a watch on a table": an indefinite object is another one than the task's
    words = [w for w, _, _ in tokens(_YOU.sub("", ref))][1:3]
    if any(w in {"a", "an", "another"} for w in words):
        return new
    return new if all(_differ(n, o) for n in new for o in named) else []
