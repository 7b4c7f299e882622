"""General English filler in a frame (h235, issues 24 and 28): what tells a word that names nothing a task
needs ("luck", "gather", "campers" addressed) from a word that may name a thing no table knows ("the zebra",
"smash that button"), for every reader's frame rule (`handover_discourse.empty`), and how a dropped frame is
said in a result (`frame_note`).

The words that keep a fragment (they add a thing, wait, hedge, say a time or an order) are
`frame_keeps.txt`'s; English is pyspellchecker's list and lemminflect's lexicon (`spelling`).
"""

from __future__ import annotations

import re
from functools import lru_cache
from itertools import pairwise
from typing import NamedTuple

from nl2hltl2plan.language.content_words import (
    LOCATIVE,
    OBJECT_START,
    frame_keeps,
    names_content,
    word_categories,
)
from nl2hltl2plan.language.spelling import american, english_lemmas, english_word

# what opens a thing's name or a place: after one of these, a word may name what is moved or where to
_THING_BEFORE = OBJECT_START | LOCATIVE - {"of"} | frozenset("to into onto toward towards".split())


# a demonstrative points at a thing in view: the noun after it may name one of the scene's ("that button")
_POINTING = frozenset("that this these those".split())


@lru_cache(maxsize=16384)
def filler(
    words: tuple[str, ...], k: int, set_off: bool = False, address: bool = False, voice: bool = False
) -> bool:
    """Whether `words[k]`, a word of a fragment that holds no content word, is general English filler
    that names nothing a task needs (h235): a word English knows that is used as something other than a
    noun ("luck", "easy", "gather", "lovely"), never after a determiner or a place's preposition (where it
    may name a thing: "smash that button", "put it on the zebra"); a noun alone only where it addresses
    the listeners, set off by a comma: a group ("campers", "buddies") or after "my" / "dear" and the words
    that describe them ("my dears", "my lovely assistants"); a British spelling is English ("marvellous").
    A word no list of English knows ("gg", a misspelt name) and a word that adds a thing ("too",
    `frame_keeps.txt`: "the zebra too") are never filler. In a `voice`'s opening or closing sentence that
    names no content word (h281: "Glove on, hood off.", "Here's the combination."), a noun is filler too,
    wherever it stands, except after a demonstrative ("Smash that like button": a thing pointed at).

    >>> filler(("best", "of", "luck"), 2), filler(("the", "zebra"), 1), filler(("zebra",), 0)
    (True, False, False)
    >>> filler(("campers",), 0, set_off=True), filler(("campers",), 0)
    (True, False)
    """
    word = american(words[k])  # a British spelling is English: "marvellous", "colour"
    if names_content(word, voice, kept=True) or not english_word(word):
        return False
    if _remark_subject(words, k):
        return True
    if voice:
        return not any(w in _POINTING for w in words[:k])
    vocative = (set_off or address) and _after_my(words[:k])
    if any(w in _THING_BEFORE for w in words[:k]) and not vocative:
        return False
    kinds = english_lemmas(word)
    if word.endswith("ly") and "ADV" in kinds:  # how or in what order: "respectively", "sequentially"
        return False
    if set(kinds) - {"NOUN", "PROPN"}:
        return True
    # a plural: "campers", "buddies", "gamers" (a word the lexicon lacks, whose singular English knows)
    group = any(lemma != word for lemma in kinds.get("NOUN", ())) or (
        not kinds and word.endswith("s") and english_word(word[:-1])
    )
    return address or (set_off and (group or vocative))


def named_alone(words: tuple[str, ...]) -> bool:
    """Whether a sentence is a thing's name alone: a noun English uses only as a noun, after determiners and
    adjectives at most ("Zebra.", "The zebra."); it may add a thing to what was asked, as "The zebra too."
    does, so no voice's edge drops it (h281; "Hood off.", "Nice putt." say something of a thing).

    >>> named_alone(("the", "zebra")), named_alone(("hood", "off")), named_alone(("nice", "putt"))
    (True, False, False)
    """
    if not words or set(english_lemmas(american(words[-1]))) != {"NOUN"}:
        return False
    return all(w in _DETERMINERS or "ADJ" in english_lemmas(american(w)) for w in words[:-1])


