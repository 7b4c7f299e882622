"""Phrases of the four-arm handover instructions (paper Table III), read against the world's layout.

A sentence is read in passes. It is normalised first (lower case, typos mended, the variants of
`handover_words.REWRITES` rewritten onto the forms read). Noun phrases then become placeholders:
blocks (`B0`: "the three pillars", "red and blue blocks", "each object"), places (`P0`: "region H, I
and J", "the opposite side", "any empty region", "the side of arm a and arm b", "where the red block
is", "the area other than the target region") and arms (`A`: "the robot arm", "any of the arms").
Then the rules of `language.handover_rules` and the clause patterns of `language.handover_reading`
consume placeholders and words. Whatever a pass leaves unread is a refusal naming the words: nothing
is silently dropped.

Places resolve against the instance: "the opposite" is, per block, the labelled regions on the other
arms' side from where the block starts (arms a, b against c, d); "the side of arm a and arm b" the
labelled regions those arms reach; "where the red block is" the region red starts on. A landmark
("next to arm a and arm b") only describes a place named beside it, and must agree with it; "swap
them", "exchanging their positions": the two blocks named before in the sentence (else unread).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Literal

from nl2hltl2plan.errors import HTTError, WorldError
from nl2hltl2plan.language.handover_words import (
    APPOSITION,
    DONE,
    EMPTY,
    GERUND,
    MODAL,
    NEG,
    REWRITES,
    SWAP,
    VERB,
    typo_table,
)
from nl2hltl2plan.worlds.handover_world import REGIONS, Layout, layout
from nl2hltl2plan.worlds.world import Cell, World

COLOURS = ("red", "blue", "yellow")
_TOUCHED = r"(?:touched|picked|grasped|grabbed|handled|moved|lifted)"
COUNTS = {"two": 2, "three": 3, "four": 4, "both": 2, "2": 2, "3": 3, "4": 4}
NOUN = r"(?:block|cube|pillar|object|item|piece|one)"
GROUP_NOUNS = r"(?:blocks|cubes|pillars|objects|items|pieces)"
NOUNS = r"(?:blocks|cubes|pillars|objects|items|pieces|ones)"
COLOUR = r"(?:red|blue|yellow)"
LETTER = r"\b[e-j]\b"
PLACE_NOUN = r"(?:regions?|areas?|zones?|places?|spots?|positions?|cells?|sides?|locations?)"
# words that carry no meaning here (articles, politeness, modal verbs, the agent)
FILLER = frozenset(
    "please plan a an the solution to for you we should shall can could would will must kindly now "
    "also so it is are be that i want need make sure this task , ( ) : and however additionally moreover "
    "furthermore independently since".split()
)


@dataclass(frozen=True)
class Place:
    """A place phrase: labelled regions, per-block opposite side, any empty region, a block's start,
    or (only in prohibitions) the labelled regions other than a goal's targets or, when `regions` is
    given, other than those; a landmark ("next to arm a and arm b") only describes a place named beside
    it and must agree with it."""

    kind: Literal["regions", "opposite", "away", "start_of", "complement", "landmark"]
    regions: tuple[str, ...] = ()
    block: str = ""  # start_of: whose start
    text: str = ""


@dataclass
class Scene:
    """What the handover phrases need of a world: its layout and where each block starts."""

    layout: Layout
    starts: dict[str, Cell]  # "Red" -> cell

    @classmethod
    def of(cls, world: World) -> Scene:
        config = world.name.split("-", 1)[1] if "-" in world.name else ""
        try:
            lay = layout(config)
        except WorldError:
            raise HTTError(f"{world.name} is not a handover world (square or line)") from None
        starts = {
            o.type[: -len("Block")]: o.interaction_cells[0]
            for o in world.objects.values()
            if o.type.endswith("Block") and o.interaction_cells
        }
        return cls(lay, starts)

    @property
    def blocks(self) -> list[str]:
        return [c.capitalize() for c in COLOURS if c.capitalize() in self.starts]

    def side(self, cell: Cell) -> int | None:
        """0: only arms a/b reach the cell; 1: only c/d; None: both sides (a shared middle cell)."""
        arms = set(self.layout.arms_reaching(cell))
        if arms <= {0, 1}:
            return 0
        if arms <= {2, 3}:
            return 1
        return None

    def opposite(self, block: str) -> tuple[str, ...]:
        side = self.side(self.starts[block])
        if side is None:
            raise HTTError(
                f"'the opposite' is unclear for the {block.lower()} block: it starts between the sides"
            )
        return tuple(
            r for r in REGIONS if r in self.layout.regions and self.side(self.layout.regions[r]) == 1 - side
        )

    def arms_side(self, arms: list[int]) -> tuple[str, ...]:
        return tuple(r for r in REGIONS if set(self.layout.arms_reaching(self.layout.regions[r])) & set(arms))

    def start_region(self, block: str) -> str:
        cell = self.starts[block]
        if cell not in self.layout.region_at:
            raise HTTError(f"the {block.lower()} block does not start on a labelled region")
        return self.layout.region_at[cell]

    def block(self, colour: str) -> str:
        name = colour.capitalize()
        if name not in self.starts:
            raise HTTError(f"there is no {colour} block in this world; blocks: {', '.join(self.blocks)}")
        return name


@dataclass
class Marked:
    """A sentence with its phrases replaced by placeholders (`B0`, `P0`, `A`)."""

    text: str
    blocks: list[list[str]] = field(default_factory=list)  # B<k> -> block names
    block_text: list[str] = field(default_factory=list)
    places: list[Place] = field(default_factory=list)  # P<k>
    notes: list[str] = field(default_factory=list)  # one-per-region statements, read as the world's rule
    last_one: str = ""  # the last single block the sentence names (what "it" means in the next)
    last_regions: tuple[str, ...] = ()  # the last regions it names ("regions other than these" in the next)

    def sub(self, pattern: str, make) -> None:  # make(match) -> replacement text
        self.text = re.sub(pattern, make, self.text)


TYPOS = typo_table()


def normalise(sentence: str) -> str:
    """Lower case, punctuation spaced out, typos mended and `REWRITES` applied."""
    text = sentence.lower().replace("’", "'")
    text = re.sub(r"(?<=[a-z])-(?=[a-z])", " ", text)  # one-by-one -> one by one
    text = re.sub(r"([,()/:])", r" \1 ", text)
    text = re.sub(r"\b(\w+)'s\b", r"\1 s", text)  # red's -> red s (a possessive)
    text = re.sub(r"[a-z]+", lambda w: TYPOS.get(w.group(0), w.group(0)), text)
    for pattern, replacement in REWRITES:
        text = re.sub(pattern, replacement, text)
    return " ".join(text.split())


def mark(sentence: str, scene: Scene, before: Marked | None = None) -> Marked:
    """The sentence with its phrases marked; `before`, the sentence before, tells what 'it' and 'these
    regions' may mean."""
    previous = before or Marked("")
    m = Marked(normalise(sentence))
    _mark_one_per_region(m)
    _mark_arms(m)
    # "do not put anything on them": after a preposition of place, a pronoun names places (a cell holds
    # one block, so nothing goes on a block); resolved once the places are marked
    m.sub(r"\b(on|onto|in|into)\s+(each\s+of\s+)?(?:them|it)\b", r"\1 \2 PLACEREF")
    _mark_blocks(m, scene, previous.last_one)
    _join_particles(m)
    # "put the three blocks there", "the yellow block is to be moved there as well"
    m.sub(rf"\b((?:{VERB}|{GERUND})\s+B\d+|B\d+\s+{MODAL}{DONE})\s+there\b", r"\1 to PLACEREF")
    _mark_places(m, scene, previous.last_regions)
    _mark_place_pronouns(m, previous.last_regions)
    _mark_capacity(m)
    named = [p.regions for p in m.places if p.kind == "regions"]
    m.last_regions = named[-1] if named else ()
    _mark_connectives(m)
    return m


