"""Spoken and instructor styles of the handover instructions, normalised before the reader's word tables
(`handover_phrases.normalise` calls `unspoken` on the lower-cased, typo-mended sentence).

General steps, each removing only words that carry no block, place, arm, count, negation, order or
time (a word that might carry one is left for the reader, which reads it or refuses naming it):

- contractions spelled out ("shan't" before the general "n't"); a time said before a scene statement
  ("right now, the red block is on g") kept as "currently" for the scene reader, not dropped as fillers;
- discourse fillers and hedges: hesitations ("um", "uh", "er"), "basically", "yeah",
  interjections that open a clause or tag its end ("okay so", "right,", "..., alright?", "oh and"),
  "just" before a verb ("just drop them", never "just the red block"), a hedge on the whole request
  ("i think", "if possible,", "it would be best if you could", "maybe" or "ideally" before a verb or rule);
- self-corrections: a phrase said again after a hesitation or "i mean" / "sorry" ("the three, uh, the
  three objects", "to i, er, region i") is read once, in its second wording; a correction that says
  something else ("on g, i mean h") is refused, naming it: the reader never guesses which was meant;
- second-person narration read as commands: "you'll put", "you want to place", "your job is to",
  "what we're going to do is", "in this exercise you move", "you start by placing" (first),
  "you may not / you're not allowed to" (do not), also after the time or period said first ("meanwhile
  you won't place ...", "during this period you will not ...");
- left dislocation: a topic set off before its clause and taken up in it by a pronoun of its number ("the
  three blocks, I need them on ...", "the blue block, don't touch it until ...", "regions F, G and H,
  nothing may go on them") is put in the pronoun's place; otherwise it is left, and refused by name;
- unpunctuated dictation: where no comma, semicolon or colon is written, a clause break is restored where
  a colour follows a block, a region letter or "placed first" ("swap the red and blue blocks red placed
  first yellow to ..."), and around a step marker that a command follows ("... touched the red block after
  all of these place the yellow block ...").
"""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.courtesy import courtesy_pattern
from nl2hltl2plan.language.grammar.everyday import HESITATION
from nl2hltl2plan.language.handover_regex import apply, rewrite_table
from nl2hltl2plan.language.handover_words import GERUND_VERBS, NEGATED_GERUNDS, VERB

# contractions spelled out first, so that each rule below has one form to match
_CONTRACTIONS = (
    (r"\bcan\s*'\s*t\b", "cannot"),
    (r"\bwon\s*'\s*t\b", "will not"),
    (r"\bshan\s*'\s*t\b", "shall not"),  # before the rule below, which would leave "sha not"
    (r"n\s*'\s*t\b", " not"),
    (r"\b(you|we|they|i)\s*'\s*ll\b", r"\1 will"),
    (r"\b(you|we|they)\s*'\s*re\b", r"\1 are"),
    (r"\b(you|we|they|i)\s*'\s*ve\b", r"\1 have"),
    (r"\b(you|we|i|it|that|they)\s*'\s*d\b", r"\1 would"),
    # spoken spellings
    (r"\bgonna\b", "going to"),
    (r"\bwanna\b", "want to"),
    (r"\bgotta\b", "have to"),
    (r"\b(?:kinda|sorta)\b", " "),
    # a dialect's dropped letters: "movin'", "puttin'" (the g), "'fore" (be-), "oughta"
    (r"\b([a-z]{2,}in)\s*'(?=\s|$|[,.;:!?])", r"\1g"),
    (r"(?<![a-z])'\s*fore\b", "before"),
    (r"\boughta\b", "ought to"),
    (r"\by\s*'\s*all\b", "you"),  # "would y'all mind", "y'all gonna move"
    (r"\bthem\s+(?=(?:three|two|both|red|blue|yellow|blocks?|pillars?|objects?)\b)", "the "),  # "them blocks"
)
_HESITATION = rf"(?:{HESITATION}|ah+)"
_POLITE_TAG = courtesy_pattern("clause")  # the courtesy frames (`courtesy.txt`)
_INTERJECTION = r"(?:okay|ok|alright|all\s+right|right|so|well|now|oh|hi|hey|hello|listen|look|yeah|yep|yup)"
_MARKER = r"(?:i\s+mean|i\s+meant|sorry|or\s+rather|no\s+wait|wait(?=\s*,)|~)"
# words that a restated phrase may add or leave out without saying something else
_RESTATED_FREELY = frozenset({"the", "region", "regions", "block", "blocks", "one", "ones", ","})
_VERB_AFTER_SUBJECT = r"(?:goes|go|comes|is|are|must|should|has|have|needs?|gets?|will|can|may)"
_OPEN = r"(?:and|or|the|a|to|on|onto|in|into|of|at|is|are|be|,)"
_GERUNDS = GERUND_VERBS | NEGATED_GERUNDS | {"returning": "return"}  # the one the tables lack
_VERB_OR_RULE = rf"(?:{VERB}|exchange|swap|fill|touch|keep|leave|do\s+not|no|nothing|never|make|be)\b"

