"""Step 3, frames: one clause -> its verb class and its items (object + prepositional phrases)."""

from __future__ import annotations

from dataclasses import dataclass, field

from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.offline import grammar as G
from nl2hltl2plan.language.offline.phrases import COLOURS, DETERMINERS, NP, match_prep, parse_np, tokens


@dataclass
class Item:
    """One object of a clause with its prepositional phrases: [(prep, NP)]."""

    obj: NP | None
    pps: list[tuple[str, NP]] = field(default_factory=list)

    def pp(self, preps: set[str]) -> list[NP]:
        return [np for p, np in self.pps if p in preps]


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


SEQ_WORDS = {"then", "finally", "lastly", "afterwards", "afterward", "later"}  # not "next": "next to"
IN_SENTENCE = "in sentence"  # a "finally" that joins clauses of one sentence
THEN_TO = "then to"  # a further destination after a stop ("to the sink and finally the toilet")


def parse_frame(text: str, start: int = 0, joiner: str = "") -> Frame:
    toks = tokens(text)
    words = [w for w, _, _ in toks]
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
    # segments: prepositions start a PP; "," / "and" separate list items
    items: list[Item] = []
    cur_prep: str | None = None
    cur: list[tuple[str, int, int]] = []
    item = Item(obj=None)

    def flush() -> None:
        nonlocal cur, cur_prep
        if cur:
            np_text = text[cur[0][1] : cur[-1][2]]
            np = parse_np(np_text)
            if cur_prep is None:
                if item.obj is None:
                    item.obj = np
                else:
                    item.pps.append(("", np))
            else:
                item.pps.append((cur_prep, np))
        elif cur_prep is not None and cur_prep in {"inside", "in", "on"}:
            item.pps.append((cur_prep, NP(text="", pronoun=True)))
        cur = []

    while i < len(words):
        w = words[i]
        if (
            w in SEQ_WORDS
            and cur_prep is not None
            and cur_prep in G.DEST_PREPS
            and cls in {"place", "trash", "pick", "clean", "heat", "cool"}
            and i + 1 < len(words)
        ):
            # "in the microwave, then on the counter" / "to the sink and finally the toilet": a further
            # destination; the earlier ones become stops on the way
            flush()
            hit = match_prep(words, i + 1)
            i += 1 + (hit[1] if hit is not None and hit[0] in G.DEST_PREPS else 0)
            cur_prep = THEN_TO
            continue
        if w in {",", "and"} or (w == "or" and cur_prep is None):
            flush()
            # a new list item starts when the next words are a noun phrase without preposition
            nxt = words[i + 1] if i + 1 < len(words) else ""
            if (
                nxt
                and nxt not in {",", "and"}
                and match_prep(words, i + 1) is None
                and nxt not in SEQ_WORDS
            ):
                if item.obj is not None or item.pps:
                    items.append(item)
                    item = Item(obj=None)
                cur_prep = None
            i += 1
            continue
        if (
            light_on
            and w in {"on", "off"}
            and (
                i + 1 >= len(words)
                or words[i + 1] in DETERMINERS
                or words[i + 1] in {",", "and", "while", "with"}
                or words[i + 1] in G.VERBS
                or find_mentions(words[i + 1])
            )
        ):
            flush()  # "turn on the lamp", "turn the lamp on": a particle, not "on the table"
            cur_prep = None
            i += 1
            continue
        hit = match_prep(words, i)
        if hit is not None and not (hit[0] == "of" and cur):
            flush()
            cur_prep = hit[0]
            i += hit[1]
            continue
        cur.append(toks[i])
        i += 1
    flush()
    if item.obj is not None or item.pps or not items:
        items.append(item)
    ambiguous = False
    # "from the bath to the sink and finally the toilet": a sequence word before a fixed receptacle adds a
    # further destination (the earlier ones are stops on the way)
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
    # "to region G, H and I": bare noun phrases after an item with a destination continue that destination
    if len(items) > 1 and items[-1].obj is not None and not items[-1].pps and items[-2].pps:
        ambiguous = True
    # "the red and blue blocks": colour words share the noun of the last item
    if len(items) > 1 and items[-1].obj is not None:
        last_words = [w for w, _, _ in tokens(items[-1].obj.text) if w not in DETERMINERS]
        if last_words and last_words[0] in COLOURS and len(last_words) > 1:
            noun = " ".join(last_words[1:])
            for it in items[:-1]:
                ws = [w for w, _, _ in tokens(it.obj.text) if w not in DETERMINERS] if it.obj else []
                if ws and all(w in COLOURS for w in ws):
                    it.obj = parse_np(" ".join(ws) + " " + noun)
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
    )


# ----- drafts -> tasks ---------------------------------------------------------------------------------
def same(a: NP | None, b: NP | None) -> bool:
    return a is not None and b is not None and bool(a.key) and a.key == b.key


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
    couch" says where the card is."""
    if cls == "pick":
        item = Item(item.obj, [(p, np) for p, np in item.pps if p in DIRECTIONAL])
    last = [np for p, np in item.pps if p == THEN_TO]
    if last:
        return last[-1]
    for p, np in item.pps:
        if p in G.DEST_PREPS and p not in UNDER and np.is_receptacle():
            break  # "in a drawer under the sink": the drawer
        if p in UNDER and np.entry is not None and np.entry.canonical == "SinkBasin":
            return parse_np("cabinet")  # "store it under the sink"
    dests = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and np.is_receptacle() and p not in UNDER]
    if not dests:
        # "to the region H" in a domain without a lexicon entry: any NP after a destination preposition
        dests = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and np.head and not np.pronoun]
    if not dests:
        # "place it with the coffee machine": a fixed receptacle after "with" is where the thing goes
        fixed = [np for p, np in item.pps if p == "with" and is_fixed(np)]
        return fixed[0] if fixed and cls != "pick" else None
    for p, np in dests:
        if p in DIRECTIONAL:
            return np
    return dests[0][1]


def is_fixed(np: NP) -> bool:
    """A receptacle that stays where it is (a table, the fridge), not a lamp."""
    return np.is_receptacle() and not np.is_movable_receptacle() and not np.is_lamp() and not np.pronoun


def near_dest(item: Item) -> NP | None:
    for p, np in item.pps:
        if p in G.NEAR_PREPS and np.entry is not None and np.entry.canonical == "SinkBasin":
            return parse_np("counter")
        if (
            p in {"under", "underneath", "below", "beneath"}
            and np.entry is not None
            and np.entry.canonical == "SinkBasin"
        ):
            return parse_np("cabinet")
    return None


