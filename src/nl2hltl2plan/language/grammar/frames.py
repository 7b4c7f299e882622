"""Step 3, frames: one clause -> its verb class and its items (object + prepositional phrases)."""

from __future__ import annotations

from dataclasses import dataclass, field

from nl2hltl2plan.domain.task_kinds import MAX_COUNT
from nl2hltl2plan.language.content_words import ROOM_WORDS, word_categories
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.phrases import COLOURS, DETERMINERS, NP, match_prep, parse_np, tokens
from nl2hltl2plan.language.grounding import find_mentions

_AFTER_OUT = frozenset({",", "and", "in", "into", "to"})  # "throw it out" then: its particle, not "out of"


@dataclass
class Item:
    """One object of a clause with its prepositional phrases: [(prep, NP)]."""

    obj: NP | None
    pps: list[tuple[str, NP]] = field(default_factory=list)
    added: bool = False  # joined by "plus": one more thing for the placing said before


@dataclass
class Frame:
    text: str
    start: int
    end: int
    cls: str  # verb class (grammar._VERBS keys) or "none"
    verb: str
    items: list[Item]
    light_on: bool = False  # "turn ... on/off"
    joiner: str = ""  # word that joined it to the previous clause ("then", "and", "to", ...)
    ambiguous: bool = False  # a list the parser cannot assign (several destinations)
    choice: bool = False  # objects joined by "or" ("the apple or the tomato"): which one is not said


# where each treatment is done ("heat the potato in the microwave")
APPLIANCE_OF = {"heat": "Microwave", "cool": "Fridge", "clean": "SinkBasin"}
SEQ_WORDS = {"then", "finally", "lastly", "afterwards", "afterward", "later"}  # not "next": "next to"
IN_SENTENCE = "in sentence"  # a "finally" that joins clauses of one sentence
OF_ALL = "of all"  # a "last" / "at the end" that ends a one-task sentence: after every other task
THEN_TO = "then to"  # a further destination after a stop ("to the sink and finally the toilet")


def parse_frame(text: str, start: int = 0, joiner: str = "") -> Frame:
    """One clause -> its verb class, verb and items (each an object with its prepositional phrases)."""
    toks = tokens(text)
    cls, verb, i, light_on = _read_verb([w for w, _, _ in toks])
    reader = _ItemReader(text, toks, cls, light_on)
    items = reader.read(i)
    _join_further_destinations(items)
    away = any(w == "away" for w, _, _ in toks[:i])  # "put away X on L in D"
    for it in items:
        _standing_place_first(it, text, away)
    _added_things(items)
    # "to region G, H and I": bare noun phrases after an item with a destination continue that destination
    ambiguous = len(items) > 1 and items[-1].obj is not None and not items[-1].pps and bool(items[-2].pps)
    _share_colour_nouns(items)
    return Frame(
        text=text,
        start=start,
        end=start + len(text),
        cls=cls,
        verb=verb,
        items=items,
        light_on=light_on,
        joiner=joiner,
        ambiguous=ambiguous,
        choice=reader.choice and len(items) > 1,
    )


def _added_things(items: list[Item]) -> None:
    """ "throw the soap into the bin, plus the spray bottle": "plus" with no place of its own adds a thing to
    the placing before it, which it shares. With a place of its own ("plus the candle on the counter") the
    place is its destination, as with "and" (users_h154's "plus" lists)."""
    for before, it in zip(items, items[1:], strict=False):
        shared = [(p, np) for p, np in before.pps if p in G.DEST_PREPS]
        if it.added and shared and not any(p in G.DEST_PREPS for p, _ in it.pps):
            it.pps.extend(shared)


def _read_verb(words: list[str]) -> tuple[str, str, int, bool]:
    """(verb class, verb, index of the first word after the verb and its particles, switches a light)."""
    cls, verb, i = "none", "", 0
    if words and words[0] in G.VERBS:
        cls, verb = G.VERBS[words[0]]
        i = 1
        # "look at", "pick up", "throw away", "put down", "turn on": particles
        extra = {"off", "out"} if cls in {"clean", "heat", "cool", "pick"} else set()
        while i < len(words) and words[i] in G.PARTICLES | {"at"} | extra:
            if words[i] == "at" and verb != "look":
                break
            if verb in {"turn", "switch", "power"} and words[i] in {"on", "off"}:
                break
            i += 1
    light_on = False
    if verb in {"turn", "switch", "power", "toggle"}:
        if any(w in {"on", "off"} for w in words[1:]):
            light_on = True
        else:
            cls = "other"
    if verb == "clean" and i > 1 and words[1] == "up":
        cls = "pick"  # "clean up pencils" = collect them
    if verb == "light" and cls == "light":
        light_on = True
    if verb in {"lit", "illuminate"}:
        light_on = True
    return cls, verb, i, light_on


