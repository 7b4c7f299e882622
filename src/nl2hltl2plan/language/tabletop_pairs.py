"""A framing-independent reading of tabletop instructions (issue 28): the fallback when the grammar
refuses an instruction in the tabletop world.

The tabletop world has one kind of task: an object goes on a plate. Whatever the phrasing ("the blue
plate gets the carrot", "carrot: blue plate", "the carrot should end up on the blue plate"), each
object mention is paired with the plate mention beside it, the object first or the plate first as the
sentence starts. The order is read from a small set of forms only: no order word (or a free-order
remark) leaves the tasks unordered; "first ... then / after that / once that's done ..." orders the
groups; any other order, relation or count word refuses. The caller (`translate`) still runs check 1
(`accounting.account`) on the reading and keeps the grammar's refusal unless every word is used.

>>> [(t.object, t.receptacle) for t in read_pairs("carrot: blue plate", {"Carrot", "BluePlate"})[0]]
[(['Carrot'], ['BluePlate'])]
>>> read_pairs("carrot: blue plate, then carrot: pink plate", {"Carrot", "BluePlate", "PinkPlate"})
"""

from __future__ import annotations

import re
from collections import Counter

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.content_words import free_order_phrase
from nl2hltl2plan.language.grounding import camel_words
from nl2hltl2plan.language.htt_build import build_htt
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter
from nl2hltl2plan.worlds.world import World

# a remark that leaves the order free ("in any order", "the order doesn't matter"; the shared list,
# content_words.free_order_phrase): read, then removed
_FREE_ORDER = re.compile(rf"\b{free_order_phrase()}\b")
# where one ordered group ends and the next begins
_THEN = re.compile(r"\b(?:and\s+)?(?:then|after\s+that|afterwards|once\s+that(?:'s|\s+is)\s+done)\b")
# how the first group is marked: "first" / "to begin" at its start, or "first" closing it or its heading
# ("yellow plate first: ...")
_FIRST = re.compile(r"^\W*(?:first(?:ly)?|to\s+(?:begin|start))\b|\bfirst\b(?=\W*$|\s*:)")
# words that state some other order, relation, count or negation: the fallback never guesses at them
_REFUSED = re.compile(
    r"\b(?:not|no|never|don't|dont|n't|without|except|unless|until|before|after|while|when|once|first|"
    r"last|finally|next|second|third|then|from|off|out|away|back|near|beside|besides|by|behind|"
    r"under|between|instead|either|or|but|only|both|all|each|every|one|two|three|four|remove|swap|"
    r"keep|leave|empty|clear|stack)\b|\d"
)
_SENTENCE = re.compile(r"[.;!?]+")
# a sentence that says how things are or were ("the blue plate had the carrot") asks for nothing, unless
# it says what to do too ("make sure the carrot is on the blue plate")
_STATEMENT = re.compile(r"\b(?:is|are|was|were|had|has|have|already|currently|still)\b")
_REQUEST = re.compile(
    r"\b(?:make\s+sure|ensure|want|needs?|should|must|please|put|place|set|move|gets?|go|goes|lands?|ends?\s+up)\b"
)


def _mention_pattern(types: set[str]) -> re.Pattern[str]:
    """Each object and plate type by its words ("green apple", "blue plate"), longest first, with a
    plural allowed so that a plural is seen (and refused) rather than missed."""
    names = sorted((camel_words(t) for t in types), key=len, reverse=True)
    alternatives = "|".join(r"\s+".join(map(re.escape, n.split())) + "s?" for n in names)
    return re.compile(rf"\b(?:{alternatives})\b")


