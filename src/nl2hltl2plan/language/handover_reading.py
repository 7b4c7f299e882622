"""The language stage on the four-arm handover worlds (paper Section IV-C, Table III).

`translate_handover(instruction, world)` reads an instruction about the blocks and regions of a
`handover-square` / `handover-line` world and returns the same `LanguageResult` as the other
worlds (HTT, base tasks, `before`, leaf formulas, the hierarchical spec) plus `constraints`: the
guards and joint goals as text, sorted. Each sentence is normalised and its phrases are resolved
against the instance's layout (`language.handover_phrases`, word tables in `handover_words`); its
orders, touch guards and prohibitions are read first (`language.handover_rules`), then its goals. The
rules, each general:

- a goal clause "VERB BLOCKS [back] to PLACE" gives one leaf per block: `F(at(B,R1) | at(B,R2) ...)`
  (the opposite side: per block; any empty region: `away(B)`; where another block starts: `@B`);
  "fill R with BLOCKS" is the same (as many regions as blocks); "exchange the positions of X and Y"
  ("while swapping their positions") gives `F at(X,@Y)` and `F at(Y,@X)`;
- a clause that moves several blocks to lasting places also asks for them there at once (a leaf
  `F(state_1 & state_2 ...)`), unless it says "at any time", "one after another" or its places hold
  fewer blocks than it moves;
- "X should be placed / gets placed / comes before Y" orders X's goal before Y's; "X first" puts X
  before the other blocks of the latest clause that moves it with others; "first ..., then ..."
  makes one node of the steps in order; "after all of these, ..." makes one node of everything said
  so far and puts the new goal after it; orders in a cycle are refused;
- "the arm cannot touch X until it touched Y" guards X's goal: `(!pick(X) U pick(Y)) & ...`;
- "no block can be placed on R (during this period)" and "cannot be placed on the area other than the
  target region" guard every goal of the sentence (or, in a sentence of its own, every goal so far)
  until it is met: `(!drop(R) & ...) U state` (a plan ends when its last goal is met, so this is
  "never" for the plan's whole run);
- "each region holds one object", "separately": the world's own rule (a cell holds one block).
Clauses are kept in the sentence's order; "but" is read only before a rule. Every word is read or is
a filler; anything else is refused, naming the words.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TypeGuard

import networkx as nx

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_phrases import FILLER, Marked, Place, Scene, drop_but, mark
from nl2hltl2plan.language.handover_rules import (
    Prohibition,
    blocks_of,
    read_leaders,
    read_orders,
    read_prohibitions,
    read_touch_guards,
)
from nl2hltl2plan.language.handover_words import (
    AFTER_ALL,
    DONE,
    GERUND,
    LEAD,
    MOD,
    MODAL,
    PERIOD_WORDS,
    PREP,
    SWAP,
    THEN,
    VERB,
)
from nl2hltl2plan.language.htt import HTT, HTTNode
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.spec_builder import build_spec
from nl2hltl2plan.language.task_specs import BaseTaskSpec, task_letter, transitive_reduction
from nl2hltl2plan.worlds.world import World


@dataclass
class Goal:
    block: str
    place: Place
    regions: tuple[str, ...]  # resolved labels (empty for away / start_of)
    text: str
    drop_guard: set[str] = field(default_factory=set)  # atoms that must not happen until the goal holds
    touch_guard: list[str] = field(default_factory=list)  # blocks Y: not picked before Y is

    def state(self) -> str:
        if self.place.kind == "away":
            return f'"away({self.block})"'
        if self.place.kind == "start_of" and not self.regions:
            return f'"at({self.block},@{self.place.block})"'
        parts = [f'"at({self.block},{r})"' for r in self.regions]
        return parts[0] if len(parts) == 1 else "(" + " | ".join(parts) + ")"

    def where(self) -> str:
        if self.place.kind == "away":
            return "any empty region"
        if self.place.kind == "start_of" and not self.regions:
            return f"where {self.place.block.lower()} started"
        return "|".join(self.regions)

    def leaf(self) -> str:
        body = f"F {self.state()}"
        if self.drop_guard:
            body = "(" + " & ".join(f'!"{a}"' for a in sorted(self.drop_guard)) + f") U {self.state()}"
        guards = [f'(!"pick({self.block})" U "pick({y})")' for y in self.touch_guard]
        return " & ".join([*guards, body])


@dataclass
class Clause:
    goals: list[Goal]
    text: str
    marker: str = ""  # "", "first", "then", "after_all"
    leader: str = ""  # a block placed before the clause's other blocks ("swap red and blue, red first")
    together: bool = False


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


def is_handover(world: object) -> TypeGuard[World]:
    return isinstance(world, World) and world.kind == "handover"


def translate_handover(instruction: str, world: World) -> LanguageResult:
    """Instruction -> LanguageResult on a handover world (see the module docstring)."""
    scene = Scene.of(world)
    clauses: list[Clause] = []
    orders: list[tuple[str, str]] = []
    touches: list[tuple[str, str]] = []
    notes: list[str] = []
    pending: list[Prohibition] = []  # prohibitions stated before any goal
    previous: Marked | None = None  # the sentence before ("it", "these regions" in the next one)
    for sentence in _sentences(instruction):
        m = mark(sentence, scene, previous)
        previous = m
        notes += m.notes
        forbids = read_prohibitions(m)
        touches += read_touch_guards(m)
        sentence_orders = read_orders(m)
        orders += sentence_orders
        # "red goes first, blue after red": the order says what "first" means
        leaders = [b for b in read_leaders(m) if b not in [x for x, _ in sentence_orders]]
        new = _goal_clauses(m, scene)
        if not new:  # "Step 2: the red block before the blue block": a step of rules only
            m.sub(r"^\s*then\b", " ")
        drop_but(m)
        _refuse_leftovers(m, sentence)
        scope = [g for c in new for g in c.goals] or [g for c in clauses for g in c.goals]
        for blocks, place, explicit, text in forbids:
            if scope:
                _guard(scope, blocks, place, explicit, scene, text)
            else:
                pending.append((blocks, place, explicit, text))
        clauses = _crossed_exchanges(clauses + new, orders)
        for block in leaders:
            _lead(clauses, block)
    orders += [(c.leader, g.block) for c in clauses if c.leader for g in c.goals if g.block != c.leader]
    if not clauses:
        raise HTTError(f"no goal for a block in {instruction!r} (say where each block goes)")
    goals = [g for c in clauses for g in c.goals]
    swapped = {b for g in goals if g.place.block and not g.regions for b in (g.block, g.place.block)}
    if sum(g.block in swapped for g in goals) > len(swapped):  # where is "its position" then: start or goal?
        raise HTTError("an exchanged block also has another goal: which positions are exchanged?")
    for blocks, place, explicit, text in pending:
        _guard(goals, blocks, place, explicit, scene, text)
    for x, y in touches:
        _first_goal(goals, x).touch_guard.append(y)
    _refuse_cyclic(orders)
    root = _tree(clauses)
    for x, y in orders:
        _order(root, _first_goal(goals, x), _first_goal(goals, y))
    return _result(world.name, instruction, root, goals, notes)


def _sentences(instruction: str) -> list[str]:
    """Split at '.', ';', '!' and '?', but not in 'i.e.' nor after a step's number ('1. Put ...')."""
    text = re.sub(r"(^|[.;!?]\s+)(\d)\.\s", r"\1\2) ", instruction)
    text = re.sub(r"\b[iI]\.\s?[eE]\.", "that is", text)
    return [s for s in re.split(r"[.;!?]+(?:\s|$)", text) if s.strip()]


