"""Step 4a, drafts: the frames of each sentence -> task drafts (consecutive clauses about one object, a
list of objects sharing one verb as a group) and temporal units (the tasks of one clause + their markers)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.clauses import Clause, expand_gapping, split_clauses
from nl2hltl2plan.language.grammar.draft_tasks import Draft, TaskBuilder, Unit
from nl2hltl2plan.language.grammar.frames import (
    APPLIANCE_OF,
    IN_SENTENCE,
    OF_ALL,
    Frame,
    Item,
    dest_of,
    frame_unread,
    item_text,
    parse_frame,
    puts_into,
    same,
    treats_another_object,
)
from nl2hltl2plan.language.grammar.lamp_phrases import carried_then_lit
from nl2hltl2plan.language.grammar.listed_things import merge_items, ordinal_of_a_list, split_last_own_place
from nl2hltl2plan.language.grammar.phrases import NP, one_of_each_under_a_shared_plural, tokens
from nl2hltl2plan.language.grammar.sentences import Sentence
from nl2hltl2plan.language.grammar.subordinate import ends_treating_it, treatment_after
from nl2hltl2plan.language.statements import WHERE_COPULA


@dataclass
class Drafts:
    """The result of step 4a: drafts, units (draft indices) and the words that state each group."""

    drafts: list[Draft] = field(default_factory=list)
    units: list[Unit] = field(default_factory=list)
    group_text: dict[int, str] = field(default_factory=dict)


@dataclass
class _SentenceState:
    """What the clauses of one sentence share while they are read."""

    sentence: Sentence
    first_unit: int
    drafts: list[int] = field(default_factory=list)
    prev_clause_tasks: list[int] = field(default_factory=list)
    # "put things into the upper rack, first X, then Y": a shared destination for the clauses that follow
    context: list[tuple[str, NP]] = field(default_factory=list)
    context_group: int = -1
    pending_joiner: str = ""
    next_clause: Clause | None = None  # the clause after the one being read


class DraftBuilder:
    """Reads sentence after sentence; the verb and destination of the last clause carry over to a verbless
    sentence that follows ("Then the tomato")."""

    def __init__(self, b: TaskBuilder) -> None:
        self.b = b
        self.out = Drafts()
        self.next_group = -1
        self.gap_groups: dict[int, int] = {}  # Clause.gap -> group
        self.last_verb = ""
        self.last_dest = ""

    def add_sentence(self, s: Sentence) -> None:
        """Read the clauses of one sentence into drafts and units, then apply the sentence's markers."""
        said = split_clauses(s.body)
        # "the knife is in the sink": a statement, not a request (set aside before gapping lends it a verb)
        statements = [c for c in said if states_where(c[0])]
        self.b.unparsed += [c[0] for c in statements]
        requests = [c for c in said if c not in statements]
        clauses = expand_gapping(requests, self.last_verb, self.last_dest, gap_base=100 * s.index)
        st = _SentenceState(s, len(self.out.units))
        for k, clause in enumerate(clauses):
            st.next_clause = clauses[k + 1] if k + 1 < len(clauses) else None
            self._add_clause(clause, st)
        self._apply_markers(st)

    def _new_group(self, text: str) -> int:
        self.next_group += 1
        self.out.group_text[self.next_group] = text
        return self.next_group

    def _add_clause(self, clause: Clause, st: _SentenceState) -> None:
        """One clause -> its frame; its items continue the last draft or start new ones (one unit)."""
        treated = treatment_after(clause.text) if clause.joiner == "after" and st.drafts else None
        if treated is not None:
            # "put the tomato in the fridge after heating it in the microwave": the state of the task before
            # (its appliance is where that state is made, no destination)
            self.out.drafts[st.drafts[-1]].frames.append((treated, Item(treated.items[0].obj)))
            return
        fr = parse_frame(clause.text, st.sentence.offset + clause.start, clause.joiner)
        if fr.cls not in {"none", "other"}:
            self.last_verb = clause.text.split()[0]
            for it in fr.items:
                dst = dest_of(it, fr.cls)
                self.last_dest = next((f"{p} {np.text}" for p, np in it.pps if np is dst), self.last_dest)
        joiner = clause.joiner or st.pending_joiner
        st.pending_joiner = ""
        if self._skip(fr, clause.text, st):
            return
        if all(it.obj is not None and it.obj.generic for it in fr.items):
            # a heading about generic things ("place items into the dishwasher"): its destination is the
            # context of the clauses that follow in this sentence, which form a group
            st.context = [(p, np) for it in fr.items for p, np in it.pps if p in G.DEST_PREPS]
            st.context_group = self._new_group(fr.text)
            st.pending_joiner = joiner
            return
        self._share_destinations(fr, st)
        if fr.cls == "slice":
            self._knife_is_a_tool(st)
        group = self._group_of(clause, fr, st)
        new_tasks = [t for it in fr.items if (t := self._add_item(fr, it, clause, joiner, group, st)) >= 0]
        if new_tasks:
            unit = Unit(tasks=new_tasks, sentence=st.sentence.index, joiner=joiner)
            if joiner == "then" and st.prev_clause_tasks:
                unit.seq_after_prev = True
            if joiner == "first":
                unit.markers.append((G.FIRST, ""))
            if joiner == "finally":
                unit.markers.append((G.FINALLY, IN_SENTENCE))
            self.out.units.append(unit)
            st.prev_clause_tasks = new_tasks

    def _skip(self, fr: Frame, c_text: str, st: _SentenceState) -> bool:
        """Clauses that state no task of ours (listed in `unparsed` when they name a real object)."""
        unparsed = self.b.unparsed
        if fr.cls == "none":
            if not st.drafts or any(
                it.obj is not None and not it.obj.empty and not it.obj.pronoun for it in fr.items
            ):
                unparsed.append(c_text)
                return True
        if why := frame_unread(fr, c_text):
            unparsed.append(why)
            return True
        last = self.out.drafts[st.drafts[-1]] if st.drafts else None
        if carried := carried_then_lit(fr, last, st.next_clause):
            unparsed.append(f"{c_text} ({carried})")
            return True
        if fr.cls == "light" and not any(
            (it.obj is not None and it.obj.is_lamp()) or any(np.is_lamp() for _, np in it.pps)
            for it in fr.items
        ):
            if not any(it.obj is not None and it.obj.pronoun for it in fr.items):
                fr.cls = "other"  # "switch on the coffee machine": no lamp, no task of ours
        if fr.cls == "other":
            real = [
                it.obj for it in fr.items if it.obj is not None and not it.obj.empty and not it.obj.pronoun
            ]
            noise = (
                fr.verb in {"open", "close", "shut"}
                and st.drafts
                and all(o.is_receptacle() or "door" in o.text.lower() for o in real)
            )
            if real and not noise:
                unparsed.append(c_text)
            return True  # "close the refrigerator door", "while doing so"
        return False

    def _share_destinations(self, fr: Frame, st: _SentenceState) -> None:
        """Items without a destination take the heading's (context) or the next one stated in the list."""
        if st.context:
            for it in fr.items:
                if it.obj is not None and not any(p in G.DEST_PREPS for p, _ in it.pps):
                    it.pps.extend(st.context)
        if len(fr.items) > 1:  # "the apple and the egg in the fridge, and the mug in the sink": next place
            last = fr.items[-1]
            shared = [(p, np) for p, np in last.pps if p in G.DEST_PREPS and not _content_it(last, np)]
            for it in reversed(fr.items[:-1]):
                own = [(p, np) for p, np in it.pps if p in G.DEST_PREPS and not _content_it(it, np)]
                shared = own or shared
                it.pps.extend([] if own else shared)
            one_of_each_under_a_shared_plural([it.obj for it in fr.items])
            fr.items = self._without_slicing_knife(fr)
            fr.items = merge_items(fr.items, self.b)

    def _knife_is_a_tool(self, st: _SentenceState) -> None:
        """ "pick up apple, pick up knife, cut apple": the knife picked up just before slicing is the tool;
        the clauses that follow continue the draft before it."""
        if not st.drafts:
            return
        d = self.out.drafts[st.drafts[-1]]
        if (
            d.obj is not None
            and d.obj.entry is not None
            and d.obj.entry.canonical in G.KNIVES
            and all(f.cls == "pick" and dest_of(it, f.cls) is None for f, it in d.frames)
        ):
            d.tool = True
            st.drafts.pop()

    def _without_slicing_knife(self, fr: Frame) -> list[Item]:
        """A knife listed with something sliceable is the tool that sliced it, not a task (noted)."""

        def canonical(it: Item) -> str:
            return it.obj.entry.canonical if it.obj is not None and it.obj.entry is not None else ""

        def place_of(it: Item) -> str:
            return dst.text.lower() if (dst := dest_of(it)) is not None else ""

        items = self._content_without_slicing_knife(fr)
        if not any(canonical(it) in G.SLICEABLE for it in items):
            return items
        cut_to = {place_of(it) for it in items if canonical(it) in G.SLICEABLE} | {""}
        # "the apple in the bin and the knife in the fridge": a knife sent somewhere of its own is moved
        knives = [it for it in items if canonical(it) in G.KNIVES and place_of(it) in cut_to]
        for it in knives:
            assert it.obj is not None
            self.b.issues.append(f"{it.obj.text!r} in {fr.text!r} is read as the tool that slices")
        return [it for it in items if it not in knives]

    def _content_without_slicing_knife(self, fr: Frame) -> list[Item]:
        """ "a pan with a tomato slice and a knife in it", "a pot containing a knife and a slice of potato":
        a knife listed with a slice in a container's content is the tool that cut it; the slice is the
        content (the items after the container continue its content list)."""
        items = fr.items
        if len(items) != 2 or items[1].obj is None or any(p in G.WITH_PREPS for p, _ in items[1].pps):
            return items
        holder, listed = items[0], items[1].obj
        held = [(k, np) for k, (p, np) in enumerate(holder.pps) if p in G.WITH_PREPS]
        if len(held) != 1:
            return items
        k, content = held[0]
        knife, cut = (listed, content) if _is_knife(listed) else (content, listed)
        if not _is_knife(knife) or cut is None or not cut.sliced or not _canonical_in(cut, G.SLICEABLE):
            return items
        holder.pps[k] = (holder.pps[k][0], cut)
        self.b.issues.append(f"{knife.text!r} in {fr.text!r} is read as the tool that slices")
        return [holder]

    def _group_of(self, clause: Clause, fr: Frame, st: _SentenceState) -> int:
        """The group of the clause's tasks: an elided-verb list, a heading, a list of objects; else -1."""
        if clause.gap >= 0:
            if clause.gap not in self.gap_groups:
                self.gap_groups[clause.gap] = self._new_group(clause.whole)
            return self.gap_groups[clause.gap]
        if st.context_group >= 0:
            return st.context_group
        if len(fr.items) > 1:
            return self._new_group(fr.text)
        return -1

    def _add_item(
        self, fr: Frame, it: Item, clause: Clause, joiner: str, group: int, st: _SentenceState
    ) -> int:
        """Attach one clause item to the sentence's last draft (-1) or start a new draft (its index)."""
        drafts = self.out.drafts
        if ordinal_of_a_list(it, drafts, st.drafts, self.b, clause.text):
            return -1
        d = drafts[st.drafts[-1]] if st.drafts else None
        if d is not None and d.obj is not None and it.obj is not None and _another_of_it(it.obj, d):
            # "put a toilet paper on the counter, then another one in the cabinet": a task of its own
            it.obj = replace(d.obj, text=it.obj.text, count=1, plural=False)  # one, after "two sets of keys"
            d = None
        if d is not None and it.obj is not None and it.obj.pronoun and _placed_again(d, fr, it):
            it.obj, d = d.obj or it.obj, None  # "put the remote on the sofa, then put it on the armchair"
        listed = _group_for_them(drafts, st.drafts, it)
        if listed and len(fr.items) == 1 and joiner not in {"first", "finally"}:
            # "wash a rag and a bar of soap and put them (both) in a drawer": each thing of the group is put
            for k in listed:
                drafts[k].frames.append((fr, it))
                drafts[k].end = fr.end
                drafts[k].label += f" and {fr.text}" if drafts[k].label else ""  # its text says the place
            return -1
        nxt, at = st.next_clause, st.sentence.offset
        if (
            d is not None
            and len(fr.items) == 1
            and _continues(d, fr, it, joiner)
            and not (nxt and treats_another_object(fr, nxt.text, at + nxt.start, nxt.joiner, d.obj))
        ):
            d.frames.append((fr, it))
            d.end = fr.end
            return -1
        if (
            d is None
            and drafts
            and not incomplete(drafts[-1])
            and not _in_its_appliance(drafts[-1])
            and it.obj is not None
            and it.obj.pronoun
            and fr.cls not in {"light", "none"}
        ):
            # "Put the mug in the sink. Then put it in the coffee machine.": "it" is the object of the
            # finished task of the sentence before, and this is a task of its own
            it.obj = drafts[-1].obj or it.obj
        label = clause.label if len(fr.items) == 1 else ""
        if len(fr.items) > 1 or st.context:
            label = item_text(fr, it)
        drafts.append(Draft(frames=[(fr, it)], start=fr.start, end=fr.end, group=group, label=label))
        st.drafts.append(len(drafts) - 1)
        return len(drafts) - 1

    def _unordered(self, units: list[Unit]) -> bool:
        """No order word opens the sentence and every task is of a group: a closing free phrase frees none."""
        return units[0].markers == [] and all(self.out.drafts[t].group >= 0 for u in units for t in u.tasks)

    def _apply_markers(self, st: _SentenceState) -> None:
        """Leading markers apply to all units of the sentence; trailing "then"/"finally" to the last."""
        units = self.out.units
        sentence_units = units[st.first_unit :]
        if not sentence_units:
            return
        one_list = len(sentence_units) == 1
        if one_list and (rest := split_last_own_place(st.sentence, units[-1], self.out.drafts)):
            units.append(rest)  # its own unit, ordered by the loop below ("A and B afterwards")
            sentence_units.append(rest)
        _refuse_free_and_ordered(st.sentence, sentence_units)
        if _one_task_in_any_order(st.sentence, sentence_units, self.out.drafts):
            why = "('in any order', but its clauses read as one task)"
            self.b.unparsed.append(f"{st.sentence.text.strip()} {why}")
        for kind, ref in st.sentence.markers:
            for u in sentence_units:
                u.markers.append((kind, ref))
        one = len(sentence_units) == 1 and not _CLOSING_TIME.search(st.sentence.text.rstrip(" .!?;"))
        for kind, ref in st.sentence.trailing:
            if kind == G.FIRST and ends_treating_it(st.sentence.body):
                continue  # "..., but wash it first": before the placing of "it", which its task's kind says
            if kind in {G.THEN, G.FINALLY} and len(sentence_units) > 1:
                # "A and B afterwards": B after the clause before it, as "A, then B"
                sentence_units[-1].seq_after_prev |= kind == G.THEN
                sentence_units[-1].markers.append((kind, IN_SENTENCE if kind == G.FINALLY else ref))
            elif kind == G.FREE and one and len(sentence_units[0].tasks) > 1:
                pass  # "move the phone and the bat to the bed in any order": order inside the group is free
                # ("put salt and pepper in the cabinet at any time" frees each task: not `one`)
            elif kind == G.FREE and _frees_last(st.sentence, sentence_units, self._unordered(sentence_units)):
                # "After that, A, and B whenever you like": the sequence word is A's, "whenever" frees B alone
                last = sentence_units[-1]
                last.markers = [m for m in last.markers if m not in st.sentence.markers] + [(kind, ref)]
            elif kind == G.FREE and len(sentence_units) > 1 and self._unordered(sentence_units):
                pass
            elif kind in {G.AFTER_REF, G.AFTER_ALL} and st.first_unit == 0 and G.THE_REST_DONE.match(ref):
                sentence_units[-1].markers.append((kind, ref))  # "A, and B when the rest is done": B after A
            else:
                # "put the apple in the fridge last": after every other task, those written after it too
                of_all = kind == G.FINALLY and len(sentence_units) == 1
                for u in sentence_units:
                    u.markers.append((kind, OF_ALL if of_all else ref))


