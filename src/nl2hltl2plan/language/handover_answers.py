"""Two sentences of a handover instruction that say one thing, joined before the sentences are read
(`handover_reading.translate_handover` calls them):

- a question the writer answers at once (`answered`, on the instruction's text): "Where do the three
  objects go? G, H and I." is "the three objects go to G, H and I."; "Which block first? Red, then blue."
  is "red first, then blue."; "In what order? Red, then blue." is "red before blue.". A question with no
  answer, or with an answer that is not a place or blocks, stays as it is (and is refused by its words);
- a goal's timing said in a sentence of its own (`timing_joined`, on the sentences): "Move the yellow
  block to the opposite side. Yellow can go at any time." (or "It doesn't matter when yellow goes.") is
  "Move the yellow block to the opposite side at any time". Only where the last clause of the sentence
  before names the same blocks and no others, and no order word: otherwise the sentence stays (refused by
  its words), as does a pronoun ("It can go at any time.": which goal?).
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.handover_words import VERB

_COLOUR = r"(?:red|blue|yellow)"
_BLOCK = rf"(?:the\s+)?{_COLOUR}(?:\s+(?:block|one|cube|object|pillar))?"
_BLOCKS = rf"{_BLOCK}(?:\s*(?:,|and)\s*{_BLOCK})*(?:\s+(?:blocks|cubes|objects|pillars))?"
_START = r"(?P<start>^|[.;!?][ \t]+)"
_END = r"(?=[ \t]*(?:[.;!]|$))"
_PLACE_START = r"(?:to|on|onto|into|in|at|over\s+to|across\s+to)\b"

_WHERE = re.compile(
    rf"(?im){_START}where\s+(?:do|does|should|must|will|shall)\s+(?P<objects>[^?.!;\n]+?)\s+go(?:\s+to)?\s*\?"
    rf"[ \t]+(?P<answer>[^?.!;\n]+?){_END}"
)
_WHICH_FIRST = re.compile(
    rf"(?im){_START}which\s+(?:block|one|object|pillar|cube)?\s*(?:goes|is\s+placed|is\s+put|comes|should\s+go)?"
    rf"(?:\s+down)?\s*first\s*\?[ \t]+(?P<first>{_BLOCK})"
    rf"(?:\s*,?\s*(?:and\s+)?then\s+(?P<then>{_BLOCK}))?{_END}"
)
_WHAT_ORDER = re.compile(
    rf"(?im){_START}(?:in\s+)?(?:what|which)\s+order\s*\?[ \t]+(?P<first>{_BLOCK})\s*,?\s*"
    rf"(?:(?:and\s+)?then|before)\s+(?P<then>{_BLOCK}){_END}"
)


def _where(match: re.Match[str]) -> str:
    answer = match["answer"].strip()
    to = "" if re.match(_PLACE_START, answer, flags=re.IGNORECASE) else "to "
    return f"{match['start']}{match['objects']} go {to}{answer}"


def _which_first(match: re.Match[str]) -> str:
    then = f", then {match['then']}" if match["then"] else ""
    return f"{match['start']}{match['first']} first{then}"


def answered(instruction: str) -> str:
    """The instruction with each question that its next sentence answers said as a statement.

    >>> answered("Where do the three objects go? G, H and I. Which block first? Red, then blue.")
    'the three objects go to G, H and I. Red first, then blue.'
    """
    instruction = _WHERE.sub(_where, instruction)
    instruction = _WHICH_FIRST.sub(_which_first, instruction)
    return _WHAT_ORDER.sub(lambda m: f"{m['start']}{m['first']} before {m['then']}", instruction)


_ANY_TIME = r"(?:at\s+any\s+(?:time|point|moment)|any\s*time|whenever(?:\s+you\s+(?:like|want))?)"
_MOVED = (
    r"(?:go(?:es)?|be\s+(?:moved|placed|put|done|taken|transferred)|is\s+(?:moved|placed|put|done|taken))"
)
_TIMING = (
    re.compile(
        rf"(?i)^\s*(?:and\s+|also\s+)?(?P<blocks>{_BLOCKS})\s+(?:can|may|could)\s+{_MOVED}\s+{_ANY_TIME}\s*$"
    ),
    re.compile(
        rf"(?i)^\s*it\s+(?:does\s+not|doesn[’']?t|does\s*nt)\s+matter\s+when\s+(?P<blocks>{_BLOCKS})\s+{_MOVED}\s*$"
    ),
)
# where the last clause of a sentence starts: a comma or semicolon, or "and" / "then" before a verb
_CLAUSE_BREAK = re.compile(rf"(?i)[,;]|\b(?:and|then)\s+(?=(?:then\s+)?{VERB}\b)")
_ORDER_WORD = re.compile(r"(?i)\b(?:first|before|after|then|last|later|next|second|time|whenever)\b")


def _colours(text: str) -> set[str]:
    return set(re.findall(_COLOUR, text.lower()))


def timing_joined(sentences: list[str]) -> list[str]:
    """The sentences with a goal's timing said apart ("Yellow can go at any time.") joined to the goal
    before it, as "at any time" (see the module docstring).

    >>> timing_joined(["Move the yellow block to G", "Yellow can go at any time"])
    ['Move the yellow block to G at any time']
    """
    out: list[str] = []
    for sentence in sentences:
        said = next((m for p in _TIMING if (m := p.match(sentence))), None)
        if said and out:
            last = _CLAUSE_BREAK.split(out[-1])[-1]
            if _colours(last) == _colours(said["blocks"]) and not _ORDER_WORD.search(last):
                out[-1] = f"{out[-1].rstrip()} at any time"
                continue
        out.append(sentence)
    return out
