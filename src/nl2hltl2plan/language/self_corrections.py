"""Self-corrections said in passing, applied before the household grammar reads (`corrected`): the
correction replaces what it corrects, and what is unclear is refused by name.

- "put the mug in the sink, no wait, in the cabinet": a place with its preposition replaces the last place
  before the marker ("in the sink");
- "put the apple in the microwave... I mean the fridge": a bare name replaces the last name before the
  marker that has its role (a place for a place, a thing to carry for a thing), where its role is certain:
  "put the pan in the sink, I mean the pot" is refused, since a pot is both a thing to carry and a place,
  and "put the mug, no wait, the cup, in the sink" replaces the mug (no place is said before the marker);
- a name with a place after it ("put the egg, no wait, the apple in the fridge") replaces by its name, and
  the place stays;
- a clause after "no", "nope" or "scratch that part" ("wash the cloth and hang it... no, put it on the
  shelf") replaces the last verb phrase before it, in its sentence ("hang it"), and its pronoun stands for
  the one thing that phrase names ("hang the apple... no, put it in the fridge"); a phrase that is negated
  or holds more than one task ("put the mug in the sink and the egg in the fridge, no, ..."), and a clause
  that may add instead ("no, put the mug in the sink too", "... first") are refused by name, and a "no"
  that opens a negation ("no, don't put it there") corrects nothing;
- any other correction that says an action ("what I mean is put ...") is left to the grammar;
- a marker with no place or name after it ("put the mug in the sink, no wait") is refused by name.

The markers: "no wait", "wait, no", "I mean", "I meant", "or rather", "sorry", "oops", "whoops", "make
that", "correction", and "no" / "nope" / "nah" / "actually" / "scratch that part" after a comma, a dash or an
ellipsis (an "Actually, ..." opening a sentence adds, and is left), and there "wait" before a comma ("put
the apple in the fridge... wait, the microwave"; "wait until ..." is no marker).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Sequence
from dataclasses import dataclass

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import categories
from nl2hltl2plan.language.grounding import Mention, find_mentions, tokens
from nl2hltl2plan.language.prepositions import PLACE_OR_LANDMARK, preposition_pattern
from nl2hltl2plan.worlds.world import World

_PAUSE = r"(?:\s*(?:,|;|:|\.{2,}|…|—|–|\s-+)\s*|\s+)"
_WORDS = (
    r"(?:no,?\s+wait|wait,?\s+no|i\s+mean[t]?|or\s+rather|no,?\s+sorry|sorry|oops|whoops|make\s+(?:that|it)|"
    r"correction)(?![\w'])"
)
# markers said only after a pause ("hang it... no, put it on the shelf"): each may also open a clause that
# replaces the verb phrase before it (`_clause_replaced`)
_AFTER_PAUSE = r"(?:no|nope|nah|actually|wait(?=\s*,)|scratch\s+that\s+part)"
# ("actually" opens a clause that adds as often as one that replaces: "..., actually put the mug in the sink
# too"; its clause stays the grammar's, which names a correction it does not follow)
_CLAUSE_MARKERS = frozenset({"no", "nope", "nah", "scratch that part"})
# words that add to or order against what was said before: a clause with one replaces nothing for certain
_ADDS = re.compile(r"\b(?:too|also|as\s+well|first|again|another|additionally|either|instead\s+of)\b", re.I)
_MARKER = re.compile(
    rf"{_PAUSE}(?P<marker>(?:{_WORDS}|(?<=[,;—–.…-])\s*{_AFTER_PAUSE}(?=[\s,.!]|$))"
    rf"(?:[\s,:;.…—–-]*(?:{_WORDS}|(?:no|nope)(?=[\s,.!]|$)))*)"  # "actually no", "sorry, no"
    r"(?:\s*[,:;.…—–-]+)?\s*",
    re.I,
)
# a place with its preposition: a destination or a landmark (the grammar's lists, `prepositions`)
_PREP = re.compile(rf"^{preposition_pattern(PLACE_OR_LANDMARK)}\s", re.I)
_DET = re.compile(r"^(?:the|a|an|one\s+of\s+the|my|your)\s+", re.I)
_ARTICLE = re.compile(r"\b(?:the|a|an|one\s+of\s+the|my|your)\s+$", re.I)
# what a correction says runs to its clause's end: a sentence's end, a comma, an order word, or an "and"
# before a verb (`_said`)
_CLAUSE_END = re.compile(r"[.;!?]|,|\s(?:and\s+)?(?:then|before|after)\s|\sand\s+(?P<next>[a-z]+)", re.I)


_AGAIN = "say it once, as meant"


@dataclass(frozen=True)
class Roles:
    """The scene's types by what they can be: a thing to carry, a place that holds things."""

    carried: frozenset[str]
    holding: frozenset[str]

    def of(self, mention: Mention) -> set[str]:
        """The roles the mention's types can take ("thing", "place")."""
        types = set(mention.entry.types)
        return {r for r, ts in (("thing", self.carried), ("place", self.holding)) if types & ts}