# ----- clause patterns --------------------------------------------------------------------------------
def _goal_clauses(m: Marked, scene: Scene) -> list[Clause]:
    clauses: list[Clause] = []

    def goal(blocks: list[str], place: Place, text: str, mods: str) -> str:
        text = text.strip()
        goals = [Goal(b, place, _resolve(place, b, scene), text) for b in blocks]
        in_turn = re.search(r"one\s+after|one\s+by|one\s+at|in\s+turn", mods) is not None
        anytime = re.search(r"any\s+time|whenever", mods) is not None
        room = len({r for g in goals for r in g.regions}) >= len(goals) or place.kind == "start_of"
        together = len(goals) > 1 and place.kind != "away" and room and not (in_turn or anytime)
        clauses.append(Clause(goals, text, together=together))
        return f" G{len(clauses) - 1} "

    def exchange(match: re.Match[str], other: str = "") -> str:
        pair = blocks_of(m, match.group(1)) + (blocks_of(m, other) if other else [])
        if len(pair) != 2:
            raise HTTError(
                f"exchange needs two blocks, '{m.block_text[int(match.group(1))]}' names {len(pair)}"
            )
        x, y = pair
        goals = [
            Goal(x, Place("start_of", block=y), (), f"{x.lower()} where {y.lower()} started"),
            Goal(y, Place("start_of", block=x), (), f"{y.lower()} where {x.lower()} started"),
        ]
        clauses.append(Clause(goals, match.group(0).strip(), together=True))
        return f" G{len(clauses) - 1} "

    def again(before: Clause, x: re.Match[str]) -> str:  # the blocks of `before` to a new place
        text = x.string[x.start("link") : x.end()]
        return goal([g.block for g in before.goals], m.places[int(x.group(3))], text, x.group(4))

    mods = rf"((?:\s*,?\s*{MOD})*)"
    # "one by one, put all three blocks on I": the modifier read where it usually stands, after the object
    m.sub(rf"\b({MOD})\s*,?\s*({VERB}\s+B\d+)", r"\2 \1")

    def matched(x: re.Match[str], k: int) -> str:  # groups from k: blocks, modifiers, place, modifiers
        place, text = m.places[int(x.group(k + 2))], x.group(0).strip()
        return goal(blocks_of(m, x.group(k)), place, text, x.group(k + 1) + x.group(k + 3))

    _read_exchanges(m, exchange)
    m.sub(
        rf"(?:\bwhile\s+)?\b(?:{VERB}|{GERUND})\s+B(\d+){mods}(?:\s+first)?\s+(?:(?:to\s+)?(?:be|end\s+up)\s+)?"
        rf"(?:back\s+)?{PREP}\s+P(\d+){mods}",
        lambda x: matched(x, 1),
    )
    # a heading-like goal at the start of a sentence or after a comma: "pillars to E, F and G"
    m.sub(
        rf"(?:^|(?<=,))\s*B(\d+){mods}\s*(?::\s*|,?\s*(?:to|into|onto)\s+)P(\d+){mods}(?:\s+first\b)?(?=\s*(?:$|,|\band\b))",
        lambda x: matched(x, 1),
    )
    # "put one block in each of regions H, I and J": every block, one per region (as many as blocks)
    m.sub(
        rf"\b{VERB}\s+(?:one|a|a\s+single)\s+(?:block|object|cube|pillar|item)\s+(?:in|on|into|onto|to)\s+(?:each|every)\s+"
        rf"(?:one\s+)?(?:of\s+)?P(\d+)(?P<b>){mods}",
        lambda x: _fill(m, x, goal, scene.blocks),
    )
    # the inverse syntax "fill regions H, I and J with the three blocks": as many places as blocks
    m.sub(rf"\b(?:fill|occupy|populate)\s+P(\d+)\s+with\s+B(\d+){mods}", lambda x: _fill(m, x, goal))
    m.sub(
        rf"\b(?:each\s+of\s+)?P(\d+)\s+{MODAL}(?:each\s+)?(?:receive|get|take|hold|contain)s?\s+(?:exactly\s+|just\s+)?"
        rf"(?:one\s+of\s+)?B(\d+){mods}",
        lambda x: _fill(m, x, goal),
    )
    m.sub(
        rf"(?:\bwith\s+)?\bB(\d+)\s+{MODAL}{DONE}{mods}(?:\s+first)?\s+(?:back\s+)?"
        rf"{PREP}\s+P(\d+){mods}",
        lambda x: matched(x, 1),
    )
    # a verb shared with the clause before: "put the red block in H, then the blue block in I"
    m.sub(
        rf"(?<=G\d)(?P<link>\s*,?\s*(?:and\s+)?(?:then\s+)?)B(\d+){mods}\s+(?:back\s+)?{PREP}\s+P(\d+)"
        rf"{mods}",
        lambda x: x.group("link") + matched(x, 2),
    )
    # the verb and the blocks shared with the clause just before: "to I, then to G", "on I first, then on G"
    m.sub(
        rf"\bG(\d+)(?P<link>(?:\s+first\b)?\s*,?\s*(?:and\s+)?(?:{THEN}{LEAD}|followed\s+by\s+))(?:back\s+)?(?:{PREP}\s+)?"
        rf"P(\d+){mods}",
        lambda x: f" G{x.group(1)} then " + again(clauses[int(x.group(1))], x),
    )
    m.sub(  # "on I first and on G second": the second place named after the first
        rf"\bG(\d+)(?P<link>\s+first\s*,?\s*and\s+)(?:back\s+)?{PREP}\s+P(\d+){mods}\s+(?:second|next|afterwards?|last)\b",
        lambda x: f" G{x.group(1)} then " + again(clauses[int(x.group(1))], x),
    )
    _markers(m, clauses)
    order = [int(k) for k in re.findall(r"\bG(\d+)\b", m.text)]  # the sentence's order, not the patterns'
    if sorted(order) != list(range(len(clauses))):  # a clause lost or read twice: never guess
        raise HTTError(f"cannot tell the order of the goals in {m.text.strip()!r}")
    return [clauses[k] for k in order]