def _mark_place_pronouns(m: Marked, named_before: tuple[str, ...]) -> None:
    """'them' after 'on', 'there' after a moved block: the last place named before it in the sentence, else
    the last regions the sentence before named; with neither it stays 'them' (unread, so refused). A place
    named as a heading ('regions H, I and J: put the blocks there') or defined ('regions G, H and I are the
    targets: place the blocks in them') is then read where the pronoun stands."""
    if "PLACEREF" not in m.text:
        return
    defined = rf"(?:is|are)\s+(?:the|our|your)\s+(?:targets?|goals?|destinations?|{TARGET}\s+{PLACE_NOUN})"
    m.sub(rf"\bP(\d+)\s+{defined}\s*:", r"P\1 :")
    headings: list[str] = []

    def resolve(match: re.Match[str]) -> str:
        before = re.findall(r"\bP(\d+)\b", m.text[: match.start()])
        if before:
            if re.search(rf"\bP{before[-1]}\s*:", m.text):
                headings.append(before[-1])
            return _new_place(m, m.places[int(before[-1])])
        if named_before:
            return _new_place(m, Place("regions", named_before, text="them"))
        return " them "

    m.sub(r"\bPLACEREF\b", resolve)
    for k in headings:
        m.sub(rf"\bP{k}\s*:", " ")


