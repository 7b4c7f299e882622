"""A framing-independent reading of tabletop instructions (issue 28): the fallback when the grammar
refuses an instruction in the tabletop world.

The tabletop world has one kind of task: an object goes on a plate. Whatever the phrasing ("the blue
plate gets the carrot", "carrot: blue plate", "the carrot should end up on the blue plate"), each
object mention is paired with the plate mention beside it, the object first or the plate first as the
sentence starts. The words around the names are read first (`tabletop_wording`: statements, free-order
remarks, corrections, plurals, step labels, and the clauses that name nothing, read by their words).
The order is read from a small set of forms only: no order word (or a free-order remark) leaves the
tasks unordered; "first ... then / after that / once that's done ..." (or "Step 1: ... Step 2: ...",
a "then" closing its clause, a clause waiting for placements it states, an order said of plates alone)
orders the groups; any other order, relation or count word refuses. Check 1 (`accounting.account`)
then judges the words read, and the grammar's refusal stands unless every word is used.

>>> [(t.object, t.receptacle) for t in read_pairs("carrot: blue plate", {"Carrot", "BluePlate"})[0]]
[(['Carrot'], ['BluePlate'])]
>>> read_pairs("carrot: blue plate, then carrot: pink plate", {"Carrot", "BluePlate", "PinkPlate"})
"""

from __future__ import annotations

import re
from collections import Counter

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.content_words import Unread, take_backs, vocabulary
from nl2hltl2plan.language.frame_filler import frame_note
from nl2hltl2plan.language.grammar.restated import count_fits
from nl2hltl2plan.language.grounding import camel_words
from nl2hltl2plan.language.headings import answered
from nl2hltl2plan.language.htt_build import build_htt
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.tabletop_chat import chat_read
from nl2hltl2plan.language.tabletop_counts import plate_counts_read, plates_said_alone, total_counts_read
from nl2hltl2plan.language.tabletop_dialogue import dialogue_read, scenario_read
from nl2hltl2plan.language.tabletop_fields import fields_read
from nl2hltl2plan.language.tabletop_freed_steps import steps_named
from nl2hltl2plan.language.tabletop_headings import (
    stage_headings_read,
    task_headings_read,
    task_headings_unread,
)
from nl2hltl2plan.language.tabletop_lines import bracketed_list_opened, lines_joined, names_spelt, stops_read
from nl2hltl2plan.language.tabletop_order import (
    BEFORE,
    FIRST,
    FIRST_CLOSING,
    PLACE_IN_THE_WHOLE,
    THEN,
    end_opener_read,
    heading_colon_put_back,
    inverted_condition_read,
    ordinal_things_read,
    plate_wait_read,
    reference_fronted,
    robot_addressed,
    then_after_subject_fronted,
    trailing_then_fronted,
    turn_phrases_read,
)
from nl2hltl2plan.language.tabletop_remarks import role_dropped
from nl2hltl2plan.language.tabletop_spelling import misspelt_order_words, names_respelt, order_words_spelt
from nl2hltl2plan.language.tabletop_steps import labels_out_of_turn, list_freed, numbered_steps, steps_read
from nl2hltl2plan.language.tabletop_waits import plate_waits_read
from nl2hltl2plan.language.tabletop_wording import (
    corrected,
    free_order,
    last_group_free,
    last_item_unmarked,
    mention_pattern,
    moving_idioms_read,
    plain_words,
    stated_not_asked,
)
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_closure
from nl2hltl2plan.worlds.world import World

# words that state some other order, relation, count or negation: the fallback never guesses at them. They
# are the shared categories of check 1 (`content_words.txt`), and the words the pairs reading has no place
# for though those categories do not refuse them: a place relative to another thing ("near", "behind",
# "from", "off"), a connective that changes which pairs hold ("or", "but", "only", "instead", "either"),
# the verb of another action ("remove", "swap", "stack"), and "while" (a free-order word to check 1, but
# here it joins two clauses this reading does not relate: "while you are at it", "while holding")
_REFUSED_CATEGORIES = ("negation", "order", "condition", "quantifier_all", "quantifier_vague", "repetition")
_NOT_PAIRED = (
    "from off out away back near beside besides by behind under between instead either or but only while "
    "remove swap keep leave empty clear stack rather"
)