# a time said before a scene statement ("right now, the red block is on g"): kept for the scene reader as
# "currently" (else "right" and "now" are dropped as interjections and the statement reads as a goal)
_SCENE_TIME = (
    r"(^|,)\s*(?:right\s+now|just\s+now|now|at\s+(?:the|this)\s+(?:moment|point|time)|at\s+present|presently|"
    r"currently|as\s+(?:things|it)\s+stands?|as\s+of\s+(?:now|right\s+now)|for\s+now)\s*,?\s*"
    r"(?=[^,;]*?\b(?:is|are|sits?|sitting|lies?|lying|stands?|standing|rests?|resting)\s+(?:(?:now|currently|still)\s+)?"
    r"(?:on|in|at)\b)"
)
# fillers and hedges that carry no meaning, each only in the place where it cannot carry one
_FILLERS: tuple[tuple[str, str], ...] = (
    (_SCENE_TIME, r"\1 currently "),
    # after a conjunction that opens a clause ("but uh dont touch ...") a hesitation restates nothing ("or
    # uh" may correct: left to the marker below)
    (rf"\b(and|but|so|then)\s*,?\s*{_HESITATION}\b\s*,?", r"\1 "),
    (rf"\b{_HESITATION}\b", " , ~ , "),  # a soft correction marker: what follows may restate what went before
    (r"\b(?:basically|literally|honestly|yeah|yep|yup)\b", " , "),
    (r"\boh\b", " , "),
    (r",\s*like\s*(?=,)", " "),  # "the blocks, like, go ..."
    (rf"\b({VERB})\s+like\s+(?=(?:the|all|both|every|each|three|two)\b)", r"\1 "),  # "put like all three ..."
    # unpunctuated (a voice transcript): "and you know only one ..." (an "okay" at the end is a frame word)
    (r"\b(and|so|but)\s+you\s+know\b", r"\1"),
    # a tag at the end of a clause ("..., right?", "..., okay") or interjections opening one
    (rf",\s*{_INTERJECTION}\s*$", " "),
    (rf"(^|,|\band\b)\s*(?:{_INTERJECTION}\s*(?:,\s*|\s+(?={_INTERJECTION}\b)|\s+(?=so\b)))+", r"\1 "),
    (
        r"^\s*(?:so|now|okay|ok|alright|well)\s+(?=what\b|here\b|the\b|all\b|first\b|your\b|you\b|we\b|in\b|for\b|today\b)",
        " ",
    ),
    (rf"\b(please|you|we|to|and)\s+like\s+(?=(?:{VERB}|swap|exchange)\b)", r"\1 "),  # "can you like swap ..."
    # "just drop all three blocks", "just make sure": "just" before a verb ("just the red block" is left)
    (rf"\b(?:just|simply)\s+(?=(?:{VERB}|stick|make|drop|swap|exchange|keep)\b)", " "),
    # a hedge on the whole request
    (r"(^|,|\band\b)\s*(?:i|we)\s+(?:think|guess|suppose|reckon|believe)\s+(?:that\s+)?", r"\1 "),
    (r"^\s*(?:i|we)\s+(?:was|were)\s+(?:thinking|wondering)\s*,", " "),
    (r",\s*(?:i|we)\s+(?:guess|think|suppose|reckon|believe|would\s+say)\s*$", " "),
    (r"^\s*if\s+(?:possible|you\s+can|you\s+could)\s*,", " "),
    (r"\s*,?\s*\bif\s+(?:possible|you\s+can)\s*$", " "),
    # a polite tag that opens or closes a clause: "if you don't mind", "if that's okay", "if you would (be
    # so kind)", "when you get a chance" (no time of any goal: the plan is as short as it can be anyway)
    (rf"(^|,)\s*{_POLITE_TAG}\s*(?=,|$)", r"\1 "),
    (rf"\b{courtesy_pattern('wish')}\b", "please"),  # courtesy.txt's polite wishes
    (r"^\s*(?:i|we)\s+would\s+(?:probably\s+|maybe\s+)?have\s+you\s+", "please "),
    # a hedge adverb in a clause with a verb ("should probably go", "ideally the red block gets placed ..."):
    # it softens a request; in a fragment without one ("maybe the red block first?") it may ask or suggest,
    # and before "not" it may negate what follows: left there, and refused by name
    (
        rf"\b(?:probably|maybe|perhaps|ideally|preferably)\b(?!\s+not\b)"
        rf"(?=[^,;:?]*\b(?:{_VERB_OR_RULE}|go|goes|gets?|should|must|needs?|(?:is|are|be)\s+\w+ed)\b)",
        " ",
    ),
    # "(it's) best if X": X is wished for, as "it would be best if you could" is
    (
        r"(^|,|\band\b)\s*(?:(?:it\s+is|it\s+would\s+be)\s+)?best\s+(?:if|that)\s+(?=no\b|nothing\b|the\b|you\b)",
        r"\1 ",
    ),
    (r"\btry\s+not\s+to\b", "do not"),
    (rf"\btry\s+to\s+(?={VERB}\b)", " "),
    # a closer that adds nothing: "and that's all there is to it", "that's it"
    (r"(?:^|,|\band\b)\s*that\s*(?:'\s*)?s\s+(?:all|it)(?:\s+there\s+is\s+to\s+it)?\s*$", " "),
    (r"(?:^|,)\s*that\s*(?:'\s*)?s\s+the\s+only\s+thing\s*$", " "),
    (
        r"^\s*(?:the\s+)?(?:one\s+|only\s+)?thing\s+(?:to\s+(?:watch|remember|note)(?:\s+out\s+for)?\s+)?is\s*(?:that\b|,)",
        " ",
    ),
    # what a teacher asks the class to notice: "remember, ...", "you'll notice each region ..."
    (r"(^|,)\s*(?:and\s+)?(?:remember|notice|note)\s*,", r"\1 "),
    (
        r"(^|,|\band\b)\s*(?:you\s+(?:will|may|can|should|might)\s+)?(?:(?:notice|see)\s+that\b|notice\s+(?=(?:each|every|only|no|nothing|none)\b))",
        r"\1 ",
    ),  # not "you'll see the red block on g": a scene, not a rule
    # when ("today you ...", "today the robots move ...", "your task today:"; who is spoken to, "alright
    # class,", is a frame word of `handover_discourse`)
    (r"^\s*(?:today|this\s+time|for\s+today)\s*,?\s*(?=(?:you|we|the\s+(?:robots?|arms?))\b)", " "),
    (r"\b(your|the|our)\s+(task|job|goal|exercise)\s+(?:today|this\s+time|here|for\s+today)\b", r"\1 \2"),
)

