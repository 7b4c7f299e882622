"""The sentences of a handover instruction (`handover_reading` reads each): split at line breaks and at
'.', ';', '!' and '?', after its layout is read (`handover_layout`: headings, bullets, transcripts, records of
labelled fields); quotation marks, markdown's bold, emoji and hashtags, a count after its noun ("blocks
(x3)") and letters joined by slashes ("H/I/J") are read here too."""

from __future__ import annotations

import re
import unicodedata

from nl2hltl2plan.language.handover_freed_steps import steps_freed
from nl2hltl2plan.language.handover_layout import (
    HEADED,
    REORDERED,
    block_bullets_read,
    later_read,
    nested_read,
    places_then_count_read,
    prohibitions_read,
    transcript_read,
    until_all_there_read,
    verb_heading_read,
)
from nl2hltl2plan.language.handover_words import MOD


def _without_emoji_and_tags(text: str) -> str:
    """A pictograph (an emoji, a symbol of Unicode's 'other symbol' class, with its joiners and variation
    selectors) ends a sentence as a full stop does ("Move the blocks 🙂 Red first"); a hashtag ("#robots")
    is the message's label and carries no task (a number after '#', "#3", stays)."""
    text = re.sub(r"(?<![\w#])#[A-Za-z]\w*", " ", text)
    if not any(_pictograph(c) for c in text):
        return text
    out = "".join(". " if _pictograph(c) else "" if c in "\u200d\ufe0f" else c for c in text)
    return re.sub(r"(?:\.\s*){2,}", ". ", out)  # a run of pictographs is one break


def _slashes_read(text: str) -> str:
    """Letters joined by slashes list regions or arms ("H/I/J" is "H, I and J", "arms a/b" "arms a and b");
    a count after its noun is the noun's count ("blocks (x3)" is "3 blocks"). (A slash between clauses is read
    by the fallback: `_slashes_split`.)"""
    letters = r"\b[A-Ja-j](?:\s*/\s*[A-Ja-j]\b)+"
    text = re.sub(letters, lambda m: _listed(re.sub(r"\s*/\s*", ", ", m[0])), text)
    text = re.sub(r"\b(blocks|pillars|objects|cubes|items)\s*\(?\s*[x×]\s*(\d)\b\s*\)?", r"\2 \1", text)
    return text


# a step numbered in Roman numerals ("Step II: ..."), before a colon, a bracket or a dash: its number, never
# a region's letter ("Step I:" is step 1)
_ROMAN = {"i": 1, "ii": 2, "iii": 3, "iv": 4, "v": 5}
_ROMAN_STEP = re.compile(r"(?i)\b(?P<word>step|stage|phase|part)\s+(?P<number>iv|v|i{1,3})\b(?=\s*[:)\-–—])")


def _pictograph(c: str) -> bool:
    return ord(c) > 0x7F and unicodedata.category(c) in ("So", "Sk")  # not "^" or "`" (ASCII, class Sk)


def split_sentences(instruction: str) -> list[str]:
    """Split at line breaks (a list of steps or bullets), '.', ';', '!' and '?', but not in 'i.e.' nor after a
    step's number ('1. Put ...', also after a colon; 'Step II:' is 'Step 2:'); a bullet ('-', '*', '•')
    starting a line or sentence is dropped. A heading ending in a colon is joined to the line below it,
    and a record of labelled fields, on lines or in sentences and in either order ('Blocks: ...' and
    'Targets: ...'), is read as one goal."""
    out: list[str] = []
    # an e-mail's quote marks ("> " at a line's start, "> > " when quoted twice): the quoted line is read
    instruction = re.sub(r"(?m)^[ \t]*(?:>[ \t]*)+(?=\S)", "", instruction)
    instruction = _ROMAN_STEP.sub(lambda m: f"{m['word']} {_ROMAN[m['number'].lower()]}", instruction)
    instruction = nested_read(transcript_read(prohibitions_read(instruction)))
    instruction = places_then_count_read(verb_heading_read(block_bullets_read(instruction)))
    instruction = until_all_there_read(instruction)
    # a record of labelled fields, on lines or in sentences, in either order: "Blocks: red, blue, yellow"
    # then "Targets: H, I, J" (or "Regions: G, H and I. Objects: all three.") is one goal
    for record in _RECORDS:
        instruction = record.sub(_record_as_goal, instruction)
    # a heading that ends in a colon goes on in the bullet below it: "Place the blocks on:\n- G, H and I"
    # (after a preposition the colon only ends the line); an open checklist box is a bullet ("Checklist:\n[ ]
    # ...")
    bullet = r"[ \t]*\n\s*(?:[-*•·]|\d[.)]|\[[ \t]*\]|☐)\s+"
    instruction = re.sub(rf"(?m)\b(on|onto|in|into|to|at)\s*:{bullet}", r"\1 ", instruction)
    instruction = re.sub(rf"(?m):{bullet}", ": ", instruction)
    instruction = re.sub(r"(?m):[ \t]*\n\s*(?=\S)", ": ", instruction)  # a heading on a line of its own
    instruction = _unquoted(re.sub(r"\*\*|__", "", instruction))  # markdown's bold: "**Goal:** ..."
    for line in instruction.splitlines():
        text = re.sub(r"(^\s*|[.;!?:]\s+)(\d)\.\s", r"\1\2) ", line)
        text = re.sub(r"\b[iI]\.\s?[eE]\.", "that is", text)
        text = re.sub(r"\b[nN]\.\s?[bB]\.?\s*:?", "NB:", text)  # "N.B. red goes first": a note's label
        text = re.sub(r"\b(?:[pP]\.\s?)+[sS]\.\s*:?", "PS:", text)  # "P.S. red goes first": a postscript
        text = re.sub(r"\b(opp|approx|resp)\.(?=\s)", r"\1", text, flags=re.IGNORECASE)  # "opp. side"
        # an open checklist box is a bullet (a ticked one says what is done, and is left unread)
        text = re.sub(r"^\s*(?:\[\s*\]|☐)\s*", "- ", text)
        text = _slashes_read(_without_emoji_and_tags(text))
        for pattern, replacement in (*REORDERED, *HEADED):
            text = pattern.sub(replacement, text)
        out += [re.sub(r"^\s*[-*•·]\s+", "", s) for s in re.split(r"[.;!?]+(?:\s|$)", text)]
    return later_read(_without_announcement(steps_freed([s for s in out if s.strip()])))


