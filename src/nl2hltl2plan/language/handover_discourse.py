"""Discourse around a handover instruction's commands, made general: the fragments that carry nothing a
spec can use are dropped, and reported speech and first-person narration become the commands they report.

- A fragment (a whole sentence, a label before a colon, a phrase set off by a comma or dash at a sentence's
  start, by commas inside it or by a comma at its end: "then, robots, put ...") is dropped when it holds
  no content word at all (no block, place, arm letter, count, negation, order, time or placing verb:
  `MEANING`, `VERB`, `content_words.txt`) and every word of it is a function word or a frame word of
  `handover_frame_words.txt` (a greeting, an acknowledgement, a memo's or message's header, "today's", a
  radio call, a filler, a cheer, a sign-off) or general English filler (`filler`, h235: a word English
  uses as more than a noun, outside a thing's or place's phrase; a noun only where it addresses the
  listeners or in a label). "Roger.", "Will do.", "Re: today's job.", "Base to arms, come in.", "Okay
  robot, ...", "Good morning - ...", "Thanks a lot!", "Best of luck!", "Campers, gather round!", "Drill 5:"
  go; "Subject: pillar move." (a block and a verb), "Smash that button." (a thing's phrase), "Optional:
  ...", "Tomorrow.", "The zebra too." (`frame_keeps.txt`), "GG." (no English list knows it), a question
  that asks for something ("What should the arms do?"), a field's name before words with no verb ("Tip:
  use arm c", "Target: region I") stay, to be read or refused. A label whose named words its sentence says
  again is its header ("Pillar job: move the three pillars ..."). What only the general rule drops is said
  in the result's assumptions (`frame_note`). Some frame words count only in one place:
  a label's words before a colon ("Steps:", "Procedure:", "Here's the idea:"), a greeting's time of day
  at a fragment's start ("Morning folks", not "this morning"), a whole sentence that ends a message
  ("Done.", "The end.", not "Done: move ..."), a record's kind with its identifier or a date in the
  instruction's first sentence ("Run 5, setup B.", "Ticket #48.", "3 Dec, trial 2."; later, "Run 2:" may
  number a step, and stays). A sign-off's writer ("Best, Ana"; "Thanks," then "Ana") is dropped with it
  when the name is no word the reader knows ("Thanks, Red" stays); so is a voice assistant or person
  called after a greeting ("Hey Google, ...", "OK Kim, ...").
- Relayed and received commands: "tell / ask / have / get the arms (not) to VERB ..." (after a name
  called, "Alexa, tell the arms to ...") is the command "(do not) VERB ..."; so are "we were asked / have
  been told (not) to VERB", "our instructions are to VERB" and an exam's "plan how the arms VERB".
- Reported speech: a speaker who names nothing ("the supervisor", "she", "Kim") and a verb of saying or
  asking ("said (that)", "says:", "told us to", "asked the arms to", "wants us to") before a command or a
  rule leave the command ("She asked us to put ..." -> "put ..."); in the past tense, the rule's modal is
  put back in the present ("had to" -> "must", "was to" -> "is to", "could" -> "can", "had been touched" ->
  "has been touched"). "she wanted X put back on G" is a need ("we want X put back on G").
- First-person narration is read as the team's commands (`handover_narration.first_person_as_team`).
- An aside's abbreviation ("btw", "fyi") that opens a sentence is dropped without a comma too.

    >>> plain(["Roger", "I'll put the red block on G", "Will do"])
    ["we'll put the red block on G"]
    >>> plain(["She said the red block had to go first"])
    ['the red block must go first']
    >>> plain(["Subject: pillar move", "Tip: use arm c"])
    ['pillar move', 'Tip: use arm c']
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import NamedTuple

from nl2hltl2plan.language import voice_remarks
from nl2hltl2plan.language.content_words import names_content, word_categories
from nl2hltl2plan.language.courtesy import courtesy_pattern, courtesy_words
from nl2hltl2plan.language.frame_filler import (
    PART_BREAK,
    PART_END,
    Dropped,
    count_in,
    filler,
    named_alone,
    parts_of,
)
from nl2hltl2plan.language.grammar.everyday import HESITATION
from nl2hltl2plan.language.handover_narration import first_person_as_team
from nl2hltl2plan.language.handover_words import DONE, GERUND, SWAP, TOUCH, VERB
from nl2hltl2plan.language.reported_forms import (
    AND_SAID,
    BACKSHIFT,
    RECEIVED,
    REPORTED_CLAUSE,
    REPORTED_COMMAND,
    SOURCE,
    WANTED,
)
from nl2hltl2plan.language.spelling import american, english_lemmas

# words that may carry a meaning here: a block, a place, an arm, a count, a negation, an order or a time
MEANING = re.compile(
    r"\b(?:red|blue|yellow|blocks?|cubes?|pillars?|objects?|items?|pieces?|ones?|it|its|them|they|their|regions?|"
    r"areas?|zones?|sides?|places?|spots?|positions?|cells?|locations?|opposite|[a-j]|arms?|robots?|one|two|three|"
    r"four|both|all|each|every|\d+|not|no|never|nothing|none|cannot|without|before|after|first|then|until|once|"
    r"last|next|finally|final|step|steps|end|start|beginning|later|earlier|second|third|previous|prior|following|"
    r"afterwards?|order|while|during|meanwhile|time|any|empty|free|clear|exchange|swap|touch\w*|finish\w*|"
    r"conclu\w+|wrap\w*|complet\w*)\b"
)


@lru_cache(maxsize=1)
def frame_words() -> dict[str, frozenset[str]]:
    """category -> words (phrases joined by '_'), from `handover_frame_words.txt`; the greetings, forms of
    address and courtesy words (thanks) are `courtesy.txt`'s (one list of them for every reader)."""
    words = word_categories("handover_frame_words.txt")
    courtesy = {kind: courtesy_words(kind) for kind in ("greeting", "address")}
    return {**words, **courtesy, "thanks": words["thanks"] | courtesy_words("word")}


