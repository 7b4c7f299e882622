"""A deterministic grammar-based parser: instruction -> base tasks + temporal relations.

Pipeline (no model involved), one module per step, chained by `parse_instruction`:

1. sentences (`sentences.py`): split on `.`, `;`, `!`, `?`; strip leading markers ("Then,", "Finally,",
   "After placing the statue,", "In any order,", "First,") and trailing ones ("at any time", "first",
   "afterwards", "after moving the X") and record them;
2. clauses (`clauses.py`): split a sentence before each verb that follows a joiner ("and", ",", "then",
   "to", ...); restore elided verbs ("first the saucers, then the cups, in the upper rack");
3. frames (`frames.py`; noun phrases in `phrases.py`): per clause the verb class and its noun phrases with
   their prepositions (object, destination, source, "with X in it", "by the light of a lamp"), the state
   words (washed, heated, chilled, sliced), counts ("two", plurals);
4. tasks: consecutive clauses about the same object ("it", "them", the same noun, the container) form
   one draft, several objects sharing one verb ("the phone and the bat") a group (`drafts.py`); each
   draft becomes a grounded base task (`tasks.py`);
5. references (`references.py`): "after placing the statue" -> the task about the statue;
6. relations (`relations.py`): the ANNOTATION_GUIDE rules ("Then Y" after the previous clause, "Finally Y"
   after every earlier task not allowed at any time, "After X-ing the Z, Y" after the task about Z,
   "first", "prior to that", "after completing the previous tasks"), transitively reduced.

Whatever cannot be read this way is listed in `unparsed` instead of being guessed.
"""

from __future__ import annotations

from pydantic import BaseModel, Field

from nl2hltl2plan.language.grammar.draft_tasks import TaskBuilder, build_tasks
from nl2hltl2plan.language.grammar.drafts import DraftBuilder
from nl2hltl2plan.language.grammar.listed_things import name_apart_across
from nl2hltl2plan.language.grammar.order_relations import relate
from nl2hltl2plan.language.grammar.put_back import back_where_belongs, put_back_where_taken
from nl2hltl2plan.language.grammar.sentences import normalize, read_sentences
from nl2hltl2plan.language.grounding import AffordanceLookup, Grounder, alfred_lookup
from nl2hltl2plan.language.result import Ambiguity
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter


class OfflineParse(BaseModel):
    """What the offline parser understood: base tasks, `before` pairs, groups, and what it could not read."""

    instruction: str
    tasks: list[BaseTaskSpec] = Field(default_factory=list)
    before: list[tuple[str, str]] = Field(default_factory=list)
    groups: list[list[str]] = Field(default_factory=list)
    group_texts: list[str] = Field(default_factory=list)  # the words that state each group
    unparsed: list[str] = Field(default_factory=list)
    issues: list[str] = Field(default_factory=list)
    # words several scene types fit, ranked (the learned backend ranks them; the grammar alone reports none)
    ambiguities: list[Ambiguity] = Field(default_factory=list)
    # sentences a reading left out that name nothing a task needs (check 1 found no content word in them):
    # said in the result's assumptions, never dropped silently (h299)
    frames: list[str] = Field(default_factory=list)


def parse_instruction(
    instruction: str,
    types: set[str] | frozenset[str] | None = None,
    scene: str = "the scene",
    strict: bool = False,
    affordances: AffordanceLookup | None = None,
) -> OfflineParse:
    """Parse one instruction. `types`: the scene's object types (None: keep the words, no grounding).

    With `strict=True` a word whose type is not in the scene raises `WorldError` ("no Statue in
    FloorPlan17"); otherwise it is kept with its most plausible type and listed in `issues`.
    `affordances` (type -> `Affordances` or None when unknown; default: ALFRED's facts when the shared data
    is there) narrows a word with several types to those that can play their role (`grounding.Roles`).
    """
    # "put it back": where the sentence said the things belong, or where they were taken from
    text = put_back_where_taken(normalize(back_where_belongs(instruction)))
    grounder = Grounder(types, scene) if types is not None else None
    if types is not None and affordances is None:
        affordances = alfred_lookup()
    b = TaskBuilder(grounder, strict, affordances)
    read = read_sentences(text)
    drafting = DraftBuilder(b)
    for sentence in read.sentences:
        drafting.add_sentence(sentence)
    drafts = drafting.out
    name_apart_across(drafts.drafts, grounder)
    tasks = build_tasks(drafts.drafts, drafts.units, b, text)
    before = relate(tasks, read.relations, b, text, instruction)
    groups = {g: members for g, members in tasks.groups.items() if len(members) > 1}
    return OfflineParse(
        instruction=instruction,
        tasks=tasks.specs,
        before=before,
        groups=[[task_letter(i) for i in members] for members in groups.values()],
        group_texts=[drafts.group_text.get(g, "") for g in groups],
        unparsed=b.unparsed,
        issues=b.issues,
    )
