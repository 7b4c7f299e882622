"""First-person narration around a handover instruction's commands, read as the team's commands
(`handover_discourse.plain` asks it for each sentence, after reported speech): "I'll / I will / I'm / I won't
/ I've ..." is read as "we ...", which the reader reads as the team's commands ("we will move ..." -> "move
..."); "I" after a list of region letters or after "region" is the region, never the pronoun. The team named
as the subject of what it is about to do is "we" too ("Today our arms are going to move ...", "the robots will
put ...", "they won't touch the blue block": "they" only before a placing or touching verb and its object),
"let me (not) move" is "we will (not) move", and a passive's future "is going to be placed" is "will be
placed".
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.handover_words import SWAP, TOUCH, VERB

# "I" as the pronoun: before a verb of will or being; never after "region" or a list of region letters
_I = re.compile(
    r"(?<![A-Za-z])I(?=\s*['’](?:ll|m|ve|d)\b|\s+(?:will|won't|won’t|shall|am|have|would|must|should|need|can|cannot|want)\b)"
)
_REGION_BEFORE = re.compile(r"(?i)(?:\bregions?|\b[A-J]\s*(?:,|\band|\bor)|\b(?:on|to|onto|into|at|in))\s*$")


# the team named as the subject of what it is about to do: "our arms are going to move ...", "the robots will
# put ...", "they won't touch ..." (where a clause starts; "they" only before a verb with its object: blocks
# "will move to G", arms "will move the red block")
_FUTURE = r"(?:\s*['’]re|\s+are)(?:\s+not)?\s+going\s+to\b|\s+(?:will|shall|won['’]t)\b|\s*['’]ll\b"
_CLAUSE_START = (
    r"(?:^|(?<=[,;:])|(?<=\band)|(?<=\bthen)|(?<=\bthereafter)|(?<=\btoday)|(?<=\bnow)|(?<=\bnext)|(?<=\btime)|"
    # after a hedge of time: "at some point they will ..."
    r"(?<=\bpoint)|(?<=\beventually)|(?<=\blater)|(?<=\blater on))"
)
_TEAM_AS_WE = re.compile(
    rf"(?i){_CLAUSE_START}\s*(?:(?:our|the|these|both|all\s+(?:the\s+)?)\s+)?(?:robot\s+)?(?:arms|robots)(?={_FUTURE})"
)
_THEY_AS_WE = re.compile(
    rf"(?i){_CLAUSE_START}\s*they(?=(?:{_FUTURE})(?:\s+not)?(?:\s+(?:also|then|eventually))?(?:\s+(?:need|have)\s+to)?\s+"
    rf"(?:{VERB}|{SWAP}|{TOUCH})\s+"
    r"(?:the|all|both|each|every|any|anything|red|blue|yellow|three|two|it|them|one|no|nothing)\b)"
)
# "let me (not) move ...": the speaker's plan, as "I'll (not) move ..."
_LET_ME = re.compile(rf"(?i)\blet\s+(?:me|us)\s+(not\s+)?(?=(?:first\s+)?(?:{VERB}|{SWAP}|{TOUCH})\b)")
# the future of a passive ("the red block is going to be placed", "nothing is going to be put") and its
# perfect ("will (not) have been touched": the state the plan reaches) are "will (not) be"
_GOING_TO_BE = re.compile(
    r"(?i)\b(?:is|are|['’]s|['’]re)\s+going\s+to\s+be\b|\bwill(\s+not)?\s+have\s+been\b"
)


def _future(match: re.Match[str]) -> str:
    return f"will{match[1] or ''} be" if match[0].lower().startswith("will") else " will be"


@lru_cache(maxsize=16384)  # pure; a sentence is read again for each restated reading
def first_person_as_team(sentence: str) -> str:
    """'I' as the speaker who will do the work is the team ('we'), which the reader reads as commands; so
    are the arms or robots named as the subject of what they are about to do.

    >>> first_person_as_team("I'm moving red to regions H and I. I'll wait.")
    "we are moving red to regions H and I. we'll wait."
    >>> first_person_as_team("Today our arms are going to move the blocks, and they won't touch red")
    "Today we will move the blocks, and we won't touch red"
    """
    sentence = _GOING_TO_BE.sub(_future, sentence)
    # "after (all of) that they'll put ...": the step's phrase set off, as before any command
    sentence = re.sub(
        r"(?i)\b(after\s+(?:all\s+(?:of\s+)?)?(?:that|these|this))\s+(?=(?:they|(?:the\s+)?(?:arms|robots))\b)",
        r"\1, ",
        sentence,
    )
    sentence = _LET_ME.sub(lambda m: "we will not " if m[1] else "we will ", sentence)
    sentence = _THEY_AS_WE.sub(" we", _TEAM_AS_WE.sub(" we", sentence))
    out, last = [], 0
    for match in _I.finditer(sentence):
        if _REGION_BEFORE.search(sentence[: match.start()]):
            continue
        out += [sentence[last : match.start()], "we"]
        last = match.end()
    text = "".join(out) + sentence[last:]
    # "after all of that we'll put ...": the step's phrase set off, as before any command
    text = re.sub(r"(?i)\b(after\s+all\s+(?:of\s+)?(?:that|these|this))\s+(?=we\b)", r"\1, ", text)
    text = re.sub(r"(?i)\bwe\s*['’]m\b", "we are", re.sub(r"(?i)\bwe\s+am\b", "we are", text))
    # "we are going to move": we will move (a plan said as what is about to happen)
    text = re.sub(r"(?i)\bwe\s*(?:['’]re|\s+are)\s+going\s+to\s+", "we will ", text)
    return " ".join(text.split())
