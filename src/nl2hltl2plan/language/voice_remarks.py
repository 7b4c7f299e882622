"""A voice's remarks around a handover instruction's commands (h296, issue 24): a warning that names no
thing of the scene ("Mind the dog.", "Keep back from the grate."), a tag question or an endearment tagged
onto a sentence's end ("..., there's a good lad.", "..., isn't it, pet?"), a farewell ("Ta-ra.") and a
heading of the voice's own words over a command ("Warm-up set: move ...", "Front counter: put ..."). The
phrases are `voice_remarks.txt`'s; `handover_discourse` asks these for a voice's edges and labels. Whether
a command with an object is a command (h235: never frame) is said here too (`commanded`).
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import (
    frame_keeps,
    phrase_list_pattern,
    phrase_words,
    vocabulary,
)
from nl2hltl2plan.language.spelling import american, english_lemmas, english_word


@lru_cache(maxsize=1)
def _pattern(kind: str) -> str:
    return phrase_list_pattern("voice_remarks.txt", kind)


def _spoken(text: str) -> str:
    """The text as the phrases are written: one apostrophe, a hyphen a space ("Ta-ra", "warm-up")."""
    return text.replace("’", "'").replace("-", " ")


def caution_of(sentence: str) -> str | None:
    """What a warning that opens the sentence warns of ("Mind the dog" -> "the dog"), or None where the
    sentence is no warning.

    >>> caution_of("Mind the soot."), caution_of("Keep your hands away from the rasp"), caution_of("Move")
    ('the soot', 'the rasp', None)
    """
    said = re.match(rf"(?i)^\W*(?:{_pattern('caution')})\b[\s,]*(.*?)[\s.!]*$", _spoken(sentence))
    return said[1] if said and said[1] else None


def aside_of(sentence: str) -> str | None:
    """What a voice's reassurance, plea for patience or apology opening the sentence is about ("Don't mind
    the draught" -> "the draught"; "" where it is the whole sentence), or None where it opens with none
    (h312).

    >>> aside_of("Nothing to worry about."), aside_of("Sorry about the racket!"), aside_of("Move it")
    ('', 'the racket', None)
    """
    said = re.match(rf"(?i)^\W*(?:{_pattern('aside')})(?!\w)[\s,]*(.*?)[\s.!?]*$", _spoken(sentence))
    return said[1] if said else None


# a clause's subject that takes up what the clause before named ("Mind the glue, it's still tacky")
_REFERS_BACK = re.compile(r"(?i)^\s*(?:it|they)(?=\s*(?:'s|'re|\s+(?:is|are|gets?)\b))")


def clauses(sentence: str) -> list[str]:
    """The sentence's parts set off by commas or semicolons, an "it" or "they" opening a later part taken
    as the thing the part before named, so dropped ("Mind the glue, it's still tacky": "'s still tacky").

    >>> clauses("Mind the glue, it's still tacky.")
    ['Mind the glue', "'s still tacky."]
    """
    parts = [p for p in re.split(r"[,;]", _spoken(sentence)) if p.strip()]
    return parts[:1] + [_REFERS_BACK.sub("", p) for p in parts[1:]]


def closing_tags(sentence: str) -> tuple[str, list[str]]:
    """The sentence without the tag questions, endearments and pet names a voice tags onto its end after a
    comma, and the tags (a sentence of a tag alone stays whole).

    >>> closing_tags("That's the lot, isn't it, pet?")
    ("That's the lot", ["isn't it", 'pet'])
    """
    tail = re.compile(rf"(?i),\s*((?:{_pattern('closing')}))\s*[?!.]*\s*$")
    tags: list[str] = []
    sentence = sentence.replace("’", "'")
    while (found := tail.search(sentence)) and sentence[: found.start()].strip():
        tags.insert(0, found[1])
        sentence = sentence[: found.start()]
    return sentence, tags


def farewell(sentence: str) -> bool:
    """Whether the sentence is a voice's farewell alone ("Ta-ra.", "Off you go!")."""
    return re.fullmatch(rf"(?i)\W*(?:{_pattern('farewell')})[\s.!]*", _spoken(sentence)) is not None


def attention(sentence: str) -> bool:
    """Whether the sentence is a voice's call for the listener's eyes alone ("Look this way, please.",
    "Eyes front!", h308): it names nothing to do.

    >>> attention("Look this way, please."), attention("Look at the red block")
    (True, False)
    """
    said = re.sub(r"(?i)^\W*(?:please|now|right|okay|ok)\b[\s,]*|[\s,]*\bplease\b", "", _spoken(sentence))
    return re.fullmatch(rf"(?i)\W*(?:{_pattern('attention')})[\s.!]*", said) is not None


