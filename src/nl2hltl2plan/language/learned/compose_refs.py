"""Validation compositions in the style of the paper's multi-agent instructions: tasks referred to by
their object, "at any time" / "in any order" freedom, "once all previous tasks are completed".

`faithful.compose_faithful` joins clauses with fixed two- to four-clause templates, and
`compose.synthesise` with connectives between neighbours. Neither refers back to a task that is not the
one just before ("A at any time. In any order, B. After putting the pan, C": C after A), and neither
says a later task is free with a trailing "at any time". This composer does, with the ground truth the
benchmark's annotation guide gives (benchmark/ANNOTATION_GUIDE.md). Two phrase families exist, so that
a set composed with `HELDOUT_REFS` measures phrasings never looked at while the code was changed
(`DEV_REFS` is the development family).
"""

from __future__ import annotations

import random
from dataclasses import dataclass

from nl2hltl2plan.language.learned.compose import (
    NO_REFERENCE_VERBS,
    VERB_GERUND,
    VERB_PARTICIPLE,
    only_one,
    placed_words,
    words_for,
)
from nl2hltl2plan.language.learned.data import Composition
from nl2hltl2plan.language.learned.faithful import FaithfulExample, by_floor_plan, composable
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_reduction


@dataclass(frozen=True)
class RefPhrases:
    """One phrase family. `{x}` the clause, `{xg}` its gerund form, `{g}` the gerund of an earlier
    clause's verb, `{o}` its object words, `{r}` its destination words, `{p}` "is in", "are on" ..."""

    free_after: tuple[str, ...]  # the clause is free: "{x} at any time"
    free_before: tuple[str, ...]  # "in any order, {x}"
    ref: tuple[str, ...]  # after the earlier task whose object is {o}
    ref_state: tuple[str, ...]  # after the earlier task that put {o} {p} {r}
    after_all: tuple[str, ...]  # after every earlier task
    seq: tuple[str, ...]  # after the clause just before
    last: tuple[str, ...]  # "finally": after every earlier task not allowed at any time
    # (and a sentence with no phrase at all: no order of its own)
    ref_pre: tuple[str, ...] = ()  # BEFORE the earlier task whose object is {o} ("prior to {g} the {o}")
    # free only by the phrase's kind (True), not by its words ("whenever the {o} is sorted" is a reference)
    free_by_kind: bool = False


DEV_REFS = RefPhrases(
    free_after=("{x} at any time", "{x} whenever you like"),
    free_before=("in any order, {x}", "In any order, {x}", "At any time, {x}"),
    ref=("After {g} the {o}, {x}", "Once you've {gp} the {o}, {x}"),
    ref_state=("Once the {o} {p} the {r}, {x}",),
    after_all=("Once all previous tasks are completed, {x}", "Once done with the first tasks, {x}"),
    seq=("After that, {x}", "Then {x}", "Followed by {xg}", "Afterward, {x}"),
    last=("Finally, {x}", "Finish by {xg}", "Lastly, {x}"),
)

HELDOUT_REFS = RefPhrases(
    free_after=("{x} at whatever time", "{x} whenever"),
    free_before=("In no particular order, {x}", "Any time, {x}"),
    ref=("When you're done {g} the {o}, {x}", "Having {gp} the {o}, {x}"),
    ref_state=("When the {o} {p} the {r}, {x}", "As soon as the {o} {p} the {r}, {x}"),
    after_all=("When everything above is finished, {x}", "After all of that, {x}"),
    seq=("Next, {x}", "After this, {x}", "Subsequently, {x}"),
    last=("To finish, {x}", "In the end, {x}", "Last of all, {x}"),
)

# h49's held-out family (issue 28, round 4): written before the relation head was built, never trained or
# tuned on, measured once at the end (`refsnew_seen/unseen`, results/language/unseen_h49.md).
NEW_REFS = RefPhrases(
    free_after=("{x} at any point", "{x} whenever it suits you"),
    free_before=("Regardless of order, {x}", "At a moment of your choosing, {x}"),
    ref=("With the {o} done, {x}", "{x}, but only once you've {gp} the {o}",
         "Whenever the {o} is sorted, {x}"),
    ref_state=("The moment the {o} {p} the {r}, {x}", "Right after the {o} ends up {q} the {r}, {x}"),
    after_all=("Only after everything listed, {x}", "With all of the above out of the way, {x}"),
    seq=("From there, {x}", "Up next, {x}", "After that's done, {x}"),
    last=("Then, lastly, {x}", "As a final step, {x}", "Wrap up by {xg}"),
    ref_pre=("Prior to {g} the {o}, {x}", "Make sure to {x} before you {v} the {o}"),
    free_by_kind=True,
)

def _forms(clause: str) -> dict[str, str] | None:
    head, _, rest = clause.partition(" ")
    g, p = VERB_GERUND.get(head.lower()), VERB_PARTICIPLE.get(head.lower())
    if not g or not p:
        return None
    return {"x": clause, "xg": f"{g} {rest}", "vg": g, "vp": p, "v": head.lower()}


