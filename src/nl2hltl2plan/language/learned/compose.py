"""Synthetic multi-task instructions for the structure model, with token-level ground truth.

Each instruction is a chain of task clauses (ALFRED annotations, re-labelled text-faithfully) joined by
connectives. Every clause is a *span* with a relation label (`RELATIONS`) that says how it is ordered
against the spans before it, read by `relations.before_pairs`. Two connective families exist:
`TRAIN_STYLE` (what the model is trained on) and `HELDOUT_STYLE` (never trained on, for validation), so
that a held-out set measures connectives the model never saw. Styles on top: contractions, polite and
casual frames, lower case, no final stop, typos, verbs in participle / gerund form ("once you've put
...", "after heating ...").
"""

from __future__ import annotations

import random
import re
from collections.abc import Callable
from dataclasses import dataclass, field

from nl2hltl2plan.language.learned.faithful import FaithfulExample, by_floor_plan, composable
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter

# Relation of a span to what came before it (text order): START the first; SEQ after the current step;
# PAR in the current step (no order with it: "X and Y"); BARE a new sentence with no temporal word ("X.
# Y.", "X. Also Y."): no order of its own (ANNOTATION_GUIDE.md), a step of its own that a later "then"
# follows and "finally" comes after; ANY the same as PAR, the order explicitly left open ("X and Y in any
# order"); FREE no order with anything (a chain of its own); PRE a new step before the current one
# ("before you X, Y": Y is PRE); LAST ("finally Y") after every earlier span not allowed in any order or
# at any time (benchmark/ANNOTATION_GUIDE.md).
# Relations that point back: REF after one earlier span named by its object ("after putting the pan, Y"),
# RPRE before one ("before you put the pan, Y", the pan's task earlier in the text), ALL after every
# earlier span ("once everything else is done, Y"); which span REF / RPRE point at is the relation
# head's (`relation_head.py`), the CRF only says that the span points back.
RELATIONS = ("START", "SEQ", "PAR", "ANY", "FREE", "PRE", "LAST", "REF", "RPRE", "ALL", "BARE")

VERB_PARTICIPLE = {
    "put": "put", "place": "placed", "pick": "picked", "take": "taken", "grab": "grabbed",
    "move": "moved", "carry": "carried", "bring": "brought", "set": "set", "heat": "heated",
    "cool": "cooled", "chill": "chilled", "wash": "washed", "rinse": "rinsed", "clean": "cleaned",
    "slice": "sliced", "cut": "cut", "turn": "turned", "examine": "examined", "look": "looked",
    "get": "got", "drop": "dropped", "throw": "thrown", "microwave": "microwaved", "warm": "warmed",
    "cook": "cooked", "hold": "held", "retrieve": "retrieved", "remove": "removed", "open": "opened",
}
VERB_GERUND = {
    "put": "putting", "place": "placing", "pick": "picking", "take": "taking", "grab": "grabbing",
    "move": "moving", "carry": "carrying", "bring": "bringing", "set": "setting", "heat": "heating",
    "cool": "cooling", "chill": "chilling", "wash": "washing", "rinse": "rinsing", "clean": "cleaning",
    "slice": "slicing", "cut": "cutting", "turn": "turning", "examine": "examining", "look": "looking",
    "get": "getting", "drop": "dropping", "throw": "throwing", "microwave": "microwaving",
    "warm": "warming", "cook": "cooking", "hold": "holding", "retrieve": "retrieving",
    "remove": "removing", "open": "opening",
}


@dataclass(frozen=True)
class RefJoiners:
    """Sentences that name an earlier span: `{x}` the new span, and of the earlier one `{v}` its verb,
    `{g}` its gerund, `{gp}` its participle, `{o}` its object words, `{r}` its destination words, `{p}`
    "is in" / "are on" ..., `{q}` "in" / "on"."""

    ref: tuple[str, ...]  # REF by the earlier task's verb and object
    ref_state: tuple[str, ...]  # REF by where the earlier task put its object
    ref_pre: tuple[str, ...]  # RPRE: the new span comes before the earlier one
    after_all: tuple[str, ...]  # ALL


