"""Grounding: words of an instruction -> AI2-THOR object types present in the scene.

The word list is `lexicon.txt` (next to this module) plus every AI2-THOR type under its own name
split into words ("garbage can" -> GarbageCan). A word maps to an ordered list of candidate types;
the first one present in the scene is used, or all present ones for words such as "table" or "knife"
whose reading the annotation guide leaves open. When no candidate is in the scene, grounding fails
with a `WorldError` that names the missing type ("no Statue in FloorPlan17").
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

from nl2hltl2plan.domain.task_kinds import camel_words
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.missing_types import other_types_note
from nl2hltl2plan.worlds.world import Affordances

# what a knife slices in ALFRED (an egg cracks): "a piece of soap" is a whole soap bar
SLICEABLE = frozenset({"Apple", "Bread", "Lettuce", "Potato", "Tomato", "Egg"})
# AI2-THOR object types (ALFRED's list plus the few AI2-THOR 5 scenes add).
THOR_TYPES: tuple[str, ...] = (
    "AlarmClock",
    "Apple",
    "ArmChair",
    "BaseballBat",
    "BasketBall",
    "Bathtub",
    "BathtubBasin",
    "Bed",
    "Blinds",
    "Book",
    "Boots",
    "Bottle",
    "Bowl",
    "Box",
    "Bread",
    "ButterKnife",
    "CD",
    "Cabinet",
    "Candle",
    "Cart",
    "CellPhone",
    "Chair",
    "Cloth",
    "CoffeeMachine",
    "CoffeeTable",
    "CounterTop",
    "CreditCard",
    "Cup",
    "Curtains",
    "Desk",
    "DeskLamp",
    "DiningTable",
    "DishSponge",
    "Drawer",
    "Dresser",
    "Dumbbell",
    "Egg",
    "Faucet",
    "FloorLamp",
    "Footstool",
    "Fork",
    "Fridge",
    "GarbageCan",
    "Glassbottle",
    "HandTowel",
    "HandTowelHolder",
    "HousePlant",
    "Kettle",
    "KeyChain",
    "Knife",
    "Ladle",
    "Laptop",
    "LaundryHamper",
    "LaundryHamperLid",
    "Lettuce",
    "LightSwitch",
    "Microwave",
    "Mirror",
    "Mug",
    "Newspaper",
    "Ottoman",
    "Painting",
    "Pan",
    "PaperTowel",
    "PaperTowelRoll",
    "Pen",
    "Pencil",
    "PepperShaker",
    "Pillow",
    "Plate",
    "Plunger",
    "Poster",
    "Pot",
    "Potato",
    "RemoteControl",
    "Safe",
    "SaltShaker",
    "ScrubBrush",
    "Shelf",
    "ShelvingUnit",
    "ShowerDoor",
    "ShowerGlass",
    "SideTable",
    "Sink",
    "SinkBasin",
    "SoapBar",
    "SoapBottle",
    "Sofa",
    "Spatula",
    "Spoon",
    "SprayBottle",
    "Statue",
    "Stool",
    "StoveBurner",
    "StoveKnob",
    "TVStand",
    "TeddyBear",
    "Television",
    "TennisRacket",
    "TissueBox",
    "Toaster",
    "Toilet",
    "ToiletPaper",
    "ToiletPaperHanger",
    "ToiletPaperRoll",
    "Tomato",
    "Towel",
    "TowelHolder",
    "Vase",
    "Watch",
    "WateringCan",
    "Window",
    "WineBottle",
    "Dishwasher",
    "DishwasherLowerRack",
    "DishwasherUpperRack",
    "Saucer",
)
# ALFRED's facts (affordances.json): receptacles, movable ones, and lamps.
RECEPTACLES = frozenset(
    {
        "ArmChair",
        "BathtubBasin",
        "Bed",
        "Bowl",
        "Box",
        "Cabinet",
        "Cart",
        "CoffeeMachine",
        "CoffeeTable",
        "CounterTop",
        "Cup",
        "Desk",
        "DiningTable",
        "Drawer",
        "Dresser",
        "Fridge",
        "GarbageCan",
        "HandTowelHolder",
        "LaundryHamper",
        "Microwave",
        "Mug",
        "Ottoman",
        "PaintingHanger",
        "Pan",
        "Plate",
        "Pot",
        "Safe",
        "Shelf",
        "SideTable",
        "SinkBasin",
        "Sofa",
        "StoveBurner",
        "TVStand",
        "Toaster",
        "Toilet",
        "ToiletPaperHanger",
        "TowelHolder",
        "Chair",
        "ShelvingUnit",
        "Footstool",
        "Stool",
        "Boots",
        "Dishwasher",
        "DishwasherLowerRack",
        "DishwasherUpperRack",
        "Saucer",  # the demo kitchen's own types
    }
)
MOVABLE_RECEPTACLES = frozenset({"Bowl", "Box", "Cup", "Mug", "Pan", "Plate", "Pot", "Saucer"})
LAMPS = frozenset({"DeskLamp", "FloorLamp"})
GENERIC = "*"

_TOKEN = re.compile(r"[a-z0-9]+(?:'[a-z]+)?")


@dataclass(frozen=True)
class Entry:
    """A lexicon entry: candidate types in order; `all_` = every present candidate is acceptable."""

    phrase: str
    types: tuple[str, ...]
    all_: bool = False

    @property
    def generic(self) -> bool:
        return self.types == (GENERIC,)

    @property
    def canonical(self) -> str:
        return self.types[0]


@dataclass(frozen=True)
class Mention:
    """A lexicon phrase found in a text: token span [start, end), character span, entry, plural form."""

    start: int
    end: int
    char_start: int
    char_end: int
    surface: str
    entry: Entry
    plural: bool


def tokens(text: str) -> list[tuple[str, int, int]]:
    """Lower-case word tokens with their character spans."""
    return list(_tokens(text))


# the readers and check 1 ask again for the same texts (a few dozen times per instruction): each text's
# tokens and mentions are found once, kept as tuples and handed out as fresh lists
_TEXTS_KEPT = 4096


@lru_cache(maxsize=_TEXTS_KEPT)
def _tokens(text: str) -> tuple[tuple[str, int, int], ...]:
    return tuple((m.group(0), m.start(), m.end()) for m in _TOKEN.finditer(text.lower()))


def sentence_start(text: str, at: int) -> int:
    """Where the sentence around character `at` begins: just after the last ".", ";", "!" or "?" before it."""
    return max((m.end() for m in re.finditer(r"[.;!?]", text[:at])), default=0)


def _plurals(word: str) -> set[str]:
    out = {word + "s", word + "es", word + "'s"}
    if word.endswith("y") and len(word) > 2 and word[-2] not in "aeiou":
        out.add(word[:-1] + "ies")
    if word.endswith("fe"):
        out.add(word[:-2] + "ves")
    elif word.endswith("f"):
        out.add(word[:-1] + "ves")
    if word.endswith("s"):
        out.discard(word + "s")
    return out


def plural_name(phrase: str) -> str | None:
    """The plural the lexicon reads as a name's things, as English writes it ("knife" -> "knives", "bar of
    soap" -> "bars of soap"), else its type's ("keys" -> "key chains"); None: none ("blinds", "stuff")."""
    entry = lookup(phrase)
    if entry is None or entry.generic:
        return None
    for name in (phrase, camel_words(entry.types[0])):
        words = name.split()
        at = words.index("of") - 1 if "of" in words[1:] else len(words) - 1
        for form in (_english_plural(words[at]), words[at] + "s"):  # "shelfs": "shelves" is a shelf's name
            said = (*words[:at], form, *words[at + 1 :])
            if (hit := lexicon().get(said)) and hit[1] and hit[0].types == entry.types:
                return " ".join(said)
    return None


