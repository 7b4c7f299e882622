"""Writers' registers beyond the plain command, rewritten onto the forms the handover reader reads
(`handover_phrases.normalise` applies `REGISTERS` to the lower-cased sentence, before
the word tables' `REWRITES`). Each rewrite changes no meaning:

- academic: the goal as a noun ("the objective is the transfer of X to P" -> "transfer of X to P", which
  the cue reader reads; "the relocation / movement of" -> "move", "placements on R are prohibited" ->
  "nothing may be placed on R", "an arbitrary empty region", "are each to be moved");
- narrative: the arms as the subject of a placing verb ("the arms (will) carry the blocks ..."), "before /
  until you touch Y" (before Y is touched), "while you do it", "somewhere along the way" (at any time),
  ("..., while regions F, G and H remain empty" is the cue reader's kept-empty place);
- telegraphic and bulleted: "three objects, three regions: G, H and I" (the regions' count is still
  checked), a pair before its exchange ("red and blue: swap places"), a count after its noun ("pillars,
  three, to E, F, G");
- emphasis: "no exceptions";
- headings: a noun of placing after a heading ("three blocks: placement on regions H, I and J"), a block's
  heading before its order ("red: before blue") or before bare region letters ("yellow: I first, then G"),
  a pair's bare "swap" ("red and blue: swap"); a pseudo-cleft of an order ("what comes first is the red
  block": the red block comes first);
- "in that order" after a clause that already orders its steps with "then" repeats that order and is
  dropped (without "then" it stays unread: which order?); asides in parentheses are read before these
  rewrites, by `handover_asides`;
- modal "is to" before a verb of holding ("each region is to hold only one block": must hold);
- frames: a user story's role ("As the operator, ..."), a requirement's identifier ("R1:"),
  office English ("kindly", "do the needful", an emphatic "itself");
- progressive narration ("nothing is being placed", "no region is getting two blocks"), "let X VERB" (X
  must VERB; "don't let anyone touch X");
- connectives: "plus", "on top of that", "as well as keeping" (and); "before you start" and "first
  things first" (first);
- manner adverbs that every plan already meets ("carefully", "quickly"; "gently" is left unread), a group
  said in other words ("the whole lot of blocks", "every single block", "the trio of objects"), a range
  of region letters ("regions H through J") and "slot" for a region;
- steps said block by block: one block's place as a choice ("red block: one of H, I or J"; after two
  blocks "one of" may mean one region for both, and is left unread), a block's heading before its
  place's preposition ("blue block: onto region I, after the red one": the block goes there); "still
  need(s) to" is "need(s) to";
- labels that say something: "Scope:" / "You will need:" (the blocks, as the scene statement "we have
  ..."), "Here's what I want:" (a need);
- the period said first ("during this, ...", "meanwhile: ..."), a time left free ("..., no timing
  constraint"), the impersonal "one must V" (you must), informal verbs of putting ("toss / chuck / plop /
  dump / shove the blocks"), "in such a way that", "at any point during the task", an order said first
  ("ahead of X, Y must be placed");
- a non-native speaker's "must to be", "please to", "before than", "near of", "in any moment", "whatever
  empty region", "after to finish all", "make exchange of the position of", "is to put before", "not can",
  "a plan for move", "at side of", "where is X now", "in each region is possible only one object", "any
  region empty", "again on G" (back on G), "cannot touch X if Y is not touched before" (until Y has been
  touched), "and after on G" and "first X and after Y" (then);
- conditions that restate an order or a rule: "when / once / by the time you place X, Y must already be
  placed" (Y before X), "if a region already holds a block, do not put another block there" and "a region
  that already has a block may not get a second one" (one block per region), "if a region is not one of
  E, F and G, put nothing on it" (nothing on any other region);
- a left-dislocated object taken up by a pronoun of its number ("the yellow block, put it on region I";
  "red and blue, just swap them"; "the other regions, place nothing on them"), a pair before its exchange
  ("red and blue blocks, swap places"), legal "said regions" (these regions), a block's heading before
  "untouched" ("blue: untouched until red is touched"), a bare region letter heading one block ("G:
  yellow"; "I:" is the pronoun, refused by name), a pirate's "afore", "ye", "haul" and "stow".
"""

from __future__ import annotations

import re
from collections.abc import Callable

from nl2hltl2plan.language.courtesy import courtesy_pattern
from nl2hltl2plan.language.handover_requirements import REQUIREMENTS
from nl2hltl2plan.language.handover_voices import VOICED
from nl2hltl2plan.language.handover_words import GERUND_VERBS, NEGATED_GERUNDS, SWAP, VERB

