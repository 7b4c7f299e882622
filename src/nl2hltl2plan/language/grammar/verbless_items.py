"""Lists with the verb left out (issue 28), read as a careful reader means them; `sentences.supply_put`
writes in the verbs they leave out.

- a verbless placement: names, with counts and state words ("two rags", "a cold tomato", "one washed
  cloth"), then in/into/to/onto/on and a place: "put" goes before it (the state word is the treatment, as
  after "put");
- a list that mixes placements with verbless examinations ("the bowl under the desk lamp, two keychains in
  the drawer, then the pencil under the same lamp"): each item gets the verb its own preposition says
  ("look at" under a lamp, "put" before a place), where it differs from the item before. A verb carried
  over to an item of the other kind is a wrong reading ("look at the bowl under the lamp, two keychains in
  the drawer" looked at the keychains), so a verb said first is written again where the kind changes;
- list items the rules read only with a verb of their own: a container's pair ("a fork in a bowl with the
  bowl on the counter"), a dash between a thing and its place ("two books - desk", as "->"), "the phone
  under it too" after an examination (under the lamp named last), "..., light on" after the lamp;
- "X to the cart and two sponges as well": the place carries over to the second thing, because "too" / "as
  well" / "also" says so; without it the second thing has no place, and is left to be refused.
"""

from __future__ import annotations

import re

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.grammar import word_tables as G
from nl2hltl2plan.language.grammar.phrases import COLOURS, tokens
from nl2hltl2plan.language.grounding import find_mentions

