"""The goal clauses of a handover sentence (`handover_reading`): "VERB BLOCKS (back) to PLACE" in its
active, gerund, passive and heading forms, the inverse "fill R with BLOCKS", exchanges, the same blocks
"then to G", and the markers of a clause ("first", "then", "after all of these", "at any time"). A
clause gives a `Goal` per block; several blocks to lasting places are also asked for at once.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_rules import blocks_of
from nl2hltl2plan.language.handover_scene import Marked, Place, Scene
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
    SWAPPED,
    THEN,
    VERB,
)

# a clause's modifier that moves its blocks one at a time ("one by one", "in turn"), not all at once
_IN_TURN = re.compile(r"one\s+after|one\s+by|one\s+at|in\s+turn")


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


GoalMaker = Callable[[list[str], Place, str, str], str]  # (blocks, place, text, modifiers) -> placeholder


@dataclass
class Clause:
    goals: list[Goal]
    text: str
    marker: str = ""  # "", "first", "then", "after_all"
    leader: str = ""  # a block placed before the clause's other blocks ("swap red and blue, red first")
    together: bool = False
    anytime: bool = False  # "at any time": in no order to the other goals, even as a numbered step


def goal_clauses(m: Marked, scene: Scene) -> list[Clause]:
    """The sentence's goal clauses, in the sentence's order (a clause lost or read twice is refused)."""
    clauses: list[Clause] = []

    def goal(blocks: list[str], place: Place, text: str, mods: str) -> str:
        text = text.strip()
        goals = [Goal(b, place, _resolve(place, b, scene), text) for b in blocks]
        in_turn = _IN_TURN.search(mods) is not None
        anytime = re.search(r"any\s+time|whenever", mods) is not None
        room = len({r for g in goals for r in g.regions}) >= len(goals) or place.kind == "start_of"
        # "at any time" frees the goals' time, not the place they end in: all there at once still holds
        together = len(goals) > 1 and place.kind != "away" and room and not in_turn
        clauses.append(Clause(goals, text, together=together, anytime=anytime))
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
    # (not "all": "after finishing all, put ..."; not a state: "after the rest is over, put ...")
    m.sub(rf"\b(?<!\bis\s)(?<!\bare\s)(?<!\bbeen\s)((?!all\b){MOD})\s*,?\s*({VERB}\s+B\d+)", r"\2 \1")

    def matched(x: re.Match[str], k: int) -> str:  # groups from k: blocks, modifiers, place, modifiers
        place, text = m.places[int(x.group(k + 2))], x.group(0).strip()
        return goal(blocks_of(m, x.group(k)), place, text, x.group(k + 1) + x.group(k + 3))

    # "the yellow block must then be returned to G": the step word read at the clause's head
    m.sub(
        r"\b(B\d+\s+(?:must|should|shall|will|can|has\s+to|needs\s+to)\s+)(then|next|afterwards|finally|lastly)\s+",
        r"\2 \1",
    )
    _read_exchanges(m, exchange)
    _read_sources(m, scene)
    m.sub(
        rf"(?:\bwhile\s+(?:you\s+|we\s+)?)?\b(?:{VERB}|{GERUND})\s+B(\d+){mods}(?:\s+first)?\s*,?\s+"
        rf"(?:to\s+(?:be\s+)?(?:{DONE}\s+)?|be\s+(?:{DONE}\s+)?|end\s+up\s+)?"
        rf"(?:back\s+)?{PREP}\s+P(\d+){mods}",
        lambda x: matched(x, 1),
    )
    # a heading-like goal at the start of a sentence, after a comma or a step word: "pillars to E, F and
    # G", "yellow: back to G last", "yellow block on I, then on G", "then yellow back to G"
    m.sub(
        rf"(?:^|(?<=,)|(?<=\bthen)|(?<=\bfinally)|(?<=\blastly))\s*B(\d+){mods}\s*(?::\s*(?:back\s+)?(?:(?:to|into|onto|on|in)\s+)?|,?\s*(?:back\s+)?"
        rf"(?:to|into|onto|on|in)\s+)P(\d+){mods}(?:\s+first\b)?(?=\s*(?:$|,|\band\b|\(|last\b|finally\b|then\b|at\s+the\s+end\b))",
        lambda x: matched(x, 1),
    )
    _read_telegraphic(m, scene, mods, matched)
    _read_inverse(m, goal, scene.blocks, mods)
    m.sub(
        rf"(?:\bwith\s+)?\bB(\d+)\s+{MODAL}{DONE}{mods}(?:\s+first)?\s+(?:back\s+)?"
        rf"{PREP}\s+P(\d+){mods}",
        lambda x: matched(x, 1),
    )
    # the state asked for: "the pillars need to be on regions E, F and G" (with a modal: "is on" is a state)
    m.sub(
        rf"(?:\bwith\s+)?\bB(\d+){mods}\s+(?:should|must|shall|will|needs?\s+to|has\s+to|have\s+to)\s+"
        rf"(?:all\s+|each\s+|both\s+)?be\s+(?:back\s+)?(?:on|in|at|onto|into)\s+P(\d+){mods}",
        lambda x: matched(x, 1),
    )
    # a verb shared with the clause before: "put the red block in H, then the blue block in I" (again after
    # the clauses that share the blocks too: "to I then to G and red and blue to any empty region")
    shared_verb = (
        rf"(?<=G\d)(?P<link>\s*,?\s*(?:and\s+)?(?:then\s+)?)B(\d+){mods}\s+(?:back\s+)?{PREP}\s+P(\d+){mods}"
    )
    m.sub(shared_verb, lambda x: x.group("link") + matched(x, 2))
    # the verb and the blocks shared with the clause just before: "to I, then to G", "on I first, then on G"
    m.sub(
        rf"\bG(\d+)(?P<link>(?:\s+first\b)?\s*,?\s*(?:and\s+)?(?:{THEN}{LEAD}|followed\s+by\s+))(?:{VERB}\s+)?(?:back\s+)?"
        rf"(?:{PREP}\s+)?P(\d+){mods}",
        lambda x: f" G{x.group(1)} then " + again(clauses[int(x.group(1))], x),
    )
    m.sub(  # "on I first and on G second": the second place named after the first
        rf"\bG(\d+)(?P<link>\s+first\s*,?\s*and\s+)(?:back\s+)?{PREP}\s+P(\d+){mods}\s+(?:second|next|afterwards?|after|last)\b(?!\s+B)",
        lambda x: f" G{x.group(1)} then " + again(clauses[int(x.group(1))], x),
    )
    m.sub(shared_verb, lambda x: x.group("link") + matched(x, 2))
    _markers(m, clauses)
    order = [int(k) for k in re.findall(r"\bG(\d+)\b", m.text)]  # the sentence's order, not the patterns'
    if sorted(order) != list(range(len(clauses))):  # a clause lost or read twice: never guess
        raise HTTError(f"cannot tell the order of the goals in {m.text.strip()!r}")
    return [clauses[k] for k in order]


def _read_inverse(m: Marked, goal: GoalMaker, every: list[str], mods: str) -> None:
    """The place before the blocks: 'region I: all three blocks', 'the opposite regions for all three
    blocks', 'H, I and J get one block each', 'fill regions H, I and J with the three blocks', 'each of
    regions H, I and J should receive one of the blocks'."""
    m.sub(
        rf"(?:^|(?<=,))\s*P(\d+)\s*(?::|\bfor\b)\s*B(\d+){mods}(?=\s*(?:$|,|\band\b))",
        lambda x: goal(blocks_of(m, x.group(2)), m.places[int(x.group(1))], x.group(0), x.group(3)),
    )
    # "H, I and J get one block each": every block, one per region (as many as blocks)
    m.sub(
        rf"\bP(\d+)\s+{MODAL}(?:(?:receive|get|take|hold)s?|ends?\s+up\s+with)\s+(?:exactly\s+)?(?:one|a\s+single)\s+"
        rf"(?:block|object|cube|pillar|item)\s+(?:each|apiece)(){mods}",
        lambda x: _fill(m, x, goal, every),
    )
    m.sub(  # "H, I and J (are to) each get exactly one block": "each" before the verb
        rf"\bP(\d+)\s+(?:(?:should|must|shall|will|can|may|has\s+to|have\s+to|needs?\s+to|are\s+to)\s+)?each\s+"
        rf"(?:(?:receive|get|take|hold)s?|ends?\s+up\s+with)\s+(?:exactly\s+|only\s+|just\s+)?(?:one|a\s+single)\s+"
        rf"(?:block|object|cube|pillar|item)\b(?!\s+of\b)(){mods}",
        lambda x: _fill(m, x, goal, every),
    )
    m.sub(  # "G, H, I: one block each"
        rf"(?:^|(?<=,))\s*P(\d+)\s*[:,]\s*(?:exactly\s+)?(?:one|a\s+single)\s+(?:block|object|cube|pillar|item)\s+"
        rf"(?:each|apiece)(){mods}",
        lambda x: _fill(m, x, goal, every),
    )
    # "put one block in each of regions H, I and J": every block, one per region (as many as blocks)
    m.sub(
        rf"\b{VERB}\s+(?:one|a|a\s+single)\s+(?:block|object|cube|pillar|item)\s+(?:in|on|into|onto|to)\s+(?:each|every)\s+"
        rf"(?:one\s+)?(?:of\s+)?P(\d+)(?P<b>){mods}",
        lambda x: _fill(m, x, goal, every),
    )
    # "put one of the three blocks in each of regions H, I and J": those blocks, one per region
    m.sub(
        rf"\b{VERB}\s+(?:one|a\s+single\s+one)\s+of\s+B(?P<b>\d+)\s+(?:in|on|into|onto|to)\s+(?:each|every)\s+(?:one\s+)?"
        rf"(?:of\s+)?P(?P<p>\d+){mods}",
        lambda x: _one_per_region(
            goal, m.places[int(x.group("p"))], blocks_of(m, x.group("b")), x.group(0), x.group(3), False
        ),
    )
    # "regions H, I and J need to be filled with the three blocks": the passive of the inverse syntax
    filled = r"(?:filled|occupied|populated|loaded)"
    m.sub(rf"\bP(\d+)\s+{MODAL}{filled}\s+with\s+B(\d+){mods}", lambda x: _fill(m, x, goal))
    # the inverse syntax "fill regions H, I and J with the three blocks": as many places as blocks
    m.sub(rf"\b(?:fill|occupy|populate|load)\s+P(\d+)\s+with\s+B(\d+){mods}", lambda x: _fill(m, x, goal))
    m.sub(
        rf"\b(?:each\s+of\s+)?P(\d+)\s+(?:each\s+)?{MODAL}(?:each\s+)?(?:(?:receive|get|take|hold|contain)s?|ends?\s+up\s+(?:holding|with))\s+"
        rf"(?:exactly\s+|just\s+)?"
        rf"(?:one\s+of\s+)?B(\d+){mods}",
        lambda x: _fill(m, x, goal),
    )


