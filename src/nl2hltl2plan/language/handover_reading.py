"""The language stage on the four-arm handover worlds (paper Section IV-C, Table III).

`translate_handover(instruction, world)` reads an instruction about the blocks and regions of a
`handover-square` / `handover-line` world and returns the same `LanguageResult` as the other
worlds (HTT, base tasks, `before`, leaf formulas, the hierarchical spec) plus `constraints`: the
guards and joint goals as text, sorted. The frame around the commands (a greeting, a sign-off, a
label, reported speech: `language.handover_discourse`) is dropped; each sentence is normalised and its
phrases are resolved against the instance's layout (`language.handover_phrases`, word tables in
`handover_words`), and its statements that are not commands (scene, target, need, question) are read
and checked (`language.handover_clauses`); its orders, touch guards and prohibitions are read first
(`language.handover_rules`), then its goal clauses (`language.handover_goals`); this module gathers them
across sentences and checks them, `handover_sentences` splits the instruction into its sentences, and
`handover_tree` builds the task tree and the spec. The rules, each general:

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

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.frame_filler import frame_note
from nl2hltl2plan.language.handover_answers import answered, fragments_joined, timing_joined
from nl2hltl2plan.language.handover_closing import check_closing, closing_said
from nl2hltl2plan.language.handover_cues import restate
from nl2hltl2plan.language.handover_discourse import plain
from nl2hltl2plan.language.handover_goals import (
    Clause,
    Goal,
    crossed_exchanges,
    goal_clauses,
    lead,
    lead_later,
)
from nl2hltl2plan.language.handover_headers import headed
from nl2hltl2plan.language.handover_phrases import drop_but, mark
from nl2hltl2plan.language.handover_rules import (
    Prohibition,
    read_leaders,
    read_orders,
    read_prohibitions,
    read_touch_guards,
)
from nl2hltl2plan.language.handover_scene import FILLER, Marked, Place, Scene
from nl2hltl2plan.language.handover_sentences import split_sentences
from nl2hltl2plan.language.handover_steps import flat_steps, refuse_unordered, scattered_joint
from nl2hltl2plan.language.handover_tree import build_tree, joint_item, language_result, order_goals
from nl2hltl2plan.language.questions import answered as labelled_answers
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.worlds.world import World


def translate_handover(instruction: str, world: World) -> LanguageResult:
    """Instruction -> LanguageResult on a handover world (see the module docstring); a line break in it ends
    a step as a full stop does. Where the form reader refuses, each sentence it cannot read alone is said
    again from its cues (`handover_cues.restate`) and the whole is read once more (`_restated`). Questions
    and answers labelled "Q:" / "A:" are first said as the instruction they state (`questions.answered`,
    every world's; a question it does not know is refused by name), after the message's layout (headers, a
    role's sign-off, a dialogue's turns, a work order's fields: `handover_headers.headed`)."""
    instruction = labelled_answers(headed(instruction))
    try:
        result = _read_forms(instruction, world)
    except HTTError as refusal:
        restated = _restated(instruction, world)
        if restated is None:
            raise refusal from None
        result = restated
    frames: list[str] = []  # what the general filler rule dropped, said so in the result (h235)
    plain(split_sentences(answered(instruction)), frames)
    if not frames:
        return result
    note = frame_note(frames)
    return result.model_copy(update={"assumptions": [*result.assumptions, note]})


def _restated(instruction: str, world: World) -> LanguageResult | None:
    """The instruction read with every sentence that the form reader refuses alone said again from its cues;
    a sentence both readers read alone must give the same spec both ways (else None: refused). The result
    keeps the instruction's own words."""
    scene = Scene.of(world)
    said: list[str] = []
    previous: Marked | None = None
    said_alone = timing_joined(fragments_joined(plain(split_sentences(answered(instruction)))))
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
    said_first: list[str] = []  # blocks said to go first before any goal of theirs
    previous: Marked | None = None  # the sentence before ("it", "these regions" in the next one)
    said = timing_joined(fragments_joined(plain(split_sentences(answered(instruction)))))
    steps, closing = closing_said(said)
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
            if any(g.block == block for c in clauses for g in c.goals):
                lead(clauses, block)
            else:  # said before any goal of it: among the blocks of a later clause
                said_first.append(block)
    clauses = _distributed(clauses, notes)
    for block in said_first:
        lead_later(clauses, block)
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
    _opening_end_state(clauses, instruction)
    _refuse_misplaced_markers(clauses)
    root = build_tree(clauses)
    if joint := scattered_joint(clauses, scene.blocks):
        root.children, root.before = flat_steps([*root.children, joint_item(joint)], root.before)
    for x, y in orders:
        order_goals(root, _first_goal(goals, x), _first_goal(goals, y))
    refuse_unordered(root, [g for c in clauses if c.anytime for g in c.goals])
    return language_result(world.name, instruction, root, goals, notes)



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
    # a refusal quotes the user's own words: a word a rewrite put in ("comes after") is none of them
    said = {w.lower() for w in re.findall(r"[A-Za-z']+\d*|\d+", sentence.replace("’", "'"))}
    own = [w for w in words if w.lower() in said or w.lower() in _EXPANDED]
    if unused or words:  # (a word only a rewrite wrote is still unread: the sentence is quoted for it)
        what = ", ".join(repr(x) for x in unused + own) or repr(" ".join(sentence.split()))
        raise HTTError(f"the handover parser cannot use {what} in {sentence.strip()!r}; rephrase it")


# what the reader writes out of the user's contractions ("don't": 'do', 'not'), still the user's words
_EXPANDED = frozenset("do does did not is are will would have has had am can cannot".split())


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


# the words that put a goal at the end ("at the end, X should be on P"; "by the end," reads as "at the end,")
_AT_THE_END = re.compile(r"\b(?:(?:at|in|by)\s+the\s+(?:very\s+)?end|finally|lastly|last)\b", re.IGNORECASE)


def _opening_end_state(clauses: list[Clause], instruction: str) -> None:
    """'At the end, the red and blue blocks should have swapped places, and at any time the yellow block
    goes to the opposite side': an end state said once, opening the message, where every other goal is at
    any time or said later still ('after all that, ...'; after an 'at / by the end' state also a step
    'then' / 'after that': the end of the first step, as the text orders them; never after 'finally'), is
    the goal it states, not a last step; a last step said before goals with no time of their own stays
    refused (`_refuse_misplaced_markers`)."""
    first, rest = clauses[0], clauses[1:]
    ends = _AT_THE_END.findall(instruction)
    if first.marker != "after_all" or not rest or len(ends) != 1:
        return
    later = ("after_all", "then") if ends[0].lower().endswith("end") else ("after_all",)
    if all(c.anytime or c.marker in later for c in rest):
        first.marker = ""


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