# second-person narration and framing, read as the command it describes
_SUBJECT = r"(?:you|we)"
# (not "you can / may / get to put ...": a permission is not a command)
# ("you would move ...": the plan said as what one would do; "you would like ..." is a wish, read elsewhere)
_WILL = (
    r"(?:\s+will|\s+shall|\s+would(?!\s+like\b)|\s+are\s+going\s+to|\s+want\s+to|\s+need\s+to|\s+have\s+to|"
    r"\s+must|\s+should)?"
)
# where a narrated command may start: a clause's start, a step word, or its time or period said first
# ("meanwhile you won't place ...", "during this period you will not place ...")
_ANCHOR = (
    r"(^|,|;|\band\b|\bthen\b|\bfirst\b|\bat\s+(?:some|any)\s+(?:point|time)\b|\bmeanwhile\b|"
    r"\bin\s+the\s+meantime\b|\bthroughout\b|\bduring\s+(?:this|that|the\s+whole)\s+(?:period|time)\b)"
)
_NARRATION: tuple[tuple[str, str], ...] = (
    (
        r"^\s*(?:in|for)\s+this\s+(?:task|exercise|run|one|activity|lesson|part|round|session|step)\s*,?\s*",
        " ",
    ),
    (
        rf"\bwhat\s+{_SUBJECT}{_WILL}\s+(?:be\s+)?do(?:ing)?\s+(?:here\s+|now\s+|today\s+|next\s+)?is\s+(?:to\s+)?",
        "please ",
    ),
    (r"^\s*(?:so\s+)?(?:here\s+)?(?:we|you)\s+have\s+(?=(?:the\s+)?(?:three|two|\d)\s+)", "there are "),
    # "once you have done that": once that is done
    (
        rf"\b(once|when|after)\s+{_SUBJECT}\s+(?:have\s+|are\s+)?(?:done|finished|completed)\s+"
        r"((?:all\s+(?:of\s+)?)?(?:this|that|these|everything))\b",
        r"\1 \2 is done",
    ),
    (rf"\b{_SUBJECT}\s+(?:start|begin)\s+by\s+", "first "),
    (r"^\s*(?:start|begin)\s+by\s+", "first "),
    # "you will be moving", "we are moving", "we are not placing": the verb
    *(
        (rf"\b{_SUBJECT}{_WILL}\s+be\s+(?:(first|also|then)\s+)?{gerund}\b", rf"\1 {verb}")
        for gerund, verb in _GERUNDS.items()
    ),
    *(
        (rf"\b{_SUBJECT}\s+are\s+(?:(first|also|then|now)\s+)?{gerund}\b", rf"\1 {verb}")
        for gerund, verb in _GERUNDS.items()
    ),
    *(
        (rf"\b{_SUBJECT}\s+are\s+(?:not|never)\s+{gerund}\b", f"do not {verb}")
        for gerund, verb in _GERUNDS.items()
    ),
    (
        rf"{_ANCHOR}\s*{_SUBJECT}(?:\s+will|\s+shall|\s+would|\s+must|\s+may|\s+should|\s+are)?\s+(?:not\s+|never\s+)"
        rf"(?:be\s+)?(?:allowed\s+to\s+|going\s+to\s+)?(?=(?:{VERB}|touch|place|drop|set|leave)\b)",
        r"\1 do not ",
    ),
    (
        rf"{_ANCHOR}\s*{_SUBJECT}\s+(?:cannot|can\s+not|do\s+not\s+want\s+to|would\s+not\s+want\s+to)\s+(?=(?:{VERB}|touch)\b)",
        r"\1 do not ",
    ),
    (
        rf"{_ANCHOR}\s*{_SUBJECT}(?:\s+(?:also|then|now|just))?{_WILL}\s+(?:(first|also|then|now)\s+)?"
        rf"(?=(?!want\b|need\b)(?:{VERB}|exchange|swap|fill|touch)\b)",  # "we want them on ...": a need
        r"\1 \2 ",
    ),
    (r"\b(?:can|could)\s+we\s+", "please "),
    (r"\b(?:how\s+about|why\s+do\s+not)\s+(?:you|we)\s+(?=(?:" + VERB + r"|swap|exchange)\b)", "please "),
    # spoken idioms of the rules: "hands off X until ...", "you can't double up", "doesn't matter when"
    # "until somebody's touched the red one": has touched; but "once that's done": that is done (passive)
    (r"\b(that|this|it|everything|all|which)\s+s\s+(?=(?:done|finished)\b)", r"\1 is "),
    # (a block's "'s touched" is its passive: "until red's touched", the red block has been touched)
    (
        r"\b(red|blue|yellow|block|one|cube|pillar)\s+s\s+(?=(?:touched|picked|grabbed|handled|lifted)\b)",
        r"\1 has been ",
    ),
    (r"\b([a-z]+)\s+s\s+(?=(?:touched|picked|grabbed|handled|lifted|done|finished)\b)", r"\1 has "),
    # a block named as a field's label, its touch guard after the colon (a coach's verbless order): "blue :
    # hands off till ...", "blue block : do not touch (it) until ..."
    (
        r"\b(red|blue|yellow)(?:\s+(?:block|one|cube))?\s*:\s*(?:(?:keep\s+(?:your|the|their)\s+)?hands\s+off|"
        r"(?:do\s+not|don't|never)\s+touch(?:\s+it)?|no\s+touching)\s+(?=(?:until|till|til|before)\b)",
        r"do not touch the \1 block ",
    ),
    (
        r"\b(?:keep\s+(?:your|the|their)\s+)?hands\s+off\s+(?=(?:the\s+)?(?:red|blue|yellow)\b)",
        "do not touch ",
    ),
    (
        r"\b(?:keep|stay)\s+(?:off|away\s+from|clear\s+of)\s+(?=(?:the\s+)?(?:red|blue|yellow)\b)",
        "do not touch ",
    ),
    (
        r"\b(?:you\s+)?(?:cannot|can\s+not|do\s+not|no)\s+doubl(?:e|ing)\s+up"
        r"(?:\s+(?:on|in)\s+(?:a|any|one|the\s+same)\s+(?:region|spot|place|area|cell))?\b",
        "one block per region",
    ),
    (r"(?<!\bit\s)\bdoes\s+not\s+matter\s+(?=when\b|at\s+what\b)", "it does not matter "),
    # said twice in one clause: "then put the yellow block back on g afterwards"
    (r"(\bthen\b[^,]*?)\s*,?\s*\bafterwards?\s*$", r"\1"),
    # "..., each one on its own region": one block per region
    (
        r",\s*each(?:\s+one)?\s+(?:on|in|to|gets)\s+(?:its|their)\s+own\s+(?:region|spot|place)s?\b",
        ", one per region",
    ),
    (r"\b(?:stick|shove|plonk|chuck|bung)\b", "put"),
)