# "There are a few things to keep in mind." before the things: it names no block, place or order; a
# number of things must be the number of sentences after it (else it stays, to be refused by name)
_ANNOUNCED = re.compile(
    r"^\s*there\s+(?:are|is)\s+(a\s+few|a\s+couple\s+of|some|several|two|three|four)\s+"
    r"(?:things|points|rules|requirements|conditions)(?:\s+here|\s+to\s+(?:keep|bear)\s+in\s+mind|\s+to\s+"
    r"(?:remember|note))?\s*:?\s*$",
    re.IGNORECASE,
)
_NUMBERS = {"two": 2, "three": 3, "four": 4}


def _without_announcement(sentences: list[str]) -> list[str]:
    said = _ANNOUNCED.match(sentences[0]) if sentences else None
    if said is None or _NUMBERS.get(said[1].lower(), len(sentences) - 1) != len(sentences) - 1:
        return sentences
    return sentences[1:]


def _unquoted(instruction: str) -> str:
    """The instruction without the quotation marks around a command quoted whole ('The note says: "Put
    ..."'): double quotes anywhere; single quotes around one letter (a region's or an arm's name: "region
    'I'"); a single quote that opens the instruction or follows a colon, and then one that closes a word
    ("blocks' places": the possessive's mark, which the reader drops anyway)."""
    text = re.sub(r"[\"“”]", "", instruction)
    text = re.sub(r"(?<!\w)['‘]([A-Za-z])['’](?!\w)", r"\1", text)
    if re.search(r"(?:^|:)\s*['‘]", text):
        text = re.sub(r"((?:^|:)\s*)['‘](?=\w)", r"\1", text)
        text = re.sub(r"(?<=[\w.!?])['’](?=[.!?,;]?(?:\s|$))", "", text)
    return text


_BLOCKS_FIELD = (
    r"\s*(?:[-*•·]\s+)?(?:blocks?|objects?|pillars?|items?|pieces?|cubes?|what|move|place|put|transfer|carry|bring)"
    r"\s*:\s*(?P<blocks>[^\n:.;]+?)\s*"
)
_PLACES_FIELD = (
    r"\s*(?:[-*•·]\s+)?(?:targets?|destinations?|(?:goal|target|placement)\s+(?:regions?|areas?)|target\s+area|"
    r"where(?:\s+to)?|regions?|places?|to|onto|into)\s*:\s*(?P<places>[^\n:.;]+?)\s*"
)
_FIELD_BREAK = r"(?:[.;]?[ \t]*\n|[.;][ \t]+)"  # a line break or a sentence's end between two fields
_FIELD_END = r"(?=[.;!?]?[ \t]*(?:\n|$)|[.;!?][ \t])"
_RECORDS = tuple(
    re.compile(rf"(?im)(?P<start>^|[.;!?][ \t]+){first}{_FIELD_BREAK}{second}{_FIELD_END}")
    for first, second in ((_BLOCKS_FIELD, _PLACES_FIELD), (_PLACES_FIELD, _BLOCKS_FIELD))
)


def _record_as_goal(fields: re.Match[str]) -> str:
    """The record's goal; a modifier of the blocks' field is said after the places ("place: three blocks,
    one after another" and "to: region I": "three blocks to region I, one after another")."""
    blocks = fields["blocks"]
    mods = found[0] if (found := re.search(rf"(?:\s*,\s*{MOD})+$", blocks)) else ""
    return f"{fields['start']}{_listed(blocks[: len(blocks) - len(mods)])} to {fields['places']}{mods}"


def _listed(items: str) -> str:
    """'red, blue, yellow' -> 'red, blue and yellow' (a record's list: its last comma is its 'and')."""
    return items if re.search(r"\band\b", items) else re.sub(r",\s*([^,]+)$", r" and \1", items)