@dataclass
class _ItemReader:
    """Reads the words after the verb: prepositions start a PP; "," / "and" separate list items."""

    text: str
    toks: list[tuple[str, int, int]]
    cls: str
    light_on: bool
    items: list[Item] = field(default_factory=list)
    item: Item = field(default_factory=lambda: Item(obj=None))
    cur: list[tuple[str, int, int]] = field(default_factory=list)  # the words of the current noun phrase
    cur_prep: str | None = None
    source_pair: bool = False  # after "from between": the next "and" joins two places, not two items
    choice: bool = False  # an "or" started a new item

    def read(self, i: int) -> list[Item]:
        words = [w for w, _, _ in self.toks]
        while i < len(words):
            i = self._step(words, i)
        self._flush()
        if self.item.obj is not None or self.item.pps or not self.items:
            self.items.append(self.item)
        return self.items

    def _flush(self) -> None:
        item, cur = self.item, self.cur
        if cur:
            np = parse_np(self.text[cur[0][1] : cur[-1][2]])
            if self.cur_prep is None:
                if item.obj is None:
                    item.obj = np
                else:
                    item.pps.append(("", np))
            else:
                item.pps.append((self.cur_prep, np))
        elif self.cur_prep is not None and self.cur_prep in {"inside", "in", "on"}:
            item.pps.append((self.cur_prep, NP(text="", pronoun=True)))
        self.cur = []

    def _step(self, words: list[str], i: int) -> int:
        """Read the word at `i`; the index of the next word to read."""
        w = words[i]
        if (
            w in SEQ_WORDS
            and self.cur_prep is not None
            and self.cur_prep in G.DEST_PREPS
            and self.cls in {"place", "trash", "pick", "clean", "heat", "cool"}
            and i + 1 < len(words)
            and words[i + 1] not in {",", "and"}  # "in the sink afterwards, and ...": it closes the item
        ):
            # "in the microwave, then on the counter" / "to the sink and finally the toilet": a further
            # destination; the earlier ones become stops on the way
            self._flush()
            hit = match_prep(words, i + 1)
            self.cur_prep = THEN_TO
            return i + 1 + (hit[1] if hit is not None and hit[0] in G.DEST_PREPS else 0)
        if w == "and" and self.cur_prep in {"from", "between", "in between"} and self.source_pair:
            self._flush()  # "from between the sink and the toilet": both say where it is
            self.source_pair = False
            return i + 1
        if w in {",", "and", "plus"} or (w == "or" and self.cur_prep is None):  # "plus": a list's "and"
            self.choice = self.choice or w == "or"
            self._flush()
            # a new list item starts when the next words are a noun phrase without preposition
            nxt = words[i + 1] if i + 1 < len(words) else ""
            if nxt and nxt not in {",", "and"} and match_prep(words, i + 1) is None and nxt not in SEQ_WORDS:
                if self.item.obj is not None or self.item.pps:
                    self.items.append(self.item)
                    self.item = Item(obj=None, added="plus" in {w, nxt})  # ", plus the mug"
                self.cur_prep = None
            return i + 1
        if self.cls == "trash" and w == "out" and (i + 1 >= len(words) or words[i + 1] in _AFTER_OUT):
            self._flush()  # "throw it out (in the bin)": the particle, as "away" is (not "out of the fridge")
            self.cur_prep = None
            return i + 1
        if self.light_on and w in {"on", "off"} and _particle_position(words, i):
            self._flush()  # "turn on the lamp", "turn the lamp on": a particle, not "on the table"
            self.cur_prep = None
            return i + 1
        hit = match_prep(words, i)
        if hit is not None and self.cur_prep == "from" and not self.cur:
            # "from between the sink and the toilet", "from under the bed": still where it is
            self.source_pair = hit[0] in {"between", "in between"}
            return i + hit[1]
        if hit is not None and not (hit[0] == "of" and self.cur):
            self._flush()
            # "in the fridge between the lettuce and the potato": after a destination, the pair says where
            # in it, not two more destinations
            self.source_pair = hit[0] in {"between", "in between"} and any(
                p in G.DEST_PREPS and p not in {"between", "in between"} for p, _ in self.item.pps
            )
            self.cur_prep = hit[0]
            return i + hit[1]
        if self._list_goes_on(words, i):  # "look at the remote the vase and a keychain": a comma left out
            self._step(words[:i] + [","] + words[i:], i)  # read as the comma: the article is read next
            return i
        self.cur.append(self.toks[i])
        return i + 1

    def _list_goes_on(self, words: list[str], i: int) -> bool:
        """Does the article at `i` start the next item of a list written without commas? Only between two
        whole noun phrases the lexicon knows, before any preposition ("look at the remote the vase and a
        keychain"), the second a thing to move (a lamp or a fixed place is where the first goes). After a
        destination the same holds ("put the watch in the box the keys on the sofa"): the thing is never read
        into the place's phrase ("the sink plate the egg" is no plate, h227)."""
        if words[i] not in {"the", "a", "an"} or not self.cur:
            return False
        if self.cur_prep is not None and self.cur_prep not in G.DEST_PREPS:
            return False
        said = parse_np(self.text[self.cur[0][1] : self.cur[-1][2]]).entry
        if said is None or not self.cur[-1][0].startswith(said.phrase.split()[-1]):  # "the keys before": no
            return False
        rest = words[i:]
        stops = (k for k in range(1, len(rest)) if rest[k] in _ITEM_ENDS or match_prep(rest, k) is not None)
        ends = next(stops, len(rest))
        nxt = parse_np(" ".join(rest[:ends]))
        if ends < 2 or nxt.entry is None or nxt.is_lamp():  # "examine a cup [under] a lamp": a typo lost
            return False
        if not rest[ends - 1].startswith(nxt.entry.phrase.split()[-1]):  # "the remote the watch is on": a
            return False  # relative clause without "that" (the phrase goes on past its noun), no list item
        return not nxt.is_receptacle() or nxt.is_movable_receptacle()