def _refused_words() -> re.Pattern[str]:
    shared = vocabulary()
    words = {w for c, ws in shared.items() if c in _REFUSED_CATEGORIES or c.startswith("count_") for w in ws}
    words |= set(_NOT_PAIRED.split())
    alternatives = "|".join(map(re.escape, sorted(words, key=len, reverse=True)))
    return re.compile(rf"\b(?:{alternatives})\b|\d")  # a digit: a count or a step number


_REFUSED = _refused_words()
_SENTENCE = re.compile(r"[.;!?]+")
# a heading before a colon that names no object or plate: "Here is what I need:", "Postcondition:",
# "Your job is to put each item on its plate:", "Three moves:" (its count must be the placements listed)
_HEADING = re.compile(r"^(?P<head>[^:]*?)(?::|\s+-\s+)")  # "Three moves:", "I'd like three things done -"
_GENERIC_QUANTITY = re.compile(
    r"\b(?:each|every|all(?:\s+the)?)\s+(?:item|thing|fruit|object|piece|one)s?\b|"
    # "each of the three fruits": the count after it is checked as a count of its own
    r"\b(?:each|every|all)\s+of\s+(?:the|these|those)\b(?=\s+(?:two|three|four)\b)|"
    r"\b(?P<count>two|three|four)\s+(?:[a-z]+\s+)?(?:items?|things?|fruits?|objects?|placements?|moves?|"
    r"pieces?|tasks?|ones|jobs|errands|chores)\b"
)
# "each plate gets one thing": one placement per plate, which the pairs listed after it must keep
_ONE_PER_PLATE = re.compile(
    r"\b(?:each|every)\s+plate\s+(?:gets|takes|holds|receives|has)\s+(?:just\s+|exactly\s+)?(?:one|a\s+single|"
    r"a)\s+(?:item|thing|fruit|object|piece)\b"
)

# verbs that order one placement after another, which check 1's order words do not list: no reading of
# the tabletop world takes them ("the green apple on the yellow plate must precede the carrot ...")
_RELATION_VERB = re.compile(r"\bpreced(?:e|es|ed|ing)\b")
# words that say an order which check 1's order words do not list: a reading with no order leaves them
# unused, and the pairs reading refuses them ("put A on P > wait > put B on Q", "P has priority; Q follows",
# "alphabetically", "by size", "biggest first"; not "no need to follow an order"); a priority only the former
# ("Priority 1: ... Priority 2: ..." are labels); "sooner than" compares times
_ORDER_SAID = re.compile(
    r"\b(?:wait(?:s|ing)?|pause|follow(?:s|ed|ing)|alphabetic(?:al(?:ly)?)?|"
    r"(?:anti-?|counter-?)?clockwise|by\s+(?:size|colou?r|height|weight|name|type)|(?:left|right)\s+to\s+"
    r"(?:right|left)|(?:bigg|small|larg|tall|short|heavi|light)est\s+(?:first|last)|in\s+turn|"
    r"sequential(?:ly)?|in\s+sequence|one\s+(?:after|by)\s+(?:the\s+)?(?:other|one)|(?:sooner|earlier)\s+than|"
    r"(?:phase|stage)\s+(?:[a-z]|\d+))\b"  # "### Phase A ... ### Phase B": parts, whose order is not said
)
_PRIORITY = re.compile(r"\bpriorit(?:y|ies|i[sz]e[sd]?)\b")
# words that turn round what was asked ("the other way round", "They're swapped."; what takes it back, "That's
# wrong.", is refused before any reading, `content_words.refuse_take_backs`): the grammar reads round them, so
# this world leaves them unused
_TURNED_ROUND = re.compile(
    r"\b(?:wrong|incorrect|opposite|(?:the\s+)?other\s+way(?:\s+round)?|swapped|reversed)\b"
)
# "rather than" / "instead of": a thing or plate not wanted, which no placement of the reading says
_RATHER_THAN = re.compile(r"\b(?:rather\s+than|instead\s+of|in\s+place\s+of)\b")
# labels that name alternatives, not steps ("Plan A: ... Plan B: ...", "Option 1: ..."): which one is meant
# is not said, and doing both is no reading of them
_ALTERNATIVES = re.compile(
    r"\b(?:option|plan|alternative|choice|scenario|variant|version|possibility)\s+(?:[a-d]|\d|one|two|three|"
    r"four|i{1,3}|iv)\b"
)
# entries of a list numbered ("Item 1: ...", "Item the second: ...", "Point two: ..."): a list's entries,
# which may or may not be steps in turn
_ENTRIES = re.compile(
    r"\b(?:item|entry|point|bullet|line)\s+(?:the\s+)?(?:\d|one|two|three|four|first|second|third|fourth)\b"
)