def _mark_capacity(m: Marked) -> None:
    """'regions H, I and J can each hold only one block': the world's own rule (a cell holds one block),
    said of named places (a pronoun after it, '..., so put one block in each of them', was resolved
    before)."""

    def note(match: re.Match[str]) -> str:
        m.notes.append("one block per region (the world's rule: a cell holds one block)")
        return " "

    m.sub(
        rf"\bP\d+\s+(?:(?:can|may|will|could)\s+)?(?:each\s+)?(?:only\s+)?(?:hold|take|fit|contain|accept)s?\s+"
        rf"(?:only\s+|just\s+|at\s+most\s+)?(?:one|a\s+single|1)\s+{NOUN}(?:\s+(?:each|apiece))?\b",
        note,
    )


def _join_particles(m: Marked) -> None:
    """A particle verb reads as the verb: 'put down the red block', 'put the red block (back) down (on G)'
    as 'put the red block (back) (on G)', 'pick the blue block up' as 'pick up the blue block'."""
    m.sub(rf"\b({VERB}|{GERUND})\s+down\b", r"\1")
    m.sub(rf"\b({VERB}|{GERUND})\s+(B\d+)\s+(back\s+)?down\b", r"\1 \2 \3")
    m.sub(r"\b(B\d+)\s+down\s+(?=(?:on|onto|in|into|at)\s)", r"\1 ")  # "..., the blue block down on H"
    m.sub(r"\b(pick|picks|picking|picked)\s+(B\d+)\s+up\b", r"\1 up \2")


def _mark_connectives(m: Marked) -> None:
    """'making sure (that)', 'ensure that', 'provided that' introduce what follows and add nothing."""
    m.sub(
        r"(?:\bwhile\s+)?\b(?:(?:making|make|be)\s+(?:sure|certain)|ensur(?:e|ing))\s+(?:that\s+)?|"
        r"\b(?:such|so)\s+that\b(?!\s+each\b)|\b(?:provided|providing|(?:on|under)\s+(?:the\s+)?condition)\s+that\b",
        " ",
    )


def drop_but(m: Marked) -> None:
    """'but' before a rule, read after the goal clauses ('move ... , but the blue block cannot be touched
    ...'): 'but' before a goal may mean an exception ('..., but the red block goes to G'), so it stays
    unread there, and so does 'all blocks but red'."""
    m.sub(r"(?:,\s*)?\bbut\b(?!\s*,?\s*(?:G\d|B\d))", " ")


def _mark_one_per_region(m: Marked) -> None:
    """'each goal region can only hold one object', 'one block per region', 'no region may hold more than
    one block', 'each in a different region': a cell holds one block in these worlds, so this is the
    world's own rule (recorded, no formula)."""
    region = r"(?:goal\s+|target\s+)?(?:region|area|zone|place|spot|cell)"
    one = (
        rf"(?:only\s+|just\s+|at\s+most\s+|no\s+more\s+than\s+|exactly\s+|max(?:imum)?\s+(?:of\s+)?)?(?:one|a\s+single|single|1)"
        rf"(?:\s+{NOUN})?"
        rf"(?:\s+of\s+(?:the\s+)?{NOUNS})?(?:\s+only)?"
    )
    hold = (
        r"(?:placed|filled|holds?|takes?|gets?|receives?|contains?|ha(?:ve|s)|fits?|accepts?|accommodates?|place|put|"
        r"ends?\s+up\s+with)"
    )
    holding = r"(?:holding|taking|getting|receiving|having|containing|accepting|accommodating)"
    patterns: tuple[str, ...] = (
        # "each goal region can only hold one object", "each region only can be placed one object", "one
        # region only one object"
        rf"(?:,\s*(?:where|in\s+which)\s+|\bwith\s+)?\b(?:each|every|an?|any|one)\s+(?:of\s+(?:the|these|those)\s+)?{region}s?\s+(?:only\s+)?(?:can|may|should|must|will)?\s*(?:only\s+)?"
        rf"(?:be\s+)?(?:{hold}\s+|{holding}\s+)?(?:only\s+)?(?:with\s+)?{one}\b",
        rf"(?:\bwith\s+)?\bno\s+{region}\s+(?:can|may|should|must|will)?\s*(?:be\s+)?"
        rf"(?:{hold}|receiving|getting|holding|having|taking)\s+(?:with\s+)?(?:more\s+than\s+"
        rf"(?:one|a\s+single|1)(?:\s+{NOUN})?|(?:two|2)\s+{NOUNS})\b",
        rf"\b(?:with\s+|placing\s+|putting\s+|there\s+(?:can|may|should|must|will)\s+be\s+)?{one}\s+(?:(?:is|being|may|can|should|must|will)\s+)?"
        r"(?:be\s+)?(?:allowed\s+|permitted\s+)?"
        rf"(?:(?:to\s+)?(?:occupy|go\s+(?:in|on|to|into)|sit\s+(?:in|on)|be\s+(?:placed\s+)?(?:in|on)|fits?\s+(?:in|on|into))\s+|"
        r"(?:per|in|on|for|to)\s+)"
        rf"(?:each|every)\s+{region}\b",
        rf"\b(?:with\s+)?{one}\s+(?:(?:is|being|may|can)\s+)?(?:allowed\s+|permitted\s+)?per\s+{region}\b",
        r"\bone\s+(?:each|apiece)\b",
        rf"(?<=,)\s*(?:with\s+)?(?:one|a\s+single)\s+{NOUN}\s+(?:each|apiece)\b",  # "..., one block each"
        rf"\b(?:with\s+)?{one}\s+(?:per|in\s+each|on\s+each|for\s+each)\b(?!\s+of\b)",
        rf"\b(?:with\s+)?no\s+two\s+{NOUNS}\s+(?:(?:may|can|should|will)\s+)?(?:sharing|share|occupy|be\s+(?:in|on))\s+"
        rf"(?:a\s+|the\s+same\s+)?{region}\b",
        rf"\beach\s+{NOUN}\s+(?:gets|has|takes|goes\s+(?:to|in|into))\s+(?:its\s+own|a\s+(?:different|separate))\s+{region}\b",
        rf"\b(?:do\s+not|never)\s+(?:put|place)\s+(?:more\s+than\s+(?:one|a\s+single)(?:\s+{NOUN})?|(?:two|2)\s+{NOUNS})\s+"
        r"(?:in|on|into|onto)\s+"
        rf"(?:a|any|each|the\s+same)\s+{region}\b",
    )

    def note(match: re.Match[str]) -> str:
        m.notes.append("one block per region (the world's rule: a cell holds one block)")
        return " "

    for pattern in patterns:
        m.sub(pattern, note)
    # "each into a different region among H, I and J", "in its own region: H, I or J"
    different = (
        rf"\b(?:each\s+)?(?:in|into|on|onto|to)\s+(?:an?\s+|its\s+|their\s+)?(?:different|separate|distinct|own)\s+"
        rf"{region}s?\s*(?:(?:among|from|of|out\s+of)\s+|:\s*)?"
    )
    m.sub(different, lambda match: note(match) + "in ")


