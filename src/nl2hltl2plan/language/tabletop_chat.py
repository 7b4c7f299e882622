"""Chat forms in the tabletop world (issue 28): how people write to a robot in a chat window.

Read before any reader sees the text (`TabletopReader.as_read`), each as the plain words it stands for:

- "(any / whatever) order you find convenient / easiest" is "order you like" (the shared free-order phrase):
  the "find" of a leave is no action;
- "when / once / after both are on it": "it" is the plate just named, read as "there" ("once both are
  there"), which the readers resolve to it;
- a greeting, an agent's reply, a closing thanks and a sign-off with a name that is no object or plate
  ("Hi there, ... Cheers, Ana", "Hey, when you're done, ...") are removed as in every reader, by one
  policy (`courtesy.without_greetings`);
- a verb the system has no word for before "them" and a free order ("Book them in any sequence", "Stamp
  them in whatever order") restates the job: "do them in any sequence" (h262); a word used so, at a
  clause's start, is no thing ("book" names no Book there);
- "once that plate's ready / is full" (the plate just named, done) is "once they're all there" (h262; the
  words of done are `tabletop_chat.txt`'s `ready`);
- "once both have arrived / boarded" (what was put, said as having arrived) is "once they're all there"
  (h267; `tabletop_chat.txt`'s `arrived`);
- "once you've got them both in there" (the one asked having placed them) is "once they're both there"
  (h229; `tabletop_chat.txt`'s `yours`);
- a thing taken up again by a pronoun after a comma ("the orange, that one can go in the yellow plate") is
  the subject itself ("the orange can go in the yellow plate"; h229): the pronouns and the verbs after them
  are `tabletop_chat.txt`'s `resumptive` and `goes`;
- a label that names the document and opens the text ("Puzzle #1:", "Exercise 2.", "Rules of play:") is
  removed where it labels nothing else in the text (the frame lists' `record` and `title`);
- a sentence, leading or closing phrase that names nothing a task needs ("Breathe in, friends.", "Campers,
  ...", "..., buddies!", "Yo chat, level 1: ...") and a label that says again its sentence's names
  ("Carrot duty: the carrot goes ...") are removed by every reader's general filler rule
  (`frame_drops.frames_dropped`: `handover_discourse.empty`, `frame_filler`, h235), and said in the
  result's notes.

Chat shorthand ("n" for "and", "u" for "you") is read before, in every world (`spelling.shorthand_read`).
The words of a leave are `tabletop_chat.txt`'s.

>>> chat_read("Hi, can you put the orange on the blue plate? Thanks!", {"blue plate": True})
'can you put the orange on the blue plate?'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import free_order_phrase, phrase_list_pattern, vocabulary
from nl2hltl2plan.language.courtesy import without_greetings
from nl2hltl2plan.language.frame_drops import frames_dropped
from nl2hltl2plan.language.handover_discourse import frame_words
from nl2hltl2plan.language.request_times import deadlines_dropped
from nl2hltl2plan.language.spelling import english_lemmas
from nl2hltl2plan.language.tabletop_wording import mention_pattern

_FIND = re.compile(
    rf"\b(?P<order>order|ordering|sequence)\s+(?:that\s+)?you\s+find\s+(?:it\s+)?"
    rf"{phrase_list_pattern('tabletop_chat.txt', 'easy')}\b",
    re.IGNORECASE,
)
# "when both are on it": "it" is the plate just named, as "there" says it ("once both are there")
_ON_IT = re.compile(
    r"\b(?P<head>(?:when|once|after|as soon as)\s+(?:both|they|those|these|the two|all)(?:\s+of them)?\s+"
    r"(?:are|have been|'re|are both|are all)\s+)(?:on|in|onto)\s+it\b",
    re.IGNORECASE,
)
# "once you've got them both in there": what the one asked has placed, said as the things being there
_YOURS = re.compile(
    rf"\b(?P<head>when|once|after|as soon as)\s+{phrase_list_pattern('tabletop_chat.txt', 'yours')}\s+"
    r"(?:them|those|these|the two)(?:\s+(?P<all>both|all))?\s+(?:in|on|onto)\s+(?:there|it)\b",
    re.IGNORECASE,
)

# a verb at a clause's start, before the things said as a pronoun and a free order ("Book them in any
# sequence"): the job said in the voice's words
_RESTATED = re.compile(
    rf"(?:^|(?<=[.!?;,]\s))(?P<verb>[A-Za-z]+)(?=\s+(?:them|these|those|the\s+lot)(?:\s+(?:all|both))?\s+"
    rf"(?:{free_order_phrase('adverb')})\b)",
    re.IGNORECASE,
)

# "..., either one first.": the stage's free order, said as "in either order" (`first_pick`)
_FIRST_PICK = re.compile(
    rf",\s*{phrase_list_pattern('tabletop_chat.txt', 'first_pick')}(?=\s*[.;!?])", re.IGNORECASE
)


def _restated(m: re.Match[str], names: frozenset[str]) -> str:
    """ "do" for a verb that names no action of the system (no word of `content_words.txt`) nor a word of
    the world's names; the verb as it is otherwise ("Remove them in any order", "Check them ...")."""
    verb = m["verb"].lower()
    if verb in names or any(verb in words for words in vocabulary().values()):
        return m[0]
    return "do" if "VERB" in english_lemmas(verb) else m[0]


