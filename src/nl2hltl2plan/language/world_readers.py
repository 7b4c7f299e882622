"""Each world's own reading around the shared grammar: one hook per kind of world (`World.kind`).

`translate` asks `world_reader(world)` at eight points (all but `unused` in the offline backends only),
and knows no world by name:

- `own_reading`: the world reads the whole instruction itself (the handover worlds, `handover_reading`);
- `as_read`: the instruction's lines as the one line the readers read (the tabletop world reads a line
  break by what the lines name and spells names as it does, `tabletop_lines`; the household and tabletop
  worlds read questions and answers as the instruction they state, `questions.answered`; elsewhere the
  lines are joined with spaces);
- `prepared`: the text as the shared grammar is to read it, or a refusal (the tabletop world refuses a
  statement of where something is and applies corrections first, `tabletop_reader`);
- `reread`: the world's reading of an instruction the grammar refused or read only in part (the tabletop
  world's pairs reading); it reads no negation, so it is asked only of an instruction without one;
- `refusal`: the grammar's refusal with what the world adds to it (the tabletop world names the objects a
  word could mean);
- `doubted`: the grammar's full reading with what the world's own reading says against it (the tabletop
  world: its pairs reading, where it reads the instruction too and differs, makes the result partial);
- `unused`: what check 1 adds for the world, for every backend (the tabletop world: a named object or
  plate that no base task uses, since nothing there can be a landmark);
- `notes`: what `prepared` read as another word, said among the result's assumptions (the household
  worlds: "read 'kettle' as 'watering can'", `household_words`).

A world kind with no reading of its own gets `SharedGrammar`, which changes nothing. A world's reader is
imported only when that world is read (the handover reader's pattern tables cost ~25 ms to load).

>>> from nl2hltl2plan.worlds.demo import demo_world
>>> world_reader(demo_world()).prepared("put the apple in the fridge")
'put the apple in the fridge'
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Protocol

from nl2hltl2plan.language.content_words import Unread, vocabulary
from nl2hltl2plan.language.courtesy import (
    courtesy_unread,
    without_apologies,
    without_framing,
    without_greetings,
    without_patter,
    without_reasons,
)
from nl2hltl2plan.language.frame_drops import frames_dropped, thing_signed
from nl2hltl2plan.language.frame_filler import frame_note
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.headings import heading_dropped, heading_note, note_counts, row_labels_dropped
from nl2hltl2plan.language.household_forms import household_forms
from nl2hltl2plan.language.household_words import contents_hint, descriptive_name_notes, descriptive_names
from nl2hltl2plan.language.landmarks import put_away_unread
from nl2hltl2plan.language.learned.request_units import frames_classified
from nl2hltl2plan.language.negation_forms import instead_said, untouched_said, untreated_said
from nl2hltl2plan.language.negations import exclusions_unread, unmoved_said
from nl2hltl2plan.language.numbered_steps import orders_by_label, step_order
from nl2hltl2plan.language.questions import answered
from nl2hltl2plan.language.request_times import (
    deadline_note,
    deadlines_dropped,
    later_days_unread,
    starts_unread,
)
from nl2hltl2plan.language.respectively import distributed
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.self_corrections import corrected, household_roles, in_own_words
from nl2hltl2plan.language.unknown_words import thing_alone
from nl2hltl2plan.worlds.world import World


class WorldReader(Protocol):
    """The reading one world adds to the shared grammar (see the module docstring)."""

    def own_reading(self, instruction: str) -> LanguageResult | None:
        """The world's whole reading (a line break in `instruction` ends a step), or None: the shared
        grammar reads it."""
        ...

    def as_read(self, lines: list[str]) -> str:
        """The instruction's lines (each one line of words) as the one line the readers read."""
        ...

    def prepared(self, instruction: str) -> str:
        """The instruction as the shared grammar is to read it; raises HTTError to refuse it."""
        ...

    def reread(self, instruction: str, backend: str) -> LanguageResult | None:
        """The world's reading of an instruction (with no negation) that the grammar refused or read in
        part, or None: the grammar's result stands."""
        ...

    def refusal(self, refused: Exception, instruction: str, prepared: str, rest: str) -> Exception:
        """The grammar's refusal of `instruction`, with what the world adds to it. `prepared`: the text
        `prepared` gave; `rest`: that text without its negated clauses, as the grammar read it."""
        ...

    def doubted(self, res: LanguageResult, backend: str) -> LanguageResult:
        """The grammar's full reading (of an instruction with no negation), with what the world's own
        reading says against it in `unparsed` (two readings that differ: neither is taken)."""
        ...

    def unused(self, res: LanguageResult) -> list[Unread]:
        """What check 1 is to add for this world: words of the instruction the reading leaves unused
        that only this world knows to be content (every backend's reading is judged so)."""
        ...

    def notes(self, instruction: str) -> list[str]:
        """What `prepared` read as another word, as assumptions of the reading ("read 'x' as 'y'")."""
        ...