def _mark_arms(m: Marked) -> None:
    # "until one of them touched the red block": them = the arms (the agent of touching)
    m.sub(
        rf"\b(?:one|any|either|each)\s+of\s+them\b(?=\s+(?:has\s+|have\s+|had\s+)?{_TOUCHED})",
        lambda _: " A ",
    )
    m.sub(
        r"\b(?:(?:any|one|some|either|each)\s+of\s+|any\s+|an?\s+|each\s+|every\s+|some\s+|either\s+)?(?:the\s+)?"
        r"(?:robot\s+)?(?:arms?|robots?)\b"
        r"(?!\s+[a-d]\b)",
        lambda _: " A ",
    )


def _new_block(m: Marked, names: list[str], text: str) -> str:
    m.blocks.append(names)
    m.block_text.append(text.strip())
    return f" B{len(m.blocks) - 1} "


def _mark_blocks(m: Marked, scene: Scene, previous: str) -> None:
    colours = (
        rf"\b(?:the\s+)?{COLOUR}(?:\s+{NOUN})?(?:\s+s\b)?(?:\s*(?:,|and|&|or|/)\s*(?:the\s+)?{COLOUR}(?:\s+{NOUN})?"
        rf"(?:\s+s\b)?)*(?:\s+{NOUNS})?\b"
    )

    def by_colour(match: re.Match[str]) -> str:
        """One phrase per list of colours; a colour named again ("the red and the blue block, the red block
        being ...") or a list whose last link is a bare comma ("the blue block, the red one") starts a new
        phrase there, which the next pass marks."""
        text = match.group(0)
        found = list(re.finditer(COLOUR, text))
        starts, words = [w.start() for w in found], [w.group(0) for w in found]
        links = [text[:k] for k in starts[1:]]
        cut = next((k for k in range(1, len(words)) if words[k] in words[:k]), None)
        if cut is None and links and re.search(r",\s*(?:the\s+)?$", links[-1]):
            cut = len(words) - 1
        if cut is None:
            return by_colour_text(text)
        head = re.sub(r"\s*(?:,|and|&|or)\s*(?:the\s+)?$", "", text[: starts[cut]])
        return by_colour_text(head) + text[len(head) :]

    def by_colour_text(text: str) -> str:
        names = [scene.block(c) for c in re.findall(COLOUR, text)]
        return _new_block(m, list(dict.fromkeys(names)), text)

    count = r"(?:(two|three|four|both|all|\d+)\s+)?"
    # (not "ones": "the opposite ones" names places)
    group = rf"\b(?:all\s+(?:of\s+)?)?(?:the\s+)?{count}(?:of\s+)?(?:the\s+)?{GROUP_NOUNS}\b"

    def all_blocks(match: re.Match[str]) -> str:
        count = match.group(1)
        n = len(scene.blocks)
        if count and count != "all" and COUNTS.get(count) != n:
            raise HTTError(
                f"'{match.group(0).strip()}' names {count} blocks; this world has {n}: which ones?"
            )
        return _new_block(m, scene.blocks, match.group(0))

    each = rf"\b(?:each|every|all)\s+(?:of\s+the\s+)?{count}(?:{NOUN}|{NOUNS})\b"  # not "any": one of them
    m.sub(colours, by_colour)
    m.sub(colours, by_colour)  # the phrases a repeated colour started
    # a heading that lists blocks with commas: "red, blue: any empty region" (one group)
    heading = re.match(r"\s*B(\d+)\s*,\s*B(\d+)\s*:", m.text)
    if heading and not set(m.blocks[int(heading.group(1))]) & set(m.blocks[int(heading.group(2))]):
        pair = [int(heading.group(1)), int(heading.group(2))]
        text = " , ".join(m.block_text[k] for k in pair)
        m.text = _new_block(m, [b for k in pair for b in m.blocks[k]], text) + ":" + m.text[heading.end() :]
    # "no block may be placed ...": the prohibitions read "no B"
    m.sub(rf"\bno\s+{NOUN}\b", lambda match: "no" + _new_block(m, scene.blocks, match.group(0)))
    # "a block may not be placed ...": a generic block in a prohibition is every block
    negation = r"(?=\s+(?:may|must|can|should|shall|is)\s*(?:not|never)|\s+(?:cannot|never|mustn))"
    m.sub(rf"\b(?:a|an|any)\s+{NOUN}\b{negation}", lambda match: _new_block(m, scene.blocks, match.group(0)))
    # "the object can not be put on ...": generic too, when no single block was named before it
    if not previous and not any(len(m.blocks[int(k)]) == 1 for k in re.findall(r"\bB(\d+)\b", m.text)):
        generic = rf"\b(?:the|each|every)\s+(?:block|object|item|piece|pillar|cube)\b{negation}"
        m.sub(generic, lambda match: _new_block(m, scene.blocks, match.group(0)))
    # "never place an object on ...", "do not put anything on ...": a generic object after a negated verb
    m.sub(
        rf"\b({NEG}\s+(?:{VERB}|drop|leave|lay)|placing|putting|dropping|setting)\s+(?:(?:a|an|any)\s+{NOUN}|any\s+{NOUNS}|anything)\b",
        lambda match: match.group(1) + _new_block(m, scene.blocks, match.group(0)),
    )
    # "three block" (a count with a singular noun), "be placed any object"
    m.sub(rf"\b(?:the\s+)?(two|three|four|\d+)\s+{NOUN}\b", all_blocks)
    # "all three (to I)": a count with no noun, not a count of places or arms ("all three regions")
    m.sub(
        rf"\ball\s+(two|three|four|\d+)\b(?!\s*(?:of\b|{NOUN}|{NOUNS}|{PLACE_NOUN}|arms?\b|robots?\b|[a-z]*s\b))",
        all_blocks,
    )
    m.sub(
        rf"\b(be\s+(?:placed|put|dropped|set))\s+(?:any\s+{NOUN}|anything)\b",
        lambda match: match.group(1) + _new_block(m, scene.blocks, match.group(0)),
    )
    m.sub(each, all_blocks)
    m.sub(group, all_blocks)

    def restated(match: re.Match[str]) -> str:  # "the blocks, all three of them,": the same blocks, counted
        before = re.findall(r"\bB(\d+)\b", m.text[: match.start()])
        if not before or m.blocks[int(before[-1])] != scene.blocks:
            return match.group(0)
        all_blocks(match)
        m.blocks.pop(), m.block_text.pop()
        return " "

    m.sub(r"\s*,?\s*\ball\s+(two|three|four|\d+)\s+of\s+them\b", restated)
    _mark_pronouns(m, previous)