# what ends an item of a list without commas: a comma, "and", or the next item's article
_ITEM_ENDS = frozenset({",", "and", "the", "a", "an"})


def _particle_position(words: list[str], i: int) -> bool:
    """Is the "on"/"off" at `i` a particle of "turn on" (followed by nothing, a determiner, a joiner, a verb
    or an object word)?"""
    return (
        i + 1 >= len(words)
        or words[i + 1] in DETERMINERS
        or words[i + 1] in {",", "and", "while", "with"}
        or words[i + 1] in G.VERBS
        or bool(find_mentions(words[i + 1]))
    )


def _join_further_destinations(items: list[Item]) -> None:
    """ "from the bath to the sink and finally the toilet": a sequence word before a fixed receptacle adds a
    further destination (the earlier ones are stops on the way)."""
    while (
        len(items) > 1
        and items[-1].obj is not None
        and not items[-1].pps
        and any(p in G.DEST_PREPS for p, _ in items[-2].pps)
        and tokens(items[-1].obj.text)[0][0] in SEQ_WORDS
        and items[-1].obj.is_receptacle()
        and not items[-1].obj.is_movable_receptacle()
    ):
        items[-2].pps.append((THEN_TO, items[-1].obj))
        items.pop()


def _share_colour_nouns(items: list[Item]) -> None:
    """ "the red and blue blocks": colour words share the noun of the last item."""
    if len(items) > 1 and items[-1].obj is not None:
        last_words = [w for w, _, _ in tokens(items[-1].obj.text) if w not in DETERMINERS]
        if last_words and last_words[0] in COLOURS and len(last_words) > 1:
            noun = " ".join(last_words[1:])
            for it in items[:-1]:
                ws = [w for w, _, _ in tokens(it.obj.text) if w not in DETERMINERS] if it.obj else []
                if ws and all(w in COLOURS for w in ws):
                    it.obj = parse_np(" ".join(ws) + " " + noun)


# ----- drafts -> tasks ---------------------------------------------------------------------------------
def same(a: NP | None, b: NP | None) -> bool:
    """Do two noun phrases name the same kind of thing (the same lexicon entry or the same words), and not
    two things the entry lumps in one type ("the glass" and "the cup", `one_type_names.txt`)?"""
    if a is None or b is None or not a.key or a.key != b.key:
        return False
    names = {_one_type_name(np) for np in (a, b)}
    return len(names) == 1 or None in names


_ONE_TYPE_NAMES = {w: name for name, words in word_categories("one_type_names.txt").items() for w in words}


