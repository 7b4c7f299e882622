"""How people say "look at X under the lamp", rewritten onto the phrasings the rules read.

ALFRED's look-at-in-light trials are told as "carry X to the lamp and switch it on"; an LLM that rewrites
them into one fluent instruction (the paper's test set, issue 28) adds the purpose of switching it on, or
says "check X out". Each rewrite below keeps the words' meaning and only changes their
form; `sentences.normalize` applies `lamp_phrasing`.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import DETERMINERS
from nl2hltl2plan.language.courtesy import IN_THIS_ORDER
from nl2hltl2plan.language.grammar.clauses import Clause
from nl2hltl2plan.language.grammar.draft_tasks import Draft
from nl2hltl2plan.language.grammar.frames import Frame, dest_of
from nl2hltl2plan.language.grammar.word_tables import VERBS
from nl2hltl2plan.language.grounding import find_mentions, tokens

_EXAMINE = r"(?:look\s+at|see|examine|view|read|inspect|check(?:\s+out)?|study|observe)"
# the looking verbs people use beside those: "have a look at X", "take a close look at X" ("look at X": the
# rules give a verb of one word to the things listed after it, "... and then the pen")
_A_LOOK_AT = re.compile(
    r"\b(?:have|take|get)\s+a\s+(?:(?:good|close|closer|quick|proper)\s+)?look\s+at\b", re.I
)
_LOOKING = rf"(?:{_EXAMINE}|{_A_LOOK_AT.pattern})"
# "give the watch a look", "give it a quick look": "look at the watch"
_GIVE_A_LOOK = re.compile(
    r"\bgive\s+(?P<np>it|them|(?:the|a|an|that|this)\s+[a-z]+(?:\s+[a-z]+){0,2}?)\s+a\s+"
    r"(?:(?:good|close|closer|quick|proper)\s+)?look\b",
    re.I,
)
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
    r"(?:(?:\s+(?:switched|turned)\s+on|\s+on|\s+lit)\s*,?\s*|\s*,\s*)"  # "with the lamp on look at"
    rf"(?P<verb>{_LOOKING}|look)\s+(?P<things>(?:the|a|an|my|your|our|this|that)\s[^.;!?]+?)"
    r"(?P<tail>\s*,?\s*(?:(?:in\s+)?(?:any|whatever|either|that|this)\s+order|one\s+(?:after\s+(?:the\s+other|another)|by\s+one)))?"
    r"(?=\s*(?:[.;!?]|$)|,?\s+(?:and\s+)?then\b|,\s+and\s+(?!(?:the|a|an)\s))",
    re.IGNORECASE,
)

# "lamp on, look at the cd", "lamp on and check out a pen" (h300's notes): the switching on, verb left out
_LAMP_ON = re.compile(
    r"(?:(?<=^)|(?<=[.;!?,]\s)|(?<=\bthen\s))(?:(?:the|my|a)\s+)?(?P<lamp>(?:[a-z]+\s+)?(?:lamp|light))\s+on"
    rf"(?:\s*,\s*|\s+)(?:and\s+)?(?:then\s+)?(?={_LOOKING}\b)",
    re.I,
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


# "Switch on the floor lamp and ...": "switch" opening a sentence was read as a light switch put on the lamp;
# before a lamp it is the verb, as "turn" is
_SWITCH_ON = re.compile(r"\b(switch)\s+(on|off)\s+(?=(?:the|a)\s+(?:[a-z]+\s+){0,2}?(?:lamp|light)\b)", re.I)


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


def _lamp_first(m: re.Match[str]) -> str:
    """ "with the floor lamp on, look at X" -> "look at X under the floor lamp" (`_LAMP_FIRST`); a bare
    "look the X" (h300's line 55) is "look at"."""
    verb = "look at" if m["verb"].lower() == "look" else _A_LOOK_AT.sub("look at", m["verb"])
    return f"{verb} {m['things']} under the {m['lamp']}{m['tail'] or ''}"


def carried_to_lamp(text: str) -> str:
    """ "carry X to the lamp and turn it on" -> "look at X under the lamp" (`_CARRY_TO_LAMP`); `everyday`
    applies it before a repeat ("do the same with the statue") is written out, and `lamp_phrasing` again."""
    return _CARRY_TO_LAMP.sub(lambda m: f"{'lL'[m[0][0].isupper()]}ook at {m['np']} under {m['lamp']}", text)


def lamp_phrasing(text: str) -> str:
    """`text` with each phrasing above rewritten (its comment says which)."""
    text = _LOOK_OVER.sub(r"\1 at ", _LIGHT_FROM.sub("light of ", carried_to_lamp(text)))
    text = _SWITCH_ON.sub(lambda m: f"{'tT'[m[1][0].isupper()]}urn {m[2]} ", text)
    text = _GIVE_A_LOOK.sub(lambda m: f"{'lL'[m[0][0].isupper()]}ook at {m['np']}", text)
    text = _LAMP_ON.sub(lambda m: f"{'tT'[m[0][0].isupper()]}urn on the {m['lamp']} and ", text)
    text = _LAMP_FIRST.sub(_lamp_first, text)
    text = _USE_LAMP.sub(_lamp_used, text)
    text = _CHECK_OUT_FRONT.sub("check ", _CHECK_OUT.sub(r"check \1", text))
    text = _AGAIN_AFTER_LAMP.sub(lambda m: m["lamp"] + ". Then ", text)
    text = _AND_AT.sub(lambda m: m["head"] + m["sep"] + "look at ", text)
    text = _WHILE_YOU.sub(lambda m: "while " + _GERUND[m[1].lower()], text)
    text = _LOOK_PURPOSE.sub(r"\g<keep>", _PURPOSE.sub(_purpose_said, text))
    # after the purposes above, which drop "to get a good look at it" whole
    return _A_LOOK_AT.sub(lambda m: "Look at" if m[0][0].isupper() else "look at", text)


# After an examination under a lamp, the things listed on are each looked at under that lamp, and a place
# said with one ("from the bed", "on the TV stand", "closest to the vase") is where it is, not where it goes
# (h203: paper_h189 read "Do the same with the newspaper on the TV stand" as a newspaper and a TV stand of
# places, and "..., and finally the phone on the TV stand" gave the TV stand to every examination):
# "..., then the remote closest to the vase, and finally the phone on the TV stand", "After that, the pillow
# from the bed", "do the same with A on L and B", "check three things under the lamp: A on L, B and C".
# Each is written "look at X under <the lamp>", which the rules read with its place as a landmark.
_LAMP = re.compile(
    r"\b(?:the|a)\s+(?:(?!(?:the|a|an|under|by|of|with|on|in|and)\b)[a-z]+\s+){0,2}?lamp\b", re.I
)
_ITEM = r"(?:the|a|an|another|my|your)\s+[a-z][^,.;!?:]*?"
_ITEM_END = r"(?=\s*(?:[,.;!?]|$)|,?\s+and\s+(?:then\s+|finally\s+|lastly\s+)?(?:the|a|an|another|my|your)\s)"
_NEXT_ITEM = re.compile(
    r"(?P<lead>(?:,\s*|;\s*|[.!?]\s+|\s+(?=and\s))(?:and\s+)?"
    r"(?:then|after\s+that|afterwards|next|lastly|finally|last\s+of\s+all)\s*,?\s+)"
    rf"(?P<np>{_ITEM}){_ITEM_END}",
    re.I,
)
_SAME_THEN_WITH = re.compile(
    r"\s*,?\s*(?:and\s+)?then\s+(?:with|for)\s+(?=(?:the|a|an|another|my|your)\s)", re.I
)
_SAME_WITH = re.compile(
    r"\b(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with)\s+"
    r"(?P<items>(?:the|a|an|another|my|your)\s[^.;!?]*?)(?=\s*(?:[.;!?]|$))",
    re.I,
)
# "check three things under the lamp: A, B and C", "Under the lamp, with it on, look at four things: ..."
_THINGS_UNDER = re.compile(
    r"\b(?:(?:look\s+at|check|examine|inspect)\s+(?P<n>two|three|four|five)\s+(?:things|items|objects)\s+"
    r"under\s+(?P<lamp>(?:the|a)\s+(?:[a-z]+\s+)?lamp(?:\s+in\s+the\s+corner)?)(?:\s+too|\s+as\s+well)?"
    r"|under\s+(?P<lamp2>(?:the|a)\s+(?:[a-z]+\s+)?lamp)\s*,\s*"
    r"(?:with\s+(?:the\s+lamp|it)\s+(?:switched\s+|turned\s+)?on\s*,\s*)?"
    r"(?:look\s+at|check|examine|inspect)\s+(?P<n2>two|three|four|five)\s+(?:things|items|objects))"
    r"\s*:\s*(?P<items>[^.;!?]+)",
    re.I,
)
# the same heading in other words (h238): "Two things to look at under the desk lamp: A and B", "look at these
# under the lamp in this order: A, B, C", "use the desk lamp to look at the following: ...", "inspecting a few
# things under the desk lamp: A first, then B"; "in this order" before the colon orders the items
_LOOK_VERB = r"(?:look(?:ing)?\s+at|check(?:ing)?|examin(?:e|ing)|inspect(?:ing)?)"
_A_LAMP = r"(?:the|a)\s+(?:[a-z]+\s+)?lamp(?:\s+in\s+the\s+corner)?"
_SOME = r"(?:two|three|four|five|a\s+few|some|several)"
_HEADED_UNDER = re.compile(
    rf"\b(?:(?P<n>{_SOME})\s+(?:things|items|objects)\s+to\s+{_LOOK_VERB}\s+under\s+(?P<lamp>{_A_LAMP})"
    rf"|(?:use|using)\s+(?P<lamp2>{_A_LAMP})\s+to\s+{_LOOK_VERB}\s+(?:these|the\s+following)"
    rf"|{_LOOK_VERB}\s+(?:these|the\s+following|(?P<n2>{_SOME})\s+(?:things|items|objects))\s+under\s+"
    rf"(?P<lamp3>{_A_LAMP}))"
    rf"(?P<order>{IN_THIS_ORDER})?"
    r"\s*:\s*(?P<items>[^.;!?]+)",
    re.I,
)
_THEN_ITEM = re.compile(r"^(?:and\s+)?then\s+", re.I)
_FIRST_ITEM = re.compile(r"\s+first$", re.I)
# "look at A by L and B on M under the desk lamp, and C and D under the floor lamp": each item under its lamp
# (the rules took "B on M" for a placement)
_LIST_UNDER = re.compile(
    r"(?:\b(?P<verb>look\s+at|examine|inspect|check)\s+|(?<=lamp)(?P<join>,?\s+and\s+))"
    r"(?P<items>(?:the|a|an|another|my|your)\s[^.;!?:]*?)\s+"
    r"(?P<lamp>(?:under|by\s+the\s+light\s+of)\s+(?:the|a)\s+(?:(?!(?:the|a|an)\b)[a-z]+\s+){0,2}?lamp)\b",
    re.I,
)
_NUMBER = {"two": 2, "three": 3, "four": 4, "five": 5}
_ITEM_SPLIT = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+(?=(?:the|a|an|another|my|your)\s)", re.I)
_ANY_ORDER = re.compile(r"^(?:in\s+)?(?:any|whatever)\s+order$", re.I)
# words that say an item is not a thing looked at where it is: a destination, a reference, the lamp itself,
# an order ("the clock after that": the rules read its order only said after a verb); "the other remote" is
# left to the repeat's own check, which asks a task of its own for it
_NOT_LOOKED_AT = {"into", "onto", "inside", "lamp", "light", "it", "them", "too", "also", "well", "but"}
_NOT_LOOKED_AT |= {"other", "after", "before", "then", "afterwards", "first", "later", "once", "when"}
_NOT_LOOKED_AT |= {"until"}
_NEAR = {"closest", "nearest", "close", "next"}  # "closest to the vase": a landmark, not a destination
# a bare "in" place on an item after an order word is the verbless placing users write ("..., then the pen
# in the drawer", as "then the apple in the fridge"), not where a thing looked at is
_PUT_IN = re.compile(r"\b(?:in|inside)\s+(?:the|a|an|another|that|this|my|your|one)\s", re.I)
_OTHER_TASK = {"place", "pick", "clean", "heat", "cool", "slice", "fill", "trash", "other"}


def _looked_at(np: str) -> bool:
    """Is `np` one thing, and words that say where it is, and nothing else (no verb, no destination)?"""
    toks = tokens(np)
    named = [m for m in find_mentions(np) if not m.entry.generic]
    if not named or named[0].start > 3 or not toks or toks[0][0] not in DETERMINERS | {"another"}:
        return False
    inside = {i for m in named for i in range(m.start, m.end)}
    for i, (word, _, _) in enumerate(toks):
        if word in _NOT_LOOKED_AT or (word == "to" and (i == 0 or toks[i - 1][0] not in _NEAR)):
            return False
        if i not in inside and word in VERBS and (i == 0 or toks[i - 1][0] not in DETERMINERS):  # "the head"
            return False
    return True


def _lamp_before(text: str, at: int, sentences: int = 0) -> str | None:
    """The lamp of the examination that the words at `at` go on ("the desk lamp"): the last lamp said
    before them, at most `sentences` sentence ends before, in a stretch with an examination or the lamp
    switched on and no verb of another task."""
    lamps = list(_LAMP.finditer(text, 0, at))
    if not lamps or len(re.findall(r"[.;!?\n]", text[lamps[-1].end() : at])) > sentences:
        return None
    start = max(text.rfind(c, 0, lamps[-1].start()) for c in ".;!?\n") + 1
    toks = tokens(text[start:at])
    named = {i for m in find_mentions(text[start:at]) for i in range(m.start, m.end)}
    said = [VERBS[w][0] for i, (w, _, _) in enumerate(toks) if w in VERBS and i not in named]
    after = tokens(text[lamps[-1].end() : at])
    if any(w in VERBS and VERBS[w][0] in _OTHER_TASK and w not in ("hold", "holding") for w, _, _ in after):
        return None
    under = re.search(r"\b(?:under|beneath|light\s+of)\s*$", text[start : lamps[-1].start()], re.I)
    return lamps[-1][0].lower() if under or {"examine", "light"} & set(said) else None


def _under(np: str, lamp: str, first: bool) -> str:
    return f"{'Look' if first else 'look'} at {np} under {lamp}"


def _listed_under(items: str, lamp: str, capital: bool, count: int | None = None) -> str | None:
    """ "A on L, B and C" -> "look at A on L under the lamp, look at B under the lamp and look at C under
    the lamp" (", in any order" kept after them); None where an item is no thing looked at."""
    parts = [p.strip() for p in _ITEM_SPLIT.split(items.strip()) if p.strip()]
    tail = ", in any order" if parts and _ANY_ORDER.match(parts[-1]) else ""
    things = parts[:-1] if tail else parts
    if not things or not all(_looked_at(p) for p in things) or count not in (None, len(things)):
        return None
    said = [_under(p, lamp, capital and not k) for k, p in enumerate(things)]
    return (", ".join(said[:-1]) + " and " + said[-1] if len(said) > 1 else said[0]) + tail


def _things_under(m: re.Match[str]) -> str:
    lamp, n = m["lamp"] or m["lamp2"], (m["n"] or m["n2"]).lower()
    listed = _listed_under(m["items"], lamp.lower(), m[0][0].isupper(), _NUMBER[n])
    return listed or m[0]


def _headed_under(m: re.Match[str]) -> str:
    """ "Two things to look at under the desk lamp: A and B" -> "look at A under the desk lamp and look at B
    under the desk lamp"; the items one after another where the heading says "in this order", or an item
    says "then" ("A first, then B"); the text as it was where an item is no thing looked at."""
    lamp = (m["lamp"] or m["lamp2"] or m["lamp3"]).lower()
    n = (m["n"] or m["n2"] or "").lower()
    parts = [p.strip() for p in _ITEM_SPLIT.split(m["items"].strip()) if p.strip()]
    then = [bool(m["order"]) or bool(_THEN_ITEM.match(p)) for p in parts]
    things = [_THEN_ITEM.sub("", p) for p in parts]
    first = bool(things) and bool(_FIRST_ITEM.search(things[0]))  # "A first, then B"
    things[:1] = [_FIRST_ITEM.sub("", t) for t in things[:1]]
    counted = _NUMBER.get(n, len(things)) == len(things)
    if len(things) < 2 or not all(_looked_at(p) for p in things) or not counted:
        return m[0]
    said = _under(things[0], lamp, m[0][0].isupper()) + (" first" if first else "")
    for k, p in enumerate(things[1:], 1):
        said += (", then " if then[k] else " and " if k == len(things) - 1 else ", ") + _under(p, lamp, False)
    return said


def _list_under(m: re.Match[str]) -> str:
    """ "look at A on L and B under the lamp": each looked at under it, where the list has two items or
    more."""
    if len(_ITEM_SPLIT.split(m["items"].strip())) < 2:
        return m[0]
    capital = bool(m["verb"]) and m[0][0].isupper()
    listed = _listed_under(m["items"], m["lamp"].split(None, 1)[1].lower(), capital)
    return (m["join"] or "") + listed if listed else m[0]


# "hold the box under the lamp, and once you've done that, hold a CD under it as well": "it" is the lamp said
# before (the rules read "under it" as no place)
_HELD_UNDER_IT = re.compile(r"\b(?:hold|look\s+at|examine)\s+[^,.;!?]+?\s+under\s+(?P<it>it)\b", re.I)


def _held_under_lamp(m: re.Match[str]) -> str:
    """The lamp said last, in this sentence or the one before, for the "it" a thing is held under."""
    lamps = list(_LAMP.finditer(m.string, 0, m.start("it")))
    if not lamps or len(re.findall(r"[.;!?\n]", m.string[lamps[-1].end() : m.start()])) > 1:
        return m[0]
    return m[0][: m.start("it") - m.start()] + lamps[-1][0].lower()


def items_under_lamp(text: str) -> str:
    """`text` with each thing listed after an examination under a lamp written as looked at under it."""
    text = _HELD_UNDER_IT.sub(_held_under_lamp, text)
    text = _HEADED_UNDER.sub(_headed_under, _THINGS_UNDER.sub(_things_under, text))
    text = _LIST_UNDER.sub(_list_under, text)

    def same(m: re.Match[str]) -> str:  # "do the same" may follow the examination's sentence
        lamp = _lamp_before(m.string, m.start(), sentences=1)
        if not lamp:
            return m[0]
        # "do the same with a watch, and then with the laptop": one after the other (h294)
        turns = _SAME_THEN_WITH.split(m["items"])
        said = [_listed_under(t, lamp, m[0][0].isupper() and not k) for k, t in enumerate(turns)]
        return ". Then ".join(said) if all(said) else m[0]  # type: ignore[arg-type]

    text = _SAME_WITH.sub(same, text)
    at = 0  # item by item: each one written out is the examination the next one follows
    while m := _NEXT_ITEM.search(text, at):
        lamp = _lamp_before(text, m.start())
        if not lamp or not _looked_at(m["np"]) or _PUT_IN.search(m["np"]):
            at = m.start() + 1
            continue
        said = m["lead"] + _under(m["np"], lamp, False)
        text, at = text[: m.start()] + said + text[m.end() :], m.start() + len(said)
    return text


_CARRYING = frozenset({"carry", "take", "bring"})


def carried_then_lit(fr: Frame, d: Draft | None, nxt: Clause | None) -> str:
    """ "carry the alarm clock to the desk and switch on the lamp": the thing may be held under the lamp
    (ALFRED's look at it in the light) or left on the desk with the lamp switched on apart; the words do not
    say which. Why, for a refusal; "" otherwise (carried to the lamp itself, "put it on the desk and ...", a
    purpose that says it: "... and turn on the lamp to look at it")."""
    lit = fr.cls == "light" or fr.light_on
    if d is None or not lit or len(d.frames) != 1 or (nxt is not None and nxt.joiner == "to"):
        return ""
    carried, it = d.frames[0]
    dest = dest_of(it, carried.cls)
    to_lamp = any(np.is_lamp() for _, np in it.pps)  # "over to the lamp on the dresser": held under it
    if carried.verb not in _CARRYING or dest is None or to_lamp or it.obj is None:
        return ""
    where = f"{it.obj.text} carried to {dest.text}"
    return f"{where}: held under the lamp, or left there with the lamp on? say which"
