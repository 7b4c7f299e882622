"""How people say "look at X under the lamp", rewritten onto the phrasings the rules read.

ALFRED's look-at-in-light trials are told as "carry X to the lamp and switch it on"; an LLM that rewrites
them into one fluent instruction (the paper's test set, issue 28) adds the purpose of switching it on, or
says "check X out". Each rewrite below keeps the words' meaning and only changes their
form; `sentences.normalize` applies `lamp_phrasing`.
"""

from __future__ import annotations

import re

_EXAMINE = r"(?:look\s+at|see|examine|view|read|inspect|check(?:\s+out)?|study|observe)"
# the looking verbs people use beside those: "have a look at X", "take a close look at X" ("look at X": the
# rules give a verb of one word to the things listed after it, "... and then the pen")
_A_LOOK_AT = re.compile(
    r"\b(?:have|take|get)\s+a\s+(?:(?:good|close|closer|quick|proper)\s+)?look\s+at\b", re.I
)
_LOOKING = rf"(?:{_EXAMINE}|{_A_LOOK_AT.pattern})"
# "look over the CD and the pen": "look at" (left, "over the CD" was a place, and the CD lost)
_LOOK_OVER = re.compile(r"\b(look)\s+over\s+(?=(?:the|a|an|this|that|these|those|it|them|my|your)\b)", re.I)