class SharedGrammar:
    """The reader of a world with no reading of its own: the shared grammar as it is."""

    def own_reading(self, instruction: str) -> LanguageResult | None:
        return None

    def as_read(self, lines: list[str]) -> str:
        return " ".join(lines)

    def prepared(self, instruction: str) -> str:
        return instruction

    def reread(self, instruction: str, backend: str) -> LanguageResult | None:
        return None

    def refusal(self, refused: Exception, instruction: str, prepared: str, rest: str) -> Exception:
        return refused

    def doubted(self, res: LanguageResult, backend: str) -> LanguageResult:
        return res

    def unused(self, res: LanguageResult) -> list[Unread]:
        return []

    def notes(self, instruction: str) -> list[str]:
        return []

    def read_off(self) -> list[Unread]:
        """What `as_read` read off the instruction (so the rest reads as said) that no task can honour
        ("..., tomorrow", the household's): check 1 is to add it, whichever reading is taken."""
        return []


def _names_a_thing(name: str) -> bool:
    return bool(find_mentions(name.lower()))


def _thing_words(text: str) -> frozenset[str]:
    """The words of `text` that name a thing of the household lexicon alone ("card", "clock") or a
    treatment ("rinsed"): a frame fragment with one is never dropped."""
    words = re.findall(r"[a-z]+", text.lower())
    # and a treatment said as a participle ("a bar of soap, rinsed, ..."): the verb's own word
    verbs = frozenset().union(*vocabulary().values())
    treated = {w for w in words if w.endswith("ed") and {w[:-1], w[:-2], w[:-3]} & verbs}
    # and a thing the lexicon lacks named alone ("The giraffe."): kept for check 1 to name, h307
    alone = {w for s in re.split(r"(?<=[.!?])\s+", text) if (w := thing_alone(s))}
    return frozenset(w for w in words if find_mentions(w)) | treated | alone


