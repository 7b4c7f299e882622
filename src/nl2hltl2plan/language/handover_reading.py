"""The language stage on the four-arm handover worlds (paper Section IV-C, Table III).

`translate_handover(instruction, world)` reads an instruction about the blocks and regions of a
`handover-square` / `handover-line` world and returns the same `LanguageResult` as the other
worlds (HTT, base tasks, `before`, leaf formulas, the hierarchical spec) plus `constraints`: the
guards and joint goals as text, sorted. The frame around the commands (a greeting, a sign-off, a
label, reported speech: `language.handover_discourse`) is dropped; each sentence is normalised and its
phrases are resolved against the instance's layout (`language.handover_phrases`, word tables in
`handover_words`), and its statements that are not commands (scene, target, need, question) are read
and checked (`language.handover_clauses`); its orders, touch guards and prohibitions are read first
(`language.handover_rules`), then its goal clauses (`language.handover_goals`); this module builds the
task tree and the spec. The rules, each general:

- a goal clause "VERB BLOCKS [back] to PLACE" gives one leaf per block: `F(at(B,R1) | at(B,R2) ...)`
  (the opposite side: per block; any empty region: `away(B)`; where another block starts: `@B`);
  "fill R with BLOCKS" is the same (as many regions as blocks); "exchange the positions of X and Y"
  ("while swapping their positions") gives `F at(X,@Y)` and `F at(Y,@X)`;
- a clause that moves several blocks to lasting places also asks for them there at once (a leaf
  `F(state_1 & state_2 ...)`), unless it says "one after another" or its places hold fewer blocks than
  it moves ("at any time" frees the goals' time, not the place they end in);
- "X should be placed / gets placed / comes before Y" orders X's goal before Y's; "X first" puts X
  before the other blocks of the latest clause that moves it with others; "first ..., then ..."
  makes one node of the steps in order; "after all of these, ..." makes one node of everything said
  so far and puts the new goal after it; orders in a cycle are refused;
- "the arm cannot touch X until it touched Y" guards X's goal: `(!pick(X) U pick(Y)) & ...`;
- "no block can be placed on R (during this period)" and "cannot be placed on the area other than the
  target region" guard every goal of the sentence (or, in a sentence of its own, every goal so far)
  until it is met: `(!drop(R) & ...) U state` (a plan ends when its last goal is met, so this is
  "never" for the plan's whole run);
- "each region holds one object", "separately": the world's own rule (a cell holds one block);
- a clause whose goals another clause of the same sentence also gives is read once ("place the red
  block on the opposite side before the blue block, and get all three blocks across");
- goals of one block per clause to one set of as many regions, under the one-block rule ("red -> G/H/I,
  blue -> G/H/I, yellow -> G/H/I; one per region"), are read at once, as one clause says it.
Clauses are kept in the sentence's order; "but" is read only before a rule. Every word is read or is
a filler; anything else is refused, naming the words. Where these forms refuse, the form-independent
reading of `handover_cues` says each refused sentence again from what its words name and relate, and the
instruction is read once more (`_restated`).
"""

from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass, field

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_answers import answered, fragments_joined, timing_joined
from nl2hltl2plan.language.handover_closing import check_closing, closing_said
from nl2hltl2plan.language.handover_cues import restate
from nl2hltl2plan.language.handover_discourse import plain
from nl2hltl2plan.language.handover_goals import Clause, Goal, crossed_exchanges, goal_clauses, lead
from nl2hltl2plan.language.handover_layout import (
    HEADED,
    REORDERED,
    block_bullets_read,
    later_read,
    nested_read,
    places_then_count_read,
    prohibitions_read,
    transcript_read,
    until_all_there_read,
    verb_heading_read,
)
from nl2hltl2plan.language.handover_phrases import drop_but, mark
from nl2hltl2plan.language.handover_rules import (
    Prohibition,
    read_leaders,
    read_orders,
    read_prohibitions,
    read_touch_guards,
)
from nl2hltl2plan.language.handover_scene import FILLER, Marked, Place, Scene
from nl2hltl2plan.language.handover_steps import flat_steps, refuse_unordered, scattered_joint
from nl2hltl2plan.language.handover_words import MOD
from nl2hltl2plan.language.headings import answered as labelled_answers
from nl2hltl2plan.language.htt import HTT, HTTNode
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_reduction
from nl2hltl2plan.worlds.world import World


