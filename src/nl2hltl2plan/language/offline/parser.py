"""A deterministic grammar-based parser: instruction -> base tasks + temporal relations.

Pipeline (no model involved):

1. sentences: split on `.`, `;`, `!`, `?`; strip leading markers ("Then,", "Finally,", "After placing the
   statue,", "In any order,", "First,") and trailing ones ("at any time", "first", "afterwards", "after
   moving the X") and record them;
2. clauses: split a sentence before each verb that follows a joiner ("and", ",", "then", "to", ...);
3. frames: per clause the verb class and its noun phrases with their prepositions (object, destination,
   source, "with X in it", "by the light of a lamp"), the state words (washed, heated, chilled, sliced),
   counts ("two", plurals);
4. tasks: consecutive clauses about the same object ("it", "them", the same noun, the container)
   form one base task; several objects sharing one verb ("the phone and the bat") form a group;
5. relations: the ANNOTATION_GUIDE rules ("Then Y" after the previous clause, "Finally Y" after every
   earlier task not allowed at any time, "After X-ing the Z, Y" after the task about Z, "first",
   "prior to that", "after completing the previous tasks"), transitively reduced.

Whatever cannot be read this way is listed in `unparsed` instead of being guessed.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from pydantic import BaseModel, Field

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.grounding import (
    LAMPS,
    MOVABLE_RECEPTACLES,
    RECEPTACLES,
    AffordanceLookup,
    Entry,
    Grounder,
    Roles,
    alfred_lookup,
    find_mentions,
)
from nl2hltl2plan.language.offline import grammar as G
from nl2hltl2plan.language.tasks import BaseTaskSpec, task_letter, transitive_closure, transitive_reduction

_WORD = re.compile(r"[A-Za-z0-9]+(?:'[A-Za-z]+)?|,")
_DETERMINERS = {
    "the",
    "a",
    "an",
    "some",
    "any",
    "one",
    "another",
    "other",
    "each",
    "every",
    "this",
    "that",
    "these",
    "those",
    "its",
    "their",
    "my",
    "your",
    "his",
    "her",
    "our",
    "all",
    "both",
    "two",
    "three",
    "four",
    "five",
    "single",
    "couple",
    "pair",
    "set",
    "of",
    "several",
}
COLOURS = {
    "red",
    "blue",
    "green",
    "yellow",
    "pink",
    "purple",
    "white",
    "black",
    "grey",
    "gray",
    "brown",
    "multi-colored",
    "multicolored",
    "colored",
    "coloured",
    "multi",
    "orange-colored",
}
_FILLER = {
    "left",
    "right",
    "upper",
    "lower",
    "top",
    "bottom",
    "back",
    "front",
    "side",
    "edge",
    "end",
    "center",
    "centre",
    "middle",
    "seat",
    "lid",
    "surface",
    "corner",
    "open",
    "empty",
    "full",
    "opened",
    "closed",
    "new",
    "old",
    "small",
    "large",
    "big",
    "little",
    "left-most",
    "leftmost",
    "rightmost",
    "same",
    "most",
    "nearest",
    "closest",
    "first",
    "second",
    "third",
    "last",
    "other",
    "kitchen",
    "living",
    "room",
    "part",
    "area",
    "spot",
    "place",
    "inside",
}


# ----- result ----------------------------------------------------------------------------------------
class OfflineParse(BaseModel):
    """What the offline parser understood: base tasks, `before` pairs, groups, and what it could not read."""

    instruction: str
    tasks: list[BaseTaskSpec] = Field(default_factory=list)
    before: list[tuple[str, str]] = Field(default_factory=list)
    groups: list[list[str]] = Field(default_factory=list)
    group_texts: list[str] = Field(default_factory=list)  # the words that state each group
    unparsed: list[str] = Field(default_factory=list)
    issues: list[str] = Field(default_factory=list)


# ----- internal structures ---------------------------------------------------------------------------
@dataclass
class NP:
    """A noun phrase: its words, the lexicon entry of its head, and what its modifiers say."""

    text: str
    entry: Entry | None = None
    head: str = ""  # words naming the thing when no lexicon entry fits ("green apple", "region h")
    plural: bool = False
    count: int = 1
    pronoun: bool = False
    states: set[str] = field(default_factory=set)
    sliced: bool = False
    generic: bool = False
    water: bool = False

    @property
    def empty(self) -> bool:
        return self.entry is None and not self.head and not self.pronoun

    @property
    def key(self) -> str:
        if self.entry is not None:
            return self.entry.canonical
        return self.head

    def is_lamp(self) -> bool:
        return self.entry is not None and set(self.entry.types) <= LAMPS | {"LightSwitch"}

    def is_receptacle(self) -> bool:
        return self.entry is not None and any(t in RECEPTACLES for t in self.entry.types)

    def is_movable_receptacle(self) -> bool:
        return self.entry is not None and self.entry.canonical in MOVABLE_RECEPTACLES


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


@dataclass
class Unit:
    """The tasks of one clause (or one sentence part) and the temporal markers that apply to them."""

    tasks: list[int]
    sentence: int
    markers: list[tuple[str, str]] = field(default_factory=list)  # (kind, ref text)
    seq_after_prev: bool = False  # joined to the previous clause by "then" inside a sentence
    before_sentence: int = -1  # index of the last unit before this unit's sentence (-1: none)


# ----- text helpers ----------------------------------------------------------------------------------
def normalize(text: str) -> str:
    text = text.replace("\u2019", "'").replace("\u2018", "'").replace("\u201c", '"').replace("\u201d", '"')
    text = re.sub(r"(?<=[a-z])\.(?=[A-Za-z])", ". ", text)
    text = re.sub(r"\s*\([^)]*\)", "", text)  # parenthetical remarks: "(where the red block is now)"
    return re.sub(r"\s+", " ", text).strip()


def split_sentences(text: str) -> list[tuple[str, int]]:
    out: list[tuple[str, int]] = []
    pos = 0
    for m in re.finditer(r"[.;!?]+(?:\s+|$)", text):
        chunk = text[pos : m.start()].strip()
        if chunk:
            out.append((chunk, pos + (len(text[pos : m.start()]) - len(text[pos : m.start()].lstrip()))))
        pos = m.end()
    rest = text[pos:].strip()
    if rest:
        out.append((rest, pos))
    return out


def _words(text: str) -> list[tuple[str, int, int]]:
    return [(m.group(0).lower(), m.start(), m.end()) for m in _WORD.finditer(text)]


# ----- noun phrases ----------------------------------------------------------------------------------
def parse_np(text: str) -> NP:
    np = NP(text=text.strip())
    words = [w for w, _, _ in _words(text) if w != ","]
    if not words:
        return np
    mentions = find_mentions(text)
    # pronoun ("it", "them", "the same one")
    words = [w for w in words if w not in G.PARTICLES]
    content = [w for w in words if w not in _DETERMINERS and w not in G.PRONOUNS]
    if not content or (
        all(w in G.PRONOUNS | _DETERMINERS for w in words) and any(w in G.PRONOUNS for w in words)
    ):
        np.pronoun = any(w in G.PRONOUNS for w in words) or not content
    for w in words:
        if w in G.STATE_WORDS:
            st = G.STATE_WORDS[w]
            if st == "slice":
                np.sliced = True
            else:
                np.states.add(st)
        if w in G.SLICE_NOUNS:
            np.sliced = True
        if w in G.WATER_WORDS:
            np.water = True
        if w in G.NUMBERS and G.NUMBERS[w] > 1:
            np.count = max(np.count, G.NUMBERS[w])
    if "toast" in words:
        np.sliced = True
    real = [m for m in mentions if not m.entry.generic]
    if real:
        # the head is the first mention unless it is followed by "of" + another ("bar of soap" is one entry)
        m = real[0]
        np.entry, np.plural = m.entry, m.plural
        if m.plural and m.entry.canonical not in {"KeyChain"}:
            np.count = max(np.count, 2)
    elif mentions:
        np.generic = True
        np.plural = mentions[0].plural
    if not np.entry and not np.pronoun:
        head = [
            w
            for w in content
            if w not in G.STATE_WORDS
            and w not in G.SLICE_NOUNS
            and w not in _FILLER
            and w not in G.WATER_WORDS
        ]
        if np.generic:
            head = []
        np.head = " ".join(head)
        if (
            np.head
            and not np.generic
            and words[-1].endswith("s")
            and not words[-1].endswith("ss")
            and len(head) == 1
        ):
            np.plural = True
            np.count = max(np.count, 2)
    if np.pronoun and np.entry is None and not np.head and "same" in words:
        np.pronoun = True
    return np


# ----- clauses and frames ------------------------------------------------------------------------------
def _is_verb_at(words: list[tuple[str, int, int]], i: int) -> bool:
    w = words[i][0]
    if w not in G.VERBS:
        return False
    if i == 0:
        return True
    prev = words[i - 1][0]
    if prev == "," or prev in G.CLAUSE_JOINERS:
        # "to the", "in place": only when this word is used as a verb (followed by a noun phrase / particle)
        if (
            prev in {"to", "in", "order", "as", "so"}
            and G.VERBS[w][0] in {"place", "pick"}
            and w in {"place", "set", "rest", "stand", "sit", "bin", "light", "watch", "use", "find"}
        ):
            nxt = words[i + 1][0] if i + 1 < len(words) else ""
            return (
                nxt in {"it", "them", "the", "a", "an", "on", "in", "down", "up", "into", "onto"}
                and prev == "to"
            )
        if prev == "in" and w not in {"order"}:
            return False
        return True
    return False


def split_clauses(sentence: str) -> list[tuple[str, int, int, str]]:
    """(clause text, start, end, joiner) for each verb clause of a sentence."""
    words = _words(sentence)
    cuts: list[tuple[int, str]] = []
    for i in range(len(words)):
        if _is_verb_at(words, i):
            j = i - 1
            joiner = ""
            while j >= 0 and (words[j][0] == "," or words[j][0] in G.CLAUSE_JOINERS):
                if words[j][0] in G.SEQ_JOINERS:
                    joiner = G.SEQ_JOINERS[words[j][0]]
                elif words[j][0] in {"to", "and", "while", "plus", "or", "as"} and not joiner:
                    joiner = words[j][0]
                j -= 1
            cut = words[j + 1][1] if j + 1 < i else words[i][1]
            cuts.append((cut if i else 0, joiner))
    if not cuts or cuts[0][0] != 0:
        cuts.insert(0, (0, ""))
    out = []
    for k, (cut, joiner) in enumerate(cuts):
        end = cuts[k + 1][0] if k + 1 < len(cuts) else len(sentence)
        chunk = sentence[cut:end]
        stripped = re.sub(
            r"^[\s,]*(?:(?:and|then|to|plus|also|while|or|as|so|first|next|finally|lastly|afterwards?|"
            r"subsequently)\b[\s,]*)*",
            "",
            chunk,
            flags=re.I,
        )
        stripped = re.sub(r"[\s,]*(?:\band\b)?[\s,]*$", "", stripped)
        if stripped:
            s = cut + chunk.index(stripped)
            out.append((stripped, s, s + len(stripped), joiner))
    return out


# ----- elided verbs ("first the saucers, then the cups, in the upper rack") -------------------------------
_GAP_SPLIT = re.compile(
    r"(?:\s*,\s*|\s+)(?:and\s+)?(?P<j>then|next|afterwards?|after\s+that|finally|lastly|followed\s+by)\b"
    r"\s*,?\s*",
    re.I,
)
_GAP_JOINER = {"finally": "finally", "lastly": "finally"}


@dataclass
class Clause:
    """One verb clause of a sentence; `gap` >= 0 marks clauses rebuilt from one elided-verb list (a group
    when they share one destination), `label` their rebuilt text ("put the cups in the upper rack")."""

    text: str
    start: int
    end: int
    joiner: str
    gap: int = -1
    label: str = ""
    whole: str = ""  # the text of the whole list, verb restored


def _movable_np(text: str) -> bool:
    """Does `text` start with a noun phrase naming a movable thing (not a fixed receptacle, not a lamp)?"""
    words = [w for w, _, _ in _words(text)]
    if not words or _match_prep(words, 0) is not None or words[0] in G.VERBS:
        return False
    head = parse_np(re.split(r"\s*,\s*|\s+(?=(?:in|into|on|onto|to|inside|at)\b)", text, maxsplit=1)[0])
    if head.entry is None or head.generic or head.is_lamp():
        return False
    return not (head.is_receptacle() and not head.is_movable_receptacle())


def _dest_pp(verb: str, text: str) -> str:
    """The destination phrase of `verb text` as written ("in the upper rack"), or ""."""
    fr = parse_frame(f"{verb} {text}")
    for it in fr.items:
        dst = _dest_of(it, fr.cls)
        if dst is not None:
            for p, np in it.pps:
                if np is dst:
                    return f"{p} {np.text}"
    return ""


def expand_gapping(
    clauses: list[tuple[str, int, int, str]], verb: str, last_dest: str, gap_base: int = 0
) -> list[Clause]:
    """Clauses with an elided verb get it back: "put the plates in the lower rack, then the cups in the upper
    rack" and a verbless "first the saucers, then the cups, in the upper rack" after a clause whose verb was
    "put". A list of objects split by sequence words ("then", "next", "finally") becomes one clause per
    object with the verb of the clause (or `verb`, the previous clause's, when the clause has none); objects
    without a destination share the last one stated (then they form a group), or, in a verbless sentence
    that names none, `last_dest` (the previous clause's destination: "Then the tomato")."""
    out: list[Clause] = []
    for k, (text, start, end, joiner) in enumerate(clauses):
        words = [w for w, _, _ in _words(text)]
        own = bool(words) and words[0] in G.VERBS
        if own:
            cut = len(text.split(None, 1)[0])
            v, args, a0 = text[:cut], text[cut:].lstrip(), len(text) - len(text[cut:].lstrip())
        elif verb and k == 0:
            v, args, a0 = verb, text, 0
        else:
            out.append(Clause(text, start, end, joiner))
            continue
        # split at sequence words that are followed by a movable object (not "then on the counter")
        parts: list[tuple[str, int, str]] = []  # (segment, offset in args, joiner)
        pos, seg_joiner = 0, joiner
        for m in _GAP_SPLIT.finditer(args):
            if m.start() <= pos or not _movable_np(args[m.end() :]):
                continue
            parts.append((args[pos : m.start()], pos, seg_joiner))
            seg_joiner = _GAP_JOINER.get(m.group("j").lower(), "then")
            pos = m.end()
        parts.append((args[pos:], pos, seg_joiner))
        parts = [(seg.strip(" ,"), off, j) for seg, off, j in parts if seg.strip(" ,")]
        if own and len(parts) < 2:
            out.append(Clause(text, start, end, joiner))
            continue
        if not parts or not _movable_np(parts[0][0]):
            out.append(Clause(text, start, end, joiner))
            continue
        dests = [_dest_pp(v, seg) for seg, _, _ in parts]
        shared = next((d for d in reversed(dests) if d), "") or ("" if own else last_dest)
        missing = [i for i, d in enumerate(dests) if not d]
        sharing = [i for i, d in enumerate(dests) if not d or d == shared]
        gap = gap_base + k if len(sharing) > 1 and missing and shared else -1
        for i, (seg, off, j) in enumerate(parts):
            seg_text = seg
            if not dests[i] and shared:  # "the saucers" + "in the upper rack"
                seg_text = f"{seg.rstrip(' ,')} {shared}"
            elif shared and dests[i] == shared:  # "the cups, in the upper rack": drop the comma
                seg_text = re.sub(r"\s*,\s*(?=" + re.escape(shared) + r"$)", " ", seg)
            label = f"{v} {seg_text}"
            s0 = start + a0 + off
            whole = text if own else f"{v} {text}"
            out.append(Clause(label, s0, s0 + len(seg), j, gap if i in sharing else -1, label, whole))
    return out


def _match_prep(words: list[str], i: int) -> tuple[str, int] | None:
    for p in G.PREPOSITIONS:
        if tuple(words[i : i + len(p)]) == p:
            return " ".join(p), len(p)
    return None


_SEQ_WORDS = {"then", "finally", "lastly", "afterwards", "afterward", "later"}  # not "next": "next to"
_IN_SENTENCE = "in sentence"  # a "finally" that joins clauses of one sentence
_THEN_TO = "then to"  # a further destination after a stop ("to the sink and finally the toilet")


def parse_frame(text: str, start: int = 0, joiner: str = "") -> Frame:
    toks = _words(text)
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
            w in _SEQ_WORDS
            and cur_prep is not None
            and cur_prep in G.DEST_PREPS
            and cls in {"place", "trash", "pick", "clean", "heat", "cool"}
            and i + 1 < len(words)
        ):
            # "in the microwave, then on the counter" / "to the sink and finally the toilet": a further
            # destination; the earlier ones become stops on the way
            flush()
            hit = _match_prep(words, i + 1)
            i += 1 + (hit[1] if hit is not None and hit[0] in G.DEST_PREPS else 0)
            cur_prep = _THEN_TO
            continue
        if w in {",", "and"} or (w == "or" and cur_prep is None):
            flush()
            # a new list item starts when the next words are a noun phrase without preposition
            nxt = words[i + 1] if i + 1 < len(words) else ""
            if (
                nxt
                and nxt not in {",", "and"}
                and _match_prep(words, i + 1) is None
                and nxt not in _SEQ_WORDS
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
                or words[i + 1] in _DETERMINERS
                or words[i + 1] in {",", "and", "while", "with"}
                or words[i + 1] in G.VERBS
                or find_mentions(words[i + 1])
            )
        ):
            flush()  # "turn on the lamp", "turn the lamp on": a particle, not "on the table"
            cur_prep = None
            i += 1
            continue
        hit = _match_prep(words, i)
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
        and _words(items[-1].obj.text)[0][0] in _SEQ_WORDS
        and items[-1].obj.is_receptacle()
        and not items[-1].obj.is_movable_receptacle()
    ):
        items[-2].pps.append((_THEN_TO, items[-1].obj))
        items.pop()
    # "to region G, H and I": bare noun phrases after an item with a destination continue that destination
    if len(items) > 1 and items[-1].obj is not None and not items[-1].pps and items[-2].pps:
        ambiguous = True
    # "the red and blue blocks": colour words share the noun of the last item
    if len(items) > 1 and items[-1].obj is not None:
        last_words = [w for w, _, _ in _words(items[-1].obj.text) if w not in _DETERMINERS]
        if last_words and last_words[0] in COLOURS and len(last_words) > 1:
            noun = " ".join(last_words[1:])
            for it in items[:-1]:
                ws = [w for w, _, _ in _words(it.obj.text) if w not in _DETERMINERS] if it.obj else []
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
def _same(a: NP | None, b: NP | None) -> bool:
    return a is not None and b is not None and bool(a.key) and a.key == b.key