def _read_exchanges(m: Marked, exchange: Callable[..., str]) -> None:
    """'exchange the positions of X and Y', 'swap X with Y', 'X and Y should trade places', 'the positions
    of X and Y should be swapped' (and '..., so that each ends up where the other was')."""
    m.sub(  # "swap the red block with the blue block"
        rf"\b{SWAP}\s+(?:the\s+)?(?:positions?\s+of\s+)?B(\d+)(?:\s+(?:s\s+)?(?:positions?|places?|locations?))?\s+(?:with|and)\s+"
        r"B(\d+)(?:\s+(?:s\s+)?(?:positions?|places?|locations?))?",
        lambda x: exchange(x, x.group(2)),
    )
    m.sub(
        rf"(?:\bwhile\s+)?\b{SWAP}\s+(?:the\s+)?(?:positions?\s+|places?\s+|locations?\s+|spots?\s+)?(?:of\s+)?B(\d+)(?:\s+(?:s\s+)?(?:positions?|places?|locations?))?(?:\s+(?:around|round|over|with\s+each\s+other|with\s+one\s+another))?",
        exchange,
    )
    m.sub(
        rf"\bB(\d+)\s+{MODAL}(?:exchange|swap|switch|trade)s?\s+(?:their\s+)?(?:positions?|places?|locations?|spots?)",
        exchange,
    )
    m.sub(  # "the positions of the red and blue blocks should be swapped"
        rf"\b(?:the\s+)?(?:positions?|places?|locations?)\s+of\s+B(\d+)\s+{MODAL}(?:swapped|exchanged|switched|interchanged)",
        exchange,
    )
    # "... so that each ends up where the other was": what an exchange is
    m.sub(
        r"(?<=G\d)\s*,?\s*so\s+that\s+each\s+(?:one\s+)?(?:ends\s+up|is|goes|lands|sits)\s+(?:where|in\s+the\s+place)\s+"
        r"the\s+other\s+(?:one\s+)?(?:was|is|started|stood|had\s+been)\b|(?<=G\d)\s*,?\s*so\s+that\s+each\s+(?:one\s+)?"
        r"(?:occupies|takes|gets|ends\s+up\s+(?:in|on)|goes\s+to)\s+the\s+other\s+(?:one\s+)?s\s+"
        r"(?:original\s+|initial\s+|starting\s+)?(?:position|place|spot|location|region)\b",
        " ",
    )