def corrected(text: str, roles: Roles) -> str:
    """`text` with each self-correction applied (see the module docstring); raises HTTError naming a
    correction that cannot be applied with certainty, in the words the user typed (`in_own_words`)."""
    text = _not_this_that(_ACTUALLY_ADDS.sub("", text), roles)
    read = [text]  # the text as rewritten so far, where a refusal quotes it
    swaps: list[tuple[str, str]] = []
    try:
        return _corrected(text, roles, read, swaps)
    except HTTError as refused:
        raise HTTError(in_own_words(str(refused), read[-1], text, swaps)) from None


# "Actually, put the egg in the fridge too" opening a sentence: the word adds (its clause says "too"), and
# takes nothing back; a sentence without such a word ("Actually, put the egg in the fridge") may replace the
# one before, and is left (check 1 names "actually" where no reading takes it)
_ACTUALLY_ADDS = re.compile(
    r"(?:(?<=^)|(?<=[.!?]\s))actually\s*,\s*(?=[^.!?]*\b(?:too|also|as\s+well)\b)", re.I
)


# a quoted fragment of a message, as repr() writes it
_QUOTED = re.compile(r"'(?:[^'\\\n]|\\.)+'|\"(?:[^\"\\\n]|\\.)+\"")


def in_own_words(message: str, read: str, said: str, swaps: Sequence[tuple[str, str]] = ()) -> str:
    """`message` with each fragment it quotes from the rewritten text `read` that the user never typed
    quoted as the words of `said` that the fragment was rewritten from: a refusal quotes what the user
    typed. `swaps`: (clause as rewritten, as typed) pairs, which say it exactly ("put the mug in the
    cabinet" for "put it in the cabinet"); otherwise the stretch of `said` the fragment aligns with."""
    low_read, low_said = read.lower(), said.lower()
    if low_read == low_said:
        return message
    ops = difflib.SequenceMatcher(None, low_read, low_said, autojunk=False).get_opcodes()

    def own(m: re.Match[str]) -> str:
        frag = m[0][1:-1]
        at = low_read.find(frag.lower())
        if not frag.strip() or frag.lower() in low_said or at < 0:
            return m[0]
        typed = frag
        for new, old in swaps:
            typed = typed.replace(new, old)
        if typed.lower() in low_said:
            return repr(typed)
        start = next(j1 + (at - i1 if tag == "equal" else 0) for tag, i1, i2, j1, _ in ops if i1 <= at < i2)
        end = at + len(frag)
        stop = next(j1 + end - i1 if tag == "equal" else j2 for tag, i1, i2, j1, j2 in ops if i1 < end <= i2)
        return repr(said[start:stop].strip(" ,;")) if said[start:stop].strip(" ,;") else m[0]

    return _QUOTED.sub(own, message)


# "Put the egg in the fridge, not the egg, the apple": "not X, Y" closing a sentence, where X was said in it,
# takes X back and says Y instead (it was read as a ban on both in the fridge next to the egg's task: exit 1)
_NAME = r"(?:the|a|an|my|your)\s+[a-z]+(?:\s+[a-z]+)?"
_NOT_THIS_THAT = re.compile(
    rf"\s*(?:,|\s-+|—|–)\s*(?:(?:no|nope)\s*,?\s*)?not\s+(?P<wrong>{_NAME})\s*,\s*(?P<right>{_NAME})\s*(?=[.;!?]|$)",
    re.I,
)


