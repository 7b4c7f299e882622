"""Segmentation rescue: clauses the grammar could not read, read by the slot model and re-parsed.

Measured per stage on the text-faithful validation (`suites.alfred.learned_validation`), the grammar's
worst stage is
segmentation: most wrong instructions have too few base tasks because one clause did not fit a frame
("move two boxes of tissue from counter to back of toilet", "put the ladle on the end tale"). The
grammar lists such clauses in `unparsed`. Here the slot model reads each of them; when it finds a task
whose words the clause names, the clause is replaced in the instruction by a canonical sentence for
that task ("put two tissue boxes in the toilet") and the grammar parses the whole instruction again, so
the connectives around the clause still give its temporal relations and groups. The rewrite is kept
only when the grammar then reads more tasks.
"""

from __future__ import annotations

import re
from functools import cache

from nl2hltl2plan.language.content_words import free_order_phrase
from nl2hltl2plan.language.grammar.drafts import states_where
from nl2hltl2plan.language.grammar.sentences import normalize
from nl2hltl2plan.language.grounding import camel_words, find_mentions, lexicon, plural_name
from nl2hltl2plan.language.learned.slot_model import SlotModel, SlotPrediction
from nl2hltl2plan.language.prepositions import a_source

_IN_CLAUSE = re.compile(
    r"^(?:no destination for the .*? in|no object to act on in|nothing to hold under the lamp in|"
    r"no object of the scene named in|"
    r"cannot hold the .*? to look at it): (?P<clause>.+)$"
)
_NOTE = re.compile(r"^(?P<clause>.+?) \((?:a list of destinations|more than two objects[^)]*)\)$")
_TREAT = {"heat_place": "heat", "cool_place": "chill", "clean_place": "rinse"}


def failed_clauses(unparsed: list[str]) -> list[str]:
    """The clause texts named by the grammar's `unparsed` messages (relations' messages left out)."""
    out = []
    for msg in unparsed:
        if msg.startswith("could not tell which task"):
            continue
        m = _IN_CLAUSE.match(msg) or _NOTE.match(msg)
        out.append(m.group("clause") if m else msg)
    return out


def _np(type_name: str, sliced: bool = False) -> str:
    return f"a slice of {camel_words(type_name)}" if sliced else f"the {camel_words(type_name)}"


def _plural(type_name: str) -> str:
    """ "two knives": the plural the lexicon reads as the type (`plural_name`), else its name as it is."""
    return plural_name(camel_words(type_name)) or camel_words(type_name)


def canonical(pred: SlotPrediction) -> str | None:
    """A sentence the grammar reads as the predicted task (None: a slot has no scene type)."""
    kind = pred.top_kind
    top = {s: r[0][0] for s, r in pred.slots.items() if r}
    if "object" not in top:
        return None
    sliced = pred.sliced >= 0.5
    obj = _np(top["object"], sliced)
    if kind == "examine_in_light":
        return f"examine {obj} under the {camel_words(top['light'])}" if "light" in top else None
    if "receptacle" not in top:
        return None
    rec = f"the {camel_words(top['receptacle'])}"
    if kind == "place_two":
        return f"put two {_plural(top['object'])} in {rec}"
    if kind == "place_in_container":
        if "container" not in top:
            return None
        return f"put the {camel_words(top['container'])} with {obj} in it in {rec}"
    if kind in _TREAT:
        return f"{_TREAT[kind]} {obj} and put it in {rec}"
    return f"put {obj} in {rec}"


def _names_object(clause: str, pred: SlotPrediction, slot: str = "object") -> bool:
    """The clause names (a lexicon phrase for) the predicted object (or `slot`), or a word of five letters
    or more of one of its phrases ("the standing liht": FloorLamp's "standing lamp"): the model found, not
    invented, it. A misspelt name ("laddle") is the lexicon's word already (`language.spelling`, through
    `normalize`)."""
    top = pred.slots.get(slot) or []
    if not top:
        return False
    if top[0][0] in {t for m in find_mentions(clause) for t in m.entry.types}:
        return True
    words = _words_of(top[0][0])
    return any(len(w) >= 5 and w in words for w in re.findall(r"[a-z]+", clause.lower()))


def _names_place(clause: str, pred: SlotPrediction) -> bool:
    """The clause names the predicted receptacle, or its verb implies it ("throw the apple away"); a place
    it names only as where the thing comes from ("from the counter to the sink") is not its destination."""
    top = pred.slots.get("receptacle") or []
    if not top:
        return False
    at = [m.char_start for m in find_mentions(clause) if top[0][0] in m.entry.types]
    if at and all(a_source(clause, i) for i in at):
        return False
    implied = {place for w in re.findall(r"[a-z]+", clause.lower()) for place in _verb_places(w)}
    return top[0][0] in implied or _names_object(clause, pred, "receptacle")


def _verb_places(word: str) -> set[str]:
    from nl2hltl2plan.language.content_words import stems, verb_places

    places = verb_places()
    return {places[s] for s in stems(word) if s in places}


@cache
def _words_of(type_name: str) -> frozenset[str]:
    """The words of the lexicon phrases that name a type."""
    return frozenset(w for phrase, (e, _) in lexicon().items() if type_name in e.types for w in phrase)


# a joiner that ends a failed clause ("putting the mug in the sink, though" before "first ..."): it belongs to
# the connective after the clause, not to the task the canonical sentence restates
_TRAILING_JOINER = re.compile(r"(?:\s*,)?\s+(?:though|although|but|and|then|plus|also)\s*,?\s*$", re.I)
# "put B on X, order doesn't matter": a free-order remark closing a failed clause is not the task's
_TRAILING_FREE_ORDER = re.compile(rf"\s*[,;]?\s*\b(?:{free_order_phrase('whole')})\W*$", re.I)


def rewrite(
    instruction: str, unparsed: list[str], model: SlotModel, types: set[str] | None, min_kind: float = 0.5
) -> str | None:
    """The instruction with each readable failed clause replaced by its canonical sentence (None: none)."""
    text = normalize(instruction)
    changed = False
    for said in failed_clauses(unparsed):
        said = _TRAILING_JOINER.sub("", said)  # the joiner stays, so its order does ("A, though first B")
        clause = _TRAILING_FREE_ORDER.sub("", said)
        at = text.lower().find(clause.lower())
        if at < 0 or not clause.strip() or states_where(clause):
            continue  # "the mug is in the sink" says where it is: no request to read back
        pred = model.predict([clause], types)[0]
        if pred.kind[0][1] < min_kind or not _names_object(clause, pred):
            continue
        if pred.top_kind != "examine_in_light" and not _names_place(clause, pred):
            continue  # "gather the cell phones": where to is not said in the clause, not a guess
        sentence = canonical(pred)
        if sentence is None:
            continue
        if clause != said and text.lower()[at : at + len(said)] == said.lower():
            # a closing free-order remark ("B, order doesn't matter") restated as the grammar reads it after
            # a clause: it groups the sentence's clauses, which h213's guide "then" orders by it
            sentence, clause = sentence + ", in any order", said
        text = text[:at] + sentence + text[at + len(clause) :]
        changed = True
    return text if changed else None
