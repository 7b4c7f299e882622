"""Wishes, goals stated as the final state and completion clauses of the handover instructions, rewritten
onto the commands the reader reads (`handover_phrases.normalise` calls `unwished` on the lower-cased
sentence after `handover_spoken.unspoken`, whose contractions it relies on: "i'd" is "i would", "that's"
is "that s"). Each rewrite changes no meaning; what it does not match is left for the reader, which reads
it or refuses it by name:

- wishes and indirect requests before a verb: "would it be possible to", "would you be able to", "i was
  hoping you (the arms) could", "i'd love it if you could", "any chance you could", "let's", "(could you
  possibly) have the arms"; a wish with the object and its participle ("i'd like the three blocks moved
  to", "let's get the blocks placed on", "have the red block put ...") or "go" ("let's have the yellow
  block go to I") as the command ("move the three blocks to"); a past-tense wish ("it would be great if
  the yellow block went to I", "... if red and blue swapped places") as the command ("move the yellow
  block to I", "swap red and blue"); "we'd like F, G and H to stay empty" as "F, G and H must stay empty";
  a polite tag at the end ("if that's okay") and a request's "for me" dropped;
- a goal stated as the final state: "by the end / in the end / when (by the time) you're finished," is
  "at the end," (a last step after other commands, nothing on its own); "the end result should be X on
  P", "the goal is X placed on P" and "what I want to see at the end: X on P" are "at the end, X should
  be on P"; "should be sitting on" and "should sit (rest, end up) on" are "should be on"; "no other region
  should (ever) have been used" is "... should be used"; "should have stayed empty" is "should stay empty";
  "should have been on I and then on G" (places in turn) is "should be on I and then on G"; "..., without
  using any other region" and "using no other region" are "..., and no other region should be used";
  "should have swapped places" is "should swap places"; "on the way there" in a prohibition is "at any
  point"; "with nothing put on ... (until then)" is "nothing put on ... (meanwhile)";
- a block's next place after "then" or "first and": "(and) then finish on / end up on / go on to region
  G", "on I first and end up on G" are "then region G";
- a completion clause: "when that's all done," is "when that is all done,"; "after this," is "after
  that,"; "once they're all over / across," and "once everything is in place," are "once that is done,";
- "with blue left alone until red has been touched" is "blue must not be touched until ...";
- order words at the end of a clause: "place the red block first and the blue block later (after)",
  "red going down first and blue later" are "... the red block before the blue block";
- "at your convenience" is "whenever convenient"; "X need(s) moving (swapping, placing)" is "X need(s) to be
  moved (swapped, placed)";
- a goal's manner as its participle after a comma: "..., placed one after another" is "..., one after
  another";
- kept-empty regions: "free of objects" is "empty"; "keep the blocks out of F, G and H" is "put nothing on
  F, G and H"; "while keeping regions F, G and H empty" is "while regions F, G and H stay empty";
- one block per region: "never more than one object in a region", "you can't have two on the same
  region", "never two on the same region" and "one block on each of those regions" are "one object per
  region"; "in each region only one
  block" is "only one block in each region".
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.handover_regex import apply, rewrite_table
from nl2hltl2plan.language.handover_words import GERUND_VERBS, NEGATED_GERUNDS, VERB

# a participle after its object in a wish ("i'd like the blocks moved to ..."), with its verb
_PARTICIPLES = {
    "moved": "move",
    "put": "put",
    "placed": "place",
    "taken": "take",
    "brought": "bring",
    "transferred": "transfer",
    "set": "set",
    "carried": "carry",
    "returned": "return",
    "delivered": "deliver",
    "relocated": "relocate",
    "shifted": "shift",
    "dropped": "drop",
    "positioned": "position",
    "swapped": "swap",
    "exchanged": "exchange",
}
_PARTICIPLE = "(?:" + "|".join(_PARTICIPLES) + ")"
_START = r"(^|,|;|\band\b)\s*"
# a noun phrase of blocks: it starts with a determiner, a count or a colour and has no clause break,
# no "of" (the academic "the relocation of ..." is another rule's) and no verb of its own
_OBJECTS = r"((?:the|all|both|each|every|three|two|red|blue|yellow)\b(?:(?!\bof\b|\bis\b|\bare\b)[^,;:])*?)"
_BLOCK = r"(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|cube|object|pillar))?"
_LETTERS = r"[e-j](?:\s*(?:,|and|or)\s*[e-j])*"
_PUT_DOWN = r"(?:(?:going|goes|go|placed|put|set)(?:\s+down)?)"

_WISH_BEFORE_VERB = (
    r"(?:(?:would|could|is)\s+it\s+be\s+(?:possible|ok|okay|alright)\s+(?:for\s+you\s+)?to|"
    r"(?:would|could|will)\s+you\s+be\s+able\s+to|"
    r"(?:i|we)\s+(?:was|were|am|are)\s+hoping\s+(?:that\s+)?(?:you|the\s+(?:robot\s+)?arms|the\s+robots)\s+"
    r"(?:could|would|can|might|will)|"
    r"let\s+(?:s|us)|"
    # "i would like the arms to put ...": the arms named in the wish are the ones asked
    r"(?:i|we)\s+(?:would\s+(?:like|love|prefer)|want|need)\s+(?:the\s+(?:robot\s+)?arms|the\s+robots)\s+to|"
    r"(?:i|we)\s+(?:wonder|am\s+wondering|was\s+wondering)\s+(?:if|whether)\s+you\s+(?:could|would|can|might)|"
    # "i'd love it if you could put ...", "it would be lovely if you could put ...", "any chance you could put
    # ...": the request's verb
    r"(?:is\s+there\s+)?any\s+chance\s+(?:that\s+)?you\s+(?:could|would|can|might)|"
    r"(?:(?:i|we)\s+would\s+(?:love|like|appreciate)\s+it|it\s+would\s+be\s+(?:great|nice|lovely|wonderful|"
    r"helpful|brilliant))\s+if\s+you\s+(?:could|would|can)|"
    r"(?:(?:could|would|can|will)\s+you\s+(?:possibly\s+|please\s+|kindly\s+)?)?"
    r"(?:have|get)\s+(?:the\s+)?(?:robot\s+)?(?:arms|robots)(?:\s+to)?)"
)
_WISH_WITH_PARTICIPLE = (
    r"(?:(?:i|we)\s+(?:would\s+(?:like|love|prefer)|want|need|wish)|let\s+(?:s|us)\s+(?:get|have)|get|have)"
)
_GOOD = r"(?:great|nice|good|ideal|lovely|helpful|best|perfect|wonderful)"
_FINISHED = r"(?:finished|done|through|complete|completed)"

_RULES: tuple[tuple[str, str], ...] = (
    # a goal stated as the final state
    (
        rf"{_START}(?:by\s+the\s+end|in\s+the\s+end|(?:when|once|by\s+the\s+time)\s+(?:you|we|they)\s+are\s+"
        rf"{_FINISHED})\s*,",
        r"\1 at the end ,",
    ),
    (
        r"^\s*(?:(?:the\s+)?(?:end\s+(?:result|state)|final\s+(?:result|state|layout|arrangement)|outcome)\s+"
        r"(?:should|must|will)\s+be|what\s+(?:i|we)\s+(?:want|would\s+like|need|expect)\s+to\s+see\s+"
        r"(?:at\s+the\s+end|in\s+the\s+end|afterwards)\s*(?::|is)|(?:the\s+)?(?:goal|aim|objective|target)\s+is"
        r"(?:\s+to\s+have)?)\s*"
        + _OBJECTS
        + r"\s+(?:(?:placed|put|sitting|resting|located|standing|lying)\s+)?(on|onto|in|at)\b",
        r"at the end , \1 should be \2",
    ),
    (r"\b(be|are|is|stay|remain)\s+(?:sitting|resting|lying|standing|sat)\s+(?=(?:on|in|at|upon)\b)", r"\1 "),
    # a posture as the verb of the end state: "should sit on", "must end up in"
    (r"\b(should|must|will)\s+(?:sit|rest|lie|stand|end\s+up)\s+(?=(?:on|in|at|upon)\b)", r"\1 be "),
    # a region "used" by then: "no other region should (ever) have been used" is "should be used"; "ever"
    # in a negated clause adds nothing ("no other region should ever be used")
    (r"(\b(?:no|nothing|not|never)\b[^,;.]*?\b(?:should|must|can|may|will))\s+ever\b", r"\1"),
    (r"\b(should|must|can|may|will)\s+have\s+been\s+(?=(?:used|occupied)\b)", r"\1 be "),
    # the regions used, said as the manner of the move: "..., without using any other region" and "...,
    # using no other region" (also "any region other than those") are "..., and no other region should be
    # used"
    (
        r"\s*,?\s*\b(?:without\s+(?:using|occupying)\s+(?:any\s+)?|(?:using|occupying)\s+no\s+)(?:(?:other|"
        r"another|further)\s+regions?|regions?\s+other\s+than\s+(?:those|these|them|that|the\s+(?:ones|"
        r"regions)\s+(?:named|given|listed|mentioned)))\b",
        ", and no other region should be used",
    ),
    (r"\b(should|must|will)\s+have\s+been\s+(?=" + _PARTICIPLE + r"\b)", r"\1 be "),
    # a move in the perfect, as the passive one above: "should have gone (moved, travelled) to any empty
    # region" is "should go to any empty region" (the state the move leaves, by the end)
    (
        r"\b(should|must|will)\s+have\s+(?:gone|moved|travelled|traveled)\s+(?=(?:to|onto|into|on|in)\b)",
        r"\1 go ",
    ),
    # a sequence of places in the perfect: "should have been on region i (first) and then on region g" is
    # "should be on region i and then on region g" (where it is, in turn); one place alone stays refused
    (
        r"\b(should|must|will)\s+have\s+been\s+(?=(?:on|in|at)\s+(?:regions?\s+)?[b-z]\b[^,;.]*?\b(?:on|in|at|"
        r"onto|to)\s+(?:region\s+)?[b-z]\b)(?=[^,;.]*?\b(?:then|after\s+that|afterwards|later)\b)",
        r"\1 be ",
    ),
    (
        r"\b(should|must|will)\s+have\s+(?:stayed|remained|been\s+kept)\s+(?=(?:empty|clear|free|unoccupied)\b)",
        r"\1 stay ",
    ),
    (
        r"\b(should|must|will)\s+have\s+(?:swapped|exchanged|switched|traded)\s+(places|positions|spots)\b",
        r"\1 swap \2",
    ),
    (r"(\b(?:no|nothing|not|never)\b[^,;]*?)\s+(?:on|along)\s+the\s+way(?:\s+there)?\b", r"\1 at any point"),
    (r",\s*with\s+(?=(?:nothing|no\s+(?:objects?|blocks?))\s+(?:put|placed|set|going|allowed)\b)", ", "),
    # a block's next place after "then" or "first and": "then finish on / end up on / go on to region G"
    (
        r"\b(?:then|(?<=first\s)and(?:\s+then)?)\s+"
        r"(?:finish(?:es)?|ends?\s+up|go(?:es)?|moves?|carr(?:y|ies)\s+on|continues?)\s+"
        r"(?:on\s+)?(?:on|to|onto|in|at)\s+(?=(?:regions?\s+)?[e-j]\b)",
        "then ",
    ),
    # a completion clause, onto the forms the word tables read ("once that is done,"): "that's" is "that s";
    # "they" are the blocks just moved; "in place" or "there" is done
    (r"\b(once|when|after)\s+(that|this|it|everything)\s+s\b", r"\1 \2 is"),
    (
        r"\b(once|when|after)\s+(?:they|all\s+of\s+them|everything)\s+(?:are|is|have\s+been|has\s+been)\s+"
        r"(?:all\s+)?(?:over|across|there|in\s+place)\s*,",
        r"\1 that is done ,",
    ),
    (r"\bafter\s+this\s*,", "after that ,"),
    # a block left alone until another is touched
    (
        rf",?\s*\b(?:with|leaving|leave|keeping|keep)\s+({_BLOCK})\s+(?:left\s+)?(?:alone|untouched|not\s+touched)"
        r"\s+(until|before)\b",
        r" , \1 must not be touched \2",
    ),
    # order words at the end of a clause
    (
        rf"({_BLOCK})\s+(?:{_PUT_DOWN}\s+)?first\s*,?\s*(?:and\s+)?(?:then\s+)?({_BLOCK})\s+"
        r"(?:later|afterwards?|after\s+that|after(?=\s*(?:,|;|$))|next|second|last)\b(?!\s*(?:to|of)\b)",
        r"\1 before \2",
    ),
    (rf"({_BLOCK})\s+(?:later|last|second)\s*,?\s*(?:and\s+)?({_BLOCK})\s+first\b", r"\2 before \1"),
    # "(should be on region I), placed one after another": the participle of the goal's own move
    (
        r",\s*(?:placed|put|set|moved|dropped|laid|going|brought)(?:\s+(?:down|there))?\s+(?=(?:one\s+after\s+"
        r"(?:another|the\s+other)|one\s+by\s+one|one\s+at\s+a\s+time|in\s+turn|sequentially)\s*(?:,|;|$))",
        ", ",
    ),
    (r"\bat\s+your\s+(?:convenience|leisure)\b", "whenever convenient"),
    # a polite tag at the end ("okay" may be gone already: `unspoken` drops it at a clause's end)
    (r"\b(could|would|can|will)\s+you\s+(?:possibly|perhaps|kindly)\b", r"\1 you"),
    # a request's "for me / for us" at a clause's end says whom it pleases, never what to do ("could you
    # swap red and blue for me?")
    (r"\s+for\s+(?:me|us)\s*(?=$|[,;.?!])", " "),
    (
        rf"\b(?:i|we)\s+(?:would\s+like|want|need)\s+((?:regions?\s+)?{_LETTERS})\s+to\s+(?:stay|remain|be\s+kept)\s+"
        r"(?=(?:empty|clear|free|unoccupied|vacant)\b)",
        r"\1 must stay ",
    ),
    # regions kept empty; one object per region
    # "keep every block (the blocks, everything, them) out of / away from F, G and H" puts nothing there
    (
        r"\bkeep\s+(?:every\s+(?:block|object|pillar)|any\s+(?:block|object|pillar)|(?:all\s+)?(?:the\s+)?(?:three\s+)?"
        r"(?:blocks|objects|pillars)|everything|anything|them)\s+(?:out\s+of|away\s+from)\s+",
        "put nothing on ",
    ),
    # ... and said of the blocks: "the blocks stay (must remain) out of F, G and H" (h215)
    (
        r"\b(?:every\s+(?:block|object|pillar)|(?:all\s+)?(?:the\s+)?(?:three\s+)?(?:blocks|objects|pillars))\s+"
        r"(?:(?:must|should|shall|will|are\s+to)\s+)?(?:stays?|remains?|keeps?)\s+(?:out\s+of|away\s+from)\s+",
        "put nothing on ",
    ),
    # "until the blocks are placed (have all been moved)": until every goal is met, as "until you are done"
    (
        r"\buntil\s+(?:all\s+)?(?:the\s+)?(?:three\s+)?(?:blocks|pillars|objects)\s+(?:are|have\s+been)\s+(?:all\s+)?"
        r"(?:placed|moved|transferred|in\s+place|put\s+down|delivered)\b",
        "until you are done",
    ),
    (r"\b(?:free|clear|empty)\s+of\s+(?:objects|blocks|pillars|anything|everything|items|things)\b", "empty"),
    (
        rf",?\s*\bwhile\s+(?:keeping|you\s+keep|we\s+keep)\s+((?:regions?\s+)?{_LETTERS})\s+"
        r"(empty|clear|free|unoccupied|vacant)\b",
        r" , while \1 stay \2",
    ),
    (
        r"\b(?:there\s+(?:should|must|can|may|will)\s+(?:never|not)\s+be\s+|(?:never|no|not)\s+)"
        r"more\s+than\s+one\s+(?:object|block|pillar|item)?\s*(?:in|on|per)\s+(?:a|any|each|every|one)\s+region\b",
        "one object per region",
    ),
    (
        r"\b(?:(?:you|we|they)\s+)?(?:cannot|can\s+not|must\s+not|should\s+not|may\s+not|do\s+not|never)\s+"
        r"(?:(?:have|put|place|set|leave)\s+)?two\s+(?:(?:objects|blocks|pillars)\s+)?(?:on|in)\s+"
        r"(?:the\s+same|one|a\s+single)\s+region\b",
        "one object per region",
    ),
    (
        r"(,\s*)(?:only\s+|just\s+|exactly\s+)?one\s+(?:block|object|pillar)\s+(?:on|in|to)\s+each\s+"
        r"(?:of\s+(?:those|these|the)\s+regions|region)\b",
        r"\1one object per region",  # after a comma ("put one block in each region" is read as is)
    ),
    (
        r"\bin\s+(?:each|every)\s+region\s+(?:only\s+|just\s+)?one\s+(block|object|pillar)\b",
        r"only one \1 in each region",
    ),
)
_COMPILED = rewrite_table((re.compile(pattern), replacement) for pattern, replacement in _RULES)
_WISH_VERB = re.compile(rf"{_START}{_WISH_BEFORE_VERB}\s+(?=(?:{VERB}|swap|exchange|keep|make)\b)")
# "would you mind moving ...": a request, read as its verb (a touching verb is not a placing request)
_MINDED = {g: v for g, v in (GERUND_VERBS | NEGATED_GERUNDS).items() if v not in ("touch", "grab", "pick up")}
_MIND = re.compile(rf"{_START}(?:would|do|will)\s+you\s+(?:please\s+)?mind\s+({'|'.join(_MINDED)})\b")
# "might I (also) ask that X be placed ...": a request for what follows ("it is requested that ..."); "might I
# ask you to move ...": the verb
_MAY_I_ASK = re.compile(
    rf"{_START}(?:might|may|could|can)\s+(?:i|we)\s+(?:also\s+)?(?:ask|request)\s+(?:you\s+)?(that|to)\b"
)
_WISH_PARTICIPLE = re.compile(rf"{_START}{_WISH_WITH_PARTICIPLE}\s+{_OBJECTS}\s+({_PARTICIPLE})\b")
# the goal named by a noun, then what it is: "the aim is to have / get X placed on P" (the wish "get X placed
# on P"); "the aim is for X to be placed on P (and for Y to be exchanged)" (X must be placed on P, and Y must
# be exchanged)
_AIM = r"(?:the|my|our)\s+(?:aim|goal|objective|purpose|intention|target)(?:\s+here)?\s+(?:is|will\s+be)"
_AIM_HAVE = re.compile(rf"^\s*{_AIM}\s+to\s+(?=(?:have|get)\s+{_OBJECTS}\s+{_PARTICIPLE}\b)")
# a request said as a possibility: "is it possible / would it be possible for X to V" (X must V)
_AIM_FOR = re.compile(rf"^\s*(?:{_AIM}|(?:is\s+it|would\s+it\s+be)\s+possible)\s+for\s+")
_SUBJECT = r"((?:the|all|both|each|every|three|two|red|blue|yellow)\b[^,;:]*?)\s+to\s+"
_FOR_SUBJECT = re.compile(rf"(^|\band\s+)for\s+{_SUBJECT}")
_FIRST_SUBJECT = re.compile(rf"^{_SUBJECT}")


def _aim_said(text: str) -> str:
    """'the aim is for X to be V-ed ... and for Y to V' -> 'X must be V-ed ... and Y must V'; 'the aim is to
    have / get X V-ed' -> 'get X V-ed' (a wish, read by `_WISH_PARTICIPLE`)."""
    text = _AIM_HAVE.sub(" ", text)
    after = _AIM_FOR.sub("", text, count=1)
    if after == text or not _FIRST_SUBJECT.match(after):
        return text
    return _FOR_SUBJECT.sub(r"\1\2 must ", _FIRST_SUBJECT.sub(r"\1 must ", after, count=1))