@dataclass
class Item:
    """A node of the task tree being built: a goal leaf, a joint ('at once') leaf, or a group."""

    text: str
    goal: Goal | None = None
    joint: list[Goal] | None = None
    children: list[Item] = field(default_factory=list)
    before: list[tuple[int, int]] = field(default_factory=list)

    def goals(self) -> list[Goal]:
        if self.goal is not None:
            return [self.goal]
        return [g for c in self.children for g in c.goals()]


def translate_handover(instruction: str, world: World) -> LanguageResult:
    """Instruction -> LanguageResult on a handover world (see the module docstring); a line break in it ends
    a step as a full stop does. Where the form reader refuses, each sentence it cannot read alone is said
    again from its cues (`handover_cues.restate`) and the whole is read once more (`_restated`). Questions
    and answers labelled "Q:" / "A:" are first said as the instruction they state (`headings.answered`,
    every world's; a question it does not know is refused by name)."""
    instruction = labelled_answers(instruction)
    try:
        return _read_forms(instruction, world)
    except HTTError as refusal:
        result = _restated(instruction, world)
        if result is None:
            raise refusal from None
        return result


def _restated(instruction: str, world: World) -> LanguageResult | None:
    """The instruction read with every sentence that the form reader refuses alone said again from its cues;
    a sentence both readers read alone must give the same spec both ways (else None: refused). The result
    keeps the instruction's own words."""
    scene = Scene.of(world)
    said: list[str] = []
    previous: Marked | None = None
    said_alone = timing_joined(fragments_joined(plain(_sentences(answered(instruction)))))
    sentences = _slashes_split(said_alone, world)
    try:
        for sentence in sentences:
            previous = mark(sentence, scene, previous)
            again = restate(previous, scene)
            alone = _spec_or_none(sentence, world)
            if again is not None and alone is not None and alone != _spec_or_none(again, world):
                return None  # the two readings disagree
            said.append(sentence if alone is not None or again is None else again)
        if said == sentences:  # nothing said again: the form reader's refusal stands
            return None
        result = _read_forms(". ".join(said) + ".", world)
    except HTTError:
        return None
    text = " ".join(instruction.split())
    first = result.htt.nodes[0]
    root = first.model_copy(update={"text": text}) if first.text == result.instruction else first
    htt = result.htt.model_copy(update={"instruction": text, "nodes": [root, *result.htt.nodes[1:]]})
    return result.model_copy(update={"instruction": text, "htt": htt})


def _slashes_split(sentences: list[str], world: World) -> list[str]:
    """A sentence the form reader refuses alone is split at slashes with spaces around them, as at
    semicolons ("3 blocks to the opposite side / red before blue"); one it reads stays whole."""
    out: list[str] = []
    for sentence in sentences:
        parts = re.split(r"\s+/\s+", sentence)
        out += parts if len(parts) > 1 and _spec_or_none(sentence, world) is None else [sentence]
    return out


def _spec_or_none(sentence: str, world: World) -> str | None:
    """The sentence's reading alone, words aside: its tree, leaf formulas and constraints."""
    try:
        r = _read_forms(sentence, world)
    except HTTError:
        return None
    return repr(([(n.id, n.children) for n in r.htt.nodes], r.htt.relations, r.leaf_specs, r.constraints))


