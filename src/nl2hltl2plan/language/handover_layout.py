"""The layout of a handover instruction's lines, read before its sentences are split (`handover_reading`):

- a transcript: a time stamp opening a line ("[09:02]", "14:20 -") says when it was said, never when to do
  anything, and a speaker's tag after it ("[09:02] Dana: ...") or one that opens every line ("Sam: ...",
  twice or more) names who said it; both are dropped. The speaker names nothing the reader reads (a name,
  a role: `handover_discourse.person`; "Arms: ..." or "Red block: ..." stay, to be read as they are);
- a nested list: an indented bullet under a line goes on with that line, after a comma ("- the three
  blocks -> region I" and under it "  - one after another": "the three blocks -> region I, one after
  another"); under a line that ends a sentence ('.', '!', '?') it is a sentence of its own, and under a
  heading (':') it goes on after the colon; a step that names no place ("1. Move the blocks.") over items is
  their heading. An indented item may be lettered or numbered ("   a. on regions H, I and J"); one that is
  a labelled field ("  - order: red before blue") stays a line of its own;
- a prohibition said as a label with its command on the same line ("Don't: touch the blue block ...",
  "Never: place ...") is the command negated ("do not touch ..."); a label on a line of its own over a list
  ("Don'ts:" then "- ...", "- ...") is left as it is, unread: a negation carried into only one item would
  read the others as commands;
- a heading that says only the verb over bullets of blocks and places ("Please move the following:" over
  "- the red block to the opposite side", ...): one clause with the verb, or steps where each bullet
  opens with a time (`verb_heading_read`); a step without a place, then a heading of places over a count
  per place ("Move the three blocks. Into regions H, I and J: one apiece."): one goal
  (`places_then_count_read`);
- a later sentence opened by a bare "later (on)": after what was said before it (`later_read`, on the
  split sentences);
- clauses said in another order than they happen (`REORDERED`, per line): "after all of this, X; but first,
  Y" and "last of all, X; before that, Y" are "Y; after all of this / last of all, X".

    >>> transcript_read("[09:02] Dana: red first.\\n[09:03] Dana: blue last.")
    'red first.\\nblue last.'
    >>> nested_read("- yellow block\\n  - first to region I\\n  - then to region G")
    '- yellow block, first to region I, then to region G'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.handover_discourse import person
from nl2hltl2plan.language.handover_words import PREP, SWAP, VERB

_STAMP = re.compile(
    r"^\s*(?:\[\s*\d{1,2}:\d{2}(?::\d{2})?\s*\]|\(\s*\d{1,2}:\d{2}(?::\d{2})?\s*\)|"
    r"\d{1,2}:\d{2}(?::\d{2})?(?=\s*[-–\]]?\s+[A-Za-z]))\s*[-–]?\s*"
)
_TAG = re.compile(r"^\s*([A-Z][A-Za-z.']*(?:\s+[A-Z][A-Za-z.']*)?)\s*:\s+(?=\S)")
_BULLET = re.compile(r"^([ \t]*)(?:[-*•·]|(?<=\s)[a-z0-9][.)])\s+(.*)$")
# a step that names a verb and a group but no place, ended by a full stop ("1. Move the blocks."): over
# indented items it is their heading, as "Move the blocks:" is
_PLACELESS_STEP = re.compile(
    r"(?i)^\s*(?:(?:\d+|[a-z])[.)]\s+|[-*•·]\s+)?(?:move|put|place|transfer|bring|carry|take|relocate|shift)\s+"
    r"(?:the\s+|all\s+(?:the\s+)?)?(?:three\s+|3\s+)?(?:blocks|objects|pillars|items|cubes)\s*\.$"
)
_FIELD = re.compile(r"^[A-Za-z][\w ]{0,20}:\s")  # a labelled field ("order: red first"): a line of its own


def transcript_read(text: str) -> str:
    lines = text.splitlines()
    stamped = [_STAMP.match(line) is not None for line in lines]
    lines = [_STAMP.sub("", line, count=1) for line in lines]
    tags = [found[1] if (found := _TAG.match(line)) else None for line in lines]
    out = []
    for line, tag, was_stamped in zip(lines, tags, stamped, strict=True):
        repeated = (
            tag is not None
            and len(lines) > 1
            and tags.count(tag) >= 2
            and tags.count(tag) == sum(1 for t in tags if t is not None)
        )
        if tag is not None and (was_stamped or repeated) and person(tag):
            line = _TAG.sub("", line, count=1)
        out.append(line)
    return "\n".join(out)


def nested_read(text: str) -> str:
    out: list[str] = []
    depth: list[int] = []  # the indentation of each line of `out` (-1: not a bullet)
    for line in text.splitlines():
        bullet = _BULLET.match(line)
        indent = len(bullet[1].expandtabs(4)) if bullet else -1
        if bullet and out and indent > max(depth[-1], 0) and not _FIELD.match(bullet[2]):
            parent = out[-1].rstrip()
            if not parent.endswith((".", "!", "?")):
                out[-1] = f"{parent} {bullet[2]}" if parent.endswith(":") else f"{parent}, {bullet[2]}"
                continue
            if _PLACELESS_STEP.match(parent):  # "1. Move the blocks." over items: a heading
                out[-1] = f"{parent[:-1]}: {bullet[2]}"
                continue
        out.append(line)
        depth.append(indent)
    return "\n".join(out)


_LETTERS = r"[E-Je-j](?:\s*(?:,|\band\b|\bor\b)\s*[E-Je-j])*\b"
_GOAL_PLACE = re.compile(rf"(?i)\b(?:on|onto|to|into|in)\s+(?:regions?\s+)?({_LETTERS})")
_UNTIL_ALL_THERE = re.compile(
    r"(?i)\buntil\s+(?:(?:all\s+)?(?:the\s+)?(?:three|last|final)\s+(?:one|objects?|blocks?|pillars?|items?)|"
    r"all\s+(?:three|of\s+them)|they\s+are\s+all|they\s+have\s+all\s+been)\s+(?:(?:is|are|has\s+been|have\s+been|"
    rf"gets?|lands?)\s+)?(?:all\s+)?(?:placed\s+|put\s+)?(?:on|onto|in|at)\s+(?:regions?\s+)?({_LETTERS})"
)


def _letters(text: str) -> set[str]:
    return set(re.findall(r"\b[e-j]\b", text.lower()))


def until_all_there_read(text: str) -> str:
    """"until the last one is on region I", "until they are all on E, F and G": until the goals are met,
    as "until then", where those are the regions an earlier goal of the instruction names (other regions
    are left unread: a period the reader does not model)."""

    def period(match: re.Match[str]) -> str:
        named = _letters(match[1])
        earlier = (_letters(g[1]) for g in _GOAL_PLACE.finditer(text[: match.start()]))
        return "until then" if any(named == e for e in earlier) else match[0]

    return _UNTIL_ALL_THERE.sub(period, text)


_PROHIBITION_LABEL = re.compile(
    r"(?im)^([ \t]*(?:[-*•·][ \t]+)?)(?:do[ \t]*n['’]?t|do[ \t]+not|must[ \t]+not|never)s?[ \t]*:"
    r"[ \t]*(?=[a-z])"
)


def prohibitions_read(text: str) -> str:
    """A prohibition's label before its command on the same line is the command negated (module docstring)."""
    return _PROHIBITION_LABEL.sub(r"\1do not ", text)