# "..., and the yellow block went to ...": the same wish goes on
_AND_WENT = re.compile(rf"(,|\band\b)\s*{_OBJECTS}\s+went\b")
_PAST_WISH = re.compile(
    rf"{_START}it\s+would\s+be\s+{_GOOD}\s+if\s+{_OBJECTS}\s+"
    rf"(?:went|moved|got\s+({_PARTICIPLE})|(?:were|was)\s+({_PARTICIPLE})|"
    r"(?P<swapped>(?:swapped|exchanged|switched|traded)\s+(?:places|positions|spots)))\b"
)
# "let's have the yellow block go to I": the block's move
_WISH_GO = re.compile(
    rf"{_START}(?:let\s+(?:s|us)\s+(?:have|get)|have|get)\s+{_OBJECTS}\s+(?:go|move|travel)\b"
)


# "red and blue need swapping", "the blocks need moving onto ...": the passive need ("need to be swapped")
_BY_VERB = {verb: participle for participle, verb in _PARTICIPLES.items()}
_NEED_GERUND = re.compile(
    r"\b(needs?)\s+("
    + "|".join(g for g, v in (GERUND_VERBS | NEGATED_GERUNDS).items() if v in _BY_VERB)
    + r")\b"
)


def _need_as_passive(match: re.Match[str]) -> str:
    return f"{match[1]} to be {_BY_VERB[(GERUND_VERBS | NEGATED_GERUNDS)[match[2]]]}"


