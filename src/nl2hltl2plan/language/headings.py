"""What a heading is and what its words name, for every world's reader (its words: `heading_heads.txt`,
read through `heading_words`; what each reader does with a heading stays in the reader). `translate`
applies `unlabelled` to each line of an instruction before any reader or backend reads it.

- A one-word label and a dash open a sentence as a colon does ("Goal - ...", "Condition — ..."); not after
  a step's number ("1 - move ...", "two - put ...").
- A labelled sentence whose value asks nothing ("Condition - none", "Notes: n/a", "Constraints: nothing";
  the labels are `empty_label` in content_words.txt, the values `empty_value`) is dropped; another label
  keeps its value, which the readers read ("Ordering: none" frees an order, "Other regions: nothing" says
  where nothing goes).
- Any other label stays for the readers, which read its value ("Task: put ...") or refuse it by name
  ("Note: the fridge is cold").
- A heading that counts what follows ("Two things:", "Three jobs to do:", "Two stages.", "4 placements -")
  is found by `counted_headings`, for a world's reader to check against its reading: the things it counts
  are the tasks, the stages the labelled steps ("Stage one: ... Stage two: ..."). It is never dropped
  unchecked.
- A note's heading or title that names no task ("Prep card: chill ...", "Lamp game: switch on ...",
  "Kitchen bingo! Heat ...", "Fridge duty. Put ...", "Guest requests: ...", "Noah, tidy-up time.", h259): a
  heading at the start of a note (a label before a colon or a dash, or a short sentence with no verb, ended
  by a stop or an exclamation) whose head noun is a word for a document, a list, an activity or a time: the
  words before the head are its name, not a thing, and `heading_dropped` drops the heading, each said in the
  assumptions (nothing is dropped silently). A heading with a preposition, a determiner, a negation, an
  order or a verb that names no thing ("Chill time:", "Jobs in order:", "Mugs on the table!") is not one: it
  stays, to be read or refused as before. A count in the heading ("Three jobs, any order:") is checked
  against the reading by `note_counts`; a free order in it ("any order") leaves the tasks unordered, as the
  reading does.
- The labels of a record's fields and of a message's headers ("Object:", "Subject:", "Task:"), the nouns of
  a step's label ("Step 1:", "### Phase A") and a heading of wishes ("What I need:") are `heading_words`'
  categories, which the tabletop, handover and grammar readers ask.

>>> unlabelled("Goal - put the apple in the fridge. Condition - none.")
'Goal: put the apple in the fridge.'
>>> unlabelled("Notes: n/a")
''
>>> unlabelled("1 - put the mug in the sink. Ordering: none")
'1 - put the mug in the sink. Ordering: none'
>>> heading_dropped("Prep card: chill a lettuce.", [])
'chill a lettuce.'
>>> heading_dropped("Chill time: chill a lettuce.", [])
'Chill time: chill a lettuce.'
"""
from __future__ import annotations

import re
from functools import cache
from typing import NamedTuple

from nl2hltl2plan.language.content_words import (
    LOCATIVE,
    OBJECT_START,
    free_order_phrase,
    phrase_category,
    shared_words,
    vocabulary,
    word_categories,
)
from nl2hltl2plan.language.grounding import find_mentions

__all__ = [
    "CountedHeading",
    "counted_headings",
    "heading_dropped",
    "heading_note",
    "heading_pattern",
    "heading_words",
    "note_counts",
    "row_labels_dropped",
    "unlabelled",
    "wish_heading",
]


@cache
def heading_words() -> dict[str, frozenset[str]]:
    """category -> the words of `heading_heads.txt`: a heading's head nouns, what a counting heading counts,
    a step label's nouns, a record's and a message's field labels (`_`-joined where two words)."""
    return word_categories("heading_heads.txt")


@cache
def heading_pattern(kind: str) -> str:
    """One category of `heading_words` as a regular expression, the longest word first (a `_` is a space),
    with no context and no flags."""
    words = sorted(heading_words()[kind], key=lambda w: (-len(w), w))
    return "(?:" + "|".join(r"\s+".join(map(re.escape, w.split("_"))) for w in words) + ")"


def wish_heading() -> str:
    """A heading that says a list of wishes ("What I need: a warm apple slice in the fridge, ...", h231) as a
    regular expression, to its colon and the space after it (no flags: the grammar ignores case)."""
    return rf"what\s+(?:I|we)(?:'d|\s+would)?\s+{heading_pattern('wish_heading')}\s*:\s*"