def _one_type_name(np: NP) -> str | None:
    """Which everyday thing of `one_type_names.txt` the phrase names (None: none, or no entry)."""
    if np.entry is None or not np.entry.phrase:
        return None
    return _ONE_TYPE_NAMES.get(np.entry.phrase.split()[-1])


UNDER = {"under", "underneath", "below", "beneath"}


DIRECTIONAL = {
    "to",
    "into",
    "onto",
    "on to",
    "in to",
    "back into",
    "back onto",
    "back to",
    "over to",
    "up to",
    "all the way to",
}


def dest_of(item: Item, cls: str = "") -> NP | None:
    """The destination of one clause item: the receptacle after to/into/onto/in/on... With a verb of taking
    (`cls` "pick") only a direction counts ("take the towel to the hamper"); "pick up the card on the
    couch" says where the card is; so does a verb of slicing ("slice the apple in the pot")."""
    if cls in {"pick", "slice"}:
        item = Item(item.obj, [(p, np) for p, np in item.pps if p in DIRECTIONAL])
    last = [np for p, np in item.pps if p == THEN_TO]
    if last:
        return last[-1]
    for p, np in item.pps:
        if p in G.DEST_PREPS and p not in UNDER and np.is_receptacle():
            break  # "in a drawer under the sink": the drawer
        if p in UNDER and np.entry is not None and np.entry.canonical == "SinkBasin":
            return parse_np("cabinet")  # "store it under the sink"
        if p in UNDER and np.entry is not None and np.entry.canonical == "CoffeeMachine":
            return np  # "a mug under the coffee maker": under its spout, ALFRED's CoffeeMachine receptacle
    dests = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and np.is_receptacle() and p not in UNDER]
    if not dests:
        # "to the region H" in a domain without a lexicon entry: any NP after a destination preposition
        dests = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and np.head and not np.pronoun]
    if not dests:
        # "place it with the coffee machine": a fixed receptacle after "with" is where the thing goes
        fixed = [np for p, np in item.pps if p == "with" and is_fixed(np)]
        return fixed[0] if fixed and cls != "pick" else None
    # "the soap on the counter between the sinks in the drawer": a landmark before a plain place says where
    # the thing is now; the plain place after it is where it goes
    plain = next((k for k, (p, _) in enumerate(dests) if p in _PLACING), None)
    if plain is not None:
        dests = [d for k, d in enumerate(dests) if k >= plain or d[0] not in _LANDMARK_PREPS]
    for p, np in dests:
        if p in DIRECTIONAL:
            return np
    return dests[0][1]


_PLACING = {"in", "into", "inside", "on", "onto"}
_LANDMARK_PREPS = frozenset(G.NEAR_PREPS) | {"between", "in between", "among"}


TWO_PLACES = "two places it could go"
PICKED_OWNER = "picks one of several places the thing is in"  # "the second drawer's spoon"
# refusals of the grammar's that the learned model must not read as one whole task (`learned.inference`):
# the clause is read, and what it says is what no task can keep to
ONLY_WHERE_IT_IS = "only where it is now is said"  # "the mug in the sink should go."
NOT_A_WHOLE_TASK = (TWO_PLACES, PICKED_OWNER, ONLY_WHERE_IT_IS)


def two_places_unread(clause: str, places: str) -> str:
    """The grammar's refusal of a thing given two places to go; the learned model must not pick one
    (`NOT_A_WHOLE_TASK`)."""
    return f"{clause} ({TWO_PLACES}: {places}; say which)"


def two_places(item: Item) -> str:
    """ "put the CDs on the desk closest to the window in the safe": after its destination the item names
    another fixed place with a plain "in"/"on", not a step on the way ("to the sink and then the toilet")
    and not where on it ("on top of the dishwasher", "at the end of the counter"); which of the two is
    where the thing goes is a guess. The two places' words; "" when there are not two."""
    if any(p in DIRECTIONAL or p == THEN_TO for p, _ in item.pps):
        return ""
    places = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and p not in UNDER and is_fixed(np)]
    if len(places) < 2 or places[0][0] not in _PLACING:
        return ""
    later = [np for p, np in places[1:] if p in _PLACING and not same(np, places[0][1])]
    return f"{places[0][1].text} / {later[-1].text}" if later else ""