# The training family (never the validation families of `compose_refs`: DEV_REFS, HELDOUT_REFS, NEW_REFS).
TRAIN_REFS = RefJoiners(
    ref=("After you {v} the {o}, {x}", "When {g} the {o} is complete, {x}", "Once the {o} task is done, {x}",
         "After the {o} has been {gp}, {x}", "{x} after you've {gp} the {o}", "Following the {o}, {x}",
         "Right after you {v} the {o}, {x}", "When you finish with the {o}, {x}",
         "Once you finish {g} the {o}, {x}", "{x} once the {o} is taken care of", "Past the {o} step, {x}",
         "After you're finished {g} the {o}, {x}", "Once you've finished with the {o}, {x}",
         "When you've {gp} the {o}, {x}", "Once you're done with the {o}, {x}",
         "{x} once you've dealt with the {o}", "{x} after the {o} is {gp}",
         "As soon as you finish {g} the {o}, {x}", "{x} as soon as the {o} is {gp}",
         "When the {o} is finished, {x}"),
    ref_state=("After the {o} {p} the {r}, {x}", "Once the {o} has been put {q} the {r}, {x}",
               "When you have the {o} {q} the {r}, {x}", "{x} when the {o} {p} the {r}",
               "As soon as you see the {o} {q} the {r}, {x}", "After you've put the {o} {q} the {r}, {x}",
               "{x} after the {o} {p} the {r}", "When you've got the {o} {q} the {r}, {x}"),
    ref_pre=("Before you {v} the {o}, {x}", "Before {g} the {o}, {x}", "{x} before {g} the {o}",
             "{x} before the {o} is {gp}", "Ahead of the {o}, {x}", "Before you get to the {o}, {x}",
             "Before starting on the {o}, {x}", "{x} before you touch the {o}", "{x} ahead of {g} the {o}"),
    after_all=("After everything else is done, {x}", "Once every other task is finished, {x}",
               "When all the earlier tasks are done, {x}", "When the rest is finished, {x}",
               "Once all of those are complete, {x}", "{x} after all the other tasks",
               "After doing all of this, {x}", "{x} once everything before it is done",
               "Once all that is done, {x}", "After the other tasks, {x}",
               "{x} when you've done everything else", "After all the others are finished, {x}",
               "When you've finished all of them, {x}", "{x} after everything else",
               "Once the rest is complete, {x}"),
)

ON_TYPES = {"CounterTop", "DiningTable", "SideTable", "CoffeeTable", "Desk", "Bed", "Sofa", "ArmChair",
            "Chair", "Dresser", "Shelf", "Ottoman", "TVStand", "Toilet", "StoveBurner", "Plate"}
# verbs whose particle "{v} the {o}" would drop ("turn on", "look at", "pick up"): no reference by them
NO_REFERENCE_VERBS = ("turn", "look", "pick")


def placed_words(t: BaseTaskSpec, o: str) -> dict[str, str]:
    """Where task `t` leaves its object, for the object words `o`: `q` "on" / "in" its receptacle, `p`
    "is on" / "are in" ..."""
    q = "on" if (t.receptacle or [""])[0] in ON_TYPES else "in"
    return {"q": q, "p": ("are " if o.endswith("s") else "is ") + q}


def words_for(text: str, types: list[str] | None) -> str | None:
    """The words of the clause that name one of `types` (its last such mention)."""
    from nl2hltl2plan.language.grounding import find_mentions

    hits = [m.surface.lower() for m in find_mentions(text) if set(m.entry.types) & set(types or [])]
    return hits[-1] if hits else None


def only_one(j: int, tasks: list[BaseTaskSpec]) -> bool:
    """Whether task `j`'s object can name no other task's object or container (a reference is clear)."""
    mine = set(tasks[j].object)
    return not any(mine & set(t.object + (t.container or [])) for k, t in enumerate(tasks) if k != j)


