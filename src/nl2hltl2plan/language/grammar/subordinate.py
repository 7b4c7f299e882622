"""Subordinate clauses that treat the task's own object: "put the tomato in the fridge when done heating
it in the microwave" is one task, `heat_place Tomato -> Fridge`, not a reference to another task.

`treated_before` (a step of `sentences.normalize`) writes such a clause as "after heating it in the
microwave"; the sentence keeps it (no trailing reference is stripped, `treatment_of_it`), the clause
splitter cuts it off with the joiner "after", and `drafts` gives its state to the task of the clause before
(`treatment_after`). Only a treatment (heat, chill, wash, slice) of "it" or of nothing named, at no
place but its own appliance, is read so: "after heating the apple" names another task, "after heating it
on the stove" a place no treatment here uses (both stay references). Check 1 still takes the connective
for an order word: in a sentence of several tasks and no order, "after" needs an order and the
instruction is refused.

`after_ref` splits the other kind, a leading reference to another task ("After placing the plunger, soap
bottle, and towel, put ..."), from the task said after it.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.clauses import split_clauses
from nl2hltl2plan.language.grammar.frames import APPLIANCE_OF, Frame, parse_frame
from nl2hltl2plan.language.grammar.phrases import tokens

TREATMENTS = frozenset({*APPLIANCE_OF, "slice"})


def treats_it(fr: Frame) -> bool:
    """Is the clause a treatment of "it" / "them" or of nothing named ("heating it in the microwave",
    "rinsing it off", "slicing"), at no place but that treatment's appliance?"""
    if fr.cls not in TREATMENTS or len(fr.items) != 1:
        return False
    it = fr.items[0]
    if it.obj is not None and not it.obj.pronoun:
        return False
    return all(
        p in G.DEST_PREPS and np.entry is not None and np.entry.canonical == APPLIANCE_OF.get(fr.cls)
        for p, np in it.pps
    )


def treatment_after(clause: str) -> Frame | None:
    """The frame of a clause "after heating it in the microwave" (the splitter's clause that the joiner
    "after" opens) when it is such a treatment; else None."""
    fr = parse_frame(re.sub(r"^after\s+", "", clause, flags=re.IGNORECASE))
    return fr if treats_it(fr) else None


def treatment_of_it(text: str) -> bool:
    """Do the words open with such a treatment ("heating it, place the mug ...": its first clause)?"""
    clauses = split_clauses(text)
    return bool(clauses) and treats_it(parse_frame(clauses[0][0]))


def ends_treating_it(body: str) -> bool:
    """Does a sentence of several clauses close with a treatment of "it" ("put the apple in the fridge, and
    the mug too, but wash it first")? Its closing "first" says the treatment comes before that task's own
    placing (the task's kind), not that the task comes before the others (h225's leftover)."""
    clauses = split_clauses(body)
    tail = re.split(r",\s*", clauses[-1][0])[-1] if clauses else ""  # "put the mug in it, wash it"
    return len(clauses) > 1 and treats_it(parse_frame(tail))


def _as_gerund(verb: str, rest: str) -> str | None:
    """ "rinsed" + " it off" -> "rinsing": the gerund of a treatment verb (any form) when the words from it
    on open a treatment of "it"; else None."""
    cls, base = G.VERBS.get(verb.lower()) or G.VERB_PAST.get(verb.lower()) or ("", "")
    if cls not in TREATMENTS:
        return None
    gerund = next((s for s, (_, b) in G.VERBS.items() if b == base and s.endswith("ing")), base)
    return gerund if treatment_of_it(gerund + rest) else None


# a connective that says the treatment is done before the clause it follows, inside a sentence (the
# leading "After heating it, Y" is a reference `subordinate.after_ref` reads): "after / once (you have)
# (done / finished)", "when (you are) done / finished", "when you have"
_DONE_FIRST = re.compile(
    r"(?<=\w)(?:\s*,)?\s+(?:"
    r"(?:after|once)\s+(?:you(?:'ve|\s+have|\s+had)?\s+)?(?:(?:done|finished)\s+(?:with\s+)?)?"
    r"|when\s+(?:you(?:'re|\s+are|'ve|\s+have)\s+)?(?:done|finished)\s+(?:with\s+)?"
    r"|when\s+you(?:'ve|\s+have)\s+"
    r")(?P<verb>[a-z]+)\b",
    re.IGNORECASE,
)