def _read_exchanges(m: Marked, exchange: Callable[..., str]) -> None:
    """'exchange the positions of X and Y', 'swap X with Y', 'X and Y should trade places', 'the positions
    of X and Y should be swapped' (and '..., so that each ends up where the other was')."""
    trade = r"(?:exchange|swap|switch|trade|change)s?"  # "X and Y should trade places"
    positions = r"(?:positions|places|locations|spots)"
    each_other = r"(?:\s+(?:with\s+)?(?:each\s+other|one\s+another))"
    m.sub(  # "the red block and the blue block shall exchange their positions (with each other)"
        rf"\bB(\d+)\s+and\s+B(\d+)\s+(?:to\s+)?{MODAL}{trade}\s+(?:their\s+)?(?:{positions}{each_other}?|"
        rf"(?:position|place|location|spot){each_other})",
        lambda x: exchange(x, x.group(2)),
    )

    def exchange_their(x: re.Match[str]) -> str:  # "their" must name the same two blocks
        same = sorted(m.blocks[int(x.group(1))]) == sorted(m.blocks[int(x.group(2))])
        return exchange(x) if same else x.group(0)

    m.sub(
        rf"\bB(\d+)\s+(?:to\s+)?{MODAL}{trade}\s+B(\d+)\s+{positions}",
        exchange_their,
    )
    m.sub(  # "swap the red block with the blue block"
        rf"\b{SWAP}\s+(?:the\s+)?(?:positions?\s+of\s+)?B(\d+)(?:\s+(?:s\s+)?(?:positions?|places?|locations?))?\s+(?:with|and)\s+"
        r"B(\d+)(?:\s+(?:s\s+)?(?:positions?|places?|locations?))?",
        lambda x: exchange(x, x.group(2)),
    )
    m.sub(
        rf"(?:\bwhile\s+)?\b{SWAP}\s+(?:the\s+)?(?:positions?\s+|places?\s+|locations?\s+|spots?\s+)?(?:of\s+)?B(\d+)(?:\s+(?:s\s+|the\s+|their\s+)?(?:positions?|places?|locations?))?(?:\s+(?:around|round|over|with\s+each\s+other|with\s+one\s+another))?",
        exchange,
    )
    m.sub(
        rf"(?:\bwhile\s+|\b(?:want|need|have)\s+)?\bB(\d+)\s+(?:to\s+)?{MODAL}{trade}\s+(?:their\s+)?"
        rf"(?:positions?|places?|locations?|spots?){each_other}?",
        exchange,
    )
    m.sub(rf"\b{SWAP}\s+(?:the\s+places\s+)?where\s+B(\d+)\s+(?:are|stand|sit|lie)\b", exchange)
    m.sub(  # "the positions of the red and blue blocks should be swapped"
        rf"\b(?:the\s+)?(?:positions?|places?|locations?)\s+of\s+B(\d+)\s+{MODAL}{SWAPPED}",
        exchange,
    )
    m.sub(  # "the red and blue blocks are to have their positions exchanged"
        rf"\bB(\d+)\s+{MODAL}(?:have|get)\s+their\s+{positions}\s+{SWAPPED}",
        exchange,
    )
    # the exchange said as the state it leaves: "the red and blue blocks should end up in each other's
    # (starting) positions"
    m.sub(
        rf"\bB(\d+)\s+{MODAL}(?:end\s+up|go|be|get)\s+(?:in|on|at|to|into)\s+each\s+other\s*s?\s+"
        r"(?:starting\s+|original\s+|initial\s+|old\s+)?(?:positions|places|spots|regions|locations)",
        exchange,
    )
    # "the red and blue blocks should be swapped" (after "the positions of ... should be swapped")
    m.sub(rf"\bB(\d+)\s+{MODAL}{SWAPPED}(?:\s+around)?", exchange)
    # "... so that each ends up where the other was": what an exchange is
    m.sub(
        r"(?<=G\d)\s*,?\s*so\s+that\s+each\s+(?:one\s+)?(?:ends\s+up|is|goes|lands|sits)\s+(?:where|in\s+the\s+place)\s+"
        r"the\s+other\s+(?:one\s+)?(?:was|is|started|stood|had\s+been)\b|(?<=G\d)\s*,?\s*so\s+that\s+each\s+(?:one\s+)?"
        r"(?:occupies|takes|gets|ends\s+up\s+(?:in|on)|goes\s+to)\s+the\s+other\s+(?:one\s+)?s\s+"
        r"(?:original\s+|initial\s+|starting\s+)?(?:position|place|spot|location|region)\b",
        " ",
    )