# a closing phrase that leaves the order of the sentence's tasks to the robot (not "at any time": a time)
_ORDER_IS_FREE = re.compile(
    r"\b(?:(?:any|whatever|no\s+(?:particular|specific|set))\s+(?:order|sequence)|order\s+is\s+(?:up\s+to\s+you|"
    r"your\s+call|yours\s+to\s+choose)|in\s+parallel|simultaneously|concurrently)\W*$",
    re.IGNORECASE,
)


_SEQUENCE = frozenset({G.THEN, G.AFTER_ALL, G.AFTER_REF})


def _frees_last(sentence: Sentence, units: list[Unit], unordered: bool) -> bool:
    """Does a closing "whenever" free the last clause alone (an opening order word reaching the ones before it
    only)? Yes after a sequence word ("After that, A, and B whenever"), or, in a sentence with an order (not
    `unordered`), where the last clause is one task joined by "and" ("A, and B at any time. Then C")."""
    if len(units) < 2 or _CLOSING_TIME.search(sentence.text.rstrip(" .!?;")) is None:
        return False
    last = units[-1]
    if any(k in _SEQUENCE for k, _ in sentence.markers):
        return True
    return not unordered and last.joiner == "and" and len(last.tasks) == 1 and not last.seq_after_prev


# a closing phrase that frees a time, not an order ("whenever you like", "at any point"; not "in whatever
# order you like")
_CLOSING_TIME = re.compile(
    r"\b(?:at\s+(?:any|whatever|some)\s+(?:time|point)|any\s*time|whenever|at\s+your\s+(?:convenience|leisure))\b"
    r"(?![^.;!?]*\b(?:order|sequence)\b)[^.;!?]*$",
    re.IGNORECASE,
)