def _not_this_that(text: str, roles: Roles) -> str:
    """`text` with each "not X, Y" closing a sentence applied: its X (said once in the sentence) is Y, where
    X and Y each name one thing that share a role (a thing to carry, a place); any other is refused by
    name."""
    for m in reversed(list(_NOT_THIS_THAT.finditer(text))):
        before = text[: m.start()]
        wrong, right = find_mentions(m["wrong"]), find_mentions(m["right"])
        head = _sentence_start(before)
        surface = wrong[0].surface.lower() if len(wrong) == 1 else ""
        said = [n for n in find_mentions(before) if n.char_start >= head and n.surface.lower() == surface]
        if len(said) != 1 or len(right) != 1 or not roles.of(wrong[0]) & roles.of(right[0]):
            words = m[0].strip(" ,-—–")
            raise HTTError(f"the correction {words!r} takes back no one thing said before it: {_AGAIN}")
        det = _ARTICLE.search(before[: said[0].char_start])
        cut = det.start() if det else said[0].char_start
        text = before[:cut] + m["right"] + before[said[0].char_end :] + text[m.end() :]
    return text


def _corrected(text: str, roles: Roles, read: list[str], swaps: list[tuple[str, str]]) -> str:
    start = 0
    while m := _MARKER.search(text, start):
        marker, after = " ".join(m["marker"].split()), text[m.end() :]
        cut = _said(after)
        said = after[:cut].strip()
        if said and (_has_verb(said) or not (_PREP.match(said) or find_mentions(said))):
            # a clause after a pause marker replaces the verb phrase before it; other clauses are the
            # grammar's ("what I mean is put ..."); words that name nothing ("I mean it") correct nothing
            # here (check 1 names a correction not followed)
            # ("actually no, put it ..." is "no, put it ...")
            bare = re.sub(r"^actually[\s,]+", "", marker.lower())
            clause = bare in _CLAUSE_MARKERS and _opens_with_verb(said)
            if clause and (added := _ADDS.search(after[: _sentence_end(after)])):
                unclear = f"whether {said!r} after {marker!r} replaces or adds ({added[0]!r}) is unclear"
                raise HTTError(f"{unclear}: {_AGAIN}")
            if clause and (swap := _clause_replaced(text[: m.start()], said, marker)) is not None:
                fixed = swap[0] + swap[1]
                text, start = fixed + after[cut:], len(fixed)
                read.append(text)
                swaps.append((swap[1], said))  # a refusal quotes the clause as typed
            else:
                start = m.end()
            continue
        if (restated := _restated(said, after[cut:])) is not None:
            # "put the spoon in the drawer, no wait, the cup, put the cup in the drawer": the clause that
            # names the correction again says it whole, and replaces the verb phrase before the marker
            if added := _ADDS.search(restated[0]):
                unclear = f"whether {restated[0]!r} after {marker!r} replaces or adds ({added[0]!r})"
                raise HTTError(f"{unclear} is unclear: {_AGAIN}")
            swap = _clause_replaced(text[: m.start()], restated[0], marker)
            if swap is not None:
                fixed = swap[0] + swap[1]
                text, start = fixed + after[cut + restated[1] :], len(fixed)
                read.append(text)
                swaps.append((swap[1], restated[0]))
                continue
        if not _PREP.match(said) and (name := _name_then_place(said)):
            if _named_last(text[: m.start()], name):  # "the book on the desk, actually no, the book in the
                said = said[len(name) :].strip()  # drawer": the same thing, so the place is what it corrects
            else:
                cut, said = cut - len(said) + len(name), name  # "the egg, no wait, the apple in the fridge"
        if not said and marker.lower() in ("no", "nope", "nah", "actually"):
            start = m.end()  # "..., actually." closing a clause corrects nothing
            continue
        fixed = _replaced(text[: m.start()], said, marker, roles)
        text, start = fixed + after[cut:], len(fixed)
        read.append(text)
    return text


_RESTATED = re.compile(r"^\s*,\s*")


