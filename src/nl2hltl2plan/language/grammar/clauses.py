"""Step 2, clauses: a sentence -> its verb clauses, with elided verbs restored."""

from __future__ import annotations

import re
from dataclasses import dataclass

from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.frames import dest_of, parse_frame
from nl2hltl2plan.language.grammar.phrases import DETERMINERS, match_prep, parse_np, tokens


def _is_verb_at(words: list[tuple[str, int, int]], i: int) -> bool:
    """Does a verb clause start at word `i` (a verb first in the sentence or after a joiner)?"""
    w = words[i][0]
    if w not in G.VERBS or (w in G.SLICE_NOUNS and words[i + 1 : i + 2] and words[i + 1][0] == "of"):
        return False  # "a knife and slice of potato": a noun
    if i == 0:
        return True
    prev = words[i - 1][0]
    if prev == "," or prev in G.CLAUSE_JOINERS:
        # "to the", "in place": only when this word is used as a verb (followed by a noun phrase / particle)
        if (
            prev in {"to", "in", "order", "as", "so"}
            and G.VERBS[w][0] in {"place", "pick"}
            and w in {"place", "set", "rest", "stand", "sit", "bin", "light", "watch", "use", "find"}
        ):
            nxt = words[i + 1][0] if i + 1 < len(words) else ""
            return (
                nxt in {"it", "them", "the", "a", "an", "on", "in", "down", "up", "into", "onto"}
                and prev == "to"
            )
        if prev == "in" and w not in {"order"}:
            return False
        return True
    return False


def _ends_an_order(words: list[tuple[str, int, int]], j: int) -> bool:
    """Is word `j` the "order" of "in any order" / "in either order" (the clause's own words, no joiner)?"""
    return words[j][0] == "order" and j > 0 and words[j - 1][0] in {"any", "either", "whatever"}


_JOINERS_FIRST = re.compile(
    r"^[\s,]*(?:(?:and|then|to|plus|also|while|or|as|so|first|next|finally|lastly|afterwards?|"
    r"subsequently)\b[\s,]*)*",
    re.I,
)
# a request asked in the middle of a run-on ("grab the mug can you put it in the sink"): its own clause
_ASKS = frozenset({"can", "could", "would", "will"})
_YOU = frozenset({"you", "u"})
_PLEASE = frozenset({"please", "pls", "plz"})
_SUBJECTS = frozenset({"you", "u", "i", "we", "they", "he", "she"})
# words of a subordinate clause or a statement: a command that holds one is not known to be whole
_NOT_A_COMMAND = _SUBJECTS | set(G.SEQ_JOINERS) | {",", "once", "until", "when", "whenever", "while", "if"}
_NOT_A_COMMAND |= {"but", "never", "not", "don't", "dont", "do", "except", "unless"}  # negations, exceptions
# the particle a verb of each class may take before its thing ("turn on the lamp", "look at the box")
_PARTICLES = {
    "light": {"on", "off", "up"},
    "examine": {"at", "out"},
    "pick": {"up"},
    "clean": {"off", "out", "up"},
    "trash": {"away", "out"},
    "place": {"away", "down", "back"},
}


def _asked_from(words: list[tuple[str, int, int]], i: int) -> int:
    """The index where "can you (please)" before word `i` starts, or `i` where none does."""
    if i > len(words):
        return i
    j = i - 1 if i > 0 and words[i - 1][0] in _PLEASE else i
    if j >= 2 and words[j - 1][0] in _YOU and words[j - 2][0] in _ASKS:
        return j - 2
    return i


def _complete(chunk: str) -> bool:
    """Is `chunk` a whole command: a verb, a thing named by a known noun or a pronoun and, for a placing,
    a place the same? ("put the cup on the" is not: the next word may be a noun, "the wash cloth")."""
    body = _JOINERS_FIRST.sub("", chunk)
    words = [w for w, _, _ in tokens(body)]
    if _NOT_A_COMMAND.intersection(words[3 if _asked_from(tokens(body), 2) == 0 else 0 :]):
        return False
    fr = parse_frame(body)
    if fr.cls in {"none", "other"} or not fr.items:
        return False
    last = fr.items[-1]
    if last.obj is None or last.obj.empty:
        return False
    if fr.cls in {"place", "trash"}:
        dst = dest_of(last, fr.cls)
        return dst is not None and not dst.empty and chunk.rstrip().endswith(dst.text)
    return not last.pps or not last.pps[-1][1].empty


