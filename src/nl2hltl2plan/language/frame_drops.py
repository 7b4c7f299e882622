"""The sentences, labels, leading and closing phrases that name nothing a task needs, dropped by one rule
for the tabletop and household readers (`handover_discourse.empty`, `frame_filler`, h235; the handover
reader applies the same rule sentence by sentence itself).

A reader passes the words that name its world's things (`names`: never dropped) and gets the text back
without its frame, each fragment only the general filler rule drops added to `dropped` (shown in the
result's notes by `frame_filler.frame_note`). A household note may also say when the whole request is for
(`times`): a fragment set off from the request whose only words that keep it are time words
(`request_times`, the one reader of the time a request is for: "for Friday", "Tonight: ...", "Today,
please.", "by 5") orders nothing and is dropped too, unless it holds an order word ("before Friday", "until
tomorrow", "first thing tomorrow"), which `empty` never drops, or is a later day at the end of a request
("..., tomorrow": a start, which `request_times` refuses). With `times`, a statement that sets the scene or
tells of an event ("Tenant away until Monday.") is dropped too, and a reference's abbreviation ("no. 7", "p.
14") is said in full first (`frame_remarks`, h279).

>>> frames_dropped("Today, please. Put the mug in the sink.", frozenset({"mug", "sink"}), [], times=True)
'Put the mug in the sink.'
>>> frames_dropped("Before Friday, put the mug in the sink.", frozenset({"mug", "sink"}), [], times=True)
'Before Friday, put the mug in the sink.'
"""

from __future__ import annotations

import re
from collections.abc import Callable

from nl2hltl2plan.language.content_words import Unread, categories
from nl2hltl2plan.language.frame_filler import Dropped
from nl2hltl2plan.language.frame_remarks import references_in_full, scene_remark
from nl2hltl2plan.language.handover_discourse import (
    empty,
    frame_gone,
    heads_dropped,
    tails_dropped,
    unsigned,
    writer_name,
)
from nl2hltl2plan.language.request_times import timed_frame, times_dropped
from nl2hltl2plan.language.spelling import english_word, known_word

# not after a list's number ("1. Carrot ..."); after "!!" or "?!" too (h295)
_SENTENCE_END = re.compile(r"(?<=[A-Za-z][.!?])\s+|(?<=[!?][.!?])\s+")
# a record's kind and number opening the text ("Level 1:", "Cabin 4,"): a header unless the kind numbers
# another part of the text too ("Task 1: ... Task 2: ...": the steps' labels)
_NUMBERED = re.compile(r"^\s*(?:[A-Za-z]+\s+){0,2}?([A-Za-z]+)\s+(?:no\.?\s+|number\s+)?#?\d+\b")


def frames_dropped(
    text: str,
    names: frozenset[str],
    dropped: list[str] | None = None,
    times: bool = False,
    closing_thing: Callable[[str], bool] | None = None,
) -> str:
    """`text` without the sentences, labels, leading and closing phrases that name nothing a task needs
    (`handover_discourse.empty`, the world's `names` as content words): "Breathe in, friends.", "Campers,
    ...", "..., buddies!", "Carrot duty: the carrot goes ..."; with `times`, also those that only say when
    the request is for (see the module docstring). What only the general filler rule drops is added to
    `dropped` (a time fragment too); what the lists alone find empty is left to each reader's own policy
    for greetings and thanks (`courtesy.without_greetings`): dropping it here would drop, unsaid, the
    words the readers read ("First, though, ...", "Oh, and also ..."). With `closing_thing` (the reader's own
    test of a thing), a closing thing's name it passes is taken out, for the reader to name it unread."""
    seen = Dropped(dropped, names, only_general=True)
    # (the household's references, "Recipe card no. 7", "p. 14": said in full, h279)
    sentences = _SENTENCE_END.split((references_in_full(text) if times else text).strip())
    # "Night, Mug": a sign-off before a thing's name stays whole, to be refused by name (`thing_signed`);
    # with `closing_thing` (the reader's own test of a thing, which names it unread) it is taken out here
    thing = closing_thing or (lambda name: name.lower() in names)
    kept = sentences.pop() if _thing_sign_off(sentences, thing) else None
    # "Night, Bo": a sign-off and its writer's name, both (said after what the sentences before drop)
    signed: list[str] | None = None if dropped is None else []
    sentences = unsigned(sentences, seen._replace(dropped=signed))
    # a word alone closing the message ("... plate. Namaste.", "... GG.", "... lamp. Bo"): a sign-off or its
    # writer's name, no word a reader or English knows (mid-message, a name alone may be a command's object:
    # it stays; an English word, "Sequentially.", "Pause.", "Matters.", may say something: it stays too)
    word = sentences[-1].strip(" .!") if len(sentences) > 1 else ""
    if _unknown_name(word, names) or _led_name(sentences, names):
        sentences.pop()
        if signed is not None:
            signed.append(word)
    # the same word called after a request's comma ("Put the apple in the fridge, Bo."): who is asked
    sentences = [_uncalled(sentence, names, signed) for sentence in sentences]
    kind = _NUMBERED.match(sentences[0]) if sentences else None
    again = kind is not None and re.search(rf"\b{kind[1]}\s+#?\d", text[kind.end() :], re.IGNORECASE)
    out = []
    for k, sentence in enumerate(sentences):
        header = k == 0 and not again
        if frame_gone(sentence, seen, whole=True, header=header):
            continue
        # (a statement that sets the scene or tells of an event, beside a request: "Tenant away until
        # Monday.", h279; the household's, whose content words `scene_remark` knows)
        remark = times and len(sentences) > 1 and scene_remark(sentence, names)
        if remark or times and timed_frame(sentence, names, whole=True, header=header):
            if dropped is not None:
                dropped.append(sentence.strip(" ,.!?;:"))
            continue
        # (a phrase dropped between commas leaves one comma: "First, though, ..." is "First, ...")
        said = re.sub(r",\s*,", ",", tails_dropped(heads_dropped(sentence, header, seen), seen)).strip()
        if times:
            said = tails_dropped(heads_dropped(times_dropped(said, seen), header, seen), seen).strip()
        if said != sentence.strip() and frame_gone(said, seen, whole=True, header=header):
            continue  # what is left of it is frame too ("Campers, gather round!": "gather round!")
        end = sentence.rstrip()[-1:]
        out.append(said + end if end in ".!?" and not said.endswith(end) else said)
    if dropped is not None and signed:
        dropped.extend(signed)
    return " ".join(s for s in [*out, "" if closing_thing is not None else kept or ""] if s)


