"""The time a household request is for (issues 28 and 23, h258). A leading phrase that sets a deadline by
a time, an occasion or an outside event ("Before I'm back, ...", "By the time the kids get back, ...",
"Ahead of the weekend, ...") is met by doing the tasks now: it is dropped and said in the notes. A start
time or a wait on an outside event ("Wait until I'm home, then ...", "At 5 pm, ...") cannot be honoured
by a plan made now: it is refused by name (`starts_unread`), whatever else reads it. Words in
`request_times.txt`; a subject that names a thing of the world ("once the mug is clean") is never an
outside event, and "you" never is (the request's own task: "before you put it away"), but in a deadline where
it only leaves ("Before you leave, ...", "Before you move out (kitchen): ...", h278). The time words set off
from the request that only say when it is for (`frame_times`, `times_dropped`: "for Friday", "Tonight: ...",
"Today, please.", h244) are frame, read by the household's frame rule (`frame_drops`); a later day set off at
the end of a request with no deadline's opener ("..., tomorrow", "..., on Friday", h273) is no frame but a
start, refused by name.

>>> deadlines_dropped("Before I'm back, put the mug in the sink.", frozenset({"mug", "sink"}), [], [])
'put the mug in the sink.'
>>> deadlines_dropped("Before you put the mug away, wash it.", frozenset({"mug"}), [], [])
'Before you put the mug away, wash it.'
>>> deadlines_dropped("Before you leave (hall): wash the mug, before you head out.", frozenset(), [], [])
'wash the mug.'
>>> deadlines_dropped("Thanks again for last week. This time could you wash it?", frozenset(), [], [])
'could you wash it?'
>>> [u.words for u in starts_unread("Wait until I'm home, then wash the mug.", frozenset({"mug"}))]
["Wait until I'm home"]
>>> [u.words for u in later_days_unread("Put the mug in the sink, tomorrow. Thanks, see you tonight!")]
['tomorrow']
>>> [u.words for u in later_days_unread("Put the mug in the sink, by tomorrow.")]
[]
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import Unread, categories, word_categories
from nl2hltl2plan.language.frame_filler import Dropped
from nl2hltl2plan.language.handover_discourse import empty


def _any(words: frozenset[str]) -> str:
    return "|".join(sorted((w.replace("_", r"\s+") for w in words), key=len, reverse=True))


@lru_cache(maxsize=1)
def _words() -> dict[str, frozenset[str]]:
    """`request_times.txt`, read once (`_outside` asks for its things at every phrase matched)."""
    return word_categories("request_times.txt")


@lru_cache(maxsize=1)
def _phrases() -> tuple[re.Pattern[str], re.Pattern[str]]:
    """(a leading deadline phrase, a start phrase), each with its outside subject as group `who`."""
    w = _words()
    when = rf"(?:(?:the|this|next|tonight'?s?)\s+)?(?:{_any(w['today'] | w['when'] | w['part'])})s?"
    clock = r"\d{1,2}(?:[:.]\d\d)?\s*(?:am|pm|o'?clock)\b|noon|midnight"
    occasion = rf"(?:(?:the|my|our|your|a)\s+)?(?:{_any(w['occasion'])})(?:\s+{when})?"
    who = r"(?P<who>i|we|he|she|(?:the\s+|my\s+|our\s+)?[a-z]+(?:\s+[a-z]+)?)"
    being = r"(?:'m|'re|'s|\s+am|\s+are|\s+is|\s+gets?|\s+comes?|\s+get\s+back)"
    verb = rf"(?P<verb>{_any(w['event'] | w['leaving'])})"
    event = rf"{who}(?:{being}\s+(?:{_any(w['back'])})\b|\s+{verb}\b)"
    what = rf"(?:{event}|{when}|{occasion}|{clock})"
    lead = rf"(?:(?:{_any(w['lead'])})\s+)?"
    # (after the phrase: "for the night", or a room in brackets, "Before you move out (kitchen):")
    rest = r"(?:\s+for\s+the\s+(?:day|night|weekend))?(?:\s*\([^()]{1,40}\))?\s*"
    deadline = rf"^\s*{lead}(?P<phrase>(?:{_any(w['deadline'])})\s+{what}){rest}(?:,|:|\s[-–—]+\s)\s*(?=\S)"
    at = r"(?:^|(?<=[.!?;:]\s)|(?<=\bthen\s))\s*"  # a sentence's or a "then" clause's start
    start = rf"{at}(?P<phrase>(?:{_any(w['start'])})\s+{what})(?=\s*[,.;:!?]|\s+then\b)"
    return re.compile(deadline, re.IGNORECASE), re.compile(start, re.IGNORECASE)


@lru_cache(maxsize=1)
def _closing_leave() -> re.Pattern[str]:
    """A closing deadline of the request's own "you" leaving (h278): "..., before you leave.", "... before
    you head out, please!" (met now, as a leading one is)."""
    phrase = rf"(?P<phrase>(?:before|by\s+the\s+time)\s+you\s+(?:{_any(_words()['leaving'])}))"
    tail = r"(?:\s+for\s+the\s+(?:day|night))?(?:\s*,?\s*please)?(?=\s*[.!]*\s*$)"
    return re.compile(rf"\s*,?\s+{phrase}{tail}", re.I)