def _go_as_command(match: re.Match[str]) -> str:
    """ "have X go to P" is "move X to P"; "have X go down / first / before Y" is "X must go down ...": its
    going down is its placing, never its pick-up ("move X before Y" says which block moves first)."""
    if not match[0].rstrip().endswith("move") and _GO_WHEN.match(match.string, match.end()):
        return f"{match[1]} {match[2]} must go"
    return f"{match[1]} move {match[2]}"


_GO_WHEN = re.compile(r"\s+(?:down|first|last|before|after|ahead|earlier|later|next)\b")


def _as_command(match: re.Match[str]) -> str:
    return f"{match[1]} {_PARTICIPLES[match[3]]} {match[2]}"


def _past_as_command(match: re.Match[str]) -> str:
    participle = match[3] or match[4]
    if match["swapped"]:
        return f"{match[1]} swap {match[2]}"  # "... if X and Y swapped places"
    return f"{match[1]} {_PARTICIPLES[participle] if participle else 'move'} {match[2]}"


def unwished(text: str) -> str:
    """The lower-cased sentence with its wishes, final-state goals and completion clauses said as commands
    (see the module docstring).

    >>> unwished("would it be possible to move the three blocks to h , i and j")
    ' move the three blocks to h , i and j'
    >>> unwished("i would like the three pillars moved to e , f and g")
    ' move the three pillars to e , f and g'
    """
    text = _aim_said(text)
    text = _MIND.sub(lambda m: f"{m[1]} {_MINDED[m[2]]}", text)
    text = _MAY_I_ASK.sub(lambda m: f"{m[1]} it is requested that" if m[2] == "that" else f"{m[1]} ", text)
    text = _WISH_VERB.sub(r"\1 ", text)
    text = _WISH_PARTICIPLE.sub(_as_command, text)
    text = _WISH_GO.sub(_go_as_command, text)
    text = _NEED_GERUND.sub(_need_as_passive, text)
    text, wishes = _PAST_WISH.subn(_past_as_command, text)
    if wishes:
        text = _AND_WENT.sub(r"\1 move \2", text)
    return apply(_COMPILED, text)
