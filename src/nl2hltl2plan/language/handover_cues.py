"""A form-independent reading of a handover sentence, the fallback where the form reader refuses.

The handover world's goals are said with a small closed vocabulary: blocks (with counts), places (named
regions, the opposite side, any empty region), exchanges, orders, touch guards, prohibitions, "at any
time", "one after another". Whatever the sentence's form (a question, a passive, fronted places, a list
item, a note), its content is what these words name and how they relate. `restate(marked)` reads a sentence
whose phrases `handover_phrases.mark` has already resolved (blocks `B<k>`, places `P<k>`) as a bag of cues
per chunk (the parts between commas, colons, semicolons, parentheses, "while", "with" and "without") and
says it again in the plain words the form reader reads ("move the three blocks to the opposite side", "the
red block should be placed before the blue block", "no arm may touch the blue block until the red block has
been touched", "..., and no object may be placed on regions F, G and H during this period"). The form
reader then reads that restatement and builds and checks the spec, so both readers share one meaning.

It is guarded as check 1 is: every word of a chunk is a cue it uses or a word that carries no meaning here
(an article, an auxiliary, a preposition, a politeness or question word); any other word, a negation it
cannot place, a block it cannot pair with a place, or a chunk of two readings returns None (refused).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from nl2hltl2plan.language.handover_scene import Marked, Place, Scene

# multi-word cues first, each read as one token (longest first where they overlap)
_PHRASES: tuple[tuple[str, str], ...] = (
    (r"(?:it )?does not matter (?:at )?(?:what time|when)(?: (?:that|this|it) happens)?", "ANYTIME"),
    (r"at (?:any|whatever) (?:time|point|moment)(?: (?:that )?suits(?: you)?)?"
     r"(?: during (?:the|this) task)?", "ANYTIME"),
    (r"any ?time|whenever(?: you like| convenient)?", "ANYTIME"),
    (r"one after (?:another|the other)|one by one|one at a time|in turn", "SEQ"),
    (r"after all (?:of )?(?:that|this|these|of them)|last of all|at the (?:very )?end|in the end|finally",
     "AFTERALL"),
    (r"(?:when|once|as soon as) (?:that|this|all (?:of )?(?:this|that)|everything) (?:is|has been) (?:all )?"
     r"(?:done|completed|finished)", "AFTERALL"),
    (r"(?:once|when) (?:everything|all (?:of )?(?:them|the blocks)) (?:is|are|has been|have been) "
     r"(?:done|moved|in place|over there|across)", "AFTERALL"),
    # "when you have put X on I, put it on G": X first, then the other goal; "when you move X to P, place red
    # before blue": the goal the rest of the sentence constrains (`_Reading.said` checks both)
    (r"(?:when|once|after|as soon as) (?:you|we) (?:have|had)", "WHENDONE"),
    (r"when (?:you|we)", "WHEN"),
    (r"(?:and )?after that|afterwards|thereafter|subsequently|(?:and )?then|next", "THEN"),
    # "initially put ...": the step said first (never "where it is initially": a scene, no verb after it)
    (r"initially(?= (?:put|place|move|take|bring|send|carry|transfer|set)\b)", "FIRST"),
    (r"(?:begin|start) with", "FIRST"),  # "begin with the red block, then the blue block"
    (r"upon completion(?: of (?:the foregoing|this|that|all (?:of )?(?:this|that)))?", "AFTERALL"),
    (r"(?:finish|end) (?:by|with)", "FINISH"),  # after the sentence's goal before it, else after all
    (r"for the duration(?: (?:thereof|of (?:this|that|it)))?|until (?:you|we|they) (?:are )?(?:finish|done)",
     "PERIOD"),
    (r"ahead of|prior to|earlier than|before", "BEFORE"),
    (r"until|till", "UNTIL"),
    (r"after", "AFTER"),
    (r"during (?:this|the) (?:period|task)|meanwhile|in the meantime|throughout(?: the (?:job|task))?|"
     r"the whole time|(?:for as long as|while) (?:this|that) (?:is )?(?:goes|going) on|ever", "PERIOD"),
    (r"(?:swap|swaps|swapped|swapping|exchange|exchanges|exchanged|exchanging|trade|trades|switch|switches)"
     r"(?: (?:are|is))?(?: (?:their|the))?(?: (?:positions?|places?)(?: of)?)?", "EXCHANGE"),
    (r"(?:the )?(?:placing order|order of placing|order of placement|placement order)", "ORDERHEAD"),
    (r"untouched", "NEG TOUCH"),
    (r"(?:has|have|having) been|(?:has|have|had)(?= (?:touched|picked|grasped|grabbed|handled|lifted)\b)",
     "PERFECT"),  # "until red has been touched", never a goal ("have been put")
    (r"(?:has|have) to|is it possible (?:to|that)|it is possible to", " "),  # a modal
    # framing said around the content is a modal: "the idea is to move X" is "move X", "what matters is that
    # red is placed before blue" is "red must be placed before blue" ("it is required that" is a rewrite)
    (r"(?:the|my|our) (?:idea|plan|aim|intention) (?:here )?is (?:to|that)|"
     r"what (?:i|we) (?:need|want) is(?: for| that)?|what (?:matters|counts) is(?: that)?|"
     # a pseudo-cleft's head of any wish, need or task: "what needs doing / needs to be done / has to happen
     # / is needed / you (need to) do / I'd like is X" says X is to be done
     r"what (?:(?:needs|has|have) (?:doing|to (?:be done|happen))|(?:must|should|will) (?:be done|happen)|"
     r"is (?:needed|required|wanted)|(?:i|we) (?:would|d) like|(?:i|we) (?:am|are) after|"
     r"you (?:(?:need|have|ought) to |must |should |will |are to |re to )?do) is(?: for| that| to)?", "must"),
    (r"(?:it is )?(?:forbidden|prohibited|not (?:allowed|permitted))(?: to)?", "NEG"),  # a prohibition
    (r"(?:empty|free|clear) of(?: new| any| other)?", "CLEAR"),  # "empty of new objects": of every block
    (r"any objects?", "ANY"),  # "it is forbidden to place any object on ...": with a negation, no object
    (r"and so (?:on|forth)|etc|et cetera", "ETC"),  # more of the same: what?
    (r"(?:by )?no (?:A|arm)|none of you", "NEG ARM"),  # "none of you touches ...": the arms addressed
    (r"(?:any|one|either|some) of you", "ARM"),
    # "touched by / with any arm"
    (r"(?:by |with )?(?:any|one) (?:of the )?(?:A|arm)|(?:by|with) A|A", "ARM"),
)
_WORDS = {
    "MOVE": "move moved moves moving put puts putting place placed places placing go goes going gone carry "
    "carried carries carrying transfer transferred transfers transferring bring brought brings get gets got "
    "take taken takes set sets setting deliver delivered send sent shift shifted relocate relocated end ends "
    "up down over across come comes distribute distributed return returned returns back lay laid travel "
    "deposit deposited stack stacked stacking pile piled piling",
    "TOUCH": "touch touched touches touching pick picked picking grasp grasped grab grabbed handle handled "
    "lift lifted",
    "NEG": "no not never nothing without none",
    "KEEP": "keep keeping kept stay stays remain remains leave leaving left",
    "CLEAR": "empty free clear unoccupied",
    "FIRST": "first",
    "RECEIVE": "receive receives",  # only with a negation: "regions F, G and H receive nothing"
    "POS": "positions position spots",
    "WANT": "need needs want wanted",
    "ANY": "anything object objects",
    "THERE": "there",
}
_CLASS = {w: cls for cls, words in _WORDS.items() for w in words.split()}
# words that carry no meaning in this world: articles, auxiliaries, modals, pronouns, prepositions,
# politeness and question words (the courtesy words of `courtesy.txt` never reach here: `handover_phrases`
# reads them as "please" and drops it)
_EMPTY = frozenset(
    "a an the is are be being do does on in by of from at for "
    "this that these those you we us our your "
    "like just also so as well here make sure possible okay ok "
    "and or what how job task arms robot robots mind you all of there's checklist things todo list "
    "steps tasks notes cause operator "
    "with".split()  # left in a chunk only as an exchange's "with" ("swap B0 with B1": `_SPLIT`)
)
_BLOCK = re.compile(r"B\d+")
# chunks end at punctuation, "while", "with" (but "swap B0 with B1": the exchange's pair), before "without",
# and at "and" but in a list of blocks ("B0 and B1"); the separators are kept: a colon ends a heading
_SPLIT = r"([,;:()]|\bwhile\b|\bwhilst\b|(?<!EXCHANGE B\d )\bwith\b|(?=\bwithout\b)|(?<!B\d )\band\b)"
_TOWARDS = frozenset("to onto into towards toward".split())
_MODAL = frozenset("should must shall will would could can may might".split())


@dataclass
class _Chunk:
    blocks: list[int] = field(default_factory=list)  # B<k>
    places: list[int] = field(default_factory=list)  # P<k>
    cues: list[str] = field(default_factory=list)  # in order, with "B<k>" / "P<k>" between them
    # what makes a block and a place a goal rather than a scene ("3 blocks, opposite side" may be either):
    # a placing verb (a cue), a preposition of direction, a modal, or a heading's colon before the place
    towards: bool = False
    modal: bool = False
    heading: bool = False
    after_with: bool = False  # "to the opposite side with the three blocks": the blocks taken there

    def has(self, *cls: str) -> bool:
        return any(c in self.cues for c in cls)


@dataclass
class _Goal:
    blocks: list[str]
    places: list[Place]
    marker: str = ""  # "first", "then", "after_all"
    anytime: bool = False
    seq: bool = False


def restate(m: Marked, scene: Scene) -> str | None:
    """The sentence `m` said again in the form reader's plain words, or None where some word of it is not a
    cue this reading uses (see the module docstring)."""
    parts = re.split(_SPLIT, _tokens(m.text))
    reading = _Reading(m, scene)
    for k in range(0, len(parts), 2):
        c = _chunk(parts[k])
        if c is None:
            return None
        c.heading = k > 0 and parts[k - 1] == ":"
        c.after_with = k > 0 and parts[k - 1] == "with"
        if (c.blocks or c.places or c.cues) and not reading.take(c):
            return None
    return reading.said()


# each cue as a whole-word pattern, compiled once
_PHRASE_CUES = tuple(
    (re.compile(rf"(?<![\w])(?:{pattern})(?![\w])"), f" {token} ") for pattern, token in _PHRASES
)


def _tokens(text: str) -> str:
    """The sentence with its multi-word cues as single tokens."""
    text = " ".join(text.split())  # the phrase layer's marks come with spaces around them ("with  A")
    for cue, token in _PHRASE_CUES:
        text = cue.sub(token, text)
    return " ".join(text.split())


def _chunk(text: str) -> _Chunk | None:
    out = _Chunk()
    words = text.split()
    if words[:1] == ["but"] and words[1:2] and "NEG" in (words[1], _CLASS.get(words[1])):
        words = words[1:]  # "..., but no arm may touch ...": a contrast that adds a prohibition
    for word in words:
        if re.fullmatch(r"B\d+", word):
            out.blocks.append(int(word[1:]))
            out.cues.append(word)
        elif re.fullmatch(r"P\d+", word):
            out.places.append(int(word[1:]))
            out.cues.append(word)
        elif word.isupper():
            out.cues.append(word)
        elif word in _TOWARDS:
            out.towards = True
        elif word in _MODAL:
            out.modal = True
        elif word in _CLASS:
            out.cues.append(_CLASS[word])
        elif word not in _EMPTY:
            return None
    return out


class _Reading:
    """The facts of one sentence, chunk by chunk."""

    def __init__(self, m: Marked, scene: Scene) -> None:
        self.m, self.scene = m, scene
        self.goals: list[_Goal] = []
        self.orders: list[tuple[str, str]] = []
        self.touches: list[tuple[str, str]] = []  # (guarded, first)
        self.forbidden: list[Place] = []
        self.swaps: list[tuple[str, str]] = []
        self.leader = ""
        self.last_moved: list[str] = []  # the blocks of the last goal or exchange ("red first" after it)
        self.followed = False  # "red first, blue after": the leader's order is said
        self.step = ""
        self.group: list[str] = []  # blocks said alone, waiting for their place
        self.group_moved = False  # the group said with a verb of moving or a modal ("X should be stacked")
        self.place: list[Place] = []  # places said alone, waiting for their blocks
        self.place_towards = False  # said with a preposition of direction ("onto region I, ...")
        self.mods: set[str] = set()  # a chunk of its own: "at any time", "one after another"
        self.when = ""  # "WHEN" / "WHENDONE": a goal said in a "when you (have) ..." clause

    def blocks(self, k: int) -> list[str]:
        return list(self.m.blocks[k])

    def take(self, c: _Chunk) -> bool:
        if c.has("WHEN", "WHENDONE"):
            return self._when(c)
        if self.m.notes and not (c.blocks or c.places) and c.cues and set(c.cues) <= {"MOVE", "KEEP"}:
            return True  # the verb of the one-per-region rule: "place no more than one block on each region"
        if c.cues and set(c.cues) <= {"FIRST", "THEN"}:  # a step's number ("1)", "then,") before its clause
            if self.step or self.goals or self.orders or self.touches or self.swaps:
                return False
            self.step = "first" if c.cues == ["FIRST"] else "then" if c.cues == ["THEN"] else ""
            return bool(self.step)
        if c.has("NEG"):
            return self._negated(c)
        if c.has("EXCHANGE"):
            return self._exchange(c)
        if c.has("TOUCH"):
            return self._touch(c, negated=False)
        if c.has("KEEP", "CLEAR"):
            return self._kept(c)
        if c.places:
            return self._goal(c)
        if c.blocks:
            return self._blocks_only(c)
        return self._modifiers(c)

    def _when(self, c: _Chunk) -> bool:
        """'when you (have) V X ...' opening the chunk: its goal or exchange, once in a sentence."""
        said = len(self.goals) + len(self.swaps)
        if self.when or c.cues[0] not in ("WHEN", "WHENDONE") or said and c.cues[0] == "WHENDONE":
            return False
        self.when, c.cues = c.cues[0], c.cues[1:]
        if c.has("WHEN", "WHENDONE") or not self.take(c):
            return False
        return len(self.goals) + len(self.swaps) == said + 1

    # ----- goals --------------------------------------------------------------------------------------
    def _goal(self, c: _Chunk) -> bool:
        places = [self.m.places[k] for k in c.places]
        if len(places) == 2 and (places[0].kind, places[0].regions) == (places[1].kind, places[1].regions):
            places = places[:1]  # "to regions E, F and G, on the side of arms a and b": one place said twice
        if [p.kind for p in places] == ["complement"] and c.cues == [f"P{c.places[0]}"]:
            # "other regions: no objects placed": the place waits for its prohibition
            self.place, self.place_towards = places, False
            return True
        if any(p.kind not in ("regions", "opposite", "away") for p in places):
            return False
        if c.has("BEFORE", "AFTER", "UNTIL", "ORDERHEAD", "THERE", "ARM", "ANY", "RECEIVE"):
            return False
        if c.has("WANT") and (not c.blocks or c.cues.index("WANT") > c.cues.index(f"B{c.blocks[0]}")):
            return False  # "the three blocks we need on H, I and J": a noun and its relative clause
        rest = [x for x in c.cues if x not in ("MOVE", "BACK", "WANT") and not re.fullmatch(r"[BP]\d+", x)]
        if len(c.blocks) > 1:
            return False
        blocks = self.blocks(c.blocks[0]) if c.blocks else []
        if blocks and blocks == self.group:  # "the red and blue blocks, put them on ...": the topic taken up
            self.group = []
        if not blocks:
            # "the three blocks, move to ...": subject, topic or the arms addressed?
            if self.group and (c.heading or not c.has("MOVE")):
                blocks, self.group = self.group, []
                # "X should be stacked, one at a time, on region I": the group's verb says it is a goal
                c.modal |= self.group_moved
            elif len(places) == 1 and not rest:
                self.place = places  # "regions H, I and J: the three blocks go there"
                self.place_towards = c.towards
                return True
            elif self.goals and len(self.goals[-1].blocks) == 1 and rest[:1] == ["THEN"] and len(places) == 1:
                blocks = self.goals[-1].blocks  # "... to region I, and after that to region G"
            else:
                return False
        said_as_goal = c.has("MOVE", "WANT") or c.towards or c.modal or (c.heading and not c.blocks)
        if not (said_as_goal or rest[:1] == ["THEN"]):
            return False  # "3 blocks, opposite side": where they go, or where they are?
        return self._goal_steps(blocks, places, rest)

    def _goal_steps(self, blocks: list[str], places: list[Place], rest: list[str]) -> bool:
        mods = {"ANYTIME", "SEQ", "FIRST", "THEN", "AFTERALL", "FINISH"}
        if any(x not in mods for x in rest) or len(set(rest)) != len(rest):
            return False
        if len(places) == 2:  # "goes first to region I and after that to region G": one block, two steps
            if len(blocks) != 1 or "THEN" not in rest or set(rest) - {"FIRST", "THEN"}:
                return False
            self.goals += [_Goal(blocks, [places[0]], "first"), _Goal(blocks, [places[1]], "then")]
            self.last_moved = blocks
            return True
        if "FINISH" in rest:  # "begin by X and finish by Y": Y after X; "..., finish by Y" alone: after all
            rest = [("THEN" if self.goals else "AFTERALL") if x == "FINISH" else x for x in rest]
        marker = "after_all" if "AFTERALL" in rest else "then" if "THEN" in rest else ""
        if "FIRST" in rest:  # the step said first ("first move the three blocks ...")
            if marker:
                return False
            marker = "first"
        self.goals.append(_Goal(blocks, places, marker, "ANYTIME" in rest, "SEQ" in rest))
        self.last_moved = blocks
        return True

    def _blocks_only(self, c: _Chunk) -> bool:
        cues = [x for x in c.cues if x != "MOVE"]
        taken = c.has("THERE") or self.place_towards and (c.has("MOVE") or c.after_with)
        if self.place and len(c.blocks) == 1 and taken:
            # "regions H, I and J: the blocks go there"; "onto region I, one after another, go the blocks"
            rest = [x for x in cues if x != "THERE" and not _BLOCK.fullmatch(x)]
            place, self.place = self.place, []
            return self._goal_steps(self.blocks(c.blocks[0]), place, rest)
        if cues == [f"B{c.blocks[0]}"] and len(c.blocks) == 1:
            if self.place:  # "region I: ... the three blocks go there"
                return False
            blocks = self.blocks(c.blocks[0])
            if self.goals and not self.goals[-1].blocks:
                return False
            self.group = blocks
            self.group_moved = c.has("MOVE") or c.modal
            return True
        return self._order(c)

    def _exchange(self, c: _Chunk) -> bool:
        names = [b for k in c.blocks for b in self.blocks(k)]
        extra = [x for x in c.cues if x not in ("EXCHANGE", "MOVE", "POS") and not _BLOCK.fullmatch(x)]
        if c.places or len(names) != 2 or len(set(names)) != 2 or extra:
            return False
        self.swaps.append((names[0], names[1]))
        self.last_moved = names
        return True

    # ----- orders and touch guards ------------------------------------------------------------------
    def _order(self, c: _Chunk) -> bool:
        singles = [self.blocks(k) for k in c.blocks]
        if any(len(b) != 1 for b in singles) or c.places:
            return False
        names = [b[0] for b in singles]
        cues = [x for x in c.cues if x not in ("MOVE", "ORDERHEAD")]
        shape = _shape(cues)
        if shape in ("B BEFORE B", "FIRST B THEN B", "B FIRST B THEN", "B FIRST B AFTER", "B FIRST THEN B"):
            self.orders.append((names[0], names[1]))
        elif shape == "B AFTER B":
            self.orders.append((names[1], names[0]))
        elif shape in ("B AFTER", "B THEN", "THEN B") and self.leader and not self.followed:
            self.orders.append((self.leader, names[0]))
            self.followed = True
        elif shape in ("B FIRST", "FIRST B"):
            if self.leader:
                return False
            self.leader = names[0]
            if self.last_moved:  # "swap red and blue, red first": before the others of the clause just said
                if names[0] not in self.last_moved or len(self.last_moved) < 2:
                    return False
                self.orders += [(names[0], b) for b in self.last_moved if b != names[0]]
                self.followed = True
        else:
            return False
        return True

    def _touch(self, c: _Chunk, negated: bool) -> bool:
        """'no arm may touch X until Y has been touched', 'X untouched till Y is touched' (X waits for Y);
        'Y is picked up before X' (the same); a touch said of one block and a move of the other is not."""
        singles = [self.blocks(k) for k in c.blocks]
        if len(singles) != 2 or any(len(b) != 1 for b in singles) or c.places or c.cues.count("NEG") > 1:
            return False
        shape = _shape([x for x in c.cues if x not in ("ARM", "NEG", "PERIOD", "PERFECT")])
        x, y = singles[0][0], singles[1][0]
        touched = ("B TOUCH", "TOUCH B")
        waits = {f"{a} {rel} {b}" for a in touched for rel in ("UNTIL", "BEFORE") for b in touched}
        goes_first = {f"{a} BEFORE {b}" for a in touched for b in (*touched, "B")}
        if negated and shape in waits:
            self.touches.append((x, y))
        elif negated and shape == "UNTIL B TOUCH B TOUCH":  # "not until red has been touched may blue be"
            self.touches.append((y, x))
        elif not negated and shape in goes_first:
            self.touches.append((y, x))
        else:
            return False
        return True

    # ----- prohibitions -----------------------------------------------------------------------------
    def _negated(self, c: _Chunk) -> bool:
        if c.has("TOUCH"):
            return self._touch(c, negated=True)
        if c.cues.count("NEG") != 1 or c.has("BEFORE", "AFTER", "UNTIL", "EXCHANGE", "THEN", "KEEP", "CLEAR"):
            return False
        if any(self.blocks(k) != self.scene.blocks for k in c.blocks):
            return False  # a prohibition on some blocks only is the form reader's
        if not c.places and self.place:  # "on regions F, G and H, nothing may be placed"
            places, self.place = self.place, []
            return self._forbid(c, places)
        return self._forbid(c, [self.m.places[k] for k in c.places])

    def _kept(self, c: _Chunk) -> bool:
        """'keep regions F, G and H empty', 'F, G and H must stay clear', 'F, G, H empty meanwhile' (without
        a verb of keeping, a modal or a period, 'F, G, H empty' may say how they are now: refused)."""
        if not c.places or c.has("BEFORE", "AFTER", "UNTIL", "THEN", "FIRST"):
            return False
        if any(self.blocks(k) != self.scene.blocks for k in c.blocks):
            return False  # "keep F clear of the red block": a prohibition on some blocks only
        if not c.has("CLEAR") or not (c.has("KEEP", "PERIOD") or c.modal):
            return False
        return self._forbid(c, [self.m.places[k] for k in c.places])

    def _forbid(self, c: _Chunk, places: list[Place]) -> bool:
        kinds = ("regions", "complement")
        if len(places) != 1 or places[0].kind not in kinds or c.has("ANYTIME", "SEQ", "FIRST", "EXCHANGE"):
            return False
        if places[0].kind == "complement" and places[0].regions:  # "any region except ...": the form reader's
            return False
        self.forbidden.append(places[0])
        return True

    def _modifiers(self, c: _Chunk) -> bool:
        allowed = {"ANYTIME", "SEQ", "PERIOD", "AFTERALL", "ORDERHEAD"}
        if any(x not in allowed for x in c.cues):
            return False
        self.mods.update(x for x in c.cues if x != "ORDERHEAD")
        return True

    # ----- the restatement --------------------------------------------------------------------------
    def said(self) -> str | None:
        if self.group or self.place or not self._when_read():
            return None
        if self.mods - {"PERIOD"}:  # a timing said in a chunk of its own belongs to the sentence's one goal
            if len(self.goals) != 1 or self.swaps or "AFTERALL" in self.mods and self.goals[0].marker:
                return None
            g = self.goals[0]
            g.anytime |= "ANYTIME" in self.mods
            g.seq |= "SEQ" in self.mods
            if "AFTERALL" in self.mods:
                g.marker = "after_all"
        if "PERIOD" in self.mods and not self.forbidden:
            return None  # "meanwhile, move ...": at the same time as what?
        if self.step and self.goals:
            if self.goals[0].marker:
                return None
            self.goals[0].marker = self.step
        if self.leader and not self.followed:
            return None  # "red first" with no clause before it nor "blue after"
        goals = [self._goal_text(g) for g in self.goals]
        if any(p is None for p in goals):
            return None
        parts = [f"swap the positions of the {x.lower()} and {y.lower()} blocks" for x, y in self.swaps]
        parts += [str(p) for p in goals]
        sentences = []
        if parts:
            text = ", and ".join(str(p) for p in parts)
            if self.m.notes:
                text += ", one block per region"
            for place in self.forbidden:
                text += f", and no object may be placed on {_forbidden_text(place)} during this period"
            sentences.append(text)
        elif self.m.notes:  # the world's rule said alone ("keeping to one block per region")
            if self.orders or self.touches or self.forbidden or self.mods:
                return None
            sentences.append("one block per region")
        else:  # a prohibition in a sentence of its own guards every goal (as the form reader reads it)
            sentences += [f"no object may be placed on {_forbidden_text(p)}" for p in self.forbidden]
        sentences += [f"the {x.lower()} block should be placed before the {y.lower()} block"
                      for x, y in self.orders]
        sentences += [
            f"no arm may touch the {x.lower()} block until the {y.lower()} block has been touched"
            for x, y in self.touches
        ]
        return ". ".join(sentences) if sentences else None

    def _when_read(self) -> bool:
        """'when you V X, <order / guard / prohibition>': X is the sentence's one goal (with a second goal the
        time between them is unsaid); 'when you have V-ed X, V Y': X first, then Y, the only two goals."""
        if self.when == "WHEN":
            return len(self.goals) + len(self.swaps) == 1
        if self.when == "WHENDONE":
            if len(self.goals) != 2 or self.swaps or any(g.marker or g.anytime for g in self.goals):
                return False
            self.goals[0].marker, self.goals[1].marker = "first", "then"
        return True

    def _goal_text(self, g: _Goal) -> str | None:
        where = _place_text(g.places[0]) if len(g.places) == 1 else None
        if where is None:
            return None
        marker = {"first": "first ", "then": "then ", "after_all": "after all of these, ", "": ""}[g.marker]
        text = f"{marker}move {self._blocks_text(g.blocks)} to {where}"
        if g.seq:
            text += " one after another"
        if g.anytime:
            text += " at any time"
        return text

    def _blocks_text(self, blocks: list[str]) -> str:
        if sorted(blocks) == sorted(self.scene.blocks) and len(blocks) == 3:
            return "the three blocks"
        names = [b.lower() for b in blocks]
        if len(names) == 1:
            return f"the {names[0]} block"
        return f"the {' and '.join(names)} blocks"


def _shape(cues: list[str]) -> str:
    """'B0 BEFORE B1' -> 'B BEFORE B'."""
    return " ".join("B" if _BLOCK.fullmatch(x) else x for x in cues)


def _place_text(p: Place) -> str | None:
    if p.kind == "opposite":
        return "the opposite side"
    if p.kind == "away":
        return "any empty region"
    if p.kind == "regions" and p.regions:
        return _regions_text(p.regions)
    return None


def _forbidden_text(p: Place) -> str:
    return "any other region" if p.kind == "complement" and not p.regions else _regions_text(p.regions)


def _regions_text(regions: tuple[str, ...]) -> str:
    if len(regions) == 1:
        return f"region {regions[0]}"
    return "regions " + ", ".join(regions[:-1]) + " and " + regions[-1]
