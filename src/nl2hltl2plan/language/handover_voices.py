"""A voice's words for a guard, a wait and an exchange, rewritten onto the forms the handover reader reads
(issue 24, h263; `handover_registers.REGISTERS` applies `VOICED` to the lower-cased sentence with its
punctuation spaced out). Each says the same constraint as the plain words, never less:

- places closed while the work goes on, with the prohibition said after them: "regions F, G and H are
  closed (to visitors) / off limits / out of bounds, so nothing gets placed there" is "regions F, G and H
  must stay empty" (the closure alone, without the prohibition, stays unread as before);
- a block closed to the arms until another is touched: "the blue block is / stays off limits (to every
  arm) until ..." is "the blue block must not be touched until ..." (a wait, `handover_rules`);
- the targets named as a noun after "other than" / "outside": "any region other than those targets" is
  "... those regions";
- the work before said done in the voice's word: "once all of that's charted", "once that's all laid" is
  "once all that is done" (a touch word stays: "once that is touched" is a wait);
- an exchange said of where the blocks rest: "swap where X and Y are sitting" is "swap where X and Y
  are"; "X and Y trade the spots they're sitting on" is "X and Y trade spots";
- "set out / laid out on P": placed on P.
"""

from __future__ import annotations

import re

_BLOCK = r"(?:the\s+)?(?:red|blue|yellow)(?:\s+(?:block|one|cube|pillar|object))?"
_CLOSED = r"(?:closed(?:\s+off)?|off\s+limits|out\s+of\s+bounds|shut|barred)"
_WHOM = r"(?:\s+to\s+(?:(?:all|any|every|the)\s+)?[a-z]+)?"  # "to visitors", "to every arm"
_REST = r"(?:sitting|lying|resting|standing|located|sat|placed|kept)"
_PLACED = r"(?:placed|put|set(?:\s+down)?|dropped|left|laid(?:\s+down)?|lands?|goes|ends\s+up)"

_RULES: tuple[tuple[str, str], ...] = (
    # places closed, and the prohibition that says what "closed" means here
    (
        rf"\b(?:are|is|stay|stays|remain|remains|must\s+(?:stay|remain|be)|will\s+(?:stay|be))\s+{_CLOSED}{_WHOM}"
        rf"\s*(?:,\s*)?(?:so|:|;)\s*(?:that\s+)?nothing\s+(?:(?:gets|is|may\s+be|can\s+be|should\s+be|will\s+be)\s+)?"
        rf"{_PLACED}\s+(?:there|on\s+them|in\s+them)\b",
        "must stay empty",
    ),
    # a block closed to the arms until another is touched: a wait
    (
        rf"\b({_BLOCK})\s+(?:is|stays|remains|must\s+(?:stay|remain|be))\s+{_CLOSED}{_WHOM}\s+(?=(?:until|till)\b)",
        r"\1 must not be touched ",
    ),
    # the targets as a noun after "other than" / "outside" / "except": the regions named
    (
        r"\b((?:other\s+than|outside(?:\s+of)?|except|besides|but))\s+(?:those|these|the)(?:\s+three)?\s+"
        r"(?:targets|destinations)\b",
        r"\1 those regions",
    ),
    # the work before said done in the voice's word: "once all of that's charted", "once that's all laid"
    (
        # ("once everything is done" is read as written: no "all" to add)
        r"\b(once|when|after)\s+(?:all\s+(?:of\s+)?)?(?!everything\s+(?:s|is|has\s+been)\s+done\b)"
        r"(that|this|everything)\s+(?:s|is|has\s+been)\s+(?:all\s+)?"
        r"(?!touched\b|handled\b|grabbed\b|grasped\b|picked\b|lifted\b)(?:[a-z]{3,}ed|laid|drawn|sewn|done)\b",
        r"\1 all \2 is done",
    ),
    # an exchange said of where the blocks rest
    (rf"\b(where\s+{_BLOCK}\s+and\s+{_BLOCK}\s+(?:are|were))\s+{_REST}\b(?:\s+(?:now|at\s+present))?", r"\1"),
    (
        r"\b(trade|swap|switch|exchange)\s+(?:the\s+)?(spots|places|positions|locations)\s+(?:that\s+)?they\s*"
        rf"(?:'\s*re|re|\s+are)\s+(?:{_REST}\s+)?(?:on|in|at)\b",
        r"\1 \2",
    ),
    # "set out / laid out on P": placed on P
    (r"\b(set|laid)\s+out(?=\s+(?:(?:separately|individually|singly)\s+)?(?:on|onto|in|into)\b)", r"\1"),
)

VOICED = tuple((re.compile(pattern), replacement) for pattern, replacement in _RULES)
