"""Phrases of the four-arm handover instructions (paper Table III), read against the world's layout.

A sentence is read in passes. It is normalised first (lower case, typos mended, the variants of
`handover_rewrites.REWRITES` rewritten onto the forms read). Noun phrases then become placeholders:
blocks (`B0`: "the three pillars", "red and blue blocks", "each object"), places (`P0`: "region H, I
and J", "the opposite side", "any empty region", "the side of arm a and arm b", "where the red block
is", "the area other than the target region") and arms (`A`: "the robot arm", "any of the arms").
Then the rules of `language.handover_rules` and the clause patterns of `language.handover_reading`
consume placeholders and words. Whatever a pass leaves unread is a refusal naming the words: nothing
is silently dropped. This module reads the blocks, arms, pronouns and the world's one-block-per-region
rule; `handover_places` the places; `handover_scene` holds the layout and the placeholders' data.

A count set off after its noun ("the blocks, all three, ...") must be the noun's count. Places resolve
against the instance: "the opposite" is, per block, the labelled regions on the other
arms' side from where the block starts (arms a, b against c, d); "the side of arm a and arm b" the
labelled regions those arms reach; "where the red block is" the region red starts on. A landmark
("next to arm a and arm b") only describes a place named beside it, and must agree with it; "swap
them", "exchanging their positions": the two blocks named before in the sentence (else unread).
"""

from __future__ import annotations

import re
from functools import lru_cache, partial

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.handover_asides import read_asides
from nl2hltl2plan.language.handover_clauses import read_statements
from nl2hltl2plan.language.handover_discourse import MEANING
from nl2hltl2plan.language.handover_places import (
    mark_capacity,
    mark_place_pronouns,
    mark_places,
    note_one_per_region,
)
from nl2hltl2plan.language.handover_regex import apply, rewrite_table
from nl2hltl2plan.language.handover_registers import REGISTERS
from nl2hltl2plan.language.handover_rewrites import REWRITES
from nl2hltl2plan.language.handover_scene import (
    COLOUR,
    COUNTS,
    GROUP_NOUNS,
    NOUN,
    NOUNS,
    PLACE_NOUN,
    Marked,
    Scene,
)
from nl2hltl2plan.language.handover_shares import shared_out
from nl2hltl2plan.language.handover_spoken import unspoken
from nl2hltl2plan.language.handover_typos import typo_table
from nl2hltl2plan.language.handover_wishes import unwished
from nl2hltl2plan.language.handover_words import (
    DONE,
    GERUND,
    MODAL,
    NEG,
    STEP_NUMBER,
    SWAP,
    VERB,
)

_TOUCHED = r"(?:touched|picked|grasped|grabbed|handled|moved|lifted)"
TYPOS = typo_table()
# compiled once: with the reader's other tables they are more than `re`'s cache holds
_REWRITES = tuple((re.compile(pattern), replacement) for pattern, replacement in REWRITES)
_TABLE = rewrite_table(REGISTERS + _REWRITES)  # each with the literals its matches need


@lru_cache(maxsize=8192)  # a sentence is normalised again for each restated reading of its text
def normalise(sentence: str) -> str:
    """Lower case, punctuation spaced out, typos mended, spoken styles normalised (`handover_spoken`),
    wishes and final-state goals said as commands (`handover_wishes`), framing dropped and `REWRITES`
    applied."""
    text = sentence.lower().replace("’", "'")
    text = re.sub(r"(?<=[a-z])-(?=[a-z])", " ", text)  # one-by-one -> one by one
    # every handover world has four arms a-d (`worlds.handover_world.ARMS`): "all four arms", "the four arms"
    # and "arms a, b, c and d" are the arms
    text = re.sub(r"\b(?:all|the)\s+(?:four|4)\s+(?:of\s+the\s+)?(?=(?:robot\s+)?arms\b)", "the ", text)
    text = re.sub(r"\barms\s+a\s*,\s*b\s*,\s*c\s*,?\s*and\s+d\b", "the arms", text)
    text = _DASH.sub(lambda dash: _dash_as_comma(text, dash), text)
    text = _NOUN_FIRST.sub(_colour_first, text)
    text = re.sub(r"\b([123])(?:st|nd|rd)\b", lambda n: ("first", "second", "third")[int(n[1]) - 1], text)
    text = read_asides(text)
    text = re.sub(r"([,()/:])", r" \1 ", text)
    text = re.sub(r"\b(\w+)'s\b", r"\1 s", text)  # red's -> red s (a possessive)
    text = re.sub(r"[a-z]+", lambda w: TYPOS.get(w.group(0), w.group(0)), text)
    text = _drop_framing(unwished(shared_out(unspoken(text))))
    text = apply(_TABLE, text)
    text = re.sub(r"\bplease\b\s*,?", " ", text)  # politeness anywhere: "all three blocks please move to ..."
    return " ".join(text.split())