# categories whose words are frame words only in one place of a fragment (see the words file)
_PLACED = ("phrase", "opening", "label", "title", "alone", "month", "score")


def _words_as_pattern(words: frozenset[str]) -> str:
    return "|".join(sorted((w.replace("_", r"\s+") for w in words), key=len, reverse=True))


class _Frame(NamedTuple):
    single: frozenset[str]  # frame words anywhere
    phrases: re.Pattern[str]
    opening: re.Pattern[str]  # a greeting's time of day, opening the fragment
    label: re.Pattern[str]  # words that announce the work before a colon
    alone: frozenset[str]  # whole sentences that end a message
    records: re.Pattern[str]  # a record's kind with its identifier, a date, a question's marks


@lru_cache(maxsize=1)
def _frame() -> _Frame:
    words = frame_words()
    months = _words_as_pattern(words["month"])
    day = r"\d{1,2}(?:st|nd|rd|th)?"
    return _Frame(
        single=frozenset(w for name, ws in words.items() if name not in _PLACED for w in ws),
        phrases=re.compile(rf"\b(?:{_words_as_pattern(words['phrase'])}|{_REPLY})\b"),
        opening=re.compile(rf"^\s*(?:good\s+)?(?:{_words_as_pattern(words['opening'])})\b"),
        label=re.compile(rf"\b(?:{_words_as_pattern(words['label'] | words['title'])})\b"),
        alone=frozenset(w.replace("_", " ") for w in words["alone"]),
        records=re.compile(
            rf"\b(?:{_words_as_pattern(words['record'])})\s+(?:no\s+|number\s+)?#?\s*(?:\d+|[a-z])\b|"
            rf"\b{day}\s+(?:{months})\b(?:\s+\d{{4}})?|\b(?:{months})\s+{day}\b(?:\s+\d{{4}})?|"
            rf"\b\d+\s+(?:{_words_as_pattern(words['score'])})\b"
        ),
    )