def _read_forms(instruction: str, world: World) -> LanguageResult:
    scene = Scene.of(world)
    clauses: list[Clause] = []
    orders: list[tuple[str, str]] = []
    touches: list[tuple[str, str]] = []
    notes: list[str] = []
    pending: list[Prohibition] = []  # prohibitions stated before any goal
    previous: Marked | None = None  # the sentence before ("it", "these regions" in the next one)
    steps, closing = closing_said(timing_joined(fragments_joined(plain(_sentences(answered(instruction))))))
    instruction = " ".join(instruction.split())
    for sentence in steps:
        m = mark(sentence, scene, previous)
        previous = m
        notes += m.notes
        forbids = read_prohibitions(m)
        touches += read_touch_guards(m)
        sentence_orders = read_orders(m)
        orders += sentence_orders
        # "red goes first, blue after red": the order says what "first" means
        leaders = [b for b in read_leaders(m) if b not in [x for x, _ in sentence_orders]]
        new = _said_before(_without_restated(goal_clauses(m, scene)), clauses)
        if not new:  # "Step 2: the red block before the blue block", "1) red before blue": rules only
            m.sub(r"^\s*(?:then|first)\b", " ")
        drop_but(m)
        _refuse_leftovers(m, sentence)
        scope = [g for c in new for g in c.goals] or [g for c in clauses for g in c.goals]
        for blocks, place, explicit, text in forbids:
            if scope:
                _guard(scope, blocks, place, explicit, scene, text)
            else:
                pending.append((blocks, place, explicit, text))
        clauses = crossed_exchanges(clauses + new, orders)
        for block in leaders:
            lead(clauses, block)
    clauses = _distributed(clauses, notes)
    orders += [(c.leader, g.block) for c in clauses if c.leader for g in c.goals if g.block != c.leader]
    if not clauses:
        raise HTTError(f"no goal for a block in {instruction!r} (say where each block goes)")
    goals = [g for c in clauses for g in c.goals]
    check_closing(closing, {g.block for g in goals}, scene.blocks)
    swapped = {b for g in goals if g.place.block and not g.regions for b in (g.block, g.place.block)}
    if sum(g.block in swapped for g in goals) > len(swapped):  # where is "its position" then: start or goal?
        raise HTTError("an exchanged block also has another goal: which positions are exchanged?")
    for blocks, place, explicit, text in pending:
        _guard(goals, blocks, place, explicit, scene, text)
    for x, y in touches:
        _first_goal(goals, x).touch_guard.append(y)
    _refuse_cyclic(orders)
    _refuse_misplaced_markers(clauses)
    root = _tree(clauses)
    if joint := scattered_joint(clauses, scene.blocks):
        root.children, root.before = flat_steps([*root.children, _joint(joint)], root.before)
    for x, y in orders:
        _order(root, _first_goal(goals, x), _first_goal(goals, y))
    refuse_unordered(root, [g for c in clauses if c.anytime for g in c.goals])
    return _result(world.name, instruction, root, goals, notes)


def _without_emoji_and_tags(text: str) -> str:
    """A pictograph (an emoji, a symbol of Unicode's 'other symbol' class, with its joiners and variation
    selectors) ends a sentence as a full stop does ("Move the blocks 🙂 Red first"); a hashtag ("#robots")
    is the message's label and carries no task (a number after '#', "#3", stays)."""
    text = re.sub(r"(?<![\w#])#[A-Za-z]\w*", " ", text)
    if not any(_pictograph(c) for c in text):
        return text
    out = "".join(". " if _pictograph(c) else "" if c in "\u200d\ufe0f" else c for c in text)
    return re.sub(r"(?:\.\s*){2,}", ". ", out)  # a run of pictographs is one break


def _slashes_read(text: str) -> str:
    """Letters joined by slashes list regions or arms ("H/I/J" is "H, I and J", "arms a/b" "arms a and b");
    a count after its noun is the noun's count ("blocks (x3)" is "3 blocks"). (A slash between clauses is read
    by the fallback: `_slashes_split`.)"""
    letters = r"\b[A-Ja-j](?:\s*/\s*[A-Ja-j]\b)+"
    text = re.sub(letters, lambda m: _listed(re.sub(r"\s*/\s*", ", ", m[0])), text)
    text = re.sub(r"\b(blocks|pillars|objects|cubes|items)\s*\(?\s*[x×]\s*(\d)\b\s*\)?", r"\2 \1", text)
    return text


def _pictograph(c: str) -> bool:
    return ord(c) > 0x7F and unicodedata.category(c) in ("So", "Sk")  # not "^" or "`" (ASCII, class Sk)