_COUNT_WORDS = {w: i for i, w in enumerate("one two three four five six seven eight nine ten".split(), 1)}
_NUMBER_WORDS = frozenset(_COUNT_WORDS) | heading_words()["numeral"]
_START = r"(?P<start>^|(?<=[.!?;])\s+)"
_DASH_LABEL = re.compile(rf"{_START}(?P<label>[A-Za-z]+)(?:\s*[—–]\s*|\s+-+\s+)")
# a label of up to three words, a colon, and a value that asks nothing, to the sentence's end
_EMPTY = re.compile(
    rf"{_START}(?P<label>[A-Za-z]+(?:\s+[A-Za-z]+){{0,2}})\s*:\s*(?:{phrase_category('empty_value')})\s*"
    r"(?:[.!?;]+|$)",
    re.I,
)


def unlabelled(line: str) -> str:
    """`line` with its labels' dashes as colons and its labelled sentences that ask nothing dropped."""
    line = _DASH_LABEL.sub(_as_colon, line)
    return " ".join(_EMPTY.sub(_dropped, line).split())


def _as_colon(m: re.Match[str]) -> str:
    if m["label"].lower() in _NUMBER_WORDS:
        return m[0]
    return f"{m['start']}{m['label']}: "


def _dropped(m: re.Match[str]) -> str:
    labels = set(re.findall(r"[a-z]+", m["label"].lower()))
    return m["start"] if labels <= _EMPTY_LABELS else m[0]


_EMPTY_LABELS = shared_words("empty_label")


def _counted(start: str) -> re.Pattern[str]:
    """A heading that counts what follows (its tasks, or the stages they come in), after `start`."""
    return re.compile(
        # "there are", "we have", "today the robot has": who has the things to do is the one asked
        rf"{start}(?:(?:(?:today|now),?\s+)?(?:there\s+are|here\s+are|(?:we|you|i)\s+have|(?:the\s+robot|it)\s+has)\s+)?"
        rf"(?P<phrase>(?P<count>\d|{'|'.join(_COUNT_WORDS)})\s+(?:(?!{heading_pattern('not_a_total')}\b)[a-z]+\s+)?"
        rf"(?:(?P<stages>{heading_pattern('counted_stage')})|{heading_pattern('counted_task')})"
        r"(?:\s+(?:to\s+(?:do|place|make|carry\s+out)|in\s+(?:all|total)|for\s+(?:you|the\s+robot|today)))?)"
        # "Three jobs, any order:": the order the heading frees is read with the tasks, not counted
        rf"(?:\s*,?\s*{free_order_phrase('whole')})?"
        r"\s*(?P<end>[:.!,]|\s-+\s|\s*[—–])",
        re.I,
    )


_COUNTED = _counted(_START)
# a note's count of its jobs, also after an address or its writer ("Kiddo, three jobs: ...", "Mum here - two
# things: ..."), which the household framing drops with the words before it (`courtesy`): its reader checks
# the tasks counted before a colon (`note_counts`)
_NOTE_COUNT = _counted(r"(?:^|[.!?;,]\s*|\s[-–—]+\s*)")


class CountedHeading(NamedTuple):
    """A heading's count: its words ("two things to do"), its number, and whether it counts stages."""

    phrase: str
    number: int
    stages: bool
    span: tuple[int, int]  # the heading in the text ("There are two stages."), its colon or stop included


def counted_headings(text: str) -> list[CountedHeading]:
    """The headings of `text` that count what follows ("Two things:", "There are two stages.", "3 jobs -"),
    each opening a sentence; the number as said, digits or a word.

    >>> [(h.phrase, h.number, h.stages) for h in counted_headings("Two stages. Stage one: ...")]
    [('Two stages', 2, True)]
    >>> counted_headings("Put two things on the plate. One more thing: ...")
    []
    """
    out = []
    for m in _COUNTED.finditer(text):
        word = m["count"].lower()
        count = int(word) if word.isdigit() else _COUNT_WORDS[word]
        out.append(CountedHeading(m["phrase"], count, m["stages"] is not None, (m.end("start"), m.end())))
    return out


def note_counts(text: str) -> list[CountedHeading]:
    """The counts of a note's jobs said as a heading closed by a colon, at the start, after a sentence, an
    address or a dash: the tasks they count, which a reading must make as many of.

    >>> [(h.phrase, h.number) for h in note_counts("Kiddo, three jobs: put the mug in the sink, ...")]
    [('three jobs', 3)]
    >>> note_counts("One more thing: put the mug in the sink.")
    []
    """
    out = []
    for m in _NOTE_COUNT.finditer(text):
        if m["stages"] or m["end"] != ":":
            continue
        word = m["count"].lower()
        count = int(word) if word.isdigit() else _COUNT_WORDS[word]
        out.append(CountedHeading(m["phrase"], count, False, m.span("phrase")))
    return out


# --- a note's heading that names no task (h259; see the module docstring)