def _read_sources(m: Marked, scene: Scene) -> None:
    """'move the blocks from the side of arm a and arm b to ...': where they start, which must be so."""

    def check(match: re.Match[str]) -> str:
        source = m.places[int(match.group(2))]
        for block in blocks_of(m, match.group(1)):
            if source.kind != "regions" or scene.start_region(block) not in source.regions:
                raise HTTError(f"the {block.lower()} block does not start on '{source.text}'")
        return f" B{match.group(1)} "

    m.sub(r"\bB(\d+)\s+(?:away\s+)?from\s+P(\d+)", check)


def _fill(m: Marked, x: re.Match[str], goal: GoalMaker, every: list[str] | None = None) -> str:
    """Groups 1, 2, 3 of `x`: the place, the blocks (else `every` block), the modifiers."""
    blocks = every or blocks_of(m, x.group(2))
    return _one_per_region(goal, m.places[int(x.group(1))], blocks, x.group(0), x.group(3), every is None)


def _one_per_region(
    goal: GoalMaker, place: Place, blocks: list[str], text: str, mods: str, in_turn_ok: bool
) -> str:
    text = text.strip()
    in_turn = _IN_TURN.search(mods) is not None
    if in_turn and in_turn_ok and place.kind == "regions":  # "region I receives the blocks one by one"
        return goal(blocks, place, text, mods)
    if place.kind != "regions" or len(set(place.regions)) != len(blocks):
        raise HTTError(f"'{text}': fill needs as many named regions as blocks")
    return goal(blocks, place, text, mods)


