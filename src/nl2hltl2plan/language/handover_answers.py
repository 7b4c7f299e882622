"""Two sentences of a handover instruction that say one thing, joined before the sentences are read
(`handover_reading.translate_handover` calls them):

- a question the writer answers at once (`answered`, on the instruction's text): "Where do the three
  objects go? G, H and I." is "the three objects go to G, H and I."; "Which block first? Red, then blue."
  is "red first, then blue."; "In what order? / Order? Red, then blue." is "red before blue."; "Which
  blocks? The three blocks. Where to? H, I and J." is "the three blocks go to H, I and J"; "And yellow? To
  the opposite side." is "yellow go to the opposite side"; "How many per region? Just one." is "one per
  region"; "Anything allowed on the other regions? No, nothing." is "nothing on the other regions"; a step
  or period asked for ("What first?", "And after that?", "Meanwhile?") is said before its answer ("first,
  ..."); a prompt that only asks for the next sentence ("What needs doing?", "What's the job?", "Any
  rule?") is dropped. A question with no answer, or with an answer that is not a place, blocks or "no",
  stays as it is (and is refused by its words);
- a goal's timing said in a sentence of its own (`timing_joined`, on the sentences): "Move the yellow
  block to the opposite side. Yellow can go at any time." (or "It doesn't matter when yellow goes.") is
  "Move the yellow block to the opposite side at any time". Only where the last clause of the sentence
  before names the same blocks and no others, and no order word: otherwise the sentence stays (refused by
  its words), as does a pronoun ("It can go at any time.": which goal?); a next place said alone ("Yellow
  to I. Then to G.") is joined to the sentence before where its last clause names one block. "No
  timing requirement." is "at any time" for the clause before where it names blocks and no order;
  otherwise it is dropped where nothing before says an order ("No other timing requirement." is always
  dropped: the order said is all).
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.handover_scene import COLOUR
from nl2hltl2plan.language.handover_words import VERB

_BLOCK = rf"(?:the\s+)?{COLOUR}(?:\s+(?:block|one|cube|object|pillar))?"
_BLOCKS = rf"{_BLOCK}(?:\s*(?:,|and)\s*{_BLOCK})*(?:\s+(?:blocks|cubes|objects|pillars))?"
_START = r"(?P<start>^|[.;!?][ \t]+)"
_END = r"(?=[ \t]*(?:[.;!]|$))"
_PLACE_START = r"(?:to|on|onto|into|in|at|over\s+to|across\s+to)\b"
_ANSWER = r"(?P<answer>[^?.!;\n]+?)"
_OBJECTS = r"(?P<objects>[^?.!;\n]+?)"

_WHERE = re.compile(
    rf"(?im){_START}where\s+(?:do|does|should|must|will|shall)\s+{_OBJECTS}\s+go(?:\s+to)?\s*\?"
    rf"[ \t]+{_ANSWER}{_END}"
)
_WHICH_FIRST = re.compile(
    rf"(?im){_START}which\s+(?:block|one|object|pillar|cube)?\s*(?:goes|is\s+placed|is\s+put|comes|should\s+go)?"
    rf"(?:\s+down)?\s*first\s*\?[ \t]+(?P<first>{_BLOCK})"
    rf"(?:\s*,?\s*(?:and\s+)?then\s+(?P<then>{_BLOCK}))?{_END}"
)
_WHAT_ORDER = re.compile(
    rf"(?im){_START}(?:(?:in\s+)?(?:what|which)\s+|any\s+|the\s+)?order\s*\?[ \t]+(?P<first>{_BLOCK})\s*,?\s*"
    rf"(?:(?:and\s+)?then|before)\s+(?P<then>{_BLOCK}){_END}"
)

# "Which blocks? The three blocks. Where to? H, I and J.": the blocks asked for, then their place
_WHICH_WHERE = re.compile(
    rf"(?im){_START}(?:which|what)\s+(?:blocks?|objects?|pillars?|things?|moves?|goes)\s*\?[ \t]+{_OBJECTS}"
    rf"[.;][ \t]+where(?:\s+to)?\s*\?[ \t]+{_ANSWER}{_END}"
)
# "And yellow? To the opposite side.": blocks asked about, answered by a place
_AND_BLOCKS = re.compile(
    rf"(?im){_START}(?:and\s+)?(?:what\s+about\s+)?(?P<objects>{_BLOCKS})\s*\?[ \t]+"
    rf"(?P<answer>(?:{_PLACE_START}|any\s+empty|the\s+opposite|regions?\s|whichever\s|whatever\s|"
    rf"(?:some|an?)\s+(?:empty|free|unoccupied)\s)[^?.!;\n]*?){_END}"
)
# "What goes on H, I and J? The three blocks.": the place asked about, answered by the blocks
_WHAT_GOES = re.compile(
    rf"(?im){_START}what\s+(?:goes|should\s+go|is\s+going)\s+(?P<place>{_PLACE_START}[^?.!;\n]+?)\s*\?[ \t]+"
    rf"(?P<objects>(?:the\s+|all\s+)?(?:three\s+|3\s+)?(?:blocks|objects|pillars)|{_BLOCKS}){_END}"
)
# a prompt that only asks for the next sentence ("What needs doing?", "Any rule?", "Order?")
_PROMPT = re.compile(
    rf"(?im){_START}(?:so\s+)?(?:what\s+(?:needs|has|is)\s+(?:to\s+be\s+)?(?:doing|done)|"
    r"what(?:\s+is|\s*['’]s)\s+the\s+(?:job|task|plan)|any\s+(?:rules?|constraints?|order)|(?:the\s+)?order)"
    r"\s*\?[ \t]+(?=\S)"
)
# a step or period asked for ("What first?", "And after that?", "Meanwhile?"): said before its answer
_STEP = re.compile(
    rf"(?im){_START}(?:and\s+)?(?:what\s+)?(?P<step>first|next|then|after\s+that|meanwhile|in\s+the\s+meantime)"
    r"\s*\?[ \t]+(?=\S)"
)
_HOW_MANY = re.compile(
    rf"(?im){_START}how\s+many\s+(?:per\s+region|(?:on|in)\s+each(?:\s+region)?)\s*\?[ \t]+"
    r"(?:just\s+|only\s+)?"
    rf"(?:one|1)(?:\s+each|\s+per\s+region)?{_END}"
)
_ANYTHING_ALLOWED = re.compile(
    rf"(?im){_START}(?:is\s+)?(?:anything|any\s+(?:object|block|pillar)s?)\s+(?:allowed|permitted)\s+"
    rf"(?P<place>(?:on|in)\s+[^?.!;\n]+?)\s*\?[ \t]+no\s*(?:,\s*)?(?:nothing|none|never)?"
    rf"(?:\s+at\s+all)?{_END}"
)


def _where(match: re.Match[str]) -> str:
    # "All onto region I": the place; "First region I, then region G": the first of the block's places
    answer = match["answer"].strip()
    answer = re.sub(rf"(?i)^all(?:\s+(?:three|3|of\s+them))?\s+(?={_PLACE_START})", "", answer)
    first = re.match(r"(?i)first\s+", answer)
    answer = answer[first.end() :] if first else answer
    to = "" if re.match(_PLACE_START, answer, flags=re.IGNORECASE) else "to "
    return f"{match['start']}{match['objects']} go {'first ' if first else ''}{to}{answer}"


def _which_first(match: re.Match[str]) -> str:
    then = f", then {match['then']}" if match["then"] else ""
    return f"{match['start']}{match['first']} first{then}"


def answered(instruction: str) -> str:
    """The instruction with each question that its next sentence answers said as a statement.

    >>> answered("Where do the three objects go? G, H and I. Which block first? Red, then blue.")
    'the three objects go to G, H and I. Red first, then blue.'
    """
    instruction = _WHERE.sub(_where, _WHICH_WHERE.sub(_where, instruction))
    instruction = _AND_BLOCKS.sub(_where, instruction)
    instruction = _WHAT_GOES.sub(lambda m: f"{m['start']}{m['objects']} go {m['place']}", instruction)
    instruction = _WHICH_FIRST.sub(_which_first, instruction)
    instruction = _WHAT_ORDER.sub(lambda m: f"{m['start']}{m['first']} before {m['then']}", instruction)
    instruction = _HOW_MANY.sub(lambda m: f"{m['start']}one per region", instruction)
    instruction = _ANYTHING_ALLOWED.sub(lambda m: f"{m['start']}nothing {m['place']}", instruction)
    instruction = _STEP.sub(lambda m: f"{m['start']}{m['step']}, ", instruction)
    return _PROMPT.sub(lambda m: m["start"], instruction)


_ANY_TIME = r"(?:at\s+any\s+(?:time|point|moment)|any\s*time|whenever(?:\s+you\s+(?:like|want))?)"
_NO_TIME = r"(?:time|timing)\s+(?:constraints?|restrictions?|requirements?)"
# the time left free for every goal said ("No timing requirement."), or for all but the order said ("No
# other timing requirement.")
_NO_TIME_AT_ALL = re.compile(rf"(?i)^\s*(?:and\s+)?(?:there\s+is\s+)?no\s+(?P<other>other\s+)?{_NO_TIME}\s*$")
_MOVED = (
    r"(?:go(?:es)?|be\s+(?:moved|placed|put|done|taken|transferred)|is\s+(?:moved|placed|put|done|taken))"
)
_TIMING = (
    re.compile(
        rf"(?i)^\s*(?:and\s+|also\s+)?(?P<blocks>{_BLOCKS}|it)\s+(?:can|may|could)\s+{_MOVED}\s+{_ANY_TIME}\s*$"
    ),
    re.compile(
        rf"(?i)^\s*it\s+(?:does\s+not|doesn[’']?t|does\s*nt)\s+matter\s+when\s+(?P<blocks>{_BLOCKS})\s+{_MOVED}\s*$"
    ),
    # a time left free in words: "the yellow block has no time constraint", "no timing requirement for yellow"
    re.compile(
        rf"(?i)^\s*(?:and\s+|also\s+)?(?P<blocks>{_BLOCKS})\s+(?:has|have)\s+no\s+{_NO_TIME}\s*$"
    ),
    re.compile(rf"(?i)^\s*(?:and\s+)?no\s+{_NO_TIME}\s+(?:for|on)\s+(?P<blocks>{_BLOCKS})\s*$"),
    # a block's heading before its time alone: "Yellow block: any time", "yellow: whenever", "yellow anytime"
    re.compile(rf"(?i)^\s*(?:[-*•·]\s+)?(?P<blocks>{_BLOCKS})\s*:?\s*{_ANY_TIME}\s*$"),
    # the time alone, of the clause before: "Yellow: opposite side. Whenever."
    re.compile(rf"(?i)^\s*(?:and\s+)?(?P<blocks>){_ANY_TIME}\s*$"),
)
# where the last clause of a sentence starts: a comma or semicolon, or "and" / "then" before a verb
_CLAUSE_BREAK = re.compile(rf"(?i)[,;]|\b(?:and|then)\s+(?=(?:then\s+)?{VERB}\b)")
# a next place alone, the block left to the sentence before: "Yellow to I. Then to G.", "Then on to region G."
_THEN_PLACE = re.compile(
    r"(?i)^\s*(?:and\s+)?then\s+(?:(?:on|over)\s+)?(?:(?:to|onto|on|into|in)\s+)?(?:region\s+)?[e-j]\s*$"
)
_ORDER_WORD = re.compile(r"(?i)\b(?:first|before|after|then|last|later|next|second|time|whenever)\b")


def _colours(text: str) -> set[str]:
    return set(re.findall(COLOUR, text.lower()))


# a sentence that only names the blocks, then one that starts with their place: "Blocks! H, I, J!"
_BARE_BLOCKS = re.compile(
    r"(?i)^\s*(?:the\s+|all\s+)?(?:(?:three|3)\s+)?(?:blocks|objects|pillars|cubes|items)\s*$"
)
_PLACE_OPENS = re.compile(
    r"(?i)^\s*(?:(?:to|onto|on|into)\s+)?(?=regions?\s+[e-j]\b|[e-j]\s*(?:,|and)\s*[e-j]\b|(?:the\s+)?opposite\s+"
    r"(?:side|regions?)\b|any\s+empty\s+region\b)"
)


def fragments_joined(sentences: list[str]) -> list[str]:
    """A sentence that only names the blocks joined to the next one where that one starts with a place:
    "Blocks! H, I, J! One each!" is "Blocks to H, I, J. One each."."""
    out: list[str] = []
    for sentence in sentences:
        if out and _BARE_BLOCKS.match(out[-1]) and (place := _PLACE_OPENS.match(sentence)):
            out[-1] = f"{out[-1].strip()} to {sentence[place.end() :].strip()}"
            continue
        out.append(sentence)
    return out


def timing_joined(sentences: list[str]) -> list[str]:
    """The sentences with a goal's timing said apart ("Yellow can go at any time.") joined to the goal
    before it, as "at any time" (see the module docstring).

    >>> timing_joined(["Move the yellow block to G", "Yellow can go at any time"])
    ['Move the yellow block to G at any time']
    """
    out: list[str] = []
    for sentence in sentences:
        if out and _THEN_PLACE.match(sentence) and len(_colours(_CLAUSE_BREAK.split(out[-1])[-1])) == 1:
            # "Yellow to I. Then to G.": one block's steps
            out[-1] = f"{out[-1].rstrip()}, {sentence.strip()}"
            continue
        said = next((m for p in _TIMING if (m := p.match(sentence))), None)
        if out and (free := _NO_TIME_AT_ALL.match(sentence)):
            last = _CLAUSE_BREAK.split(out[-1])[-1]
            if _colours(last) and not _ORDER_WORD.search(last) and not free["other"]:
                out[-1] = f"{out[-1].rstrip()} at any time"  # of the blocks of the clause before
                continue
            if free["other"] or not any(_ORDER_WORD.search(o) for o in out):
                continue  # says no more than the goals (and the order) said before it
        if said and out:
            last = _CLAUSE_BREAK.split(out[-1])[-1]
            # "It can go at any time": "it" is the one block of the clause before; a time alone, its blocks
            alone = not said["blocks"] and _colours(last)
            one = len(_colours(last)) == 1
            named = _colours(said["blocks"]) or (_colours(last) if one or alone else {"?"})
            if _colours(last) == named and not _ORDER_WORD.search(last):
                out[-1] = f"{out[-1].rstrip()} at any time"
                continue
        out.append(sentence)
    return out
