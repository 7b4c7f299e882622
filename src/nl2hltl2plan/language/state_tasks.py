"""Clauses that change one object's state or treat one object without moving it anywhere: SMART-LLM's
skills and goals ("turn on the laptop", "switch off the light", "break a vase", "slice the tomato",
"open the book", "pick up the pillow", "wash the knife", "chill the apple", "toast a slice of bread"),
and goals that only name the state of a room ("make the kitchen dark": its lights off).

The grammar reads tasks that move objects; a clause it leaves unread (`unparsed`) is read here when it
is nothing but such a verb and one object of the scene that can take it:
- a state verb gives a `set_state` base task (`worlds.tasks`), whose recipe is the one action (a slice
  also takes a knife; a toast puts the slice into a toaster and switches it on);
- a treatment verb with no destination (wash / rinse / clean, chill / cool / refrigerate, heat / warm /
  microwave / cook) gives ALFRED's clean / cool / heat task with no receptacle: the treated state is
  the whole goal, and the object stays in the sink, fridge or microwave;
- a room's light state ("make the room dark", "darken the kitchen", "light up the room") is the room's
  light switch off or on; "in a well lit room" / "in the dark" after a clause switches the lights
  first and orders the clause after it. A room word that names another kind of room than the scene's
  floor plan (the kitchen of a bathroom) is refused.
"all the X" / "every X" takes the scene's one X; with several, the clause is refused (a state task
switches one object). Anything else in the object phrase leaves the clause unread (refused).

>>> from nl2hltl2plan.language.grounding import Grounder
>>> read_state_clause("Turn on the laptop", Grounder({"Laptop", "Desk"})).summary()
'set_state Laptop on'
>>> read_state_clause("wash the mug", Grounder({"Mug", "SinkBasin"})).summary()
'clean_place Mug -> ?'
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.content_words import LOCATIVE, Unread, categories, stems, verb_places
from nl2hltl2plan.language.grounding import LAMPS, Grounder, find_mentions, tokens
from nl2hltl2plan.language.task_specs import BaseTaskSpec

_DET = r"(?:the|a|an|my|that|this|your|our)\s+"
_ALL = r"(?:all\s+(?:of\s+)?(?:the\s+)?|every\s+|each\s+)"
# (pattern, kind, state): state "" = read "on"/"off" from the text
_RULES: tuple[tuple[str, str, str], ...] = (
    (r"^(?:turn|switch|power|put)\s+(on|off|out)\s+(?P<obj>.+)$", "set_state", ""),
    (r"^(?:turn|switch|power)\s+(?P<obj>.+?)\s+(on|off|out)$", "set_state", ""),
    (r"^(?:break|smash|shatter)\s+(?P<obj>.+)$", "set_state", "broken"),
    (r"^(?:slice|cut|chop)\s+(?:up\s+)?(?P<obj>.+)$", "set_state", "sliced"),
    # "get the potato sliced", "the bread needs cutting up" (h173; the grammar reads them via treatments_said)
    (r"^(?:get|have)\s+(?P<obj>.+?)\s+(?:sliced|cut|chopped)(?:\s+up)?$", "set_state", "sliced"),
    (
        r"^(?P<obj>.+?)\s+needs?\s+(?:slicing|cutting|chopping|to\s+be\s+(?:sliced|cut|chopped))(?:\s+up)?$",
        "set_state",
        "sliced",
    ),
    (r"^open\s+(?:up\s+)?(?P<obj>.+)$", "set_state", "open"),
    (r"^(?:close|shut)\s+(?P<obj>.+)$", "set_state", "closed"),
    (r"^(?:pick\s+up|grab|take|lift)\s+(?P<obj>.+)$", "set_state", "held"),
    (r"^(?:pick|grab|take|lift)\s+(?P<obj>.+?)\s+up$", "set_state", "held"),
    (r"^toast\s+(?P<obj>.+)$", "set_state", "toasted"),
    (
        r"^(?:get\s+rid\s+of|throw\s+(?:away|out)|dispose\s+of|discard|bin|trash)\s+(?P<obj>.+)$",
        "place",
        "trash",
    ),
    (r"^(?:throw|toss|chuck)\s+(?P<obj>.+?)\s+(?:away|out)$", "place", "trash"),
    (r"^(?:wash|rinse|clean|scrub)\s+(?:off\s+|up\s+)?(?P<obj>.+?)(?:\s+(?:off|up))?$", "clean_place", ""),
    (r"^(?:chill|cool|refrigerate)\s+(?:down\s+)?(?P<obj>.+?)(?:\s+down)?$", "cool_place", ""),
    (r"^(?:heat|warm|reheat|microwave|cook)\s+(?:up\s+)?(?P<obj>.+?)(?:\s+up)?$", "heat_place", ""),
)
LIGHT_WORDS = {
    "light",
    "lights",
    "the light",
    "the lights",
    "light switch",
    "light switches",
    "ceiling light",
}
# a slice named as such: "a slice of the bread", "two slices of bread", "the bread slice", "sliced bread"
_SLICE = re.compile(
    r"^(?:(?:a|one|some|the)\s+)?(?:slices?|pieces?)\s+of\s+(?P<a>.+)$|^(?P<b>.+?)\s+slices?$|^sliced\s+(?P<c>.+)$"
)

# ---- rooms and their light -------------------------------------------------------------------------
ROOMS = r"(?:room|kitchen|living\s+room|lounge|bedroom|bathroom|restroom|house|home|flat|apartment|place)"
DARK = r"(?:dark|darker|dim|dimmer|unlit|pitch\s+dark|pitch\s+black)"
LIT = r"(?:lit|well[-\s]+lit|brightly\s+lit|bright|brighter|light|illuminated)"
_ROOM_STATE = (
    (
        rf"^(?:make|get|leave|keep|have|render)\s+(?:{_DET})?(?P<room>{ROOMS})\s+(?:nice\s+and\s+|very\s+|completely\s+|fully\s+)?{DARK}$",
        "off",
    ),
    (
        rf"^(?:make|get|leave|keep|have|render)\s+(?:{_DET})?(?P<room>{ROOMS})\s+(?:nice\s+and\s+|very\s+|well\s+)?{LIT}$",
        "on",
    ),
    (rf"^(?:darken|dim)\s+(?:{_DET})?(?P<room>{ROOMS})$", "off"),
    (rf"^(?:brighten|illuminate|light)\s+(?:up\s+)?(?:{_DET})?(?P<room>{ROOMS})(?:\s+up)?$", "on"),
)
# a light condition ending a clause: "open a book in a well lit room", "... with the lights off"
_CONDITION = re.compile(
    rf"\s+(?:(?:in|inside)\s+(?:{_DET})?(?:(?P<dark>{DARK})|{LIT})(?:\s+(?P<room>{ROOMS}))?"
    r"|with\s+(?:the\s+)?lights?\s+(?:switched\s+|turned\s+)?(?P<state>on|off))$"
)
# which AI2-THOR floor plans are which room (ai2thor.allenai.org/ithor/documentation/scenes)
ROOM_KINDS = {"kitchen": (1, 30), "living room": (201, 230), "bedroom": (301, 330), "bathroom": (401, 430)}
_ROOM_SYNONYMS = {"lounge": "living room", "restroom": "bathroom"}


def read_state_clause(
    clause: str,
    grounder: Grounder,
    pronoun: str | Sequence[str] | None = None,
    counts: Mapping[str, int] | None = None,
    can: Callable[[str, str], bool] | None = None,
) -> BaseTaskSpec | None:
    """A task for a clause that is one state or treatment verb and one object, or a room's light
    state (None: not such a clause). `pronoun`: the object type(s) "it" may stand for, nearest first;
    `counts`: instances per type, to refuse "all the X" when the scene holds several; `can(type,
    state)`: whether objects of a type can take a state."""
    pronouns = [pronoun] if isinstance(pronoun, str) else list(pronoun or [])
    return _read(clause, StateReader(grounder, counts, can), pronouns)


def _read(clause: str, scene: StateReader, pronouns: list[str]) -> BaseTaskSpec | None:
    text = _normal(clause)
    clause = re.sub(r"^(?:(?:and|then|also)\s+)+", "", clause.strip(), flags=re.IGNORECASE)
    light = _room_light(text, scene)
    if light is not None:
        return BaseTaskSpec(kind="set_state", text=clause.strip(), object=["LightSwitch"], state=light)  # type: ignore[arg-type]
    for pattern, kind, state in _RULES:
        m = re.match(pattern, text)
        if m is None:
            continue
        state = state or next((g for g in m.groups() if g in ("on", "off", "out")), "")
        state = {"out": "off"}.get(state, state)
        phrase, sliced = _slice_phrase(m.group("obj").strip())
        types = _ground(phrase, state, scene, pronouns)
        if not types or (sliced and kind == "set_state" and state != "toasted"):
            continue
        if kind == "set_state":
            return BaseTaskSpec(
                kind="set_state",
                text=clause.strip(),
                object=types,
                state=state,  # type: ignore[arg-type]
                sliced=sliced,
            )
        if kind == "place":  # thrown away: into the scene's garbage can
            trash = _ground("garbage can", "", scene, [])
            return (
                BaseTaskSpec(kind="place", text=clause.strip(), object=types, sliced=sliced, receptacle=trash)
                if trash
                else None
            )
        return BaseTaskSpec(kind=kind, text=clause.strip(), object=types, sliced=sliced)  # type: ignore[arg-type]
    return None


def _normal(clause: str) -> str:
    text = " ".join(re.sub(r"[.!?,;]+$", "", clause.strip()).split()).lower()
    polite = r"(?:could|can|would|will)\s+you\s+(?:please\s+)?|i\s+(?:want|need|would\s+like)\s+you\s+to\s+"
    return re.sub(rf"^(?:please\s+|then\s+|and\s+|also\s+|now\s+|first\s+|finally\s+|{polite})+", "", text)


def _slice_phrase(phrase: str) -> tuple[str, bool]:
    """("bread", True) for "a slice of the bread"; the phrase itself otherwise."""
    m = _SLICE.match(phrase)
    if m is None:
        return phrase, False
    return next(g for g in m.groups() if g), True


def _ground(word: str, state: str, scene: StateReader, pronouns: list[str]) -> list[str]:
    if word in ("it", "them"):
        fit = [p for p in pronouns if scene.can is None or scene.can(p, state)]
        return fit[:1]
    every = re.match(_ALL, word)
    word = re.sub(rf"^{_ALL}|^{_DET}", "", word)
    g = scene.grounder
    room = re.search(rf"\s+(?:in|of)\s+(?:{_DET})?(?P<room>{ROOMS})$", word) or re.match(
        rf"^(?P<room>{ROOMS})\s+(?=\w)", word
    )
    if room is not None:  # "the lights in the kitchen", "the bedroom lamp": the scene's own room
        word = word[: room.start()] if room.start() else word[room.end() :]
    lamps = g.types is not None and bool(g.types & LAMPS)
    lamp_word = word in ("lamp", "lamps") and not lamps  # a room without lamps: its light
    if state in ("on", "off") and (word in LIGHT_WORDS or lamp_word) and g.types and "LightSwitch" in g.types:
        types = ["LightSwitch"]  # the room's lights
    elif not _one_thing(word):
        return []
    else:
        try:
            types = g.ground(word, "object")
        except WorldError:
            return []
    if every and scene.counts is not None:
        several = [t for t in types if scene.counts.get(t, 0) > 1]
        if several:
            n = scene.counts[several[0]]
            raise HTTError(
                f"{word!r}: {g.scene} holds {n} of them; a state request acts on one object, so name "
                "each one it should change"
            )
    return types


_NOT_A_NAME = LOCATIVE | {"to", "into", "onto", "toward", "towards", "while", "then", "and", "or"}
_VERBS = {
    "verb_any",
    "verb_take",
    "verb_step",
    "verb_switch",
    "verb_heat_place",
    "verb_cool_place",
    "verb_clean_place",
}


def _one_thing(phrase: str) -> bool:
    """Is the phrase one object's name, with nothing after it ("the red mug", not "the mug on the
    table": a place there is for the grammar, or is not understood)?"""
    toks = tokens(phrase)
    mentions = find_mentions(phrase)
    if not mentions:
        return len(toks) == 1  # a type name the lexicon lacks is left to the grounder
    last = mentions[-1]
    if last.end != len(toks) or any(m.end != last.start for m in mentions[:-1]):
        return False  # words after the name, or a second thing named ("the lamp while holding a vase")
    return not any(w in _NOT_A_NAME or categories(w) & _VERBS for w, _, _ in toks[: last.start])