# a goal for all three blocks before: "put the three objects on ...", "all three blocks go to ..."
_ALL_THREE_PLACED = re.compile(
    r"\b(?:the|all)\s+(?:three|3)\s+(?:objects|blocks|pillars|items)\b[^.;!?]*?\b(?:on|onto|to|into|in)\s+"
    r"(?:regions?|the\s+opposite|any\s+empty)\b|\b(?:put|place|move|bring|carry|transfer)\s+(?:the|all)\s+"
    r"(?:three|3)\s+(?:objects|blocks|pillars|items)\b",
    re.IGNORECASE,
)

_NOUNS = r"(?:blocks|objects|pillars|cubes|items)"
# a bullet that only names blocks: a count ("three blocks"), a group or one colour ("the red block")
_BLOCKS_ONLY = (
    r"(?:the\s+|all\s+(?:the\s+)?)?(?:(?:two|three|2|3|both)\s+)?(?:(?:red|blue|yellow)(?:\s*(?:,|and|&)\s*"
    r"(?:the\s+)?(?:red|blue|yellow))*\s+)?(?:blocks?|objects?|pillars?|cubes?|items?|ones?)|"
    r"(?:the\s+)?(?:red|blue|yellow)"
)
_BLOCK_BULLET = re.compile(rf"(?i)^\s*(?:[-*•·]|\d[.)])\s+({_BLOCKS_ONLY})\s*[.,;]?\s*$")