def reference(
    j: int, clauses: list[str], tasks: list[BaseTaskSpec], refs: RefJoiners, rng: random.Random
) -> tuple[str, str] | None:
    """A sentence for a later span that names the earlier span `j` (`{x}` left for the span) and its relation
    (REF or RPRE); None when span `j` cannot be named clearly."""
    verb = clauses[j].split(" ", 1)[0].lower()
    t = tasks[j]
    o = words_for(clauses[j], t.object) if only_one(j, tasks) else None
    if not o or verb not in VERB_GERUND or verb in NO_REFERENCE_VERBS:
        return None
    names = {"v": verb, "g": VERB_GERUND[verb], "gp": VERB_PARTICIPLE[verb], "o": o, "x": "{x}"}
    kind = rng.choice(["ref", "ref", "ref_state", "ref_pre"])
    r = words_for(clauses[j], t.receptacle)
    if kind == "ref_state" and r and t.kind != "examine_in_light":
        names |= {"r": r, **placed_words(t, o)}
    elif kind == "ref_state":
        kind = "ref"
    return rng.choice(getattr(refs, kind)).format(**names), "RPRE" if kind == "ref_pre" else "REF"


# a composition: (text, spans, relations, targets), as `_pair` and `_chain` make it
Made = tuple[str, list[tuple[int, int]], list[str], list[int | None]]


@dataclass(frozen=True)
class Voices:
    """A family's clause voices and numbered lists (`compose_voices`): `voiced` rewrites some clauses and
    returns the tasks they now say; `listed` writes the spans as a numbered list."""

    voiced: Callable[[list[str], list[BaseTaskSpec], random.Random], tuple[list[str], list[BaseTaskSpec]]]
    listed: Callable[[list[str], random.Random], Made]


@dataclass(frozen=True)
class Connectives:
    """One style family: openers of the first span, joiners of a later span by relation (`{x}` = the
    span, `{xp}` its participle form, `{xg}` its gerund form), whole-instruction endings that force one
    relation on every later span, fixed two-span templates (spans in text order, their relations), and
    openers that leave the first span free."""

    openers: tuple[str, ...]
    joiners: dict[str, tuple[str, ...]]
    endings: dict[str, tuple[str, ...]]
    pairs: tuple[tuple[str, tuple[str, str]], ...]
    free_openers: tuple[str, ...] = ()  # a first span free of every later one ("{x} at any time. ...")
    refs: RefJoiners | None = None  # sentences that point back at an earlier span
    voices: Voices | None = None  # clause voices and numbered lists too (`compose_voices`)