def _room_light(text: str, scene: StateReader) -> str | None:
    """ "on" / "off" when the clause only asks for a room to be lit or dark (None: it does not)."""
    for pattern, state in _ROOM_STATE:
        m = re.match(pattern, text)
        if m is not None:
            _check_room(m.group("room"), scene.grounder)
            return state
    return None


def _check_room(room: str | None, grounder: Grounder) -> None:
    """Refuse a room goal in a scene without a light switch, or naming another kind of room than the
    scene's floor plan (an object's room, "the bedroom lamp", is not checked: it only says which)."""
    if grounder.types is not None and "LightSwitch" not in grounder.types:
        raise WorldError(f"no light switch in {grounder.scene}: its lights cannot be switched")
    word = " ".join((room or "").split())
    word = _ROOM_SYNONYMS.get(word, word)
    number = re.fullmatch(r"FloorPlan(\d+)", grounder.scene)
    if word not in ROOM_KINDS or number is None:
        return
    kind = next((k for k, (lo, hi) in ROOM_KINDS.items() if lo <= int(number.group(1)) <= hi), None)
    if kind is not None and kind != word:
        raise WorldError(f"'the {word}': {grounder.scene} is a {kind}, not a {word}")


def light_condition(clause: str, grounder: Grounder) -> tuple[str, BaseTaskSpec | None]:
    """Split a light condition off the end of a clause: ("Open a book", lights-on task) for "Open a
    book in a well lit room"; (clause, None) without one."""
    text = re.sub(r"[.!?,;\s]+$", "", clause)
    m = _CONDITION.search(text.lower())
    if m is None or _lamp_light(text[: m.start()], m, grounder):
        return clause, None
    _check_room(m.group("room"), grounder)
    state = m.group("state") or ("off" if m.group("dark") else "on")
    head, tail = text[: m.start()].rstrip(), text[m.start() :].strip()
    return head, BaseTaskSpec(kind="set_state", text=tail, object=["LightSwitch"], state=state)  # type: ignore[arg-type]