_PLACE_PREPS = ("in", "into", "to", "onto", "on")
# a count names the objects too ("Two rags to the shelf", "two phones to the sofa": h190; a notes-app list's
# "2 soap bars in the tub": users_h195dev)
_LIST_WORDS = frozenset(
    {"the", "a", "an", "and", "or", "both", ",", "one", "two", "three", "four", "2", "3", "4"}
    | {"another", "more"}  # "another cloth in the tub", "two more books to the desk"
)
_OTHER_ONE = frozenset({"other", "second", "third", "2nd", "3rd"})
_COUNTS = frozenset({"one", "two", "three", "four", "2", "3", "4", "both", "all"})
# a state word after the first word gives the treatment ("a cold tomato", "one washed cloth"); first, a word
# that is also a verb opens a clause ("clean the mug in the sink")
_STATES = frozenset(G.STATE_WORDS)
# the lamp an examination is under, ending its item: "under the desk lamp", "under the same lamp", with the
# lamp said to be on after it ("..., light on", "with the lamp switched on"), which the rules read
_UNDER_LAMP = re.compile(
    r"\s*,?\s*(?:under|beneath|in\s+the\s+light\s+of)\s+(?:the|a|that|this)\s+(?:same\s+)?(?:[a-z]+\s+)?"
    r"(?:lamp|light)(?:\s*,?\s*(?:with\s+)?(?:the\s+|it\s+)?(?:lamp\s+|light\s+)?(?:switched\s+|turned\s+)?on)?\s*$",
    re.I,
)
# "the phone under it too" after an examination: the same lamp
_UNDER_IT = re.compile(r"\s*,?\s*under\s+it(?:\s+too|\s+as\s+well)?\s*$", re.I)
_UNDER_IT_SAID = re.compile(r"\s+under\s+it(?P<too>\s+too|\s+as\s+well)?(?=\s*(?:[,.;!?]|$))", re.I)
_LAMP_NAME = re.compile(r"\b(?:the|a)\s+(?:desk\s+|floor\s+)?(?:lamp|light)\b", re.I)
# "a fork in a bowl, the bowl on the counter" / "... with the bowl on the counter": one task, the container
# carried (a verb must open the item after it, which the rules would take into the pair); the container may
# have words before its name ("a pen in the black mug with the mug on the dresser": h252)
_PAIR = re.compile(
    r"^(?P<x>.+?)\s+(?:in|into|on|onto|inside)\s+(?:a|an|the|your)\s+(?:[a-z]+\s+){0,2}?(?P<c>[a-z]+)\s*"
    r"(?:,|\s+with|\s+and)\s+(?:the|that|your)\s+(?P=c)\s+(?:in|into|on|onto|inside)\s",
    re.I,
)
_WITH_CONTAINER = re.compile(  # (", with the mug on the desk": h212; "with the mug still on the desk")
    r"\b(?P<c>[a-z]+)\s*,?\s+with\s+(?P<d>the|that)\s+(?P=c)(?:\s+(?P<w>[a-z]+))??"
    r"(?=\s+(?:in|into|on|onto|inside)\s)",
    re.I,
)
# "a bowl, with the other bowl on the dresser": a second container, which the one task cannot move
_WITH_OTHER = re.compile(r"\b(?P<c>[a-z]+)\s*,?\s+with\s+(?:the\s+other|another)\s+(?P=c)\b", re.I)
# what may stand between the container and its place and say nothing a task must do ("still", "then")
_PASSING = frozenset("still then later afterwards now also".split())
# "the remote - coffee table": a dash between a thing and a place says where it goes, as "->" does
_DASH = re.compile(r"(?P<x>[^,;:\-]+?)\s+[-\u2013]\s+(?P<y>[^,;:\-]+?)(?=\s*(?:,|$))")
# ", lamp on" after the lamp: the rules read "with the lamp on" (a bare "lamp on" they take for a thing)
_LAMP_ON = re.compile(
    r"\b(?P<l>lamp|light)\s*,\s*(?:the\s+)?(?:lamp|light)\s+(?:switched\s+|turned\s+)?on\b", re.I
)
# the verb said before a list's first item: "look at the bowl under the lamp, two keychains in the drawer"
_SAID_VERB = re.compile(r"^(?:(?P<look>look\s+at|examine|inspect|check\s+out)|put|place|set)\s+", re.I)
# where one list item ends and the next begins
_GAP = re.compile(r"\s*,\s*(?:and\s+)?(?:then\s+)?|\s+(?:and\s+)?then\s+|\s+and\s+", re.I)
_VERB = {"put": "put ", "pair": "put ", "look": "look at "}
# "X to the cart and two sponges as well": the second thing, said with "too" where its list item ends
_TOO = re.compile(
    r"(?:^|(?<=, ))(?P<lead>(?:and\s+)?(?:then\s+)?)(?P<x>[^,;]+?)\s+"
    r"(?P<dest>(?:in|into|on|onto|to)\s+(?:the|a|an|that|this)\s+[a-z]+(?:\s+[a-z]+)?)\s*,?\s+and\s+"
    r"(?P<y>(?:(?:the|a|an|two|three|both|2|3)\s+)?[a-z]+(?:\s+[a-z]+){0,3}?)\s*,?\s+(?:too|as\s+well|also)"
    r"(?=\s*(?:,|$))",
    re.I,
)


def names_object_before(text: str, at: int) -> bool:
    """Does a name end right before `at` (spaces aside)?"""
    mentions = find_mentions(text[:at])
    return bool(mentions) and mentions[-1].char_end == len(text[:at].rstrip())


# what a container holds, said after it: "the pot with the knife in it", "a box with a card inside" (h238)
_HELD = (
    r"\s+(?:with|containing|holding)\s+(?:with\s+)?(?P<held>(?:the|a|an|two|some)\s+[a-z]+(?:\s+[a-z]+){0,3}?)"
    r"(?:\s+(?:in|on|inside)\s+(?:it|them)|\s+inside)?"
)
_HELD_AFTER = re.compile(rf"{_HELD}\s*$", re.I)


def names_holder_before(text: str, at: int) -> bool:
    """Does a name end right before `at`, or a name and the thing it holds ("the pot with the knife in it
    goes on the table": the pot goes there, with the knife in it), or a name and its slice ("a potato slice
    goes in the fridge": left with "goes", the sentence took the verb of the one before it)?"""
    if names_object_before(text, at):
        return True
    if (cut := _SLICE_END.search(text[:at].rstrip())) is not None and names_object_before(text, cut.start()):
        return True
    held = _HELD_AFTER.search(text[:at])
    return held is not None and names_object_before(text, held.start()) and bool(find_mentions(held["held"]))