# compiled once: with the reader's other tables they are more than `re`'s cache holds
_STEPS = tuple(
    rewrite_table((re.compile(pattern), replacement) for pattern, replacement in table)
    for table in (_CONTRACTIONS, _FILLERS, _NARRATION)
)

_COMMAS = re.compile(r"(\s*,)+")  # a run of commas, each with the space before it


def unspoken(text: str) -> str:
    """The sentence with its spoken fillers, hedges, repeated phrases and narration normalised away (see
    the module docstring); a self-correction that says something else is refused."""
    contractions, fillers, narration = _STEPS
    text = apply(fillers, apply(contractions, _clause_breaks(text)))
    text = _COMMAS.sub(" ,", _said_once(text))  # the commas left where fillers were
    text = apply(narration, apply(fillers, text))  # fillers again: an opener behind a hesitation
    text = _resumed(_COMMAS.sub(" ,", text))
    text = re.sub(r"^\s*,|,\s*$", " ", text)
    text = re.sub(r"\b(the|a|and|to|on|in)\s+\1\b", r"\1", text)  # a stutter: "the the"
    return " ".join(text.split())


# dictated without punctuation: where a phrase that ends on a block, a region letter or "placed first" meets a
# colour, a new clause begins ("exchange the red and blue blocks red placed first yellow to ...", "then to
# g red and blue to any empty region"); "a" is the article, "one" a count, never a phrase's end here
_CLAUSE_BREAK = re.compile(
    r"\b((?:blocks?|pillars?|objects?|ones|side|regions?|[b-j])|(?:placed|put|moved|goes|going)\s+first)"
    r"\s+(?=(?:the\s+)?(?:red|blue|yellow)\b)"
)