# Places that stand on the floor: never inside or on top of another place
_STANDING = frozenset(
    {"DiningTable", "CounterTop", "SideTable", "CoffeeTable", "Desk", "Dresser", "Bed", "Sofa", "ArmChair"}
    | {"Ottoman", "Fridge", "StoveBurner", "Toilet", "BathtubBasin", "TVStand"}
)
# parts of a piece of furniture or of an appliance ("the shelf in the fridge", "a drawer in the desk")
_PARTS = frozenset({"Drawer", "Shelf", "ShelvingUnit", "Cabinet"})
# what sits in or on a piece of furniture: its parts and the coffee maker ("the coffee maker on the counter";
# not the microwave: "cook it in the microwave to be placed on the counter" goes on to the counter)
_SITS_ON_FURNITURE = _PARTS | {"CoffeeMachine"}


def _standing_place_first(item: Item, text: str, away: bool = False) -> None:
    """ "wash the fork on the table in the sink", "put the goblet in the refrigerator on the table": of two
    fixed places with a plain "in"/"on", the first stands on the floor and the second is no part of it (a
    table is never in a sink), so the first says where the thing is and the second where it goes. Where
    the first is a part of a piece of furniture or the coffee maker and the second stands on the floor ("in
    a drawer in the dresser", "on the coffee maker on the counter"), the second says which one the first
    is ("of", no destination). After "put away" (`away`) the last place is where it is stored and the first
    where it is ("put away the candles on the counter in the cabinet"). Otherwise `two_places` refuses:
    which one is meant is not said."""
    if any(p in DIRECTIONAL or p == THEN_TO for p, _ in item.pps):
        return
    places = [k for k, (p, n) in enumerate(item.pps) if p in G.DEST_PREPS and p not in UNDER and is_fixed(n)]
    if len(places) != 2:
        return
    (p1, a), (p2, b) = item.pps[places[0]], item.pps[places[1]]
    types_a, types_b = set(a.entry.types) if a.entry else set(), set(b.entry.types) if b.entry else set()
    # "in the top drawer on the right side of the counter": a side says which drawer (a side after a whole
    # thing, "on the counter on the left side of the desk", stays refused)
    whole = not (types_a and types_a <= _PARTS)
    if not ({p1, p2} <= _PLACING and types_a and types_b) or types_a & types_b:
        return
    if not _one_phrase(text, a, b, whole):
        return
    if away and not (types_a <= _SITS_ON_FURNITURE and types_b <= _STANDING):
        item.pps[places[0]] = ("from", a)
    elif types_a <= _STANDING and (not types_b & _PARTS or _part_of_another(b, types_a)):
        item.pps[places[0]] = ("from", a)
    elif types_a <= _SITS_ON_FURNITURE and types_b <= _STANDING:  # "in a drawer in the dresser"
        item.pps[places[1]] = ("of", b)


def _part_of_another(part: NP, types_a: set[str]) -> bool:
    """ "on the dining table in the middle drawer of the dresser": the part says whose it is, a piece of
    furniture other than the first place, so it is no part of that place (which says where the thing is)."""
    _, of, owner = part.text.lower().partition(" of ")
    said = {t for m in find_mentions(owner) for t in m.entry.types} if of else set()
    return bool(said) and said <= _STANDING and not said & types_a


def _one_phrase(text: str, a: NP, b: NP, whole: bool = True) -> bool:
    """Do the places `a` and `b` follow each other in one phrase: no joiner or verb between them ("on the
    bed and on the nightstand" lists two places, "in the microwave to be placed on the counter" goes on),
    and, where `whole`, `b` is a whole thing, not a side or part of one ("on the night stand on the left
    side of the bed", "in the front of the coffee machine"; "the counter top" is a whole thing)?"""
    low = text.lower()
    i = low.find(a.text.lower())
    j = low.find(b.text.lower(), i + len(a.text)) if i >= 0 else -1
    if j < 0:
        return False
    # the words from the first place to the second ("the fridge or" is one noun phrase to the reader)
    between = [w for w, _, _ in tokens(low[i:j])]
    joined = set(between) & {"and", "or", "then", ",", "as", "while", "so", "followed"} or any(
        w in G.VERBS or w == "be" for w in between
    )
    b_words = [w for w, _, _ in tokens(b.text)]
    side_of = any(w in _SIDE_WORDS and b_words[k + 1 : k + 2] == ["of"] for k, w in enumerate(b_words))
    return not joined and not (side_of and whole)


_SIDE_WORDS = frozenset(
    {"side", "left", "right", "front", "back", "end", "edge", "corner", "top", "middle", "part"}
)