def start_signal(sentence: str) -> bool:
    """Whether the sentence is a start signal alone ("Go.", "Go ahead!", "Begin.", "Proceed.", a coach's
    "Move!"): when to start, which is now; it names nothing to do ("go" alone has no block and no place)."""
    return re.fullmatch(rf"(?i)\W*(?:{_pattern('start')})[\s.!]*", _spoken(sentence)) is not None


# what may follow a command's verb without being a thing it acts on ("Grab your partners", "Hold on")
_NO_OBJECT = frozenset("your yours yourself yourselves on off up down out in it".split())
# a courtesy or a "let's" before a command's verb ("Please raise your glasses", "Let's play darts": the verb
# is "raise", "play")
_POLITE = re.compile(r"^\W*(?:(?:please|kindly|now|just|and|so|let['’]s|let\s+us)\s+)+")
# "is" / "'s" after a remark's subject ("Floors are wet", "Power's off"): a remark, no command
_COPULA = frozenset("s is are was were".split())


def commanded(sentence: str) -> bool:
    """Whether a clause of the sentence is a command with an object ("sing a song", "Stoke the forge"): an
    action on a thing, which no voice's edge drops (h235: a verb with an object is read or refused); or
    the sentence is a word no lexicon of English forms knows, alone (a name). A remark on a thing ("Floors
    are wet"), a likeness ("like a gondola under a bridge") and a warning ("Mind the dog": `caution_of`) are
    no commands.

    >>> commanded("Stoke the forge"), commanded("Floors are wet, so listen"), commanded("Let's play darts")
    (True, False, True)
    """
    if len(ws := re.findall(r"[a-z]+", sentence.lower())) == 1 and not english_lemmas(american(ws[0])):
        return True  # a name alone, no sign-off's ("Ana"): it may name who acts, so it is read or refused
    for clause in re.split(r"[,;:!?.]", sentence.lower()):
        ws = re.findall(r"[a-z]+", _POLITE.sub("", clause))
        # (a clause opened by a participle is no command: "reading glasses on", h308)
        # ("be quick", "let's be neat about this": a copula's command, no object; h312)
        if len(ws) < 2 or ws[0] in ("like", "be") or ws[1] in _NO_OBJECT | _COPULA or caution_of(clause):
            continue
        if _participle(ws[0]) or attention(clause):
            continue
        if "VERB" in english_lemmas(american(ws[0])):
            return True
    return False


def _participle(word: str) -> bool:
    """A verb's -ing form ("reading", "sitting", "making"; not "bring", "sing", "string")."""
    stems = (word[:-3], word[:-3] + "e", word[:-4])
    return len(word) >= 6 and word.endswith("ing") and any("VERB" in english_lemmas(s) for s in stems if s)


# what a heading over a command never holds: an article or a pronoun (a thing pointed at or named:
# "Clean the table: ..."), a word no English list knows
_NOT_IN_HEADING = frozenset("the a an this that these those it its them they their his her".split())


def heading_words(label: str) -> bool:
    """Whether a label's words (before a colon) may be a voice's heading over a command: at most three words
    English knows (a compound's parts, "warm-up"), no article or pronoun ("Warm-up set", "Today's special",
    "Chorus, everybody"; not "Clean the table"), no word that says a count, an order, a negation or a time
    (the readers' lists) or that adds, hedges or places (`frame_keeps.txt`: "Optional:", "Top shelf:").
    Whether they name a thing of the scene is the caller's test.

    >>> heading_words("Warm-up set"), heading_words("Clean the table"), heading_words("Optional")
    (True, False, False)
    """
    words = re.findall(r"[a-z]+", label.lower().replace("'s", ""))
    if not words or len(re.findall(r"[\w'-]+", label)) > 3:
        return False
    return all(w not in _not_in_heading() and english_word(american(w)) and not _says_how(w) for w in words)


@lru_cache(maxsize=1)
def _not_in_heading() -> frozenset[str]:
    """The words a heading never holds: `_NOT_IN_HEADING`, `frame_keeps.txt`'s (they add, hedge, say a
    time or a place: "Optional:", "Top shelf:") and `voice_remarks.txt`'s `never_heading` ("Done:")."""
    return _NOT_IN_HEADING | frame_keeps() | phrase_words("voice_remarks.txt", "never_heading")


# the readers' word kinds a heading may use as nouns ("Warm-up set", "Power cut"): things and actions; a
# count, order, negation, condition, time or correction word is never a heading's
_NAMING_KINDS = ("verb_", "noun_", "implied_", "state_", "person")


def _says_how(word: str) -> bool:
    return any(word in ws for kind, ws in vocabulary().items() if not kind.startswith(_NAMING_KINDS))