# "use the light from the lamp to look at the book": the lamp lights the examination
_USE_LAMP = re.compile(
    r"\b(?:use|using) (?:the |a )?(?:light (?:from|of) (?:the |a )?)?(?P<lamp>(?:\w+ )?lamp|light)"
    r"(?: light)? to (?P<verb>look at|see|examine|view|read|inspect|check) "
    # the things: one, or a list ("a book, a pen and the vase"), up to a clause of its own
    r"(?P<obj>[^.;!?]+?)(?=[.;!?]|,\s+(?!(?:and\s+)?(?:the|a|an)\s)|,?\s+and\s+(?!(?:the|a|an)\s)|\s+then\b|$)",
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


# "hold the vase and turn on the lamp to get a good look at it", "... to see it better": after the lamp is
# switched on, a purpose that names "it" (the thing held) says the examination the rules already read; the
# rules read "to look at it" alone (kept), not the noun "a look" or a manner word after "it"
_MANNER = r"(?:better|properly|closely|clearly|well|more\s+closely)"
_LOOK_PURPOSE = re.compile(
    r"(?P<keep>\b(?:turn|switch)\s+(?:on\s+)?(?:it|the\s+(?:[a-z]+\s+)?(?:lamp|light))(?:\s+on)?)"
    r"\s+(?:in\s+order\s+)?to\s+(?:(?:get|take|have)\s+a\s+(?:(?:good|better|close|closer|proper|clear|quick)\s+)?"
    rf"(?:look|view)\s+(?:at|of)\s+(?:it|them)(?:\s+{_MANNER})?|{_EXAMINE}\s+(?:it|them)\s+{_MANNER})"
    r"(?=\s*(?:[,.;!?]|$))",
    re.I,
)


# "examine the mug by the light of the lamp, then put a pen in the mug" (or "in it"): the next clause puts a
# thing in the thing examined; the rules would take it for the examination going on (the pen examined, the
# mug placed), so the clause is read as a sentence of its own ("... lamp. Then put a pen in the mug"), unless
# an order said later in the sentence ("in this order") covers both
_AGAIN_AFTER_LAMP = re.compile(
    rf"(?P<lamp>\b{_EXAMINE}\s+(?:the|a|an)\s+(?:[a-z]+\s+)?(?P<noun>[a-z]+)\s+(?:by|under|in|with)\s+"
    r"[^,.;!?]*?\b(?:lamp|light)),\s+then\s+"
    r"(?=[^,.;!?]*\b(?:in|into|inside)\s+(?:(?:the|a|an)\s+(?:[a-z]+\s+)?(?P=noun)|it)\b)"
    r"(?![^.;!?]*\bin\s+(?:this|that)\s+)",
    re.I,
)

# "look at the box under the lamp and at the pencil by the lamp as well", "..., then at the pencil": "and
# at" / "then at" goes on with "look at"
_AND_AT = re.compile(
    r"(?P<head>\blook\s+at\s+[^,.;!?]*?\b(?:lamp|light))(?P<sep>,?\s+(?:and\s+(?:then\s+)?|then\s+))at\s+"
    r"(?=(?:the|a|an)\s)(?!(?:the|a|an)\s+(?:same|end|start|beginning|moment|time)\b)",
    re.I,
)

# "Using the desk lamp, look at A, B and C": the lamp named before a list of things to look at lights each
# of them (read as a thing to look at itself, it was a task too many); the lamp goes after the list, where the
# rules give it to every item ("look at A, B and C under the desk lamp"), before a closing order phrase.
# "By the floor lamp, have a look at A": a lamp beside which one looks is the light one looks by
_LAMP_FIRST = re.compile(
    r"(?:(?<=^)|(?<=[.;!?]\s)|(?<=,\s)|(?<=\bthen\s))"
    r"(?:using|with|by\s+the\s+light\s+of|in\s+the\s+light\s+of|under|by|beside|next\s+to|near)\s+"
    r"(?:the\s+|a\s+)?"
    r"(?P<lamp>(?:[a-z]+\s+)?lamp(?:\s+on\s+the\s+(?!same\b)[a-z]+)?)"
    r"(?:\s+(?:switched|turned)\s+on|\s+on|\s+lit)?\s*,\s*"
    rf"(?P<verb>{_LOOKING})\s+(?P<things>(?:the|a|an)\s[^.;!?]+?)"
    r"(?P<tail>\s*,?\s*(?:in\s+(?:any|whatever|either|that|this)\s+order|one\s+(?:after\s+(?:the\s+other|another)|by\s+one)))?"
    r"(?=\s*(?:[.;!?]|$)|,?\s+(?:and\s+)?then\b|,\s+and\s+(?!(?:the|a|an)\s))",
    re.IGNORECASE,
)

# "carry a pen while you turn on the lamp", "turn on the lamp while you hold the pen": the gerund the rules
# read ("while turning on the lamp", "while holding the pen")
_WHILE_YOU = re.compile(r"\bwhile\s+you(?:'re|\s+are)?\s+(turn|switch|hold|carry)(?:ing)?\b", re.I)
_GERUND = {"turn": "turning", "switch": "switching", "hold": "holding", "carry": "carrying"}


# "carry the laptop to the lamp and turn it on", "bring the watch over to the floor lamp and switch it on":
# ALFRED's look-at-in-light told as its steps, written as the examination it is ("look at the laptop under the
# lamp"), so that "do the same with X" after it repeats an examination, not a carrying (h190; a later clause
# read "the lamp" as the laptop's destination, and "do the same with the statue" found no task to repeat)
_CARRY_TO_LAMP = re.compile(
    r"\b(?:carry|take|bring)\s+(?P<np>(?:the|a|an|another|one)\s+(?:[a-z]+\s+){0,2}?[a-z]+|it)\s+"
    r"(?:over\s+|across\s+)?to\s+(?P<lamp>(?:the|a)\s+(?:[a-z]+\s+)?lamp)\s+and\s+(?:then\s+)?(?:turn|switch)\s+"
    r"(?:(?:it|the\s+(?:[a-z]+\s+)?lamp|that\s+lamp)\s+on|on\s+(?:it|the\s+(?:[a-z]+\s+)?lamp|that\s+lamp))\b"
    r"(?!\s+(?:in\s+order\s+)?to\s)",
    re.I,
)


def _purpose_said(m: re.Match[str]) -> str:
    """The purpose dropped where it names the thing carried to the lamp (it, or a noun said before)."""
    what = m["what"].lower().split()
    if what[0] in ("it", "them") or what[-1] in m.string[: m.start()].lower().split():
        return m["keep"]
    return m[0]


def _lamp_used(m: re.Match[str]) -> str:
    """ "use the lamp to look at X" -> "look at X by the light of the lamp"; a list goes "under the lamp",
    the words the rules give every item of a list."""
    listed = re.search(r",|\sand\s", m["obj"]) is not None
    return f"{m['verb']} {m['obj']} {'under' if listed else 'by the light of'} the {m['lamp']}"


def carried_to_lamp(text: str) -> str:
    """ "carry X to the lamp and turn it on" -> "look at X under the lamp" (`_CARRY_TO_LAMP`); `everyday`
    applies it before a repeat ("do the same with the statue") is written out, and `lamp_phrasing` again."""
    return _CARRY_TO_LAMP.sub(lambda m: f"{'lL'[m[0][0].isupper()]}ook at {m['np']} under {m['lamp']}", text)


def lamp_phrasing(text: str) -> str:
    """`text` with each phrasing above rewritten (its comment says which)."""
    text = _LOOK_OVER.sub(r"\1 at ", _LIGHT_FROM.sub("light of ", carried_to_lamp(text)))
    text = _LAMP_FIRST.sub(lambda m: f"{_A_LOOK_AT.sub('look at', m['verb'])} {m['things']} under the "
                           f"{m['lamp']}{m['tail'] or ''}", text)
    text = _USE_LAMP.sub(_lamp_used, text)
    text = _CHECK_OUT_FRONT.sub("check ", _CHECK_OUT.sub(r"check \1", text))
    text = _AGAIN_AFTER_LAMP.sub(lambda m: m["lamp"] + ". Then ", text)
    text = _AND_AT.sub(lambda m: m["head"] + m["sep"] + "look at ", text)
    text = _WHILE_YOU.sub(lambda m: "while " + _GERUND[m[1].lower()], text)
    text = _LOOK_PURPOSE.sub(r"\g<keep>", _PURPOSE.sub(_purpose_said, text))
    # after the purposes above, which drop "to get a good look at it" whole
    return _A_LOOK_AT.sub(lambda m: "Look at" if m[0][0].isupper() else "look at", text)
