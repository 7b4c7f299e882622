"""Step 4b, tasks: one draft (the frames about one object) -> a grounded `BaseTaskSpec`."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from nl2hltl2plan.domain.task_kinds import Kind
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.frames import (
    APPLIANCE_OF,
    ONLY_WHERE_IT_IS,
    PICKED_OWNER,
    THEN_TO,
    UNDER,
    Frame,
    Item,
    dest_of,
    is_fixed,
    near_dest,
    puts_into,
    same,
)
from nl2hltl2plan.language.grammar.phrases import DETERMINERS, FILLER, NP, parse_np, tokens
from nl2hltl2plan.language.grounding import (
    THOR_TYPES,
    AffordanceLookup,
    Grounder,
    Roles,
    alfred_lookup,
    find_mentions,
)
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.worlds.world import Affordances


@dataclass
class Draft:
    """A base task being assembled from frames."""

    frames: list[tuple[Frame, Item]]
    start: int
    end: int
    group: int = -1
    label: str = ""  # own text for one item of a list clause ("put plates into the lower rack")
    tool: bool = False  # only picked up a knife that a later clause slices with: no task of its own

    @property
    def obj(self) -> NP | None:
        for _, it in self.frames:
            if it.obj is not None and not it.obj.pronoun and not it.obj.empty and not it.obj.is_lamp():
                return it.obj
        return None


@dataclass
class Unit:
    """The tasks of one clause (or one sentence part) and the temporal markers that apply to them."""

    tasks: list[int]
    sentence: int
    markers: list[tuple[str, str]] = field(default_factory=list)  # (kind, ref text)
    seq_after_prev: bool = False  # joined to the previous clause by "then" inside a sentence
    joiner: str = ""  # the word that joins it to the clause before ("and", "then"; "" for a comma alone)


@dataclass
class Tasks:
    """The result of step 4: the base tasks the drafts state, the noun phrase each is about, the temporal
    units (task indices into `specs`) and the groups (group number -> task indices)."""

    specs: list[BaseTaskSpec]
    nps: list[NP | None]
    units: list[Unit]
    groups: dict[int, list[int]]


def build_tasks(drafts: list[Draft], units: list[Unit], b: TaskBuilder, text: str) -> Tasks:
    """Ground every draft; drafts that state no task are dropped (and the units' indices follow)."""
    specs = [None if d.tool else b.spec(d, d.label or text[d.start : d.end]) for d in drafts]
    keep = [i for i, s in enumerate(specs) if s is not None]
    index = {old: new for new, old in enumerate(keep)}
    for u in units:
        u.tasks = [index[t] for t in u.tasks if t in index]
    groups: dict[int, list[int]] = {}
    for old, new in index.items():
        if drafts[old].group >= 0:
            groups.setdefault(drafts[old].group, []).append(new)
    return Tasks(
        specs=[s for s in specs if s is not None],
        nps=[drafts[i].obj for i in keep],
        units=[u for u in units if u.tasks],
        groups=groups,
    )


class TaskBuilder:
    """Grounds drafts into `BaseTaskSpec`s; keeps what it cannot read (`unparsed`) and grounding `issues`."""

    def __init__(self, grounder: Grounder | None, strict: bool, look: AffordanceLookup | None = None) -> None:
        self.g = grounder
        self.look = look
        self.strict = strict
        self.issues: list[str] = []
        self.unparsed: list[str] = []

    # grounding -----------------------------------------------------------------------------------------
    def types(self, np: NP | None, role: str) -> list[str] | None:
        """The candidate types of a noun phrase (its own words, capitalised, when there is no scene)."""
        if np is None:
            return None
        if self.g is None:
            if np.entry is not None and not (np.head and len(np.head.split()) > 1):
                # no scene: keep words that distinguish objects the lexicon would merge ("red apple")
                spans = [(m.char_start, m.char_end) for m in find_mentions(np.text)]
                words = [
                    w
                    for w in tokens(np.text)
                    if w[0] not in DETERMINERS
                    and w[0] not in G.STATE_WORDS
                    and not any(a <= w[1] < b for a, b in spans)
                ]
                extra = [
                    w[0]
                    for w in words
                    if w[0] not in FILLER
                    and w[0] not in G.SLICE_NOUNS
                    and w[0] != ","
                    and w[0] not in G.NUMBERS
                ]
                if extra and np.entry.canonical not in {"KeyChain"}:
                    return ["".join(x.capitalize() for x in extra) + np.entry.canonical]
                return [np.entry.canonical] if not np.entry.all_ else list(np.entry.types)
            return ["".join(x.capitalize() for x in np.head.split())] if np.head else None
        if np.entry is None:
            msg = f"cannot map the {role} {np.head or np.text!r} to an object type of {self.g.scene}"
            if self.strict:
                raise WorldError(msg)
            self.issues.append(msg)
            return None
        got = self.g.candidates(np.entry)
        if not got:
            err = self.g.missing(np.entry, np.text)
            if self.strict:
                raise err
            self.issues.append(str(err))
            return [np.entry.canonical]
        return got

    def ground(
        self, kind: str, sliced: bool, nps: dict[str, NP | None]
    ) -> dict[str, list[str] | None] | None:
        """Types per field (object, container, receptacle, light): the scene's candidates of each word,
        narrowed to those that can play their role (`Roles.narrow`), then the first one unless the word
        accepts all ("table", "knife")."""
        got = {role: self.types(np, role) for role, np in nps.items()}
        if got["object"] is None:
            return None
        if self.g is None:
            return got
        roles = Roles(got["object"], got["receptacle"], got["container"], got["light"]).narrow(
            self.look, kind, sliced
        )
        self._no_holder(got, nps, sliced)
        out: dict[str, list[str] | None] = {}
        for role in nps:
            types, np = getattr(roles, role), nps[role]
            if types and np is not None and np.entry is not None and not np.entry.all_:
                types = types[:1]
            out[role] = types
        return out

    def _not_the_source(self, places: list[str] | None, d: Draft) -> list[str] | None:
        """ "move a bowl and a watch from the desk to the table": the table is not the desk; a word of several
        types loses the one type that the place the thing comes from names alone (never its last one)."""
        if self.g is None or places is None or len(places) < 2:
            return places
        sources: set[str] = set()
        for _, it in d.frames:
            for p, np in it.pps:
                if p == "from" and np.entry is not None and len(got := self.g.resolve(np.entry)) == 1:
                    sources.update(got)
        return [t for t in places if t not in sources] or places

    def _no_holder(self, got: dict[str, list[str] | None], nps: dict[str, NP | None], sliced: bool) -> None:
        """A word of several types ("bar": a soap bar or a towel bar) as the place of a thing none of its
        types can hold ("put the mug on the bar" where the only bar is soap) is unread, not the first type."""
        held = got["container"] or got["object"] or []
        place, np = got["receptacle"], nps.get("receptacle")
        several = np is not None and np.entry is not None and len(np.entry.types) > 1
        if self.look is None or np is None or not several or not place or not held:
            return
        if not any(self.can_hold([p], held, sliced and not got["container"]) for p in place):
            self.unparsed.append(f"nothing named {np.text!r} here can hold the {held[0]}")

    def can_hold(self, containers: list[str] | None, objects: list[str], sliced: bool) -> bool:
        """Can one of the container types hold one of the object types? Not itself ("the mug in the mug"),
        nor what its affordances say it does not accept (a mug holds utensils, not an apple); unknown
        types can."""
        cont = containers or []
        if set(cont) & set(objects):
            return False
        look = self.look
        if look is None:
            return True
        for c in cont:
            a = look(c)
            if a is None or any(
                look(o) is None or o in a.accepts or (sliced and o + "Sliced" in a.accepts) for o in objects
            ):
                return True
        return not cont

    # one draft -> BaseTaskSpec ------------------------------------------------------------------------
    def spec(self, d: Draft, text: str) -> BaseTaskSpec | None:
        """The base task a draft states, or None (with the reason in `unparsed`) when it states none."""
        r = _Reading()
        for fr, it in d.frames:
            _read_frame(r, fr, it, self.look)
        obj = r.obj
        if obj is None:
            if r.light is not None:
                self.unparsed.append(f"nothing to hold under the lamp in: {text}")
            elif d.frames and d.frames[0][0].cls not in {"none", "other"}:
                self.unparsed.append(f"no object to act on in: {text}")
            return None
        picked = _picked_owner(obj, r.container)
        if picked:
            self.unparsed.append(f"{picked!r} {PICKED_OWNER}: {text}")
            return None
        if (r.light is not None or r.examine) and _unholdable(obj):
            self.unparsed.append(f"cannot hold the {obj.text!r} to look at it: {text}")
            return None
        final = _settle_container(r, obj)
        unknown = next((np for np in r.dests if np is not final and np.entry is None and np.head), None)
        if unknown is not None and self.g is not None:
            # "put a knife in a goblet, move both to a counter": a place on the way that no word of this
            # world names was dropped, and the goblet with it; unread, never a plain placement
            self.unparsed.append(
                f"{unknown.head!r} (place): no object of this world is called so, in: {text}"
            )
            return None
        if r.light is None and r.examine:
            r.light = parse_np("lamp")
        said = _treatments_said(d)
        if len(said) > 1:  # "chill then warm a tomato": one task has one treatment; which is meant is a guess
            self.unparsed.append(f"two treatments ({' and '.join(sorted(said))}) of one object in: {text}")
            return None  # (before a missing destination: no reading of the clause may drop one of them)
        if r.light is None and final is None:  # "the mug from the sink": the model must not make it the place
            pps = [p for _, it in d.frames for p, _ in it.pps]
            source = "from" in pps and not any(p in G.DEST_PREPS or p == "to" for p in pps)
            where = f" ({ONLY_WHERE_IT_IS})" if source else ""
            self.unparsed.append(f"no destination for the {obj.text or obj.key!r} in: {text}{where}")
            return None
        kind = _kind_of(r)
        untreated = said - _treated_where(final)
        if kind == "place_in_container" and untreated:
            # "place a chilled head of lettuce on a plate on a counter": no base task both treats a thing
            # and puts it in a container ("refrigerate a slice in a bowl" ends in the fridge: that is the
            # chilling); dropping the treatment would be a guess
            treated = f"a {min(untreated)}ed thing in a container"
            self.unparsed.append(f"{treated} (no base task does both) in: {text}")
            return None
        fields = self.ground(
            kind,
            r.sliced,
            {
                "object": obj,
                "container": r.container if kind == "place_in_container" else None,
                "receptacle": final if kind != "examine_in_light" else None,
                "light": r.light if kind == "examine_in_light" else None,
            },
        )
        if fields is None or fields["object"] is None:
            self.unparsed.append(f"no object of the scene named in: {text}")
            return None
        fields["receptacle"] = self._not_the_source(fields["receptacle"], d)
        held_in = fields["container"] if kind == "place_in_container" else None
        if held_in is not None and not self.can_hold(held_in, fields["object"], r.sliced):
            # "put the mug and the apple in the sink": two things to move, not an apple inside a mug
            held, holder = "/".join(fields["object"]), "/".join(held_in)
            self.unparsed.append(f"a {holder} cannot hold a {held} in: {text}")
            return None
        return BaseTaskSpec(
            kind=kind,
            object=fields["object"],
            count=r.count,
            sliced=r.sliced and _sliceable(fields["object"]),
            text=text,
            container=fields["container"],
            receptacle=fields["receptacle"],
            light=fields["light"],
        )


def _treatments_said(d: Draft) -> set[str]:
    """The treatments (heat, cool, clean) that the draft's verbs and state words say; water and the
    appliances passed on the way are not counted."""
    said = {fr.cls for fr, _ in d.frames}
    said |= {s for _, it in d.frames if it.obj is not None for s in it.obj.states}
    return said & {"heat", "cool", "clean"}


def _sliceable(types: list[str]) -> bool:
    """ "both pieces of soap" are whole soap bars: only what a knife can slice is ever sliced."""
    return any(t in G.SLICEABLE or t not in THOR_TYPES for t in types)


@dataclass
class _Reading:
    """What the frames of one draft say about its task, gathered frame by frame."""

    obj: NP | None = None
    container: NP | None = None
    light: NP | None = None
    states: list[str] = field(default_factory=list)
    sliced: bool = False
    count: int = 1
    examine: bool = False
    dests: list[NP] = field(default_factory=list)
    slice_next: bool = False  # "slice then cool the tomato": a bare "slice" before the object is named


def _read_frame(r: _Reading, fr: Frame, it: Item, look: AffordanceLookup | None) -> None:
    """Add what one clause item says: its verb's state change, its object, its phrases, its destination."""
    o = it.obj
    if fr.cls in {"clean", "heat", "cool"}:
        r.states.append(fr.cls)
    if fr.cls == "fill":
        r.states.append("clean")
    if fr.cls == "slice":
        r.sliced = r.sliced or r.obj is not None or (o is not None and not o.pronoun)
        r.slice_next = r.obj is None and o is None and not it.pps
    if fr.cls == "examine":
        r.examine = True
    if o is not None and o.is_lamp() and fr.cls in {"light", "examine"}:
        r.light = o
        o = None
    for np in [o] + [np for _, np in it.pps]:
        if np is not None and np.is_lamp() and (fr.cls in {"light", "examine", "pick"} or fr.light_on):
            r.light = r.light or np
    if o is not None and r.container is None and puts_into(r.obj, fr, it):
        r.container, r.obj = r.obj, o  # "move a cup to the sink and put a knife in the cup"
    if o is not None and r.container is None and r.obj is not None and _holds_it(o, r.obj, it):
        r.container = o  # "slice a tomato and put a pot with a tomato slice in it on the table"
    if o is not None:
        _read_object(r, o)
    for p, np in it.pps:
        _read_pp(r, fr, it, p, np, look)
    _read_destination(r, fr, it)


def _holds_it(o: NP, thing: NP, it: Item) -> bool:
    """Is `o` a movable container said to hold the task's thing ("a pot with a tomato slice in it")?"""
    return o.is_movable_receptacle() and any(
        p in G.WITH_PREPS and (same(np, thing) or (np.sliced and np.entry is None)) for p, np in it.pps
    )  # ("a pot containing a slice": the slice of the thing cut before)


def _read_object(r: _Reading, o: NP) -> None:
    """The first object is the task's; a later one may be its container or a lamp."""
    if not o.pronoun and not o.empty:
        if r.obj is None:
            r.obj = o
            r.sliced = r.sliced or r.slice_next
        elif r.container is None and r.dests and same(o, r.dests[-1]) and o.is_movable_receptacle():
            r.container = o  # "put a card in a bowl and put the bowl on the desk"
        elif same(o, r.container):
            pass
        elif not same(o, r.obj) and o.is_lamp():
            r.light = o
    r.states += sorted(o.states)
    r.sliced = r.sliced or o.sliced
    if o.water:
        r.states.append("clean")
    r.count = max(r.count, o.count)


def _read_pp(r: _Reading, fr: Frame, it: Item, p: str, np: NP, look: AffordanceLookup | None) -> None:
    """ "with X in it", "containing X", "holding X", "along with the other set", "by the light of a lamp",
    and a second listed object ("a bowl and a pencil")."""
    if p in {"along with", "together with"} and np.entry is None and not np.head:
        r.count = max(r.count, 2)  # "one set of keys along with the other set"
        return
    if p in G.WITH_PREPS and not np.pronoun and _read_with(r, fr, it, p, np, look):
        return
    if p in G.LIGHT_PREPS and np.is_lamp():
        r.light = np
    if (
        p in UNDER
        and r.container is None
        and r.obj is not None
        and r.obj.is_movable_receptacle()
        and fits_in(np, r.obj, look)
    ):
        # "move a pan beneath a tomato slice on the table", "put a plate under the spatula": the container
        # is slid under the thing, which ends up in it (ALFRED's "pick and place with a movable receptacle")
        r.container, r.obj = r.obj, np
        r.sliced = r.sliced or np.sliced
        return
    if p == "" and np.entry is not None and r.obj is not None and not np.pronoun and r.container is None:
        # "a bowl and a pencil": one movable receptacle and its content
        if r.obj.is_movable_receptacle() and not np.is_movable_receptacle():
            r.container, r.obj = r.obj, np
        elif np.is_movable_receptacle() and not r.obj.is_movable_receptacle():
            r.container = np
        elif same(np, r.obj):
            r.count = max(r.count, 2)


def fits_in(np: NP, container: NP, look: AffordanceLookup | None) -> bool:
    """Does the noun phrase name a thing a hand picks up (a knife, a tomato slice) that the container
    holds, by the world's affordances (`look`; none: no)? Not a receptacle, a lamp or a fixed thing
    ("under the faucet", "under the sink" say where), nor what the container does not take ("the pan
    under the kettle")."""
    if look is None or np.entry is None or container.entry is None or np.pronoun:
        return False
    if np.is_receptacle() or np.is_lamp():
        return False
    facts = [look(t) for t in np.entry.types]
    holders = [look(t) for t in container.entry.types]
    return (
        bool(facts)
        and all(f is not None and f.pickupable for f in facts)
        and all(
            h is not None and any(t in h.accepts or t + "Sliced" in h.accepts for t in np.entry.types)
            for h in holders
        )
    )


def _read_with(r: _Reading, fr: Frame, it: Item, p: str, np: NP, look: AffordanceLookup | None) -> bool:
    """One "with"-like phrase; True when it is settled (nothing else to read from it)."""
    if p == "with" and is_fixed(np):
        return True  # "place it with the coffee machine": the destination (dest_of)
    if np.water:
        r.states.append("clean")
        return True
    if np.is_lamp():
        if fr.cls != "place" or fr.light_on or dest_of(it, fr.cls) is None:
            r.light = np  # "examine the box with the lamp"
        # else "put the box on the dresser with the lamp": which dresser, no light (check 1 judges it)
        return True
    if p in {"along with", "together with"} and (same(np, r.obj) or np.entry is None):
        r.count = max(r.count, 2)
        return True
    if r.obj is None and (r.light is not None or fr.cls == "light" or fr.light_on):
        r.obj = np  # "turn on a lamp with a book in hand"
        return True
    if r.obj is not None and np.entry is not None and r.container is None:
        # "the mug with a pencil in it": the pencil goes in the mug; "the dresser with the television": the
        # television, which no hand picks up, only says which dresser (check 1 judges it as a landmark)
        if np.is_movable_receptacle():
            r.container = np
        elif r.obj.is_movable_receptacle() and (_said_inside(it, np) or _holdable(np, r.obj, look)):
            r.container, r.obj = r.obj, np  # (a content said, "with a ball in it", is checked after)
    r.states += sorted(np.states)
    r.sliced = r.sliced or np.sliced
    return False


def _said_inside(it: Item, np: NP) -> bool:
    """ "a bowl with a ball in it": the phrase after "with X" puts X in or on the receptacle ("it")."""
    at = next((k for k, (_, n) in enumerate(it.pps) if n is np), -1)
    after = it.pps[at + 1] if 0 <= at < len(it.pps) - 1 else None
    return after is not None and after[1].pronoun and after[0] in {"in", "on", "inside", "into", "onto"}


def _holdable(np: NP, holder: NP, look: AffordanceLookup | None) -> bool:
    """Can the noun phrase name a thing a hand picks up that one of the holder's types takes (a pencil in
    a mug, which may be a Mug or a Cup)? By the world's affordances, else ALFRED's for a type the world
    did not build ("the dresser with the television" where the floor plan's objects lack it); a type no
    facts know, or no facts at all (no scene), can. Not: "the dresser with the laptop" (no mug takes a
    laptop) says which dresser."""
    if look is None or np.entry is None or holder.entry is None:
        return True
    alfred = alfred_lookup()

    def facts(t: str) -> Affordances | None:
        return look(t) or (alfred(t) if alfred is not None else None)

    held = [(t, facts(t)) for t in np.entry.types]
    holders = [facts(t) for t in holder.entry.types]
    return any(
        f is None or (f.pickupable and any(h is None or {t, t + "Sliced"} & h.accepts for h in holders))
        for t, f in held
    )


# a verb that itself says the thing goes to the bin ("throw away", "discard"); after it "in the fridge" is
# where the thing is, where "toss the apple in the sink" may say where it lands
_THROWN_AWAY = re.compile(r"\b(?:away|out|discard|dispose|get\s+rid)\b", re.I)


def _read_destination(r: _Reading, fr: Frame, it: Item) -> None:
    """Where the item goes (stops on the way first); "in a cup to the counter" also names a container."""
    # "throw away the apple next to the sink", "grab the mug by the sink.": the sink says which one; the
    # verb (or the next clause) says where it goes
    dst = dest_of(it, fr.cls) or (near_dest(it) if fr.cls not in ("trash", "pick") else None)
    if any(p == THEN_TO for p, _ in it.pps):  # stops on the way come before the destination
        r.dests += [np for p, np in it.pps if p in G.DEST_PREPS and np.is_receptacle() and np is not dst]
    binned = dst is not None and dst.entry is not None and "GarbageCan" in dst.entry.types
    if fr.cls == "trash" and dst is not None and not binned and _THROWN_AWAY.search(fr.text):
        dst = None  # "throw away the apple in the fridge": the fridge is where it is; away is the bin
    if fr.cls == "trash" and dst is None:
        dst = parse_np("garbage can")
    if dst is None or dst.is_lamp():
        return
    recs = [np for p, np in it.pps if p in G.DEST_PREPS and np.is_receptacle() and p not in UNDER]
    movable = [np for np in recs if np.is_movable_receptacle()]
    fixed = [np for np in recs if not np.is_movable_receptacle()]
    obj = r.obj
    held = obj is not None and not obj.is_movable_receptacle()
    if fr.cls in _APPLIANCE_NP and movable and not fixed and held:
        # "refrigerate a tomato slice in a bowl": the bowl holds it in the fridge, it is no destination
        r.container = movable[0]
        r.dests += [r.container, parse_np(_APPLIANCE_NP[fr.cls])]
        return
    if obj is not None and r.container is None and not obj.is_movable_receptacle() and movable and fixed:
        # "place the spoon in a cup to the counter", "place the watch on the table on a plate"
        r.container = movable[0]
        r.dests.append(r.container)
        dst = fixed[-1]
    r.dests.append(dst)


# an ordinal before a possessive owner: "the second drawer's spoon", "the 3rd shelf's vase"
_PICKED_OWNER = re.compile(
    r"\b(?:first|second|third|fourth|fifth|last|\d+(?:st|nd|rd|th))\s+(?:[a-z]+\s+)?[a-z]+'s\b", re.IGNORECASE
)

def _picked_owner(*nps: NP | None) -> str:
    """ "the second drawer's spoon": which spoon is said by which of the drawers it is in, and the spec's
    atoms name types (any spoon does), so the words are unread; "the drawer's spoon" is "the spoon from the
    drawer", a source, as "from" is read."""
    found = (_PICKED_OWNER.search(np.text) for np in nps if np is not None)
    return next((m.group(0) for m in found if m is not None), "")


# the appliance a verb of heating or cooling does its work in
_APPLIANCE_NP = {"heat": "microwave", "cool": "fridge"}


def _unholdable(obj: NP) -> bool:
    """A fixed receptacle (not a box) cannot be held under a lamp."""
    return (
        obj.is_receptacle()
        and not obj.is_movable_receptacle()
        and obj.entry is not None
        and obj.entry.canonical not in {"Box"}
    )


def _settle_container(r: _Reading, obj: NP) -> NP | None:
    """The final destination; a content placed into a movable receptacle that is then moved gets that
    receptacle as its container, and appliances on the way add their state change."""
    dests, container = r.dests, r.container
    final = dests[-1] if dests else None
    if (
        container is None
        and len(dests) >= 2
        and dests[-2].is_movable_receptacle()
        and not (obj.is_movable_receptacle())
    ):
        container = dests[-2]
    if container is not None and final is not None and same(final, container):
        final = dests[-2] if len(dests) >= 2 and not same(dests[-2], container) else None
        if final is None:
            container = None
            final = dests[-1]
    # intermediate appliances imply a state change ("put it in the microwave, then on the counter")
    for mid in dests[:-1]:
        if mid.entry is not None and not same(mid, container):
            st = {"Microwave": "heat", "Fridge": "cool", "SinkBasin": "clean"}.get(mid.entry.canonical)
            if st:
                r.states.append(st)
    r.container = container
    return final


def _treated_where(place: NP | None) -> set[str]:
    """The treatment that leaving a thing in `place` makes (the fridge chills it), if any."""
    canonical = place.entry.canonical if place is not None and place.entry is not None else None
    return {st for st, appliance in APPLIANCE_OF.items() if appliance == canonical}


_STATE_KINDS: dict[str, Kind] = {"heat": "heat_place", "cool": "cool_place", "clean": "clean_place"}


def _kind_of(r: _Reading) -> Kind:
    """The task kind, once the object and (unless a lamp is involved) the destination are known."""
    state = next((s for s in ("heat", "cool", "clean") if s in r.states), None)
    if r.light is not None:
        return "examine_in_light"
    if r.container is not None:
        return "place_in_container"
    if state:
        return _STATE_KINDS[state]
    return "place_two" if r.count >= 2 else "place"