@lru_cache(maxsize=1)
def _remarks() -> tuple[re.Pattern[str], re.Pattern[str]]:
    """(a sentence that thanks for a past time, a leading remark on the occasion before a request)."""
    w = _words()
    thanks = r"^\s*(?:thanks|thank\s+you)(?:\s+(?:again|so\s+much))*\s+for\s+"
    thanks += rf"(?:{_any(w['past'])})\s*[.!]*\s*$"
    asking = r"(?=(?:could|can|would|will)\s+you\b|please\b)"
    return re.compile(thanks, re.IGNORECASE), re.compile(rf"^\s*(?:{_any(w['remark'])})\s+{asking}", re.I)


def _outside(m: re.Match[str], names: frozenset[str], leaves: bool = False) -> bool:
    """Is the phrase's subject (if it has one) no thing of the world, none said before ("they") and not
    the request's own "you"? With `leaves` (a deadline), "you" that only leaves is ("before you leave")."""
    who = set((m["who"] or "").lower().split())
    if leaves and who == {"you"}:
        return "_".join((m["verb"] or "").lower().split()) in _words()["leaving"]
    return not (who & (names | _words()["thing"] | {"you"}))


def deadlines_dropped(text: str, names: frozenset[str], said: list[str], frames: list[str]) -> str:
    """`text` without each sentence's leading deadline phrase (added to `said`) and the remarks on a past
    time or the occasion (added to `frames`: "Thanks again for last week.", "This time could you ...")."""
    deadline, _ = _phrases()
    thanks, remark = _remarks()
    out = []
    for sentence in re.split(r"(?<=[.!?])\s+", text.strip()):
        if thanks.match(sentence):
            frames.append(sentence.strip(" .!"))
            continue
        if said_first := remark.match(sentence):
            frames.append(said_first[0].strip())
            sentence = sentence[said_first.end() :]
        if (m := deadline.match(sentence)) and _outside(m, names, leaves=True):
            said.append(sentence[: m.end()].strip(" ,:-–—"))
            sentence = sentence[m.end() :]
        if closing := _closing_leave().search(sentence):
            said.append(closing["phrase"])
            sentence = sentence[: closing.start()] + sentence[closing.end() :]
        out.append(sentence)
    return " ".join(out)


def deadline_note(said: list[str]) -> str:
    return "done now: " + ", ".join(f"{p!r} is met" for p in dict.fromkeys(said))


def starts_unread(instruction: str, names: frozenset[str]) -> list[Unread]:
    """Each start time or wait on an outside event the instruction says ("after lunch", "at 5 pm", "once
    the guests leave", "wait until I'm home")."""
    _, start = _phrases()
    why = "no base task waits for a time or an outside event: a plan made now cannot honour it"
    return [Unread(m["phrase"], "time", why) for m in start.finditer(instruction) if _outside(m, names)]


def later_days_unread(text: str) -> list[Unread]:
    """Each later day set off at the end of a request ("..., tomorrow", "..., on Friday"; h273), read
    before the frame rule reads it off (`times_dropped`)."""
    why = "no base task waits for a later day: a plan made now cannot be done then; say 'by' for a deadline"
    wait = "no base task waits for a time: a plan made now is done now; say what to do now"
    days = (closing_later_day(s) for s in re.split(r"(?<=[.!?;])\s+", text.strip()))
    return [Unread(day, "time", wait if day.lower().startswith("in ") else why) for day in days if day]


# --- the time words that only say when a whole request is for (h244's frame times) ---