def _only_names(body: str, end: int) -> bool:
    """Are the words before `end` names, counts, articles and state words only, a name last?"""
    named = [(m.char_start, m.char_end) for m in find_mentions(body[:end])]
    words = [(w, s) for w, s, _ in tokens(body) if s < end]
    listed = all(
        # a source said of a name is where it is: "the book from the bed" (`landmarks.subject_sources`)
        w in _LIST_WORDS or (k and w in _STATES | COLOURS | {"from"}) or any(a <= s < b for a, b in named)
        # "2 red cloths", "2 of the pink rags" (h293): a colour, and a part after its count, name no verb
        or (w == "of" and k and words[k - 1][0] in _COUNTS)
        # "the other card on the armchair", "a second card on the shelf": a thing of a type said before
        or (w in _OTHER_ONE and k and words[k - 1][0] in {"the", "a", "an"})
        or _slice_word(words, k, named)
        for k, (w, s) in enumerate(words)
    )
    head = _SLICE_END.sub("", body[:end].rstrip().rstrip(","))  # "one washed cloth, in the tub"
    return bool(words) and listed and names_object_before(head, len(head))


# a slice of a named thing ("a warm apple slice", "a cold slice of the bread", h231): the slice is the item
_SLICE_END = re.compile(r"\s+(?:slice|piece)s?$", re.I)


def _slice_word(words: list[tuple[str, int]], k: int, named: list[tuple[int, int]]) -> bool:
    """Is the k-th word a slice noun right after its name ("apple slice") or before any name of its list item
    ("a slice"), or the "of" of "slice of"? ("toast a slice of bread" is a verb and its thing: "toast" names
    bread too.)"""
    w, at = words[k]
    if not k or not (w in G.SLICE_NOUNS or (w == "of" and words[k - 1][0] in G.SLICE_NOUNS)):
        return False
    slice_at = at if w != "of" else words[k - 1][1]
    item_at = max((s for x, s in words if x in {"and", "or", ","} and s < slice_at), default=-1)  # its item's
    ends = [b for a, b in named if item_at < a < slice_at]
    return not ends or (w != "of" and ends[-1] == words[k - 1][1] + len(words[k - 1][0]) and len(ends) == 1)


# a container and what it holds, then its place: "the pot with the knife in it on the table" (h238)
_HOLDER_PLACED = re.compile(rf"^(?P<x>.+?){_HELD}\s+(?=(?:in|into|to|onto|on)\s)", re.I)


def verbless_placement(body: str) -> bool:
    """Does the sentence start with object names only ("green apple and the orange", "a cold tomato"; a
    container with what it holds) and go on with in/into/to/onto/on and a place?"""
    if (holder := _HOLDER_PLACED.match(body)) and _only_names(holder["held"], len(holder["held"])):
        return _only_names(holder["x"], len(holder["x"])) and bool(find_mentions(body[holder.end() :]))
    words = tokens(body)
    k = next((i for i, (w, _, _) in enumerate(words) if w in _PLACE_PREPS), None)
    if not k:
        return False
    return _only_names(body, words[k][1]) and bool(find_mentions(body[words[k][2] :]))


def _kind(item: str, before: str | None) -> str | None:
    """ "put" for a verbless placement, "pair" for a thing put in a container and the container placed, "look"
    for a verbless examination under a lamp (or "under it" after one), else None."""
    lamp = _UNDER_LAMP.search(item) or (_UNDER_IT.search(item) if before == "look" else None)
    if lamp:
        return "look" if _only_names(item, lamp.start()) else None
    pair = _PAIR.match(item)
    if pair and _only_names(pair["x"], len(pair["x"])):
        return "pair"
    return "put" if verbless_placement(item) else None


