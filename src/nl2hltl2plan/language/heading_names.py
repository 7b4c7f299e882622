"""Headings and titles whose words are taken for things (h259, issues 28 and 23): "Prep card: chill ...",
"Lamp game: switch on ...", "Kitchen bingo! Heat ...", "Fridge duty. Put ...", "Guest requests: ...",
"Noah, tidy-up time.". A heading at the start of a note (a label before a colon or a dash, or a short
sentence with no verb, ended by a stop or an exclamation) whose head noun is a word for a document, a list,
an activity or a time (`heading_heads.txt`) names no task: the words before the head are its name, not a
thing, and the heading is dropped, each dropped heading said in the assumptions (nothing is dropped
silently). A heading with a preposition, a determiner, a negation, an order or a verb that names no thing
("Chill time:", "Jobs in order:", "Mugs on the table!") is not one: it stays, to be read or refused as
before. A count in the heading ("Three jobs, any order:") is checked against the reading by
`headings.note_counts`; a free order in it ("any order") leaves the tasks unordered, as the reading does.

>>> heading_dropped("Prep card: chill a lettuce.", [])
'chill a lettuce.'
>>> heading_dropped("Chill time: chill a lettuce.", [])
'Chill time: chill a lettuce.'
"""

from __future__ import annotations

import re
from functools import cache

from nl2hltl2plan.language.content_words import (
    LOCATIVE,
    OBJECT_START,
    free_order_phrase,
    vocabulary,
    word_categories,
)
from nl2hltl2plan.language.grounding import find_mentions

# a label of up to six words before a colon or a spaced dash, or a sentence of as many (a label and its
# record: "Housekeeping: Room 305.") ended by a stop or an exclamation, at the start of the text
_LABEL = re.compile(r"^\s*(?P<words>[^:.!?;()]{1,60}?)\s*(?::|\s[-–—]+\s|[—–])\s*(?=\S)")
_TITLE = re.compile(r"^\s*(?P<words>[^.!?;,()]{1,50}?)\s*[.!]+(?:\s+|$)")


@cache
def _heads() -> dict[str, frozenset[str]]:
    return word_categories("heading_heads.txt")


@cache
def _blocking() -> frozenset[str]:
    """Words a heading never holds: what places or picks a thing, and the order, negation and condition
    words, which the readers read."""
    words = vocabulary()
    kinds = ("order", "negation", "condition", "quantifier_all", "quantifier_vague", "hedge")
    return frozenset(LOCATIVE | OBJECT_START - {"today's"}).union(*(words.get(k, ()) for k in kinds))


@cache
def _verbs() -> frozenset[str]:
    return frozenset().union(*(ws for kind, ws in vocabulary().items() if kind.startswith("verb_")))


def _is_heading(words: str) -> bool:
    """Whether `words` (a label or a title, its free order taken out) is a heading that names no task: it
    ends in a head noun (after its name, which may count it: "Three jobs") or opens with one and a record's
    number ("Ticket 2291, room 8 bathroom"), and holds no word the readers read."""
    said = re.findall(r"[a-z0-9'-]+", words.lower().replace("’", "'"))
    # a head alone ("Task:", "Chores:") is read as before; a name set off by a comma is an address ("Love,
    # two things:"), not a heading's, except in a record ("Ticket 2291, room 8 bathroom")
    if not 2 <= len(said) <= 6 or ("," in words and not any(w.isdigit() for w in said)):
        return False
    # a thing's name that ends in a head ("Credit card: look at it ...") is the thing
    if any(m.end == len(said) and m.start < m.end - 1 for m in find_mentions(" ".join(said))):
        return False
    heads = _heads()
    kinds = heads["document"] | heads["activity"] | heads["time"]
    # a record's kind and number opening it ("Ticket 2291, room 8"): a document, never a task or a job,
    # which may number the steps ("Task 1: ... Task 2: ...")
    named = said[-1] in kinds or (said[0] in kinds - heads["steps"] and any(w.isdigit() for w in said[1:]))
    if not named:
        return False
    counted = [w for w in said if w in heads["count"] or w.isdigit()]
    if counted and not (said[0] in kinds or said[-2:-1] == counted[-1:]):  # "Three jobs", "Ticket 2291"
        return False
    for word in said:
        plain = word.removesuffix("'s")
        if word in _blocking() or plain in _blocking():
            return False
        # a verb the readers read is a command ("Chill time:"), unless it also names a thing ("Microwave
        # duty") or is a noun's part ("tidy-up time")
        if plain in _verbs() and not find_mentions(plain):
            return False
    return True


def _numbers_parts(heading: re.Match[str], text: str) -> bool:
    """Whether the heading's kind and number ("Card 1") number another part of the text ("Card 2: ...")."""
    kind = re.match(r"\s*([A-Za-z]+)\s+#?\d", heading["words"])
    return kind is not None and re.search(rf"\b{kind[1]}\s+#?\d", text[heading.end() :], re.I) is not None


def heading_note(dropped: list[str]) -> str:
    """The note that says which headings were dropped (their words name no thing a task uses)."""
    return "read as a heading, not as things: " + ", ".join(map(repr, dict.fromkeys(dropped)))


@cache
def _free_order() -> re.Pattern[str]:
    return re.compile(rf",?\s*\b{free_order_phrase('whole')}\s*$", re.I)


def heading_dropped(text: str, dropped: list[str]) -> str:
    """`text` without the headings that open it and name no task (see the module docstring), each added to
    `dropped` as said; a heading's free order ("Three jobs, any order:") is dropped with it (the reading
    leaves tasks unordered unless an order is said)."""
    while True:
        for m in (_TITLE.match(text), _LABEL.match(text)):
            if m is None or _numbers_parts(m, text) or not _is_heading(_free_order().sub("", m["words"])):
                continue
            kept = _count_kept(m)
            if kept and " ".join(m["words"].split()).lower() == kept[:-1].lower():
                return text  # a count and its head alone ("Two things."): read as before
            dropped.append(" ".join(m["words"].split()))
            text = kept + " " + text[m.end() :] if kept else text[m.end() :]
            break
        else:
            return text


def _count_kept(heading: re.Match[str]) -> str:
    """What stays of a heading that counts its tasks ("Three jobs, any order:" is "Three jobs:"), for
    `headings.note_counts` to check the count against the reading; "" for a heading with no count."""
    count = re.search(r"(?i)\b(\w+)\s+(\w+)\W*$", _free_order().sub("", heading["words"]))
    if count is None or count[1].lower() not in _heads()["count"]:
        return ""
    return f"{count[1]} {count[2]}:"