def _refuse_free_and_ordered(sentence: Sentence, units: list[Unit]) -> None:
    """ "A and then B, the order is yours to choose": the closing phrase frees the clause that "then" (or
    "finally") has just ordered; which one the user means is a guess, so it is refused as "then ... in
    reverse order" is. ("A, then B, and C and D in any order" frees the last clauses only, and "A, and
    then B and C in any order" the group of the last clause.)"""
    last = units[-1]
    ordered = len(units) > 1 and (last.seq_after_prev or any(kind == G.FINALLY for kind, _ in last.markers))
    ordered = ordered and len(last.tasks) == 1
    free = any(kind == G.FREE for kind, _ in sentence.trailing) and _ORDER_IS_FREE.search(sentence.text)
    if ordered and free:
        raise HTTError(
            f"contradictory ordering in the instruction: {sentence.text.strip()!r} orders its tasks and "
            "leaves their order free; say which"
        )


_ANY_ORDER = re.compile(r"\b(?:any|whatever|no\s+(?:particular|specific|set))\s+(?:order|sequence)\W*$", re.I)


def _one_task_in_any_order(sentence: Sentence, units: list[Unit], drafts: list[Draft]) -> bool:
    """ "Rinse a cup and put it away and rinse the cup and put it away in any order": the order of what is
    one task cannot be free; the clauses were joined into one task that the writer meant as several."""
    if len(units) != 1 or len(units[0].tasks) != 1 or not _ANY_ORDER.search(sentence.text):
        return False
    return len(drafts[units[0].tasks[0]].frames) > 1