def _runs_on_at(sentence: str, words: list[tuple[str, int, int]], i: int, since: int) -> tuple[int, str]:
    """Plain users' run-on commands, no "and" or comma between them ("put the phone on the desk throw the
    pencil in the trash", "slice a potato chill one piece"): where a new clause starts at the imperative verb
    `i` after a whole command that began at offset `since`. The verb must be followed by a thing or a
    particle of its own and follow a whole command; inside a noun phrase ("a cook book", "a slice of bread")
    the command before it is not whole. A split that is not certain is left to the readers, which name the
    words they could not read. Returns (the index the clause starts at, its joiner), or (-1, "")."""
    w = words[i][0]
    nxt = words[i + 1][0] if i + 1 < len(words) else ""
    # the bare form only: "a box of tissues using the light of a lamp" is no command
    if w not in G.VERBS or G.VERBS[w][1] != w or i == 0 or words[i - 1][0] in G.CLAUSE_JOINERS | {","}:
        return -1, ""
    # "put two in the cabinet": a count with no noun names no thing (two of which? the split would guess)
    count = nxt in G.NUMBERS or nxt.isdigit()
    if count and (i + 2 >= len(words) or match_prep([t for t, _, _ in words], i + 2) is not None):
        return -1, ""
    starts = count or nxt in {"it", "them"} or (nxt in DETERMINERS and nxt != "of")
    if not (starts or nxt in _PARTICLES.get(G.VERBS[w][0], ())):
        return -1, ""
    b = _asked_from(words, i)
    if b == i and words[i - 1][0] in _SUBJECTS:  # "after you look at ...": a subordinate clause's verb
        return -1, ""
    if 0 < b < i and words[b - 1][0] in {"and", "then", ","}:  # "... and can you put ...": said as a clause
        return b - 1, "then" if words[b - 1][0] == "then" else "and"
    joiner = "and"
    if b > 1 and words[b - 1][0] == "last":  # "... in the tub last put ...": "lastly", its comma left out
        if since == 0:  # "A last put B": "A, lastly B" or "A last, then B", opposite orders (h227)
            return -1, ""
        b, joiner = b - 1, "finally"
    if b == 0 or sentence[words[b - 1][2] : words[b][1]].strip():  # a bullet or a dash: a list of its own
        return -1, ""
    if words[b - 1][0] in DETERMINERS or not _complete(sentence[since : words[b - 1][2]]):
        return -1, ""
    before = parse_np(words[b - 1][0]).entry  # "heat a tomato slice the same way": a noun
    if w in G.SLICE_NOUNS and before is not None and G.SLICEABLE.intersection(before.types):
        return -1, ""
    return b, joiner