_UNDER = {"under", "underneath", "below", "beneath"}


_DIRECTIONAL = {
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


def _dest_of(item: Item, cls: str = "") -> NP | None:
    """The destination of one clause item: the receptacle after to/into/onto/in/on... With a verb of taking
    (`cls` "pick") only a direction counts ("take the towel to the hamper"); "pick up the card on the
    couch" says where the card is."""
    if cls == "pick":
        item = Item(item.obj, [(p, np) for p, np in item.pps if p in _DIRECTIONAL])
    last = [np for p, np in item.pps if p == _THEN_TO]
    if last:
        return last[-1]
    for p, np in item.pps:
        if p in G.DEST_PREPS and p not in _UNDER and np.is_receptacle():
            break  # "in a drawer under the sink": the drawer
        if p in _UNDER and np.entry is not None and np.entry.canonical == "SinkBasin":
            return parse_np("cabinet")  # "store it under the sink"
    dests = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and np.is_receptacle() and p not in _UNDER]
    if not dests:
        # "to the region H" in a domain without a lexicon entry: any NP after a destination preposition
        dests = [(p, np) for p, np in item.pps if p in G.DEST_PREPS and np.head and not np.pronoun]
    if not dests:
        # "place it with the coffee machine": a fixed receptacle after "with" is where the thing goes
        fixed = [np for p, np in item.pps if p == "with" and _fixed(np)]
        return fixed[0] if fixed and cls != "pick" else None
    for p, np in dests:
        if p in _DIRECTIONAL:
            return np
    return dests[0][1]