def _mark_pronouns(m: Marked, previous: str) -> None:
    """'it' / 'them': the blocks of the nearest mention before (one block for 'it'; for 'it' with none
    in its sentence, the last single block the sentence before named)."""

    def resolve(match: re.Match[str]) -> str:
        head = m.text[: match.start()]
        # not the block just before an "after"/"before" ("the blue block after it": it is not the blue block)
        head = re.sub(r"\bB\d+\s+(?:after|before|than|behind)\s*$", " ", head)
        before = [int(k) for k in re.findall(r"\bB(\d+)\b", head)]
        fits = [k for k in before if match.group(0) != "it" or len(m.blocks[k]) == 1]
        if fits:
            return _new_block(m, m.blocks[fits[-1]], match.group(0))
        return (
            _new_block(m, [previous], match.group(0))
            if previous and match.group(0) == "it"
            else match.group(0)
        )

    def pair(match: re.Match[str]) -> str:  # "while exchanging their positions": the two blocks named
        named = [b for k in re.findall(r"\bB(\d+)\b", m.text[: match.start()]) for b in m.blocks[int(k)]]
        if len(set(named)) != 2 or re.search(r"B\d+\s+(?:should\s+|must\s+)?$", m.text[: match.start()]):
            return match.group(0)  # not two, or the pair is the subject: "X and Y exchange their positions"
        return match.group(1) + _new_block(m, list(dict.fromkeys(named)), match.group(2))

    m.text = re.sub(rf"\b({SWAP}\s+)(them|their)\b", pair, m.text)
    # "while the two exchange positions": the two blocks named before
    m.text = re.sub(
        rf"\b()(the\s+two|both\s+of\s+them|the\s+pair)(?=\s+(?:should\s+|must\s+|will\s+)?{SWAP})",
        pair,
        m.text,
    )
    m.text = re.sub(r"\b(?:it|them|they)\b", resolve, m.text)
    # "red and blue: move them to any empty region": the heading is what "them" names
    heading = re.match(r"\s*B(\d+)\s*:", m.text)
    if heading and any(
        m.blocks[int(k)] == m.blocks[int(heading.group(1))] for k in re.findall(r"\bB(\d+)\b", m.text)[1:]
    ):
        m.text = m.text[heading.end() :]
    singles = [m.blocks[int(k)] for k in re.findall(r"\bB(\d+)\b", m.text) if len(m.blocks[int(k)]) == 1]
    m.last_one = singles[-1][0] if singles else ""