def _clause(text: str) -> str:
    t = text.strip().rstrip(".!").strip()
    return t[:1].lower() + t[1:]


def _sentence(piece: str) -> str:
    return piece[:1].upper() + piece[1:] if piece[:1].isalpha() and piece[:2] != "in" else piece


def _pick(
    i: int, forms: list[dict[str, str]], tasks: list[BaseTaskSpec], free: set[int], fam: RefPhrases,
    rng: random.Random,
) -> tuple[str, list[int], list[int], bool] | None:
    """The phrase of clause `i` (i > 0), the earlier clauses it comes after, those it comes before, and
    whether its phrase leaves it free (None: none fits)."""
    f = {"x": forms[i]["x"], "xg": forms[i]["xg"]}
    kinds = ["free_after", "free_before", "ref", "ref", "ref_state", "after_all", "seq", "bare"]
    kinds += ["ref_pre"] if fam.ref_pre else []  # (the older families draw exactly as before)
    choice = rng.choice(kinds + ["last"] * 2 if i == len(forms) - 1 else kinds)
    if choice in ("free_after", "free_before"):
        return rng.choice(getattr(fam, choice)).format(**f), [], [], True
    if choice == "bare":  # a sentence with no temporal word: no order of its own, but not free
        return f["x"], [], [], False
    if choice == "seq":
        return rng.choice(fam.seq).format(**f), [i - 1], [], False
    if choice == "after_all":
        return rng.choice(fam.after_all).format(**f), list(range(i)), [], False
    if choice == "last":
        return rng.choice(fam.last).format(**f), [j for j in range(i) if j not in free], [], False
    j = rng.randrange(i)
    t = tasks[j]
    clear = only_one(j, tasks) and forms[j]["vg"] not in [VERB_GERUND[v] for v in NO_REFERENCE_VERBS]
    o = words_for(t.text, t.object) if clear else None
    verbs = {"g": forms[j]["vg"], "gp": forms[j]["vp"], "v": forms[j]["v"]}
    if choice == "ref" and o:
        return rng.choice(fam.ref).format(**f, **verbs, o=o), [j], [], False
    if choice == "ref_pre" and o:  # "prior to putting the pan, X": X comes before that earlier task
        return rng.choice(fam.ref_pre).format(**f, **verbs, o=o), [], [j], False
    r = words_for(t.text, t.receptacle)
    if choice == "ref_state" and o and r and t.kind != "examine_in_light":
        return rng.choice(fam.ref_state).format(**f, o=o, r=r, **placed_words(t, o)), [j], [], False
    return None


def compose_refs(items: list[FaithfulExample], n: int, fam: RefPhrases, seed: int = 0) -> list[Composition]:
    """`n` instructions of 1-5 base tasks (a fifth each), each from one floor plan (deterministic), less
    those that would hold an under-specified annotation (`faithful.composable`)."""
    rng = random.Random(seed)
    by_plan = by_floor_plan(items)
    plans = sorted(by_plan)
    out: list[Composition] = []
    drawn = 0  # instructions drawn, kept or not (`faithful.composable`)
    while drawn < n:
        k = 1 + drawn % 5
        pool = by_plan[rng.choice(plans)]
        chosen = rng.sample(pool, min(k, len(pool)))
        clauses = [_clause(c.text) for c in chosen]
        forms = [_forms(c) for c in clauses]
        if len({c.example.trial for c in chosen}) < k or any(f is None for f in forms):
            continue
        fs = [f for f in forms if f is not None]
        tasks = [
            c.task.model_copy(update={"id": task_letter(i), "text": clauses[i]}) for i, c in enumerate(chosen)
        ]
        made = _compose(fs, tasks, fam, rng)
        if made is None:
            continue
        text, pairs = made
        ids = [t.id for t in tasks]
        before = list(transitive_reduction({(ids[a], ids[b]) for a, b in pairs}, ids))
        drawn += 1
        if not composable(chosen):
            continue
        out.append(Composition(text, chosen[0].example.floor_plan, tasks, before, "refs",
                               [c.example.trial for c in chosen]))
    return out


def _compose(
    forms: list[dict[str, str]], tasks: list[BaseTaskSpec], fam: RefPhrases, rng: random.Random
) -> tuple[str, list[tuple[int, int]]] | None:
    free: set[int] = set()
    first = forms[0]["x"]
    if len(forms) > 1 and rng.random() < 0.4:
        first = rng.choice(fam.free_after).format(x=forms[0]["x"])
        free.add(0)
    sentences = [_sentence(first)]
    pairs: list[tuple[int, int]] = []
    for i in range(1, len(forms)):
        for _try in range(6):
            picked = _pick(i, forms, tasks, free, fam, rng)
            if picked is not None:
                break
        else:
            return None
        phrase, after, before, free_kind = picked
        if free_kind if fam.free_by_kind else any(
            w in phrase for w in ("any time", "any order", "whenever", "Any time", "whatever time",
                                  "no particular order")
        ):
            free.add(i)
        pairs += [(j, i) for j in after] + [(i, j) for j in before]
        sentences.append(_sentence(phrase))
    return ". ".join(sentences) + ".", pairs