class _HouseholdReader(SharedGrammar):
    """The household (ALFRED) floor plans: the shared grammar, with "Q: ... A: ..." read as the
    instruction the answers state (`questions.answered`), greetings and thanks dropped
    (`courtesy.without_greetings`), what names nothing a task needs dropped as frame by every reader's
    rule (`frame_drops`: a note's name, label or time, "Liam, ...", "Today, please.", each said in the
    assumptions), colon lists, topic questions and treated "respectively" lists written out
    (`household_forms`), descriptive names read with the floor plan's types (`household_words`),
    self-corrections applied (`self_corrections.corrected`), "... respectively" lists written out
    (`respectively.distributed`) and an order said by step number applied (`numbered_steps.step_order`)."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.frames: list[str] = []  # what the general filler rule drops, for `notes`
        self.deadlines: list[str] = []  # the deadlines met by doing the tasks now, for `notes`
        self.headings: list[str] = []  # the headings `headings.heading_dropped` drops, for `notes`
        self.later_days: list[Unread] = []  # "..., tomorrow": read off with the frame, for `read_off`

    def as_read(self, lines: list[str]) -> str:  # greetings and thanks as every reader drops them; the
        # reasons a household request gives ("so it stays cold") ask for nothing (a tabletop "so that" states)
        said = without_patter(without_apologies(answered(" ".join(lines)), _names_a_thing)).strip()
        text = without_greetings(said, _names_a_thing)
        # labels an order sentence names ("Item 2 before item 1", "(1) A (2) B. Do (3) first.") number steps:
        # read once, before the strippers below take labels off, and left for `step_order` (h292)
        labels_ordered = orders_by_label(text)
        # a row's or an item's label ("Row 1 -", "item 3 -"): before the frame rule, which dropped some
        self.headings = []
        text = text if labels_ordered else row_labels_dropped(text, self.headings)
        self.frames = []
        # ("Night, Mug", "Later, Bread": a closing thing's name, taken out below and named unread, h307)
        self.later_days = later_days_unread(text) + thing_signed(text, _names_a_thing)
        text = frames_dropped(text, _thing_words(text), self.frames, times=True, closing_thing=_names_a_thing)
        self.deadlines = []
        text = deadlines_dropped(text, _thing_words(text), self.deadlines, self.frames)
        # a heading whose name is a thing's ("Prep card:", "Lamp game:"): the frame rule keeps thing words
        text = heading_dropped(text, self.headings)
        # what the rules above leave that a learned classifier is sure is a voice's frame, naming nothing
        # check 1 asks about (h287)
        text = frames_classified(text, _thing_words(text), self.frames)
        # "Mom says put ...", "P.S.", "I was hoping you could"; "the mug stays put" is "don't move the mug"
        text = untreated_said(instead_said(without_framing(without_reasons(text), labels_ordered)))
        return unmoved_said(untouched_said(text))

    def prepared(self, instruction: str) -> str:
        named = descriptive_names(household_forms(instruction), set(self.world.object_types()))
        return distributed(corrected(step_order(named), household_roles(self.world)))

    def notes(self, instruction: str) -> list[str]:
        named = descriptive_name_notes(household_forms(instruction), set(self.world.object_types()))
        named += [deadline_note(self.deadlines)] if self.deadlines else []
        heads = [heading_note(self.headings)] if self.headings else []
        return [*named, frame_note(self.frames), *heads] if self.frames else [*named, *heads]

    def unused(self, res: LanguageResult) -> list[Unread]:
        """A note's heading that counts its jobs ("Kiddo, three jobs: ...", dropped with the framing around
        it) where the reading makes another number of base tasks (or of tasks and prohibitions, "two jobs:
        put the egg in the fridge, and don't put the mug in the sink"): the count was not understood."""
        n, forbids = len(res.tasks), len(res.constraint_specs)
        why = f"the heading counts them, and the reading makes {n} base task{'s' * (n != 1)}"
        counted = note_counts(res.instruction)
        unread = [Unread(h.phrase, "count", why) for h in counted if h.number not in {n, n + forbids}]
        # what no reading can tell: "Cheers, Mug", "Thanks for putting ...", "all but the mug" (h208)
        said = res.instruction
        # (a sign-off only the frame rule knows, "Night, Mug", is read off with the frame: `read_off`)
        unclear = [*courtesy_unread(said, _names_a_thing), *exclusions_unread(said), *put_away_unread(said)]
        read = " ".join(res.unparsed).lower()  # a start the parse already left unread is not said twice
        starts = [
            u for u in starts_unread(said, _thing_words(said))
            if u.words.lower().split(None, 1)[1] not in read
        ]
        return [*unread, *unclear, *starts]

    def read_off(self) -> list[Unread]:
        return self.later_days

    def refusal(self, refused: Exception, instruction: str, prepared: str, rest: str) -> Exception:
        hint = contents_hint(instruction)
        # quoted in the user's words, not as corrections, the household forms and a negation's "them" (the
        # things it named given back) rewrote them
        said = in_own_words(in_own_words(str(refused), rest, instruction), prepared, instruction)
        if said == str(refused) and not hint:
            return refused
        return type(refused)(f"{said}; {hint}" if hint else said)


class _HandoverReader(SharedGrammar):
    """The four-arm handover worlds read every instruction themselves (`handover_reading`)."""

    def __init__(self, world: World) -> None:
        self.world = world

    def own_reading(self, instruction: str) -> LanguageResult | None:
        from nl2hltl2plan.language.handover_reading import translate_handover

        return translate_handover(instruction, self.world)


def _tabletop_reader(world: World) -> WorldReader:
    from nl2hltl2plan.language.tabletop_reader import TabletopReader

    return TabletopReader(world)


# World.kind -> its reader; a kind not listed reads with the shared grammar alone
_READERS: dict[str, Callable[[World], WorldReader]] = {
    "alfred": _HouseholdReader,
    "handover": _HandoverReader,
    "tabletop": _tabletop_reader,
}


def world_reader(world: object) -> WorldReader:
    """The reader of `world` (a `World`, or a scene known only by its types: the shared grammar)."""
    if isinstance(world, World) and world.kind in _READERS:
        return _READERS[world.kind](world)
    return SharedGrammar()