def _new_place(m: Marked, place: Place) -> str:
    m.places.append(place)
    return f" P{len(m.places) - 1} "


def _mark_places(m: Marked, scene: Scene, named_before: tuple[str, ...]) -> None:
    _mark_target_complements(m)
    _mark_starts(m, scene)
    m.sub(
        r"\b(?:the\s+)?(?:opposite(?:\s+(?:side|sides|end|regions?|areas?|zones?|ones?))?|(?:far|other|facing)\s+"
        r"(?:side|sides|end|regions?|areas?|zones?))(?:\s+(?:regions?|areas?))?"
        r"(?:\s+of\s+the\s+(?:table|workspace|work\s+area|board))?\b",
        lambda match: _new_place(m, Place("opposite", text=match.group(0).strip())),
    )
    m.sub(
        rf"\b(?:(?:any|an|some|a)\s+)?(?:other\s+)?{EMPTY}\s+{PLACE_NOUN}\b",
        lambda match: _new_place(m, Place("away", text=match.group(0).strip())),
    )
    _mark_arm_sides(m, scene)
    _mark_region_lists(m, scene)
    # "the placement area (on the side of) P", "any region except P", "those regions": the place named
    count = r"(?:(?:two|three|four|\d+)\s+)?"
    named = rf"\b(?:the\s+)?{count}(?:{TARGET}\s+(?:regions?|areas?|zones?)|areas?|zones?|regions)"
    m.sub(rf"{named}\s*,?\s*(?:{APPOSITION}\s*)?,?\s*(?=P\d)", " ")
    m.sub(
        rf"\b(?:(?:the|an?|any|all)\s+)?(?:other\s+)?{PLACE_NOUN}\s+{OTHER_THAN}\s+P(\d+)|\boutside\s+(?:of\s+)?P(\d+)",
        lambda match: _complement_of(m, match),
    )

    def other_than_these(match: re.Match[str]) -> str:  # the labelled regions but the ones just named
        lists = [p.regions for p in m.places if p.kind == "regions"] or [named_before]
        if not lists[-1]:
            return match.group(0)
        return _new_place(m, Place("complement", lists[-1], text=match.group(0).strip()))

    m.sub(
        rf"\b(?:(?:the|any|all|an?)\s+)?(?:other\s+)?{PLACE_NOUN}\s+{OTHER_THAN}\s+(?:these|those|them|the\s+ones\s+(?:named|above))\b",
        other_than_these,
    )
    m.sub(
        rf"\b(?:those|these|the\s+same|said)\s+{PLACE_NOUN}\b",
        lambda match: _new_place(m, m.places[-1]) if m.places else match.group(0),
    )
    # a place named twice ("region G (where the red block is)", "area (E, F, G) to the side of arm a",
    # "next to arm a and arm b, that is region E, F and G"): both readings must agree
    # ("from P to Q" names a source and a goal: not a place named twice)
    apposition = rf"(?<!from)(?<=\S)(\s+)P(\d+)\s*,?\s*{APPOSITION}?\s*,?\s*P(\d+)\s*\)?"
    while re.search(apposition, m.text):
        m.sub(apposition, lambda match: match.group(1) + _merge(m, int(match.group(2)), int(match.group(3))))


