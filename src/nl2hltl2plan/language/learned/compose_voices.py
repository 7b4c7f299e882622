"""The structure model's second training family: connectives, numbered lists and clause voices that
`compose.TRAIN_STYLE` lacks (issue 28; h193), from `compose_voices.txt`.

Held-out style sets lose points where the grammar reads most tasks and leaves one clause: "do the same
with the tennis racket", "take it to the round table", "the mug goes in the sink", numbered lists, "the
mug by the sink". This family teaches the CRF where such spans start and end; each span is still read by
the grammar + slot model (`structured.resolved` gives "do the same with X" and "it" their words back).
`VOICE_STYLE` chains spans with this file's openers, joiners, endings and pairs (the training family's
references, `compose.TRAIN_REFS`, point back as there); `voiced` rewrites some clauses:
- *same*: a later span that repeats the task before it for its own thing ("do the same with the cup");
  its truth is the task before with that thing;
- *it*: a later span whose thing is the one before ("put it on the table"); its truth takes that thing;
- *goes*: "put the mug in the sink" said without its verb ("the mug goes in the sink");
- *landmark*: a place the thing is by ("put the mug by the window in the sink"), not where it goes.
`listed` writes the spans as a numbered list ("1) X 2) Y", "First: X. Second: Y"), each after the one
before (a numbered list is a sequence: tests/language/data/styles, "1) ... 2) ...").
"""

from __future__ import annotations

import random
import re
from collections import defaultdict
from pathlib import Path

from nl2hltl2plan.language.learned.compose import (
    ELIDABLE,
    TRAIN_REFS,
    VERB_GERUND,
    Connectives,
    Made,
    Voices,
    placed_words,
    words_for,
)
from nl2hltl2plan.language.task_specs import BaseTaskSpec

VOICES_FILE = Path(__file__).with_name("compose_voices.txt")
ORDINALS = ("First", "Second", "Third", "Fourth", "Fifth")
# kinds whose task "do the same with X" repeats whole for another thing
REPEATABLE = frozenset({"place", "heat_place", "cool_place", "clean_place"})


def _entries() -> dict[str, list[str]]:
    """The file's templates by their head ("opener", "SEQ", "ending ANY", "pair START PRE", "list", ...)."""
    out: dict[str, list[str]] = defaultdict(list)
    for line in VOICES_FILE.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            head, _, template = line.partition(" | ")
            out[head.strip()].append(template)
    return out


ENTRIES = _entries()


def _object_words(clause: str, task: BaseTaskSpec) -> str | None:
    """The clause's words for its thing when they follow its verb and a determiner ("put the mug ...")."""
    o = words_for(clause, task.object)
    if o and re.match(rf"^\w+ (?:the|a|an) {re.escape(o)}\b", clause, re.I):
        return o
    return None


def _same(i: int, clauses: list[str], tasks: list[BaseTaskSpec], rng: random.Random) -> BaseTaskSpec | None:
    prev, mine = tasks[i - 1], tasks[i]
    o = words_for(clauses[i], mine.object)
    verb = clauses[i - 1].split(" ", 1)[0].lower()
    if not o or prev.kind not in REPEATABLE or verb not in VERB_GERUND or prev.count != 1:
        return None
    clauses[i] = rng.choice(ENTRIES["same"]).format(o=o)
    return prev.model_copy(update={"object": mine.object, "sliced": mine.sliced})


def _it(i: int, clauses: list[str], tasks: list[BaseTaskSpec]) -> BaseTaskSpec | None:
    o = _object_words(clauses[i], tasks[i])
    if not o or clauses[i].split(" ", 1)[0].lower() not in ELIDABLE or tasks[i].count != 1:
        return None
    if not _object_words(clauses[i - 1], tasks[i - 1]) or tasks[i - 1].count != 1:
        return None
    clauses[i] = re.sub(rf"^(\w+) (?:the|a|an) {re.escape(o)}\b", r"\1 it", clauses[i], count=1, flags=re.I)
    return tasks[i].model_copy(update={"object": tasks[i - 1].object, "sliced": tasks[i - 1].sliced})


def _goes(clause: str, task: BaseTaskSpec) -> str | None:
    o, r = _object_words(clause, task), words_for(clause, task.receptacle)
    if task.kind != "place" or not o or not r or clause.split(" ", 1)[0].lower() not in ELIDABLE:
        return None
    return f"the {o} goes {placed_words(task, o)['q']} the {r}"


def _landmark(clause: str, task: BaseTaskSpec, rng: random.Random) -> str | None:
    o = _object_words(clause, task)
    place = rng.choice(ENTRIES["place"])
    if not o or place in clause.lower():
        return None
    near = rng.choice(ENTRIES["landmark"]).format(l=place)
    return re.sub(rf"\b{re.escape(o)}\b", f"{o} {near}", clause, count=1)


def voiced(
    clauses: list[str], tasks: list[BaseTaskSpec], rng: random.Random
) -> tuple[list[str], list[BaseTaskSpec]]:
    """The clauses with some in a voice of this family, and the tasks they now say (module docstring)."""
    clauses, tasks = list(clauses), list(tasks)
    for i in range(len(clauses)):
        voice = rng.choice(["", "", "same", "it", "goes", "landmark"])
        if voice == "same" and i > 0 and (t := _same(i, clauses, tasks, rng)):
            tasks[i] = t
        elif voice == "it" and i > 0 and (t := _it(i, clauses, tasks)):
            tasks[i] = t
        elif voice == "goes" and (said := _goes(clauses[i], tasks[i])):
            clauses[i] = said
        elif voice == "landmark" and (said := _landmark(clauses[i], tasks[i], rng)):
            clauses[i] = said
    return clauses, tasks


def listed(clauses: list[str], rng: random.Random) -> Made:
    """The spans as a numbered list, each after the one before: (text, spans, relations, targets)."""
    form = rng.choice(ENTRIES["list"])
    between = rng.choice([" ", "; ", ". ", "\n", ", "])
    text, spans = rng.choice(["", "", "Here's the list: ", "To do:\n"]), []
    for i, clause in enumerate(clauses):
        head, _, tail = form.format(n=i + 1, w=ORDINALS[i], x="\0").partition("\0")
        text += (between if i else "") + head
        spans.append((len(text), len(text) + len(clause)))
        text += clause + tail
    text += rng.choice([".", "", "!"])
    return text, spans, ["START"] + ["SEQ"] * (len(clauses) - 1), [None] * len(clauses)


VOICE_STYLE = Connectives(
    openers=tuple(ENTRIES["opener"]),
    joiners={k: tuple(v) for k, v in ENTRIES.items() if k.isupper()},
    endings={k.split()[1]: tuple(v) for k, v in ENTRIES.items() if k.startswith("ending ")},
    pairs=tuple(
        (t, (k.split()[1], k.split()[2])) for k, v in ENTRIES.items() if k.startswith("pair ") for t in v
    ),
    refs=TRAIN_REFS,
    voices=Voices(voiced, listed),
)