def _english_plural(word: str) -> str:
    """ "knives", "potatoes", "boxes", "berries", "mugs"; a word that looks plural already stays ("keys")."""
    if re.search(r"(?:[lr]f|af|ife)$", word):
        return re.sub(r"fe?$", "ves", word)
    if re.search(r"(?:s|x|z|ch|sh|[^aeiou]o)$", word):
        return word if re.search(r"[^s]s$", word) else word + "es"
    return word[:-1] + "ies" if re.search(r"[^aeiou]y$", word) else word + "s"


def phrase_lines(name: str) -> list[tuple[list[str], list[str]]]:
    """The lines of a word file of this package in the lexicon's format, `phrase[, phrase...] : field [:
    field ...]` (`#` comments): each line's phrases and its fields (lexicon.txt, everyday_names.txt)."""
    out = []
    for raw in resources.files("nl2hltl2plan.language").joinpath(name).read_text().splitlines():
        line = raw.split("#", 1)[0].strip()
        if line:
            head, *fields = (p.strip() for p in line.split(" : "))
            out.append(([p.strip() for p in head.split(",") if p.strip()], fields))
    return out


@lru_cache(maxsize=1)
def lexicon() -> dict[tuple[str, ...], tuple[Entry, bool]]:
    """phrase tokens -> (entry, is_plural_form). Own entries win over type names and plural forms."""
    table: dict[tuple[str, ...], tuple[Entry, bool]] = {}
    singular: dict[tuple[str, ...], Entry] = {}
    for t in THOR_TYPES:
        for phrase in {camel_words(t), t.lower()}:
            singular[tuple(phrase.split())] = Entry(phrase, (t,))
    listed_plurals: list[tuple[str, str]] = []  # `: plural of PHRASE` lines: (plural, PHRASE)
    for phrases, fields in phrase_lines("lexicon.txt"):
        types, all_ = tuple(fields[0].split()), len(fields) > 1 and fields[1] == "all"
        if len(fields) > 1 and fields[1].startswith("plural of "):
            listed_plurals += [(phrase, fields[1].removeprefix("plural of ")) for phrase in phrases]
            continue
        for phrase in phrases:
            singular[tuple(phrase.split())] = Entry(phrase, types, all_)
    for phrase, of in listed_plurals:
        table[tuple(phrase.split())] = (singular[tuple(of.split())], True)
    for key, entry in singular.items():
        # the last word's plurals, and in "bar of soap" the counted word's: "bars of soap", "sets of keys"
        for at in {len(key) - 1, key.index("of") - 1 if "of" in key[1:] else len(key) - 1}:
            for pl in _plurals(key[at]):
                pkey = key[:at] + (pl,) + key[at + 1 :]
                if pkey not in singular:
                    table.setdefault(pkey, (entry, True))
    for key, entry in singular.items():
        table[key] = (entry, False)
    return table