_BLOCK = r"(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|cube))?"
# who asks, in a user story ("As the cell operator, ...")
_ROLE = (
    r"(?:user|operator|supervisor|manager|engineer|customer|client|owner|lead|technician|planner|worker|"
    r"researcher|scientist|teacher|student|admin|administrator|person|member)"
)
# a manner that every plan already has: checked free of collisions (carefully, safely), as short as it can
# be (quickly, efficiently), each block on its cell (precisely); a way of moving that the planner does not
# model ("gently", "slowly", "smoothly") is left unread, and refused by name
_MANNER = (
    r"(?:carefully|cautiously|safely|securely|quickly|swiftly|speedily|promptly|efficiently|properly|correctly|"
    r"precisely|accurately)"
)
_VERBS = rf"(?:{VERB}|swap|exchange|keep|leave|put|place)\b"
# what "let" commands: a block, a group, a region or nothing, then the verb it does in its base form
_SUBJECT_NP = (
    r"(?:the|no|nothing|none|red|blue|yellow|all|each|every|both)\b(?:\s+(?!(?:go|be|hold|come|stay|remain|land|"
    r"end|sit|get)\b)[a-z]+){0,5}?"
)
# an object said first and taken up again by a pronoun of its number (left dislocation): one block by its
# colour ("it"); blocks by their colours, a counted group or the other regions ("them")
_ONE_BLOCK = r"(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|pillar|object))?"
_GROUP = (
    r"(?:the\s+)?(?:red|blue|yellow)(?:\s*(?:,|and)\s*(?:the\s+)?(?:red|blue|yellow))+(?:\s+(?:blocks|ones|"
    r"pillars|objects))?|(?:the\s+|all\s+)?(?:three|3)\s+(?:blocks|pillars|objects)|the\s+other\s+regions"
)
_DISLOCATED = ((_ONE_BLOCK, "it"), (_GROUP, "them"))
_NOTHING_ON = r"\2 \3 \1"  # "the other regions, place nothing on them": place nothing on the other regions
_SAID = r"(?:the\s+)?(?:said|aforesaid|aforementioned)"
_ON = r"(?:on|onto|in|into)"
_PUT_NOTHING = r"(?:put|place|drop|set|leave|lay)\s+(?:nothing|no\s+(?:block|object|pillar)s?)"
_BARE_VERB = r"(?:go|be|hold|come|stay|remain|land|end\s+up|sit|get)"
_LETTERS = r"[e-j](?:\s*(?:,|and|or)\s*[e-j])*"
# "those (three) (regions)": the regions named before, read by the places pass; a consequent that puts
# nothing there
_THOSE = r"(?:those|these)(?:\s+(?:two|three|four))?(?:\s+regions)?"
_NONE_ON = (
    r"(?:do\s+not|never)\s+put\s+(?:any\s+object|anything|objects|an\s+object|a\s+block|any\s+block)|put\s+nothing"
)

_COUNTS = {"2": "two", "3": "three"}
_PLACED_PP = r"placed|put(?:\s+down)?|set\s+down|dropped|down|in\s+place"
_TOUCHED_PP = r"touched|picked\s+up|handled"
# a condition's placing: "if red has not been placed (has not gone down, is not there)"
_ARRIVED = rf"{_PLACED_PP}|gone\s+down|there"
_NOT_YET = (
    rf"(^|[,;]|\band\b)\s*(?:if|as\s+long\s+as|so\s+long\s+as)\s+(?:(?P<x>{_BLOCK})\s+(?:has|is|was)\s+not\s+(?:yet\s+)?"
    rf"(?:been\s+)?(?P<pp>{_ARRIVED}|{_TOUCHED_PP})|(?:no\s+arm|nobody|no\s+one)\s+has\s+(?:yet\s+)?"
    rf"(?P<pp2>{_TOUCHED_PP})\s+(?P<x2>{_BLOCK}))(?:\s+yet)?\s*,\s*(?:(?:do\s+not|never|(?:you\s+)?"
    rf"(?:must|may|should)\s+not)\s+(?P<verb>place|put(?:\s+down)?|set\s+down|drop|touch|pick\s+up|handle)\s+"
    rf"(?P<y>{_BLOCK})(?:\s+down)?|leave\s+(?P<y2>{_BLOCK})\s+alone|(?:keep\s+(?:your\s+)?)?hands\s+off\s+"
    rf"(?P<y3>{_BLOCK})|(?:no\s+arm|nobody|no\s+one)\s+(?:touches|picks\s+up|(?:may|can|should)\s+(?:touch|pick\s+up))\s+"
    rf"(?P<y7>{_BLOCK})|"
    rf"(?P<y4>{_BLOCK})\s+(?:(?:has|needs|will\s+have)\s+to\s+wait|must\s+wait|should\s+wait|waits)|"
    rf"hold\s+off\s+on\s+(?P<y8>{_BLOCK})|"
    rf"(?P<y5>{_BLOCK})\s+(?:must|may|should|can)\s+not\s+be\s+(?P<ypp>{_PLACED_PP}|{_TOUCHED_PP})|"
    rf"(?P<y6>{_BLOCK})\s+(?:stays|must\s+stay|should\s+stay|remains|must\s+remain)\s+untouched)\s*(?=$|[,;.])"
)


def _not_yet_as_until(m: re.Match[str]) -> str:
    """The command of a not-yet condition, until the condition holds: a placing ("down", "in place", "gone
    down", "there") is "placed"; "leave Y alone", "hands off Y", "nobody touches Y" and "Y stays untouched"
    do not touch Y; "Y waits" and "hold off on Y" do not place Y, or do not touch it after a condition of
    touching; "Y must not be V-ed" does not V Y."""
    said = m["pp"] or m["pp2"]
    placing = re.fullmatch(_ARRIVED, said) is not None
    done = "placed" if placing else said
    if m["ypp"]:
        placed = re.fullmatch(_PLACED_PP, m["ypp"])
        verb = "place" if placed else {"picked up": "pick up"}.get(m["ypp"], "touch")
    else:
        verb = m["verb"] or ("place" if (m["y4"] or m["y8"]) and placing else "touch")
    kept = next(m[f"y{k}"] for k in ("", 2, 3, 4, 5, 6, 7, 8) if m[f"y{k}"])
    return f"{m[1]} do not {verb} {kept} until {m['x'] or m['x2']} has been {done}"


def _letters_between(match: re.Match[str]) -> str:
    """'regions h through j' -> 'regions h , i and j' (a range the wrong way round is left as written)."""
    first, last = match[1], match[2]
    if first >= last:
        return match[0]
    letters = [chr(c) for c in range(ord(first), ord(last) + 1)]
    return "regions " + " , ".join(letters[:-1]) + " and " + letters[-1]


