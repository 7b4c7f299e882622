"""Clauses that change one object's state: "turn on the laptop", "switch off the light", "break a
vase", "slice the tomato", "open the book", "pick up the pillow" (SMART-LLM's skills).

The grammar reads tasks that move objects; a clause it leaves unread (`unparsed`) is read here when it
is nothing but a state verb and one object of the scene that can take that state. The result is a
`set_state` base task (`worlds.tasks`), whose recipe is the one action (a slice also takes a knife).

>>> from nl2hltl2plan.language.grounding import Grounder
>>> read_state_clause("Turn on the laptop", Grounder({"Laptop", "Desk"})).summary()
'set_state Laptop on'
"""

from __future__ import annotations

import re

from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.language.grounding import Grounder
from nl2hltl2plan.language.task_specs import BaseTaskSpec

_DET = r"(?:the|a|an|my|that|this)\s+"
_PATTERNS: tuple[tuple[str, str], ...] = (
    (rf"^(?:turn|switch|power)\s+(on|off)\s+(?:{_DET})?(?P<obj>.+)$", ""),
    (rf"^(?:turn|switch|power)\s+(?:{_DET})?(?P<obj>.+?)\s+(on|off)$", ""),
    (rf"^(?:break|smash|shatter)\s+(?:{_DET})?(?P<obj>.+)$", "broken"),
    (rf"^(?:slice|cut|chop)\s+(?:up\s+)?(?:{_DET})?(?P<obj>.+)$", "sliced"),
    (rf"^open\s+(?:{_DET})?(?P<obj>.+)$", "open"),
    (rf"^(?:close|shut)\s+(?:{_DET})?(?P<obj>.+)$", "closed"),
    (rf"^(?:pick\s+up|grab|take|lift)\s+(?:{_DET})?(?P<obj>.+)$", "held"),
    (rf"^(?:pick|grab|take|lift)\s+(?:{_DET})?(?P<obj>.+?)\s+up$", "held"),
)
LIGHT_WORDS = {"light", "lights", "the light", "the lights", "lamp", "light switch"}


def read_state_clause(clause: str, grounder: Grounder, pronoun: str | None = None) -> BaseTaskSpec | None:
    """A `set_state` task for a clause that is one state verb and one object (None: not such a clause).

    `pronoun`: the object type "it" stands for (the previous state clause's)."""
    text = " ".join(re.sub(r"[.!,;]+$", "", clause.strip()).split()).lower()
    text = re.sub(r"^(?:please\s+|then\s+|and\s+|also\s+)+", "", text)
    for pattern, state in _PATTERNS:
        m = re.match(pattern, text)
        if m is None:
            continue
        state = state or next(g for g in m.groups() if g in ("on", "off"))
        word = m.group("obj").strip()
        types = _ground(word, state, grounder, pronoun)
        if types:
            return BaseTaskSpec(kind="set_state", text=clause.strip(), object=types, state=state)  # type: ignore[arg-type]
    return None


def _ground(word: str, state: str, grounder: Grounder, pronoun: str | None) -> list[str]:
    if word in ("it", "them") and pronoun:
        return [pronoun]
    if state in ("on", "off") and word in LIGHT_WORDS and grounder.types and "LightSwitch" in grounder.types:
        return ["LightSwitch"]  # the room's lights
    try:
        return grounder.ground(word, "object")[:1]
    except WorldError:
        return []


_GUESS = re.compile(r"^'(?P<clause>.+)': its \w+ is not stated")


def read_unparsed_states(
    unparsed: list[str], first_id: int, grounder: Grounder
) -> tuple[list[BaseTaskSpec], list[str]]:
    """The state tasks among the parser's unread clauses (ids from `first_id` on: 0 = A) and the
    messages left unread."""
    from nl2hltl2plan.language.learned.rescue import failed_clauses
    from nl2hltl2plan.language.task_specs import task_letter

    tasks: list[BaseTaskSpec] = []
    left: list[str] = []
    done: set[str] = set()
    for msg in unparsed:
        guess = _GUESS.match(msg)
        clause = guess.group("clause") if guess else (failed_clauses([msg]) or [msg])[0]
        if clause.lower() in done:  # the same clause, reported twice (unread, then not guessed)
            continue
        parts = [p for p in re.split(r",\s*|\s+and\s+", clause) if p.strip()]
        read: list[BaseTaskSpec] = []
        for part in parts:
            it = read[-1].object[0] if read else (tasks[-1].object[0] if tasks else None)
            task = read_state_clause(part, grounder, it)
            if task is None:
                break
            read.append(task)
        if read and len(read) == len(parts):
            done.add(clause.lower())
            for task in read:
                task.id = task_letter(first_id + len(tasks))
                tasks.append(task)
        else:
            left.append(msg)
    return tasks, left


_THEN = re.compile(r"\b(then|after that|afterwards|next|once done|finally|lastly)\b")
_LAST = re.compile(r"\b(finally|lastly)\b")


def state_orderings(
    instruction: str, tasks: list[BaseTaskSpec], states: list[BaseTaskSpec]
) -> list[tuple[str, str]]:
    """`before` pairs for state tasks that a sequence word introduces ("..., then slice the tomato"):
    after the task just before them ("finally": after every earlier task), as the annotation guide's
    "Then Y" / "Finally Y"."""
    low = instruction.lower()

    def at(t: BaseTaskSpec) -> int:
        return low.find(t.text.lower()) if t.text else -1

    pairs: list[tuple[str, str]] = []
    for s in states:
        start = at(s)
        earlier = sorted((at(t), t.id) for t in tasks if t.id != s.id and 0 <= at(t) < start)
        if start < 0 or not earlier:
            continue
        gap = low[max(0, start - 25) : start]
        if _LAST.search(gap):
            pairs += [(tid, s.id) for _, tid in earlier]
        elif _THEN.search(gap):
            pairs.append((earlier[-1][1], s.id))
    return pairs