def _lamp_light(head: str, m: re.Match[str], grounder: Grounder) -> bool:
    """Is a light condition the lamp a thing is looked at by, not the room's light: "in the light" (no
    room word, not dark) after an examine clause ("look at the CD in the light", ALFRED's wording of an
    examine-in-light task), in a world that has a lamp? The grammar reads such a clause whole."""
    lamps = grounder.types is not None and bool(grounder.types & LAMPS)
    lit = m.group("room") is None and m.group("dark") is None and m.group("state") is None
    return lamps and lit and any("verb_examine_in_light" in categories(w) for w, _, _ in tokens(head))


_GUESS = re.compile(r"^'(?P<clause>.+)': its \w+ is not stated")
_PARTS = re.compile(r",\s*|;\s*|\s+and\s+|\s+(?=then\s)|(?<=[.!?])\s+")
_CONNECTIVE = re.compile(r"^(?:and|then|also)?$", re.IGNORECASE)


def _parts(text: str) -> list[str]:
    """A text's clauses: split at commas, semicolons, "and", "then" and sentence ends."""
    return [p for p in _PARTS.split(text) if not _CONNECTIVE.match(p.strip())]


@dataclass
class StateReader:
    """Reads clauses as state and treatment requests in one scene (see the module docstring): its types
    (grounder), how many of each it holds (to refuse "all the X" when there are several), and whether
    a type can take a state (for "it": the toaster, not the bread, is switched on)."""

    grounder: Grounder
    counts: Mapping[str, int] | None = None
    can: Callable[[str, str], bool] | None = None

    def read(self, text: str, pronouns: Sequence[str] = ()) -> list[BaseTaskSpec] | None:
        """Every part of `text` (split at commas, semicolons, "and" and sentence ends) read as a
        request, a light condition before the task it conditions; None when a part is no request.
        Tasks have no ids yet; `light_orders(tasks)` gives the conditions' pairs once they do."""
        out: list[BaseTaskSpec] = []
        for part in _parts(text):
            head, condition = light_condition(part, self.grounder)
            near = [*(x for t in reversed(out) for x in t.object[:1]), *pronouns]
            task = _read(head, self, near)
            if task is None:
                return None
            out += [condition, task] if condition is not None else [task]
        return out or None

    def read_unparsed(
        self, unparsed: list[str], context: Sequence[BaseTaskSpec] = ()
    ) -> tuple[list[BaseTaskSpec], list[str]]:
        """The requests among the parser's unread clauses (without ids) and the messages left unread.
        `context`: the parser's tasks, whose objects and places "it" may stand for."""
        from nl2hltl2plan.language.learned.rescue import failed_clauses

        tasks: list[BaseTaskSpec] = []
        left: list[str] = []
        done: set[str] = set()  # clause parts already read: the grammar names a clause, then its parts
        for msg in unparsed:
            guess = _GUESS.match(msg)
            clause = guess.group("clause") if guess else (failed_clauses([msg]) or [msg])[0]
            parts = {_normal(p) for p in _parts(clause)}
            if parts and parts <= done:
                continue
            near = [
                x for t in reversed([*context, *tasks]) for x in [*t.object[:1], *(t.receptacle or [])[:1]]
            ]
            read = self.read(clause, near)
            if read is None:
                left.append(msg)
                continue
            done |= parts
            tasks += read
        return tasks, left