def _fixed(np: NP) -> bool:
    """A receptacle that stays where it is (a table, the fridge), not a lamp."""
    return np.is_receptacle() and not np.is_movable_receptacle() and not np.is_lamp() and not np.pronoun


def _near_dest(item: Item) -> NP | None:
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


class _Builder:
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
                    for w in _words(np.text)
                    if w[0] not in _DETERMINERS
                    and w[0] not in G.STATE_WORDS
                    and not any(a <= w[1] < b for a, b in spans)
                ]
                extra = [
                    w[0]
                    for w in words
                    if w[0] not in _FILLER
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
                elif container is None and dests and _same(o, dests[-1]) and o.is_movable_receptacle():
                    container = o  # "put a card in a bowl and put the bowl on the desk"
                elif _same(o, container):
                    pass
                elif not _same(o, obj) and o.is_lamp():
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
                    if p == "with" and _fixed(np):
                        continue  # "place it with the coffee machine": the destination (_dest_of)
                    if np.water:
                        states.append("clean")
                        continue
                    if np.is_lamp():
                        light = np
                        continue
                    if p in {"along with", "together with"} and (_same(np, obj) or np.entry is None):
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
                    elif _same(np, obj):
                        count = max(count, 2)
            dst = _dest_of(it, fr.cls) or _near_dest(it)
            if any(p == _THEN_TO for p, _ in it.pps):  # stops on the way come before the destination
                dests += [
                    np for p, np in it.pps if p in G.DEST_PREPS and np.is_receptacle() and np is not dst
                ]
            if fr.cls == "trash" and dst is None:
                dst = parse_np("garbage can")
            if dst is not None and not dst.is_lamp():
                recs = [
                    np for p, np in it.pps if p in G.DEST_PREPS and np.is_receptacle() and p not in _UNDER
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
        if container is not None and final is not None and _same(final, container):
            final = dests[-2] if len(dests) >= 2 and not _same(dests[-2], container) else None
            if final is None:
                container = None
                final = dests[-1]
        # intermediate appliances imply a state change ("put it in the microwave, then on the counter")
        for mid in dests[:-1]:
            if mid.entry is not None and not _same(mid, container):
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


def _item_text(fr: Frame, it: Item) -> str:
    """Own text of one item of a list clause: verb + object + its destination ("put plates into the rack")."""
    verb = fr.text.split()[0] if fr.text.split() else ""
    parts = [verb, it.obj.text if it.obj is not None else ""]
    parts += [f"{p} {np.text}" for p, np in it.pps if p in G.DEST_PREPS and np.text]
    return " ".join(x for x in parts if x)


def _joins(d: Draft, fr: Frame, it: Item) -> bool:
    """Does clause item `it` continue task draft `d` (same object, pronoun, no object, container)?"""
    o = it.obj
    last_fr = d.frames[-1][0]
    cur = d.obj
    if fr.joiner == "after" or fr.joiner == "before":
        return False
    if o is None or o.empty:
        if fr.cls == "fill" and _dest_of(it, fr.cls) is not None:
            return False  # "fill water in the bathtub": not about the current object
        return fr.cls != "none" or bool(it.pps)
    if o.pronoun:
        return True
    if o.is_lamp() and (fr.cls in {"light", "examine"} or fr.light_on):
        return _incomplete(d)  # "pick up the keys and turn on the lamp"; not after a placement
    if cur is None:
        # the draft so far only switched a lamp on: "turn on a lamp while holding a laptop"
        return fr.cls in {"pick", "examine"} or (fr.cls == "place" and last_fr.cls == "light")
    if _same(o, cur):
        # "place the yellow block to region I, then place it... to region G": a second placement is a new task
        prev_dest = _dest_of(d.frames[-1][1], last_fr.cls)
        if (
            fr.joiner in {"then", "first"}
            and fr.cls == "place"
            and last_fr.cls == "place"
            and prev_dest is not None
            and _dest_of(it, fr.cls) is not None
            and (
                prev_dest.entry is None
                or prev_dest.entry.canonical not in {"SinkBasin", "Microwave", "Fridge"}
            )
        ):
            return False
        return True
    if o.sliced and o.entry is None and o.head in {"", "slice", "piece"}:
        return True
    for (
        _,
        it2,
    ) in d.frames:  # the container of the content: "put a spoon in a mug and put the mug on the table"
        dst = _dest_of(it2)
        if dst is not None and _same(o, dst) and o.is_movable_receptacle():
            return True
        for p, np in it2.pps:
            if p in G.WITH_PREPS and _same(o, np):
                return True
    if last_fr.cls in {"slice"} and o.sliced:
        return True
    return False


def _incomplete(d: Draft) -> bool:
    """A draft that only picked / changed the state of something: the next clause usually completes it."""
    for fr, it in d.frames:
        if _dest_of(it, fr.cls) is not None or fr.cls in {"light", "examine", "trash"} or fr.light_on:
            return False
    return True


# ----- reference resolution -----------------------------------------------------------------------------
def _ref_parts(ref: str) -> list[str]:
    return [p.strip() for p in re.split(r",|\band\b|\bas well as\b|\bplus\b", ref, flags=re.I) if p.strip()]


def _ref_targets(
    ref: str,
    specs: list[BaseTaskSpec],
    nps: list[NP | None],
    lights: list[bool],
    upto: int | None,
    exclude: list[int] | None = None,
) -> tuple[list[int], list[str]]:
    """Task indices a reference ("placing the statue and moving the knife") names; unresolved parts."""
    found: list[int] = []
    missing: list[str] = []
    last_np: NP | None = None
    candidates = [i for i in (range(len(specs)) if upto is None else range(upto)) if i not in (exclude or [])]
    for part in _ref_parts(ref):
        words = [w for w, _, _ in _words(part)]
        k = 0
        while k < len(words) and (
            words[k] in G.VERBS
            or words[k] in G.VERB_PAST
            or words[k] in G.PARTICLES
            or words[k] in {"having", "been", "is", "are", "was", "you"}
        ):
            k += 1
        np = parse_np(
            " ".join(
                w for w in words[k:] if w not in {"is", "are", "was", "were", "been"} and w not in G.VERB_PAST
            )
        )
        hit: list[int] = []
        if (
            np.entry is not None
            and np.is_lamp()
            or (not np.entry and any(w in {"lamp", "light"} for w in words))
        ):
            hit = [i for i in candidates if lights[i]]
        elif np.entry is not None or np.head:
            key = np.key
            hit = [i for i in candidates if nps[i] is not None and nps[i].key == key]
            hit = hit or [
                i
                for i in candidates
                if nps[i] is not None
                and (
                    nps[i].key == key
                    or (
                        np.entry is not None
                        and nps[i].entry is not None
                        and set(np.entry.types) & set(nps[i].entry.types)
                    )
                )
            ]
            if not hit and np.entry is not None:
                hit = [
                    i
                    for i in candidates
                    if np.entry.canonical in (specs[i].container or [])
                    or np.entry.canonical in specs[i].object
                ]
            if not hit and np.entry is not None:  # "after putting items to the lower rack": by destination
                hit = [i for i in candidates if np.entry.canonical in (specs[i].receptacle or [])]
                found.extend(hit)
            if not hit and np.head:
                hit = [
                    i
                    for i in candidates
                    if np.head.replace(" ", "") in "".join(specs[i].object).lower()
                    or any(np.head.replace(" ", "") in r.lower() for r in (specs[i].receptacle or []))
                ]
        elif last_np is None and part:
            pass
        if hit:
            found.append(hit[-1] if len(hit) > 1 and np.entry is not None and not np.plural else hit[-1])
            if np.plural and len(hit) > 1:
                found.extend(hit)
        else:
            missing.append(part)
        last_np = np
    return sorted(set(found)), missing


# ----- main entry ----------------------------------------------------------------------------------------
def parse_instruction(
    instruction: str,
    types: set[str] | frozenset[str] | None = None,
    scene: str = "the scene",
    strict: bool = False,
    affordances: AffordanceLookup | None = None,
) -> OfflineParse:
    """Parse one instruction. `types`: the scene's object types (None: keep the words, no grounding).

    With `strict=True` a word whose type is not in the scene raises `WorldError` ("no Statue in
    FloorPlan17"); otherwise it is kept with its most plausible type and listed in `issues`.
    `affordances` (type -> `Affordances` or None when unknown; default: ALFRED's facts when the shared data
    is there) narrows a word with several types to those that can play their role (`grounding.Roles`).
    """
    text = normalize(instruction)
    grounder = Grounder(types, scene) if types is not None else None
    if types is not None and affordances is None:
        affordances = alfred_lookup()
    b = _Builder(grounder, strict, affordances)
    drafts: list[Draft] = []
    units: list[Unit] = []
    extra_rel: list[tuple[str, int, str]] = []  # relation sentences between objects
    next_group = [-1]
    group_text: dict[int, str] = {}
    gap_groups: dict[int, int] = {}  # Clause.gap -> group
    last_verb, last_dest = "", ""
    for s_idx, (sentence, s_start) in enumerate(split_sentences(text)):
        body = sentence
        markers: list[tuple[str, str]] = []
        changed = True
        while changed:
            changed = False
            split = _after_ref(body)
            if split is not None:
                markers.append((G.AFTER_REF, split[0]))
                body = split[1]
                changed = True
                continue
            for pat, kind in G.LEADING:
                m = pat.match(body)
                if m and m.end() > 0:
                    ref = m.groupdict().get("ref") or ""
                    if kind:
                        markers.append((kind, ref))
                    body = body[m.end() :]
                    changed = True
                    break
        rel = G.REL_SENTENCE.match(body)
        if rel and not any(w in G.VERBS for w, _, _ in _words(rel.group("a"))[:1]):
            # "The red block should be placed before the blue block": relation between tasks named by objects
            extra_rel.append((rel.group("rel").lower(), -1, rel.group("a") + "|" + rel.group("b")))
            continue
        trailing: list[tuple[str, str]] = []
        changed = True
        while changed and body:
            changed = False
            for pat, kind in G.TRAILING:
                m = pat.search(body)
                if m and m.start() > 0:
                    if kind == "ref":
                        rel = m.group("rel").lower()
                        trailing.append((G.BEFORE_REF if rel == "before" else G.AFTER_REF, m.group("ref")))
                    else:
                        trailing.append((kind, ""))
                    body = body[: m.start()]
                    changed = True
                    break
        body = body.strip(" ,")
        if not body:
            continue
        rel = G.REL_SENTENCE.match(body)
        if rel and not any(w in G.VERBS for w, _, _ in _words(rel.group("a"))[:1]):
            # "The red block should be placed before the blue block."
            extra_rel.append((rel.group("rel").lower(), -1, rel.group("a") + "|" + rel.group("b")))
            continue
        if G.NO_ORDER_SENTENCE.search(body) and not any(w in G.VERBS for w, _, _ in _words(body)[:1]):
            continue
        offset = s_start + sentence.index(body) if body in sentence else s_start
        clauses = expand_gapping(split_clauses(body), last_verb, last_dest, gap_base=100 * s_idx)
        first_unit = len(units)
        sentence_drafts: list[int] = []
        prev_clause_tasks: list[int] = []
        # "put things into the upper rack, first X, then Y": a shared destination for the clauses that follow
        context: list[tuple[str, NP]] = []
        context_group = -1
        pending_joiner = ""
        for clause in clauses:
            c_text, c_start, joiner = clause.text, clause.start, clause.joiner
            fr = parse_frame(c_text, offset + c_start, joiner)
            if fr.cls not in {"none", "other"}:
                last_verb = c_text.split()[0]
                for it in fr.items:
                    dst = _dest_of(it, fr.cls)
                    last_dest = next((f"{p} {np.text}" for p, np in it.pps if np is dst), last_dest)
            joiner = joiner or pending_joiner
            pending_joiner = ""
            if fr.cls == "none":
                if not sentence_drafts or any(
                    it.obj is not None and not it.obj.empty and not it.obj.pronoun for it in fr.items
                ):
                    b.unparsed.append(c_text)
                    continue
            if any(it.obj is not None and it.obj.count > 2 for it in fr.items):
                b.unparsed.append(
                    f"{c_text} (more than two objects of one kind in one task is not supported)"
                )
                continue
            if fr.ambiguous:
                b.unparsed.append(f"{c_text} (a list of destinations)")
                continue
            if fr.cls == "light" and not any(
                (it.obj is not None and it.obj.is_lamp()) or any(np.is_lamp() for _, np in it.pps)
                for it in fr.items
            ):
                if not any(it.obj is not None and it.obj.pronoun for it in fr.items):
                    fr.cls = "other"  # "switch on the coffee machine": no lamp, no task of ours
            if fr.cls == "other":
                real = [
                    it.obj
                    for it in fr.items
                    if it.obj is not None and not it.obj.empty and not it.obj.pronoun
                ]
                noise = (
                    fr.verb in {"open", "close", "shut"}
                    and sentence_drafts
                    and all(o.is_receptacle() or "door" in o.text.lower() for o in real)
                )
                if real and not noise:
                    b.unparsed.append(c_text)
                continue  # "close the refrigerator door", "while doing so"
            if all(it.obj is not None and it.obj.generic for it in fr.items):
                # a heading about generic things ("place items into the dishwasher"): its destination is the
                # context of the clauses that follow in this sentence, which form a group
                context = [(p, np) for it in fr.items for p, np in it.pps if p in G.DEST_PREPS]
                next_group[0] += 1
                context_group = next_group[0]
                group_text[context_group] = fr.text
                pending_joiner = joiner
                continue
            if context:
                for it in fr.items:
                    if it.obj is not None and not any(p in G.DEST_PREPS for p, _ in it.pps):
                        it.pps.extend(context)
            # multi-object clause items sharing one destination at the end: copy it to the others
            if len(fr.items) > 1:
                shared = [(p, np) for p, np in fr.items[-1].pps if p in G.DEST_PREPS]
                for it in fr.items[:-1]:
                    if not any(p in G.DEST_PREPS for p, _ in it.pps):
                        it.pps.extend(shared)
                fr.items = _merge_items(fr.items, b)
            new_tasks: list[int] = []
            if clause.gap >= 0:
                if clause.gap not in gap_groups:
                    next_group[0] += 1
                    gap_groups[clause.gap] = next_group[0]
                    group_text[next_group[0]] = clause.whole
                group = gap_groups[clause.gap]
            elif context_group >= 0:
                group = context_group
            elif len(fr.items) > 1:
                next_group[0] += 1
                group = next_group[0]
                group_text[group] = fr.text
            else:
                group = -1
            for it in fr.items:
                d = drafts[sentence_drafts[-1]] if sentence_drafts else None
                if (
                    d is not None
                    and len(fr.items) == 1
                    and joiner not in {"first", "finally"}
                    and (
                        _joins(d, fr, it)
                        or (
                            _incomplete(d)
                            and fr.cls not in {"pick"}
                            and it.obj is not None
                            and (it.obj.pronoun or it.obj.empty)
                        )
                    )
                ):
                    d.frames.append((fr, it))
                    d.end = fr.end
                    continue
                if d is not None and len(fr.items) == 1 and _incomplete(d) and d.obj is None:
                    d.frames.append((fr, it))
                    d.end = fr.end
                    continue
                label = clause.label if len(fr.items) == 1 else ""
                if len(fr.items) > 1 or context:
                    label = _item_text(fr, it)
                drafts.append(
                    Draft(
                        frames=[(fr, it)],
                        sentence=s_idx,
                        start=fr.start,
                        end=fr.end,
                        group=group,
                        label=label,
                    )
                )
                sentence_drafts.append(len(drafts) - 1)
                new_tasks.append(len(drafts) - 1)
            if new_tasks:
                unit = Unit(tasks=new_tasks, sentence=s_idx, before_sentence=first_unit - 1)
                if joiner == "then" and prev_clause_tasks:
                    unit.seq_after_prev = True
                if joiner == "first":
                    unit.markers.append((G.FIRST, ""))
                if joiner == "finally":
                    unit.markers.append((G.FINALLY, _IN_SENTENCE))
                units.append(unit)
                prev_clause_tasks = new_tasks
        sentence_units = units[first_unit:]
        if not sentence_units:
            continue
        for kind, ref in markers:
            for u in sentence_units:
                u.markers.append((kind, ref))
        for kind, ref in trailing:
            if kind in {G.THEN, G.FINALLY} and len(sentence_units) > 1:
                sentence_units[-1].markers.append((kind, _IN_SENTENCE if kind == G.FINALLY else ref))
                sentence_units[-1].before_sentence = len(units) - 2
            elif kind == G.FREE and len(sentence_units) == 1 and len(sentence_units[0].tasks) > 1:
                pass  # "move the phone and the bat to the bed in any order": order inside the group is free
            elif (
                kind == G.FREE
                and len(sentence_units) > 1
                and sentence_units[0].markers == []
                and all(drafts[t].group >= 0 for u in sentence_units for t in u.tasks)
            ):
                pass
            else:
                for u in sentence_units:
                    u.markers.append((kind, ref))

    # drafts -> specs (drop drafts that are not tasks)
    specs: list[BaseTaskSpec | None] = []
    for d in drafts:
        t = d.label or text[d.start : d.end]
        try:
            specs.append(b.spec(d, t))
        except WorldError:
            raise
    keep = [i for i, s in enumerate(specs) if s is not None]
    index = {old: new for new, old in enumerate(keep)}
    final_specs: list[BaseTaskSpec] = [specs[i] for i in keep]  # type: ignore[misc]
    nps = [drafts[i].obj for i in keep]
    lights = [s.kind == "examine_in_light" for s in final_specs]
    for u in units:
        u.tasks = [index[t] for t in u.tasks if t in index]
    units = [u for u in units if u.tasks]

    # relations --------------------------------------------------------------------------------------------
    edges: set[tuple[int, int]] = set()
    free: set[int] = set()
    for u in units:
        kinds = {kind for kind, _ in u.markers}
        if G.FREE in kinds:
            free.update(u.tasks)
    for k, u in enumerate(units):
        prev = units[k - 1] if k > 0 else None
        seq_prev = prev
        # sentence markers refer to the clause before the sentence, not to a sibling clause of the sentence
        if prev is not None and prev.sentence == u.sentence and not u.seq_after_prev:
            cands = [v for v in units[:k] if v.sentence != u.sentence]
            prev = cands[-1] if cands else None
        first_of_sentence = min(t for v in units if v.sentence == u.sentence for t in v.tasks)
        earlier = [t for t in range(len(final_specs)) if t < first_of_sentence]
        for kind, ref in u.markers:
            if kind == G.THEN and prev is not None:
                edges.update((a, b2) for a in prev.tasks for b2 in u.tasks)
            elif kind == G.FINALLY:
                # "..., and finally Y" inside a sentence: after its sibling clauses too
                scope = [t for t in range(min(u.tasks))] if ref == _IN_SENTENCE else earlier
                edges.update((a, b2) for a in scope if a not in free for b2 in u.tasks)
            elif kind == G.AFTER_ALL:
                edges.update((a, b2) for a in earlier for b2 in u.tasks)
            elif kind == G.BEFORE_PREV and prev is not None:
                edges.update((b2, a) for a in prev.tasks for b2 in u.tasks)
            elif kind in {G.AFTER_REF, G.BEFORE_REF}:
                targets, missing = _ref_targets(ref, final_specs, nps, lights, None, exclude=u.tasks)
                own, _ = _ref_targets(ref, final_specs, nps, lights, None)
                if not targets and own and all(t in u.tasks for t in own):
                    _self_state(ref, [final_specs[t] for t in u.tasks])
                    continue
                targets = [t for t in targets if t not in u.tasks]
                for t in targets:
                    for b2 in u.tasks:
                        edges.add((t, b2) if kind == G.AFTER_REF else (b2, t))
                if missing and not targets:
                    # "after refrigerating the pan" about the task itself: a state, not an order
                    self_ref = any(
                        parse_np(p).key
                        and any(parse_np(p).key == (nps[t].key if nps[t] else None) for t in u.tasks)
                        for p in missing
                    )
                    if not self_ref:
                        new = _new_tasks_from_ref(ref, b, text)
                        for spec in new:
                            final_specs.append(spec)
                            nps.append(None)
                            lights.append(spec.kind == "examine_in_light")
                            t = len(final_specs) - 1
                            for b2 in u.tasks:
                                edges.add((t, b2) if kind == G.AFTER_REF else (b2, t))
                        if not new:
                            b.unparsed.append(f"could not tell which task {ref!r} refers to")
        if u.seq_after_prev and seq_prev is not None:
            edges.update((a, b2) for a in seq_prev.tasks for b2 in u.tasks)
    # "First X" with no sequencing word right after: X before every later task not allowed at any time
    for k, u in enumerate(units):
        if any(kind == G.FIRST for kind, _ in u.markers):
            nxt = units[k + 1] if k + 1 < len(units) else None
            if nxt is not None and (
                nxt.seq_after_prev
                or any(kind in {G.THEN, G.AFTER_ALL, G.AFTER_REF} for kind, _ in nxt.markers)
            ):
                continue
            later = [t for v in units[k + 1 :] for t in v.tasks if t not in free]
            edges.update((a, b2) for a in u.tasks for b2 in later)
    # relation sentences between objects ("the red block should be placed before the blue block")
    for rel_kind, _, payload in extra_rel:
        if "|" not in payload:
            continue
        a_txt, b_txt = payload.split("|", 1)
        ta, _ = _ref_targets(a_txt, final_specs, nps, lights, None)
        tb, _ = _ref_targets(b_txt, final_specs, nps, lights, None)
        if not ta or not tb:
            b.unparsed.append(f"{a_txt} {rel_kind} {b_txt}")
        for x in ta:
            for y in tb:
                if x != y:
                    edges.add((x, y) if rel_kind == "before" else (y, x))

    # ids, acyclicity, reduction
    ids = [task_letter(i) for i in range(len(final_specs))]
    for i, s in enumerate(final_specs):
        s.id = ids[i]
    pairs = {(ids[a], ids[b2]) for a, b2 in edges if a != b2}
    closure = transitive_closure(pairs, ids)
    cyc = [(a, b2) for a, b2 in pairs if (b2, a) in closure]
    if cyc:
        b.unparsed.append(
            f"contradictory order words (cycle among {sorted({x for p in cyc for x in p})}); dropped"
        )
        pairs -= set(cyc)
    before = transitive_reduction(pairs, ids)
    groups: dict[int, list[str]] = {}
    for old, new in index.items():
        g = drafts[old].group
        if g >= 0:
            groups.setdefault(g, []).append(ids[new])
    return OfflineParse(
        instruction=instruction,
        tasks=final_specs,
        before=[(a, b2) for a, b2 in before],
        groups=[v for v in groups.values() if len(v) > 1],
        group_texts=[group_text.get(k, "") for k, v in groups.items() if len(v) > 1],
        unparsed=b.unparsed,
        issues=b.issues,
    )


def _after_ref(body: str) -> tuple[str, str] | None:
    """ "After placing the plunger, soap bottle, and towel, put ...": (reference, rest) split at the comma
    that is followed by a verb (references may contain commas)."""
    m = re.match(r"^(?:only\s+)?(?:after|once|when|following|upon)\s+", body, flags=re.I)
    if not m or re.match(
        r"^(?:completing|finishing|doing|all|these|those|the\s+previous|the\s+above|both|"
        r"everything|each|every|that|this|it|done|finished|complete|completed|over|through|you|we)\b",
        body[m.end() :],
        flags=re.I,
    ):
        return None
    for c in re.finditer(r",\s*", body):
        rest = body[c.end() :]
        first = re.match(r"(?:then\s+|please\s+|now\s+|you\s+should\s+|we\s+)?([A-Za-z]+)", rest)
        if c.start() > m.end() and first and first.group(1).lower() in G.VERBS:
            return body[m.end() : c.start()], rest
    return None


def _self_state(ref: str, specs: list[BaseTaskSpec]) -> None:
    """ "After refrigerating the pan, pick up a pan ... and put it on the table": the reference is a state
    change of the task itself, not an order."""
    words = [w for w, _, _ in _words(ref)]
    cls = G.VERBS.get(words[0], ("", ""))[0] if words else ""
    kind = {"clean": "clean_place", "heat": "heat_place", "cool": "cool_place", "fill": "clean_place"}.get(
        cls
    )
    for s in specs:
        if kind and s.kind in {"place", "place_two"} and s.count == 1:
            s.kind = kind  # type: ignore[assignment]


def _merge_items(items: list[Item], b: _Builder) -> list[Item]:
    """Two objects that one clause lists for one destination: a container and its content ("a bowl and a
    pencil"), or two objects of the same type ("an empty roll and a full roll of toilet paper")."""
    items = [
        it
        for it in items
        if not (
            it.obj is not None
            and it.obj.is_receptacle()
            and not it.obj.is_movable_receptacle()
            and len(items) > 1
        )
    ] or items
    if len(items) != 2 or any(it.obj is None or it.obj.pronoun or it.obj.entry is None for it in items):
        return items
    x, y = items
    assert x.obj is not None and y.obj is not None
    dests = [(p, np) for p, np in y.pps if p in G.DEST_PREPS]
    if (
        b.g is not None
        and set(b.g.resolve(x.obj.entry)) == set(b.g.resolve(y.obj.entry))
        and b.g.resolve(x.obj.entry)
    ):
        x.obj.count = 2
        return [Item(obj=x.obj, pps=dests or x.pps)]
    if x.obj.is_movable_receptacle() != y.obj.is_movable_receptacle():
        cont, content = (x, y) if x.obj.is_movable_receptacle() else (y, x)
        return [Item(obj=content.obj, pps=[("containing", cont.obj), *dests])]
    return items


def _new_tasks_from_ref(ref: str, b: _Builder, text: str) -> list[BaseTaskSpec]:
    """A reference that names no earlier task but states one ("after picking up the box and placing it on
    the armchair"): parse it as clauses of its own."""
    drafts: list[Draft] = []
    for c_text, _s, _e, _j in split_clauses(ref):
        words = [w for w, _, _ in _words(c_text)]
        if words and words[0] not in G.VERBS:
            continue
        fr = parse_frame(c_text, 0, "")
        for it in fr.items:
            if drafts and (_joins(drafts[-1], fr, it) or _incomplete(drafts[-1])):
                drafts[-1].frames.append((fr, it))
            else:
                drafts.append(Draft(frames=[(fr, it)], sentence=-1, start=0, end=0))
    out = []
    saved = list(b.unparsed)
    for d in drafts:
        spec = b.spec(d, ref)
        if spec is not None:
            out.append(spec)
    b.unparsed = saved
    return out