_PLACE_BULLET = re.compile(
    r"(?i)^\s*(?:[-*•·]|\d[.)])\s+((?:to|onto|into|on|in)\s+(?:the\s+|any\s+|regions?\s+|[e-j]\b).*)$"
)
_ENDS_WITH_BLOCKS = re.compile(rf"(?i)(?:^\s*(?:[-*•·]|\d[.)])\s+|:\s*)(?:{_BLOCKS_ONLY})\s*$")


def block_bullets_read(text: str) -> str:
    """Bullets under a heading (a line ending in ':') that each name only blocks are one list of them:
    "Exchange the positions of:" over "- the red block" and "- the blue block" is "- the red block and the
    blue block" (the heading's verb and place are then read with them: `HEADED`); a bullet that is only a
    place ("- to the opposite side") goes on with the blocks named alone on the line before it."""
    lines = text.splitlines()
    out: list[str] = []
    k = 0
    while k < len(lines):
        run: list[str] = []
        if out and out[-1].rstrip().endswith(":"):
            while k + len(run) < len(lines) and (item := _BLOCK_BULLET.match(lines[k + len(run)])):
                run.append(item[1])
        if len(run) > 1:
            out.append("- " + ", ".join(run[:-1]) + " and " + run[-1])
            k += len(run)
            continue
        place = _PLACE_BULLET.match(lines[k])
        if place and out and _ENDS_WITH_BLOCKS.search(out[-1]):  # "- three blocks", "- to the opposite side"
            out[-1] = f"{out[-1].rstrip()} {place[1]}"
        else:
            out.append(lines[k])
        k += 1
    return "\n".join(out)


# a heading with the verb and the bullet below it with the rest, joined at the colon: the words put back
# in a command's order, "Move to the opposite side: three blocks" as "Move three blocks to the opposite
# side", "The arms should place, one per region: the three objects on G, H and I" as "... place the three
# objects on G, H and I, one per region", "Swap: the red and blue blocks, red first" as "Swap the red and
# blue blocks, red first"
_LIST = rf"(?:{_BLOCKS_ONLY})(?:\s*(?:,|and|&)\s*(?:{_BLOCKS_ONLY}))*"
HEADED = tuple(
    (re.compile(pattern, re.IGNORECASE), replacement)
    for pattern, replacement in (
        (  # "Blocks to move to regions H, I and J: red, blue and yellow"
            rf"^\s*(?:the\s+)?{_NOUNS}\s+to\s+({VERB})\s+({PREP}\s+[^:]+?)\s*:\s*({_LIST})\s*$",
            r"\1 \3 \2",
        ),
        (  # "Move (these / the following) to the opposite side: three blocks"
            rf"^([^:]*?\b{VERB})(?:\s+(?:these|those|them|the\s+following(?:\s+{_NOUNS})?))?\s+({PREP}\s+[^:]+?)\s*:\s*"
            rf"({_LIST})((?:\s*,\s*[^,:]+)*)\s*$",
            r"\1 \3 \2\4",
        ),
        (
            rf"^([^:]*?\b{VERB}(?:\s+(?:down|over|across))?)(?:\s+(?:these|those|the\s+following(?:\s+{_NOUNS})?))?"
            rf"\s*((?:,\s*[^,:]+?)*)\s*:\s*(({_LIST})\s+{PREP}\s+[^:]+?)\s*$",
            r"\1 \3\2",
        ),
        (rf"^\s*({PREP}\s+[^:]+?)\s*:\s*({_LIST})\s*$", r"\2 \1"),  # "To the opposite side: three blocks"
        (
            rf"^([^:]*?\b{SWAP}(?:\s+the\s+(?:positions|places|spots)\s+of)?)\s*:\s*({_LIST}(?:\s*,[^:]*)?)$",
            r"\1 \2",
        ),
    )
)