# ... and after a step marker that a bare colour follows ("after that yellow back to g"; not "after that
# yellow block", where "that" may be the determiner)
_MARKER_BREAK = re.compile(
    r"\b(after\s+(?:that|this)|afterwards)\s+(?=(?:red|blue|yellow)\b(?!\s+(?:blocks?|ones?|cubes?|pillars?)\b))"
)


# ... and around a step marker that a command follows ("... until an arm touched the red block after all of
# these place the yellow block ...": the marker opens the command, never the clause before it, and "these"
# is no determiner of "place")
_STEP_BREAK = re.compile(
    r"(?:(?<=\w)\s+|^\s*)(after\s+all(?:\s+of)?\s+(?:these|this|that|them)|after\s+(?:that|this)|afterwards)"
    rf"\s+(?=(?:please\s+)?{VERB}\b)"
)


def _clause_breaks(text: str) -> str:
    """The commas of a sentence dictated without any punctuation, restored at the clause breaks of
    `_CLAUSE_BREAK`, `_MARKER_BREAK` and `_STEP_BREAK`; a sentence with a comma, semicolon or colon is left
    as it is."""
    if re.search(r"[,;:]", text):
        return text
    text = _STEP_BREAK.sub(r" , \1 , ", _TOPIC_BREAK.sub(r"\1 , ", text))
    return _MARKER_BREAK.sub(r"\1 , ", _CLAUSE_BREAK.sub(r"\1 , ", text))


# ... and after a topic said first, where its clause's subject and a pronoun that takes it up follow ("so
# the three blocks i need them on ..."); `_resumed` then puts the topic back in the pronoun's place
_TOPIC_BREAK = re.compile(
    r"^(\s*(?:(?:so|okay|ok|right|now|well|um|uh)\s+)*(?:the\s+)?"
    r"(?:(?:all|three|two|red|blue|yellow|and|both)\s+){0,4}(?:blocks?|pillars?|objects?))\s+(?=(?:i|we|you)(?:['’]d)?\s+(?:\S+\s+){1,3}?(?:them|it)\b)"
)


