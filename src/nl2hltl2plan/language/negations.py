"""Negations become constraints: "never open the fridge", "do not put the cups in the upper rack",
"avoid the sofa", "without using the microwave", "put the keys on the sofa, not the remote".

`read_negations(instruction, grounder, look)` finds each negated clause, reads what it forbids as
action-atom patterns over the scene's types (`open(Fridge)`, `put(Cup,DishwasherUpperRack)`, every
action on the microwave for "use" / "avoid" / "touch"), and returns the instruction without those
clauses (what the task parser reads) plus one `Negation` per clause. A clause with "until" / "before"
("do not open the fridge until the mug is in the sink") is an until-guard lifted by the task the
words after it name (`resolve_until`, once the base tasks exist). "Do not X until you Y" is left to
the task parser, which reads it as the ordering Y before X (the composed instructions' phrasing), as
is "do not put X until Y". "Do not heat / chill / wash X" forbids the change of state (`heat(X)`). A
negation this module cannot read (a skill: "never examine the watch"; a thing the scene lacks; "no",
"nothing", "except") is left in the text, where the word accounting refuses it.

The LLM backends state constraints themselves (`decompose.md`, `ConstraintWords`); both readings end
in `ConstraintSpec`, which `account` judges like the base tasks and `spec_constraints` puts beside
the hierarchical spec (`logic.constraints`).

>>> from nl2hltl2plan.language.grounding import Grounder
>>> rest, found = read_negations("put the apple in the fridge but never open the microwave",
...                              Grounder({"Apple", "Fridge", "Microwave"}))
>>> rest, [(n.spec.text, n.spec.forbid) for n in found]
('put the apple in the fridge', [('never open the microwave', ['open(Microwave)'])])
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import Unread, categories, stems
from nl2hltl2plan.language.counts import all_but_said
from nl2hltl2plan.language.grounding import (
    AffordanceLookup,
    Grounder,
    Mention,
    find_mentions,
    sentence_start,
    tokens,
)
from nl2hltl2plan.language.negation_forms import names_one_thing
from nl2hltl2plan.language.order_words import until_first_at
from nl2hltl2plan.language.spec_builder import spec_name
from nl2hltl2plan.language.task_specs import BaseTaskSpec, ConstraintSpec
from nl2hltl2plan.logic.atom import Atom
from nl2hltl2plan.logic.constraints import Constraint

CUES = {
    "not",
    "never",
    "don't",
    "dont",
    "doesn't",
    "mustn't",
    "shouldn't",
    "cannot",
    "can't",
    "won't",
    "avoid",
    "without",
    # typed without the apostrophe (`grammar.everyday` reads them as the contractions)
    "doesnt",
    "mustnt",
    "shouldnt",
    "cant",
    "wont",
}
LEAD = {"do", "does", "please", "you", "must", "should", "will", "and", "but", "or", "so", "just"}
FILLER = {"do", "to", "ever", "you", "please", "be", "at", "all", "go", "the", "a", "an", "any"}
UNTIL = {"until", "till", "before", "unless"}
LISTED = {"the", "a", "an", "some", "my", "your", "its", "their", "two", "both", "all"}  # "and the mugs"
PREPS = {"in", "into", "on", "onto", "inside", "to", "under", "at", "near", "by", "beside"}
# a verb of the clause (any inflection: `content_words.stems`) -> the action it forbids ("any": every
# action on the thing)
VERBS = {
    **dict.fromkeys("put place set leave drop store stick throw toss insert load hang stack".split(), "put"),
    **dict.fromkeys("move carry take bring pick grab get lift remove hold fetch handle".split(), "pickup"),
    **dict.fromkeys("touch use using disturb approach bother".split(), "any"),  # ("using": too short a stem)
    "open": "open",
    "close": "close",
    "shut": "close",
    **dict.fromkeys("slice cut chop dice".split(), "slice"),
    **dict.fromkeys("break smash shatter".split(), "break"),
    **dict.fromkeys("turn switch power toggle".split(), "switch"),
    # changes of state (`worlds.checker.STATE_EVENTS`): "do not heat the cup"
    **dict.fromkeys("heat warm cook microwave".split(), "heat"),
    **dict.fromkeys("chill cool refrigerate freeze".split(), "cool"),
    **dict.fromkeys("wash rinse clean scrub".split(), "clean"),
}
ALL_VERBS = ("pickup", "open", "close", "toggle_on", "toggle_off", "slice", "break")
STATE_VERBS = ("heat", "cool", "clean")  # an object becomes hot / cold / clean


NO_CONSTRAINT = (
    "a negated request that no constraint of the spec carries (only actions on things of the world, and "
    "their heating, cooling or cleaning, can be forbidden)"
)


@dataclass
class Negation:
    """One negated clause of the instruction: its character span, the constraint it states and the
    words naming the task that lifts it (until-guards)."""

    start: int
    end: int
    spec: ConstraintSpec
    until_words: str = ""
    thing: str = ""  # the words naming what it forbids an action on ("the knife"), for a later "it"
    several: bool = False  # `thing` names more than one ("the fork and the knife", "the forks"): "them"


def patterns(
    verb: str, objects: Sequence[str], places: Sequence[str] = (), look: AffordanceLookup | None = None
) -> list[str]:
    """The atom patterns a forbidden verb on these types stands for (`any`: every action the
    affordances allow on the thing; `put` without a place: putting it anywhere)."""
    out: list[str] = []
    for o in objects:
        if verb == "put":
            out += [f"put({o},{p})" for p in places] or [f"put({o},*)"]
        elif verb == "pickup" and places:
            out += [f"put({o},{p})" for p in places]
        elif verb == "any":
            out += _every_action(o, look)
        elif verb in ALL_VERBS or verb in STATE_VERBS:
            out.append(f"{verb}({o})")
    return sorted(set(out))


def _every_action(type_: str, look: AffordanceLookup | None) -> list[str]:
    aff = look(type_) if look is not None else None
    if aff is None:
        return [f"{v}({type_})" for v in ALL_VERBS] + [f"put({type_},*)", f"put(*,{type_})"]
    out = [f"pickup({type_})", f"put({type_},*)"] if aff.pickupable else []
    out += [f"open({type_})", f"close({type_})"] if aff.openable else []
    out += [f"toggle_on({type_})", f"toggle_off({type_})"] if aff.toggleable else []
    out += [f"slice({type_})"] if aff.sliceable else []
    out += [f"put(*,{type_})"] if aff.receptacle else []
    return out or [f"{v}({type_})" for v in ALL_VERBS]


def read_negations(
    instruction: str, grounder: Grounder, look: AffordanceLookup | None = None
) -> tuple[str, list[Negation]]:
    """(the instruction without its negated clauses, the negations read); see the module docstring."""
    toks = tokens(instruction)
    words = [w for w, _, _ in toks]
    mentions = find_mentions(instruction)
    found: list[Negation] = []
    for i, w in enumerate(words):
        goes_on = w in ("or", "nor") and bool(found) and not instruction[found[-1].end : toks[i][1]].strip()
        if (
            (w not in CUES and not goes_on)
            or about_order(instruction, toks[i])
            or _an_ordering(instruction, toks[i])
            or any(n.start <= toks[i][1] < n.end for n in found)
        ):
            continue
        neg = _read_clause(instruction, toks, i, mentions, grounder, look)
        if neg is not None:
            found.append(neg)
    rest = instruction
    for n in sorted(found, key=lambda n: -n.start):
        rest = rest[: n.start] + " " + _named_again(rest[n.end :], n)
    rest = re.sub(r"\s+([,.;!?])", r"\1", " ".join(rest.split()))
    rest = re.sub(r"^[,;\s]+|^(?:and|but|then)\s+|[,;\s]+$", "", rest, flags=re.I).strip()
    return rest, found


def _named_again(after: str, neg: Negation) -> str:
    """The text after a negated clause, its "it" or "them" given back the thing the clause named when no
    thing comes between them in the sentence: "don't put the knife in the sink, put it in the drawer"
    leaves "put the knife in the drawer" (not "put it in the drawer", which names nothing); so does
    "Don't put the knife in the sink. Put it in the drawer." "them" stands for several things ("don't put
    the fork and the knife in the sink, put them in the drawer"), "it" for one: a pronoun of the other
    number names nothing for certain, and is refused naming it."""
    thing = neg.thing
    lead = len(after) - len(after.lstrip(" ,.;!?"))  # "Don't put the knife in the sink. Put it ..."
    head = after[: lead + len(re.split(r"[.;!?]", after[lead:], maxsplit=1)[0])]
    pronoun = re.search(r"\b(?:it|them)\b", head, re.I)
    if not thing or pronoun is None or any(m.char_start < pronoun.start() for m in find_mentions(head)):
        return after
    if (pronoun[0].lower() == "them") != neg.several:
        said = f"{pronoun[0]!r} after {neg.spec.text!r}"
        what = f"is one of {thing!r}: name which" if neg.several else f"names more than {thing!r}: name them"
        raise HTTError(f"{said} {what}")
    return after[: pronoun.start()] + thing + after[pronoun.end() :]


def _an_ordering(instruction: str, tok: tuple[str, int, int]) -> bool:
    """ "Do not X until you Y" (and "before you", "unless you"): the composed instructions' way to say
    Y before X, both to be done, which the task parser reads as an ordering."""
    rest = re.split(r"[.;!?]", instruction[tok[2] :], maxsplit=1)[0].lower()
    if re.search(r"\b(until|till|before|unless) you\b", rest) is not None:
        return True
    return until_first_at(instruction, tok[1])  # "Until the plate is on the shelf, don't put X there"


def about_order(instruction: str, tok: tuple[str, int, int]) -> bool:
    """ "the order is not specified", "in no particular order": a negation about the order itself."""
    start = sentence_start(instruction, tok[1])
    end = tok[2] + len(re.split(r"[.;!?]", instruction[tok[2] :], maxsplit=1)[0])
    return re.search(r"\b(order|sequence)\b", instruction[start:end].lower()) is not None


def _read_clause(
    text: str,
    toks: list[tuple[str, int, int]],
    i: int,
    mentions: list[Mention],
    grounder: Grounder,
    look: AffordanceLookup | None,
) -> Negation | None:
    words = [w for w, _, _ in toks]
    end_tok = _clause_end(text, toks, i)
    j = i + 1
    while j < end_tok and words[j] in FILLER - {"the", "a", "an", "any"}:
        j += 1
    verb = _verb_of(words[j]) if j < end_tok else None
    if verb is None and words[i] in ("avoid", "without"):
        verb = "any"  # "avoid the stove", "without the microwave"
    cut = next((k for k in range(j, end_tok) if words[k] in UNTIL), end_tok)
    if verb == "put" and cut < end_tok:
        return None  # "do not put X until you put Y": the parser's ordering Y before X
    inside = [m for m in mentions if i < m.start < cut and not m.entry.generic]
    if verb == "switch":
        after = words[j + 1 : cut]
        verb = "toggle_on" if "on" in after else "toggle_off" if "off" in after else None
    places: list[str] = []
    if verb is None and inside and inside[0].start <= j + 1:  # "..., not the remote": the clause before's
        verb, places = "put", _previous_destination(text, toks, i, mentions, grounder)
        if not places:
            return None
        contrast = _contrasted_place(text, toks, i, inside, mentions, grounder, look)
        if contrast is not None:  # "put the tomato in the fridge, not the microwave"
            return _negation(text, toks, i, end_tok, end_tok, "put", *contrast)
        affs = [look(t) for m in inside for t in grounder.resolve(m.entry)] if look is not None else []
        if any(a is not None and not a.pickupable for a in affs):
            return None  # "not the microwave or the apple": places and things mixed, neither is read
    if verb in _DONE_TO_IT and not inside and j + 1 < cut and words[j + 1] in ("it", "them"):
        inside = []  # "put the apple in the fridge, don't heat it": the pronoun alone names the thing
    elif verb is None or not inside:
        return None
    if PRONOUNS & set(words[j + 1 : inside[0].start if inside else cut]):  # "don't put it in the sink"
        antecedent = _previous_object(text, toks, i, mentions)
        if antecedent is None:
            return None
        inside = [antecedent, *inside]
    things, where = _objects_and_places(inside, words, grounder)
    if things is None:
        return None
    if verb == "put" and not where and _there_or_in_it(words[j + 1 : cut]):  # "don't put the fork in it"
        where = _previous_destination(text, toks, i, mentions, grounder)
        if not where:
            return None
    if verb in ("put", "pickup") and where:
        places = where
    elif where:  # "never open the fridge on the left": the extra place is not read
        return None
    neg = _negation(text, toks, i, end_tok, cut, verb, things, places, look)
    named = [m for m in inside if m.start > i and not PREPS & set(words[max(0, m.start - 3) : m.start])]
    if neg is not None and named and _listed(words, named):  # things of its own (not an "it")
        spans = [text[toks[_determined(words, m.start)][1] : m.char_end] for m in named]
        neg.thing, neg.several = " and ".join(spans), len(named) > 1 or named[0].plural
    return neg


def _there_or_in_it(words: list[str]) -> bool:
    """Does a negated placing name its place by "there" or by "in/on it" (the place said before: "put the egg
    in the fridge, don't put the apple in it" forbids the fridge only, never every placing of the apple)?"""
    return "there" in words or any(a in PREPS and b == "it" for a, b in itertools.pairwise(words))


def _determined(words: list[str], k: int) -> int:
    """Where the name at word `k` starts with its determiner ("the knife")."""
    return k - 1 if k and words[k - 1] in LISTED else k


def _listed(words: list[str], named: list[Mention]) -> bool:
    """Are the names one thing, or a list of things with nothing between them but "and", "or", "nor", a
    comma and determiners ("the fork and the knife"), so that a later "them" names exactly them?"""
    joins = {"and", "or", "nor", ","} | LISTED
    return all(set(words[a.end : _determined(words, b.start)]) <= joins for a, b in itertools.pairwise(named))


# "Until the bat is on the bed, don't touch the keys": the guard said before its negation, in its sentence
_FRONTED_UNTIL = re.compile(
    r"(?:^|[.;!?]\s+)(?:until|till)\s+(?P<ref>[^,.;!?]+?)\s*,\s*(?:please\s+)?$", re.I
)


def _negation(
    text: str,
    toks: list[tuple[str, int, int]],
    i: int,
    end_tok: int,
    cut: int,
    verb: str,
    things: Sequence[str],
    places: Sequence[str],
    look: AffordanceLookup | None = None,
) -> Negation | None:
    forbid = patterns(verb, things, places, look)
    start = _clause_start(text, toks, i)
    end = toks[end_tok - 1][2] if end_tok > i else toks[i][2]
    clause = text[toks[_first_word(toks, i)][1] : end]
    until_words = text[toks[cut][2] : end].strip() if cut < end_tok else ""
    if not until_words and (fronted := _FRONTED_UNTIL.search(text[: toks[_first_word(toks, i)][1]])):
        until_words = fronted["ref"]  # "Until that's done, don't touch the keys": a guard, not for ever
    return Negation(start, end, ConstraintSpec(text=clause, forbid=forbid), until_words) if forbid else None


def _contrasted_place(
    text: str,
    toks: list[tuple[str, int, int]],
    i: int,
    inside: list[Mention],
    mentions: list[Mention],
    grounder: Grounder,
    look: AffordanceLookup | None,
) -> tuple[list[str], list[str], AffordanceLookup | None] | None:
    """ "..., not the microwave (or the sink)" after a placing: the thing must not go to those places, when
    every type the words name is a place nothing carries (a microwave, never a bowl: "not the bowl" may be a
    thing); a list of them ("not the microwave or the sink") was read as things put in the place before."""
    words = [w for w, _, _ in toks]
    if look is None or not inside or not _listed(words, inside):
        return None
    types = [t for m in inside for t in grounder.resolve(m.entry)]
    affs = [look(t) for t in types]
    if not types or any(a is None or a.pickupable or not a.receptacle for a in affs):
        return None
    thing = _previous_object(text, toks, i, mentions)
    things = grounder.resolve(thing.entry) if thing is not None else []
    return (things, types, look) if things else None


def _verb_of(word: str) -> str | None:
    """The forbidden action a verb names, inflected or not ("breaking", "opens", "touched")."""
    return next((VERBS[f] for f in sorted(stems(word), key=len, reverse=True) if f in VERBS), None)


def _objects_and_places(
    inside: list[Mention], words: list[str], grounder: Grounder
) -> tuple[list[str] | None, list[str]]:
    """Scene types of the things the clause names, split into objects and places (after a preposition);
    a place after "from" / "off" only says where the thing is ("don't move the vase from the table")."""
    things: list[str] = []
    places: list[str] = []
    last: Mention | None = None  # the mention before, where it was a place
    for m in inside:
        types = grounder.resolve(m.entry)
        if not types:
            return None, []  # an object the scene lacks: the negation stays unread (refused)
        before = words[max(0, m.start - 3) : m.start]
        if things and {"from", "off"} & set(before):
            continue
        # "never put the egg in the fridge or the microwave": a place listed after a place is one too
        listed = last is not None and set(words[last.end : _determined(words, m.start)]) <= {"or", "nor", ","}
        listed = listed and not PREPS & set(words[m.end : m.end + 2])  # "or the apple in the sink": a thing
        is_place = (any(w in PREPS for w in before) or listed) and things
        (places if is_place else things).extend(types)
        last = m if is_place else None
    return (things or None), places


PRONOUNS = frozenset({"it", "them", "this", "that", "these", "those"})  # that stand for a thing named before
# what may be forbidden of "it" alone, the thing said before: done to a thing, never to a place ("don't open
# it" after "in the fridge" may be the fridge) nor its move (the task moves it)
_DONE_TO_IT = frozenset({"heat", "cool", "clean", "slice", "break"})


def _previous_object(
    text: str, toks: list[tuple[str, int, int]], i: int, mentions: list[Mention]
) -> Mention | None:
    """The last thing (not a place after a preposition) named in the cue's sentence before it: what "it"
    stands for in "wash the mug but don't put it in the sink"."""
    start = sentence_start(text, toks[i][1])
    words = [w for w, _, _ in toks]
    before = [m for m in mentions if start <= m.char_start < toks[i][1] and not m.entry.generic]
    things = [m for m in before if not any(w in PREPS for w in words[max(0, m.start - 3) : m.start])]
    return things[-1] if things else None


def _previous_destination(
    text: str, toks: list[tuple[str, int, int]], i: int, mentions: list[Mention], grounder: Grounder
) -> list[str]:
    """The destination of the clause before the cue in its sentence ("put the keys on the sofa, not ...")."""
    start = sentence_start(text, toks[i][1])
    words = [w for w, _, _ in toks]
    before = [m for m in mentions if start <= m.char_start < toks[i][1]]
    for m in reversed(before):
        if any(w in PREPS for w in words[max(0, m.start - 3) : m.start]):
            return grounder.resolve(m.entry)
    return []


def _clause_end(text: str, toks: list[tuple[str, int, int]], i: int) -> int:
    """The token index that ends the negated clause: a full stop, or a comma, "and", "but" or "then"
    not followed by a determiner (a list of things goes on)."""
    for k in range(i + 1, len(toks)):
        gap = text[toks[k - 1][2] : toks[k][1]]
        if re.search(r"[.;!?]", gap) or ("," in gap and toks[k][0] not in LISTED):
            return k  # a comma goes on with a list of things: "the butter knife, the fork and the spoon"
        if toks[k][0] in ("and", "but", "then") and k + 1 < len(toks) and toks[k + 1][0] not in LISTED:
            return k  # "never open the fridge and heat the mug" (not "the cups and the mugs")
        if toks[k][0] in ("or", "nor") and k + 1 < len(toks) and _verb_of(toks[k + 1][0]):
            return k  # "without opening the fridge or using the microwave": a negation of its own
    return len(toks)


def _first_word(toks: list[tuple[str, int, int]], i: int) -> int:
    """The clause's first word: "do" / "please" before "not" belong to it."""
    k = i
    while k > 0 and toks[k - 1][0] in LEAD - {"and", "but", "or", "so"}:
        k -= 1
    return k


def _clause_start(text: str, toks: list[tuple[str, int, int]], i: int) -> int:
    """Where the removed text starts: the clause's first word, with the joiner before it (", but")."""
    k = _first_word(toks, i)
    while (
        k > 0
        and toks[k - 1][0] in ("and", "but", "or", "so")
        and not re.search(r"[.;!?]", text[toks[k - 1][2] : toks[k][1]])
    ):
        k -= 1
    start = toks[k][1]
    prefix = text[:start].rstrip()
    return len(prefix) - 1 if prefix.endswith(",") else start


def resolve_until(
    negations: list[Negation], tasks: Sequence[BaseTaskSpec], grounder: Grounder
) -> list[Negation]:
    """Each until-guard gets the base task its words name (the first task on the thing they name);
    a guard whose words name no task is dropped (its negation then stays unread)."""
    out = []
    for n in negations:
        if not n.until_words:
            out.append(n)
            continue
        named = [
            t for m in find_mentions(n.until_words) if not m.entry.generic for t in grounder.resolve(m.entry)
        ]
        task = next((t for t in tasks if named and set(t.object) & {named[0]}), None)
        if task is not None:
            n.spec = n.spec.model_copy(update={"until": task.id})
            out.append(n)
    return out


def spec_constraints(constraints: Sequence[ConstraintSpec], task_node: dict[str, str]) -> list[Constraint]:
    """The language stage's constraints beside the spec: an until-guard waits for its task's node."""
    return [
        Constraint(c.text, tuple(c.forbid), spec_name(task_node[c.until]) if c.until else None)
        for c in constraints
    ]


# a verb inside a negated clause -> what its constraint must forbid (an action, or a change of state)
CONSTRAINT_VERBS = {
    "verb_break": "break",
    "verb_sliced": "slice",
    "verb_heat_place": "heat",
    "verb_cool_place": "cool",
    "verb_clean_place": "clean",
}


def unforbidden_verb(
    w: str, cats: frozenset[str], words: list[str], i: int, c: ConstraintSpec
) -> Unread | None:
    """A verb inside a negated clause that its constraint does not forbid (check 1 of `accounting`):
    "never turn on the microwave" needs toggle_on among the forbidden actions, "do not heat the cup" heat."""
    verbs = {a.verb for p in c.forbid if (a := Atom.read_pattern(p)) is not None}
    after = words[i + 1 : i + 5]
    if "verb_switch" in cats and ("on" in after or "off" in after):
        need = "toggle_on" if "on" in after else "toggle_off"
        if need in verbs:
            return None
        return Unread(w, "action", f"the constraint {c.text!r} does not forbid {need}")
    for cat, verb in CONSTRAINT_VERBS.items():
        if cat in cats and verb not in verbs:
            return Unread(w, "action", f"the constraint {c.text!r} does not forbid {verb}")
    if "verb_examine_in_light" in cats or "verb_unsupported" in cats:
        return Unread(w, "action", "a constraint forbids actions and changes of state, not this skill")
    return None


def nothing_to_do(instruction: str, constraints: list[ConstraintSpec]) -> str:
    """The refusal of an instruction that only says what not to do (there is no task to plan)."""
    said = "; ".join(c.describe() for c in constraints)
    return (
        f"nothing to do: {instruction!r} only says what not to do ({said}); state a task too, "
        "e.g. 'put the mug in the sink, but never open the fridge'"
    )


def after_negation(instruction: str, tok: tuple[str, int, int]) -> bool:
    """Does a negation come before the word in its sentence ("do not X unless Y": the negation's guard)?
    Check 1 (`accounting`) asks it of a condition word."""
    start = sentence_start(instruction, tok[1])
    return any("negation" in categories(w) for w, _, _ in tokens(instruction[start : tok[1]]))


def until_guard(instruction: str, tok: tuple[str, int, int], ordered: bool) -> bool:
    """ "Do not X until Y" is the ordering Y before X, which a reading with an order (`ordered`) has as a
    `before` pair: check 1 (`accounting`) does not name its negation."""
    rest = re.split(r"[.;!?]", instruction[tok[2] :], maxsplit=1)[0].lower()
    said = re.search(r"\b(until|unless|before)\b", rest) is not None or until_first_at(instruction, tok[1])
    return ordered and said


# a thing said to stay as it is ("P.S. the mug stays where it is", "the mug can stay put", "the mug stays.",
# "leave the mug alone"): it is not to be moved; read before, "stays put" put the mug where the last thing
# went, at exit 0 (h205)
_NP = r"(?:the|a|an|both|all\s+the)\s+[a-z]+(?:\s+[a-z]+){0,2}?"
_UNMOVED = (
    r"(?:put|there|(?:right\s+)?where\s+(?:it\s+is|they\s+are)|as\s+(?:it\s+is|they\s+are|is)|alone|be)"
)
# "the keys stay on the coffee table", "the pot remains on the stove": where it is now, kept (h236); a placing
# said so ("put the keys on the table") is a task, and "leave it on the table" stays one
_WHERE_IT_STAYS = r"(?:on|in|inside|at)\s+(?:the|its|their)\s+[a-z]+(?:\s+[a-z]+)?"
_KEPT_AS_IT_IS = re.compile(
    rf"(?:^|(?<=[.;!?])\s+|(?<=,)\s+|(?<=\band\s)|(?<=\bbut\s))"
    rf"(?:(?:(?:make|be)\s+sure\s+(?:that\s+)?)?(?P<x>{_NP})\s+(?:(?:can|should|must|will)\s+)?(?:stays?|remains?)"
    rf"(?:\s+{_UNMOVED}|\s+{_WHERE_IT_STAYS})?|(?:just\s+)?(?:leave|leaving|keep)\s+(?P<y>{_NP})\s+{_UNMOVED})"
    rf"(?=\s*(?:[.;!?,]|$))",
    re.I,
)


def unmoved_said(text: str) -> str:
    """`text` with a thing said to stay where it is as "don't move X", which `read_negations` reads as a
    ban on picking it up, where the lexicon names the thing (the household reader's `as_read`).

    >>> unmoved_said("Put the egg in the fridge. P.S. the mug stays where it is.")
    "Put the egg in the fridge. P.S. don't move the mug."
    """

    def unmoved(m: re.Match[str]) -> str:
        thing = m["x"] or m["y"]
        if not names_one_thing(thing):
            return m[0]
        lead = m[0][: len(m[0]) - len(m[0].lstrip())]
        # "... and leave X alone", ", leaving X be": untouched, more than unmoved (users_h195held's truth;
        # h311: it was left unread); a sentence of its own ("Leave the mug alone.") stays h205's "don't move"
        inside = not lead or text[: m.start()].rstrip().endswith(",")
        ban = "touch" if m[0].endswith(("alone", " be")) and m.start() and inside else "move"
        return f"{lead}don't {ban} {thing[0].lower()}{thing[1:]}"

    return _KEPT_AS_IT_IS.sub(unmoved, text)


# "Rather than the mug, the apple." on its own, with no verb: a swap of which request is unclear (the grammar
# read both as more items); "all but the mug" is `counts.all_but_said`'s. h208
_BARE_SWAP = re.compile(
    r"(?:^|(?<=[.;!?]))\s*(?:rather\s+than|instead\s+of)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?\s*,\s*"
    r"(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?\s*(?=[.;!?]|$)",
    re.I,
)

# "... and the apple in the sink. Actually leave the apple.": a take-back that the grammar read as one more
# placing of the apple (exit 0); "leave the apple alone / where it is" is `unmoved_said`'s
_BARE_LEAVE = re.compile(
    r"(?:^|(?<=[.;!?]))\s*(?:(?:actually|no|wait|oh)\s*,?\s+)*leave\s+(?:the|a|an)\s+[a-z]+"
    r"(?:\s+and\s+(?:the|a|an)\s+[a-z]+)?\s*(?=[.;!?]|$)",
    re.I,
)


def exclusions_unread(text: str) -> list[Unread]:
    """An exclusion from a whole ("all but the mug"), a swap said with no verb ("Rather than the mug, the
    apple.") and a bare "leave the apple.", each named unread for the household reader's `unused`.

    >>> [u.words for u in exclusions_unread("Put all but the mug away. Rather than the egg, the apple.")]
    ['all but', 'Rather than the egg, the apple']
    >>> [u.words for u in exclusions_unread("Put the apple in the sink. Actually leave the apple.")]
    ['Actually leave the apple']
    """
    bare = [*_BARE_SWAP.finditer(text), *_BARE_LEAVE.finditer(text)]
    found = [*all_but_said(text), *(m[0].strip() for m in bare)]
    why = "an exclusion, a swap or a bare 'leave' that no rule reads: say each thing to move"
    return [Unread(words, "negation", why) for words in found]
