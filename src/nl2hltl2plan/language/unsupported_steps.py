"""Steps of an instruction that no base task does, judged in word accounting (`accounting.account`):
a slice or treatment said after the placing ("put the tomato in the fridge, then slice it"), closing
after a placing ("... and close it"), returning a thing to where it was ("bring it back"), repeating a
task ("three times"), leaving things out ("leave one out"), telling two things of one type apart ("the
other apple"), switching a machine on ("start it"), an object's task said to come first or last. What no
spec says at all (questions, vague amounts and places, times, waiting on a state) is `vague_words`.

>>> from nl2hltl2plan.language.parse_usage import ParseUsage
>>> from nl2hltl2plan.language.task_specs import BaseTaskSpec
>>> [u.words for u in returns_and_repeats("bring it back", [], ParseUsage([], [], [], []))]
['back']
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Mapping, Sequence

import networkx as nx

from nl2hltl2plan.domain.task_kinds import APPLIANCE
from nl2hltl2plan.language.content_words import DETERMINERS, Unread, categories
from nl2hltl2plan.language.grammar.frames import UNDER
from nl2hltl2plan.language.grammar.put_back import BELONGS_THEN_BACK, WHERE_IT_WAS
from nl2hltl2plan.language.grammar.repeats import REPEAT_FRAGMENT
from nl2hltl2plan.language.grounding import Mention, lookup, sentence_start, tokens
from nl2hltl2plan.language.landmarks import NEAR_WORDS
from nl2hltl2plan.language.mention_use import task_spans
from nl2hltl2plan.language.negations import NO_CONSTRAINT, PRONOUNS
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.picked_states import picked_states
from nl2hltl2plan.language.prepositions import a_source
from nl2hltl2plan.language.statements import REFERENCE
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.vague_words import counted

# "bring it back", "then back again", "return it", "put it back where it was", "back in its place": to
# where it was (`put_back.WHERE_IT_WAS`), which no base task names ("at the back" is a place); "three times"
_ENDS = r"(?=\s*(?:$|[.,;!?)]|(?:and{}|then|again|afterwards|after|later|here|please|now)\b))"
_RETURN = re.compile(r"(?<!\bthe )\bback(?: again)?\b" + WHERE_IT_WAS + _ENDS.format(""))
# "return the mug", "return both": the thing is named, its place is not ("return the mug and the cup to the
# shelf" names it after the list)
_RETURN_VERB = re.compile(
    r"\breturn\s+(?:it|them|both|(?:the|your|that|this|these|those)(?:\s+[a-z]+){1,2})\b"
    + WHERE_IT_WAS
    + _ENDS.format(r"(?!\s+(?:the|a|an|your|my)\b)")
)
_LEFT_OUT = re.compile(r"\bleave (?:\w+ ){0,3}out\b(?! of)")  # "leave one out": an exception, as "except one"
# (any count in digits or words, `vague_words.counted`: "eleven times", "a couple of times", h311)
_TIMES = re.compile(
    rf"\b(?:{counted()}|several|many|multiple|a few|a couple(?: of)?|a number of|a dozen|dozens of|numerous)"
    r"(?:\s+more)? times\b"
)


# "then take the pen out", "get the spoon back out of the mug": a removal from a container, which no base
# task does; "take the butter knife out of the sink, put it in ..." says where it comes from
_TAKEN_OUT = re.compile(
    r"\b(?:take|takes|took|taking|get|gets|getting|pull|pulls|pulling|lift|lifts|fish|grab)"
    r"(?P<thing>(?:\s+[a-z']+){0,4}?)\s+(?:back\s+)?out\b(?!side)"
    r"(?:\s+of(?:\s+[a-z']+){1,3}?(?=\s*(?:[,.;!?]|$|and\b|then\b)))?"
)
_PLACED_NEXT = re.compile(  # "... out of the drawer and place them on the table"
    r"[^.;!?]*?(?:\band|\bthen|,)\s+(?:\w+\s+){0,2}?(?:put|place|set|drop|move|carry|bring|toss|throw)\s+(?:it|them)\b"
)
_REMOVAL = "a removal from a container, which no base task does: say where it goes instead (put it in/on ...)"


def taken_out(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """ "Take the pen out (of the mug)": where a task acts on the pen and the pen is first named here, the
    words say where it comes from; a thing named before ("put the pen in the box, then take the pen out",
    "take it out") or that no task acts on is taken out and left so, which no task of the world does."""
    out, lowered = [], instruction.lower()
    used = {o for t in parse.tasks for o in (*t.object, *(t.container or ()))}
    for m in _TAKEN_OUT.finditer(lowered):
        start, end = m.span("thing") if m["thing"] else (m.end(), m.end() + 12)  # "take out the apple"
        named = [x for x in mentions if start <= x.char_start < end]
        types = {t for x in named[:1] for t in x.entry.types}
        said_before = any(set(x.entry.types) & types for x in mentions if x.char_start < m.start())
        placed_next = _PLACED_NEXT.match(lowered, m.end())
        if not (types & used and (not said_before or placed_next)) or (
            not placed_next and _put_in_source(m, types, mentions, parse)
        ):
            out.append(Unread(m.group(0).strip(), "action", _REMOVAL))
    return out


def _put_in_source(m: re.Match[str], types: set[str], mentions: list[Mention], parse: ParseUsage) -> bool:
    """ "..., and take the mug out of the microwave" with no placing after: a task of only these words that
    puts the mug into the microwave it is taken out of read the removal as a placing (h242); "take the soap
    out of the cabinet, wash it and return it" is a task of more words."""
    source = {t for x in mentions if m.end("thing") <= x.char_start < m.end() for t in x.entry.types}
    return any(
        set(t.object) & types and set(t.receptacle or ()) & source and t.text.lower().strip() in m.group(0)
        for t in parse.tasks
        if t.text
    )


