"""Courtesy frames that carry nothing ("if you don't mind", "if it isn't too much trouble", "when you have a
moment", "while you're at it"; the list is `courtesy.txt`): removed before the parser backends read, so
that a politeness frame is never read as a condition, a negation or an order.

>>> without_courtesy("If you don't mind, put the apple in the fridge.")
'put the apple in the fridge.'
>>> without_courtesy("put the mug and, while you're at it, the cup in the sink")
'put the mug and the cup in the sink'
>>> without_courtesy("if you don't mind the mess, put the apple in the fridge")
"if you don't mind the mess, put the apple in the fridge"
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import phrase_list_pattern

# a frame with the comma after it, where its clause ends (a comma, a sentence's end or the text's end)
_FRAMES = f"(?:{phrase_list_pattern('courtesy.txt', 'clause')}|{phrase_list_pattern('courtesy.txt', 'time')})"
_FRAME = re.compile(rf"(?:,\s*)?\b{_FRAMES}\b(?=\s*(?:[,.;:!?]|$))\s*,?", re.I)


def without_courtesy(text: str) -> str:
    """`text` without its courtesy frames (and the commas around them); the text as it was when nothing
    else is left."""
    out = _FRAME.sub(" ", text)
    out = re.sub(r"\s+([,.;:!?])", r"\1", " ".join(out.split()))
    out = re.sub(r"^[\s,.;:!?]+", "", out)
    return out if re.search(r"\w", out) else text