TRAIN_STYLE = Connectives(
    openers=("{x}", "{x}", "{x}", "First {x}", "First, {x}", "Start by {xg}", "Please {x}",
             "Could you {x}", "Can you {x}", "I'd like you to {x}", "Hey robot, {x}", "To begin, {x}",
             "Go ahead and {x}", "I need you to {x}", "Okay, {x}", "Ok so {x}", "Hi, {x}",
             "Robot, please {x}", "Step one: {x}", "Here's what I need: {x}", "I want you to {x}", "So, {x}",
             "Task 1: {x}", "Hey, could you {x}", "Can u {x}", "pls {x}"),
    joiners={
        "SEQ": (", then {x}", ". Then {x}", " and then {x}", ". After that, {x}", ", after that {x}",
                ", and after that {x}", ". Once that's done, {x}", ". Once you've done that, {x}",
                ". Next, {x}", ". Afterwards, {x}", ". When you're done with that, {x}",
                ". Once you're done with that, {x}", ". After you're done, {x}", ". Then, {x}",
                ". After this, {x}", " and afterwards {x}",
                ". Following that, {x}", ". Once finished, {x}", ", and once that is done, {x}",
                ". Subsequently, {x}", ". Only then {x}", ", followed by {xg}",
                ". When that's finished, {x}", ", then go on to {x}", ". When done, {x}",
                ". After doing that, {x}", ". Once it's done, {x}", "; after that {x}", ", and then {x}",
                ". And then {x}", ". Once that is finished, {x}", "? Then {x}", "? After that, {x}",
                "? And then {x}", ". Followed by {xg}", ". When that's complete, {x}",
                ". After finishing that, {x}", ". As soon as that's done, {x}", ". Then go ahead and {x}",
                ". Step two: {x}",
                ". After it's finished, {x}", ", and once finished, {x}", ". Later, {x}", ". Second, {x}",
                ". Now {x}", ". Right after, {x}", " and next {x}", ". Once complete, {x}",
                ". When you've done that, {x}", ". After you've done that, {x}",
                ", and after you're done {x}", ". Then u can {x}", " then {x}", ", next {x}"),
        "PAR": (" and {x}", ", and {x}", ", and also {x}", ", as well as {xg}", "; and {x}", ", also {x}",
                " as well as {xg}", ", and additionally {x}", " and then also {x}", " & {x}"),
        "BARE": (". {x}", ". {x}", ". Also {x}", ". Also, {x}", ". And {x}", ". In addition, {x}",
                 ". Plus, {x}", ". Additionally, {x}", "? Also {x}", "? And {x}", ". Oh and {x}",
                 ". Another thing: {x}", ". Besides that, {x}", ". Oh, and also {x}", ". Also, please {x}"),
        "ANY": (" and {x} in any order", ", and {x}, in any order", " and {x}, in whatever order you like",
                ", {x}, order doesn't matter"),
        "FREE": (". At any time, {x}", ". Whenever you like, {x}", ". Meanwhile, {x}",
                 ". At some point, {x}", ". Independently, {x}", ". Whenever you want, {x}",
                 ". Simultaneously, {x}", ". At the same time, {x}", ". In parallel, {x}",
                 ". {x} at any time", ". {x} whenever you like", ". In any order, {x}",
                 ". Sometime, {x}", ". Whenever you get a chance, {x}", ". {x} at some point",
                 ". {x} whenever you can", ". {x} any time you like", ". Separately, {x}"),
        "LAST": (". Finally, {x}", ", and finally {x}", ". Lastly, {x}", ". In the end, {x}",
                 ", and lastly {x}", ". Finally {x}", ". Finish by {xg}", ". Last, {x}",
                 ". At the very end, {x}", ". End by {xg}", ". The last thing: {x}", ", and at the end {x}",
                 ". Finally, please {x}"),
        "PRE": (". Before that, {x}", ", but before that {x}", ", but first {x}", ". But first, {x}",
                ". Prior to that, {x}", ". Before doing so, {x}", ". But before you do that, {x}",
                ". Before all that, {x}", ", but make sure you first {x}", ". First, though, {x}",
                ". Before any of that, {x}", ". Before you do this, {x}", ", but before doing that, {x}"),
    },
    endings={
        "SEQ": (", in that order.", " in that order.", ", one after the other.", ", in exactly that order.",
                ", in the order given.", " - in that order.", ", in that exact order please.",
                ". Do them in that order."),
        "ANY": (" in any order.", ", in any order.", ", in whatever order you like.",
                ". The order does not matter.", ", order doesn't matter.", ". Any order is fine.",
                ", any order works.", ", order is not important.", " in whichever order.",
                ", doesn't matter which first.", ". Do them in any order."),
    },
    pairs=(
        ("Once you've {0p}, {1}.", ("START", "SEQ")),
        ("After you've {0p}, {1}.", ("START", "SEQ")),
        ("After you're done {0g}, {1}.", ("START", "SEQ")),
        ("Before you {0}, {1}.", ("START", "PRE")),
        ("Before {0g}, {1}.", ("START", "PRE")),
        ("{0} before you {1}.", ("START", "SEQ")),
        ("{0} after you {1}.", ("START", "PRE")),
        ("{0} after {1g}.", ("START", "PRE")),
        ("{0} once you've {1p}.", ("START", "PRE")),
        ("After {0g}, {1}.", ("START", "SEQ")),
        ("When you have {0p}, {1}.", ("START", "SEQ")),
        ("Do not {0} until you {1}.", ("START", "PRE")),
        ("{0}, but only after you {1}.", ("START", "PRE")),
        ("As soon as you've {0p}, {1}.", ("START", "SEQ")),
        ("{0} after you're done {1g}.", ("START", "PRE")),
        ("{0} once you're done {1g}.", ("START", "PRE")),
        ("{0} after you've {1p}.", ("START", "PRE")),
        ("{0} when you have {1p}.", ("START", "PRE")),
        ("Once you're done {0g}, {1}.", ("START", "SEQ")),
        ("After you're finished {0g}, {1}.", ("START", "SEQ")),
        ("Once you have {0p}, {1}.", ("START", "SEQ")),
        ("When finished {0g}, {1}.", ("START", "SEQ")),
        ("{0}, but not before you {1}.", ("START", "PRE")),
        ("{0} but first {1}.", ("START", "PRE")),
        ("{0}, but {1} first.", ("START", "PRE")),
        ("After you {0}, {1}.", ("START", "SEQ")),
        ("When you've {0p}, go ahead and {1}.", ("START", "SEQ")),
        ("{0} and, once that's done, {1}.", ("START", "SEQ")),
        ("{0} only after {1g}.", ("START", "PRE")),
    ),
    free_openers=("{x} at any time", "{x} whenever you like", "At any time, {x}"),
    refs=TRAIN_REFS,
)