def _markers(m: Marked, clauses: list[Clause]) -> None:
    def set_marker(match: re.Match[str], marker: str) -> str:
        clauses[int(match.group(1))].marker = marker
        return f" G{match.group(1)} "

    m.sub(rf"\b(?:first(?:ly)?|to\s+begin\s+with|start\s+by){LEAD}G(\d+)", lambda x: set_marker(x, "first"))
    m.sub(
        rf"(?:,\s*)?(?:\band\s+)?\b{THEN}{LEAD}G(\d+)",
        lambda x: set_marker(x, "then"),
    )
    # stacked markers say it once: "in the end, after all of this, put ..."
    m.sub(
        rf"\b(?:then\s*,?\s*)?(?:{AFTER_ALL}\s*,?\s*)*{AFTER_ALL}{LEAD}G(\d+)",
        lambda x: set_marker(x, "after_all"),
    )
    # "put the yellow block back on G once all of this is done"
    m.sub(rf"\bG(\d+)\s*,?\s*{AFTER_ALL}(?=\s*(?:$|,))", lambda x: set_marker(x, "after_all"))
    m.sub(  # "put the yellow block back on G at the end"
        r"\bG(\d+)\s*,?\s*(?:at\s+the\s+(?:very\s+)?end|in\s+the\s+end|lastly|finally|last|as\s+the\s+(?:last|final)\s+step)\b",
        lambda x: set_marker(x, "after_all"),
    )
    m.sub(r"\bG(\d+)\s+first\b", lambda x: set_marker(x, "first"))

    def anytime(match: re.Match[str]) -> str:
        clauses[int(match.group(1))].anytime = True
        return f" G{match.group(1)} "

    m.sub(r"\b(?:at\s+any\s+time|any\s+time|in\s+any\s+order)\s*,?\s*G(\d+)", anytime)
    # "meanwhile, move ...", "..., while the red block goes ...": a goal with no order to the others, as
    # any goal without a marker
    m.sub(rf"\b(?:{PERIOD_WORDS}|while)\s*,?\s*(?=G\d+|at\s+any\s+time)", " ")
    m.sub(r"(?:,\s*)?\band\s+(?=G\d+)", lambda _: " ")
    for c in clauses:  # "Step 3: at any time, move ...": a step that says "at any time" is in no order
        if c.anytime and c.marker == "then":
            c.marker = ""


