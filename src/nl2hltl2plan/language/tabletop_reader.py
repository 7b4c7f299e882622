"""The tabletop world's reader hook (`world_readers.WorldReader`; issue 28): the shared grammar reads first,
and this hook prepares the instruction for it, reads again with the pairs reading (`tabletop_pairs`) what
the grammar refuses or reads in part, checks a full reading against the pairs reading, and names every
thing a reading leaves unused."""

from __future__ import annotations

import re
from collections import Counter

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.content_words import Unread
from nl2hltl2plan.language.frame_filler import frame_note
from nl2hltl2plan.language.grounding import camel_words
from nl2hltl2plan.language.questions import answered
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.tabletop_chat import chat_read
from nl2hltl2plan.language.tabletop_dialogue import dialogue_read, scenario_read
from nl2hltl2plan.language.tabletop_fields import fields_read
from nl2hltl2plan.language.tabletop_freed_steps import steps_named
from nl2hltl2plan.language.tabletop_headings import (
    stage_headings_read,
    task_headings_unread,
)
from nl2hltl2plan.language.tabletop_lines import bracketed_list_opened, lines_joined, names_spelt, stops_read
from nl2hltl2plan.language.tabletop_order import (
    PLACE_IN_THE_WHOLE,
    end_opener_read,
    ordinal_things_read,
    robot_addressed,
    turn_phrases_read,
)
from nl2hltl2plan.language.tabletop_pairs import (
    ALTERNATIVES,
    ENTRIES,
    ORDER_MATTERS,
    ORDER_SAID,
    PRIORITY,
    RATHER_THAN,
    RELATION_VERB,
    TURNED_ROUND,
    is_plate,
    read_pairs,
    shared_heads,
    tabletop_fallback,
)
from nl2hltl2plan.language.tabletop_remarks import role_dropped
from nl2hltl2plan.language.tabletop_spelling import misspelt_order_words, names_respelt, order_words_spelt
from nl2hltl2plan.language.tabletop_steps import labels_out_of_turn, numbered_steps
from nl2hltl2plan.language.tabletop_waits import plate_waits_read
from nl2hltl2plan.language.tabletop_wording import (
    corrected,
    mention_pattern,
    moving_idioms_read,
    stated_not_asked,
)
from nl2hltl2plan.language.task_specs import transitive_closure
from nl2hltl2plan.worlds.world import World


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
        kinds = {camel_words(t): is_plate(t) for t in self.world.object_types()}
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
        kinds = {camel_words(t): is_plate(t) for t in self.world.object_types()}
        stated = stated_not_asked(instruction, kinds)
        if stated is not None:
            raise HTTError(
                f"'{stated}' says where something is, not what to do: ask for it (\"put ...\", \"make sure "
                "... is on ...\") or leave it out"
            )
        if entry := ENTRIES.search(instruction.lower()):
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
            name = " ".join(found[0].split())
            type_ = by_words.get(name) or by_words.get(name.removesuffix("s"))
            if type_ is not None and type_ not in used:
                kind = "place" if is_plate(type_) else "object"
                out[name] = Unread(name, kind, f"no base task uses it ({type_})")
        placed = Counter(o for task in res.tasks for o in task.object)
        for type_ in (t for t, n in placed.items() if n > 1):  # "I hate oranges" read as a placement too
            why = "placed by two tasks: a thing ends on one plate, and which one is meant is not said"
            out[camel_words(type_)] = Unread(camel_words(type_), "object", why)
        if (labels := labels_out_of_turn(res.instruction.lower())) is not None:
            out[labels] = Unread(labels, "order", "steps numbered out of turn")
        for found in ORDER_MATTERS.finditer(res.instruction.lower()):
            why = "it says that the order matters, not which order: say it with first / then"
            out[found[0]] = Unread(found[0], "order", why)
        for found in RELATION_VERB.finditer(res.instruction.lower()):
            why = "an order between placements that this reading does not take"
            out[found[0]] = Unread(found[0], "order", why)
        for found in TURNED_ROUND.finditer(res.instruction.lower()):
            why = "it may turn round what was asked: say what is meant"
            out[found[0]] = Unread(found[0], "negation", why)
        for phrase, why in task_headings_unread(res.instruction, len(res.tasks)):  # "Three things:" and two
            out[phrase] = Unread(phrase, "count", why)
        for word in misspelt_order_words(res.instruction):
            out[word] = Unread(word, "order", "it may misspell an order word: which one is not guessed")
        for found in RATHER_THAN.finditer(res.instruction.lower()):
            out[found[0]] = Unread(found[0], "negation", "what is not wanted is no placement: leave it out")
        for found in ALTERNATIVES.finditer(res.instruction.lower()):
            out[found[0]] = Unread(found[0], "condition", "alternatives: which one is meant is not said")
        for found in ENTRIES.finditer(res.instruction.lower()):
            why = "entries of a list: whether their numbers are steps in turn is not said"
            out[found[0]] = Unread(found[0], "order", why)
        lowered = res.instruction.lower()
        said = [*ORDER_SAID.finditer(lowered), *PRIORITY.finditer(lowered)]
        said += PLACE_IN_THE_WHOLE.finditer(lowered)
        for found in said if not res.before else ():
            why = "it says an order (a wait, what follows, a priority, a sorting) and the reading has none"
            out[found[0]] = Unread(found[0], "order", why)
        return list(out.values())


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
    heads, modifiers = shared_heads(by_words), {w for n in by_words for w in n.split()[:-1]}
    words = re.findall(r"[a-z]+", instruction.lower())
    alone = {w.removesuffix("s") for i, w in enumerate(words) if i == 0 or words[i - 1] not in modifiers}
    used = [h for h in heads if h in alone]
    if not used:
        return ""
    said = "; ".join(" and ".join(f"the {n}" for n in heads[h]) for h in used)
    return f" ({world.name} has {said})"