_RULES: tuple[tuple[str, str | Callable[[re.Match[str]], str]], ...] = (
    # labels that say something ("here's" is "here s" by then): the blocks the instruction is about, as the
    # scene statement "we have ..." (which must name every block of the scene), and a need
    (
        r"^\s*(?:scope|you\s+(?:will\s+)?need|what\s+you\s+need|materials|equipment|ingredients)\s*:\s*",
        "we have ",
    ),
    (r"^\s*here\s*(?:s|is)\s+what\s+(i|we)\s+(?:want|need|would\s+like)\s*:", r"\1 want "),
    # a telegraphic count after its noun: "pillars, three, to E, F, G" (three pillars to ...)
    (r"^\s*(blocks|pillars|objects|cubes|items)\s*,\s*(two|three|2|3)\s*,\s*", r"\2 \1 "),
    # one block's place said as a choice: "red block: one of H, I or J" is "red block: H, I or J" (after two
    # blocks, "one of" may mean one region for both: left unread)
    (
        r"(?<!\band\s)(?<!\bor\s)(?<!,\s)\b((?:red|blue|yellow)\b"
        r"(?:\s+(?!and\b|or\b|red\b|blue\b|yellow\b)[a-z]+){0,2}?\s*:?\s*)one\s+of\s+"
        r"(?=(?:the\s+)?(?:regions?\s+)?[e-j]\b)",
        r"\1",
    ),
    # a block's heading before a preposition ("blue block: onto region i, ..."): the block goes there
    (
        r"^(\s*(?:the\s+)?(?:red|blue|yellow)\s+(?:block|pillar|cube|object))\s*:\s*"
        r"(?=(?:onto|on|to|into|in)\s)",
        r"\1 goes ",
    ),
    # "the pillars still need to go ...": what is still to be done is what is to be done
    (r"\bstill\s+(?=(?:needs?|has|have|must)\s+(?:to\b|be\b))", " "),
    # the period said first, before a comma or as a label: "during this, place nothing on F" (meanwhile)
    (r"(^|[,;:]\s*)during\s+(?:all\s+)?(?:this|that)\s*(?=,)", r"\1meanwhile "),
    # a time left free in words after its goal: "..., no timing constraint" (a sentence of its own, "the
    # yellow block has no time constraint", is joined to its goal: `handover_answers.timing_joined`)
    (r",\s*(?:with\s+)?no\s+(?:time|timing)\s+(?:constraints?|restrictions?)\s*$", ", at any time"),
    # the impersonal "one" before a modal and a verb is whoever does the work: "one must place X" (you must)
    (
        r"(^|,|;|\band\b|\bthen\b)\s*one\s+(must|should|has\s+to|needs\s+to|is\s+to|may|can)\s+"
        rf"(?=(?:not\s+|never\s+|first\s+|also\s+)?(?:{VERB}|{SWAP})\b)",
        r"\1 you \2 ",
    ),
    # informal verbs of putting: "chuck / toss / plop / dump / shove the blocks into ..." (put)
    (
        r"\b(?:chuck|toss|plop|dump|shove|haul|stow)(?=\s+(?:the|all|both|it|them|red|blue|yellow|three|\d)\b)",
        "put",
    ),
    # a pirate's English: "afore" (before), "ye" (you)
    (r"\bafore\b", "before"),
    (r"\bye\b", "you"),
    # a left-dislocated object, taken up again by "it" or "them": "the yellow block, put it on region i" (put
    # the yellow block on region i); "red and blue, just swap them"; "the other regions, place nothing on
    # them"
    *(
        (rf"^\s*({np})\s*,\s*(?:just\s+)?((?:{VERB}|{SWAP})\b)\s+{pronoun}\b", r"\2 \1")
        for np, pronoun in _DISLOCATED
    ),
    *(
        (rf"^\s*({np})\s*,\s*(?:just\s+)?({_PUT_NOTHING})\s+({_ON})\s+{pronoun}\b", _NOTHING_ON)
        for np, pronoun in _DISLOCATED
    ),
    # legal English names the places or blocks it said before with "said": "said regions" (these regions;
    # "said block" is left unread)
    (rf"\b{_SAID}\s+(?=(?:regions|blocks|pillars|objects|areas)\b)", "these "),
    # a block's heading before its touch state: "blue block: untouched until ..." (the blue block stays ...)
    (
        r"^\s*(?:the\s+)?(red|blue|yellow)(?:\s+(?:block|pillar|object))?\s*:\s*(?=untouched\b)",
        r"the \1 block stays ",
    ),
    # a bare region letter heading one block ("g: yellow, last"): the region ("i" is the pronoun: refused)
    (
        r"^\s*([e-hj])\s*:\s*(?=(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|pillar|object|one))?\s*(?:,|$))",
        r"region \1 : ",
    ),
    # a pair before its exchange, after a comma: "red and blue blocks, swap places" (swap ...); "swap them"
    # is the dislocation's, "swap it" is left unread
    (
        rf"^\s*({_GROUP})\s*,\s*(?:just\s+)?({SWAP})(?:\s+(?:places|positions))?\b(?!\s+(?:it|them)\b)",
        r"\2 \1",
    ),
    # a manner said as a result: "..., in such a way that each region holds one block" (..., each region ...)
    (r",?\s*\bin\s+such\s+a\s+way\s+that\b", " ,"),
    # a region said again as the spot a block holds: "region g, the spot the red block occupies now" (h312:
    # where the red block is now)
    (
        r",\s*the\s+(?:spot|place|region|square)\s+(?:that\s+)?(the\s+(?:red|blue|yellow)\s+block)\s+"
        r"(?:occupies|holds|sits\s+on|is\s+on|is\s+in)\b",
        r", where \1 is",
    ),
    # "every one of the three blocks" (h312): all three blocks
    (r"\bevery\s+one\s+of\s+the\s+(two|three)\s+(?=(?:blocks|pillars|objects)\b)", r"all \1 "),
    # "at any point / time during the task", "... along the way" (h312): at any time
    (
        r"\b(at\s+any\s+(?:point|time|moment))\s+(?:(?:during|in|throughout)\s+(?:the|this)\s+"
        r"(?:task|job|process|work)|along\s+the\s+way)\b",
        r"\1",
    ),
    # an order said first: "ahead of / before the blue block, the red block must be placed" (red before blue)
    (
        r"^\s*(?:ahead\s+of|before|prior\s+to)\s+(the\s+(?:red|blue|yellow)\s+(?:block|pillar|object))\s*,\s*"
        r"(the\s+(?:red|blue|yellow)\s+(?:block|pillar|object))\s+(must|should|is\s+to|has\s+to)\s+be\s+"
        r"(placed|put|moved)\b",
        r"\2 \3 be \4 before \1",
    ),
    # non-native: "to" after a modal or "please" ("must to be placed", "please to move"), "before than", "near
    # of", "in any / whatever moment" (at any time), "whatever empty region", "after (to) finish all",
    # "make exchange of the position(s) of", "X is to put before Y" (is to be put), "and only afterwards"
    (rf"\b(must|can|cannot|should|may|could|will|would|please)\s+to\s+(?=(?:be|have|not|{VERB})\b)", r"\1 "),
    (r"\b(before|after)\s+than\b", r"\1"),
    (r"\bnear\s+of\b", "near"),
    (r"\bin\s+(?:any|whatever|whichever|every)\s+moment\b", "at any time"),
    (r"\bwhatever\s+(?=(?:empty|free|unoccupied)\s+regions?\b)", "any "),
    (r"\bafter\s+(?:to\s+)?finish(?:ing)?\s+all(?:\s+of\s+(?:this|that|it))?\b", "after all of this"),
    (r"\bmake\s+(?:an?\s+|the\s+)?exchange\s+of\s+the\s+positions?\s+of\b", "exchange the positions of"),
    (r"\b(is|are)\s+to\s+put\s+(?=before|after|first|on|in|onto|into)\b", r"\1 to be put "),
    (r"\band\s+only\s+(?:afterwards?|after\s+that|then)\b", "and then"),
    # the same phrase set off by commas between a block's two places: "on region I and, (only) after that,
    # on region G"
    (r"\band\s*,\s*(?:only\s+)?(?:afterwards?|after\s+that|then)\s*,\s*", "and then "),
    # non-native: "not can" (cannot); "for" before a bare verb ("a plan for move": to move); "at (the) side
    # of" (beside); "where is X now" in a clause after a comma (where X is now); "in each region is possible /
    # allowed only one object" (only one object is allowed in each region); "after" as "then" before a
    # place ("and after on region G") and after "first ... and" before a block that ends the clause ("First
    # red block and after blue block"); not before a verb (", after put it on G": then, or after putting?)
    (r"\bnot\s+can\b", "cannot"),
    (r"^\s*not\s+any\s+(?=(?:object|block|pillar)s?\b)", "no "),
    (r"\b(area|region|place)s?\s+different\s+(?:of|from|than)\s+(?=the\b)", r"\1 other than "),
    (r"\s*,\s*it\s+is\s+(?=regions?\s+[e-j]\b)", ", that is "),
    (r"\bany\s+region\s+(empty|free)\b", r"any \1 region"),
    (r"\bagain\s+(?=(?:on|onto|in|into|to)\s+(?:region\s+)?[e-j]\b)", "back "),
    (r"\bfor\s+(?=(?:move|put|place|transfer|bring|carry)\s+(?:the|all|a|three|both|\d)\b)", "to "),
    (r"\bat\s+(?:the\s+)?side\s+of\b", "beside"),
    (rf"([,(]\s*)where\s+(?:is|are)\s+({_BLOCK})\s+(now|currently|at\s+the\s+moment)\b", r"\1where \2 is \3"),
    (
        r"\bin\s+(?:each|every|any)\s+region\s+(?:is|it\s+is)\s+(?:possible|allowed|permitted)\s+(?:only|just)\s+"
        r"(?:one|a\s+single|1)\s+(block|object|pillar)\b",
        r"only one \1 is allowed in each region",
    ),
    # "cannot touch X if (before) Y is / was not touched (before)": X untouched until Y has been touched
    (
        rf"\b(cannot|can\s+not|may\s+not|must\s+not|no\s+arm\s+(?:can|may))\s+touch\s+({_BLOCK})\s+if\s+"
        rf"(?:before\s+)?({_BLOCK})\s+(?:is|was|has|had)\s+not\s+(?:been\s+)?touched(?:\s+before)?\b",
        r"\1 touch \2 until \3 has been touched",
    ),
    (r"\band\s+after\s+(?=(?:on|onto|in|into|to)\s+(?:region\s+)?[e-j]\b)", "and then "),
    (rf"^(\s*first\b[^,]*?\s)and\s+after\s+(?=(?:{_BLOCK})\s*(?:,|$))", r"\1and then "),
    # "a region that already has a block may not get a second one": the world's rule (one block per region)
    (
        r"\b(?:a|any)\s+region\s+that\s+already\s+(?:has|holds|contains)\s+(?:a|one)\s+(?:block|object)\s+"
        r"(?:may|can|must|should)\s+not\s+(?:get|receive|hold|take)\s+(?:a\s+second|another)(?:\s+one|\s+block|"
        r"\s+object)?\b",
        "one block per region",
    ),
    # conditions that restate an order or a rule: "when / once / by the time you place X, Y must (already) be
    # placed (already)" (Y before X); "if a region (already) holds a block, do not / you may not put another
    # block on it / there" (one block per region); "if a region is not one of E, F and G, put nothing on it"
    # (nothing on any region other than E, F and G)
    (
        rf"^\s*(?:when|once|by\s+the\s+time|whenever|if)\s+(?:you|we)\s+(?:place|put|set|drop)\s+({_BLOCK})\s*,\s*"
        rf"({_BLOCK})\s+(?:must|has\s+to|should|needs\s+to)\s+(?:already\s+)?(?:be|have\s+been)\s+"
        r"(?:already\s+)?(?:placed|put|set|dropped)(?:\s+already)?\s*$",
        r"\2 must be placed before \1",
    ),
    (
        r"^\s*if\s+a\s+region\s+(?:already\s+)?(?:holds|has|contains)\s+(?:a|one)\s+(?:block|object)(?:\s+already)?\s*,\s*"
        r"(?:(?:do\s+not|don\s+t|never|(?:you\s+)?(?:may|must|should|can)\s*not)\s+(?:put|place|set)\s+(?:another|a\s+second)"
        r"(?:\s+(?:block|object|one))?|(?:put|place|set)\s+no\s+(?:other|second|further)\s+(?:block|object|one))\s+"
        r"(?:there|(?:on|in|onto|into)\s+it)\s*$",
        "one block per region",
    ),
    (
        rf"^\s*if\s+a\s+region\s+is\s+not\s+(?:one\s+of\s+)?((?:regions?\s+)?{_LETTERS}|{_THOSE})\s*,\s*"
        rf"(?:{_NONE_ON})\s+(?:on|in)\s+it\s*$",
        r"nothing may be put on any region other than \1",
    ),
    # a conditional that restates an order or a guard: "if red has not been placed (yet), do not place blue",
    # "if nobody has touched the red block yet, leave the blue block alone", "if red is not down yet, blue has
    # to wait": the command until the condition holds ("do not place blue until red has been placed")
    (_NOT_YET, _not_yet_as_until),
    # "if a region is F, G or H, put nothing on it" (nothing on F, G or H); "the blue block may only be placed
    # if (once) the red block has been placed" (not until then)
    (
        rf"\bif\s+a\s+region\s+is\s+(?:one\s+of\s+)?((?:regions?\s+)?{_LETTERS})\s*,\s*(?:{_NONE_ON})\s+(?:on|in)\s+it\s*$",
        r"put nothing on \1",
    ),
    (
        rf"\b({_BLOCK})\s+(?:may|can|must|should)\s+only\s+be\s+(placed|put\s+down|touched|picked\s+up)\s+(?:if|once|"
        rf"when|after)\s+({_BLOCK})\s+(?:has|is)\s+(?:been\s+)?(placed|put\s+down|down|touched|picked\s+up)\b",
        lambda m: f"{m[1]} must not be {m[2]} until {m[3]} has been {'placed' if m[4] == 'down' else m[4]}",
    ),
    # "if (should) you need to set a block down in the meantime, do not use F, G or H": the period's rule
    (
        r"(^|[,;])\s*(?:if\s+(?:you|we)\s+(?:need|have|want)|should\s+(?:you|we)\s+need)\s+(?:somewhere\s+|a\s+(?:place|spot)\s+)?to\s+(?:set|put|place|lay|rest)\s+(?:a\s+block|an\s+"
        r"object|a\s+pillar|anything|something|one|it)(?:\s+down)?\s+(meanwhile|in\s+the\s+meantime)\s*,\s*"
        r"(?=(?:do\s+not|never)\s+use\b)",
        r"\1 \2 , ",
    ),
    # the goal as "the idea / plan / intention is to ... / that ...": as "the aim is"
    (r"^\s*(?:the|my|our)\s+(?:idea|plan|intention)(?:\s+here)?\s+is\s+(?=to\s|that\b)", "the aim is "),
    # academic: the goal as a noun
    (r"^\s*the\s+(?:objective|aim|purpose|goal)\s+is\s+(?:that\b|the\s+(?=\w+\s+of\b))", " "),
    (r"\b(?:the\s+)?(?:relocation|movement)\s+of\s+(?=(?:the|all|both|each|every)\b)", "move "),
    # a block's state named as the goal: "make sure the yellow block is back on region G" (put it back there)
    (
        r"\b(?:make\s+sure|ensure)\s+(?:that\s+)?((?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|object))?)\s+"
        r"is\s+back\s+(?=(?:on|in|onto)\b)",
        r"put \1 back ",
    ),
    # "I'd rather nothing went on R": a prohibition said as a wish (nothing may go on R)
    (
        r"\b(?:i|we)\s+would\s+rather\s+(nothing|no\s+(?:object|block|item)s?)\s+went\s+(?=(?:on|onto|in|into|to)\b)",
        r"\1 may go ",
    ),
    # the places said again in an aside: "regions E, F and G (the ones beside arms a and b)"
    (r"\(\s*the\s+ones\s+((?:beside|next\s+to|by|near)\s+arms?\b[^()]*?)\s*\)", r"\1"),
    # "one block in each one": each of the places (a block holds no block)
    (r"\b(one\s+(?:block|object|item)\s+(?:in|on)\s+each)\s+one\b", r"\1 region"),
    # a gerund's step as the subject: "moving X to P is the job" (move X to P), "putting X back on G is the
    # last step" (finally, put X back on G)
    (
        rf"(^|,|;|\band\b)(\s*)({'|'.join(GERUND_VERBS | NEGATED_GERUNDS)})\b([^,;]+?)\s+"
        r"is\s+the\s+(?:last|final)\s+step\b",
        lambda m: f"{m[1]}{m[2]} finally , {(GERUND_VERBS | NEGATED_GERUNDS)[m[3]]}{m[4]}",
    ),
    # a gerund step that is forbidden: "touching the blue block before ... is not allowed" (do not touch ...)
    (
        rf"(^|,|;|\band\b)(\s*)({'|'.join(NEGATED_GERUNDS)})\b([^,;]+?)\s+"
        r"is\s+(?:not\s+allowed|not\s+permitted|forbidden|prohibited)\b",
        lambda m: f"{m[1]}{m[2]}do not {NEGATED_GERUNDS[m[3]]}{m[4]}",
    ),
    # the last step's time without its comma: "after all that yellow back to g"
    (r"\b(after\s+all\s+(?:of\s+)?(?:that|this|these))\s+(?=(?:the\s+)?(?:red|blue|yellow)\b)", r"\1 , "),
    # "placement / return / transfer of X": the verb; "with placement of X before Y" adds that step
    (
        r"\b(?:the\s+)?(placement|positioning|return|transfer|delivery)\s+of\s+"
        r"(?=(?:the|all|both|each|every|red|blue|yellow)\b)",
        lambda m: {"placement": "place", "positioning": "place", "delivery": "deliver"}.get(m[1], m[1]) + " ",
    ),
    # "no placement of (any) objects on R": nothing placed on R
    (
        r"\bno\s+placements?\s+of\s+(?:any\s+)?(?:objects?|blocks?|items?|anything)\s+(?=(?:on|in|onto)\b)",
        "nothing placed ",
    ),
    (
        r"\bwith\s+an?\s+(?:limit|maximum)\s+of\s+"
        r"(?=one\s+(?:block|object|item)s?\s+(?:per|on\s+each|in\s+each)\b)",
        "with ",
    ),
    (r"\ban?\s+arbitrary\s+(?=(?:empty|free|unoccupied)\s)", "any "),
    (r"\b(?:is|are)\s+(each|all|both)\s+to\s+be\b", r"must \1 be"),
    (
        r"\b(?:any\s+)?placements?\s+((?:on|in|onto)\s+[^,;]+?)\s+(?:are|is)\s+"
        r"(?:prohibited|forbidden|not\s+allowed|not\s+permitted|banned)\b",
        r"nothing may be placed \1",
    ),
    # narrative (and a question's "would the arms please put ...": the courtesy word adds nothing)
    (
        r"\b(?:the\s+)?(?:robot\s+)?(?:arms|robots)\s+(?:will\s+|shall\s+|should\s+|must\s+|(?:have|need|are)\s+to\s+)?"
        r"(?:please\s+|kindly\s+)?(?=(?:carry|move|take|put|place|bring|transfer|set|deliver|relocate|shift|stack|deposit|drop|arrange|"
        r"position|distribute|return|send|lay|collect|gather|spread)\b)",
        " ",
    ),
    (
        r"\b(before|until)\s+(?:you|we)\s+(?:have\s+)?(?:touch|touched|pick\s+up|picked\s+up|grab|grabbed)\b",
        r"\1 touching",
    ),
    # (before "it" is read as a block)
    (r"\b(while\s+(?:you|we|they)\s+(?:are\s+)?(?:do|doing|perform|performing))\s+it\b", r"\1 this"),
    (r"\b(?:somewhere|at\s+some\s+point)\s+along\s+the\s+way\b", "at any time"),
    # two blocks listed before a colon or their place without "and" ("Red, blue: swap spots", "red, blue ->
    # any empty region"): the pair
    (r"^\s*(red|blue|yellow)\s*,\s*(red|blue|yellow)\s*(?=:|(?:to|onto|into)\b|-+\s*>|→)", r"\1 and \2 "),
    # telegraphic and bulleted
    (
        r"^\s*((?:the\s+)?(?:two|three|four|\d)\s+(?:blocks|objects|pillars|items|cubes|pieces))\s*,\s*"
        r"(?=(?:the\s+)?(?:two|three|four|\d)\s+(?:(?:goal|target)\s+)?regions\s*:)",
        r"put \1 on ",
    ),
    (
        r"^\s*((?:the\s+)?(?:red|blue|yellow)\s+(?:and|&)\s+(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:blocks|ones))?)\s*:\s*"
        rf"{SWAP}(?:\s+(?:(?:their|the)\s+)?(?:places|positions|spots)\b|(?=\s*(?:[.;,!?]|$)))",
        r"swap \1",
    ),
    # emphasis
    (r"\s*,?\s*\b(?:no\s+exceptions|without\s+exception)\b", " "),
    (r"(\bthen\b[^,;()]*?)\s*(?:,\s*)?(?:\(\s*)?\bin\s+(?:that|this|the\s+same)\s+order\b(?:\s*\))?", r"\1"),
    # a noun of placing after a heading, before its place: "three blocks: placement on regions H, I and J",
    # "yellow block: transfer to region I, then ..." (the heading's blocks go there: "three blocks: on ...")
    (
        r"(:\s*)(?:placement|transfer|relocation|delivery|movement|move|positioning|transport)\s+"
        r"(?=(?:on|onto|to|into|in)\s)",
        r"\1",
    ),
    # a block's heading before its order: "red: before blue" (the red block goes before the blue block)
    (
        r"^\s*((?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|cube))?)\s*:\s*(?=(?:before|after|ahead\s+of)\s+"
        r"(?:the\s+)?(?:red|blue|yellow)\b)",
        r"\1 goes ",
    ),
    # a block's heading before bare region letters in its steps: "yellow: I first, then G" (after the heading
    # a letter that opens a step, before "first", "then", a comma or the end, is a region, never "I")
    (
        r"^(\s*(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|cube))?\s*:\s*)([e-j])(\s+first)?\s*,\s*"
        r"(?:and\s+)?then\s+(?:on\s+to\s+|to\s+)?([e-j])\s*$",
        lambda m: f"{m[1]}region {m[2]}{m[3] or ''} , then region {m[4]}",
    ),
    # a pseudo-cleft of an order: "what comes / goes / is placed first is the red block" (the red block comes
    # first: the words the clause would have without the cleft)
    (
        r"\bwhat\s+(comes|goes|is\s+placed|gets\s+placed|is\s+put)\s+(first|last|next)\s+is\s+"
        r"((?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|object|cube))?)\b",
        r"\3 \1 \2",
    ),
    # modal "is to" (or "is set / meant / supposed / due / going to") before a verb of holding, with "each"
    # before "to" or after it ("regions H, I and J are each (set) to receive one of the blocks": must each
    # receive)
    # ("is to take the pillars ..." is a goal: "take", "carry" and "get" hold only before a count of one)
    (
        r"\b(?:is|are)\s+(?:(each|all|both)\s+)?(?:set\s+|meant\s+|supposed\s+|due\s+|going\s+)?to\s+"
        r"(?=(?:hold|contain|receive|accept)\b|(?:take|carry|get)\s+"
        r"(?:(?:only|just|exactly|at\s+most)\s+)?(?:one|a\s+single|no\s+more\s+than)\b)",
        lambda m: f"must {m[1] or ''} ",
    ),
    # a region "is to be given" / "should each be given" one: it receives one
    (
        r"\b(?:(?:is|are)\s+(?:(each|all)\s+)?to|((?:should|must|shall|will)\s+(?:each\s+|all\s+)?))be\s+given\s+"
        r"(?=(?:exactly\s+|only\s+|just\s+)?(?:one|a\s+single)\b)",
        lambda m: (m[2] or f"must {m[1] or ''} ") + "receive ",
    ),
    # "one block of the three" is one of the three blocks
    (
        r"\bone\s+(block|object|pillar|cube)\s+of\s+the\s+(two|three|[23])\b(?!\s+[a-z]+s\b)",
        r"one of the \2 \1s",
    ),
    # progressive narration: "nothing is being placed on F" (is placed), "no region is getting two blocks"
    (
        r"\b(is|are)\s+being\s+(?=(?:placed|put|set|dropped|moved|touched|handled|grabbed|picked\s+up)\b)",
        r"\1 ",
    ),
    # a user story's role ("As the operator, I want ...") says who asks, never what is asked
    (rf"^\s*as\s+(?:an?|the)\s+(?:[a-z]+\s+){{0,2}}?{_ROLE}\s*,", " "),
    # a clause added with "plus", "on top of that", "as well as" (before a verb): "and"
    (
        rf"(?:,\s*|^\s*)plus\s*,?\s*(?=(?:the|do|never|no|nothing|red|blue|yellow|only|each|one)\b|{_VERBS})",
        ", and ",
    ),
    (r"(^|,|\band\b)\s*on\s+top\s+of\s+(?:that|this|all\s+that)\s*,", r"\1 "),
    *(
        (rf",\s*as\s+well\s+as\s+{gerund}\b", f", and {verb}")
        for gerund, verb in (GERUND_VERBS | NEGATED_GERUNDS | {"keeping": "keep", "leaving": "leave"}).items()
    ),
    # what comes before the work comes first: "Before you start(,|:) ..." / "First things first: ..." (a rule
    # said there is a rule of the whole instruction; "before you start, know that ..." introduces one)
    (
        r"^\s*(?:before\s+(?:you|we)\s+(?:start|begin)(?:\s+(?:the\s+)?(?:job|task|work))?|first\s+things\s+first)"
        r"\s*[:,]?",
        "first ,",
    ),
    # a courtesy word (`courtesy.txt`: "kindly", "pls", "thx", "thank you") is "please" (dropped wherever it
    # stands, so a step word still reaches its verb: "after all that is done, kindly put ...")
    (rf"\b{courtesy_pattern('word')}\b", "please"),
    # a command's label: "Execute: transfer ...", "Then perform: ...", "Execute at any time: ..." (a verb with
    # no object of its own before a colon asks for what follows)
    (r"\b(?:execute|perform|carry\s+out)\s*(at\s+any\s+time\s*)?:", r"please \1 ,"),
    # office English: "do the needful" asks for what the rest says, and "itself" / "themselves" after a noun
    # only stresses it
    (r"(?:\band\s+)?\bdo\s+the\s+needful\b(?:\s+and\b)?", " "),
    (r"(?<=[a-z])\s+(?:itself|themselves)\b", " "),
    # a requirement's identifier before it ("R1:", "REQ-2:"), and a spec sheet's numbered goal or constraint
    # ("Goal 1:", "Constraint 2:"): they are listed, not ordered ("Step 2:" orders, and stays)
    (r"^\s*(?:r|rq|req|requirement|item|(?:goal|constraint|objective)\s)\s*-?\s*\d+\s*:", " "),
    # a spec sheet's goal said as where the blocks are: "Goal: three blocks at the opposite side" (on it)
    (r"\bat\s+(?=(?:the\s+)?(?:opposite\s+(?:side|regions?)|regions?\s+[e-j]\b))", "on "),
    # a constraint said as a fact, a terse "No other region used." (as "no other region is to be used")
    (
        r"\bno\s+other\s+(region|area|place|zone|spot)(s?)\s+(?:is\s+|are\s+|gets?\s+|being\s+)?used\b",
        r"no other \1\2 is to be used",
    ),
    # "lands" is "goes": "Nothing lands outside the target region", "the red block should land on G"
    (r"\blands\b", "goes"),
    (r"\b(should|must|to|can|may|will)\s+land\b", r"\1 go"),
    # "none / not one of them", "not a single pillar" before a placing verb's passive (or the participle
    # alone, a verbless prohibition: "..., not one of them put down anywhere except ...") is "no object":
    # every object of the scene is one of the blocks (regions are never "placed": "none of them may hold two"
    # is left as it is)
    (
        r"\b(?:none\s+of\s+them|not\s+(?:a\s+single\s+)?one\s+of\s+them|not\s+a\s+single\s+(?:block|pillar|object)"
        r"|not\s+one\s+(?:block|pillar|object))\s+(?:((?:may|can|must|should|shall|is\s+to|will)\s+(?:not\s+|ever\s+)?be"
        r"|is|gets?)\s+)?(?=(?:put|placed|set|dropped|laid|left)\b)",
        lambda m: f"no object {m[1] or 'may be'} ",
    ),
    # "comes back to G" is "goes back to G": the block's return, said from the place's side
    (r"\b(?:comes|coming|come)\s+back\s+(?=(?:to|on|onto|in|into)\b)", "goes back "),
    # "let X VERB" commands X's verb: "let the red block go down before blue" (must go down), "let nothing be
    # placed on F" (nothing must be placed); "letting red go down first" (red going down first)
    (rf"\blet\s+({_SUBJECT_NP})\s+(?={_BARE_VERB}\b)", r"\1 must "),
    (rf"\bletting\s+({_SUBJECT_NP})\s+go\b", r"\1 going"),
    # a group said in other words: "the whole lot of blocks" (all the blocks), "every single block", "each
    # one of the pillars", "the trio of objects" (the three objects)
    (r"\bthe\s+whole\s+lot\s+of\s+(?=(?:the\s+)?(?:blocks|objects|pillars|items|cubes)\b)", "all the "),
    (r"\b(every|each)\s+single\s+", r"\1 "),
    (r"\beach\s+one\s+of\s+(?=the\b)", "each of "),
    (r"\bthe\s+(?:trio|threesome)\s+of\s+", "the three "),
    # "everything" moved somewhere is every object ("Everything to the opposite regions", "move everything
    # onto I"); "none" put somewhere is no object ("and none on F, G or H"): verbless orders
    (r"\beverything(?=\s+(?:to|onto|into|goes|go)\b)", "all the objects"),
    (r"\bnone(?=\s+(?:on|onto|in|into)\s+(?:regions?\s+)?[e-j]\b)", "nothing"),
    # a range of region letters ("regions H through J", "regions E to G"): each letter from the first to the
    # last (a letter the world lacks is refused later, by name); "slot" is a region
    (r"\bregions\s+([e-j])\s+(?:through|thru|to)\s+([e-j])\b", _letters_between),
    (r"\bslot(s?)\b", r"region\1"),
    # a region named by its mark: "the spot marked G", "the areas labelled G, H and I" (regions G, H and I)
    (
        r"\b(?:the\s+)?(?:region|area|zone|spot|place|position|cell|square|pad|location)(s?)\s+(?:marked|labell?ed|"
        r"lettered)\s+(?=(?:with\s+)?[e-j]\b)(?:with\s+)?",
        r"region\1 ",
    ),
    # a list's count as a multiplier after its noun: "pillars x3" (three pillars; the count is still checked)
    (r"\b(blocks|pillars|objects|cubes)\s+[x×]\s*([23])\b", lambda m: f"{_COUNTS[m[2]]} {m[1]}"),
    # telegraphic: "never drop on H, I, J" (drop anything there); "F, G, H: keep clear" (keep F, G, H clear)
    (
        r"\b(never|do\s+not)\s+(drop|put|place|set)(?:\s+down)?\s+(?=(?:on|onto|in|into)\s+(?:regions?\s+)?[e-j]\b)",
        r"\1 \2 anything ",
    ),
    (rf"^\s*((?:regions?\s+)?{_LETTERS})\s*:\s*keep\s+(empty|clear|free|vacant|unoccupied)\b", r"keep \1 \2"),
    # an absolute participle of the one-block rule: "..., one block being put on each region"
    (
        r",\s*(?:with\s+)?one\s+(?:block|object|pillar)\s+being\s+(?:put|placed|set)\s+(?:on|in|onto|into)\s+"
        r"(?:each|every)\s+region\b",
        ", one object per region",
    ),
    # the first thing said: "first off", "to start (with)" (as "to begin with": the step comes first)
    (r"(^|,)\s*(?:first\s+off|to\s+start(?:\s+with)?|to\s+start\s+off)\s*(?=,)", r"\1 to begin with "),
    # legal English: "upon" before a place is "on", "thereafter" is "then", "each such region" is each region
    (r"\bupon\s+(?=(?:the\s+)?(?:regions?|areas?|any|opposite|[e-j])\b)", "on "),  # ("upon completion" stays)
    (r"\bthereafter\b", "then"),
    (r"\b(each|every|any)\s+such\s+(?=(?:region|area|place|zone)s?\b)", r"\1 "),
    # and the last: "Last: yellow back to G", "Last, ..." (as "finally"; "the last block" stays)
    (r"^\s*last\s*(?=[,:])", "finally "),
    # a manner adverb that every plan already meets
    (rf"\b{_MANNER}\b", " "),
    *(
        (rf"\bis\s+{gerund}\b", third_person)
        for gerund, third_person in (("getting", "gets"),)
    ),
)

# compiled once: with the reader's other tables they are more than `re`'s cache holds
REGISTERS = REQUIREMENTS + VOICED + tuple((re.compile(pat), replacement) for pat, replacement in _RULES)