@lru_cache(maxsize=1)
def _max_len() -> int:
    return max(len(k) for k in lexicon())


def find_mentions(text: str) -> list[Mention]:
    """Longest lexicon matches, left to right, without overlaps."""
    return list(_mentions(text))


@lru_cache(maxsize=_TEXTS_KEPT)
def _mentions(text: str) -> tuple[Mention, ...]:
    toks = _tokens(text)
    words = [t[0] for t in toks]
    lex, longest = lexicon(), _max_len()  # asked once per text, not once per word
    out: list[Mention] = []
    i = 0
    while i < len(words):
        for n in range(min(longest, len(words) - i), 0, -1):
            hit = lex.get(tuple(words[i : i + n]))
            if hit:
                entry, plural = hit
                out.append(
                    Mention(
                        i,
                        i + n,
                        toks[i][1],
                        toks[i + n - 1][2],
                        text[toks[i][1] : toks[i + n - 1][2]],
                        entry,
                        plural,
                    )
                )
                i += n
                break
        else:
            i += 1
    return tuple(out)


def lookup(phrase: str) -> Entry | None:
    """The entry of a whole phrase or of its last mention ("the red mug" -> mug), else None."""
    hit = lexicon().get(tuple(w for w, _, _ in tokens(phrase)))
    if hit:
        return hit[0]
    ms = find_mentions(phrase)
    return ms[-1].entry if ms else None