_COPULA_PLACE = re.compile(rf"\b{WHERE_COPULA}\s+(?:in|on|inside|into|onto|at|under|by)\s", re.IGNORECASE)


def states_where(clause: str) -> bool:
    """A clause with no verb of ours that says where a thing is ("the knife is in the sink", "the moment the
    fork is on the table"): it states no task, and reading it as a placement would be a guess."""
    words = tokens(clause)
    return bool(words) and words[0][0] not in G.VERBS and _COPULA_PLACE.search(clause) is not None


def _continues(d: Draft, fr: Frame, it: Item, joiner: str) -> bool:
    """Does the single item of a clause continue draft `d` rather than start a task of its own?"""
    if joiner not in {"first", "finally"} and (
        joins(d, fr, it)
        or (
            incomplete(d)
            and fr.cls not in {"pick"}
            and it.obj is not None
            and (it.obj.pronoun or it.obj.empty)
        )
    ):
        return True
    return incomplete(d) and d.obj is None


# the pronouns that name every thing of a list said before ("them", "both of them", "each of them")
_THEM = frozenset("them|both|both of them|them both|all of them|them all|those|these|each|each one"
                  "|each of them|them each|each of those|each of these".split("|"))


def _group_for_them(drafts: list[Draft], mine: list[int], it: Item) -> list[int]:
    """The drafts of the sentence's last group (a list of things sharing a verb, each one still to be put
    somewhere) that a plural pronoun names; [] where it names no such list."""
    if it.obj is None or not it.obj.pronoun or it.obj.text.lower() not in _THEM or not mine:
        return []
    group = drafts[mine[-1]].group
    members = [k for k in mine if drafts[k].group == group] if group >= 0 else []
    # "wash a tomato and an egg in the sink and put them on the counter": each is still in its appliance
    still_open = [incomplete(drafts[k]) or _in_its_appliance(drafts[k]) for k in members]
    return members if len(members) > 1 and all(still_open) else []