# a support agent's reply around the request ("Happy to help!", "Thanks for reaching out!": `courtesy.txt`'s
# `reply`), said of the fragment as `empty` sees it (lower case, an apostrophe a space: "there s")
_REPLY = courtesy_pattern("reply").replace("'", r"\s*")
_ACTION = re.compile(rf"\b(?:{VERB}|{GERUND}|{DONE}|{SWAP}|{TOUCH})\b")
# the team as a whole, addressed ("okay robot", "attention all arms"): one arm by its letter says who acts,
# and after a preposition the arms are a place ("by the arms", "to the arms")
_ADDRESSEE = re.compile(r"\b(?:all\s+)?(?:the\s+)?(?:arms|robots?)\b(?!\s+[a-j]\b)")
_PLACE_BEFORE = re.compile(
    r"\b(?:by|near|beside|at|on|in|from|behind|of|with|to|next|towards?|around|between|for)\s+(?:(?:all|the)\s+)*$"
)


def _without_addressees(text: str) -> str:
    return _ADDRESSEE.sub(lambda m: m[0] if _PLACE_BEFORE.search(text[: m.start()]) else " ", text)


# a call's header: "base to arms", "memo to the team" (the caller first, then "to" and the team)
_CALL = re.compile(
    r"^(\s*(?!to\b|the\b)[a-z]+)\s+to\s+(?=(?:all\s+)?(?:the\s+)?(?:arms|robots?|team|crew)\b)"
)


@lru_cache(maxsize=16384)  # pure; a sentence is read again for each restated reading
def empty(
    fragment: str,
    label: bool = False,
    whole: bool = False,
    header: bool = False,
    edge: bool = False,
    outer: bool = False,
    general: bool = True,
    names: frozenset[str] = frozenset(),
    voice: bool = False,
) -> bool:
    """True when the fragment says nothing a spec can use (see the module docstring); a `label` (before a
    colon) may also hold the words that announce the work ("Steps", "Here's the idea"), a `whole`
    sentence may also be one that ends the message ("Done."), and the instruction's `header` (its first
    sentence) may name its record ("Run 6", "Ticket #48", "3 Dec"; later ones may number steps). A
    `voice`'s opening or closing sentence may hold any noun English knows (`filler`: "Hood off.").

    >>> empty("Re: today's job"), empty("Copy that"), empty("pillar move"), empty("Optional")
    (True, True, False, False)
    >>> empty("Good morning, team"), empty("this morning"), empty("Steps", label=True), empty("Steps")
    (True, False, True, False)
    """
    frame = _frame()
    general = general and not _ASKED.search(fragment)
    text = re.sub(r"#\s*\d+\b", " ", fragment.lower().replace("’", "'"))  # "#212": a ticket's number
    marked = re.findall(r"[a-z0-9#]+", PART_BREAK.sub(f" {PART_END} ", text))  # each part's end marked
    text = " ".join(re.sub(r"[^a-z0-9#]+", " ", text).split())
    if whole and (text in frame.alone or (general and count_in(text))):
        return True
    text = frame.opening.sub(" ", text)
    if header:
        text = frame.records.sub(" ", text)
        text = _RECORD.sub(lambda m: " " if general and _record_kind(m[1]) else m[0], text)
        alone = re.match(rf"{_RECORD_SAID.pattern}\s+{PART_END}\b", " ".join([*marked, PART_END]))
        text = _RECORD_SAID.sub(lambda m: " " if general and alone and _record_kind(m[1]) else m[0], text)
    text = " ".join(frame.phrases.sub(" ", text).split())
    if label:
        text = frame.label.sub(" ", text)
    text = _without_addressees(_CALL.sub(r"\1 ", text))
    # "it" as the whole job ("can you do it", "easy does it") and "one" as a thing said of the job ("here's
    # a tricky one") name nothing a task needs
    if general:
        text = _A_ONE.sub(lambda m: m[0] if names_content(m[1]) else " ", _DO_IT.sub(" ", text))
    if voice:
        text = _voice_words(text)
    if MEANING.search(text) or _ACTION.search(text):
        return False
    parts = parts_of(re.findall(r"[a-z0-9]+", text), marked)
    parted = len(parts_of([w for w in marked if w != PART_END], marked)) > 1  # ("Morning, sweetheart")
    set_off = edge or parted  # a part set off by a comma or dash may address the listeners

    def said(ws: tuple[str, ...], k: int) -> bool:
        # a label's words, a word alone at an edge or by another part ("Squad, ...", "..., sweetheart"): nouns
        address = label or (set_off and len(ws) == 1 and (outer or parted))
        return filler(ws, k, set_off, address, voice)

    def frame_word(ws: tuple[str, ...], k: int) -> bool:
        w = ws[k]
        if names_content(w, voice, names):
            return False
        return w in frame.single or bool(_HESITATION.fullmatch(w)) or (general and said(ws, k))

    return all(frame_word(ws, k) for ws in parts for k in range(len(ws)))