# clauses said out of their order or joined where a sentence ends: the last step said first ("put yellow
# back on G after all of this: <the rest>", "after all of that, put yellow back on G; but first <the rest>"
# are the rest, then the last step) and a verbless goal joined by "and" ("one block per region, and the
# three blocks on regions H, I and J": the goal said alone, as after a semicolon)
REORDERED = tuple(
    (re.compile(pattern, re.IGNORECASE), replacement)
    for pattern, replacement in (
        (  # one command, then its time: not "<steps> / after all of that: <last step>"
            r"^\s*((?:put|place|move|return|bring|set)\b[^:;.,/]+?)\s+"
            r"(after\s+all\s+(?:of\s+)?(?:this|that|these|the\s+above))\s*:\s*(.+)$",
            r"\3; \2, \1",
        ),
        (
            r"^\s*(after\s+all\s+(?:of\s+)?(?:this|that|these))\s*,\s*([^;:.]+?)\s*;\s*but\s+first\s*,?\s*(.+)$",
            r"\3; \1, \2",
        ),
        (  # the last step said first, then what comes before it: "last of all, X; before that, Y" is "Y;
            # last of all, X" ("last" alone: "after that"); "it" opening Y is X's one block ("Last, the yellow
            # block goes to G; before that, it goes to I"), other pronouns are left unread
            r"(^|[.!?]\s+)(last\s+of\s+all|lastly|last|finally|at\s+the\s+(?:very\s+)?end)\s*,\s*"
            r"([^;:.!?]+?)\s*;\s*before\s+(?:that|this|then|it)\s*,?\s*(?!(?:they|them|its|their)\b)"
            r"([^;:.!?]+?)\s*(?=[.!?]|$)",
            lambda m: _last_said_first(m[1], m[2], m[3], m[4]),
        ),
        (  # a note's group, then its regions, as fragments: "three blocks; regions H, I and J; ..." (the
            # group goes to those regions)
            r"(^|:\s*)((?:the\s+|all\s+)?(?:two|three|2|3)\s+(?:blocks|pillars|objects|cubes|items))\s*;\s*"
            r"(regions?\s+[a-j](?:\s*,\s*[a-j])*(?:\s*,?\s*(?:and|or|&)\s+[a-j])?)(?![a-z])",
            r"\1\2 to \3",
        ),
        (  # "every object is used (once)" after a goal for all three: every object is placed, which that goal
            # says already (left unread where no goal before it names the three)
            r"(\s*[;,]\s*(?:and\s+)?|(?<=[.!?])\s+|^\s*)(?:every|each|all(?:\s+three)?)(?:\s+of\s+the)?\s+"
            r"(?:objects?|blocks?|pillars?|items?)\s+(?:is|are|gets?)\s+used(?:\s+(?:once|exactly\s+once|one\s+time))?"
            r"\s*(?:[.!]|(?=[;?]|$))",
            lambda m: " " if _ALL_THREE_PLACED.search(m.string[: m.start()]) else m[0],
        ),
        (
            r"\s*,\s*and\s+(?=(?:the|all|both)\s+(?:three\s+)?(?:blocks|pillars|objects)\s+(?:on|onto|in|into)\s+"
            r"(?:regions?\s+)?[e-j]\b)",
            "; ",
        ),
    )
)