def _items(body: str) -> list[tuple[int, int, str]] | None:
    """(gap start, start, kind) of each item of a list whose every item is verbless, shortest items first ("a
    heated egg and a cold lettuce on the table" is one item; a container's pair is two joined); None where
    some words are no such item."""
    cuts = [(m.start(), m.end()) for m in _GAP.finditer(body)] + [(len(body), len(body))]
    out: list[tuple[int, int, str]] = []
    gap_at, start, before = 0, 0, None
    for end, after in cuts:
        if out and out[-1][2] == "put" and _kind(body[out[-1][1] : end], None) == "pair":
            out[-1] = (*out[-1][:2], "pair")
            gap_at, start = end, after
            continue
        if out and out[-1][2] == "look" and _kind(body[out[-1][1] : end], None) == "look":  # "..., light on"
            gap_at, start = end, after
            continue
        kind = _kind(body[start:end], before)
        if kind:
            out.append((gap_at, start, kind))
            gap_at, start, before = end, after, kind
    return out if start >= len(body) and out else None


def _dash_place(m: re.Match[str]) -> str:
    y = m["y"]
    named = find_mentions(y)
    whole = bool(named) and named[-1].char_end == len(y) and _only_names(y, len(y))
    return f"{m['x']} onto {y}" if whole and _only_names(m["x"], len(m["x"])) else m[0]


def _place_shared(m: re.Match[str]) -> str:
    """ "the pencil on the desk and the alarm clock too" -> "the pencil and the alarm clock on the desk"."""
    if not _only_names(m["x"], len(m["x"])) or not names_object_before(m["y"], len(m["y"])):
        return m[0]
    return f"{m['lead']}{m['x']} and {m['y']} {m['dest']}"


def _container_placed(m: re.Match[str]) -> str:
    """ "a mug, with the mug (still) on the desk" -> "a mug and the mug on the desk"; another word there
    ("with the box empty on the sofa") says what no task does: refused by name, never dropped."""
    if m["w"] and m["w"].lower() not in _PASSING:
        raise HTTError(f"{m['w']!r} in {m[0]!r}: no task says this of the {m['c']}")
    return f"{m['c']} and {m['d']} {m['c']}"


def verbs_written(body: str) -> str | None:
    """A sentence with the verbs its list leaves out written in (see the module's note), or None where it is
    no such list. A list of placements alone is left to `supply_put`'s one verb, which carries over; a verb
    said before the first item stays, and is written again only where an item of the other kind follows."""
    if other := _WITH_OTHER.search(body):
        raise HTTError(f"{other[0]!r}: a second {other['c']}, which no task moves: say what to do with it")
    said = _WITH_CONTAINER.sub(_container_placed, _DASH.sub(_dash_place, body))
    said = _TOO.sub(_place_shared, said)
    verb = _SAID_VERB.match(said)
    head = verb.end() if verb else 0
    items = [(gap_at + head, start + head, kind) for gap_at, start, kind in _items(said[head:]) or []]
    kinds = {kind for *_, kind in items}
    said_kind = "look" if verb and verb["look"] else "put"
    if not items or kinds == {"put"} or (verb and (len(kinds) < 2 or items[0][2] != said_kind)):
        return ("put " + said if verbless_placement(said) else said) if said != body else None
    out, pos, last = [], 0, said_kind if verb else ""
    for gap_at, start, kind in items:
        if kind == last and kind != "pair" or start == head and verb:
            continue
        gap = said[gap_at:start]
        # a bare comma before a verb reads as "then" (the grammar's order of comma clauses): a list's items
        # are in no order, as sentences with no order word are
        joined = gap if not start or re.search(r"\b(?:and|then)\b", gap, re.I) else "; "
        out.append(said[pos:gap_at] + joined + _VERB[kind])
        pos, last = start, kind
    return _lamp_named(_LAMP_ON.sub(r"\g<l> with the lamp on", "".join(out) + said[pos:]))


def _lamp_named(text: str) -> str:
    """ "..., then the phone under it too": under the lamp named last before it (a bare "it" or "the same
    lamp" the rules take for any lamp where the room has two)."""

    def named(m: re.Match[str]) -> str:
        lamps = _LAMP_NAME.findall(text[: m.start()])
        return f" under {lamps[-1]}{m['too'] or ''}" if lamps else m[0]

    return _UNDER_IT_SAID.sub(named, text)