# a record's kind and its number opening the text ("Drill 5", "Speedrun attempt 3", "Ward round, bed 2"):
# any word English knows that says nothing a task needs, before a number (a letter may be a region: only the
# listed kinds take one)
_RECORD = re.compile(r"\b((?:[a-z]+\s+){0,2}?[a-z]+)\s+(?:no\s+|number\s+)?\d+\b")
# (a number said in words opens it and ends its part: "Lane two, listen.", "Table four.", not "Kiddo, one
# job", a count of the jobs; h296)
_RECORD_SAID = re.compile(r"^((?:[a-z]+\s+)?[a-z]+)\s+(?:one|two|three|four|five|six|seven|eight|nine|ten)\b")


# a question that asks for something ("What should the arms do?"): its answer may be what a task needs,
# so only the frame lists may drop it
_ASKED = re.compile(
    r"(?i)\b(?:what|which|where|how|who|whom|when|why)\b[^.!]*\?|^\W*(?:what|which|where|how|who|whom|when|why)\s+"
    r"(?:should|shall|do|does|did|is|are|was|were|can|could|will|would|must|might|may)\b"
)


def _record_kind(words: str) -> bool:
    said = tuple(words.split())
    if said[-1] in frame_words()["function"]:  # "1 of 3": a count, no record's kind
        return False
    return not MEANING.search(words) and all(
        not names_content(w) and (w in _frame().single or filler(said, k, address=True))
        for k, w in enumerate(said)
    )


_ARTICLE_A = re.compile(r"\ba\s+(?!(?:and|or|nor|to|through|then|before|after)\b)(?=[a-z]{2,})")
# in a voice's opening or closing: a verb on the listener's own things ("Grab your partners": never a scene's
# thing), and "all" / "every" / "each" on a noun that names none ("all eyes on me", "all hands on deck")
_ON_YOURS = re.compile(rf"\b(?:{VERB}|{TOUCH})\s+(?=your\s+[a-z])")
_ALL_OF = re.compile(r"\b(?:all|every|each)\s+(?=([a-z]+))")
# (a count or an ordinal on such a noun too, h308: "Two coats today.", "Right, first course.", "One more job
# for you.", "First things first."; not before "at" / "by" / "in" / "after", a pace: "one eye at a time")
_COUNT_OF = re.compile(
    r"\b(?:first\s+(?=things\s+first\b)|(?:one|two|three|four|five|first|second|third)\s+(?:more\s+)?)"
    r"(?=([a-z]+)\b(?!\s+(?:at|in|by|after)\b))"
)
_THINGS_FIRST = re.compile(r"\bthings\s+first\b")
# (a "then" that ends it, after other words, follows on from the talk: "Cheers, then.", "Right then."; h312)
_THEN_CLOSING = re.compile(r"(?<=[a-z])\s+then\s*$")
# (and the job said of them, where the sentence ends: "Three slates to lay.", "Two poles to put up today.")
_COUNTED_JOB = re.compile(
    r"\b(?:one|two|three|four|five)\s+(?:more\s+)?([a-z]+)\s+to\s+[a-z]+(?:\s+(?:up|down|in|on))?"
    r"(?=(?:\s+(?:today|now|here))?\s*$)"
)


def _voice_words(text: str) -> str:
    """A voice's sentence without what names nothing there: "a" before a word (an article, no region: "we
    have a visual", "what a gallop"), a verb on the listener's own things, a quantifier or count of a noun
    that names nothing (the noun itself stays, to be judged as frame)."""
    text = _ON_YOURS.sub(" ", _ARTICLE_A.sub(" ", _THEN_CLOSING.sub(" ", text)))
    text = _COUNTED_JOB.sub(lambda m: f" {m[1]} " if _uncounted(m) == " " else m[0], text)
    text = _COUNT_OF.sub(_uncounted, _ALL_OF.sub(_unnamed, text))
    return _THINGS_FIRST.sub(lambda m: m[0] if names_content("things", True) else " things ", text)