@lru_cache(maxsize=1)
def ordinal_date() -> str:
    """A date said by its ordinal ("the 14th", "night of the 3rd", "the 5th of May"; h295): a time, never a
    count of things or a thing (the nightstand of "night of the 14th"), as a regular expression."""
    w = {kind: "|".join(sorted(ws)) for kind, ws in _words().items()}
    return rf"\b(?:(?:{w['part']})\s+of\s+)?the\s+\d{{1,2}}(?:st|nd|rd|th)(?:\s+of\s+(?:{w['month']}))?\b"


@lru_cache(maxsize=1)
def _time() -> re.Pattern[str]:
    w = {kind: "|".join(sorted(ws)) for kind, ws in _words().items()}
    when = rf"(?:{w['today']}|{w['when']}|{w['part']})s?"
    return re.compile(
        rf"\b(?:(?:{w['opener']}|of)\s+)?{ordinal_date()}|"
        rf"\b(?:(?:{w['opener']})\s+)?(?:(?:the|this|next|last(?=\s+(?:{w['part']})))\s+)?{when}(?:\s+{when})*\b"
        rf"|\bby\s+\d{{1,2}}(?:[:.]\d\d)?\s*(?:am|pm|o'?clock)?(?=\s*(?:[,.!?;:]|$|please\b|{when}\b))",
        re.IGNORECASE,
    )


@lru_cache(maxsize=1)
def _closing_later() -> re.Pattern[str]:
    """A later day (no deadline's "for" or "by") set off at the end of a sentence: "..., tomorrow.",
    "..., on Friday", "- tonight!", "..., next week, please."; or a short wait closing it ("... in a
    bit.")."""
    w = {kind: _any(ws) for kind, ws in _words().items()}
    later = rf"(?:(?:on|this|next)\s+)?(?:{w['when']})s?(?:\s+(?:{w['part']}))?|next\s+(?:{w['part']})"
    closing = rf"(?:(?:,|\s[-–—]+)\s*(?P<day>{later})|\s*,?\s+(?P<wait>{w['delay']}))"
    closing += r"(?:\s*,?\s*please)?\s*[.!?;]*\s*$"
    return re.compile(closing, re.IGNORECASE)


def closing_later_day(sentence: str) -> str | None:
    """The later day said at the end of a request (a sentence with a verb) as when to do it ("Put the mug
    away, tomorrow."): a start a plan made now cannot honour, never frame (h273)."""
    m = _closing_later().search(sentence)
    # (after a heading that asks nothing, "Chore chart, Saturday.", the day is the note's: frame)
    said = re.findall(r"[a-z]+", sentence[: m.start()].lower()) if m else []
    asked = any(c.startswith("verb_") for w in said for c in categories(w))
    return (m["day"] or m["wait"]) if m and asked else None


def _untimed(fragment: str) -> str:
    """The fragment without its time phrases ("for Friday", "tomorrow morning", "by 5")."""
    return _time().sub(" ", fragment)


# a leading or closing phrase set off by a comma, a colon or a dash
_LEAD = re.compile(r"^\s*([^,:;.!?]{1,40}?)\s*(,|:|\s[-–—]+\s)\s*(?=\S)")
_TAIL = re.compile(r"(?:,|\s[-–—]+)\s*([^,:;.!?]{1,40}?)\s*(?=[.!?]*\s*$)")


def timed_frame(fragment: str, names: frozenset[str], **where: bool) -> bool:
    """Is the fragment frame once its time phrases are read as frame (it holds one, and nothing else that
    keeps it)? (`where` as `handover_discourse.empty`'s: `whole`, `header`, `edge`, `outer`, `label`.)"""
    untimed = _untimed(fragment)
    return untimed != fragment and empty(untimed.strip(" ,.!?"), names=names, **where)


def times_dropped(sentence: str, seen: Dropped) -> str:
    """The sentence without the leading and closing phrases that only say when the request is for (each
    added to `seen.dropped`, but a closing later day, which `starts_unread` refuses)."""
    while (head := _LEAD.match(sentence)) and timed_frame(
        head[1], seen.names, edge=True, outer=True, label=head[2] != ","
    ):
        if seen.dropped is not None:
            seen.dropped.append(head[1].strip())
        sentence = sentence[head.end() :]
    if (tail := _TAIL.search(sentence)) and timed_frame(tail[1], seen.names, edge=True):
        # (a closing later day is read off too, so the request reads as said, but it is no frame: it is
        # not said as dropped, and `starts_unread` refuses it)
        if seen.dropped is not None and not closing_later_day(sentence):
            seen.dropped.append(tail[1].strip())
        sentence = sentence[: tail.start()] + sentence[tail.end() :]
    return sentence