HELDOUT_STYLE = Connectives(
    openers=("{x}", "Kindly {x}", "Would you {x}", "Begin by {xg}", "Your first job: {x}",
             "Alright, {x}"),
    joiners={
        "SEQ": (". Having done that, {x}", "; then {x}", ". After you finish, {x}",
                ". With that done, {x}", ", and when finished {x}", ". After which, {x}"),
        "PAR": ("; also {x}", ". On top of that, {x}", ", plus {x}"),
        "FREE": (". Whenever convenient, {x}", ". At whatever point suits you, {x}"),
        "LAST": (". To finish, {x}", ". And to wrap up, {x}"),
        "PRE": (". Ahead of that, {x}", ", though first {x}"),
    },
    endings={
        "SEQ": (", strictly in this order.", ", in this sequence."),
        "ANY": (", the order is up to you.", " in no particular order."),
    },
    pairs=(
        ("Once you're through {0g}, {1}.", ("START", "SEQ")),
        ("Prior to {0g}, {1}.", ("START", "PRE")),
        ("{0} as soon as you've {1p}.", ("START", "PRE")),
        ("Only after you've {0p} should you {1}.", ("START", "SEQ")),
    ),
)


def _verb_form(clause: str, table: dict[str, str]) -> str | None:
    head, _, rest = clause.partition(" ")
    form = table.get(head.lower())
    return f"{form} {rest}".strip() if form else None


def _typo(word: str, rng: random.Random) -> str:
    if len(word) < 5 or not word.isalpha():
        return word
    i = rng.randrange(1, len(word) - 1)
    op = rng.randrange(3)
    if op == 0:
        return word[:i] + word[i + 1 :]  # a letter dropped
    if op == 1:
        return word[:i] + word[i + 1] + word[i] + word[i + 2 :]  # two letters swapped
    return word[:i] + word[i] + word[i:]  # a letter doubled


_CONTRACT = ((r"\bdo not\b", "don't"), (r"\byou have\b", "you've"), (r"\byou are\b", "you're"),
             (r"\bit is\b", "it's"), (r"\bthat is\b", "that's"), (r"\byou will\b", "you'll"),
             (r"\bthat has\b", "that's"), (r"\bI would\b", "I'd"))


def noisy(piece: str, rng: random.Random, p: float = 0.08) -> str:
    """A connective with, sometimes, a typo in one of its own words (never inside a `{x}` slot): people
    misspell "afterwards" as often as "microwave"."""
    if rng.random() >= p:
        return piece
    parts = re.split(r"(\{[^}]+\})", piece)
    spots = [(k, m.start(), m.end()) for k, part in enumerate(parts) if not part.startswith("{")
             for m in re.finditer(r"[A-Za-z]{5,}", part)]
    if not spots:
        return piece
    k, a, b = rng.choice(spots)
    parts[k] = parts[k][:a] + _typo(parts[k][a:b], rng) + parts[k][b:]
    return "".join(parts)


def styled_clause(text: str, rng: random.Random) -> str:
    """An annotation as a clause: no final stop, lower-case start, sometimes a typo or a contraction."""
    t = re.sub(r"^(to|you|please)\s+", "", text.strip().rstrip(".!").strip(), flags=re.I)
    t = t[:1].lower() + t[1:]
    if rng.random() < 0.15:
        words = t.split(" ")
        j = rng.randrange(len(words))
        words[j] = _typo(words[j], rng)
        t = " ".join(words)
    for pat, rep in _CONTRACT:
        if rng.random() < 0.5:
            t = re.sub(pat, rep, t)
    return t