_ONE_BLOCK = re.compile(
    r"^\s*((?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|cube|one))?)\b(?!\s+(?:and|&|or)\b)", re.IGNORECASE
)


def _last_said_first(start: str, last: str, step: str, before: str) -> str:
    """'Y; last of all, X' for 'last of all, X; before that, Y' (see `REORDERED`), or the words as they
    were where Y's "it" has no one block in X to stand for."""
    if re.match(r"it\b", before, re.I):
        block = _ONE_BLOCK.match(step)
        if block is None:
            return f"{start}{last}, {step}; before that, {before}"
        before = block[1] + before[2:]
    return f"{start}{before}; {'after that' if last.lower() == 'last' else last}, {step}"


# a heading that says only the verb ("Please move the following:", "The arms should move:") over bullets
# that each name blocks and their place: the heading's one verb over its list. Bullets that each open with a
# time ("- first, ...", "- then, ...", "- at any time, ...") are steps, each said with the verb; bullets
# without one are one clause ("move X to P and Y to P": "move X and Y to P" where their places are the same)
_TIME = (
    r"(?:first(?:\s+of\s+all)?|then|next|after\s+that|afterwards|finally|lastly|last|at\s+any\s+time|any\s+time)"
)
_VERB_HEADING = re.compile(
    rf"(?i)^\s*(?P<lead>[^:\n]*?\b(?:{VERB}|{SWAP}))(?:\s+(?:these|those|the\s+following)(?:\s+{_NOUNS})?)?\s*:\s*$"
)
_GOAL_BULLET = re.compile(
    rf"(?i)^\s*(?:[-*•·]|\d[.)])\s+(?:(?P<time>{_TIME})\s*,?\s+)?(?P<blocks>{_LIST})\s+(?P<place>{PREP}\s+[^:]+?)"
    r"\s*[.;]?\s*$"
)


def verb_heading_read(text: str) -> str:
    """Bullets of blocks and places under a heading that says only the verb, said with the verb (see
    `_VERB_HEADING`); a heading over one bullet, or over bullets that are not all blocks with a place, is
    left to the colon's joining (`handover_sentences.split_sentences`)."""
    if ":" not in text:  # no heading
        return text
    lines = text.splitlines()
    out: list[str] = []
    k = 0
    while k < len(lines):
        heading = _VERB_HEADING.match(lines[k])
        items: list[re.Match[str]] = []
        while heading and k + 1 + len(items) < len(lines):
            item = _GOAL_BULLET.match(lines[k + 1 + len(items)])
            if item is None:
                break
            items.append(item)
        if heading is None or len(items) < 2 or len({i["time"] is None for i in items}) > 1:
            out.append(lines[k])
            k += 1
            continue
        lead = heading["lead"].strip()
        if items[0]["time"] is not None:  # steps in time: each said with the verb
            out += [f"- {i['time']}, {lead} {i['blocks']} {i['place']}" for i in items]
        elif len({" ".join(i["place"].lower().split()) for i in items}) == 1:  # one place: one list of blocks
            blocks = [i["blocks"] for i in items]
            out.append(f"{lead} {', '.join(blocks[:-1])} and {blocks[-1]} {items[0]['place']}")
        else:
            goals = [f"{i['blocks']} {i['place']}" for i in items]
            out.append(f"{lead} {', '.join(goals[:-1])} and {goals[-1]}")
        k += 1 + len(items)
    return "\n".join(out)