class Grounder:
    """Maps entries/words to the types of one scene; `types=None` means "no scene": keep canonical types."""

    def __init__(self, types: Iterable[str] | None, scene: str = "the scene") -> None:
        self.types: frozenset[str] | None = frozenset(types) if types is not None else None
        self.scene = scene
        self._by_lower = {t.lower(): t for t in (self.types or THOR_TYPES)}

    def candidates(self, entry: Entry) -> list[str]:
        """Every type of the scene the entry could stand for, in the lexicon's order ([] when none)."""
        if entry.generic:
            return []
        if self.types is None:
            return list(entry.types)
        return [t for t in entry.types if t in self.types]

    def resolve(self, entry: Entry) -> list[str]:
        """Types of the scene the entry stands for ([] when none is present)."""
        if entry.generic:
            return []
        if self.types is None:
            return list(entry.types) if entry.all_ else [entry.canonical]
        present = self.candidates(entry)
        return present if entry.all_ else present[:1]

    def missing(self, entry: Entry, what: str = "") -> WorldError:
        words = " ".join(w for w, _, _ in tokens(what))
        plain = camel_words(entry.canonical)
        said = (
            f" (for {what.strip()!r})" if words and plain not in words and entry.phrase not in words else ""
        )
        note = other_types_note(entry, entry.canonical, self.types or (), self.scene, alfred_lookup())
        return WorldError(f"no {entry.canonical}{said} in {self.scene}{note}")

    def ground(self, word: str, role: str = "object") -> list[str]:
        """A word or type name -> present types; WorldError naming it when the scene has none."""
        w = word.strip()
        if not w:
            raise WorldError(f"empty {role} name")
        exact = self._by_lower.get(w.lower().replace(" ", "")) or self._by_lower.get(w.lower())
        entry = lookup(w)
        if (
            exact
            and (self.types is None or exact in self.types)
            and (exact == w.replace(" ", "") or entry is None)
        ):
            return [exact]  # a type name as such ("Knife"); a plain word ("knife") goes through the lexicon
        if entry is None or entry.generic:
            if exact:  # a real type that is not in the scene
                raise WorldError(f"no {exact} in {self.scene}")
            known = {t.lower() for t in THOR_TYPES}
            if w.lower().replace(" ", "") in known:
                raise WorldError(f"no {w} in {self.scene}")
            raise WorldError(f"cannot map the {role} {w!r} to an object type of {self.scene}")
        got = self.resolve(entry)
        if not got:
            raise self.missing(entry, w)
        return got


def own_type(entry: Entry, types: Sequence[str]) -> str | None:
    """The type of `types` whose own name the entry's phrase is ("towel" of a Towel, "cup" of a Cup), else
    None ("mug" of a Cup)."""
    return next((t for t in types if entry.phrase in (camel_words(t), t.lower())), None)


def exact_name_conflict(entry: Entry, present: list[str], scene: str = "the scene") -> str | None:
    """Why a word read as its entry's first type is refused when it is exactly the name of another type
    of the scene (`present`, in the lexicon's order), else None (check 1 asks it of each reading,
    `referents.exact_names`; words such as "table" that accept every type are not asked). ALFRED's annotators
    call a HandTowel "towel" (126 annotations of non-excluded training tasks on a HandTowel; no such task
    is on a Towel), yet every ALFRED bathroom has a Towel too: neither reading is safe (docs/language.md)."""
    named = own_type(entry, present)
    if entry.all_ or named is None or present.index(named) == 0:
        return None
    first = present[0]
    say = " or ".join(repr(_own_name(t, entry.phrase)) for t in (named, first))
    return f"{entry.phrase!r} is both the {named} of {scene} and ALFRED's word for its {first}: say {say}"


def role_swap_conflict(
    entry: Entry, present: list[str], things: Collection[str], scene: str, places: Mapping[str, str]
) -> str | None:
    """Why a word that is the own name of a type of the scene (`present`, the entry's types there) is
    refused when the thing handled is read as another of its types (`things`), else None (check 1 asks it,
    `referents.exact_names`). The task's role narrows a word's types (`Roles.narrow`): "the cup in the
    coffee machine" became the Mug, ALFRED's coffee machine holding only a Mug. Where the scene has a Mug
    only, the Mug is what "cup" can mean (the annotation guide's "cup -> Cup, else Mug"); where it has a Cup
    too, the text names the Cup, which cannot do it, and the Mug would be a guess. Only a word whose own
    type is the lexicon's first reading of it is asked ("cup", "mug", "cloth", "soap bar"). `places`: where
    a task puts a thing of a type, named in the message."""
    named = own_type(entry, present)
    other = next((t for t in present if t != named and t in things), None)
    if entry.all_ or named is None or other is None or named != entry.types[0]:
        return None  # "towel", the HandTowel first, is `exact_name_conflict`'s (a towel washed is a Cloth)
    place = places.get(other)
    cannot = f"which the {place} cannot hold" if place else "which cannot do what is asked here"
    say = _own_name(other, entry.phrase)
    return f"{entry.phrase!r} is the {named} of {scene}, {cannot}: say {say!r} for its {other}"