def _another_of_it(o: NP, d: Draft) -> bool:
    """Is `o` "another one" / "another" / "the other one" after draft `d` has put its thing somewhere?"""
    return o.pronoun and o.text.lower() in {"another", "another one", "the other one"} and not incomplete(d)


def joins(d: Draft, fr: Frame, it: Item) -> bool:
    """Does clause item `it` continue task draft `d` (same object, pronoun, no object, container)?"""
    o = it.obj
    last_fr = d.frames[-1][0]
    cur = d.obj
    if fr.joiner == "after" or fr.joiner == "before":
        return False
    if fr.cls == "light" and any(f.cls == "light" for f, _ in d.frames):
        return False  # a lamp switched on again ("turn on the desk lamp, and turn on the floor lamp with the
        # statue in hand"): one task has one light, so this is another task
    if o is None or o.empty:
        if fr.cls == "fill" and dest_of(it, fr.cls) is not None:
            return False  # "fill water in the bathtub": not about the current object
        return fr.cls != "none" or bool(it.pps)
    if o.pronoun:
        return not _placed_again(d, fr, it)
    if o.is_lamp() and (fr.cls in {"light", "examine"} or fr.light_on):
        return incomplete(d)  # "pick up the keys and turn on the lamp"; not after a placement
    if cur is None:
        held = [np for _, i in d.frames for p, np in i.pps if p in G.WITH_PREPS and not np.is_lamp()]
        if held:  # "turn a light on with a bat in hand": the bat is the task's object
            return same(o, held[0])
        # the draft so far only switched a lamp on: "turn on a lamp while holding a laptop"
        return fr.cls in {"pick", "examine"} or (fr.cls == "place" and last_fr.cls == "light")
    if same(o, cur):
        if fr.cls == last_fr.cls == "place" and same(dest_of(it, fr.cls), dest_of(d.frames[-1][1], fr.cls)):
            return False  # the placement said again, no wash ("... in the sink, and put the cup in the sink")
        # a task that is done ("a clean mug under the coffee maker") and a clause that names the object again
        # with a destination of its own ("a warm mug in the cabinet"): a second task on another one; so is
        # "a" tomato after one was put somewhere (an indefinite article introduces another referent)
        # and so is one treated again once done ("rinse a soap and put it in the drawer, then rinse the pink
        # soap and drop it in the tub": h300's line 99 moved the first soap to the tub)
        again = _done(d) and fr.cls in APPLIANCE_OF and any(f.cls == fr.cls for f, _ in d.frames)
        return not (((_done(d) or (_placed(d) and _indefinite(o))) and _restates(fr, it)) or again)
    if puts_into(cur, fr, it):
        # "look at the box under the lamp, then put the keys in it": the box looked at is a new task's holder
        return not any(f.cls in {"light", "examine"} or f.light_on for f, _ in d.frames)
    if o.sliced and o.entry is None and o.head in {"", "slice", "piece"}:
        return True
    if _placed(d) and _indefinite(o) and _restates(fr, it):
        return False  # "put a glass with a fork in it on the table, then wash a dirty fork": another fork
    for (
        _,
        it2,
    ) in d.frames:  # the container of the content: "put a spoon in a mug and put the mug on the table"
        dst = dest_of(it2)
        if dst is not None and same(o, dst) and o.is_movable_receptacle():
            return True
        for p, np in it2.pps:
            if p in G.WITH_PREPS and same(o, np):
                return True
    if last_fr.cls in {"slice"} and (o.sliced or any(p in G.WITH_PREPS and np.sliced for p, np in it.pps)):
        return True  # "slice a tomato and put a pot with a tomato slice in it on the table": the slice cut
    return False


