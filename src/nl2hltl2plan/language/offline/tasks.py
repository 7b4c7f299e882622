"""Step 4b, tasks: one draft (the frames about one object) -> a grounded `BaseTaskSpec`."""

from __future__ import annotations

from dataclasses import dataclass

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.grounding import AffordanceLookup, Grounder, Roles, find_mentions
from nl2hltl2plan.language.offline import grammar as G
from nl2hltl2plan.language.offline.frames import (
    THEN_TO,
    UNDER,
    Frame,
    Item,
    dest_of,
    is_fixed,
    near_dest,
    same,
)
from nl2hltl2plan.language.offline.phrases import DETERMINERS, FILLER, NP, parse_np, tokens
from nl2hltl2plan.language.tasks import BaseTaskSpec


@dataclass
class Draft:
    """A base task being assembled from frames."""

    frames: list[tuple[Frame, Item]]
    sentence: int
    start: int
    end: int
    group: int = -1
    label: str = ""  # own text for one item of a list clause ("put plates into the lower rack")

    @property
    def obj(self) -> NP | None:
        for _, it in self.frames:
            if it.obj is not None and not it.obj.pronoun and not it.obj.empty and not it.obj.is_lamp():
                return it.obj
        return None


class TaskBuilder:
    def __init__(self, grounder: Grounder | None, strict: bool, look: AffordanceLookup | None = None) -> None:
        self.g = grounder
        self.look = look
        self.strict = strict
        self.issues: list[str] = []
        self.unparsed: list[str] = []

    # grounding -----------------------------------------------------------------------------------------
    def types(self, np: NP | None, role: str) -> list[str] | None:
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
        out: dict[str, list[str] | None] = {}
        for role in nps:
            types, np = getattr(roles, role), nps[role]
            if types and np is not None and np.entry is not None and not np.entry.all_:
                types = types[:1]
            out[role] = types
        return out

    # one draft -> BaseTaskSpec ------------------------------------------------------------------------
    def spec(self, d: Draft, text: str) -> BaseTaskSpec | None:
        obj: NP | None = None
        container: NP | None = None
        light: NP | None = None
        states: list[str] = []
        sliced = False
        count = 1
        examine = False
        dests: list[NP] = []
        for fr, it in d.frames:
            o = it.obj
            if fr.cls in {"clean", "heat", "cool"}:
                states.append(fr.cls)
            if fr.cls == "fill":
                states.append("clean")
            if fr.cls == "slice":
                sliced = sliced or obj is not None or (o is not None and not o.pronoun)
            if fr.cls == "examine":
                examine = True
            if o is not None and o.is_lamp() and fr.cls in {"light", "examine"}:
                light = o
                o = None
            for np in [o] + [np for _, np in it.pps]:
                if np is None:
                    continue
                if np.is_lamp() and (fr.cls in {"light", "examine", "pick"} or fr.light_on):
                    light = light or np
            if o is not None and not o.pronoun and not o.empty:
                if obj is None:
                    obj = o
                elif container is None and dests and same(o, dests[-1]) and o.is_movable_receptacle():
                    container = o  # "put a card in a bowl and put the bowl on the desk"
                elif same(o, container):
                    pass
                elif not same(o, obj) and o.is_lamp():
                    light = o
            if o is not None:
                states += sorted(o.states)
                sliced = sliced or o.sliced
                if o.water:
                    states.append("clean")
                count = max(count, o.count)
            # "with X in it", "containing X", "holding X", "along with the other set"
            for p, np in it.pps:
                if p in {"along with", "together with"} and np.entry is None and not np.head:
                    count = max(count, 2)  # "one set of keys along with the other set"
                    continue
                if p in G.WITH_PREPS and not np.pronoun:
                    if p == "with" and is_fixed(np):
                        continue  # "place it with the coffee machine": the destination (dest_of)
                    if np.water:
                        states.append("clean")
                        continue
                    if np.is_lamp():
                        light = np
                        continue
                    if p in {"along with", "together with"} and (same(np, obj) or np.entry is None):
                        count = max(count, 2)
                        continue
                    if obj is None and (light is not None or fr.cls == "light" or fr.light_on):
                        obj = np  # "turn on a lamp with a book in hand"
                        continue
                    if obj is not None and np.entry is not None and container is None:
                        if obj.is_movable_receptacle() and not np.is_movable_receptacle():
                            container, obj = obj, np
                        elif np.is_movable_receptacle():
                            container = np
                        elif obj.is_movable_receptacle():
                            container, obj = obj, np
                    states += sorted(np.states)
                    sliced = sliced or np.sliced
                if p in G.LIGHT_PREPS and np.is_lamp():
                    light = np
                if (
                    p == ""
                    and np.entry is not None
                    and obj is not None
                    and not np.pronoun
                    and container is None
                ):
                    # "a bowl and a pencil": one movable receptacle and its content
                    if obj.is_movable_receptacle() and not np.is_movable_receptacle():
                        container, obj = obj, np
                    elif np.is_movable_receptacle() and not obj.is_movable_receptacle():
                        container = np
                    elif same(np, obj):
                        count = max(count, 2)
            dst = dest_of(it, fr.cls) or near_dest(it)
            if any(p == THEN_TO for p, _ in it.pps):  # stops on the way come before the destination
                dests += [
                    np for p, np in it.pps if p in G.DEST_PREPS and np.is_receptacle() and np is not dst
                ]
            if fr.cls == "trash" and dst is None:
                dst = parse_np("garbage can")
            if dst is not None and not dst.is_lamp():
                recs = [
                    np for p, np in it.pps if p in G.DEST_PREPS and np.is_receptacle() and p not in UNDER
                ]
                movable = [np for np in recs if np.is_movable_receptacle()]
                fixed = [np for np in recs if not np.is_movable_receptacle()]
                if (
                    obj is not None
                    and container is None
                    and not obj.is_movable_receptacle()
                    and movable
                    and fixed
                ):
                    # "place the spoon in a cup to the counter", "place the watch on the table on a plate"
                    container = movable[0]
                    dests.append(container)
                    dst = fixed[-1]
                dests.append(dst)
        if obj is None:
            if light is not None:
                self.unparsed.append(f"nothing to hold under the lamp in: {text}")
            elif d.frames and d.frames[0][0].cls not in {"none", "other"}:
                self.unparsed.append(f"no object to act on in: {text}")
            return None
        if light is not None or examine:
            if (
                obj.is_receptacle()
                and not obj.is_movable_receptacle()
                and obj.entry is not None
                and obj.entry.canonical not in {"Box"}
            ):
                self.unparsed.append(f"cannot hold the {obj.text!r} to look at it: {text}")
                return None
        # a content placed into a movable receptacle that is then moved: place_in_container
        final = dests[-1] if dests else None
        if (
            container is None
            and len(dests) >= 2
            and dests[-2].is_movable_receptacle()
            and not obj.is_movable_receptacle()
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
                    states.append(st)
        if light is None and examine:
            light = parse_np("lamp")
        kind: str
        state = next((s for s in ("heat", "cool", "clean") if s in states), None)
        if light is not None:
            kind = "examine_in_light"
        elif final is None:
            self.unparsed.append(f"no destination for the {obj.text or obj.key!r} in: {text}")
            return None
        elif container is not None:
            kind = "place_in_container"
        elif state:
            kind = {"heat": "heat_place", "cool": "cool_place", "clean": "clean_place"}[state]
        elif count >= 2:
            kind = "place_two"
        else:
            kind = "place"
        fields = self.ground(
            kind,
            sliced,
            {
                "object": obj,
                "container": container if kind == "place_in_container" else None,
                "receptacle": final if kind != "examine_in_light" else None,
                "light": light if kind == "examine_in_light" else None,
            },
        )
        if fields is None:
            return None
        spec = BaseTaskSpec(
            kind=kind,
            object=fields["object"],
            count=min(count, 2) if kind == "place_two" else count,
            sliced=sliced,
            text=text,
            container=fields["container"],
            receptacle=fields["receptacle"],
            light=fields["light"],
        )
        if kind == "place_two":
            spec.count = 2
        return spec