def _sentences(instruction: str) -> list[str]:
    """Split at line breaks (a list of steps or bullets), '.', ';', '!' and '?', but not in 'i.e.' nor after a
    step's number ('1. Put ...', also after a colon); a bullet ('-', '*', '•') starting a line or sentence is
    dropped. A heading ending in a colon is joined to the line below it, and a record of labelled fields,
    on lines or in sentences and in either order ('Blocks: ...' and 'Targets: ...'), is read as one goal."""
    out: list[str] = []
    instruction = nested_read(transcript_read(prohibitions_read(instruction)))
    instruction = places_then_count_read(verb_heading_read(block_bullets_read(instruction)))
    instruction = until_all_there_read(instruction)
    # a record of labelled fields, on lines or in sentences, in either order: "Blocks: red, blue, yellow"
    # then "Targets: H, I, J" (or "Regions: G, H and I. Objects: all three.") is one goal
    for record in _RECORDS:
        instruction = record.sub(_record_as_goal, instruction)
    # a heading that ends in a colon goes on in the bullet below it: "Place the blocks on:\n- G, H and I"
    # (after a preposition the colon only ends the line)
    bullet = r"[ \t]*\n\s*(?:[-*•·]|\d[.)])\s+"
    instruction = re.sub(rf"(?m)\b(on|onto|in|into|to|at)\s*:{bullet}", r"\1 ", instruction)
    instruction = re.sub(rf"(?m):{bullet}", ": ", instruction)
    instruction = re.sub(r"(?m):[ \t]*\n\s*(?=\S)", ": ", instruction)  # a heading on a line of its own
    instruction = _unquoted(re.sub(r"\*\*|__", "", instruction))  # markdown's bold: "**Goal:** ..."
    for line in instruction.splitlines():
        text = re.sub(r"(^\s*|[.;!?:]\s+)(\d)\.\s", r"\1\2) ", line)
        text = re.sub(r"\b[iI]\.\s?[eE]\.", "that is", text)
        text = re.sub(r"\b[nN]\.\s?[bB]\.?\s*:?", "NB:", text)  # "N.B. red goes first": a note's label
        text = re.sub(r"\b(?:[pP]\.\s?)+[sS]\.\s*:?", "PS:", text)  # "P.S. red goes first": a postscript
        text = re.sub(r"\b(opp|approx|resp)\.(?=\s)", r"\1", text, flags=re.IGNORECASE)  # "opp. side"
        # an open checklist box is a bullet (a ticked one says what is done, and is left unread)
        text = re.sub(r"^\s*(?:\[\s*\]|☐)\s*", "- ", text)
        text = _slashes_read(_without_emoji_and_tags(text))
        for pattern, replacement in (*REORDERED, *HEADED):
            text = pattern.sub(replacement, text)
        out += [re.sub(r"^\s*[-*•·]\s+", "", s) for s in re.split(r"[.;!?]+(?:\s|$)", text)]
    return later_read(_without_announcement([s for s in out if s.strip()]))


# "There are a few things to keep in mind." before the things: it names no block, place or order; a
# number of things must be the number of sentences after it (else it stays, to be refused by name)
_ANNOUNCED = re.compile(
    r"^\s*there\s+(?:are|is)\s+(a\s+few|a\s+couple\s+of|some|several|two|three|four)\s+"
    r"(?:things|points|rules|requirements|conditions)(?:\s+here|\s+to\s+(?:keep|bear)\s+in\s+mind|\s+to\s+"
    r"(?:remember|note))?\s*:?\s*$",
    re.IGNORECASE,
)
_NUMBERS = {"two": 2, "three": 3, "four": 4}


def _without_announcement(sentences: list[str]) -> list[str]:
    said = _ANNOUNCED.match(sentences[0]) if sentences else None
    if said is None or _NUMBERS.get(said[1].lower(), len(sentences) - 1) != len(sentences) - 1:
        return sentences
    return sentences[1:]


def _unquoted(instruction: str) -> str:
    """The instruction without the quotation marks around a command quoted whole ('The note says: "Put
    ..."'): double quotes anywhere; a single quote that opens the instruction or follows a colon, and then
    one that closes a word ("blocks' places": the possessive's mark, which the reader drops anyway)."""
    text = re.sub(r"[\"“”]", "", instruction)
    if re.search(r"(?:^|:)\s*['‘]", text):
        text = re.sub(r"((?:^|:)\s*)['‘](?=\w)", r"\1", text)
        text = re.sub(r"(?<=[\w.!?])['’](?=[.!?,;]?(?:\s|$))", "", text)
    return text