def _content_it(it: Item, np: NP) -> bool:
    """Is `np` the "it" of a content said ("a mug with a spoon in it"): no place of the item's own?"""
    return np.pronoun and any(p in G.WITH_PREPS for p, _ in it.pps)


def _canonical_in(np: NP | None, types: set[str] | frozenset[str]) -> bool:
    return np is not None and np.entry is not None and np.entry.canonical in types


def _is_knife(np: NP | None) -> bool:
    return _canonical_in(np, G.KNIVES)


def _done(d: Draft) -> bool:
    """Has draft `d` reached its end: an object examined under a lamp, or put down at a final place (not
    the appliance of a state it still needs: a cooked tomato put into the sink is done, a mug is not)?"""
    fr, it = d.frames[-1]
    if fr.cls in {"light", "examine", "trash"} or fr.light_on:
        return True  # ("throw it away": the garbage can is a final place)
    dest = dest_of(it, fr.cls)
    if dest is None or dest.entry is None or dest.entry.canonical not in APPLIANCE_OF.values():
        return dest is not None
    states = {f.cls for f, _ in d.frames}
    states |= {s for _, i in d.frames if i.obj is not None for s in i.obj.states}
    states &= set(APPLIANCE_OF)
    return bool(states) and all(APPLIANCE_OF[s] != dest.entry.canonical for s in states)