TARGET = r"(?:goal|target|placement|destination|assigned)"
OTHER_THAN = r"(?:other\s+than|except(?:\s+for)?|besides|apart\s+from|but|outside(?:\s+of)?)"


def _mark_target_complements(m: Marked) -> None:
    """'an area other than the target region', 'anywhere else', 'any other region': in a prohibition,
    every labelled region but the goals' targets."""
    non_target = (
        rf"\b(?:an?\s+|any\s+)?non\s+{TARGET}\s+{PLACE_NOUN}\b|\b(?:the\s+|all\s+(?:the\s+)?|any\s+(?:of\s+the\s+)?)?"
        rf"(?:remaining|rest\s+of\s+the)\s+{PLACE_NOUN}\b"
    )
    targets = (
        rf"(?:the\s+|their\s+|its\s+|an?\s+|one\s+of\s+the\s+)?(?:{TARGET}\s+{PLACE_NOUN}|targets?|goals?)\b"
    )
    complement = (
        rf"\b(?:the\s+|an?\s+)?(?:any\s+)?(?:other\s+)?(?:{PLACE_NOUN}|anywhere)\s+(?:{OTHER_THAN}|that\s+(?:is|are)\s+not)\s+"
        rf"{targets}|\boutside\s+(?:of\s+)?{targets}|\b(?:(?:any\s+|an\s+)?other|another)\s+{PLACE_NOUN}\s+than\s+{targets}|"
        rf"\b(?:any|all)\s+other\s+{PLACE_NOUN}\b|{non_target}"
    )

    def other_than(match: re.Match[str]) -> str:  # "anywhere other than ...", "elsewhere": with its "on"
        on = " on " if re.match(r"anywhere|elsewhere|outside", match.group(0)) else ""
        return on + _new_place(m, Place("complement", text=match.group(0).strip()))

    m.sub(complement + r"|\b(?:anywhere\s+else|elsewhere)\b", other_than)


def _complement_of(m: Marked, match: re.Match[str]) -> str:
    """'any region except E, F and G', 'outside E, F and G': the labelled regions but those."""
    named = m.places[int(match.group(1) or match.group(2))]
    if named.kind != "regions":
        raise HTTError(f"cannot tell which regions '{match.group(0).strip()}' leaves out")
    on = " on " if match.group(2) else ""
    return on + _new_place(m, Place("complement", named.regions, text=match.group(0).strip()))


def _mark_starts(m: Marked, scene: Scene) -> None:
    """'where the red block is', 'the original position of the red block': the region it starts on."""

    def start_of(match: re.Match[str], group: int = 1) -> str:
        k = int(match.group(group))
        if len(m.blocks[k]) != 1:
            return match.group(0)
        block = m.blocks[k][0]
        return _new_place(m, Place("start_of", (scene.start_region(block),), block, match.group(0).strip()))

    where = (
        r"(?:\b(?:to|in|into|on|onto|at)\s+)?\(?\s*\bwhere\s+B(\d+)\s+(?:currently\s+|now\s+|initially\s+)?"
        r"(?:is|was|lies|lay|sits|sat|stands|started|starts|locates|stays|rests)\s*"
        r"(?:currently\s+|now\s+|"
        r"initially\s+|at\s+first\s+)?(?:located|locating|lying|placed|sitting|standing|from)?\s*"
        r"(?:currently|now|initially|at\s+first|at\s+the\s+start)?\s*\)?"
    )

    def where_of(match: re.Match[str]) -> str:  # "back (to) where the red block is": a place to go to
        place = start_of(match)
        return match.group(0) if place == match.group(0) else " to " + place

    m.sub(where, where_of)
    start = r"(?:original\s+|initial\s+|starting\s+|start\s+)?(?:position|place|spot|location|cell|region)"
    m.sub(rf"\b(?:the\s+)?{start}\s+of\s+B(\d+)\s*(?=\W|$)", start_of)

    # "to the blue block's position" (the possessive may be read with the block)
    def possessive(match: re.Match[str]) -> str:
        place = start_of(match, 2)
        return match.group(0) if place == match.group(0) else match.group(1) + place

    m.sub(rf"\b((?:to|into|onto|on|in|at)\s+)B(\d+)\s+(?:s\s+)?{start}\b", possessive)