_BLOCKS_FIELD = (
    r"\s*(?:[-*•·]\s+)?(?:blocks?|objects?|pillars?|items?|pieces?|cubes?|what|move|place|put|transfer|carry|bring)"
    r"\s*:\s*(?P<blocks>[^\n:.;]+?)\s*"
)
_PLACES_FIELD = (
    r"\s*(?:[-*•·]\s+)?(?:targets?|destinations?|(?:goal|target|placement)\s+(?:regions?|areas?)|target\s+area|"
    r"where(?:\s+to)?|regions?|places?|to|onto|into)\s*:\s*(?P<places>[^\n:.;]+?)\s*"
)
_FIELD_BREAK = r"(?:[.;]?[ \t]*\n|[.;][ \t]+)"  # a line break or a sentence's end between two fields
_FIELD_END = r"(?=[.;!?]?[ \t]*(?:\n|$)|[.;!?][ \t])"
_RECORDS = tuple(
    re.compile(rf"(?im)(?P<start>^|[.;!?][ \t]+){first}{_FIELD_BREAK}{second}{_FIELD_END}")
    for first, second in ((_BLOCKS_FIELD, _PLACES_FIELD), (_PLACES_FIELD, _BLOCKS_FIELD))
)


def _record_as_goal(fields: re.Match[str]) -> str:
    """The record's goal; a modifier of the blocks' field is said after the places ("place: three blocks,
    one after another" and "to: region I": "three blocks to region I, one after another")."""
    blocks = fields["blocks"]
    mods = found[0] if (found := re.search(rf"(?:\s*,\s*{MOD})+$", blocks)) else ""
    return f"{fields['start']}{_listed(blocks[: len(blocks) - len(mods)])} to {fields['places']}{mods}"


def _listed(items: str) -> str:
    """'red, blue, yellow' -> 'red, blue and yellow' (a record's list: its last comma is its 'and')."""
    return items if re.search(r"\band\b", items) else re.sub(r",\s*([^,]+)$", r" and \1", items)


def _without_restated(clauses: list[Clause]) -> list[Clause]:
    """A sentence's clause whose every goal another clause of it also gives (same block, same place; no
    step marker on either) restates it: 'place the red block on the opposite side before the blue
    block, and get all three blocks to the opposite regions' moves red once."""

    def key(g: Goal) -> tuple[str, str, tuple[str, ...], str]:
        return (g.block, g.place.kind, g.regions, g.place.block)

    out = list(clauses)
    for c in clauses:
        others = [d for d in out if d is not c and not d.marker]
        given = {key(g) for d in others for g in d.goals}
        if not c.marker and others and all(key(g) in given for g in c.goals):
            out.remove(c)
    return out


def _said_before(new: list[Clause], clauses: list[Clause]) -> list[Clause]:
    """A clause that gives again goals an earlier sentence gave ('The pillars belong on E, F and G. Move them
    there, ...') is read once; said again with another step marker or timing, it is refused (which one
    holds?)."""

    def key(c: Clause) -> set[tuple[str, str, tuple[str, ...], str]]:
        return {(g.block, g.place.kind, g.regions, g.place.block) for g in c.goals}

    out: list[Clause] = []
    for c in new:
        same = [d for d in clauses if key(c) <= key(d)]
        if not same:
            out.append(c)
            continue
        d = same[-1]
        # (one goal is never "at once": its `together` says nothing)
        moved_apart = len(c.goals) > 1 and c.together != d.together
        if c.marker or d.marker or moved_apart or (c.anytime, c.leader) != (d.anytime, d.leader):
            raise HTTError(f"'{c.text}' gives again a goal said before ('{d.text}') otherwise: which holds?")
    return out


def _distributed(clauses: list[Clause], notes: list[str]) -> list[Clause]:
    """'red -> G, H or I; blue -> G, H or I; yellow -> G, H or I; one per region': goals of one block each,
    all to one set of as many regions as there are goals, under the one-block rule, ask for the blocks
    there at once, as 'the three blocks to G, H and I, one per region' does: one clause."""
    regions = {g.regions for c in clauses for g in c.goals if g.place.kind == "regions"}
    plain = all(len(c.goals) == 1 and not (c.marker or c.anytime or c.together or c.leader) for c in clauses)
    ruled = any(n.startswith("one block per region") for n in notes)
    blocks = {c.goals[0].block for c in clauses}
    if not (plain and ruled and len(regions) == 1 and len(clauses) > 1):
        return clauses
    if not all(c.goals[0].place.kind == "regions" for c in clauses):
        return clauses
    if not len(blocks) == len(clauses) == len(next(iter(regions))):
        return clauses
    text = "; ".join(c.text for c in clauses)
    return [Clause(goals=[c.goals[0] for c in clauses], text=text, together=True)]