_TREATING = frozenset({"heat", "cool", "clean", "slice"})


def treats_another_object(fr: Frame, nxt: str, start: int, joiner: str, current: NP | None) -> bool:
    """Is `fr` a bare treatment verb of the object of the clause `nxt` right after it, another one than
    `current` ("put the egg in the sink, then chill then warm a tomato": the tomato is chilled, not the
    egg; "get the mug, chill, and return the mug": the mug)?"""
    if fr.cls not in _TREATING or joiner not in {"then", "and"} or len(fr.items) != 1 or current is None:
        return False
    it = fr.items[0]
    if (it.obj is not None and not it.obj.empty) or it.pps:
        return False
    o = next((i.obj for i in parse_frame(nxt, start, joiner).items[:1]), None)
    return o is not None and not o.empty and not o.pronoun and not same(o, current)


def is_fixed(np: NP) -> bool:
    """A receptacle that stays where it is (a table, the fridge), not a lamp."""
    return np.is_receptacle() and not np.is_movable_receptacle() and not np.is_lamp() and not np.pronoun


def near_dest(item: Item) -> NP | None:
    """ "by the sink" -> the counter, "under the sink" -> the cabinet."""
    for p, np in item.pps:
        if p in G.NEAR_PREPS and np.entry is not None and np.entry.canonical == "SinkBasin":
            return parse_np("counter")
        if p in UNDER and np.entry is not None and np.entry.canonical == "SinkBasin":
            return parse_np("cabinet")
    return None


def puts_into(holder: NP | None, fr: Frame, it: Item) -> bool:
    """Does a clause item put something else into `holder`, a movable receptacle the task moved so far
    ("move a cup to the sink and put a knife in the cup": one place_in_container task, as
    ANNOTATION_GUIDE.md says)?"""
    o = it.obj
    return (
        holder is not None
        and o is not None
        and not o.pronoun
        and holder.is_movable_receptacle()
        and not o.is_movable_receptacle()
        and (same(dest_of(it, fr.cls), holder) and not _said_other(dest_of(it, fr.cls)) or _into_it(it))
    )


def _said_other(np: NP | None) -> bool:
    """ "another box", "the other box", "a second box": not the holder moved so far (h212)."""
    words = np.text.lower().split()[:2] if np is not None else []
    return words[:1] == ["another"] or (len(words) == 2 and words[1] in _OTHER)


_OTHER = frozenset({"other", "second", "third", "different"})


def _into_it(it: Item) -> bool:
    """ "put the plate on the table, put the tissue box in it": its only place is "in / on it", the
    thing the task moved so far."""
    places = [(p, np) for p, np in it.pps if p in G.DEST_PREPS]
    into = {"in", "into", "on", "onto", "inside"}
    return len(places) == 1 and places[0][0] in into and places[0][1].pronoun


def item_text(fr: Frame, it: Item) -> str:
    """Own text of one item of a list clause: verb + object + its destination ("put plates into the rack")."""
    verb = fr.text.split()[0] if fr.text.split() else ""
    parts = [verb, it.obj.text if it.obj is not None else ""]
    parts += [f"{p} {np.text}" for p, np in it.pps if p in G.DEST_PREPS and np.text]
    return " ".join(x for x in parts if x)


def frame_unread(fr: Frame, c_text: str) -> str | None:
    """Why a clause's frame alone states no task of ours, as its `unparsed` entry; None where it may."""
    if any(it.obj is not None and it.obj.count > MAX_COUNT for it in fr.items):
        return f"{c_text} (more objects of one kind than any scene holds)"
    objects = [it.obj for it in fr.items if it.obj is not None]
    if any(o.heading_count or (o.generic and o.count > 2) for o in objects):
        # "three things: the egg ... and the mug ...": the count of a heading (`restated` drops one whose
        # count is the things listed) or of things of no named kind, not the count of the thing
        return f"{c_text} (a count of things of no named kind)"
    if fr.ambiguous:
        return f"{c_text} (a list of destinations)"
    if any(o.empty and o.text.lower().endswith(ROOM_WORDS) for o in objects):
        # "clean the kitchen": a room is never the thing of the task before (it was cleaned instead, h227)
        return f"{c_text} (a room: no thing to treat or move)"
    if fr.choice:
        return f"{c_text} (a choice between objects: say which one)"
    if places := next((w for it in fr.items if (w := two_places(it))), ""):
        return two_places_unread(c_text, places)
    return None