# "once that plate's ready": the plate just named, with what was put on it, done
_PLATE_READY = re.compile(
    rf"\b(?P<head>when|once|after|as soon as)\s+(?:that|this)\s+plate(?:'s|\s+is|\s+has\s+been)\s+"
    rf"{phrase_list_pattern('tabletop_chat.txt', 'ready')}\b",
    re.IGNORECASE,
)
# "once both have arrived": what was put, there
_ARRIVED = re.compile(
    r"\b(?P<head>when|once|after|as soon as)\s+(?:both|they|those|these|the two|all)"
    r"(?:\s+of\s+(?:them|those))?"
    rf"\s+(?:have|'ve)\s+(?:both\s+|all\s+)?{phrase_list_pattern('tabletop_chat.txt', 'arrived')}\b",
    re.IGNORECASE,
)

# "the orange, that one can go ...": the thing taken up again by a pronoun
_RESUMED = (
    rf",\s+{phrase_list_pattern('tabletop_chat.txt', 'resumptive')}\s+"
    rf"(?={phrase_list_pattern('tabletop_chat.txt', 'goes')}\b)"
)


def _resumed(text: str, kinds: dict[str, bool]) -> str:
    things = [name for name, plate in kinds.items() if not plate]
    if not things:
        return text
    return re.sub(rf"({mention_pattern(things).pattern}){_RESUMED}", r"\1 ", text, flags=re.IGNORECASE)


def _pattern(words: frozenset[str]) -> str:
    return "|".join(sorted((w.replace("_", r"\s+") for w in words), key=len, reverse=True))


# a label that names the document and opens the text: a record's kind with its number ("Puzzle #1:",
# "Exercise 2.", "Agenda item 2 -") or a game's title ("Rules of play:"): the frame lists'
# `record` and `title` (h220); a kind that labels another part of the text ("Task 1: ... Task 2: ...") is
# a step's label, left to the step readers
_DOCUMENT = re.compile(
    rf"^\s*(?:(?P<kind>{_pattern(frame_words()['record'])})\s+(?:no\.?\s+|number\s+)?#?\s*(?:\d+|[a-z])\b|"
    rf"(?:{_pattern(frame_words()['title'])}))\s*(?:[:.]|\s[-\u2013\u2014])\s+(?=\S)",
    re.IGNORECASE,
)


def _document_label_dropped(text: str) -> str:
    label = _DOCUMENT.match(text)
    if label is None or (label["kind"] and re.search(rf"\b{label['kind']}\b", text[label.end() :], re.I)):
        return text
    return text[label.end() :]


def chat_read(text: str, kinds: dict[str, bool], dropped: list[str] | None = None) -> str:
    """`text` with its chat forms read as plain words (see the module docstring); `kinds`: each object or
    plate name in words -> is it a plate (a sign-off's name that is a word of one stays); what the general
    filler rule drops is added to `dropped`."""
    names = frozenset(w for name in kinds for w in name.lower().split())
    # a deadline by an outside event ("Before the gates open, ...") is met by doing the tasks now, as in
    # a household request (`request_times`); the phrase is said with the frames
    said: list[str] = [] if dropped is None else dropped
    text = deadlines_dropped(text, names, said, said)
    text = frames_dropped(_document_label_dropped(text), names, dropped)
    text = _FIRST_PICK.sub(", in either order", _FIND.sub(lambda m: f"{m['order']} you like", text))
    text = _RESTATED.sub(lambda m: _restated(m, names), text)
    text = _YOURS.sub(lambda m: f"{m['head']} they're {m['all'] or 'all'} there", text)  # "in there": there
    text = _ON_IT.sub(r"\g<head>there", text)
    text = _PLATE_READY.sub(r"\g<head> they're all there", text)
    text = _ARRIVED.sub(r"\g<head> they're all there", text)
    text = _resumed(text, kinds)
    return without_greetings(text, lambda name: any(name.lower() in said.split() for said in kinds))