def _fill(
    m: Marked,
    x: re.Match[str],
    goal: Callable[[list[str], Place, str, str], str],
    every: list[str] | None = None,
) -> str:
    place, blocks = m.places[int(x.group(1))], every or blocks_of(m, x.group(2))
    if place.kind != "regions" or len(set(place.regions)) != len(blocks):
        raise HTTError(f"'{x.group(0).strip()}': fill needs as many named regions as blocks")
    return goal(blocks, place, x.group(0).strip(), x.group(3))


def _markers(m: Marked, clauses: list[Clause]) -> None:
    def set_marker(match: re.Match[str], marker: str) -> str:
        clauses[int(match.group(1))].marker = marker
        return f" G{match.group(1)} "

    m.sub(rf"\b(?:first(?:ly)?|to\s+begin\s+with|start\s+by){LEAD}G(\d+)", lambda x: set_marker(x, "first"))
    m.sub(
        rf"(?:,\s*)?(?:\band\s+)?\b{THEN}{LEAD}G(\d+)",
        lambda x: set_marker(x, "then"),
    )
    m.sub(rf"\b(?:then\s*,?\s*)?{AFTER_ALL}{LEAD}G(\d+)", lambda x: set_marker(x, "after_all"))
    m.sub(  # "put the yellow block back on G at the end"
        r"\bG(\d+)\s*,?\s*(?:at\s+the\s+(?:very\s+)?end|in\s+the\s+end|lastly|finally|last|as\s+the\s+(?:last|final)\s+step)\b",
        lambda x: set_marker(x, "after_all"),
    )

    m.sub(r"\bG(\d+)\s+first\b", lambda x: set_marker(x, "first"))

    def anytime(match: re.Match[str]) -> str:
        clauses[int(match.group(1))].together = False
        return f" G{match.group(1)} "

    m.sub(r"\b(?:at\s+any\s+time|any\s+time|in\s+any\s+order)\s*,?\s*G(\d+)", anytime)
    # "meanwhile, move ...", "..., while the red block goes ...": a goal with no order to the others, as
    # any goal without a marker
    m.sub(rf"\b(?:{PERIOD_WORDS}|while)\s*,?\s*(?=G\d+|at\s+any\s+time)", " ")
    m.sub(r"(?:,\s*)?\band\s+(?=G\d+)", lambda _: " ")