def _unnamed(said: re.Match[str]) -> str:
    """The quantifier before a word, or nothing where the word names nothing a task could use."""
    return said[0] if MEANING.fullmatch(said[1]) or names_content(said[1], True) else " "


def _uncounted(said: re.Match[str]) -> str:
    """The count before a word, or nothing where the word is a noun (never an adverb: "one apiece" is a
    count per place) that names nothing a task could use."""
    kinds = english_lemmas(american(said[1]))
    return " " if "NOUN" in kinds and "ADV" not in kinds and _unnamed(said) == " " else said[0]


_DO_IT = re.compile(r"\b(?:do|does|did)\s+it\b(?!\s+(?:again|twice|\d))")
_A_ONE = re.compile(r"\ban?\s+([a-z]+)\s+one\b")
_LABEL = re.compile(r"^\s*([^:]{1,60}?)\s*:\s*(?=\S)")
# a label set off by a dash that says again what its sentence names ("Green apple stuff - put ...")
_DASHED = re.compile(r"^\s*([^,:;]{1,40}?)\s+[-–—]+\s+(?=\S)")
# (a dash sets a leading phrase off as a comma does: "Morning folks - ...")
_LEAD = re.compile(r"^\s*([^,:]{1,40}?)\s*(?:,|\s[-–—]+\s|[–—])\s*(?=\S)")
_TAIL = re.compile(r",\s*([^,:]{1,40}?)\s*$")


_NOTHING_SEEN = Dropped()


def frame_gone(fragment: str, seen: Dropped, shown: str | None = None, **where: bool) -> bool:
    """`empty(fragment, **where)`; a fragment that only the general filler rule finds empty is added to
    `seen.dropped` (as `shown`, where the fragment was read without some of its words)."""
    if not empty(fragment, names=seen.names, **where):
        return False
    listed = empty(fragment, general=False, names=seen.names, **where)
    if seen.dropped is not None and not listed:
        seen.dropped.append(" ".join((shown or fragment).split()).strip(" ,.!?;:"))
    return not (listed and seen.only_general)


def _label_restated(label: str, after: str, names: frozenset[str]) -> str:
    """The label without its words that the sentence under it says again: "Carrot duty: the carrot goes
    ..." is "duty", "Blue block stuff - put the blue block ..." is "stuff" (a header of what follows)."""
    again = {form for w in re.findall(r"[a-z]+", after.lower()) for form in (w, w.removesuffix("s"))}

    def said_again(m: re.Match[str]) -> str:
        word = m[0].lower()
        named = MEANING.fullmatch(word) or names_content(word, names=names)
        return " " if named and (word in again or word.removesuffix("s") in again) else m[0]

    return re.sub(r"[A-Za-z]+", said_again, label).strip()


def heads_dropped(
    sentence: str, header: bool = False, seen: Dropped = _NOTHING_SEEN, voice: bool = False
) -> str:
    """The sentence without its empty labels ("Re: ...:", "Copy that: ...", a label that only says again
    what the sentence under it names: "Carrot duty:"), a `voice`'s heading over a command ("Warm-up set:
    move ...": `heading_words`, no word of the scene) and its empty leading phrases ("Okay robot, ...")."""
    whole = sentence
    while True:
        label = _LABEL.match(sentence) or _DASHED.match(sentence)
        if voice and label and voice_remarks.heading_words(label[1]) and not MEANING.search(label[1].lower()):
            if _ACTION.search(sentence[label.end() :].lower()):  # a command of its own under it
                if seen.dropped is not None:
                    seen.dropped.append(label[1])
                sentence = sentence[label.end() :]
                continue
        bare = _label_restated(label.group(1), sentence[label.end() :], seen.names) if label else ""
        is_label = label is not None and empty(bare, label=True, header=header, names=seen.names)
        head = label if is_label else _LEAD.match(sentence)
        if head is None:
            break
        said = head.group(1)
        if head is label:
            # a reader with its own labels (`only_general`: the tabletop's fields, methods) loses a label
            # only where it restates its sentence's names, numbers the header, or is set off ("Right, mate:")
            kept = seen.only_general and bare == said and "," not in said and sentence is whole
            kept = kept and not (header and re.search(r"\d", said))
            # a label only the general rule empties heads a command ("Morning activity: move ..."); one
            # before words with no verb is a field's name ("Target: region I, all three blocks")
            general = not empty(bare, label=True, header=header, general=False, names=seen.names)
            field = general and not _ACTION.search(sentence[head.end() :].lower())
            if kept or field or not frame_gone(bare, seen, shown=said, label=True, header=header):
                break
        elif not (frame_gone(said, seen, edge=True, outer=True, header=header) or _called(said)):
            break
        sentence = sentence[head.end() :]
    return sentence