def _restated(said: str, rest: str) -> tuple[str, int] | None:
    """The clause after a corrected name that opens with a verb and names it again ("the cup, put the cup in
    the drawer": "put the cup in the drawer"), and where it ends in `rest`; None for any other words."""
    named = find_mentions(said)
    if len(named) != 1 or _PREP.match(said) or not (lead := _RESTATED.match(rest)):
        return None
    end = lead.end() + _said(rest[lead.end() :])
    clause = rest[lead.end() : end].strip()
    if not clause or not _opens_with_verb(clause.split()[0]):
        return None
    again = [n for n in find_mentions(clause) if n.surface.lower() == named[0].surface.lower()]
    return (clause, end) if again else None


def _has_verb(said: str) -> bool:
    """Does a word of `said` outside its names say an action ("is put the apple ...", not "the microwave")?"""
    spans = [(n.char_start, n.char_end) for n in find_mentions(said)]
    words = [(w, a) for w, a, _ in tokens(said) if not any(s <= a < e for s, e in spans)]
    return any(_opens_with_verb(w) for w, _ in words)


def _name_then_place(said: str) -> str | None:
    """The name opening `said` where a place follows it ("the apple in the fridge": "the apple")."""
    article = len(said) - len(_DET.sub("", said))
    named = find_mentions(said)
    if len(named) < 2 or named[0].char_start != article:
        return None
    if not _PREP.match(said[named[0].char_end :].lstrip()):
        return None
    return said[: named[0].char_end]


def _named_last(before: str, name: str) -> bool:
    """Is `name` ("the book") the thing last named in the sentence before the marker (its words, as said)?"""
    head = _sentence_start(before)
    things = [n for n in find_mentions(before) if n.char_start >= head and not _after_preposition(before, n)]
    return bool(things) and things[-1].surface.lower() == _DET.sub("", name).lower()


def _said(after: str) -> int:
    """Where the words a correction says end in the text `after` its marker."""
    for end in _CLAUSE_END.finditer(after):
        if not end["next"] or _opens_with_verb(end["next"]):
            return end.start()
    return len(after)


def _replaced(before: str, said: str, marker: str, roles: Roles) -> str:
    """`before` with the part the correction `said` replaces (in its sentence) swapped for it."""
    if not said:
        raise HTTError(f"the correction {marker!r} says nothing in place of what it corrects: {_AGAIN}")
    head = _sentence_start(before)
    if not before[head:].strip() and before.strip():  # "... in the microwave. Sorry, I mean the potato"
        head = _sentence_start(before.rstrip()[:-1])  # a correction opening a sentence: the one before
    found = [n for n in find_mentions(before) if n.char_start >= head]
    if _PREP.match(said):  # a place with its preposition
        places = [n for n in found if _after_preposition(before, n)]
        if not places:
            raise HTTError(f"the correction {marker!r} {said!r} corrects no place said before it")
        return before[: _preposition_start(before, places[-1])] + said
    named = find_mentions(said)
    article = len(said) - len(_DET.sub("", said))
    if len(named) != 1 or (named[0].char_start, named[0].char_end) != (article, len(said)):
        raise HTTError(f"the correction {marker!r} {said!r} names not one thing or place: {_AGAIN}")
    # the roles the correction can take that a name before it has ("the cup" after "put the mug," with
    # no place said yet: a thing); more than one is unclear ("the pan in the sink, I mean the pot")
    want = roles.of(named[0]) & {_role_at(before, n) for n in found}
    candidates = [n for n in found if _role_at(before, n) in want]
    # "the remote by the desk lamp, sorry, floor lamp": one name before it with the same head noun is what it
    # replaces, whatever the roles (users_h195dev)
    kin = [n for n in found if n.surface.lower().split()[-1] == named[0].surface.lower().split()[-1]]
    if len(want) != 1 and len(kin) == 1:
        want, candidates = {_role_at(before, kin[0])}, kin
    if len(want) != 1:
        what = " or ".join(repr(n.surface) for n in found[-2:]) or "nothing said before it"
        unclear = f"which words the correction {marker!r} {said!r} replaces is unclear ({what})"
        raise HTTError(f"{unclear}: {_AGAIN}")
    last = candidates[-1]
    det = _ARTICLE.search(before[: last.char_start])
    return before[: det.start() if det else last.char_start] + said + before[last.char_end :]