@dataclass
class Synth:
    """One synthetic instruction: its text, the spans' character ranges and relations, the ground truth."""

    text: str
    spans: list[tuple[int, int]]
    relations: list[str]
    tasks: list[BaseTaskSpec]
    before: list[tuple[str, str]]
    scene: str
    targets: list[int | None]  # the earlier span a REF / RPRE span points at
    # the ALFRED trials composed, whose objects a validation world holds (not training data: no repr)
    trials: list[str] = field(default_factory=list, repr=False)


class _Builder:
    def __init__(self) -> None:
        self.text = ""
        self.spans: list[tuple[int, int]] = []

    def add(self, piece: str, clauses: dict[str, str]) -> None:
        """Append a piece with `{x}`-style slots filled from `clauses` (key -> clause), recording spans."""
        for part in re.split(r"(\{[^}]+\})", piece):
            if part.startswith("{") and part.endswith("}"):
                start = len(self.text)
                self.text += clauses[part[1:-1]]
                self.spans.append((start, len(self.text)))
            else:
                self.text += part


def _forms(clause: str) -> dict[str, str] | None:
    p, g = _verb_form(clause, VERB_PARTICIPLE), _verb_form(clause, VERB_GERUND)
    return {"": clause, "p": p, "g": g} if p and g else None


ELIDABLE = frozenset({"put", "place", "move", "set", "bring", "take", "carry", "drop", "throw"})


def _same_verb(a: str, b: str) -> bool:
    verb = a.split(" ", 1)[0].lower()
    return verb in ELIDABLE and verb == b.split(" ", 1)[0].lower() and " " in b


def _chain(
    style: Connectives, clauses: list[str], tasks: list[BaseTaskSpec], rng: random.Random
) -> tuple[str, list, list[str], list[int | None]] | None:
    """Spans joined one by one: an opener, then a joiner per later span (sometimes a sentence that points
    back at an earlier span, `style.refs`), sometimes a forcing ending."""
    forms = [_forms(c) or {"": c} for c in clauses]
    ending_rel = rng.choice([None, None, None, "SEQ", "ANY"]) if len(clauses) > 1 else None
    b = _Builder()
    free_first = bool(style.free_openers) and len(clauses) > 1 and not ending_rel and rng.random() < 0.2
    openers = style.free_openers if free_first else style.openers
    opener = rng.choice([o for o in openers if "{xg}" not in o or "g" in forms[0]])
    b.add(noisy(opener, rng).replace("{x", "{0"), {"0" + k: v for k, v in forms[0].items()})
    rels = ["FREE" if free_first else "START"]
    targets: list[int | None] = [None]
    for i in range(1, len(clauses)):
        made = None
        if style.refs and not ending_rel and rng.random() < 0.3:  # three in ten point back where they can
            made = _pointing(i, clauses, tasks, style.refs, rng)
        if made:
            b.add(". " + noisy(made[0], rng).replace("{x}", "{" + str(i) + "}"), {str(i): clauses[i]})
            rels.append(made[1])
            targets.append(made[2])
            continue
        last = i == len(clauses) - 1 and i > 1 and rng.random() < 0.4
        # ANY inside the instruction ("X and Y in any order. Finally Z") where the style has its joiners
        choices = ["SEQ", "SEQ", "SEQ", "PAR", "FREE", "PRE"]
        choices += [r for r in ("ANY", "BARE") if r in style.joiners]
        rel = ending_rel or ("LAST" if last else rng.choice(choices))
        if ending_rel:  # "A, B and C in any order" / "..., in that order": plain joiners only
            pool = [", {x}", " and {x}", ", and {x}", ", then {x}" if rel == "SEQ" else ", {x}"]
        else:
            pool = [j for j in style.joiners[rel] if "{xg}" not in j or "g" in forms[i]]
        clause = forms[i]
        joiner = rng.choice(pool)
        if rel == "PAR" and joiner.startswith(". "):  # a new sentence ("X. On top of that, Y") is BARE
            rel = "BARE"
        elidable = pool[0] == ", {x}" or (rel == "PAR" and joiner in (" and {x}", ", and {x}"))
        if elidable and _same_verb(clauses[i - 1], clauses[i]) and rng.random() < 0.6:
            clause = {"": clauses[i].split(" ", 1)[1]}  # "put X in Y and Z in W": the verb left out
        b.add(noisy(joiner, rng).replace("{x", "{" + str(i)), {str(i) + k: v for k, v in clause.items()})
        rels.append(rel)
        targets.append(None)
    b.add(rng.choice(style.endings[ending_rel]) if ending_rel else rng.choice([".", ".", "", "!"]), {})
    return b.text, b.spans, rels, targets