def _mark_arm_sides(m: Marked, scene: Scene) -> None:
    """'the side of arm a and arm b' (a place), 'next to arm a and arm b' (a landmark beside a place)."""

    def arms(match: re.Match[str]) -> str:
        letters = re.findall(r"\b[a-d]\b", re.sub(r"side of|reach of", "", match.group(0)))
        regions = scene.arms_side(["abcd".index(x) for x in letters])
        side = (
            "side" in match.group(0) or re.search(r"(?:area|region|zone)s?\s+of", match.group(0)) is not None
        )
        kind: Literal["regions", "landmark"] = "regions" if side else "landmark"
        if re.match(r"on|of|at", match.group(0)) and kind == "landmark":  # "on arm a" names no place
            return match.group(0)
        return _new_place(m, Place(kind, regions, text=match.group(0).strip()))

    m.sub(
        r"\b(?:(?:the\s+)?sides?\s+of|(?:the\s+)?(?:goal\s+|target\s+|placement\s+)?(?:area|region|zone)s?\s+of|"
        r"next\s+to|beside|by|near|close\s+to|in\s+front\s+of|within\s+reach\s+of|"
        r"reachable\s+by|adjacent\s+to|on|of|at)\s+(?:the\s+)?arms?\s+[a-d](?:\s*(?:,|and|&)\s*(?:the\s+)?(?:arm\s+)?[a-d])*"
        r"(?:(?:\s+s)?\s+sides?)?\b",
        arms,
    )
    # "the a/b side", "the side of a and b" without the word "arm"
    m.sub(
        r"\b(?:the\s+)?(?:arms?\s+)?[a-d]\s*(?:/|&|and|,)\s*(?:arm\s+)?[a-d]\s+(?:arms?\s+)?(?:s\s+)?sides?\b",
        lambda match: _new_place(
            m, Place("regions", _sides(scene, match.group(0)), text=match.group(0).strip())
        ),
    )


def _sides(scene: Scene, text: str) -> tuple[str, ...]:
    return scene.arms_side(["abcd".index(x) for x in re.findall(r"\b[a-d]\b", text)])


def _mark_region_lists(m: Marked, scene: Scene) -> None:
    """'region H, I and J', 'the goal regions G/H/I', and bare letters after a preposition ('on I')."""

    def regions(match: re.Match[str]) -> str:
        letters = [x.upper() for x in re.findall(LETTER, match.group("list"))]
        unknown = [x for x in letters if x not in scene.layout.regions]
        if unknown:
            raise HTTError(f"no region {', '.join(unknown)} in handover-{scene.layout.name}")
        text = match.group(0)[len(match.group("prep") or "") :]
        count = re.match(r"\s*(?:the\s+)?(two|three|four|\d+)\s", text)
        if count and COUNTS.get(count.group(1)) != len(set(letters)):
            raise HTTError(f"'{text.strip()}' says {count.group(1)} regions but names {len(set(letters))}")
        place = _new_place(m, Place("regions", tuple(dict.fromkeys(letters)), text=text.strip()))
        return (match.group("prep") or "") + place

    link = rf"(?:\s*(?:,|\band\b|\bor\b|\bat\b|&|/|\(|\)))*\s*(?:\b(?:{TARGET}\s+)?{PLACE_NOUN}\s+)?"
    lead = (
        rf"(?P<prep>)\b(?:the\s+)?(?:(?:two|three|four|\d+)\s+)?(?:{TARGET}\s+)?"
        rf"{PLACE_NOUN}\s*(?::\s*)?(?:\(\s*)?(?:at\s+)?(?:{PLACE_NOUN}\s+)?"
    )
    bare = r"(?P<prep>\b(?:to|into|onto|on|in|at|among|over|between|than|except|besides|from|outside)\s+)"
    letters = LETTER + r"(?:" + link + LETTER + r")*(?:\s*\))?"
    m.sub(rf"{lead}(?P<list>{letters})(?:\s+at\b(?=\s*,))?", regions)
    m.sub(rf"{bare}(?P<list>{letters})", regions)
    # telegraphic: "yellow: I, then G" (a letter after a block's heading, or after "then" ending a clause)
    m.sub(rf"(?P<prep>\bB\d+\s*:\s*)(?P<list>{letters})(?=\s*(?:$|,))", regions)
    m.sub(rf"(?P<prep>\bthen\s+)(?P<list>{LETTER})(?=\s*(?:$|,))", regions)
    # a bare list of two or more letters ("F, G, H stay empty"): regions anywhere (one letter may be "I")
    listed = LETTER + r"(?:(?:\s*(?:,|\band\b|\bor\b|&|/))+\s*" + LETTER + r")+"
    m.sub(rf"(?P<prep>)(?P<list>{listed})", regions)


def _merge(m: Marked, i: int, j: int) -> str:
    if m.places[i].kind != "regions":  # keep the named regions; the other reading must agree with them
        i, j = j, i
    a, b = m.places[i], m.places[j]
    agree = a.kind == "regions" and b.kind in ("regions", "start_of", "landmark")
    if not agree or set(a.regions) != set(b.regions):
        raise HTTError(f"'{a.text}' and '{b.text}' name different places")
    return f" P{i} "