def tails_dropped(sentence: str, seen: Dropped = _NOTHING_SEEN) -> str:
    """The sentence without an empty phrase at its end ("..., over") or set off by commas inside it."""
    tail = _TAIL.search(sentence)
    # (what only the general rule drops must leave a clause, not a turn phrase of three words or fewer:
    # "That done, relax")
    short = tail is not None and len(sentence[: tail.start()].split()) <= 3
    if short and tail and not empty(tail.group(1), edge=True, outer=True, general=False, names=seen.names):
        tail = None
    if tail and frame_gone(tail.group(1), seen, edge=True, outer=True):
        sentence = sentence[: tail.start()]
    # and a phrase set off by commas inside it ("then, robots, put ..."); a hesitation ("the three, uh, the
    # three objects") stays, for `handover_spoken` to tell a phrase said again from a correction
    return _INNER.sub(
        lambda m: "," if not _hesitation(m[1]) and frame_gone(m[1], seen, edge=True) else m[0], sentence
    )


def _unframed_sentence(sentence: str, header: bool = False, dropped: list[str] | None = None) -> str:
    """The sentence without its empty labels, leading phrases and phrases at its end, a relayed command
    said as the command."""
    seen = Dropped(dropped)
    return tails_dropped(_unrelayed(_ASIDE.sub("", heads_dropped(sentence, header, seen, voice=True))), seen)


def _hesitation(fragment: str) -> bool:
    filler = frame_words()["filler"]
    return all(w in filler or _HESITATION.fullmatch(w) for w in re.findall(r"[a-z]+", fragment.lower()))


_HESITATION = re.compile(HESITATION)  # "um", "uh", "er", "hmm": the shared list


# a voice assistant or a person called by name after a greeting or an acknowledgement ("Hey Google", "OK
# Kim"), who passes the command on: "Alexa, tell the arms to ...", "ask the robots to ...", "have the arms
# ..." (a name called alone, "Siri, swap ...", may be a word the reader does not know: left unread)
_CALL_WORD = re.compile(r"(?i)^\s*(?:hey|hi|hello|yo|ok|okay|dear)\s+(\S+)\s*$")
_RELAYED = re.compile(
    r"(?i)^\s*(?:(?P<name>[A-Za-z]+)\s*,\s*)?(?:please\s+)?(?:tell|ask|instruct|get|have)\s+(?:the|all|our)\s+"
    r"(?:robot\s+)?(?:arms|robots|team)\s+(?:(?P<not>not\s+)?to\s+)?(?=[a-z])"
)


def _unrelayed(sentence: str) -> str:
    relayed = _RELAYED.match(sentence)
    if relayed is None or (relayed["name"] and not writer_name(relayed["name"])):
        return sentence
    return ("do not " if relayed["not"] else "") + sentence[relayed.end() :]


# an aside's abbreviation that opens the sentence, with or without a comma ("btw red goes first")
_ASIDE = re.compile(rf"(?i)^\s*(?:{'|'.join(sorted(frame_words()['aside']))})\b[\s,:]*(?=\S)")


def _called(fragment: str) -> bool:
    called = _CALL_WORD.match(fragment)
    return called is not None and writer_name(called[1])


