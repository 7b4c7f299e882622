"""The sentences, labels, leading and closing phrases that name nothing a task needs, dropped by one rule
for the tabletop and household readers (`handover_discourse.empty`, `frame_filler`, h235; the handover
reader applies the same rule sentence by sentence itself).

A reader passes the words that name its world's things (`names`: never dropped) and gets the text back
without its frame, each fragment only the general filler rule drops added to `dropped` (shown in the
result's notes by `frame_filler.frame_note`). A household note may also say when the whole request is for
(`times`): a fragment set off from the request whose only words that keep it are time words
(`frame_times.txt`: "for Friday", "tomorrow", "Today, please.", "by 5") orders nothing and is dropped too,
unless it holds an order word ("before Friday", "until tomorrow", "first thing tomorrow"), which `empty`
never drops.

>>> frames_dropped("Today, please. Put the mug in the sink.", frozenset({"mug", "sink"}), [], times=True)
'Put the mug in the sink.'
>>> frames_dropped("Before Friday, put the mug in the sink.", frozenset({"mug", "sink"}), [], times=True)
'Before Friday, put the mug in the sink.'
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import word_categories
from nl2hltl2plan.language.frame_filler import Dropped
from nl2hltl2plan.language.handover_discourse import empty, frame_gone, heads_dropped, tails_dropped

_SENTENCE_END = re.compile(r"(?<=[A-Za-z][.!?])\s+")  # not after a list's number ("1. Carrot ...")
# a record's kind and number opening the text ("Level 1:", "Cabin 4,"): a header unless the kind numbers
# another part of the text too ("Task 1: ... Task 2: ...": the steps' labels)
_NUMBERED = re.compile(r"^\s*(?:[A-Za-z]+\s+){0,2}?([A-Za-z]+)\s+(?:no\.?\s+|number\s+)?#?\d+\b")


@lru_cache(maxsize=1)
def _time() -> re.Pattern[str]:
    words = {kind: "|".join(sorted(ws)) for kind, ws in word_categories("frame_times.txt").items()}
    when = rf"(?:{words['when']}|{words['part']})s?"
    return re.compile(
        rf"\b(?:(?:{words['opener']})\s+)?(?:(?:the|this|next|last(?=\s+(?:{words['part']})))\s+)?{when}(?:\s+{when})*\b"
        rf"|\bby\s+\d{{1,2}}(?:[:.]\d\d)?\s*(?:am|pm|o'?clock)?(?=\s*(?:[,.!?;:]|$|please\b|{when}\b))",
        re.IGNORECASE,
    )


def _untimed(fragment: str) -> str:
    """The fragment without its time phrases ("for Friday", "tomorrow morning", "by 5")."""
    return _time().sub(" ", fragment)


# a leading or closing phrase set off by a comma, a colon or a dash
_LEAD = re.compile(r"^\s*([^,:;.!?]{1,40}?)\s*(,|:|\s[-–—]+\s)\s*(?=\S)")
_TAIL = re.compile(r"(?:,|\s[-–—]+)\s*([^,:;.!?]{1,40}?)\s*(?=[.!?]*\s*$)")


def _timed_frame(fragment: str, names: frozenset[str], **where: bool) -> bool:
    """Is the fragment frame once its time phrases are read as frame (it holds one, and nothing else that
    keeps it)?"""
    untimed = _untimed(fragment)
    return untimed != fragment and empty(untimed.strip(" ,.!?"), names=names, **where)


def _times_dropped(sentence: str, seen: Dropped) -> str:
    """The sentence without the leading and closing phrases that only say when the request is for."""
    while (head := _LEAD.match(sentence)) and _timed_frame(
        head[1], seen.names, edge=True, outer=True, label=head[2] != ","
    ):
        if seen.dropped is not None:
            seen.dropped.append(head[1].strip())
        sentence = sentence[head.end() :]
    if (tail := _TAIL.search(sentence)) and _timed_frame(tail[1], seen.names, edge=True):
        if seen.dropped is not None:
            seen.dropped.append(tail[1].strip())
        sentence = sentence[: tail.start()] + sentence[tail.end() :]
    return sentence


def frames_dropped(
    text: str, names: frozenset[str], dropped: list[str] | None = None, times: bool = False
) -> str:
    """`text` without the sentences, labels, leading and closing phrases that name nothing a task needs
    (`handover_discourse.empty`, the world's `names` as content words): "Breathe in, friends.", "Campers,
    ...", "..., buddies!", "Carrot duty: the carrot goes ..."; with `times`, also those that only say when
    the request is for (see the module docstring). What only the general filler rule drops is added to
    `dropped` (a time fragment too); what the lists alone find empty is left to each reader's own policy
    for greetings and thanks (`courtesy.without_greetings`): dropping it here would drop, unsaid, the
    words the readers read ("First, though, ...", "Oh, and also ...")."""
    seen = Dropped(dropped, names, only_general=True)
    sentences = _SENTENCE_END.split(text.strip())
    kind = _NUMBERED.match(sentences[0]) if sentences else None
    again = kind is not None and re.search(rf"\b{kind[1]}\s+#?\d", text[kind.end() :], re.IGNORECASE)
    out = []
    for k, sentence in enumerate(sentences):
        header = k == 0 and not again
        if frame_gone(sentence, seen, whole=True, header=header):
            continue
        if times and _timed_frame(sentence, names, whole=True, header=header):
            if dropped is not None:
                dropped.append(sentence.strip(" ,.!?;:"))
            continue
        # (a phrase dropped between commas leaves one comma: "First, though, ..." is "First, ...")
        said = re.sub(r",\s*,", ",", tails_dropped(heads_dropped(sentence, header, seen), seen)).strip()
        if times:
            said = tails_dropped(heads_dropped(_times_dropped(said, seen), header, seen), seen).strip()
        if said != sentence.strip() and frame_gone(said, seen, whole=True, header=header):
            continue  # what is left of it is frame too ("Campers, gather round!": "gather round!")
        end = sentence.rstrip()[-1:]
        out.append(said + end if end in ".!?" and not said.endswith(end) else said)
    return " ".join(s for s in out if s)