def _placed_again(d: Draft, fr: Frame, it: Item) -> bool:
    """ "put the remote on the sofa, then put it on the armchair" / "then look at it under the lamp": a thing
    put down at a final place, then put elsewhere ("then", "next") or examined: each a task of its own. A
    first place that is a treatment's appliance (the sink) or a clause with no sequence word joins."""
    last_fr, last_it = d.frames[-1]
    first = dest_of(last_it, last_fr.cls)
    if d.obj is None or d.obj.plural or (first is not None and first.is_movable_receptacle()):
        return False  # "put the pencils in the mug, then put it ...": "it" is (or may be) the holder
    if re.search(r"\b(?:back|return|returns)\b", fr.text, re.I):
        return False  # "then put it back (where it was)": the place it was taken from (`put_back`)
    return (fr.cls == "examine" and _placed(d)) or (  # no base task both places and examines
        fr.joiner == "then"
        and fr.cls == last_fr.cls == "place"
        and _done(d)
        and dest_of(it, fr.cls) is not None
        and not same(dest_of(it, fr.cls), dest_of(last_it, last_fr.cls))
    )


def _placed(d: Draft) -> bool:
    """Has draft `d` put its object somewhere (its last clause names a destination)?"""
    fr, it = d.frames[-1]
    return dest_of(it, fr.cls) is not None or fr.cls == "trash"


def _indefinite(o: NP) -> bool:
    """ "a tomato", "another mug", "the other mug", "two sets of keys" (a number, no "the"): a referent
    other than the one before."""
    words = o.text.lower().split()
    return words[:1] in (["a"], ["an"], ["another"], ["two"], ["three"]) or words[:2] == ["the", "other"]


def _restates(fr: Frame, it: Item) -> bool:
    """Does a clause name its object anew with a task of its own: a destination ("a warm mug in the cabinet",
    "a clean mug under the coffee maker"), or "grab a credit card", "examine a credit card"?"""
    o = it.obj
    if o is None or o.pronoun:
        return False
    if dest_of(it, fr.cls) is not None or fr.cls == "examine":
        return True
    if any(p in G.DEST_PREPS and np.is_receptacle() for p, np in it.pps) and fr.cls != "pick":
        return True
    return _indefinite(o)


def _in_its_appliance(d: Draft) -> bool:
    """ "Heat the potato in the microwave.": the place is the treatment's appliance, the task goes on."""
    fr, it = d.frames[-1]
    dst = dest_of(it, fr.cls)
    return dst is not None and dst.entry is not None and dst.entry.canonical == APPLIANCE_OF.get(fr.cls)


def incomplete(d: Draft) -> bool:
    """A draft that only picked / changed the state of something: the next clause usually completes it."""
    for fr, it in d.frames:
        if dest_of(it, fr.cls) is not None or fr.cls in {"light", "examine", "trash"} or fr.light_on:
            return False
    return True