def _refuse_leftovers(m: Marked, sentence: str) -> None:
    unused = [m.block_text[int(k)] for k in re.findall(r"\bB(\d+)\b", m.text)]
    unused += [_unmarked(m.places[int(k)].text, m) for k in re.findall(r"\bP(\d+)\b", m.text)]
    words = [w for w in re.findall(r"[A-Za-z']+\d*|\d+", m.text) if w not in FILLER]
    words = [w for w in words if not re.fullmatch(r"[BPG]\d+|A", w)]
    if unused or words:
        what = ", ".join(repr(x) for x in unused + words)
        raise HTTError(f"the handover parser cannot use {what} in {sentence.strip()!r}; rephrase it")


def _unmarked(text: str, m: Marked) -> str:
    """A place's words with the blocks marked in them written as they were said ("where it is", never the
    marker "where  B2  is")."""
    said = re.sub(r"\bB(\d+)\b", lambda b: m.block_text[int(b[1])], text)
    return " ".join(said.split())


def _guard(
    goals: list[Goal], blocks: list[str], place: Place | None, explicit: list[str], scene: Scene, text: str
) -> None:
    every = not blocks or set(blocks) == set(scene.blocks)
    for g in goals:
        if explicit:
            regions = explicit
        elif place is not None and place.regions:  # "any region except E, F and G"
            regions = [r for r in scene.layout.regions if r not in place.regions]
        else:
            if g.place.kind not in ("regions", "opposite"):
                raise HTTError(f"'{text}': the goal '{g.text}' has no target regions to except")
            regions = [r for r in scene.layout.regions if r not in g.regions]
        for r in regions:
            g.drop_guard.update({f"drop({r})"} if every else {f"put({b},{r})" for b in blocks})


def _refuse_misplaced_markers(clauses: list[Clause]) -> None:
    """'Finally, put yellow on G. First, put it on I.': a step said out of the text's order is not modelled
    (the tree follows the text), so it is refused rather than read without its order: 'first' after other
    goals that no 'then' follows, 'finally' / 'after all of these' before any goal."""
    for k, c in enumerate(clauses):
        follows = k + 1 < len(clauses) and clauses[k + 1].marker == "then"
        if c.marker == "first" and k > 0 and not follows:
            raise HTTError(f"'{c.text}' comes first, but is said after other goals: say the steps in order")
        if c.marker == "after_all" and k == 0 and len(clauses) > 1:
            raise HTTError(f"'{c.text}' comes last, but is said before other goals: say the steps in order")


def _refuse_cyclic(orders: list[tuple[str, str]]) -> None:
    """'red before blue' and 'blue before red' (or 'red before itself'): no plan can keep both."""
    graph = nx.DiGraph(orders)
    if not nx.is_directed_acyclic_graph(graph):
        cycle = [x.lower() for x, _ in nx.find_cycle(graph)]
        raise HTTError(f"the instruction orders the blocks in a cycle: {' before '.join([*cycle, cycle[0]])}")


def _first_goal(goals: list[Goal], block: str) -> Goal:
    mine = [g for g in goals if g.block == block]
    if not mine:
        raise HTTError(f"the instruction orders or guards the {block.lower()} block but gives it no goal")
    if len(mine) > 1:
        raise HTTError(f"the {block.lower()} block has {len(mine)} goals: which one is ordered?")
    return mine[0]


# ----- the task tree ----------------------------------------------------------------------------------
def _items(c: Clause) -> list[Item]:
    items = [Item(f"{g.block.lower()} block to {g.where()}", goal=g) for g in c.goals]
    return items + ([_joint(c.goals)] if c.together else [])


def _joint(goals: list[Goal]) -> Item:
    said = ", ".join(f"{g.block.lower()} on {g.where()}" for g in goals)
    return Item(f"at once: {said}", joint=list(goals))


def _unit(c: Clause) -> Item:
    items = _items(c)
    return items[0] if len(items) == 1 else Item(c.text, children=items)