_INNER = re.compile(r",\s*([^,:;]{1,40}?)\s*(?=,)")


# -- reported speech (its forms are `reported_forms`'s) -------------------------------------------

_NOBODY = frozenset("nobody noone none nothing neither never no".split())


def person(speaker: str) -> bool:
    """A speaker is a person who names nothing the reader reads: a pronoun, a name ("Kim"), a role ("the
    supervisor"); never a block, place or arm ("the red block said ...")."""
    words = speaker.lower().split()
    if words[-1] in _NOBODY:  # "Nobody said to ...": no one asks for it
        return False
    if speaker.lower() in ("he", "she", "they", "someone"):  # "they said": people, not blocks
        return True
    if MEANING.search(speaker.lower()) or _ACTION.search(speaker.lower()):
        return False
    if words[-1] in frame_words()["function"] or words[-1] in ("who", "which", "everything", "nothing"):
        return False  # "What needs to happen is ...": no speaker
    return not any(names_content(w) for w in words)


@lru_cache(maxsize=16384)  # pure; a sentence is read again for each restated reading
def unreported(sentence: str) -> str:
    """The command or rule that a reported sentence reports (see the module docstring).

    >>> unreported("The supervisor said to move the red block to G and told us the blue one had to wait")
    'move the red block to G and the blue one must wait'
    """
    reported = False

    def command(match: re.Match[str]) -> str:
        nonlocal reported
        if not person(match.group("speaker")):
            return match.group(0)
        reported = True
        return match.group("start") + ("do not " if match.group("neg") else "")

    def clause(match: re.Match[str]) -> str:
        nonlocal reported
        if not person(match.group("speaker")):
            return match.group(0)
        reported = True
        return match.group("start")

    def wanted(match: re.Match[str]) -> str:
        nonlocal reported
        if not person(match.group("speaker")):
            return match.group(0)
        reported = True
        return match.group("start") + "we want "

    def received(match: re.Match[str]) -> str:
        nonlocal reported
        reported = True
        return match.group("start") + ("do not " if match.group("neg") else "")

    sentence = RECEIVED.sub(received, sentence)
    sentence = SOURCE.sub(clause, sentence)
    sentence = REPORTED_COMMAND.sub(command, sentence)
    sentence = REPORTED_CLAUSE.sub(clause, sentence)
    sentence = WANTED.sub(wanted, sentence)
    if not reported:
        return sentence
    sentence = AND_SAID.sub("and ", sentence)
    sentence = re.sub(r"(?i)\band\s+that\s+", "and ", sentence)
    # "told us to move ... and (not) to put ...": the second command
    second = re.compile(rf"(?i)\band\s+(not\s+)?to\s+(?=(?:{VERB}|{SWAP}|{TOUCH})\b)")
    sentence = second.sub(lambda m: "and do not " if m[1] else "and ", sentence)
    for pattern, replacement in BACKSHIFT:
        sentence = pattern.sub(replacement, sentence)
    return sentence


# a writer's name: one or two capitalised words that the reader reads as nothing ("Ana", "Mr Okafor"; not
# "Red", not "Arm"), a team's ("The Robotics Team", "Support Desk"), after a dash at most ("- Priya")
_NAME = re.compile(r"^\s*[-\u2013\u2014~]*\s*(?-i:(?:The\s+)?[A-Z][a-z]+(?:\s+[A-Z][a-z]+)?)\s*[.!]*\s*$")


def writer_name(text: str, names: frozenset[str] = frozenset()) -> bool:
    """Whether no word of the name `text` is a block, place, action, content word or thing (`names`)."""
    words = re.findall(r"[a-z]+", text.lower())
    known = (MEANING.search(w) or _ACTION.search(w) or names_content(w, names=names) for w in words)
    return bool(_NAME.match(text)) and not any(known)