def split_clauses(sentence: str, run_ons: bool = True) -> list[tuple[str, int, int, str]]:
    """(clause text, start, end, joiner) for each verb clause of a sentence; `run_ons=False` leaves run-on
    commands whole (in "before you A B, and C" where the subordinate clause ends is not certain)."""
    words = tokens(sentence)
    cuts: list[tuple[int, str]] = []
    for i in range(len(words)):
        since = cuts[-1][0] if cuts else 0
        verb_at = _is_verb_at(words, i)
        at, said = _runs_on_at(sentence, words, i, since) if run_ons and not verb_at else (-1, "")
        if at >= 0:
            cuts.append((words[at][1], said))
        elif verb_at:
            j = i - 1
            joiner = ""
            ends_before = -1  # "X first and then Y": the "first" that ends the clause before
            while j >= 0 and (words[j][0] in G.CLAUSE_JOINERS or words[j][0] == ",") and not _ends_an_order(
                words, j
            ):
                # "A finally, and B": the word before the comma and "and" closes A (B was made last, h207)
                closes = joiner == "and" and words[j + 1][0] == ","
                if words[j][0] in G.SEQ_JOINERS and not closes and not (
                    joiner and G.SEQ_JOINERS[words[j][0]] == "first"
                ):
                    joiner = G.SEQ_JOINERS[words[j][0]]
                elif words[j][0] in G.SEQ_JOINERS and ends_before < 0:
                    ends_before = j  # it stays with that clause, whose order reads it ("first" at its end)
                elif words[j][0] in {"to", "and", "while", "plus", "also", "or", "as"} and not joiner:
                    joiner = words[j][0]
                j -= 1
            cut = words[j + 1][1] if j + 1 < i else words[i][1]
            if ends_before >= j + 1:
                cut = words[ends_before][2]
            cuts.append((cut if i else 0, joiner))
    if not cuts or cuts[0][0] != 0:
        cuts.insert(0, (0, ""))
    out = []
    for k, (cut, joiner) in enumerate(cuts):
        end = cuts[k + 1][0] if k + 1 < len(cuts) else len(sentence)
        chunk = sentence[cut:end]
        stripped = _JOINERS_FIRST.sub("", chunk)
        if _asked_from(tokens(stripped), 2) == 0:  # "can you put ...": the request
            stripped = re.sub(r"^\w+\s+\w+\s+(?:(?:please|pls|plz)\s+)?", "", stripped)
        stripped = re.sub(r"^last\s+", "", stripped) if joiner == "finally" else stripped
        stripped = re.sub(r"[\s,]*(?:\band\b)?[\s,]*$", "", stripped)
        if stripped:
            s = cut + chunk.index(stripped)
            out.append((stripped, s, s + len(stripped), joiner))
    return out


# ----- elided verbs ("first the saucers, then the cups, in the upper rack") -------------------------------
_GAP_SPLIT = re.compile(
    r"(?:\s*,\s*|\s+)(?:and\s+)?(?P<j>then|next|afterwards?|after\s+that|finally|lastly|followed\s+by|but\s+first)\b"
    r"(?!\s*,?\s*(?:and|then)\b)\s*,?\s*",  # "A and B afterwards, and C": the word closes B's (h226)
    re.I,
)
# "A, then B, but first C": the list keeps the marker of C (it was swallowed into B's segment)
_GAP_JOINER = {"finally": "finally", "lastly": "finally", "but first": "first"}
# a clause's own verb may take a pronoun before the list ("put it on the desk and then the pen in the drawer":
# the verb is elided only after it); the later segments must name movable things, each with its own place
_AT = re.compile(r"at\s+", re.I)
_PRONOUN_FIRST = re.compile(r"(?:it|them)\s+(?:in|into|on|onto|inside)\s", re.I)


@dataclass
class Clause:
    """One verb clause of a sentence; `gap` >= 0 marks clauses rebuilt from one elided-verb list (a group
    when they share one destination), `label` their rebuilt text ("put the cups in the upper rack")."""

    text: str
    start: int
    end: int
    joiner: str
    gap: int = -1
    label: str = ""
    whole: str = ""  # the text of the whole list, verb restored


def _movable_np(text: str) -> bool:
    """Does `text` start with a noun phrase naming a movable thing (not a fixed receptacle, not a lamp)?"""
    words = [w for w, _, _ in tokens(text)]
    if not words or match_prep(words, 0) is not None or words[0] in G.VERBS:
        return False
    head = parse_np(re.split(r"\s*,\s*|\s+(?=(?:in|into|on|onto|to|inside|at)\b)", text, maxsplit=1)[0])
    if head.entry is None or head.generic or head.is_lamp():
        return False
    return not (head.is_receptacle() and not head.is_movable_receptacle())


def _dest_pp(verb: str, text: str) -> str:
    """The destination phrase of `verb text` as written ("in the upper rack"), or ""."""
    fr = parse_frame(f"{verb} {text}")
    for it in fr.items:
        dst = dest_of(it, fr.cls)
        if dst is not None:
            for p, np in it.pps:
                if np is dst:
                    return f"{p} {np.text}"
    return ""