def _unknown_name(word: str, names: frozenset[str]) -> bool:
    """Whether `word` is a capitalised name that neither the reader's lists nor English know ("Bo", "Namaste";
    not "Sequentially", "Pause", "Mug")."""
    low = word.lower()
    known = known_word(low) or bool(categories(low)) or english_word(low)
    return word[:1].isupper() and word.isalpha() and not known and writer_name(word.capitalize(), names)


def _led_name(sentences: list[str], names: frozenset[str]) -> bool:
    """Whether the last of several sentences is a writer's name (`_unknown_name`) after a short lead the
    sign-off lists lack and that names no thing ("Later, Bo", "See you later, Priya", h307): nothing follows
    to be ordered, so the lead orders nothing."""
    m = _closing_signed(sentences)
    if m is None or not m["off"] or not _unknown_name(m["name"], names):
        return False
    return _short_lead(m["off"].lower().split(), lambda w: w in names)


# a word called after a comma where a sentence ends ("..., Bo.", "..., Kit!")
_CALLED_AFTER = re.compile(r"\s*,\s*(?P<name>[A-Za-z]+)\s*(?P<end>[.!]*)\s*$")


def _uncalled(sentence: str, names: frozenset[str], dropped: list[str] | None) -> str:
    """The sentence without a name called after its last comma, where a request comes before it (a name
    alone is a sentence of its own, above); the name goes to `dropped`."""
    m = _CALLED_AFTER.search(sentence)
    if m is None or not _unknown_name(m["name"], names) or len(sentence[: m.start()].split()) < 2:
        return sentence
    if dropped is not None:
        dropped.append(m["name"])
    return sentence[: m.start()] + m["end"]


# a closing sentence of a sign-off and a name after its comma ("Night, Mug", "Peace, The Box"), or of a
# capitalised name alone ("Bread.")
_SIGNED = re.compile(r"\s*(?:(?P<off>[^,]+?)\s*,\s*)?(?P<name>(?:The\s+)?[A-Z][a-z]+)\W*")
_CLOSING_LEAD_WORDS = 3  # "See you later, Kettle": a salutation or an order word before the name


def _closing_signed(sentences: list[str]) -> re.Match[str] | None:
    """The last of several sentences as a sign-off and a name, or a name alone (`_SIGNED`)."""
    return _SIGNED.fullmatch(sentences[-1]) if len(sentences) > 1 else None


def _short_lead(words: list[str], names_a_thing: Callable[[str], bool]) -> bool:
    """Whether the words before a closing name are a short lead that names no thing ("Later", "See you
    later")."""
    return len(words) <= _CLOSING_LEAD_WORDS and not any(names_a_thing(w.strip(".!")) for w in words)


def _thing_sign_off(sentences: list[str], names_a_thing: Callable[[str], bool]) -> bool:
    """Whether the last of several sentences is one capitalised name that names a thing (`names_a_thing`),
    alone or after a sign-off the frame rule drops ("Night", "Peace", "Okay") or any short lead that names
    no thing ("Later", "See you later": an order word, h307): a writer's name or one more item, verbless
    either way, so never read as a second task (a lowercase "the bread too" asks one)."""
    m = _closing_signed(sentences)
    if m is None or not names_a_thing(m["name"].split()[-1]):  # ("The Mug": the mug)
        return False
    off = m["off"] or ""
    return not off or empty(off, edge=True, outer=True) or _short_lead(off.split(), names_a_thing)


def thing_signed(text: str, names_a_thing: Callable[[str], bool]) -> list[Unread]:
    """A closing sign-off before a name that is also a thing, named unread as `courtesy_unread` names
    "Thanks, Mug": a writer's name or one more item, no reading can tell ("Night, Mug", h299).

    >>> [u.words for u in thing_signed("Put the egg in the fridge. Night, Mug", lambda name: name == "Mug")]
    ['Night, Mug']
    """
    sentences = _SENTENCE_END.split(text.strip())
    if not _thing_sign_off(sentences, names_a_thing):
        return []
    return [Unread(sentences[-1].strip(" .!"), "object", CLOSING_THING_WHY)]


CLOSING_THING_WHY = (
    "a closing name that is also a thing, with nothing asked of it (a writer's name or one more item?): "
    "say the thing in a request of its own"
)