def tabletop_fallback(instruction: str, world: World, backend: str) -> LanguageResult | None:
    """The pairs reading of an instruction the grammar refused in the tabletop world, as a result for
    `translate` to finish; None (the grammar's refusal stands) in any other world, when the text is not
    one of the forms `read_pairs` knows, or when check 1 finds a content word the reading does not use."""
    if world.kind != "tabletop":
        return None
    read = read_pairs(instruction, set(world.object_types()))
    if read is None:
        return None
    tasks, before, groups = read
    instances = Counter(o.type for o in world.objects.values() if o.present)
    if account(instruction, tasks, before, instances, world.name):
        return None
    htt, task_node, leaf_task = build_htt(instruction, tasks, before, groups if len(groups) > 1 else None)
    return LanguageResult(
        backend=backend,
        instruction=instruction,
        scene=world.name,
        htt=htt,
        tasks=tasks,
        before=before,
        task_node=task_node,
        leaf_task=leaf_task,
    )


Reading = tuple[list[BaseTaskSpec], list[tuple[str, str]], list[list[str]]]


def read_pairs(text: str, types: set[str]) -> Reading | None:
    """Place tasks (object -> plate), their order and their ordered groups (task ids), or None when the
    text is not one of the forms this reading knows, an object is named twice, or an object or plate
    stays unpaired."""
    by_words = {camel_words(t): t for t in types}
    pattern = _mention_pattern(types)
    groups = _ordered_groups(_FREE_ORDER.sub(" ", text.lower()))
    if groups is None:
        return None
    tasks: list[BaseTaskSpec] = []
    group_ids: list[list[str]] = []
    for group in groups:
        ids: list[str] = []
        for sentence in _SENTENCE.split(group):
            rest = pattern.sub(" ", sentence)
            if _REFUSED.search(rest) or (_STATEMENT.search(rest) and not _REQUEST.search(rest)):
                return None
            found = [m.group(0) for m in pattern.finditer(sentence)]
            if any(" ".join(f.split()) not in by_words for f in found):
                return None  # a plural: a count this reading does not take
            pairs = _paired([by_words[" ".join(f.split())] for f in found])
            if pairs is None:
                return None
            for obj, plate in pairs:
                ids.append(task_letter(len(tasks)))
                words = f"put the {camel_words(obj)} on the {camel_words(plate)}"
                tasks.append(
                    BaseTaskSpec(id=ids[-1], text=words, kind="place", object=[obj], receptacle=[plate])
                )
        group_ids.append(ids)
    objects = [t.object[0] for t in tasks]
    if not tasks or len(set(objects)) != len(objects) or any(not g for g in group_ids):
        return None
    before = [(a, b) for i, g in enumerate(group_ids) for h in group_ids[i + 1 :] for a in g for b in h]
    return tasks, before, group_ids


def _ordered_groups(text: str) -> list[str] | None:
    """The text cut at its "then"s; "first" may open only the first group, and only when a "then"
    follows. None: no text left, or a "first" with no "then"."""
    parts = [p for p in _THEN.split(text) if p.strip(" ,.;:!?")]
    if not parts:
        return None
    opened = _FIRST.search(parts[0])
    if opened is not None and len(parts) == 1:
        return None  # "first" with no "then" after it: which tasks come first is not said
    if opened is not None:
        parts[0] = parts[0][: opened.start()] + " " + parts[0][opened.end() :]
    return parts


def _paired(types_in_order: list[str]) -> list[tuple[str, str]] | None:
    """Objects paired with their plate: runs of objects alternate with single plates, each run with the
    plate after it when the sentence starts with an object, before it when it starts with a plate."""
    runs: list[list[str]] = []
    for t in types_in_order:
        if runs and _is_plate(runs[-1][0]) == _is_plate(t):
            runs[-1].append(t)
        else:
            runs.append([t])
    if len(runs) % 2 or any(_is_plate(r[0]) and len(r) != 1 for r in runs):
        return None
    plate_first = bool(runs) and _is_plate(runs[0][0])
    out: list[tuple[str, str]] = []
    for i in range(0, len(runs), 2):
        objects, plate = (runs[i + 1], runs[i][0]) if plate_first else (runs[i], runs[i + 1][0])
        out += [(o, plate) for o in objects]
    return out


def _is_plate(type_name: str) -> bool:
    return type_name.endswith("Plate")