def _resolve(place: Place, block: str, scene: Scene) -> tuple[str, ...]:
    if place.kind == "opposite":
        return scene.opposite(block)
    if place.kind in ("regions", "start_of", "away"):
        return place.regions  # () for "away" and an exchange's start_of
    raise HTTError(f"'{place.text}' is not a place a block can go to")


def _refuse_leftovers(m: Marked, sentence: str) -> None:
    unused = [m.block_text[int(k)] for k in re.findall(r"\bB(\d+)\b", m.text)]
    unused += [m.places[int(k)].text for k in re.findall(r"\bP(\d+)\b", m.text)]
    words = [w for w in re.findall(r"[A-Za-z']+\d*|\d+", m.text) if w not in FILLER]
    words = [w for w in words if not re.fullmatch(r"[BPG]\d+|A", w)]
    if unused or words:
        what = ", ".join(repr(x) for x in unused + words)
        raise HTTError(f"the handover parser cannot use {what} in {sentence.strip()!r}; rephrase it")


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


def _crossed_exchanges(clauses: list[Clause], orders: list[tuple[str, str]]) -> list[Clause]:
    """'put the red block where the blue block is and the blue block where the red block is' (also in
    two sentences, '... then ...': red before blue) is the exchange of their positions."""
    out = list(clauses)
    for first in clauses:
        g = first.goals[0]
        if first not in out or len(first.goals) != 1 or g.place.kind != "start_of":
            continue
        if first.marker == "after_all":
            continue
        second = next(
            (
                c
                for c in out[out.index(first) + 1 :]
                if len(c.goals) == 1
                and c.marker in ("", "then")
                and c.goals[0].place.kind == "start_of"
                and (c.goals[0].block, c.goals[0].place.block) == (g.place.block, g.block)
            ),
            None,
        )
        if second is None:
            continue
        h = second.goals[0]
        if second.marker == "then":
            orders.append((g.block, h.block))
        g.regions = h.regions = ()  # where the other started: `@B`, as an exchange
        merged = Clause([g, h], f"{first.text}; {second.text}", marker=first.marker, together=True)
        out[out.index(first)] = merged
        out.remove(second)
    return out


def _lead(clauses: list[Clause], block: str) -> None:
    """'swap red and blue, red first', 'the red block has to be placed first': the block goes before the
    other blocks of the latest clause that moves it with others."""
    for clause in reversed(clauses):
        if len(clause.goals) > 1 and block in [g.block for g in clause.goals]:
            clause.leader = block
            return
    raise HTTError(
        f"'the {block.lower()} block first': first among which blocks? (say 'before the ... block')"
    )


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
    if c.together:
        text = "at once: " + ", ".join(f"{g.block.lower()} on {g.where()}" for g in c.goals)
        items.append(Item(text, joint=list(c.goals)))
    return items


def _unit(c: Clause) -> Item:
    items = _items(c)
    return items[0] if len(items) == 1 else Item(c.text, children=items)


def _tree(clauses: list[Clause]) -> Item:
    root = Item("")
    chain: Item | None = None
    prev: Clause | None = None
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
            old = root.children[0] if len(root.children) == 1 else root
            root = Item("", children=[old])
            root.children += _items(c)
            root.before += [(0, k) for k in range(1, len(root.children))]
            chain = None
        else:
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