def returns_and_repeats(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """ "Back" with no place after it names one only where the sentence said where the thing came from
    and a task puts it there ("wash the cloth from the cabinet, put it back"); "move the plate from the
    counter to the table and back" has no task that returns the plate to the counter."""
    lowered = instruction.lower()
    out = [
        Unread(m.group(0), "place", "no base task returns a thing to where it was: name the place")
        for m in [*_RETURN.finditer(lowered), *_RETURN_VERB.finditer(lowered)]
        if not _returned(lowered, sentence_start(instruction, m.start()), m.start(), mentions, parse)
    ]
    out += [Unread(m.group(0), "negation", NO_CONSTRAINT) for m in _LEFT_OUT.finditer(lowered)]
    out += taken_out(instruction, mentions, parse)
    return out + [
        Unread(m.group(0), "count", "no base task is done more than once: say each time as its own task")
        for m in _TIMES.finditer(lowered)
    ]


def one_of_several(
    instruction: str, mentions: list[Mention], parse: ParseUsage, instances: Mapping[str, int] | None
) -> list[Unread]:
    """ "Put the second egg in the fridge", "the left apple", "the top pillow": words that pick one of
    several things of a type the scene holds, which the spec (type-level atoms: any egg does) cannot
    keep to, and a state that does so ("the empty mug": `picked_states`). Judged only where the scene is
    known; a place picked by position ("the top drawer") is read as the place's type, and the result
    says so (`referents.picked_places`)."""
    if instances is None:
        return []
    objects = {t for task in parse.tasks for t in task.object}
    out = []
    for m in PICKS_ONE.finditer(instruction.lower()):
        named = next((x for x in mentions if x.char_start == m.end()), None)
        if named is not None and any(instances.get(t, 0) > 1 for t in set(named.entry.types) & objects):
            out.append(Unread(f"{m.group(1)} {named.surface}", "object", _PICKED))
    return out + picked_states(instruction, mentions, parse, instances)  # "the empty mug"


def under_a_place(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """ "Put the apple under the counter": a task's place named only after "under" (or "below",
    "beneath"), where no base task puts a thing; "a mug under the coffee machine" is ALFRED's placing in
    the machine, under its spout."""
    lowered = instruction.lower()
    out = []
    for place in {r for t in parse.tasks for r in t.receptacle or ()} - {"CoffeeMachine"}:
        named = [m for m in mentions if place in m.entry.types]
        below = [m for m in named if _UNDER_BEFORE.search(lowered[max(0, m.char_start - 30) : m.char_start])]
        if named and len(below) == len(named):
            out.append(Unread(below[0].surface, "place", _UNDER))
    # "on the sofa or under it": the other place of a choice said only next to the first names no place
    return out + [Unread(m[1], "place", _BESIDE_IT) for m in _OR_BESIDE_IT.finditer(lowered)]


_UNDER = "no base task puts a thing under another: say in or on"
_BESIDE_IT = "a place said only as under, behind or next to another is no place a base task puts a thing"
_OR_BESIDE_IT = re.compile(
    r"\bor\s+(?:(?:put|leave|set|place|stick)\s+it\s+)?(?:just\s+)?"
    rf"((?:{'|'.join(sorted(UNDER | NEAR_WORDS))}|(?:next|close)\s+to|in\s+front\s+of)\s+(?:it|them)\b)"
)
_UNDER_BEFORE = re.compile(rf"\b(?:{'|'.join(sorted(UNDER))})\s+(?:the\s+|a\s+|an\s+|your\s+|my\s+)?$")


PICKS_ONE = re.compile(
    r"\bthe\s+(second|third|fourth|fifth|left|right|leftmost|rightmost|middle|nearest|closest|farthest|"
    r"furthest|biggest|smallest|larger|smaller|bigger|top|bottom|upper|lower|topmost|bottommost|uppermost|"
    r"highest|lowest|front|frontmost)\s+"
)
_PICKED = "picks one of several things of its type: the spec's atoms name types (any one does)"


def repeated_tasks(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """Two tasks that are the same task need the thing named as a thing to act on as often: "... after
    the apple is in the fridge" refers to a placing, it asks for no second apple in the fridge."""
    same: dict[tuple[object, ...], list[BaseTaskSpec]] = {}
    for t in parse.tasks:
        key = (t.kind, tuple(t.object), tuple(t.receptacle or ()), t.sliced, tuple(t.container or ()))
        same.setdefault(key, []).append(t)
    out = []
    lowered = instruction.lower()
    for tasks in (ts for ts in same.values() if len(ts) > 1):
        named = [m for m in mentions if set(m.entry.types) & set(tasks[0].object)]
        references = [m for m in named if _state_reference(lowered, m)]
        if references and len(named) - len(references) < len(tasks):
            out.append(Unread(references[0].surface, "object", _SAID_ONCE))
    return out


_SAID_ONCE = "a task said once is read twice (once where the words only refer to it): say it once"
_REFERENCE_BEFORE = re.compile(rf"\b{REFERENCE}\s+(?:the|a|an|your|my)?\s*$")
_STATE_AFTER = re.compile(r"\s+(?:is|are|was|were|has been|have been|gets|goes|'s)\b")


def _state_reference(lowered: str, m: Mention) -> bool:
    """ "after the apple is in the fridge": the thing named in a reference to a state, not acted on."""
    return bool(
        _REFERENCE_BEFORE.search(lowered[max(0, m.char_start - 30) : m.char_start])
        and _STATE_AFTER.match(lowered, m.char_end)
    )


def _returned(lowered: str, start: int, end: int, mentions: list[Mention], parse: ParseUsage) -> bool:
    """Does a task put something into a place the words between `start` and `end` name as a source
    ("from the cabinet", "out of the fridge"), or that a statement right before the return says the things
    belong in ("the remotes live on the armchair, put them back": `put_back.BELONGS_THEN_BACK`)?"""
    places = {r for t in parse.tasks for r in t.receptacle or ()}
    belongs = [b.span("place") for b in BELONGS_THEN_BACK.finditer(lowered) if b.start() < end < b.end()]
    return any(
        set(m.entry.types) & places
        and (
            start <= m.char_start < end
            and a_source(lowered, m.char_start)
            or any(a <= m.char_start < b for a, b in belongs)
        )
        for m in mentions
    )


_THEN_VERB = re.compile(
    r"\b(?:then|afterwards|after that|next|later|before)\s*,?\s+(?:you\s+)?(?:can\s+)?([a-z]+)"
)


def treated_after_placing(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """A task's slice or treatment comes before its placing; "put the tomato in the fridge, then slice
    it" says the opposite, so a sliced tomato in the fridge is not what it asks."""
    out = []
    lowered = instruction.lower()
    for t in parse.tasks:
        wanted = {f"verb_{t.kind}"} | ({"verb_sliced"} if t.sliced else set())
        places = set(t.receptacle or ()) - {APPLIANCE.get(t.kind, "")}
        at = lowered.find(t.text.lower()) if t.text else -1  # the task's own words, else the whole text
        start, end = (at, at + len(t.text)) if at >= 0 else (0, len(lowered))
        placed = [m.char_end for m in mentions if set(m.entry.types) & places and start <= m.char_start < end]
        sentence_end = next((k for k in range(end, len(lowered)) if lowered[k] in ".;!?"), len(lowered))
        for then in _THEN_VERB.finditer(lowered, start, sentence_end):
            if not (placed and then.start() > max(placed) and categories(then.group(1)) & wanted):
                continue
            if _treats_its_own(then, t, parse.tasks, lowered):
                continue  # "..., then cook a tomato and put it in the sink": another task's own treatment
            after = lowered[then.end() : then.end() + 40]
            if _PRONOUN.match(after) or any(
                m.char_start >= then.end()
                and set(m.entry.types) & set(t.object)
                and m.char_start < then.end() + 40
                for m in mentions
            ):
                out.append(
                    Unread(then.group(0), "order", f"task {t.id}'s treatment comes before its placing")
                )
    return out


def _treats_its_own(
    then: re.Match[str], task: BaseTaskSpec, tasks: Sequence[BaseTaskSpec], text: str
) -> bool:
    """Is the treatment verb after an order word the first words of another task that has this treatment
    ("place a heated tomato in the sink, then cook a tomato and put it in the sink": two tasks)?"""
    verb = then.group(1)
    for u in tasks:
        if u is task or not u.text or not categories(verb) & ({f"verb_{u.kind}"} | _SLICED[u.sliced]):
            continue
        at = text.find(u.text.lower())  # not found where `everyday` rewrote a phrase ("rinse off")
        if (at <= then.start(1) < at + len(u.text)) if at >= 0 else u.text.lower().split()[0] == verb:
            return True
    return False


_SLICED = {True: {"verb_sliced"}, False: set()}


_PRONOUN = re.compile(rf"\s+(?:{'|'.join(sorted(PRONOUNS))})\b")


def closed_after_placing(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """A placing task leaves its receptacle open: "put the knife in the drawer and close it" is not done
    unless a task closes it."""
    places = {r for t in parse.tasks for r in t.receptacle or ()}
    first = min((m.char_end for m in mentions if set(m.entry.types) & places), default=None)
    if first is None or "closed" in parse.states:
        return []
    return [
        Unread(shut.group(0), "action", "no base task closes it: the plan leaves it open")
        for shut in _CLOSE.finditer(instruction.lower(), first)
    ]


_CLOSE = re.compile(r"\b(?:close|closed|shut)\b(?! (?:to|by)\b)")


_OTHER = re.compile(r"\b(?:the other|another|a different|the same|a (?:second|third|fourth|fifth))\b")


def other_instances(
    instruction: str, mentions: list[Mention], parse: ParseUsage, instances: Mapping[str, int] | None = None
) -> list[Unread]:
    """ "Put the pen in the drawer and the pencil in the other drawer": two tasks on one type, which the
    spec (type-level atoms) cannot keep to two different things, or to one. "The other" / "another" /
    "a different" / "the same" before such a thing (a place, or "the same" object), or standing for it, is
    unread; a landmark ("next to the other food") names a thing no two tasks take. "The same" of a
    type the scene (`instances`) holds once is that one. "The other" / "another" / "a different" thing of
    a type that tasks pick up and take each to a place of its own is read: a leaf's picked-up objects are
    its own, so two such tasks take two different ones (docs/planning.md, "The model"; the goal checker
    asks the same)."""
    taken = Counter(t for task in parse.tasks for t in set(task.object))
    picked = Counter(t for task in parse.tasks if task.kind != "set_state" for t in set(task.object))
    # "a drawer ... the other drawer", "the same drawer": places are type-level atoms too
    taken.update(t for task in parse.tasks for t in set(task.receptacle or ()))
    shared = {t for t, n in taken.items() if n > 1}
    if not shared:
        return []
    # picked up by each task that takes it, to a place (or a container) of its own: two things kept apart
    # ("the other book" on the bed after a book is a pair, `place_two`, which this reading is not)
    ends = {t: {_end(k) for k in parse.tasks if t in k.object} for t in shared}
    apart = {t for t in shared if picked[t] == taken[t] == len(ends[t])}
    out = []
    lowered = instruction.lower()
    for m in _OTHER.finditer(lowered):
        rest = lowered[m.end() :]
        named = next((x for x in mentions if m.end() <= x.char_start <= m.end() + 20), None)
        hit = shared  # the types it may say: a thing's, or any two tasks take where it stands for one
        if named is not None and not _PLACE_OR_STOP.search(lowered[m.end() : named.char_start]):
            hit = set(named.entry.types) & shared
            the_shared = bool(hit)  # "the other apple"
            if m.group(0) == "the same":  # unknown scene (None): not judged, as counts are not
                held = instances or {}
                the_shared = any(held.get(t, 0) > 1 for t in hit)
        else:
            the_shared = _STANDS_FOR.match(rest) is not None  # "the other on the counter", "another one"
            hit = {t for t in shared if picked[t]}  # it stands for a thing moved, not for a place
        # "the other tomato", "one in the fridge and the other in the sink": the tasks take two apart
        if the_shared and (m.group(0) == "the same" or not hit <= apart):
            out.append(Unread(m.group(0), "object", _TWO_OF_A_TYPE))
    return out


def _end(task: BaseTaskSpec) -> tuple[str, ...]:
    """Where a task leaves its thing: its kind, place and container."""
    return (task.kind, *(task.receptacle or ()), *(task.container or ()))


_PLACE_OR_STOP = re.compile(r"[,.;:!?]|\b(?:in|on|to|into|onto|at|of)\b")
_STANDS_FOR = re.compile(r"\s*(?:[,.;:!?]|$|(?:ones?|in|on|into|onto|to|at|goes|go|should|is|needs)\b)")
_TWO_OF_A_TYPE = (
    "two tasks take this type: the spec cannot require two different ones, or the same one (any one of"
    " the type does)"
)


_START = re.compile(r"\b(?:start|run|operate|activate)\s+(?:it|them|the\s+\w+)\b(?![^,.;!?]*\bunder\b)")


def started(instruction: str, parse: ParseUsage) -> list[Unread]:
    """ "Put the mug in the coffee machine and start it": switching a machine on, which no task does
    unless one switches something on ("run the mug under the water" rinses it)."""
    if "on" in parse.states:
        return []
    return [
        Unread(m.group(0), "action", "no base task switches it on")
        for m in _START.finditer(instruction.lower())
    ]


_FIRST_OR_LAST = re.compile(r"\s+(?:(?:goes|comes|should go|has to go|must go)\s+)?(first|last)\b")


def first_and_last(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """ "..., then the tomato, but the egg first": the one task on the egg must come before every other
    task ("last": after every other); an order that does not say so left the words unread."""
    closure: dict[str, set[str]] = {}  # built at the first "first" / "last" only: most texts have none
    out = []
    for m in mentions:
        said = _FIRST_OR_LAST.match(instruction.lower(), m.char_end)
        ids = [t.id for t in parse.tasks if set(t.object) & set(m.entry.types)]
        if said is None or len(ids) != 1 or len(parse.tasks) < 2:
            continue
        if not closure:
            order = nx.DiGraph(list(parse.before))
            order.add_nodes_from(t.id for t in parse.tasks)
            closure = {a: nx.descendants(order, a) for a in order}
        others = {t.id for t in parse.tasks} - {ids[0]}
        ordered = (
            others <= closure[ids[0]]
            if said.group(1) == "first"
            else all(ids[0] in closure[o] for o in others)
        )
        if not ordered:
            out.append(
                Unread(f"{m.surface} {said.group(1)}", "order", f"task {ids[0]} is not {said.group(1)}")
            )
    return out


OPENED_FOR_ITSELF = frozenset({"Book", "Laptop", "Blinds"})  # opened to be open, not to reach inside


def opened_for_itself(after: list[str], parse: ParseUsage) -> str | None:
    """The object an "open" / "close" names when it is opened for its own sake (a book, a laptop, the
    blinds: never a container on the way) and no task opens or closes it."""
    rest = " ".join(after[1:] if after and after[0] in DETERMINERS else after)
    entry = lookup(rest.split()[0]) if rest else None
    if entry is None or not set(entry.types) & OPENED_FOR_ITSELF:
        return None
    done = {
        t for x in parse.tasks if x.kind == "set_state" and x.state in ("open", "closed") for t in x.object
    }
    return None if set(entry.types) & done else entry.canonical


CORRECTION = "a correction said in passing that the reading does not follow: say it once, as meant"


def corrections(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """Corrections said in passing that the reading does not follow (`_correction_not_taken`)."""
    toks = tokens(instruction)
    return [
        Unread(" ".join(w for w, _, _ in toks[max(i - 1, 0) : i + 1]), "correction", CORRECTION)
        for i, (w, _, _) in enumerate(toks)
        if "correction" in categories(w) and _correction_not_taken(instruction, toks, i, mentions, parse)
    ]


def _correction_not_taken(
    instruction: str, toks: list[tuple[str, int, int]], i: int, mentions: list[Mention], parse: ParseUsage
) -> bool:
    """Does the word take back the thing named before it in its sentence ("..., I mean", "or rather",
    "scratch that", "..., actually the cabinet") while a task still uses that thing ("in the fridge, I
    mean the microwave" read as chilling in the fridge)? "I'd rather" and a leading "Actually, ..." take
    nothing back."""
    w, prev, nxt = toks[i][0], toks[i - 1][0] if i else "", toks[i + 1][0] if i + 1 < len(toks) else ""
    if (w == "mean" and (prev != "i" or nxt in ("it", "that"))) or (w == "rather" and prev != "or"):
        return False
    if (w == "scratch" and nxt != "that") or (w == "wait" and prev != "no"):
        return False  # "scratch the paint", "wait for it": no correction
    start = sentence_start(instruction, toks[i][1])
    if w in ("sorry", "oops") and start and not instruction[start : toks[i][1]].strip(" ,"):
        # opening its sentence, an own mistake takes back the sentence before ("put the book on the desk
        # lamp... sorry, look at the book under it"); "Actually, ..." opening a sentence adds instead
        start = sentence_start(instruction, len(instruction[:start].rstrip(" .;!?")))
    taken = [m for m in mentions if start <= m.char_start < toks[i][1]]
    used = {t for _, _, st in parse.slots() for t in st} | parse.implied()
    return bool(taken) and bool(set(taken[-1].entry.types) & used)


# a fragment after an instruction ("Hers too.", "Both of them.", "And the other one."): words that refer
# to a thing (`_REFERRING`) and words that only join or point (`_JOINING`), no verb and no named thing
_REFERRING = frozenset(
    "hers his theirs mine yours ours both other others one ones same too also another rest remaining again "
    "either".split()
)
_JOINING = DETERMINERS | frozenset(
    "and then plus please now next for as well with to it they them that's is are of here there".split()
)
FRAGMENT = "a fragment that names no thing and no action: say the whole task (which thing, what to do)"


def fragments(instruction: str, mentions: list[Mention]) -> list[Unread]:
    """Sentences after the first that only refer ("Hers too.", "Both of them.", "Same again."): which thing
    and which task they mean is not said, so they are named, never dropped. A fragment that names a thing
    ("The cup too.") is left to the readers and to check 1's nouns."""
    out = []
    for m in re.finditer(r"[^.;!?\n]+", instruction):
        words = [w for w, _, _ in tokens(m.group(0))]
        named = any(m.start() <= n.char_start < m.end() for n in mentions)
        if (
            m.start() > 0
            and words
            and not named
            and set(words) <= _REFERRING | _JOINING
            and set(words) & _REFERRING
            and not any(c.startswith("verb_") for w in words for c in categories(w))
        ):
            out.append(Unread(m.group(0).strip(" ,"), "fragment", FRAGMENT))
    return out


# a sentence after a task that asks for that task again for another thing (issue 23): "The cup too.",
# "Same for the bowl." (`grammar.repeats`, which writes out those it can); "the same for the cup, but ..."
_SAME_FOR = re.compile(
    r"\bsame\s+(?:thing\s+)?(?:for|with|to)\s+(?:the|a|an|my|your)\s+(?:other\s+|second\s+)?", re.I
)
_SAME_TASK = "the task before, for another thing: no task does the whole of it (its treatment, slicing, "
_SAME_TASK += "place, order) for this thing: say the whole task"
_SAME_THING = "no task of its own does the task for this thing (unread, or read as another task's thing)"


def repeats_for_another(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """A fragment sentence that repeats the task before it for another thing ("Wash the mug and put it on
    the counter. The cup too."): read only where a task does exactly what another task does (kind,
    slicing, count, places, light, state, order) to the thing named, and that other task's thing is
    another type; a cup placed but not washed is named, never dropped. A thing after "the same for" is
    never read as the thing of another task ("the cup" as the mug before it)."""
    out = []
    for s in re.finditer(r"[^.;!?\n]+", instruction):
        if s.start() == 0 or not REPEAT_FRAGMENT.match(s.group(0)):
            continue
        named = [x for x in mentions if s.start() <= x.char_start < s.end()]
        if named and not all(_repeated(set(x.entry.types), parse) for x in named):
            out.append(Unread(s.group(0).strip(" ,"), "fragment", _SAME_TASK))
    spans = task_spans(instruction, parse.tasks)  # per mention: not the task of an earlier "a remote"
    for m in _SAME_FOR.finditer(instruction):
        x = next((x for x in mentions if x.char_start == m.end()), None)
        types = set(x.entry.types) if x is not None else set()
        said = [t for t in parse.tasks if (sp := spans[t.id]) is None or sp[1] > m.start()]
        # its own task: no other task's thing ("the cup" read as the mug before), or by its own name (the
        # other remote, after "a remote")
        if x is not None and not any(
            set(t.object) & types and (_own(t, parse) or x.entry.canonical in t.object) for t in said
        ):
            out.append(Unread(x.surface, "object", _SAME_THING))
    return out


def _others(t: BaseTaskSpec, parse: ParseUsage) -> list[BaseTaskSpec]:
    return [o for o in parse.tasks if o is not t]


def _own(t: BaseTaskSpec, parse: ParseUsage) -> bool:
    """No other task acts on a thing of `t`'s type."""
    return not any(set(o.object) & set(t.object) for o in _others(t, parse))


def _repeated(types: set[str], parse: ParseUsage) -> bool:
    def what(t: BaseTaskSpec, other: BaseTaskSpec) -> tuple[object, ...]:
        ids = {t.id, other.id}
        after = {a for a, b in parse.before if b == t.id and a not in ids}
        before = {b for a, b in parse.before if a == t.id and b not in ids}
        return (t.kind, t.sliced, t.count, t.receptacle, t.container, t.light, t.state, after, before)

    return any(
        set(t.object) & types and _own(t, parse) and what(t, o) == what(o, t)
        for t in parse.tasks
        for o in _others(t, parse)
    )