# words of a stated rule ("the arm cannot touch the blue block until ..."), never an elided-verb object list
_STATEMENT_WORDS = frozenset({"cannot", "can't", "must", "should", "until", "not"})


def expand_gapping(
    clauses: list[tuple[str, int, int, str]], verb: str, last_dest: str, gap_base: int = 0
) -> list[Clause]:
    """Clauses with an elided verb get it back: "put the plates in the lower rack, then the cups in the upper
    rack" and a verbless "first the saucers, then the cups, in the upper rack" after a clause whose verb was
    "put". A list of objects split by sequence words ("then", "next", "finally") becomes one clause per
    object with the verb of the clause (or `verb`, the previous clause's, when the clause has none); objects
    without a destination share the last one stated (then they form a group), or, in a verbless sentence
    that names none, `last_dest` (the previous clause's destination: "Then the tomato")."""
    out: list[Clause] = []
    for k, (text, start, end, joiner) in enumerate(clauses):
        words = [w for w, _, _ in tokens(text)]
        own = bool(words) and words[0] in G.VERBS
        if own:
            cut = len(text.split(None, 1)[0])
            v, args, a0 = text[:cut], text[cut:].lstrip(), len(text) - len(text[cut:].lstrip())
            if words[0] == "look" and (at := _AT.match(args)):  # "look at the box ..., then the book"
                v, args, a0 = f"{v} at", args[at.end() :], a0 + at.end()
        elif verb and k == 0 and not _STATEMENT_WORDS.intersection(words):
            v, args, a0 = verb, text, 0
        else:
            out.append(Clause(text, start, end, joiner))
            continue
        # split at sequence words that are followed by a movable object (not "then on the counter")
        parts: list[tuple[str, int, str]] = []  # (segment, offset in args, joiner)
        pos, seg_joiner = 0, joiner
        for m in _GAP_SPLIT.finditer(args):
            if m.start() <= pos or not _movable_np(args[m.end() :]):
                continue
            parts.append((args[pos : m.start()], pos, seg_joiner))
            seg_joiner = _GAP_JOINER.get(" ".join(m.group("j").lower().split()), "then")
            pos = m.end()
        parts.append((args[pos:], pos, seg_joiner))
        parts = [(seg.strip(" ,"), off, j) for seg, off, j in parts if seg.strip(" ,")]
        if own and len(parts) < 2:
            out.append(Clause(text, start, end, joiner))
            continue
        pronoun = bool(parts) and own and bool(_PRONOUN_FIRST.match(parts[0][0]))
        if not parts or not (_movable_np(parts[0][0]) or pronoun):
            out.append(Clause(text, start, end, joiner))
            continue
        dests = [_dest_pp(v, seg) for seg, _, _ in parts]
        # "wash it and put it on the desk, then the pen": is the pen washed? And the pronoun's segment is
        # its place alone ("it on the desk", not "it on the desk and yeah")
        placed = all(dests) and re.fullmatch(rf"(?:it|them)\s+{re.escape(dests[0])}", parts[0][0])
        if pronoun and not placed:
            out.append(Clause(text, start, end, joiner))
            continue
        shared = next((d for d in reversed(dests) if d), "") or ("" if own else last_dest)
        missing = [i for i, d in enumerate(dests) if not d]
        sharing = [i for i, d in enumerate(dests) if not d or d == shared]
        gap = gap_base + k if len(sharing) > 1 and missing and shared else -1
        for i, (seg, off, j) in enumerate(parts):
            seg_text = seg
            if not dests[i] and shared:  # "the saucers" + "in the upper rack"
                seg_text = f"{seg.rstrip(' ,')} {shared}"
            elif shared and dests[i] == shared:  # "the cups, in the upper rack": drop the comma
                seg_text = re.sub(r"\s*,\s*(?=" + re.escape(shared) + r"$)", " ", seg)
            label = f"{v} {seg_text}"
            s0 = start + a0 + off
            whole = text if own else f"{v} {text}"
            out.append(Clause(label, s0, s0 + len(seg), j, gap if i in sharing else -1, label, whole))
    return out