_DASH = re.compile(r"\s*[—–]\s*|\s+-+\s+")


# the noun before its colour, as a label names it ("block red is to be placed before block blue"); read
# before the dictation's clause breaks (`handover_spoken`), which take "the yellow block red first" (a colour
# word before the noun) as two phrases
_NOUN_FIRST = re.compile(
    rf"(?P<before>\b[a-z]+\s+|^\s*|[,;:(]\s*)(?P<noun>block|cube|pillar|object)\s+(?P<colour>{COLOUR})\b"
    rf"(?!\s+{NOUN}s?\b)"
)
_NOT_NOUN_FIRST = frozenset({"red", "blue", "yellow", "one", "each", "every", "any", "another", "that"})


def _colour_first(found: re.Match[str]) -> str:
    before = found["before"]
    if before.strip() in _NOT_NOUN_FIRST:
        return found[0]
    article = "" if before.strip() in ("the", "a") else " the " if before.strip() in ",;:(" else "the "
    return f"{before}{article}{found['colour']} {found['noun']}"


def _dash_as_comma(text: str, dash: re.Match[str]) -> str:
    """A dash sets off a phrase, as a comma does; not after a step's number ("1 - move ...", "step two -
    put ...": at most two words before it). A label's dash ("Goal - ...") is a colon already, as in every
    world (`headings.unlabelled`)."""
    return dash[0] if len(text[: dash.start()].split()) <= 2 else " , "


def _drop_framing(text: str) -> str:
    """A purpose or reason that names nothing the reader could use ('to keep things simple, ...', 'for
    safety, ...', '..., since that is faster') frames the sentence and is dropped; one that names a block,
    a place, an arm, a count, a negation, an order or a time stays to be read (or refused)."""
    # ("as soon as X is done, ..." says when, never why: it is no frame)
    lead = re.match(
        rf"({STEP_NUMBER})\s*(?:to|in\s+order\s+to|for|because|since|{_AS})\s+([^,]{{1,60}}),", text
    )
    if lead and not MEANING.search(lead.group(2)):
        text = lead.group(1) + " " + text[lead.end() :]
    tail = re.search(rf",\s*(?:because|since|{_AS}|so\s+that|for)\s+([^,]+)$", text)
    if tail and not MEANING.search(tail.group(1)):
        text = text[: tail.start()]
    # a preamble of four words or more before a colon that names nothing either, nor any verb, condition or
    # exception ("so here is what i would like to happen today: ...", "what we are after is simple:")
    head = re.match(r"\s*([^:,;]{1,80}):", text)
    if head and len(head.group(1).split()) >= 4 and not _NAMES.search(_I_SAYS.sub(" ", head.group(1))):
        text = text[head.end() :]
    return text


# a reason's "as", never the time's "as soon as" ("as soon as possible" says no time: a frame still)
_AS = r"as(?!\s+soon\s+as\b(?!\s+(?:possible|you\s+can|we\s+can)\b))"


# what a preamble may not hold: a meaning word, a placing verb, a condition ("when that is done:" is a time),
# an exception or a warning
_NAMES = re.compile(
    rf"{MEANING.pattern}|\b(?:{VERB}|{SWAP}|if|when|whenever|done|unless|except|only|instead|avoid|but|careful|sure|make|keep|"
    r"leave|do|does|don|stop|wait|hold|go|goes|step|rule|order|note|remember|important)\b"
)
_I_SAYS = re.compile(r"\bi\s+(?=would|need|want|am|have|think|wish|hope|was|will|d|m)\b")