def light_orders(tasks: Sequence[BaseTaskSpec]) -> list[tuple[str, str]]:
    """A light condition ("in a well lit room") comes first: (condition, the task after it) pairs."""
    return [
        (a.id, b.id)
        for a, b in zip(tasks, tasks[1:], strict=False)
        if a.object == ["LightSwitch"] and _CONDITION.search(" " + a.text.lower()) is not None
    ]


def reread(tasks: Sequence[BaseTaskSpec], instruction: str, reader: StateReader) -> list[list[BaseTaskSpec]]:
    """Per parsed task, the tasks it stands for: itself when its reading uses every word of its clause
    (as the instruction words it); otherwise (a word left unread, a place no word names) the clause's
    requests when it is nothing but requests ("wash the mug and turn off the lights", which the learned
    model reads as a lamp), or itself followed by the requests that end the clause ("put the bread in
    the toaster and turn it on")."""
    out: list[list[BaseTaskSpec]] = []
    for t in tasks:
        said = bool(t.text) and t.text.lower() in instruction.lower()
        if not said or not (account(t.text, [t], []) or guessed_slot(t, t.text)):
            out.append([t])  # the parser's reading uses every word of the clause: it stands
            continue
        read = reader.read(t.text)
        out.append(read if read is not None else [t, *_requests_after(t, reader)])
    return out


