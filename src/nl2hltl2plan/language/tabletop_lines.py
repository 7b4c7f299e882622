"""A tabletop instruction as the readers read it (issue 28): its lines as one line, and the names of
the world's things as the world spells them.

`translate` joins an instruction's lines with spaces, which loses what the line breaks said in a list
written one item a line ("yellow plate first: green apple + orange" / "then blue plate: ..."; a plate
heading with its objects on the lines under it; "[ ] green apple -> blue plate" / "[ ] orange -> ...").
Here each line break says what a writer of one line would have put there, by what the lines name:

- after a line that ends in punctuation, or in a word that cannot end a clause ("the", "on", "and"), the
  line goes on: a space, as before;
- after a line that names nothing (a title, a subject line, a table's header), a space, as before;
- a line that names plates and no object, with a line of object names alone after it, is that plate's
  heading: ": " ("Step 1: yellow plate" / "- green apple" -> "Step 1: yellow plate: green apple");
- two lines in a row of object names alone are items of one list: ", ";
- any other line that names something ends a sentence: ". ".

A keycap emoji opening a line ("1️⃣") is its number ("1."). A bullet that opens a line ("-", "*", "•",
"->", "[ ]", "[x]") only marks the item and is dropped, and so is a chat log's time stamp ("[09:14] Dana:
...", "09:14 Dana: ..."; not "12:00 put ...", which may say when). A line's number or label ("1.", "a)", "Step
2:") is kept: the readers read those as before.

Names spelt otherwise (`names_spelt`) are the world's names where the words can mean nothing else: an
identifier's words ("green_apple", "blue-plate"), a colour said in a clause after its noun ("the plate
that's blue"), and a colour said after its noun, as in the languages that put it there ("the plate blue":
the blue plate; not before another name's noun, "the plate green
apple ...", nor after a name, "the yellow plate green ...").

>>> kinds = {"green apple": False, "orange": False, "yellow plate": True}
>>> lines_joined(["Yellow plate", "- green apple", "- orange"], kinds)
'Yellow plate: green apple, orange'
>>> lines_joined(["[ ] green apple -> yellow plate", "[ ] orange -> yellow plate"], kinds)
'green apple -> yellow plate. orange -> yellow plate'
>>> lines_joined(["put the green apple on the", "yellow plate"], kinds)
'put the green apple on the yellow plate'
>>> names_spelt("Put the Green_Apple on the plate yellow", kinds)
'Put the green apple on the yellow plate'
"""

from __future__ import annotations

import re
from collections.abc import Callable

from nl2hltl2plan.language.tabletop_wording import mention_pattern

# an arrow opening a line ("-> carrot on the blue plate") is a bullet too: it points at the item
_BULLET = re.compile(r"^(?:->|=>|[-*•·–→➡]|\[\s*[xX✓]?\s*\])(?:\s+|$)")
# a keycap emoji's digit opening a line ("1️⃣ green apple ➡️ pink plate"): the list's number, as "1."
_KEYCAP = re.compile(r"^(?P<digit>\d)\ufe0f?\u20e3\s*")
# a chat log's time stamp opening a line: bracketed ("[09:14] Dana: ..."), or before the writer's name and
# a colon ("09:14 Dana: ..."); a time with no such mark ("12:00 put ...") may say when, and stays
_TIME_STAMP = re.compile(
    r"^(?:\[\s*\d{1,2}:\d{2}(?::\d{2})?\s*(?:[ap]\.?m\.?)?\s*\]|"
    r"\d{1,2}:\d{2}(?::\d{2})?\s*(?:[ap]\.?m\.?)?(?=\s+[A-Z][a-z]+:))\s*",
    re.IGNORECASE,
)
# what a line of names alone may hold besides the names ("the green apple and the orange", "carrot + orange")
_OTHER_WORDS = re.compile(r"\b(?:the|a|an|and)\b|[\s,+&]")
# a line that ends so: the sentence goes on past the line break
_GOES_ON = re.compile(
    r"(?:[.,;:!?(\[{]|\b(?:the|a|an|on|onto|in|into|to|and|or|with|of|then))\s*$", re.IGNORECASE
)


