"""A tabletop instruction written as a dialogue with speaker labels (issue 28): "Robot: What do you
need?\\nMe: The green apple on the pink plate, ...\\nRobot: In which order?\\nMe: Doesn't matter."; also a
test scenario's voice (`scenario_read`).

The text is read as a dialogue only where every sentence belongs to a turn ("Name: ..."), one speaker is
the robot (`_ROBOT`) and there is one other, and each of the robot's turns is a question. Then:

- the user's turns are what is asked, their labels dropped;
- a robot's question about the order ("In which order?", "Any particular order?"; also of a step's turn,
  "Where do I start?", "And then?") with an answer that leaves it free ("Doesn't matter.", "No.",
  "Whatever.") is "In any order."; with any other answer the dialogue is left as it is (refused: the
  answer is not read here);
- any other question of the robot's that names nothing is dropped where the user's answer names
  something of the world ("What do you need?"); where it does not ("Anything else?" / "No."), or where a
  question names something, the dialogue is left as it is.

>>> import re
>>> names = re.compile(r"\\b(?:green apple|pink plate)\\b", re.I)
>>> dialogue_read("Robot: What do you need? Me: The green apple on the pink plate. Robot: In which "
...               "order? Me: Doesn't matter.", names)
'The green apple on the pink plate. In any order.'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import free_order_phrase

_ROBOT = frozenset("robot bot assistant ai helper".split())
_TURN = re.compile(r"(?:^|(?<=[.!?])\s+)(?P<who>[A-Za-z]+)\s*:\s*")
# a question about the order or the turn of a step ("In which order?", "Where do I start?", "And then?")
_ORDER_QUESTION = re.compile(
    r"\b(?:order|ordering|sequence|first|start|begin|then|next|after|afterwards|before|last|finish|turn)\b",
    re.IGNORECASE,
)
# ... and an answer that leaves it free: a short one, or any phrase of the shared list (free_order.txt)
_FREE_ANSWER = re.compile(
    r"(?:no|nope|not really|none|any|anything|whatever|either|no preference|"
    r"(?:it\s+)?(?:doesn't|does\s+not|doesnt)\s+matter|up\s+to\s+you|your\s+call|(?:i\s+)?don't\s+mind|"
    rf"{free_order_phrase('whole')})[\s,]*(?:thanks|thank you)?\s*[.!]*",
    re.IGNORECASE,
)


def dialogue_read(text: str, names: re.Pattern[str]) -> str:
    """`text` as what its user asks where it is a dialogue with the robot (see the module docstring);
    `names`: the world's names. The text as it is otherwise."""
    turns = list(_TURN.finditer(text))
    if len(turns) < 2 or turns[0].start() != 0:
        return text
    said = [(m["who"].lower(), text[m.end() : nxt.start() if nxt else None].strip())
            for m, nxt in zip(turns, [*turns[1:], None], strict=True)]
    speakers = {who for who, _ in said}
    if len(speakers) != 2 or len(speakers & _ROBOT) != 1:
        return text
    out: list[str] = []
    i = 0
    while i < len(said):
        who, words = said[i]
        if who not in _ROBOT:
            out.append(words)
            i += 1
            continue
        answer = said[i + 1][1] if i + 1 < len(said) else ""
        if not words.endswith("?") or names.search(words):
            return text
        if _ORDER_QUESTION.search(words):
            if not _FREE_ANSWER.fullmatch(answer):
                return text
            out.append("In any order.")
            i += 2
            continue
        if not names.search(answer):
            return text
        i += 1  # a question that only asks what is wanted
    return " ".join(out)


# a test scenario's voice (Gherkin): "[Scenario: TITLE.] [Given CONTEXT,] When TRIGGER, then X is on P [and
# Y is on Q]": the outcome is what is asked, where the title, the context and the trigger name nothing
_SCENARIO = re.compile(
    r"^\s*(?:(?:scenario|feature)\s*:\s*(?P<title>[^.!?]*?)[.!?]?\s+)?(?:given\s+(?P<given>[^,.;!?]*?)[,.;]?\s+)?"
    r"when\s+(?P<when>[^,.;!?]*?)[,.;]?\s+then\s+(?P<rest>.*)$",
    re.IGNORECASE | re.DOTALL,
)
_STATE_VERB = r"(?:is|are|should\s+be|must\s+be|will\s+be|ends\s+up|end\s+up)"


def scenario_read(text: str, names: re.Pattern[str]) -> str:
    """A test scenario ("Given the robot is at its start, when I say go, then the green apple is on the
    blue plate and the orange is on the yellow plate") as "Make sure" and its outcome; the text as it is
    where its title, context or trigger names something of the world, or where its outcome does not open
    with a named thing's state.

    >>> import re
    >>> names = re.compile(r"\\b(?:green apple|pink plate|orange|yellow plate)\\b", re.I)
    >>> scenario_read("Given two plates When I say go Then the green apple is on the pink plate. And the "
    ...               "orange is on the yellow plate.", names)
    'Make sure the green apple is on the pink plate, and the orange is on the yellow plate.'
    """
    m = _SCENARIO.match(text)
    if m is None or any(names.search(m[part] or "") for part in ("title", "given", "when")):
        return text
    if not re.match(rf"(?:the\s+)?(?:{names.pattern})\s+{_STATE_VERB}\b", m["rest"], re.IGNORECASE):
        return text
    rest = re.sub(r"[.;]\s+and\s+(?=(?:the\s+)?(?:" + names.pattern + "))", ", and ", m["rest"], flags=re.I)
    return f"Make sure {rest}"