def _read_telegraphic(
    m: Marked, scene: Scene, mods: str, matched: Callable[[re.Match[str], int], str]
) -> None:
    """A telegraphic sentence, the blocks and their place with a comma between: "Three blocks, opposite
    side." (where a block starts on that place, the comma may say where it is: refused)."""

    def telegraphic(x: re.Match[str]) -> str:
        place = m.places[int(x.group(3))]
        if place.kind == "regions" and any(_starts_on(scene, b, place) for b in blocks_of(m, x.group(1))):
            said = f"{m.block_text[int(x.group(1))]}, {place.text}"
            raise HTTError(f"'{said}' may say where a block is, not where it goes: say 'to'")
        return matched(x, 1)

    m.sub(rf"^\s*B(\d+){mods}\s*,\s*P(\d+){mods}(?=\s*(?:$|,))", telegraphic)


def _starts_on(scene: Scene, block: str, place: Place) -> bool:
    try:
        return scene.start_region(block) in place.regions
    except HTTError:  # it starts off the labelled regions
        return False


def _resolve(place: Place, block: str, scene: Scene) -> tuple[str, ...]:
    if place.kind == "opposite":
        return scene.opposite(block)
    if place.kind in ("regions", "start_of", "away"):
        return place.regions  # () for "away" and an exchange's start_of
    raise HTTError(f"'{place.text}' is not a place a block can go to")


def crossed_exchanges(clauses: list[Clause], orders: list[tuple[str, str]]) -> list[Clause]:
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


def lead(clauses: list[Clause], block: str) -> None:
    """'swap red and blue, red first', 'the red block has to be placed first': the block goes before the
    other blocks of the latest clause that moves it with others."""
    for clause in reversed(clauses):
        if len(clause.goals) > 1 and block in [g.block for g in clause.goals]:
            clause.leader = block
            return
    raise HTTError(
        f"'the {block.lower()} block first': first among which blocks? (say 'before the ... block')"
    )


def lead_later(clauses: list[Clause], block: str) -> None:
    """'The red block should be placed first. Exchange the red and blue blocks. ...': a block said first
    before any goal of it goes before the other blocks of the one later clause that moves it with others,
    where every other clause is free of order ("at any time"); otherwise first among which blocks is not
    said, and it is refused."""
    moved_with = [c for c in clauses if len(c.goals) > 1 and block in [g.block for g in c.goals]]
    others = [c for c in clauses if c not in moved_with and not c.anytime]
    if len(moved_with) == 1 and not others and moved_with[0].leader in ("", block):
        moved_with[0].leader = block
        return
    raise HTTError(
        f"'the {block.lower()} block first': first among which blocks? (say 'before the ... block')"
    )

