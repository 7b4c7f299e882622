"""A sentence that sets the scene or tells of an event, and asks nothing (issue 28, h279): "Tenant away until
Monday.", "Doctor's round at 9.", "Photographer arrives at 3!", "The tavern falls silent as the robot walks
in.", "Visitors left at 8." A voice's frame, read by the household frame rule (`frame_drops`), which drops it
and says so in the assumptions.

Such a sentence is a statement: its subject is a noun, a name or a pronoun that is not the listener ("you",
"robot"), and what follows it is a form of "be", a possessive ("Doctor's round"), a verb in a finite form
("arrives", "left") or a word that says a state ("Patient asleep", "Seas calm"). It names no thing of the
world, holds no number but a clock time, and no word of a count, an order, a negation or a condition; a
time set off by "at", "until", "on" ... is the event's. An action word is said of someone else ("Landlord
inspects Friday"), never asked. A command ("Roll for initiative!", "Record observations."), a question, a
sentence with a thing ("Lights out at 10": the lamps) or an order ("Cue 8 goes first") stays, to be read or
refused by name. Words in `frame_remarks.txt`.
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import categories, word_categories
from nl2hltl2plan.language.request_times import ordinal_date
from nl2hltl2plan.language.spelling import american, english_lemmas, english_word


@lru_cache(maxsize=1)
def _words() -> dict[str, frozenset[str]]:
    return word_categories("frame_remarks.txt")


@lru_cache(maxsize=1)
def _time() -> re.Pattern[str]:
    """A time the event is at, with the word that sets it ("at 9", "until Monday", "7am", "0600 hours")."""
    w = _words()
    days = "|".join(sorted(w["day"]))
    clock = r"\d{1,2}(?:[:.]\d\d)?\s*(?:am|pm|o'?clock)?|\d{4}\s*(?:hours|hrs)?"
    clock = rf"{ordinal_date()}|{clock}"  # (a date by its ordinal: "the 14th", "night of the 3rd", h295)
    return re.compile(
        rf"(?:\b(?:{'|'.join(sorted(w['time_word']))})\s+)?(?:\b(?:this|next)\s+)?(?:{clock}|\b(?:{days})s?)\b",
        re.IGNORECASE,
    )


@lru_cache(maxsize=1)
def _abbreviations() -> tuple[re.Pattern[str], dict[str, str]]:
    full = dict(w.split("=") for w in _words()["abbreviation"])
    return re.compile(rf"\b({'|'.join(full)})\.\s*(?=#?\d)", re.IGNORECASE), full


def references_in_full(text: str) -> str:
    """`text` with a reference's abbreviation before its number said in full ("Recipe card no. 7" ->
    "Recipe card number 7", "p. 14" -> "page 14"): its "." ends no sentence, its "no" is no negation.

    >>> references_in_full("Ticket No. 7: see p. 14. No. Put it away.")
    'Ticket number 7: see page 14. No. Put it away.'
    """
    pattern, full = _abbreviations()
    return pattern.sub(lambda m: full[m[1].lower()] + " ", text)


_WORD = re.compile(r"[A-Za-z]+(?:['’][a-z]+)?")


def _subject(word: str, said: str, after: str) -> bool:
    """Whether `word` (as `said` in the text, `after` the word after it) may be a statement's subject: a
    noun, a name, or a pronoun of a third party; a noun that is also a verb's base form only before a
    form of "be" or a state ("Tenant away"), since it may open a command ("Record observations")."""
    if word in _words()["listener"]:
        return False
    if word in _words()["pronoun"] or said[:1].isupper() and not english_word(word):
        return True
    kinds = english_lemmas(american(word))
    if "NOUN" not in kinds:
        return False
    state = "NOUN" not in english_lemmas(american(after)) and _predicate(after)
    return word not in kinds.get("VERB", ()) or after in _words()["be"] or state


def _predicate(word: str) -> bool:
    """Whether `word`, after a subject, says what it is, does or did: "is", "'s", "arrives", "left",
    "asleep", "calm", "away"."""
    if word in _words()["be"]:
        return True
    kinds = english_lemmas(american(word))
    finite = not word.endswith("ing") and any(lemma != word for lemma in kinds.get("VERB", ()))
    return finite or bool({"ADJ", "ADV"} & set(kinds))


def _askless(word: str, names: frozenset[str], subject_done: bool) -> bool:
    """Whether the word names nothing a task could use: no thing, no count, order, negation or condition
    (`content_words`); an action word only in a finite form after the subject (said of someone else)."""
    if word in names or word.removesuffix("s") in names or word in _words()["kept"]:
        return False
    kinds = categories(word) - {"person", "person_relation", "time"}
    if not kinds:
        return True
    # (only its present tense, said of the subject: "is washed", "gets cleaned" ask for the task; a past
    # tense only of a step no task takes: "Max walked!" tells of what someone did, h295)
    verbs = all(k.startswith("verb_") for k in kinds)
    finite = any(lemma != word for lemma in english_lemmas(word).get("VERB", ())) and not word.endswith("ing")
    stepped = kinds == {"verb_step"} and not word.endswith("s")
    return verbs and finite and (word.endswith("s") or stepped) and subject_done


def scene_remark(sentence: str, names: frozenset[str]) -> bool:
    """Whether the whole sentence is a statement that sets the scene or tells of an event, naming nothing a
    task needs (see the module docstring).

    >>> none = frozenset()
    >>> scene_remark("Tenant away until Monday.", none), scene_remark("Roll for initiative!", none)
    (True, False)
    >>> scene_remark("Lights out at 10.", frozenset({"lights"})), scene_remark("Cue 8 goes first.", none)
    (False, False)
    """
    text = sentence.strip()
    if "?" in text or ":" in text:
        return False
    untimed = _time().sub(" ", text)
    if re.search(r"\d", untimed):
        return False
    said = [m[0].replace("’", "'") for m in _WORD.finditer(untimed)]
    words = [w.lower() for w in said]
    at = 0
    while at < len(words) and words[at] in _words()["determiner"]:
        at += 1
    if at >= len(words) - 1:
        return False
    head, after = words[at].split("'")[0], words[at + 1].split("'")[0]
    possessive = words[at].endswith("'s") and words[at] not in ("it's", "that's")  # "Doctor's round"
    if not (possessive and english_word(head) or _subject(head, said[at], after)):
        return False
    # (a plural subject takes the verb's base form: "Guests arrive at 6")
    plural = any(lemma != head for lemma in english_lemmas(american(head)).get("NOUN", ()))
    if not (possessive or _predicate(after) or plural and "VERB" in english_lemmas(american(after))):
        return False
    return all(_askless(w.split("'")[0], names, subject_done=k > at) for k, w in enumerate(words))