def _pointing(
    i: int, clauses: list[str], tasks: list[BaseTaskSpec], refs: RefJoiners, rng: random.Random
) -> tuple[str, str, int | None] | None:
    """A sentence for span `i` that points back (ALL, or REF / RPRE at a random earlier span)."""
    if i > 1 and rng.random() < 0.25:
        return rng.choice(refs.after_all), "ALL", None
    j = rng.randrange(i)
    made = reference(j, clauses, tasks, refs, rng)
    return (made[0][:1].upper() + made[0][1:], made[1], j) if made else None


def _pair(
    style: Connectives, clauses: list[str], rng: random.Random
) -> tuple[str, list, list[str], list[int | None]] | None:
    template, rels = rng.choice(style.pairs)
    forms = [_forms(c) for c in clauses]
    if any(f is None for f in forms):
        return None
    values = {str(i) + k: v for i, f in enumerate(forms) for k, v in (f or {}).items()}
    b = _Builder()
    b.add(template, values)
    return b.text, b.spans, list(rels), [None, None]


def _finish(text: str, rng: random.Random) -> str:
    """Whole-instruction styles: a capital or not, a polite ending, all lower case."""
    text = text[:1].upper() + text[1:]
    if rng.random() < 0.25:
        text = text.lower()
    if rng.random() < 0.1:
        text = text.rstrip(".!") + rng.choice([", thanks!", ". Thank you.", " please.", ", cheers"])
    return text


def synthesise(
    items: list[FaithfulExample], n: int, style: Connectives, seed: int = 0, said_only: bool = True
) -> list[Synth]:
    """`n` instructions of 1-5 spans (one floor plan each, different trials), deterministic for a seed,
    less those that would hold an under-specified annotation (`faithful.composable`) unless `said_only`
    is off (the structure model's training: spans and their order, which an unsaid slot does not touch)."""
    from nl2hltl2plan.language.learned.span_order import before_pairs, leading_first, then_after_last

    rng = random.Random(seed)
    by_plan = by_floor_plan(items)
    plans = sorted(by_plan)
    out: list[Synth] = []
    drawn = 0  # instructions drawn, kept or not (`faithful.composable`)
    while drawn < n:
        k = rng.choice([1, 2, 2, 3, 3, 4, 5])
        pool = by_plan[rng.choice(plans)]
        chosen = rng.sample(pool, min(k, len(pool)))
        if len({c.example.trial for c in chosen}) < len(chosen):
            continue
        clauses = [styled_clause(c.text, rng) for c in chosen]
        said = [c.task for c in chosen]
        made = None
        if style.voices:  # the second training family: its clause voices, and a numbered list in five
            clauses, said = style.voices.voiced(clauses, said, rng)
            made = style.voices.listed(clauses, rng) if k > 1 and rng.random() < 0.2 else None
        if made is None and k == 2 and rng.random() < 0.5:
            made = _pair(style, clauses, rng)
        elif made is None:
            made = _chain(style, clauses, said, rng)
        if made is None:
            continue
        text, spans, rels, targets = made
        lowered = _finish(text, rng)
        ids = [task_letter(i) for i in range(len(chosen))]
        tasks = [t.model_copy(update={"id": i, "text": ""}) for t, i in zip(said, ids, strict=True)]
        pairs = then_after_last(text, spans, rels, before_pairs(rels, targets))
        pairs = leading_first(text, spans, rels, pairs)
        before = [(ids[a], ids[b]) for a, b in pairs]
        drawn += 1
        if said_only and not composable(chosen):
            continue
        trials = [c.example.trial for c in chosen]
        out.append(Synth(lowered, spans, rels, tasks, before, chosen[0].example.floor_plan, targets, trials))
    return out