# a step that names the blocks but no place, then a heading that names only the places over a count per
# place ("Move the three blocks. Into regions H, I and J: exactly one each.", "At any time, move the red and
# blue blocks. Into the free regions: one each.", "Put the blocks down.\nRegions H, I and J: one apiece."):
# one goal, with the count as the one-block rule it states ("move the three blocks into regions H, I and
# J, one per region"; a heading without a preposition is "to")
_PER_PLACE = (
    r"(?:exactly\s+|only\s+|just\s+)?(?:one|1|a\s+single)(?:\s+(?:block|object|pillar|item|cube|one))?\s+"
    r"(?:each|apiece|per\s+(?:region|area|place|spot)|(?:in|on)\s+each(?:\s+(?:region|area|one))?)"
)
_PLACES_THEN_COUNT = re.compile(
    rf"(?i)(\b{VERB}\s+{_LIST})(?:\s+down)?[ \t]*[.:]?[ \t]*\n?[ \t]*(?:[-*•·][ \t]+)?"
    rf"(?:(to|onto|into|in|on)\s+)?((?:the\s+)?(?:regions?\s+)?{_LETTERS}|"
    rf"(?:the\s+|any\s+)?(?:free|empty|unoccupied)\s+regions?)[ \t]*:[ \t]*{_PER_PLACE}[ \t]*(?=[.;!?]|$)",
    re.MULTILINE,
)


def places_then_count_read(text: str) -> str:
    """A placeless step, then its places with a count per place, as one goal (see `_PLACES_THEN_COUNT`)."""
    if ":" not in text:
        return text
    return _PLACES_THEN_COUNT.sub(lambda m: f"{m[1]} {m[2] or 'to'} {m[3]}, one per region", text)


# a later sentence that opens with a bare time adverb ("Later on the arms will put ...", "At a later point,
# put ...", "Eventually the robots will put ...") says its step comes after what was said before it, as
# "after that"; an added step ("later on they will also ...") or one that says what it follows ("later on,
# once that is done") is read as it is. Inside a clause "eventually" is a hedge (`handover_words`)
_LATER = re.compile(
    r"(?i)^(\s*)(?![^;]*\b(?:also|too|as\s+well)\b)(?>later(?:\s+on)?|eventually|(?:some\s+time|a\s+(?:little\s+)?while|shortly)\s+"
    r"later|at\s+a\s+later\s+(?:point|stage|time|moment)|after\s+this)\b(?>\s*,?\s*)(?!(?:once|when|after)\b)(?=\S)"
)
# a time adverb set off by no comma before the team as the subject of a future ("Afterwards the robots will
# put ...", "After that they will ..."): the comma that ends the adverb, so that the subject reads as the
# team's (`handover_discourse`)
_TIME_THEN_TEAM = re.compile(
    r"(?i)^(\s*(?:afterwards?|after\s+(?:that|this)|subsequently|thereafter|then|next|finally|lastly|in\s+the\s+end|"
    r"at\s+the\s+end))\s+(?=(?:(?:the|our|both|all\s+(?:the\s+)?)\s+)?(?:robot\s+)?(?:arms|robots)\s+|they\s+)"
    r"(?=\S+(?:\s+\S+)?\s+(?:will|shall|are\s+going\s+to)\b)"
)

# a hedge between the subject and the verb of a one-clause sentence ("the yellow block eventually goes to G",
# "they will eventually put it on G") orders nothing (where it leaves a block's two goals unordered, the
# reading refuses: `handover_reading`)
_HEDGE = re.compile(
    r"(?i)^((?:(?!\band\b|\bthen\b)[^,;])*?\b(?:blocks?|ones?|pillars?|objects?|it|they)(?:\s+will)?)\s+"
    r"(?:eventually|sooner\s+or\s+later|in\s+due\s+course)\s+(?=[a-z])"
)


def later_read(sentences: list[str]) -> list[str]:
    """Each sentence after the first with its opening "later (on)" as "after that" (see `_LATER`), an
    opening time adverb set off from the team's future by a comma (`_TIME_THEN_TEAM`), and a hedge inside
    a clause dropped (`_HEDGE`)."""
    said = [s if k == 0 else _LATER.sub(r"\1after that, ", s, count=1) for k, s in enumerate(sentences)]
    return [_HEDGE.sub(r"\1 ", _TIME_THEN_TEAM.sub(r"\1, ", s, count=1), count=1) for s in said]