def _requests_after(task: BaseTaskSpec, reader: StateReader) -> list[BaseTaskSpec]:
    """The requests ending a moving task's clause that the parser passed over ("put the bread in the
    toaster and turn it on"): the longest run of final parts that read as requests, "it" standing
    for the task's object or place. A treatment or lamp task's own switching is not such a request."""
    if task.kind not in ("place", "place_two", "place_in_container"):
        return []
    parts = _parts(task.text)
    near = [*task.object[:1], *(task.receptacle or [])[:1], *(task.container or [])[:1]]
    for k in range(1, len(parts)):
        read = reader.read(", ".join(parts[k:]), near)
        if read is not None:
            return read
    return []


def guessed_slot(task: BaseTaskSpec, text: str) -> bool:
    """Does the task fill a place (receptacle, container, lamp) that no word of `text` names (a learned
    guess: "warm up the mug" -> onto the coffee machine)?"""
    named = {t for m in find_mentions(text) for t in m.entry.types}
    named |= {verb_places()[f] for w, _, _ in tokens(text) for f in stems(w) if f in verb_places()}
    slots = [task.receptacle, task.container, task.light]
    return any(types and not set(types) & named for types in slots)


_THEN = re.compile(r"\b(then|after that|afterwards|next|once done|finally|lastly)\b")
_LAST = re.compile(r"\b(finally|lastly)\b")