# "the order matters" / "sequence is important" / "the order is not up to you": an order is meant, but only
# the mention order says which
_ORDER_MATTERS = re.compile(
    r"\b(?:order(?:ing)?|sequence)\b(?:(?![.;!?]|\bnot\b|n't)[^.;!?]){0,30}?\b(?:matters|(?:does|do)\s+matter|"
    r"is\s+important|counts)\b|\b(?:order(?:ing)?|sequence)\s+(?:is|isn't)\s+(?:not\s+)?(?<=n't\s|not\s)(?:up\s+to\s+"
    r"you|free|arbitrary|optional|your\s+(?:call|choice))\b"
)

Reading = tuple[list[BaseTaskSpec], list[tuple[str, str]], list[list[str]], str]


class TabletopReader:
    """The tabletop world's hook (`world_readers.WorldReader`; the shared grammar reads first): statements
    refused, corrections and numbered lists read before the grammar reads (`prepared`), the pairs reading
    of what it refuses or reads in part (`reread`) and as a check of what it reads in full (`doubted`), the
    objects a word could mean beside a refusal (`refusal`), and every named thing a reading leaves unused
    (`unused`)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.frames: list[str] = []

    def own_reading(self, instruction: str) -> LanguageResult | None:
        return None  # the shared grammar reads first (world_readers imports this module: no base class)

    def as_read(self, lines: list[str]) -> str:
        """An instruction's lines as the one line its line breaks say (a plate heading with its objects
        under it, a list of items one a line), with the names spelt as the world spells them
        ("green_apple", "the plate blue"): `tabletop_lines`; misspelt names and order words written right
        (`tabletop_spelling`); a user story's role ("As a tidy person, I want ..."); "the first thing to
        do is" as "first" (`tabletop_order.ordinal_things_read`); "the robot puts / has put" said to the
        one asked (`tabletop_order.robot_addressed`); a clause that looks back on the step before as
        "then" (`tabletop_order.turn_phrases_read`); "makes its way into" as "goes into"."""
        kinds = {camel_words(t): _is_plate(t) for t in self.world.object_types()}
        self.frames = []  # what the general filler rule drops, for `notes`
        text = names_spelt(stops_read(chat_read(lines_joined(lines, kinds), kinds, self.frames)), kinds)
        text = bracketed_list_opened(text, kinds)  # "sort fruit (green apple -> pink plate, ...)"
        text = fields_read(text, kinds, self.frames)  # "Object: ... Target: ...", "as follows:", "Chart: ..."
        text = answered(text)  # "Q: Where does the green apple go? A: On the blue plate."
        text = dialogue_read(text, mention_pattern(kinds, re.I))  # "Robot: What do you need? Me: ..."
        text = scenario_read(text, mention_pattern(kinds, re.I))  # "Given ..., when I say go, then ..."
        mentions = mention_pattern(kinds, re.I)
        text = role_dropped(text, mentions)  # "As a tidy person, I want ..."
        text = robot_addressed(ordinal_things_read(text, mentions))  # "The first thing is ...", "it puts"
        text = moving_idioms_read(end_opener_read(turn_phrases_read(text)), kinds)  # "Having done that,"
        return order_words_spelt(names_respelt(text, kinds))

    def prepared(self, instruction: str) -> str:
        """A clause that says where something is ("the carrot is on the blue plate") with no wish or goal
        before it is no task, and is refused by name; a correction ("the blue plate, sorry, the yellow
        plate") is applied, and a numbered list's numbers read as "first" / "then" (`numbered_steps`), before
        any reading (`tabletop_wording`); numbered entries of a list ("Item 1:") are refused by name."""
        kinds = {camel_words(t): _is_plate(t) for t in self.world.object_types()}
        stated = stated_not_asked(instruction, kinds)
        if stated is not None:
            raise HTTError(
                f"'{stated}' says where something is, not what to do: ask for it (\"put ...\", \"make sure "
                "... is on ...\") or leave it out"
            )
        if entry := _ENTRIES.search(instruction.lower()):
            raise HTTError(f"'{entry[0]}' numbers the entries of a list: say whether they are steps in turn")
        # "Two stages. Stage one: ...": the heading checked against the labels before they are read
        stepped = numbered_steps(stage_headings_read(plate_waits_read(corrected(instruction, kinds), kinds)))
        if named := steps_named(stepped):  # a remark on steps by number that `runs_freed` could not read
            raise HTTError(f"'{named}': which steps are free of their order is not clear; say it another way")
        return stepped

    def reread(self, instruction: str, backend: str) -> LanguageResult | None:
        return tabletop_fallback(instruction, self.world, backend)

    def refusal(self, refused: Exception, instruction: str, prepared: str, rest: str) -> Exception:
        """A refusal ("no Apple in tabletop") with the objects the world has for a word that names
        several of them alone ("tabletop has the green apple and the red apple")."""
        has = world_has(instruction, self.world)
        return type(refused)(f"{refused}{has}") if has else refused

    def doubted(self, res: LanguageResult, backend: str) -> LanguageResult:
        """The grammar's full reading, or the pairs reading where it reads the instruction too, gives other
        placements or another order, and check 1 on the words it read accepts it and rejects the grammar's
        reading ("The robot shall first place A on P and shall then place B on Q": the grammar pairs A with
        Q and leaves "first" and "then" unused); made partial where neither is rejected: two readings that
        differ are never a guess."""
        paired = tabletop_fallback(res.instruction, self.world, backend)
        if paired is None or _signature(paired) == _signature(res):
            return res
        if self._rejected_on_words_paired(res):
            return paired
        why = (
            f"'the placements and their order' (order): read two ways, {_described(res)} (the grammar) or "
            f"{_described(paired)} (object and plate paired); say it another way"
        )
        return res.model_copy(update={"unparsed": [*res.unparsed, why]})

    def _rejected_on_words_paired(self, res: LanguageResult) -> bool:
        """Does check 1 reject the grammar's reading on the words the pairs reading read (its wording rules
        applied), which the pairs reading passed?"""
        read = read_pairs(res.instruction, set(self.world.object_types()))
        if read is None:
            return False
        instances = Counter(o.type for o in self.world.objects.values() if o.present)
        try:
            return bool(account(read[3], res.tasks, res.before, instances, self.world.name))
        except HTTError:  # a count or order check 1 rejects outright
            return True

    def notes(self, instruction: str) -> list[str]:
        """What the general filler rule dropped as frame in `as_read` (respellings have their own notes)."""
        return [frame_note(self.frames)] if self.frames else []

    def unused(self, res: LanguageResult) -> list[Unread]:
        """Each object or plate the instruction names (outside its negated clauses) that no base task
        uses: nothing lies on a plate or beside a named thing at the start, so a name read as a landmark
        ("the green apple on the pink plate orange on the yellow plate ...") was not understood; and each
        object that two tasks place (a thing ends on one plate)."""
        text = res.instruction.lower()
        for c in res.constraint_specs:
            text = text.replace(c.text.lower(), " ")
        by_words = {camel_words(t): t for t in self.world.object_types()}
        used = {t for task in res.tasks for t in (*task.object, *(task.receptacle or []))}
        out: dict[str, Unread] = {}
        for found in mention_pattern(by_words).finditer(text):
            name = _name(found[0])
            type_ = by_words.get(name) or by_words.get(name.removesuffix("s"))
            if type_ is not None and type_ not in used:
                kind = "place" if _is_plate(type_) else "object"
                out[name] = Unread(name, kind, f"no base task uses it ({type_})")
        placed = Counter(o for task in res.tasks for o in task.object)
        for type_ in (t for t, n in placed.items() if n > 1):  # "I hate oranges" read as a placement too
            why = "placed by two tasks: a thing ends on one plate, and which one is meant is not said"
            out[camel_words(type_)] = Unread(camel_words(type_), "object", why)
        if (labels := labels_out_of_turn(res.instruction.lower())) is not None:
            out[labels] = Unread(labels, "order", "steps numbered out of turn")
        for found in _ORDER_MATTERS.finditer(res.instruction.lower()):
            why = "it says that the order matters, not which order: say it with first / then"
            out[found[0]] = Unread(found[0], "order", why)
        for found in _RELATION_VERB.finditer(res.instruction.lower()):
            why = "an order between placements that this reading does not take"
            out[found[0]] = Unread(found[0], "order", why)
        for found in _TURNED_ROUND.finditer(res.instruction.lower()):
            why = "it may turn round what was asked: say what is meant"
            out[found[0]] = Unread(found[0], "negation", why)
        for phrase, why in task_headings_unread(res.instruction, len(res.tasks)):  # "Three things:" and two
            out[phrase] = Unread(phrase, "count", why)
        for word in misspelt_order_words(res.instruction):
            out[word] = Unread(word, "order", "it may misspell an order word: which one is not guessed")
        for found in _RATHER_THAN.finditer(res.instruction.lower()):
            out[found[0]] = Unread(found[0], "negation", "what is not wanted is no placement: leave it out")
        for found in _ALTERNATIVES.finditer(res.instruction.lower()):
            out[found[0]] = Unread(found[0], "condition", "alternatives: which one is meant is not said")
        for found in _ENTRIES.finditer(res.instruction.lower()):
            why = "entries of a list: whether their numbers are steps in turn is not said"
            out[found[0]] = Unread(found[0], "order", why)
        lowered = res.instruction.lower()
        said = [*_ORDER_SAID.finditer(lowered), *_PRIORITY.finditer(lowered)]
        said += PLACE_IN_THE_WHOLE.finditer(lowered)
        for found in said if not res.before else ():
            why = "it says an order (a wait, what follows, a priority, a sorting) and the reading has none"
            out[found[0]] = Unread(found[0], "order", why)
        return list(out.values())


def tabletop_fallback(instruction: str, world: World, backend: str) -> LanguageResult | None:
    """The pairs reading of an instruction the grammar refused in the tabletop world, as a result for
    `translate` to finish; None (the grammar's refusal stands) in any other world, when the text is not
    one of the forms `read_pairs` knows, or when check 1 finds a content word the reading does not use
    (in the words read: corrections applied, plurals named, free-order remarks and step labels read)."""
    if world.kind != "tabletop":
        return None
    read = read_pairs(instruction, set(world.object_types()))
    if read is None:
        return None
    tasks, before, groups, words_read = read
    instances = Counter(o.type for o in world.objects.values() if o.present)
    try:
        if account(words_read, tasks, before, instances, world.name):
            return None
    except HTTError:  # a count or order check 1 rejects in the words read: the grammar's refusal stands
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


def _signature(res: LanguageResult) -> tuple[list[tuple[str, ...]], list[tuple[tuple[str, ...], ...]]]:
    """A reading's placements and closed order, by placement (task ids left out)."""
    key = {t.id: (*t.object, *(t.receptacle or [])) for t in res.tasks}
    closure = transitive_closure(res.before, list(key))
    return sorted(key.values()), sorted((key[a], key[b]) for a, b in closure)


def _described(res: LanguageResult) -> str:
    """ "A green apple on the yellow plate, B carrot on the blue plate; A before B" """
    plates = {t.id: " and the ".join(camel_words(p) for p in t.receptacle or []) for t in res.tasks}
    names = [f"{t.id} {camel_words(t.object[0])} on the {plates[t.id]}" for t in res.tasks]
    orders = ", ".join(f"{a} before {b}" for a, b in res.before) or "no order"
    return f"{', '.join(names)}; {orders}"


def world_has(instruction: str, world: World) -> str:
    """What the world has for a head noun that several of its objects share, where the instruction uses
    it: " (tabletop has the green apple and the red apple)", or ""."""
    by_words = {camel_words(t): t for t in world.object_types()}
    heads, modifiers = _shared_heads(by_words), {w for n in by_words for w in n.split()[:-1]}
    words = re.findall(r"[a-z]+", instruction.lower())
    alone = {w.removesuffix("s") for i, w in enumerate(words) if i == 0 or words[i - 1] not in modifiers}
    used = [h for h in heads if h in alone]
    if not used:
        return ""
    said = "; ".join(" and ".join(f"the {n}" for n in heads[h]) for h in used)
    return f" ({world.name} has {said})"


def read_pairs(text: str, types: set[str]) -> Reading | None:
    """Place tasks (object -> plate), their order, their ordered groups (task ids) and the words read
    (for check 1), or None when the text is not one of the forms this reading knows, states where
    something is, names an object twice, or leaves an object or plate unpaired."""
    by_words = {camel_words(t): t for t in types}
    kinds = {w: _is_plate(t) for w, t in by_words.items()}
    try:
        text = stage_headings_read(text)  # "Two stages. Stage one: ...", as `TabletopReader.prepared` has it
    except HTTError:
        return None
    pattern = mention_pattern(by_words)
    # "only when A is on P should B go on Q": the usual order, before the clause is taken for a statement
    plain = inverted_condition_read(plain_words(text, kinds, _shared_heads(by_words)), pattern)
    plain = plate_wait_read(plain, pattern)  # "only if both of them are on the yellow plate": "... there"
    plates = mention_pattern([w for w, plate in kinds.items() if plate])
    plain, plate_counts = plate_counts_read(plain, plates)  # "two for the yellow plate": checked below
    plain, total_counts = total_counts_read(plain)  # "- those four placements, that's all": checked below
    plain, headed = task_headings_read(plain)  # "Two things: A on P; B on Q.": checked as the counts above
    total_counts += headed
    unread_order = _RELATION_VERB.search(plain) or _ORDER_MATTERS.search(plain) or _ORDER_SAID.search(plain)
    labels_unread = _ALTERNATIVES.search(text.lower()) or _ENTRIES.search(text.lower())
    labels_unread = labels_unread or _TURNED_ROUND.search(text.lower())  # "swapped": never read round
    if take_backs(text):
        return None
    if stated_not_asked(plain, by_words) is not None or unread_order or labels_unread:
        return None
    plain, last_free = last_group_free(plain)
    unordered, remarks = free_order(plain)
    free, listed = bool(remarks), list_freed(plain, remarks)
    stepped = steps_read(last_item_unmarked(unordered) if listed else unordered, listed)
    if stepped is not None:  # a clause waiting for placements, and a "then" closing its clause, put first
        stepped = heading_colon_put_back(reference_fronted(stepped, pattern), pattern)
        stepped = trailing_then_fronted(stepped, pattern)
        stepped = then_after_subject_fronted(stepped, pattern)
    if stepped is not None and PLACE_IN_THE_WHOLE.search(stepped):
        return None  # "... to finish" where it closes no clause that a "then" can open
    plates_first, rest = _plate_order(stepped or "", pattern)
    if plates_first and (THEN.search(rest) or FIRST.search(rest) or BEFORE.search(rest)):
        return None  # the order said of plates and again of placements
    groups = None if stepped is None else _ordered_groups(rest, pattern)
    if stepped is None or groups is None:
        return None
    tasks: list[BaseTaskSpec] = []
    group_ids: list[list[str]] = []
    for group in groups:
        ids: list[str] = []
        for sentence in _SENTENCE.split(group):
            pairs = _sentence_pairs(sentence, pattern, by_words)
            if pairs is None:
                return None
            for obj, plate in pairs:
                ids.append(task_letter(len(tasks)))
                words = f"put the {camel_words(obj)} on the {camel_words(plate)}"
                tasks.append(
                    BaseTaskSpec(id=ids[-1], text=words, kind="place", object=[obj], receptacle=[plate])
                )
        group_ids.append(ids)
    if plates_first:
        on = {t.id: camel_words((t.receptacle or [""])[0]) for t in tasks}
        group_ids = [[i for i, plate in on.items() if plate == p] for p in plates_first]
    objects = [t.object[0] for t in tasks]
    if not tasks or len(set(objects)) != len(objects) or any(not g for g in group_ids):
        return None
    if sum(map(len, group_ids)) != len(tasks):
        return None  # a plate with placements that the order of the plates leaves out
    on_plate = Counter(camel_words((t.receptacle or [""])[0]) for t in tasks)
    if any(on_plate[plate] != count for plate, count in plate_counts):
        return None  # "two for the yellow plate" and another number of placements on it
    if any(count != len(tasks) for count in total_counts):
        return None  # "those four placements, that's all" and another number of placements
    if last_free is not None and (len(group_ids) < 2 or len(group_ids[-1]) != last_free):
        return None  # "those last two can go in any order" must name the last group, and only it
    if free and all(len(g) < 2 for g in group_ids):
        return None  # "A, then B - either order is ok": the remark frees no pair the "then"s leave unordered
    before = [(a, b) for i, g in enumerate(group_ids) for h in group_ids[i + 1 :] for a in g for b in h]
    # "each plate gets one thing" is kept by its heading, not counted; "the plates" are the plates paired
    return tasks, before, group_ids, plates_said_alone(_ONE_PER_PLATE.sub(" ", stepped), kinds)


def _sentence_pairs(
    sentence: str, pattern: re.Pattern[str], by_words: dict[str, str]
) -> list[tuple[str, str]] | None:
    """The (object, plate) pairs of one sentence of a group, after its heading; None when a word outside
    the names states an order, relation, count or negation, or a name is a plural."""
    heading = _HEADING.match(sentence)
    if heading and not pattern.search(heading["head"]):
        listed = [_name(f) for f in pattern.findall(sentence[heading.end() :])]
        pairs = _paired([by_words[f] for f in listed if f in by_words]) or []
        one_each = _ONE_PER_PLATE.search(heading["head"])
        if one_each and len({plate for _, plate in pairs}) != len(pairs):
            return None  # "each plate gets one thing" and then two things on one plate
        if not _heading_fits(_ONE_PER_PLATE.sub(" ", heading["head"]), len(pairs)):
            return None
        sentence = sentence[heading.end() :]
    found = [_name(f) for f in pattern.findall(sentence)]
    if _REFUSED.search(pattern.sub(" ", sentence)) or any(f not in by_words for f in found):
        return None  # an order, relation, count or negation word, or a plural (a count not taken here)
    return _paired([by_words[f] for f in found])


def _heading_fits(head: str, placements: int) -> bool:
    """A heading may quantify the things listed after it ("each item", "three moves"), with their count;
    any other order, count or negation word in it refuses."""
    for m in _GENERIC_QUANTITY.finditer(head):
        if not count_fits(m["count"], placements):
            return False
    return _REFUSED.search(_GENERIC_QUANTITY.sub(" ", head)) is None


def _ordered_groups(text: str, pattern: re.Pattern[str]) -> list[str] | None:
    """The text cut at its "then"s; a first-marker may open the first group (before its first name),
    close it, or, when the group names one plate, stand anywhere in it; and only when a "then" follows.
    None: no text left, or a "first" with no "then"."""
    split = THEN.split(text)
    if len(split) > 1 and not split[0].strip(" ,.;:!?-"):
        return None  # "when you're done, put ...": after what is not said
    parts = [q for p in split for q in _before_split(p, pattern) if q.strip(" ,.;:!?")]
    if not parts:
        return None
    names = [_name(f) for f in pattern.findall(parts[0])]
    name = pattern.search(parts[0])
    opened = FIRST.search(parts[0], 0, name.start() if name else len(parts[0]))
    opened = opened or FIRST_CLOSING.search(parts[0])
    if opened is None and len({n for n in names if n.endswith("plate")}) == 1:
        opened = FIRST.search(parts[0])  # one plate in the group: "do the yellow plate first, with ..."
    if opened is not None and len(parts) == 1:
        return None  # "first" with no "then" after it: which tasks come first is not said
    if opened is not None:
        parts[0] = parts[0][: opened.start()] + " " + parts[0][opened.end() :]
    return parts


# the words besides plate names of an order said of plates alone ("do the yellow plate before the blue
# plate", "start with the yellow plate, then the blue plate", "the blue plate after the yellow plate")
_PLATE_ORDER_WORDS = frozenset(
    "do the fill load start begin with and then first before after next please you could can go goes come "
    "comes placed filled done".split()
)


def _plate_order(text: str, pattern: re.Pattern[str]) -> tuple[list[str], str]:
    """The plates (in words) in the order that a clause naming two or more plates and nothing else says,
    and the text without that clause; no plates and the text as it is when there is no such clause."""
    for piece in re.finditer(r"[^.;:!?\n]+", text):
        found = list(pattern.finditer(piece[0]))
        plates = [_name(f[0]) for f in found]
        words = set(re.findall(r"[a-z']+", pattern.sub(" ", piece[0])))
        if len(plates) < 2 or len(set(plates)) != len(plates) or not all(p.endswith("plate") for p in plates):
            continue
        if not words <= _PLATE_ORDER_WORDS:
            continue
        gaps = [piece[0][a.end() : b.start()] for a, b in zip(found, found[1:], strict=False)]
        if all(re.search(r"\b(?:before|then|next)\b", g) for g in gaps):
            order = plates
        elif len(gaps) == 1 and re.search(r"\bafter\b", gaps[0]) and "first" not in words:
            order = plates[::-1]
        else:
            continue
        return order, text[: piece.start()] + " " + text[piece.end() :]
    return [], text


def _before_split(part: str, pattern: re.Pattern[str]) -> list[str]:
    """ "A on P before B or C goes on Q": A's group, then B's and C's ("or" after "before" waits for each
    of them). Only a "before" inside a clause, not one that opens it ("Before X, Y" puts Y first) or
    refers back ("before that")."""
    pieces = BEFORE.split(part)
    for i in range(1, len(pieces)):
        names = list(pattern.finditer(pieces[i]))
        for left, right in reversed(list(zip(names, names[1:], strict=False))):
            if re.fullmatch(r"\s+or\s+(?:the\s+|a\s+|an\s+)?", pieces[i][left.end() : right.start()]):
                pieces[i] = pieces[i][: left.end()] + " and " + pieces[i][left.end() + 4 :].lstrip()
    return pieces


def _shared_heads(by_words: dict[str, str]) -> dict[str, list[str]]:
    """Head nouns that several objects share ("apple": green apple, red apple); plates are not counted."""
    heads: dict[str, list[str]] = {}
    for words, t in sorted(by_words.items()):
        if not _is_plate(t):
            heads.setdefault(words.split()[-1], []).append(words)
    return {h: names for h, names in heads.items() if len(names) > 1}


def _name(found: str) -> str:
    return " ".join(found.split())


def _paired(types_in_order: list[str]) -> list[tuple[str, str]] | None:
    """Objects paired with their plate: runs of objects alternate with single plates, each run with the
    plate after it when the sentence starts with an object, before it when it starts with a plate."""
    runs: list[list[str]] = []
    for t in types_in_order:
        if runs and _is_plate(runs[-1][0]) == _is_plate(t):
            runs[-1].append(t)
        else:
            runs.append([t])
    runs = [r[:1] if _is_plate(r[0]) and len(set(r)) == 1 else r for r in runs]  # "on blue, the blue plate"
    runs = _topics_said_once(runs)
    if len(runs) % 2 or any(_is_plate(r[0]) and len(r) != 1 for r in runs):
        return None
    plate_first = bool(runs) and _is_plate(runs[0][0])
    out: list[tuple[str, str]] = []
    for i in range(0, len(runs), 2):
        objects, plate = (runs[i + 1], runs[i][0]) if plate_first else (runs[i], runs[i + 1][0])
        out += [(o, plate) for o in objects]
    return out


def _topics_said_once(runs: list[list[str]]) -> list[list[str]]:
    """In a text that starts with a plate, a plate named again right after its objects is the same topic,
    not the next one ("the yellow plate comes first: the green apple and the orange go on it", "the blue
    plate ends up with the green apple on it and the yellow plate with the orange")."""
    if not runs or not _is_plate(runs[0][0]):
        return runs
    out: list[list[str]] = []
    for run in runs:
        if _is_plate(run[0]) and len(out) >= 2 and _is_plate(out[-2][0]) and run[0] == out[-2][-1]:
            run = run[1:]
        if run and out and _is_plate(out[-1][0]) == _is_plate(run[0]):
            out[-1] = out[-1] + run
        elif run:
            out.append(run)
    return out


def _is_plate(type_name: str) -> bool:
    return type_name.endswith("Plate")