# "Y, but wash it first", "Y but heat it up before (that)", "Y, but only after rinsing it": the treatment
# added after the placing is done before it (h225's leftover, h236)
_BUT_FIRST = re.compile(
    r"(?<=\w)(?:\s*,)?\s+but\s+(?:(?P<verb>[a-z]+)(?P<rest>\s+(?:it|them)(?:\s+(?:up|off|down))?)\s+"
    r"(?:first|beforehand|before(?:\s+that)?)(?=\s*(?:[.;!?]|$))|only\s+after\s+(?P<ing>[a-z]+ing)(?=\s+(?:it|them)\b))",
    re.IGNORECASE,
)


def treated_before(text: str) -> str:
    """ "Y when done heating it in the microwave" / "Y once you've rinsed it" / "Y, but rinse it first" -> "Y
    after heating it in the microwave" / "Y after rinsing it", where the words are such a treatment (see
    above)."""

    def sub(m: re.Match[str]) -> str:
        rest = re.split(r"[.;!?]", text[m.end() :], maxsplit=1)[0]
        gerund = _as_gerund(m["verb"], rest)
        return f" after {gerund}" if gerund else m[0]

    def but_first(m: re.Match[str]) -> str:
        rest = m["rest"] or re.split(r"[.;!?]", text[m.end() :], maxsplit=1)[0]
        gerund = _as_gerund(m["verb"] or m["ing"], rest)
        return f" after {gerund}{m['rest'] or ''}" if gerund else m[0]

    return _BUT_FIRST.sub(but_first, _DONE_FIRST.sub(sub, text))


# "before (you) <put/throw>ing it / them": the thing of the clause before, put down next
_BEFORE_PUTTING_IT = re.compile(
    r"(?<=\w)(?:\s*,)?\s+before\s+(?:you\s+)?(?P<verb>[a-z]+)(?=\s+(?:it|them)\b)", re.I
)


def placed_after(text: str) -> str:
    """ "X before throwing it away" / "X before you put it in B" -> "X, then throw it away" / "X, then put it
    in B" (a placing or throwing verb only: "before heating it" stays an order between tasks)."""

    def sub(m: re.Match[str]) -> str:
        cls, base = G.VERBS.get(m["verb"].lower(), ("", ""))
        return f", then {base}" if cls in {"place", "trash"} else m[0]

    return _BEFORE_PUTTING_IT.sub(sub, text)


def after_ref(body: str) -> tuple[str, str] | None:
    """ "After placing the plunger, soap bottle, and towel, put ...": (reference, rest) split at the comma
    that is followed by a verb (references may contain commas)."""
    m = re.match(rf"^{G.AFTER_OPENER}", body, flags=re.I)
    if not m or re.match(
        r"^(?:completing|finishing|doing|all|these|those|the\s+previous|the\s+above|both|"
        r"everything|each|every|that|this|it|which|done|finished|complete|completed|over|through|you|we)\b",
        body[m.end() :],
        flags=re.I,
    ):
        return None
    splits: list[tuple[str, str]] = []
    for c in re.finditer(r",\s*", body):
        rest = body[c.end() :]
        first = re.match(r"(?:then\s+|please\s+|now\s+|you\s+should\s+|we\s+)?([A-Za-z]+)", rest)
        if c.start() > m.end() and first and first.group(1).lower() in G.VERBS:
            splits.append((body[m.end() : c.start()], rest))
    # "after slicing the bread, cook a slice, put it in the fridge, put the lettuce on the counter": clauses
    # about the reference's own object (a pronoun, a slice) still belong to it
    return next((sp for sp in splits if not _about_the_last_object(sp[1])), splits[0] if splits else None)


def _about_the_last_object(clause: str) -> bool:
    """Does a clause act on the object named before it ("put it in the fridge", "cook a slice")?"""
    words = [w for w, _, _ in tokens(clause.split(",")[0])][1:]
    words = [w for w in words if w not in G.PARTICLES and w not in {"a", "an", "the", "one"}]
    return bool(words) and (words[0] in {"it", "them"} or words[0] in G.SLICE_NOUNS)