# what keeps a verb phrase from being one task to replace: a negation before its verb, a list or an order
# in it
_NEGATED = re.compile(r"\b(?:not|never|don'?t|do\s+not|doesn'?t|won'?t)\s+$", re.I)
_SEVERAL = re.compile(r",|\b(?:and|or|then|before|after|but)\b", re.I)
_PRONOUN = re.compile(r"\b(?:it|them)\b", re.I)
_OBJECT_PRONOUN = re.compile(r"^\S+\s+(?:it|them)\b", re.I)


def _clause_replaced(before: str, said: str, marker: str) -> tuple[str, str] | None:
    """`before` without its last verb phrase, and the clause `said` that replaces it ("wash the cloth and
    hang it... no, put it on the shelf": "hang it" goes); the one thing that phrase names stands for a
    pronoun of `said` ("hang the apple... no, put it in the fridge": the apple). None where no verb is said
    before the marker in its sentence (the grammar reads it, as before); HTTError where the part replaced is
    unclear."""
    head, named = _sentence_start(before), find_mentions(before)
    spans = [(n.char_start, n.char_end) for n in named]
    verbs = [a for w, a, _ in tokens(before) if a >= head and _opens_with_verb(w)]
    verbs = [a for a in verbs if not any(s <= a < e for s, e in spans)]
    if not verbs:
        return None
    phrase = before[verbs[-1] :].rstrip()
    if _NEGATED.search(before[: verbs[-1]]):
        raise HTTError(f"the correction {marker!r} {said!r} follows a negated request ({phrase!r}): {_AGAIN}")
    if _SEVERAL.search(phrase):
        unclear = f"which words the correction {marker!r} {said!r} replaces is unclear ({phrase!r})"
        raise HTTError(f"{unclear}: {_AGAIN}")
    things = [n for n in named if n.char_start >= verbs[-1] and not _after_preposition(before, n)]
    if _PRONOUN.search(said) and things:
        # the pronoun stands for the phrase's thing only as the object of its verb ("put it in ..."), not
        # in a place ("put the apple next to it")
        if len(things) > 1 or not _OBJECT_PRONOUN.match(said):
            unclear = f"which thing {said!r} after {marker!r} refers to is unclear ({phrase!r})"
            raise HTTError(f"{unclear}: {_AGAIN}")
        det = _ARTICLE.search(before[: things[0].char_start])
        thing = before[det.start() if det else things[0].char_start : things[0].char_end]
        said = _PRONOUN.sub(thing, said, count=1)
    return before[: verbs[-1]], said



def _sentence_end(after: str) -> int:
    """Where the sentence that `after` opens ends (an ellipsis ends no sentence)."""
    end = re.search(r"(?<!\.)[.!?;](?!\.)", after)
    return end.start() if end else len(after)


def _sentence_start(before: str) -> int:
    """Where the sentence that ends at `before`'s end begins (an ellipsis ends no sentence)."""
    ends = [m.end() for m in re.finditer(r"(?<!\.)[.!?;](?!\.)", before)]
    return ends[-1] if ends else 0


# a place's preposition and article, just before its name
_BEFORE_PLACE = re.compile(
    r"\b(?:in|into|inside|on|onto|on\s+top\s+of|to|under|at|beside|next\s+to)\s+(?:the\s+|a\s+|an\s+)?$", re.I
)


def _after_preposition(text: str, mention: Mention) -> bool:
    return bool(_BEFORE_PLACE.search(text[: mention.char_start]))


def _preposition_start(text: str, mention: Mention) -> int:
    m = _BEFORE_PLACE.search(text[: mention.char_start])
    return m.start() if m else mention.char_start


def _role_at(text: str, mention: Mention) -> str:
    return "place" if _after_preposition(text, mention) else "thing"


def _opens_with_verb(said: str) -> bool:
    first = said.split()[0].lower()
    return any(c.startswith("verb_") for c in categories(first))


def household_roles(world: World) -> Roles:
    """The roles of a floor plan's types, from its objects' affordances."""
    objects = world.objects.values()
    return Roles(
        frozenset(o.type for o in objects if o.pickupable),
        frozenset(o.type for o in objects if o.affordances.receptacle),
    )