def _tree(clauses: list[Clause]) -> Item:
    root = Item("")
    chain: Item | None = None
    prev: Clause | None = None
    closed = False  # the last step was ordered after all before it
    for c in clauses:
        if c.marker == "then" and prev is not None:
            if chain is None:
                n_prev = len(_items(prev))
                root.children = root.children[:-n_prev]
                chain = Item(prev.text, children=[_unit(prev)])
                root.children.append(chain)
            chain.children.append(_unit(c))
            chain.before.append((len(chain.children) - 2, len(chain.children) - 1))
            chain.text += "; " + c.text
        elif c.marker == "after_all" and root.children:
            if any(d.anytime for d in clauses[: clauses.index(c)]):  # "after all of these" would order them
                raise HTTError("'after all of these' ('once that is done') orders goals said 'at any time'")
            old = root.children[0] if len(root.children) == 1 else root
            root = Item("", children=[old])
            root.children += _items(c)
            root.before += [(0, k) for k in range(1, len(root.children))]
            chain = None
            closed = True
        else:
            if closed:  # a goal said after the steps that "after all of these" ordered: beside them, as one
                root = Item("", children=[root])
                closed = False
            root.children += _items(c)
            chain = None
        prev = c
    return root


def _order(root: Item, a: Goal, b: Goal) -> None:
    def visit(item: Item) -> bool:
        kids = [c.goal for c in item.children]
        if a in kids and b in kids:
            item.before.append((kids.index(a), kids.index(b)))
            return True
        return any(visit(c) for c in item.children)

    if not visit(root):
        raise HTTError(f"cannot order {a.text!r} before {b.text!r}: they belong to different steps")


def _result(scene: str, instruction: str, root: Item, goals: list[Goal], notes: list[str]) -> LanguageResult:
    if len(root.children) == 1:
        root = root.children[0]
    nodes: list[HTTNode] = []
    relations: list[tuple[str, str]] = []
    leaf_specs: dict[str, str] = {}
    goal_leaf: dict[int, str] = {}  # id(goal) -> its HTT leaf

    def add(item: Item, node_id: str, text: str) -> None:
        if not item.children:
            nodes.append(HTTNode(id=node_id, text=text))
            if item.goal is not None:
                goal_leaf[id(item.goal)] = node_id
                leaf_specs[node_id] = item.goal.leaf()
            else:
                leaf_specs[node_id] = "F(" + " & ".join(g.state() for g in item.joint or []) + ")"
            return
        kids = [f"{node_id}.{k}" for k in range(1, len(item.children) + 1)]
        nodes.append(HTTNode(id=node_id, text=text, children=kids))
        relations.extend((kids[i], kids[j]) for i, j in item.before)
        for kid, child in zip(kids, item.children, strict=True):
            add(child, kid, child.text)

    add(root, "1", instruction)
    htt = HTT(instruction=instruction, nodes=nodes, relations=relations)
    letter = {id(g): task_letter(k) for k, g in enumerate(goals)}
    tasks = [
        BaseTaskSpec(
            id=letter[id(g)],
            text=g.text,
            kind="place",
            object=[f"{g.block}Block"],
            receptacle=[f"Region{r}" for r in g.regions] or [g.where()],
        )
        for g in goals
    ]
    task_node = {letter[id(g)]: goal_leaf[id(g)] for g in goals}
    return LanguageResult(
        backend="offline",
        instruction=instruction,
        scene=scene,
        htt=htt,
        tasks=tasks,
        before=transitive_reduction(_task_pairs(root, letter), [t.id for t in tasks]),
        task_node=task_node,
        leaf_task={v: k for k, v in task_node.items()},
        leaf_specs=dict(leaf_specs),
        spec=build_spec(htt, action_completion=lambda node: leaf_specs[node.id]),
        constraints=_constraints(root, goals, notes),
    )


def _task_pairs(item: Item, letter: dict[int, str]) -> set[tuple[str, str]]:
    """Base-task precedence: every goal under an earlier sibling before every goal under a later one."""
    out = {
        (letter[id(a)], letter[id(b)])
        for i, j in item.before
        for a in item.children[i].goals()
        for b in item.children[j].goals()
    }
    return out.union(*(_task_pairs(c, letter) for c in item.children))


def _constraints(root: Item, goals: list[Goal], notes: list[str]) -> list[str]:
    """The guards and joint goals as text, sorted (the canonical order of `plan --json`)."""
    out = set(notes) | set(_joint_texts(root))
    for g in goals:
        out.update(f"{g.block.lower()} is not picked up before {y.lower()} is" for y in g.touch_guard)
        if g.drop_guard:
            out.add(f"until {g.block.lower()} is on {g.where()}: none of {', '.join(sorted(g.drop_guard))}")
    return sorted(out)


def _joint_texts(item: Item) -> list[str]:
    own = [item.text] if item.joint else []
    return own + [t for c in item.children for t in _joint_texts(c)]  # `_constraints` sorts them