def unsigned(sentences: list[str], seen: Dropped = _NOTHING_SEEN) -> list[str]:
    """The sentences without the sign-off and writer's name ending them: "Best, Ana", "Night, Bo", "Night,
    Mr Okafor" (the sign-off found empty by `frame_gone`), or "Thanks!" and then "- Priya". A sign-off only
    the general filler rule drops goes to `seen.dropped` with its name ("Night, Bo"); a thing's name
    (`seen.names`: "Night, Mug") is no writer's. Every reader's frame rule (`plain`, `frames_dropped`)."""
    signed = re.fullmatch(r"(.+),([^,]+)", sentences[-1]) if sentences else None
    alone = len(sentences) > 1 and writer_name(sentences[-1], seen.names)
    if alone and empty(sentences[-2], whole=True):
        if seen.dropped is not None and not empty(sentences[-2], whole=True, general=False):
            seen.dropped.append(sentences[-1].strip(" -\u2013\u2014~.!"))  # the name of "Night. Bo"
    elif not (signed and writer_name(signed[2], seen.names)
              and frame_gone(signed[1], seen, shown=sentences[-1], edge=True, outer=True)):
        return sentences
    return sentences[:-1]



def _voice_edges(sentences: list[str]) -> set[int]:
    """The opening and closing sentences of a voice that name nothing (h281: "Bow to your partner!",
    "Glove on, hood off.", "Good dog."): the runs at either end of sentences that `empty` finds empty with
    any noun English knows, but a thing's name alone ("Zebra.": `named_alone`); never every sentence (a
    message of frame alone is refused, by its words)."""
    said = [_edge_empty(s, header=k == 0) or _remark(s) for k, s in enumerate(sentences)]
    if all(said):
        return set()
    first = said.index(False)
    last = len(said) - said[::-1].index(False)
    return set(range(first)) | set(range(last, len(said)))


def _edge_empty(sentence: str, header: bool = False) -> bool:
    return (
        empty(sentence, whole=True, header=header, voice=True)
        and not named_alone(tuple(re.findall(r"[a-z]+", sentence.lower())))
        and not voice_remarks.commanded(sentence)
    )


def _remark(sentence: str) -> bool:
    """A voice's warning of nothing the scene has ("Mind the dog."), its farewell ("Ta-ra.", h296), its
    reassurance, plea for patience or apology about nothing the scene has ("Nothing to worry about.", h312),
    or parts each such a remark or empty, one a remark ("Mind the glue, it's still tacky.")."""
    warned = voice_remarks.caution_of(sentence)
    said = warned if warned is not None else voice_remarks.aside_of(sentence)
    unnamed = said is not None and not (MEANING.search(said.lower()) or _ACTION.search(said.lower()))
    if unnamed or voice_remarks.farewell(sentence) or voice_remarks.attention(sentence):
        return True
    parts = voice_remarks.clauses(sentence)
    return len(parts) > 1 and any(map(_remark, parts)) and all(_remark(p) or _edge_empty(p) for p in parts)


def plain(sentences: list[str], dropped: list[str] | None = None) -> list[str]:
    """The sentences with empty fragments, start signals and a sign-off's name dropped, reported speech and
    first-person narration said as the team's commands (see the module docstring); what only the general
    filler rule dropped is added to `dropped`, where given."""
    out = []
    # "..., isn't it, pet?": a voice's closing tags (h296)
    untagged = [voice_remarks.closing_tags(s) for s in unsigned(sentences, Dropped(dropped))]
    sentences = [s for s, _ in untagged]
    if dropped is not None:
        dropped.extend(tag for _, tags in untagged for tag in tags)
    edges = _voice_edges(sentences)
    for k, sentence in enumerate(sentences):
        framed = frame_gone(sentence, Dropped(dropped), whole=True, header=k == 0, voice=k in edges)
        remark = not framed and k in edges and _remark(sentence)
        if remark and dropped is not None:
            dropped.append(sentence.strip(" .!?"))
        if framed or remark or voice_remarks.start_signal(sentence):
            continue
        if k == 0 and _called(sentence.rstrip(" ,.!:")):  # a letter's greeting on its own: "Dear Sam,"
            continue
        text = _unframed_sentence(sentence, header=k == 0, dropped=dropped)
        text = _unframed_sentence(first_person_as_team(unreported(text)), header=k == 0, dropped=dropped)
        if text.strip() and not frame_gone(text, Dropped(dropped), whole=True, header=k == 0):
            out.append(text)
    return out