# a left-dislocated topic: blocks ("the three blocks", "the red one") or named regions ("regions f, g and h")
_TOPIC = (
    r"(?:the\s+)?(?:(?:all|three|two|red|blue|yellow|and|both)\s+){0,4}(?:blocks?|pillars?|objects?|ones?)"
    r"|regions\s+[a-z](?:\s*,\s*[a-z])*\s+(?:and|or)\s+[a-z]|region\s+[a-z]"
    r"|each\s+(?:of\s+(?:those|these|the)\s+regions|region)|(?:any|every)\s+other\s+region"
)
_DISLOCATED = re.compile(
    rf"(^|[,;:])\s*(?P<conj>and\s+)?(?P<topic>{_TOPIC})\s*,\s*(?!(?:and|or|but|then|so)\b)"
    # (not a count set off after the noun: "the blocks, all three of them, go ...")
    r"(?!\s*(?:all\s+(?:\w+\s+)?|both\s+|the\s+\w+\s+|every\s+one\s+)of\s+them\b)"
    r"(?P<before>[^,;:]*?)\b(?P<pro>they|them|it|that\s+one|th(?:o|e)se(?:\s+ones)?|their\s+(?:positions|places))\b"
)


def _resumed(text: str) -> str:
    """A topic set off before its clause and taken up there by a pronoun that agrees with it in number
    ("the three blocks , i want them moved ...", "the blue block , do not touch it until ...") is put back in
    the pronoun's place; a pronoun of the other number, or none in the next clause, leaves the text as it is
    (then refused by name: "the red block , the blue block ..." is a list, not a topic)."""

    def put_back(match: re.Match[str]) -> str:
        topic, pronoun = match.group("topic"), match.group("pro")
        plural = bool(re.search(r"s$|\band\b|\bor\b|\bboth\b", topic)) and not topic.startswith("each")
        if plural != (pronoun not in ("it", "that one")):
            return match.group(0)
        said = f"the {pronoun.split()[1]} of {topic}" if pronoun.startswith("their") else topic
        return f"{match.group(1)} {match.group('conj') or ''}{match.group('before')}{said}"

    return _DISLOCATED.sub(put_back, text)


def _said_once(text: str) -> str:
    """A phrase said again after a hesitation or a correction marker, in other words that add or drop only
    `_RESTATED_FREELY`, is kept once (its second wording); after a marker ("i mean", "sorry") that is
    followed by something else the sentence is refused; a hesitation followed by something else is dropped."""
    while marker := re.search(rf"(?:\s*,)*\s*(?<!\w){_MARKER}(?!\w)(?:\s*,)*\s*", text):
        before, after = text[: marker.start()].split(), text[marker.end() :].split()
        said = marker.group().strip(" ,")
        if not before and (
            said == "~" or (said == "sorry" and after[:1] in (["could"], ["can"], ["would"], ["please"]))
        ):
            text = " ".join(after)  # "sorry, could you ...": politeness
            continue
        # a correction that opens the sentence ("No wait, ...") corrects the one before: refused
        found = _restated(before, after) if before else None
        if found is None and said != "~":
            raise HTTError(
                f"a self-correction in {' '.join(before[-4:] + [said] + after[:4])!r}: say what is meant once"
            )
        if found is None:  # a hesitation inside a phrase ("on g, h and, uh, i") leaves no comma behind
            text = " ".join(before + after if re.fullmatch(_OPEN, before[-1]) else before + [","] + after)
            continue
        cut, length = found
        # "the red block, i mean the red block, goes ...": no comma between the subject and its verb
        if after[length : length + 1] == [","] and re.fullmatch(
            _VERB_AFTER_SUBJECT, "".join(after[length + 1 :][:1])
        ):
            after = after[:length] + after[length + 1 :]
        text = " ".join(before[:cut] + after)
    return text


def _restated(before: list[str], after: list[str]) -> tuple[int, int] | None:
    """Where the phrase that `after` begins by saying again starts in `before` (the longest such end of
    `before`, compared without `_RESTATED_FREELY`), and how many words of `after` say it; or None."""
    for n in range(min(8, len(before)), 0, -1):
        said = [w for w in before[-n:] if w not in _RESTATED_FREELY]
        if not said or before[-n] in _RESTATED_FREELY:
            continue
        content = [i for i, w in enumerate(after) if w not in _RESTATED_FREELY][: len(said)]
        if [after[i] for i in content] == said:
            length = content[-1] + 1  # with the words that end the phrase ("the red one")
            while after[length : length + 1] and after[length] in _RESTATED_FREELY - {","}:
                length += 1
            return len(before) - n, length
    return None
