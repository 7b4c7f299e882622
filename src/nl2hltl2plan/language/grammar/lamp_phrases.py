"""How people say "look at X under the lamp", rewritten onto the phrasings the rules read.

ALFRED's look-at-in-light trials are told as "carry X to the lamp and switch it on"; an LLM that rewrites
them into one fluent instruction (the paper's test set, issue 28) adds the purpose of switching it on, or
says "check X out". Each rewrite below keeps the words' meaning and only changes their
form; `sentences.normalize` applies `lamp_phrasing`.
"""

from __future__ import annotations

import re

_EXAMINE = r"(?:look\s+at|see|examine|view|read|inspect|check(?:\s+out)?|study|observe)"

# "use the light from the lamp to look at the book": the lamp lights the examination
_USE_LAMP = re.compile(
    r"\b(?:use|using) (?:the |a )?(?:light (?:from|of) (?:the |a )?)?(?P<lamp>(?:\w+ )?lamp|light)"
    r"(?: light)? to (?P<verb>look at|see|examine|view|read|inspect|check) "
    r"(?P<obj>[^,.;!?]+?)(?=[,.;!?]|\s+(?:and|then)\b|$)",
    re.IGNORECASE,
)
# "examine the box using the light from a floor lamp": the light of that lamp
_LIGHT_FROM = re.compile(r"\blight from (?=(?:the |a |an )?(?:[a-z]+ )?(?:lamp|light)\b)", re.IGNORECASE)
# "check the phone out under the lamp", "check out the vase": the particle of "check out" ("look at")
_CHECK_OUT = re.compile(r"\bcheck\s+(it|them|(?:the|a|an|that|this)\s+[a-z]+(?:\s+[a-z]+)?)\s+out\b", re.I)
_CHECK_OUT_FRONT = re.compile(r"\bcheck\s+out\s+(?=(?:the|a|an|that|this)\s)", re.I)
# "bring the box to the floor lamp and turn it on to look at the box": the purpose names the examination
# the carrying to the lamp and the switching on already said (read again, it is a second examination)
_PURPOSE = re.compile(
    r"(?P<keep>\bto\s+the\s+(?:[a-z]+\s+)?lamp\b[^,.;!?]*?\s+and\s+(?:then\s+)?(?:turn|switch)\s+"
    r"(?:on\s+)?(?:it|the\s+(?:[a-z]+\s+)?lamp)(?:\s+on)?)"
    rf"\s+(?:in\s+order\s+)?to\s+{_EXAMINE}\s+(?P<what>it|them|the\s+[a-z]+)(?=\s*(?:[,.;!?]|$))",
    re.I,
)


def _purpose_said(m: re.Match[str]) -> str:
    """The purpose dropped where it names the thing carried to the lamp (it, or a noun said before)."""
    what = m["what"].lower().split()
    if what[0] in ("it", "them") or what[-1] in m.string[: m.start()].lower().split():
        return m["keep"]
    return m[0]


def lamp_phrasing(text: str) -> str:
    """`text` with each phrasing above rewritten (its comment says which)."""
    text = _LIGHT_FROM.sub("light of ", text)
    text = _USE_LAMP.sub(lambda m: f"{m['verb']} {m['obj']} by the light of the {m['lamp']}", text)
    text = _CHECK_OUT_FRONT.sub("check ", _CHECK_OUT.sub(r"check \1", text))
    return _PURPOSE.sub(_purpose_said, text)