def state_orderings(
    instruction: str, tasks: list[BaseTaskSpec], states: list[BaseTaskSpec]
) -> list[tuple[str, str]]:
    """`before` pairs for state tasks that a sequence word introduces ("..., then slice the tomato"):
    after the task just before them ("finally": after every earlier task), as the annotation guide's
    "Then Y" / "Finally Y"; and an appliance switched on after the task that puts something into it,
    when the instruction says so in that order ("put the mug in the coffee machine and switch it on":
    the machine works on what is in it)."""
    low = instruction.lower()

    def at(t: BaseTaskSpec) -> int:
        return low.find(t.text.lower()) if t.text else -1

    pairs: list[tuple[str, str]] = []
    for s in states:
        start = at(s)
        earlier = sorted((at(t), t.id) for t in tasks if t.id != s.id and 0 <= at(t) < start)
        if start < 0 or not earlier:
            continue
        gap = low[max(0, start - 25) : start]
        if _LAST.search(gap):
            pairs += [(tid, s.id) for _, tid in earlier]
        elif _THEN.search(gap):
            pairs.append((earlier[-1][1], s.id))
        elif s.state == "on":
            before_it = {tid for _, tid in earlier}
            pairs += [(t.id, s.id) for t in tasks if t.id in before_it and _fills(t, s)]
    return list(dict.fromkeys(pairs))


def _fills(task: BaseTaskSpec, switch: BaseTaskSpec) -> bool:
    """Does `task` put its object into the appliance `switch` turns on (the faucet serves the sink)?"""
    into = set(task.receptacle or []) | set(task.container or [])
    return bool(into & set(switch.object)) or (
        "Faucet" in switch.object and bool(into & {"SinkBasin", "Sink"})
    )


_TREATED = ("clean_place", "cool_place", "heat_place")


def treated_apart(tasks: Sequence[BaseTaskSpec]) -> list[Unread]:
    """A treatment with no destination whose thing another task moves: "The cup and the pot both need
    chilling, and the cup goes on the table" read as a chilling of the cup and a placing of it, two goals
    for one cup (one says it stays in the fridge), where the words meant one task or left the pot's place
    unsaid (h242); refused by name, never solved."""
    out = []
    for t in tasks:
        if t.kind in _TREATED and not t.receptacle and any(
            o.receptacle and o.sliced == t.sliced and set(o.object) & set(t.object) for o in tasks
        ):
            why = "a thing treated in one task and moved in another: say it once ('heat X and put it ...')"
            out.append(Unread(t.text or t.id, "action", why))
    return out