def mark(sentence: str, scene: Scene, before: Marked | None = None) -> Marked:
    """The sentence with its phrases marked; `before`, the sentence before, tells what 'it' and 'these
    regions' may mean. Memoised on what the marking reads (the sentence, the layout, the blocks' starts and
    the sentence before's last block, group, regions and place): a sentence is marked again for each
    restated reading of the instruction; the caller gets a copy that its rules may change."""
    previous = before or Marked("")
    key = (
        sentence,
        scene.layout.name,
        tuple(sorted(scene.starts.items())),
        (previous.last_one, previous.last_group, previous.last_regions, previous.last_place),
    )
    if key not in _MARKED:
        if len(_MARKED) >= 8192:
            _MARKED.clear()
        _MARKED[key] = _marked(sentence, scene, previous)
    return _MARKED[key].copy()


_MARKED: dict[tuple[object, ...], Marked] = {}


def _marked(sentence: str, scene: Scene, previous: Marked) -> Marked:
    m = Marked(normalise(sentence))
    _mark_one_per_region(m)
    _mark_arms(m)
    # "do not put anything on them": after a preposition of place, a pronoun names places (a cell holds
    # one block, so nothing goes on a block); resolved once the places are marked
    m.sub(r"\b(on|onto|in|into|over|across|among|between)\s+(each\s+of\s+)?(them|it)\b", r"\1 \2 PLACEREF_\3")
    _mark_blocks(m, scene, previous.last_one, previous.last_group)
    # "after the red block (after it), the blue block goes on I": the order said before its clause, put after
    # it (one clause, with its own block, and no other order word)
    m.sub(rf"^\s*(after|before)\s+(B\d+)\s*,\s*({_ONE_CLAUSE}\bB\d+\b{_ONE_CLAUSE})$", r"\3 \1 \2")
    _join_particles(m)
    # "put the three blocks there", "the yellow block is to be moved there as well"
    m.sub(rf"\b((?:{VERB}|{GERUND})\s+B\d+|B\d+\s+{MODAL}{DONE})\s+there\b", r"\1 PLACEREF_there")
    mark_places(m, scene, previous.last_regions)
    # "i" that ends a clause is region I that no place phrase took in ("g , h , also i"), never the pronoun
    # (a filler word, which a verb follows): refused, not dropped
    if re.search(r"\bi\s*(?=$|[,;:()])", m.text):
        raise HTTError(f"'i' in {sentence.strip()!r} is not read as a place: say 'region I'")
    mark_place_pronouns(m, previous.last_regions, previous.last_place, previous.last_group)
    mark_capacity(m)
    read_statements(m, scene)
    # the regions named last in the sentence's order (not the order the passes marked them in)
    named = [m.places[int(k)] for k in re.findall(r"\bP(\d+)\b", m.text)]
    regions = [p.regions for p in named if p.kind == "regions"]
    m.last_regions = regions[-1] if regions else ()
    goals = [p for p in named if p.kind in ("regions", "opposite", "away")]
    m.last_place = goals[-1] if goals else None
    # "There are three goal regions, H, I and J.": places named for the next sentence ("put ... into them")
    m.sub(r"^\s*there\s+(?:are|is)\s+P\d+\s*$", " ")
    _mark_connectives(m)
    return m


_ONE_CLAUSE = r"(?:(?!\b(?:after|before|then|and)\b)[^,;:])*"


def _join_particles(m: Marked) -> None:
    """A particle verb reads as the verb: 'put down the red block', 'put the red block (back) down (on G)'
    as 'put the red block (back) (on G)', 'drop the red block off on G' as 'drop the red block on G', 'pick
    the blue block up' as 'pick up the blue block'."""
    m.sub(rf"\b({VERB}|{GERUND})\s+down\b", r"\1")
    m.sub(r"\b(set|lay|laid|spread)\s+(B\d+)\s+out\b", r"\1 \2")  # "set the objects out on G, H and I"
    m.sub(r"\b(drop|drops|dropping|dropped)\s+(?:off\s+(B\d+)|(B\d+)\s+(back\s+)?off)\b", r"\1 \2\3 \4")
    m.sub(rf"\b({VERB}|{GERUND})\s+(B\d+)\s+(back\s+)?down\b", r"\1 \2 \3")
    m.sub(r"\b(B\d+)\s+down\s+(?=(?:on|onto|in|into|at)\s)", r"\1 ")  # "..., the blue block down on H"
    m.sub(r"\b(pick|picks|picking|picked)\s+(B\d+)\s+up\b", r"\1 up \2")