# a label of up to six words before a colon or a spaced dash, or a sentence of as many (a label and its
# record: "Housekeeping: Room 305.") ended by a stop or an exclamation, at the start of the text
_LABEL = re.compile(r"^\s*(?P<words>[^:.!?;()]{1,60}?)\s*(?::|\s[-–—]+\s|[—–])\s*(?=\S)")
_TITLE = re.compile(r"^\s*(?P<words>[^.!?;,()]{1,50}?)\s*[.!]+(?:\s+|$)")


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
    heads = heading_words()
    kinds = heads["document"] | heads["activity"] | heads["time"]
    # a record's kind and number opening it ("Ticket 2291, room 8"): a document, never a task or a job,
    # which may number the steps ("Task 1: ... Task 2: ...")
    named = said[-1] in kinds or (said[0] in kinds - heads["steps"] and any(w.isdigit() for w in said[1:]))
    if not named:
        return False
    counted = [w for w in said if w in _COUNT_WORDS or w.isdigit()]
    # "armchair: 2 newpapers + 2 cards.": counted things joined by "and" are a list, not a heading's name
    # (h300's line 93 dropped both tasks, its head "cards" taken for a document's)
    if any(w == "and" and (n in _COUNT_WORDS or n.isdigit()) for w, n in zip(said, said[1:], strict=False)):
        return False
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
    `note_counts` to check the count against the reading; "" for a heading with no count."""
    count = re.search(r"(?i)\b(\w+)\s+(\w+)\W*$", _free_order().sub("", heading["words"]))
    if count is None or count[1].lower() not in _COUNT_WORDS:
        return ""
    return f"{count[1]} {count[2]}:"


# --- a row's or an item's label in a household list (h294, issue 28): "Row 1 - pick up two books.",
# "Rnd 2: 2 sets of keys onto the sofa.", "item 3 - wrist watch, ...", "bathroom hack number two: ...",
# "(a) smartphone - ...", "b) the blue vase ...". The label names the part: its number is no count (read as
# one, "Row 2 - a credit card" took two cards) and no order (the guide: a sequence with no temporal word
# orders nothing; "hack number one ... number two" was read as one after the other), and a verb after it is
# read as the sentence's own ("Hack: rinse a bar of soap" left 'rinse' unread). Numbered steps ("1.", "Step
# 2:") are `numbered_steps`' and stay. A label with an order word ("Next item:", "Last row:") stays.
_ROW_NUMBER = r"(?:(?:number|no\.?|#)\s*)?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
_ROW_LABEL = re.compile(
    rf"(?P<start>^|(?<=[.!?;:,])\s*)(?P<label>(?:(?P<name>[A-Za-z]+)\s+)?{heading_pattern('row_label')}"
    rf"(?:\s+{_ROW_NUMBER})?)\s*(?::|\s+[-–—]+\s+|[–—])\s*(?=\S)",
    re.I,
)
# a letter's label, "(a) ..." / "b) ...", opening the text or a sentence: two or more of them make a list
_LETTER_LABEL = re.compile(r"(?P<start>^|(?<=[.!?;:])\s*)(?P<label>\(?[a-h]\))\s+(?=\S)")
# "Work the rows in order": the order of the labelled parts is the order they are written in
_PARTS_IN_ORDER = re.compile(
    rf"\b(?:work|do|knit|follow|complete|take)\s+(?:the|these|those)\s+{heading_pattern('row_label')}s?"
    r"\s+(?:in\s+(?:that\s+|this\s+)?order|in\s+turn|one\s+after\s+the\s+other)\b",
    re.I,
)


def row_labels_dropped(text: str, dropped: list[str]) -> str:
    """`text` without the labels of its rows and items (see above), each added to `dropped` as said; a
    sentence that works "the rows (items) in order" is "Do them in that order", labelled or not. (Where a
    sentence orders the items by their labels, "Item 2 before item 1", the labels number steps: the
    household reader leaves them to `numbered_steps` and does not ask this, h292.)"""

    def drop(m: re.Match[str]) -> str:
        if m["name"] and (m["name"].lower() in _blocking() or m["name"].lower() in _verbs()):
            return m[0]  # "Next item:", "put item ...": an order word or a verb is read
        dropped.append(" ".join(m["label"].split()))
        return m["start"] and " "

    def letter(m: re.Match[str]) -> str:
        dropped.append(m["label"])
        return m["start"] and " "

    said = _ROW_LABEL.sub(drop, text)
    if len(_LETTER_LABEL.findall(said)) >= 2:
        said = _LETTER_LABEL.sub(letter, said)
    if said == text and not _PARTS_IN_ORDER.search(text):
        return text
    return " ".join(_PARTS_IN_ORDER.sub("Do them in that order", said).split())