def lines_joined(lines: list[str], kinds: dict[str, bool]) -> str:
    """The lines (each already one line of words) as one line, each break read by what the lines name
    (see the module docstring); `kinds`: each name in words -> is it a plate."""
    pattern = mention_pattern(kinds, re.I)
    items = [_BULLET.sub("", _TIME_STAMP.sub("", line.strip())).strip() for line in lines]  # indentation kept
    items = [_KEYCAP.sub(r"\g<digit>. ", item) for item in items]  # "1️⃣ green apple" is "1. green apple"
    items = [item for item in items if item]
    named = [{_is_plate(found, kinds) for found in pattern.findall(item)} for item in items]
    bare = [not _OTHER_WORDS.sub("", pattern.sub(" ", item)) for item in items]
    out = items[0] if items else ""
    for i in range(1, len(items)):
        if _GOES_ON.search(items[i - 1]) or not named[i - 1]:
            out += " "  # the sentence goes on, or the line names nothing (a title, a subject line)
        elif named[i - 1] == {True} and named[i] == {False} and bare[i]:
            out += ": "  # a plate heading and the objects under it
        elif named[i - 1] == {False} and bare[i - 1] and named[i] == {False} and bare[i]:
            out += ", "  # items of one list of objects
        else:
            out += ". "
        out += items[i]
    return out


def _is_plate(found: str, kinds: dict[str, bool]) -> bool | None:
    name = " ".join(found.lower().split())
    return kinds.get(name, kinds.get(name.removesuffix("s")))


# a telegram's "STOP" (in capitals, closing the text) ends each sentence: "GREEN APPLE TO BLUE PLATE STOP ..."
_TELEGRAM_STOP = re.compile(r"\s*\bSTOP\b[\s.!]*")
# a pause ("...") before a word of place goes on with its sentence: "and the orange... on the yellow plate"
_PAUSE_BEFORE_PLACE = re.compile(r"\s*(?:\.{3,}|…)\s*(?=(?:on|onto|in|into|to|upon)\b)", re.IGNORECASE)


def stops_read(text: str) -> str:
    """`text` with a telegram's capital "STOP"s as full stops where one closes the text, and a pause before
    a word of place ("the orange... on the yellow plate") as a space.

    >>> stops_read("GREEN APPLE TO BLUE PLATE STOP ORANGE TO YELLOW PLATE STOP")
    'GREEN APPLE TO BLUE PLATE. ORANGE TO YELLOW PLATE.'
    """
    text = _PAUSE_BEFORE_PLACE.sub(" ", text)
    if re.search(r"\bSTOP[\s.!]*$", text):
        text = _TELEGRAM_STOP.sub(". ", text).strip()
    return text


def names_spelt(text: str, kinds: dict[str, bool]) -> str:
    """`text` with each name written as an identifier or with its colour after its noun spelt as the
    world's name (see the module docstring); `kinds`: each name in words -> is it a plate."""
    two_words = [name.split() for name in kinds if len(name.split()) == 2]
    for first, second in two_words:
        joined = rf"\b{first}[_-]{second}\b|\b{first.capitalize()}{second.capitalize()}\b"
        text = re.sub(joined, f"{first} {second}", text, flags=re.IGNORECASE)
    for first, second in two_words:  # "the plate that's blue", "the plate which is blue": the blue plate
        said = rf"\b{second}\s+(?:that|which)(?:'s|\s+is)\s+{first}\b"
        text = re.sub(said, f"{first} {second}", text, flags=re.IGNORECASE)
    nouns = "|".join(sorted({second for _, second in two_words}))
    modifiers = {first for first, _ in two_words}
    for first, second in two_words:
        after = re.compile(rf"\b(?P<before>\w+\s+){second}\s+{first}\b(?!\s+(?:{nouns})\b)", re.IGNORECASE)
        text = after.sub(_colour_fronted(f"{first} {second}", modifiers), text)
    return text


def _colour_fronted(name: str, modifiers: set[str]) -> Callable[[re.Match[str]], str]:
    """ "the plate blue" -> "the blue plate"; "yellow plate blue" (after a name's modifier) as it was."""

    def fronted(m: re.Match[str]) -> str:
        return m[0] if m["before"].strip().lower() in modifiers else f"{m['before']}{name}"

    return fronted


_BRACKETS = re.compile(r"\s*\((?P<inside>[^()]*)\)")


def bracketed_list_opened(text: str, kinds: dict[str, bool]) -> str:
    """A list in brackets that holds every name of the text, after words that name nothing ("sort fruit
    (green apple -> pink plate, orange -> yellow plate)"), as the list after a heading's colon; the text as
    it is otherwise (brackets that add to a named thing: "the carrot (the long one)").

    >>> bracketed_list_opened("sort fruit (carrot -> blue plate, orange -> blue plate), any order",
    ...                       {"carrot": False, "orange": False, "blue plate": True})
    'sort fruit: carrot -> blue plate, orange -> blue plate, any order'
    """
    pattern = mention_pattern(kinds, re.IGNORECASE)
    found = list(_BRACKETS.finditer(text))
    if len(found) != 1:
        return text
    m = found[0]
    outside = text[: m.start()] + " " + text[m.end() :]
    if pattern.search(outside) or len(pattern.findall(m["inside"])) < 2 or not text[: m.start()].strip():
        return text
    return f"{text[: m.start()]}: {m['inside'].strip()}{text[m.end() :]}"