def _mark_connectives(m: Marked) -> None:
    """'making sure (that)', 'ensure that', 'provided that', 'as long as' introduce what follows and add
    nothing; nor does 'but' before a negated command ('move ... but don't touch ...', read before the rule
    is)."""
    m.sub(r"(?:,\s*)?\bbut\s+(?=(?:do\s+not|never)\b)", " , ")
    m.sub(
        r"(?:\bwhile\s+)?\b(?:(?:making|make|be)\s+(?:sure|certain)|ensur(?:e|ing))\s+(?:that\s+)?|"
        r"\b(?:such|so)\s+that\b(?!\s+each\b)|\b(?:provided|providing|(?:on|under)\s+(?:the\s+)?condition)\s+that\b"
        # "as long as" of a condition; of a duration ("as long as they are being moved", "... has not been
        # touched") it stays, to be refused
        r"|\bas\s+long\s+as\b(?![^,;.]*\b(?:being|still|not|never|yet|while)\b)",
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
        rf"(?:only\s+|just\s+|at\s+most\s+|(?:no|not)\s+more\s+than\s+|exactly\s+|(?:a\s+)?max(?:imum)?\s+(?:of\s+)?)?(?:one|a\s+single|single|1)"
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
        rf"(?:,\s*(?:where|in\s+which)\s+|\bwith\s+)?\b(?:each|every|an?|any|one)\s+(?:of\s+(?:the|these|those)\s+)?{region}s?\s+(?:only\s+)?(?:can|may|should|must|will|shall)?\s*(?:only\s+)?"
        rf"(?:be\s+|being\s+)?(?:{hold}\s+|{holding}\s+|given\s+)?(?:only\s+)?(?:with\s+)?{one}\b",
        rf"(?:\bwith\s+)?\bno\s+{region}\s+(?:can|may|should|must|will|shall)?\s*(?:be\s+)?"
        rf"(?:{hold}|receiving|getting|holding|having|taking)\s+(?:with\s+)?(?:more\s+than\s+"
        rf"(?:one|a\s+single|1)(?:\s+{NOUN}|\s+of\s+them)?|(?:two|2)\s+{NOUNS})\b",
        rf"\b(?:with\s+|placing\s+|putting\s+|(?:put|place)\s+|there\s+(?:can|may|should|must|will)\s+be\s+)?{one}\s+(?:(?:is|being|may|can|should|must|will)\s+)?"
        r"(?:be\s+)?(?:allowed\s+|permitted\s+)?"
        rf"(?:(?:to\s+)?(?:occupy|go\s+(?:in|on|to|into)|sit\s+(?:in|on)|be\s+(?:placed\s+)?(?:in|on)|fits?\s+(?:in|on|into))\s+|"
        r"(?:per|in|on|for|to)\s+)"
        rf"(?:each|every)\s+{region}\b(?:\s+only\b)?",
        # "only one block can go on each one": "each one" after a place's preposition is each place
        rf"\b{one}\s+(?:(?:can|may|should|must|will)\s+)?(?:go|fit|be)\s+(?:on|in|into)\s+each\s+one\b",
        rf"\b(?:with\s+)?{one}\s+(?:(?:is|being|may|can)\s+)?(?:allowed\s+|permitted\s+)?(?:per|to\s+a)\s+{region}\b"
        r"(?:\s+only\b)?",  # "... per region only"
        r"\b(?:one|1)\s+(?:each|apiece)\b",
        rf"(?:,\s*)?\b(?:an?\s+)?(?:different|separate|distinct)\s+{region}\s+(?:for|per)\s+(?:each|every)(?:\s+{NOUN})?\b",
        rf"(?:,\s*)?\b(?:an?\s+)?(?:different|separate|distinct)\s+{region}\s+(?:each|apiece)\b",
        # "each region only has room for one"; "every block gets a region of its own"
        rf"(?:,\s*)?\b(?:each|every)\s+{region}\s+(?:only\s+)?(?:has|having)\s+(?:only\s+)?room\s+for\s+(?:only\s+)?(?:one|a\s+single)"
        rf"(?:\s+{NOUN})?\b",
        rf"\b(?:each|every)\s+{NOUN}\s+(?:gets|has|takes|goes\s+(?:to|in|into))\s+an?\s+{region}\s+of\s+its\s+own\b",
        # a limit said of any region ("at most one object in any region", "not more than one block on a
        # region") or after its count ("one pillar maximum per region", "one block at most in each region")
        rf"\b(?:with\s+)?(?:at\s+most|(?:no|not|never)\s+more\s+than|(?:a\s+)?max(?:imum)?\s+(?:of\s+)?)\s+"
        rf"(?:one|a\s+single|1)(?:\s+{NOUN})?\s+(?:in|on|per)\s+(?:any|a|each|every)\s+(?:single\s+)?{region}\b",
        rf"\b(?:with\s+)?(?:one|a\s+single|1)(?:\s+{NOUN})?\s+(?:max(?:imum)?|at\s+most|tops)\s+"
        rf"(?:per|(?:in|on)\s+(?:any|a|each|every))\s+{region}\b",
        # the way a block rests, after its count ("no more than one block resting on any of those regions",
        # "one block fitted to each region", "one resting on each")
        rf"\b(?:with\s+)?{one}\s+(?:resting|sitting|lying|standing|fitted|set|placed)\s+(?:on|in|onto|into|to)\s+"
        rf"(?:any|each|every|a)(?:\s+(?:one|single))?(?:\s+of\s+(?:the|these|those|them))?(?:\s+{region}s?)?(?=\s*(?:$|[,.;]|and\b))",
        # "only one block may occupy a region": any region, so each
        rf"\b(?:only|at\s+most|no\s+more\s+than)\s+(?:one|a\s+single|1)\s+{NOUN}\s+(?:may|can|is\s+allowed\s+to|should|will)\s+"
        rf"(?:occupy|fit\s+(?:in|on|into)|go\s+(?:in|on|into)|be\s+(?:placed\s+)?(?:in|on))\s+(?:a|any|each|every)\s+"
        rf"(?:single\s+)?{region}\b",
        # "each gets one block", "one region is only for one block"
        rf"(?:,\s*)?\beach\s+(?:one\s+)?(?:gets|receives|takes|holds)\s+(?:exactly\s+)?(?:one|a\s+single)(?:\s+{NOUN})?\b",
        rf"\b(?:each|every|one|a)\s+{region}\s+(?:is\s+)?(?:only\s+)?for\s+(?:only\s+)?(?:one|a\s+single|1)(?:\s+{NOUN})?"
        r"(?:\s+only)?\b",
        # "..., one (a) block each"
        rf"(?<=,)\s*(?:with\s+)?(?:one|a\s+single|an?)\s+{NOUN}\s+(?:each|apiece)\b",
        rf"\b(?:with\s+)?{one}\s+(?:per|in\s+each|on\s+each|for\s+each)\b(?!\s+of\b)",
        rf"\b(?:with\s+)?{one}\s+(?:each|every)\s+{region}\b",  # a phone's "one block each region" (per)
        # "..., one block in each of them": the regions just named (the world's rule holds for every region)
        rf"\b(?:with\s+)?{one}\s+(?:in|on|for)\s+each\s+of\s+(?:them|these|those)(?:\s+{region}s)?\b",
        rf"(?:,\s*)?\b(?:with\s+)?(?:no|never)\s+two(?:\s+{NOUNS})?\s+(?:(?:may|can|should|will)\s+)?(?:sharing|share|occupy|be\s+(?:in|on)|in|on)\s+"
        rf"(?:a\s+|one\s+|a\s+single\s+|the\s+same\s+)?{region}\b",
        # "a region never gets more than one block", "any region may not hold two blocks"
        rf"\b(?:a|any|each|every)\s+{region}\s+(?:(?:can|may|must|should|will|shall)\s+)?(?:never|not|cannot)\s+(?:ever\s+)?"
        rf"{hold}\s+(?:more\s+than\s+(?:one|a\s+single|1)(?:\s+{NOUN}|\s+of\s+them)?|(?:two|2)\s+{NOUNS})\b",
        rf"\beach\s+{NOUN}\s+(?:gets|has|takes|goes\s+(?:to|in|into))\s+(?:its\s+own|a\s+(?:different|separate))\s+{region}\b",
        rf"\b(?:do\s+not|never)\s+(?:put|place)\s+(?:more\s+than\s+(?:one|a\s+single)(?:\s+{NOUN})?|(?:two|2)\s+{NOUNS})\s+"
        r"(?:in|on|into|onto)\s+"
        rf"(?:a|any|each|one|a\s+single|the\s+same)\s+{region}\b",
    )

    note = partial(note_one_per_region, m)
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
    # "they may never put a pillar on ...": the doer of an active placing or touching verb (blocks do not act)
    m.sub(
        r"\bthey\b(?=\s+(?:(?:may|must|can|should|shall|will)\s+)?(?:not\s+|never\s+)?"
        r"(?:put|place|set|drop|touch|pick)\s+(?:an?|any|the|no)\b)",
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


# a count of blocks with their colours after it, with or without a comma or bracket ("the 2 blocks red and
# blue", "the two blocks, red and blue", "both blocks (red and blue)"): the blocks of those colours, where the
# colours listed are as many as the count; other lists are left to the rules below (which refuse them)
_COUNTED_COLOURS = (
    rf"\b(?:the\s+)?(two|three|both|2|3)\s+{GROUP_NOUNS}\s*(?:,\s*|\(\s*)?(?:the\s+)?"
    rf"({COLOUR}(?:\s*(?:,|and|&)\s*(?:the\s+)?{COLOUR})*)(?:\s*\))?(?!\s*(?:{NOUN}|{NOUNS})\b)"
)


def _colours_counted(match: re.Match[str]) -> str:
    """The blocks of the colours listed; a colour said again ("the 2 blocks red and blue, red placed ...")
    ends the list there, and what follows is kept."""
    found = list(re.finditer(COLOUR, match.group(2)))
    repeat = next((k for k in range(len(found)) if found[k][0] in [f[0] for f in found[:k]]), len(found))
    colours = [f[0] for f in found[:repeat]]
    if COUNTS.get(match.group(1)) != len(colours):
        return match.group(0)
    rest = match.group(2)[found[repeat - 1].end() :] if repeat < len(found) else ""
    if repeat == len(found):  # a closing bracket is the list's own
        rest = re.sub(r"^\s*\)", "", match.group(0)[match.end(2) - match.start(0) :])
    else:
        rest += match.group(0)[match.end(2) - match.start(0) :]
    return f" the {' and '.join(colours)} blocks {rest}"


def _mark_blocks(m: Marked, scene: Scene, previous: str, previous_group: tuple[str, ...]) -> None:
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
    m.sub(_COUNTED_COLOURS, _colours_counted)  # "the 2 blocks red and blue": the red and blue blocks
    counts = _counts_after_nouns(m)
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
    # "never place an object on ...", "do not put anything on ...": a generic object after a negated verb;
    # "only ever put a pillar (down) on ...": after a verb limited by "only", every block too
    m.sub(
        rf"\b({NEG}\s+(?:{VERB}|drop|leave|lay)|only\s+(?:ever\s+)?(?:{VERB}|drop|lay)|placing|putting|dropping|setting)\s+(?:(?:a|an|any)\s+{NOUN}|any\s+{NOUNS}|anything|"
        rf"(?:objects?|items?|things?)(?=\s+(?:on|in|onto|into)\b))\b",
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

    _check_counts_after_nouns(m, counts)

    def restated(match: re.Match[str]) -> str:  # "... so move all three of them there": the blocks, counted
        before = re.findall(r"\bB(\d+)\b", m.text[: match.start()])
        if not before or m.blocks[int(before[-1])] != scene.blocks:
            return match.group(0)
        all_blocks(match)
        m.blocks.pop(), m.block_text.pop()
        return " "

    m.sub(r"\s*,?\s*\ball\s+(two|three|four|\d+)\s+of\s+them\b", restated)
    _mark_pronouns(m, previous, previous_group)


# a count set off after its noun: "the blocks, all three (of them), go ...", "pillars (all three) -> ...",
# "the red and blue blocks, both of them, ...", unpunctuated before a verb ("the pillars all three go to
# ..."); not a part ("the blocks, two of them, ...": which two?)
_COUNT_AFTER_NOUN = re.compile(
    rf"\b({NOUNS}|{COLOUR})\s*(?:,|\(|—|–|-)?\s*"
    r"(all\s+(?:of\s+them|(?:two|three|four|\d)(?:\s+of\s+them)?)|the\s+(?:two|three|four|\d)\s+of\s+them|"
    r"both(?:\s+of\s+them)?|each\s+of\s+the\s+(?:two|three|four|\d)|every\s+one\s+of\s+them)\s*"
    r"(?:,|\)|—|–|-|(?=(?:go|goes|to|on|onto|in|into|should|must|are|will|can|need|have|swap|exchange|trade)\b))"
)


def _counts_after_nouns(m: Marked) -> list[str]:
    """Each count set off after its noun, replaced by a token `Q<k>` (the k-th count's words) that
    `_check_counts_after_nouns` checks against the blocks the noun names once they are marked."""
    counts: list[str] = []

    def token(match: re.Match[str]) -> str:
        counts.append(match.group(2))
        return f"{match.group(1)} Q{len(counts) - 1} "

    m.text = _COUNT_AFTER_NOUN.sub(token, m.text)
    return counts


def _check_counts_after_nouns(m: Marked, counts: list[str]) -> None:
    """'the blocks, all three,' names the blocks once, counted: the count must be theirs ('the pillars,
    both of them,' with three pillars, or 'the red block, all three of them,' is refused)."""

    def counted(match: re.Match[str]) -> str:
        blocks, said = m.blocks[int(match.group(1))], counts[int(match.group(2))]
        number = next((COUNTS[w] for w in said.split() if w in COUNTS), None)
        if len(blocks) < 2 or number not in (None, len(blocks)):
            raise HTTError(
                f"'{m.block_text[int(match.group(1))]}, {said}' counts {number or 'all'} of "
                f"{len(blocks)} block(s): which blocks?"
            )
        return f" B{match.group(1)} "

    m.sub(r"\bB(\d+)\s+Q(\d+)\b", counted)
    if left := re.search(r"\bQ(\d+)\b", m.text):
        raise HTTError(f"'{counts[int(left.group(1))]}' counts no blocks named before it")


def _mark_pronouns(m: Marked, previous: str, previous_group: tuple[str, ...]) -> None:
    """'it' / 'them': the blocks of the nearest mention before (one block for 'it'; for 'it' with none
    in its sentence, the last single block the sentence before named; for 'them' / 'they' with none, the
    one group of blocks the sentence before named)."""

    def resolve(match: re.Match[str]) -> str:
        head = m.text[: match.start()]
        # not the block just before an "after"/"before" ("the blue block after it": it is not the blue block)
        head = re.sub(r"\bB\d+\s+(?:after|before|than|behind)\s*$", " ", head)
        before = [int(k) for k in re.findall(r"\bB(\d+)\b", head)]
        fits = [k for k in before if match.group(0) != "it" or len(m.blocks[k]) == 1]
        if fits:
            return _new_block(m, m.blocks[fits[-1]], match.group(0))
        if previous and match.group(0) == "it":
            return _new_block(m, [previous], match.group(0))
        if previous_group and match.group(0) in ("them", "they"):
            return _new_block(m, list(previous_group), match.group(0))
        return match.group(0)

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
    # "while they do that": the doer of the work is the arms, never the blocks
    doer = r"they(?!\s+(?:are\s+)?(?:do|doing|carry|carrying|perform|performing)\b)"
    m.text = re.sub(rf"\b(?:it|them|{doer})\b", resolve, m.text)
    # "red and blue: move them to any empty region": the heading is what "them" names
    heading = re.match(r"\s*B(\d+)\s*:", m.text)
    if heading and any(
        m.blocks[int(k)] == m.blocks[int(heading.group(1))] for k in re.findall(r"\bB(\d+)\b", m.text)[1:]
    ):
        m.text = m.text[heading.end() :]
    singles = [m.blocks[int(k)] for k in re.findall(r"\bB(\d+)\b", m.text) if len(m.blocks[int(k)]) == 1]
    m.last_one = singles[-1][0] if singles else ""
    groups = {tuple(m.blocks[int(k)]) for k in re.findall(r"\bB(\d+)\b", m.text) if len(m.blocks[int(k)]) > 1}
    m.last_group = groups.pop() if len(groups) == 1 else ()