def _own_name(type_: str, phrase: str) -> str:
    """A phrase of the lexicon that reads `type_` first and is not `phrase` (the type's own name
    preferred, "hand towel" and not "towel", which may name a Towel too; then one sharing the phrase's last
    word: "bath towel" for a Towel), else the type's own name in words."""
    own = [
        " ".join(k)
        for k, (e, plural) in lexicon().items()
        if not plural and e.canonical == type_ and " ".join(k) != phrase and not e.generic
    ]
    last = phrase.split()[-1]
    plain = camel_words(type_)
    return min(own, key=lambda p: (p != plain, last not in p.split(), len(p)), default=plain)


# ----- roles: which of a word's types can do what the task asks ------------------------------------------
AffordanceLookup = Callable[[str], "Affordances | None"]


def alfred_lookup() -> AffordanceLookup | None:
    """ALFRED's affordance facts as a lookup (None when the shared data is missing)."""
    from nl2hltl2plan.errors import DataError
    from nl2hltl2plan.worlds.affordances import alfred_affordances

    try:
        table = alfred_affordances()
    except DataError:
        return None
    known = table.object_types | table.receptacles

    def look(type_: str) -> Affordances | None:
        return table(type_) if type_ in known else None

    return look


def world_lookup(world: object) -> AffordanceLookup | None:
    """The affordances of a world's own objects, by type (None when the world has no objects)."""
    instances = getattr(world, "instances", None)
    if instances is None or not hasattr(world, "objects"):
        return None

    seen: dict[str, Affordances | None] = {}  # a world is static: each type is looked up once

    def look(type_: str) -> Affordances | None:
        if type_ not in seen:
            objs = instances(type_)
            seen[type_] = objs[0].affordances if objs else None
        return seen[type_]

    return look


_STATE_FLAG = {"clean_place": "cleanable", "heat_place": "heatable", "cool_place": "coolable"}


@dataclass
class Roles:
    """Candidate types per field of one task; `narrow` keeps the ones that can play their role."""

    object: list[str]
    receptacle: list[str] | None = None
    container: list[str] | None = None
    light: list[str] | None = None

    def narrow(self, look: AffordanceLookup | None, kind: str, sliced: bool) -> Roles:
        """Keep, per field, the types whose affordances fit the task (a field that would become empty is
        kept as it was): the object must be pickupable, cleanable / heatable / coolable for those kinds,
        sliceable when sliced; the container must accept the object; the receptacle must accept what is put
        into it (the container, else the object); the light must be toggleable. Types the lookup does not
        know are kept. E.g. "a clean towel" -> Cloth (a HandTowel cannot be cleaned in ALFRED), "the
        chair" -> ArmChair (ALFRED's Chair accepts nothing), "a chilled bottle" -> WineBottle."""
        if look is None:
            return self

        def keep(types: list[str] | None, ok: Callable[[str], bool]) -> list[str] | None:
            if not types:
                return types
            return [t for t in types if look(t) is None or ok(t)] or types

        def flags(t: str) -> Affordances:
            a = look(t)
            assert a is not None
            return a

        def accepts(rec: str, thing: str) -> bool:
            a = look(rec)
            if a is None or look(thing) is None:
                return True
            return thing in a.accepts or (sliced and thing + "Sliced" in a.accepts)

        flag = _STATE_FLAG.get(kind)
        obj: list[str] = keep(self.object, lambda t: flags(t).pickupable) or []
        if flag:
            treated = keep(obj, lambda t: getattr((look(t + "Sliced") if sliced else None) or flags(t), flag))
            obj = treated or []
        if sliced:
            obj = keep(obj, lambda t: flags(t).sliceable) or []
        cont = keep(self.container, lambda c: any(accepts(c, o) for o in obj))
        if cont:
            chosen = cont
            obj = keep(obj, lambda o: any(accepts(c, o) for c in chosen)) or []
        inner = cont or obj
        rec = keep(self.receptacle, lambda r: any(accepts(r, x) for x in inner))
        if rec:
            if cont:
                cont = keep(cont, lambda c: any(accepts(r, c) for r in rec))
            else:
                obj = keep(obj, lambda o: any(accepts(r, o) for r in rec)) or []
        light = keep(self.light, lambda t: flags(t).toggleable)
        return Roles(obj, rec, cont, light)


def scene_types(scene: str) -> set[str]:
    """Object types of an ALFRED floor plan from the shared data (scene_info and the layout's object list:
    `worlds.floor_plans.listed_types`). Used where no `World` is at hand (benchmark measurement)."""
    from nl2hltl2plan.worlds.floor_plans import listed_types

    return set(listed_types(scene))