# "is" after the subject of a remark, "'s" as the reader spaces it ("smoker s lit")
_COPULA = frozenset("s is are was were".split())
_DETERMINERS = frozenset("the a an our my".split())


def _remark_subject(words: tuple[str, ...], k: int) -> bool:
    """Whether `words[k]` is the subject of a remark on the scene, or its "is" / "'s": a noun opening the
    fragment (after a determiner at most) before "is" / "'s" and what is said of it ("Smoker's lit", "The
    furnace is hot", "Clay's wedged and ready"; "That's the map", all its words; h263). A remark names
    no thing to move; a command on a noun ("Smash that like button") and a noun alone ("Zebra.") stay
    refused."""
    pointed = len(words) > 2 and words[0] in ("that", "this") and words[1] in _COPULA  # "That's the map."
    if pointed and words[2] in _DETERMINERS:
        return True
    at = 1 if words and words[0] in _DETERMINERS | {"this"} else 0
    if k == at + 1 and words[k] in _COPULA:
        return _remark_subject(words, at)
    subject = k == at and k + 2 < len(words) and words[k + 1] in _COPULA
    return subject and "NOUN" in english_lemmas(american(words[k]))


@lru_cache(maxsize=1)
def _counts() -> dict[str, int]:
    words = word_categories("content_words.txt")
    counts = {name.removeprefix("count_"): ws for name, ws in words.items() if name.startswith("count_")}
    return {w: int(value) for value, ws in counts.items() for w in ws}


def count_in(text: str) -> bool:
    """Whether a whole sentence (lower case, words only) is a count-in: three or more numbers said one
    after another, up by one ("And five, six, seven, eight!", "one two three"; h263); it gives a beat,
    never a count of things."""
    said = text.split()
    said = said[1:] if said[:1] == ["and"] else said
    values = [_counts().get(w, int(w) if w.isdigit() else -1) for w in said]
    return len(values) >= 3 and min(values) >= 0 and all(b == a + 1 for a, b in pairwise(values))


def _after_my(before: tuple[str, ...]) -> bool:
    """Whether the words `before` a word end in "my", "dear" or "dearest" and the words that describe whom
    they call: "my", "my lovely", "my good old" ("my lovely assistants", "my good man", "Dearest Lily"), a
    vocative's opening."""
    for k in range(len(before) - 1, -1, -1):
        if before[k] in ("my", "dear", "dearest"):
            return True
        kinds = english_lemmas(american(before[k]))
        if "ADJ" not in kinds or before[k] in frame_keeps():
            return False
    return False


def frame_note(dropped: list[str]) -> str:
    """The note that says what the general filler rule dropped (every reader's wording)."""
    return "dropped as frame (names nothing a task needs): " + ", ".join(map(repr, dict.fromkeys(dropped)))


class Dropped(NamedTuple):
    """Where the general filler rule's drops are written (`dropped`, shown in the result's notes), the
    world's own names, each word a content word (`names`: "orange", "plate" in the tabletop world), and
    whether only what the lists alone keep is dropped (`only_general`: a reader with its own policy for
    listed greetings and thanks, the tabletop's `courtesy.without_greetings`)."""

    dropped: list[str] | None = None
    names: frozenset[str] = frozenset()
    only_general: bool = False


PART_BREAK = re.compile(r",|;|\s[-–—]+\s")  # what sets a part of a fragment off
PART_END = "qqpartqq"  # the mark of a part's end among a fragment's words


def parts_of(kept: list[str], marked: list[str]) -> list[tuple[str, ...]]:
    """The words `kept` of a fragment (its words in order, some dropped) grouped by the parts that commas
    and dashes set off in it (`marked`: all its words, each part's end marked)."""
    parts: list[list[str]] = [[]]
    at = 0
    for word in kept:
        while at < len(marked) and marked[at] != word:
            if marked[at] == PART_END:
                parts.append([])
            at += 1
        parts[-1].append(word)
        at += 1
    return [tuple(p) for p in parts if p]
