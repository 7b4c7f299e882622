"""Counted and ordinal references to things of a type named before (issue 28, h185), written out as the
forms the grammar and check 1 read. ALFRED's tasks each take any thing of their type, so a careful reader
of "put one X on A, then the remaining two in B" asks for one X on A and two X in B:

- "the remaining two (Xs)", "the other two", "both of the others", "both of the other Xs" -> "two other Xs";
- "two others", "another two (Xs)", "two other sets" / "two more slices" (a measure word of the thing before:
  "a set of keys", "a slice of apple") -> "two other Xs" ("two other sets of keys", "two more slices of
  apple"); "the other set" / "one more set" after "two sets of keys" -> "the other set of keys" / "another
  set of keys";
- "the rest of the Xs", "the remaining Xs", "the rest of them", "the others" -> "all the other Xs", which
  `counts.take_every_instance` reads as what the scene holds less what the other tasks on X take; "the
  remaining X" (one) -> "the other X";
- "the other one" after "one of the Xs" / "one X" / "an X" -> "the other X" (a second task on X);
- "the third X", "a second one" after an X -> "a third X", "a second X" (the word said stays, for a
  refusal to name); "the last X / one", "one more (X)" -> "another X";
- a count said after a bare plural ("put remotes on the sofa, two of them", "candles - both -",
  "books and mugs, two of each") -> before it ("put two remotes on the sofa");
- "the one you (just) used" after a lamp -> that lamp.

The elided noun is the last thing named before the words (not a place, not a lamp); "the other one", the
elided counts and the elided ordinals need that thing said as one of several ("one X", "an X", "one of the
Xs", a plural): after "the apple", "the other one" stays as written and is refused
(`referents.another_thing`), and "the last one" stays unread.

>>> counted_references("Put one salt shaker on the table, then put the remaining two in a cabinet.")
'Put one salt shaker on the table, then put two other salt shakers in a cabinet.'
>>> counted_references("Put remotes on the sofa, two of them.")
'Put two remotes on the sofa.'
"""

from __future__ import annotations

import re
from functools import lru_cache

from nl2hltl2plan.language.content_words import categories
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS
from nl2hltl2plan.language.grounding import LAMPS, Mention, find_mentions, plural_name, tokens

_N = r"(?:two|three|four|five|both|2|3|4|5)"
_PLACE_WORDS = frozenset("in into on onto inside to under by near at beside from next behind".split())
_SKIPPED = frozenset({"the", "a", "an", "other"})  # the words between a preposition and its place
_ONE_OF = frozenset("one a an another each single".split())
# "the remaining two (pencils)", "the other two", "both of the other(s) (spoons)", "both others"
_COUNTED_OTHER = re.compile(
    rf"\b(?:the\s+(?:remaining|other)\s+(?P<n>{_N})|both\s+(?:of\s+the\s+)?other(?P<s>s)?)\b", re.I
)
# "two others", "two other sets", "two more slices", "another two", "a couple more", "another pair", "two more
# of them": `n` more things of the type before (h237)
_COUNTED_MORE = re.compile(
    r"\b(?:(?P<n>two|three|four|2|3|4|a\s+couple)\s+(?:(?P<others>others)|(?P<kind>other|more))"
    r"|(?:another|a\s+further)\s+(?P<n2>two|three|four|2|3|4|pair|couple))\b(?:\s+of\s+(?:them|those|these)\b)?"
    r"(?:\s+(?P<w>[a-z]+)\b)?",
    re.I,
)
# the words after "two others" that end its noun phrase: a place, a verb of placing, or the clause's end
_AFTER_COUNT = frozenset("in into inside on onto to under at by near next go goes too also there".split())
_SLICE_UNITS = frozenset("slices pieces".split())
# "the rest of the (Xs)", "the rest of them", "the remaining (ones|Xs)", "the others"
# not "before the others" / "after the rest": the other tasks (an order, `order_relations._OTHERS`; h190)
_REST = re.compile(
    r"(?<!\bbefore\s)(?<!\bafter\s)\bthe\s+(?:rest\s+of\s+(?:the\b|them\b)|remaining\b(?:\s+ones\b)?|others\b)",
    re.I,
)
# "the other one", or "the other" alone before a place or the clause's end
_OTHER_ONE = re.compile(
    r"(?<!after\s)\bthe\s+other(?:\s+one\b|(?=\s*(?:$|[,.;!?]|(?:in|into|on|onto|inside|to|too|as\s+well|goes|go)\b)))",
    re.I,
)
# "one more" said of a thing, not "one more time" / "one more step": the one family of words for a second
# thing of a type with "another" (`another_said` below, `referents.another_thing`)
ONE_MORE = r"one\s+more\b(?!\s+(?:time|step|thing|task|minute|second)s?\b)"
# "the third (X|one)", "the last (X|one)", "a second one", "one more (X)"; not "the last two can be done
# any time": tasks counted by their place in the list (`order_remarks`)
_ANOTHER = re.compile(
    r"\b(?:the\s+(?:second|third|fourth|fifth|last)(?!\s+(?:two|three|2|3)\s+(?:can|in|ones|tasks|jobs|things)\b)"
    r"|(?:a|one)\s+(?:second|third|fourth|fifth)(?=\s+one\b)|another(?=\s+one\b)"
    rf"|{ONE_MORE})(?:\s+one\b)?",
    re.I,
)
# "another" / "one more" said of a thing; `alone`: its noun (one or two words) closes the clause
_ANOTHER_SAID = re.compile(
    rf"\b(?:another\b|{ONE_MORE})"
    r"(?P<alone>(?=\s+(?!one\b)[a-z]+(?:\s+[a-z]+)?\s*(?:too|as\s+well|also)?\s*(?:[,.;!?]|$)))?",
    re.I,
)
# "one more" with no verb of its own ("..., then one more", "and one more on the sofa"): not another X here
_MORE_WITHOUT_VERB = re.compile(r"(?:[,;]|\b(?:then|and|also|plus))\s*$", re.I)
# "one of the two tomatoes" is one tomato, "two of the three cups" two (the count is of those there, not of
# the task's: the task took three cups at exit 0); "both of the three cups" keeps "both" by the count it
# contradicts ("both three cups"), which check 1 names
_ONE_OF_N = re.compile(rf"\b(?P<k>one|two|three|four|both|[1-5])\s+of\s+the\s+(?P<n>{_N}\s+)", re.I)
_JUST_USED = re.compile(r"\bthe\s+one\s+you(?:'ve|\s+have)?\s+(?:just\s+)?used\b", re.I)
# a count after a bare plural: ", two of them", " - two -", "(both)", ", also two", ", two of each"
_COUNT_AFTER = re.compile(
    rf"\s*(?:,|:|\s-+|\s—|\()\s*(?:also\s+|just\s+)?(?P<n>{_N})(?:\s+of\s+(?P<of>them|those|these|each))?"
    r"(?:\s*(?:-+|—|\))(?=\s))?(?=\s*(?:[,.;!?)]|$|(?:and|go|goes|then)\b))",
    re.I,
)


@lru_cache(maxsize=1024)  # `everyday`, `counts` and `referents` each ask it of every reading's text
def counted_references(text: str) -> str:
    """`text` with the counted and ordinal references above written out (a pure function of the text)."""
    text = _ONE_OF_N.sub(_count_of_those, text)
    rules = (_counts_after, _lamp_used, _counted_others, _counted_more, _other_unit)
    for rule in (*rules, _rest, _other_one, _another, _treated_one, _slice_of_before, _pieces_of_two):
        text = rule(text)
    return text


def _count_of_those(m: re.Match[str]) -> str:
    """ "two of the three cups" -> "two of the cups"; "both of the three cups" -> "both three cups"; a count
    more than those there ("three of the two mugs") stays as said, for check 1 to name."""
    k, n = _value(m["k"]), _value(m["n"])
    if m["k"].lower() == "both" and n != 2:
        return f"{m['k']} {m['n']}"
    return m[0] if k > n else m[0][: m.start("n") - m.start()]


def _value(word: str) -> int:
    """The number a count word says ("both" is two), 0 for none (as `counts.count_value`)."""
    w = word.strip().lower()
    cats = [c for c in categories(w) if c.startswith("count_")]
    return 2 if w == "both" else int(w) if w.isdigit() else int(cats[0].removeprefix("count_")) if cats else 0


def another_said(text: str) -> str:
    """ "one more" said of a thing is "another", which `drafts` reads as a second thing of the type just
    placed ("a remote on the sofa and one more on the armchair"); after "then" it is left to `everyday`'s
    count with its noun left out ("then one more (in the cabinet)"). With no verb and no place of its own
    after "then" / "and" ("put an apple in the fridge, then another apple"), either is "one more X": the
    task before again, for a second X (the second thing was dropped, unread and unnamed); "then another
    one" stays, and is refused as a second thing not named."""

    def sub(m: re.Match[str]) -> str:
        joined = re.search(r"\b(then|and)\s$", text[: m.start()], re.I)
        if joined and m["alone"] is not None:
            return "one more"
        if m[0][:1].lower() == "o" and not (joined and joined[1].lower() == "then"):
            # "then wash one more and put it ...": its noun left out, the thing named last (h293)
            x = _antecedent(text, m.start(), one_of=False) if _NOUN_LEFT.match(text, m.end()) else None
            return _cased("another" + (f" {_singular(x, text)}" if x is not None else ""), m[0])
        return m[0]

    return _ANOTHER_SAID.sub(sub, text)


_NOUN_LEFT = re.compile(r"\s+and\s+(?:put|place|set|leave|stick|drop)\b", re.I)


def _things(text: str) -> list[Mention]:
    """The mentions of things a task may act on: not a lamp, not a place after a preposition."""
    toks = tokens(text)
    out = []
    for m in find_mentions(text):
        # the word before it, past determiners and describing words ("in the blue recycling bin"); "look at X"
        # names a thing
        said = [
            i for i in range(max(0, m.start - 3), m.start)
            if toks[i][0] in _PLACE_WORDS or (toks[i][0] not in _SKIPPED and categories(toks[i][0]))
        ]
        place = bool(said) and toks[said[-1]][0] in _PLACE_WORDS
        place = place and not (toks[said[-1]][0] == "at" and toks[said[-1] - 1][0].startswith("look"))
        if not m.entry.generic and not set(m.entry.types) & LAMPS and not place:
            out.append(m)
    return out


def _antecedent(text: str, at: int, one_of: bool) -> Mention | None:
    """The last thing named before character `at`; with `one_of`, only one said as one of several."""
    toks = tokens(text)
    things = [m for m in _things(text) if m.char_end <= at]
    if not things:
        return None
    m = things[-1]
    said = [w for w, _, _ in toks[max(0, m.start - 4) : m.start]]
    return m if not one_of or set(said) & _ONE_OF or m.plural else None


def _plural(m: Mention) -> str:
    """The words that name several of the mention's things ("salt shakers", "keys" -> "key chains")."""
    return m.surface if m.plural else plural_name(m.entry.phrase) or m.surface


def _singular(m: Mention, text: str = "") -> str:
    """The words that name one of the mention's things; "bottle of hand soap" whole, where the mention is the
    last noun of such a phrase ("the other soap" read a bar of soap)."""
    head = [x for x in _things(text) if x.char_end < m.char_start] if text else []
    if head and not m.plural and _OF_PHRASE.fullmatch(text[head[-1].char_end : m.char_start]):
        return text[head[-1].char_start : m.char_end]
    return m.entry.phrase if m.plural else m.surface


_OF_PHRASE = re.compile(r"\s+of\s+(?:[a-z]+\s+)?", re.I)


def _cased(new: str, old: str) -> str:
    return new[:1].upper() + new[1:] if old[:1].isupper() else new


def _noun_at(text: str, at: int) -> Mention | None:
    """The mention that starts right after character `at` (past blanks)."""
    start = len(text) - len(text[at:].lstrip())
    return next((m for m in find_mentions(text) if m.char_start == start), None)


def _counted_others(text: str) -> str:
    def sub(m: re.Match[str]) -> str:
        n = "two" if m["n"] is None or m["n"].lower() == "both" else m["n"]
        noun = _noun_at(text, m.end()) if not m["s"] else None
        if noun is not None and noun.plural:
            return _cased(f"{n} other", m[0])
        x = _antecedent(text, m.start(), one_of=True)
        return _cased(f"{n} other {_plural(x)}", m[0]) if x else m[0]

    return _COUNTED_OTHER.sub(sub, text)


def _counted_more(text: str) -> str:
    """ "two others" / "another two" / "two other sets" after "a set of keys": "two other sets of keys" (the
    measure word said, or none, names the thing before); "another two spoons": "two other spoons"."""

    def sub(m: re.Match[str]) -> str:
        n, word = (m["n"] or m["n2"]).lower(), (m["w"] or "").lower()
        n = "two" if n in ("a couple", "pair", "couple") else n
        rest = m[0][: m.start("w") - m.start()] if m["w"] else m[0]  # the words before the noun or place
        noun = _noun_at(text, m.start("w")) if m["w"] else None
        # "another two spoons": "two other spoons"; "two more hand towels" stays ("bars" may be a measure)
        if noun is not None and noun.plural and (m["n2"] or noun.surface.lower() != word):
            return _cased(f"{n} other", m[0]) + m[0][len(rest) - 1 :] if m["n2"] else m[0]
        x = _antecedent(text, m.start(), one_of=False)
        if x is None or text[m.end() :].lstrip().lower().startswith("of "):
            return m[0]  # "two more slices of apple": said whole
        other = _cased(f"{n} {(m['kind'] or 'other').lower()}", m[0])
        unit = "" if word in _AFTER_COUNT else word  # a measure word said ("sets", "slices"), or none
        if _sliced_before(text, x) and (not unit or unit in _SLICE_UNITS):
            named = f"{unit or 'slices'} of {x.entry.phrase}"
        elif not unit or (x.entry.phrase.split()[0] + "s" == unit and " of " in x.entry.phrase):
            named = _plural(x)  # "two others", "two other sets" after "a set of keys"
        else:
            return m[0]  # "two more times"
        return f"{other} {named}" + ("" if unit or not m["w"] else " " + m["w"])

    return _COUNTED_MORE.sub(sub, text)


_OTHER_UNIT = re.compile(
    r"\b(?:the\s+other|one\s+more|another|a\s+(?:second|third))\s+(?P<w>[a-z]+)\b(?!\s+of\b)", re.I
)


def _other_unit(text: str) -> str:
    """ "the other set" / "one more set" after "two sets of keys", "another slice" after "a slice of bread":
    the measure word names the thing before ("the other set of keys", "another slice of bread")."""

    def sub(m: re.Match[str]) -> str:
        x, word = _antecedent(text, m.start(), one_of=True), m["w"].lower()
        if x is None:
            return m[0]
        if word in ("slice", "piece") and _sliced_before(text, x):
            return f"{m[0]} of {x.entry.phrase}"
        unit = x.entry.phrase.split()  # "set of keys": "set" names it
        return f"{m[0]} {' '.join(unit[1:])}" if unit[1:2] == ["of"] and unit[0] == word else m[0]

    return _OTHER_UNIT.sub(sub, text)


def _sliced_before(text: str, x: Mention) -> bool:
    """Is the thing named as a slice ("a slice of apple", "a piece of bread", "an apple slice")?"""
    before = [w for w, _, _ in tokens(text[: x.char_start])][-2:]
    after = [w for w, _, _ in tokens(text[x.char_end :])][:1]
    return bool(set(before) & {"slice", "piece", "sliced"}) or after == ["slice"]


def _rest(text: str) -> str:
    for m in reversed(list(_REST.finditer(text))):
        tail = m[0].lower().split()[-1]
        noun = _noun_at(text, m.end()) if tail in ("the", "remaining") else None
        x = noun or _antecedent(text, m.start(), one_of=True)
        if x is None or (noun is None and tail not in ("them", "ones", "others")):
            continue
        if noun is not None and not _said_before(text, m.start(), noun):
            continue  # "the remaining eggs" with no egg said before: a vague count, as "the rest" (h299)
        end = noun.char_end if noun is not None else m.end()  # "the rest of the keys": key chains
        new = f"all the other {_plural(x)}"
        if tail == "remaining" and noun is not None and not noun.plural:  # "the remaining cd": one
            new = f"the other {noun.surface}"
        text = text[: m.start()] + _cased(new, m[0]) + text[end:]
    return text


def _said_before(text: str, at: int, noun: Mention) -> bool:
    """Whether a thing of the noun's type is named before character `at` (what the remaining ones are of)."""
    types = set(noun.entry.types)
    return any(set(m.entry.types) & types for m in _things(text) if m.char_end <= at)


def _other_one(text: str) -> str:
    def sub(m: re.Match[str]) -> str:
        x = _antecedent(text, m.start(), one_of=True)
        if x is None or _of_two_kinds(text, x):
            return m[0]
        return _cased(f"the other {_singular(x, text)}", m[0])

    return _OTHER_ONE.sub(sub, text)


def _another(text: str) -> str:
    def sub(m: re.Match[str]) -> str:
        if _MORE_WITHOUT_VERB.search(text[: m.start()]) and m[0].lower().startswith("one more"):
            return m[0]  # "..., then one more (X)": the task before again, `everyday`'s count left out
        noun = _noun_at(text, m.end())
        elided = m[0].lower().endswith(" one") or noun is None  # "the last one": one of several before
        x = _antecedent(text, m.start(), one_of=elided)
        if x is None or _after_place(text, m.start()):
            return m[0]
        if m[0].lower().startswith("another") and _sliced_before(text, x):
            return m[0]  # "heat an apple slice ..., then heat another one": a slice, the grammar's to read
        # "the second fork": "a second fork" (the word said stays); "the last one", "one more": another
        ordinal = m[0].split()[1].lower() if m[0].lower().startswith(("the ", "a ")) else "last"
        said = "another" if ordinal == "last" else f"a {ordinal}"
        if elided or noun is None:
            return _cased(f"{said} {_singular(x, text)}", m[0])
        return _cased(said, m[0]) if set(noun.entry.types) & set(x.entry.types) else m[0]

    return _ANOTHER.sub(sub, text)


# "2 sponges in the tub, and a rinsed one in there too": a treated one of the things just named (h293)
_TREATED_ONE = re.compile(rf"\b(?P<a>a|an|one)\s+(?P<state>{'|'.join(sorted(STATE_WORDS))})\s+one\b", re.I)


def _treated_one(text: str) -> str:
    """ "a rinsed one" after "two sponges" (or "a sponge") -> "a rinsed sponge"."""

    def sub(m: re.Match[str]) -> str:
        x = _antecedent(text, m.start(), one_of=True)
        return m[0] if x is None else f"{m['a']} {m['state']} {_singular(x, text)}"

    return _TREATED_ONE.sub(sub, text)


# "slice a tomato. i want a warm slice on the counter, a cold slice in the sink": a slice in a later sentence
# is one of the thing sliced before ("a warm slice of tomato"), the one thing sliced (h293)
_SLICING = re.compile(r"\b(?:slice|cut|chop)\s+(?:up\s+)?(?:a|an|the|one|my)\s+(?=[a-z])", re.I)
_SLICE_SAID = re.compile(
    rf"\b(?P<a>a|an|one|another)\s+(?P<state>(?:{'|'.join(sorted(STATE_WORDS))})\s+)(?:slice|piece)\b(?!\s+of\b)",
    re.I,
)


def _slice_of_before(text: str) -> str:
    """ "a warm slice" in a sentence after "slice a tomato" -> "a warm slice of tomato" (a plain "a slice" is
    the grammar's own, which reads it with what it knows of the slices said)."""
    sliced = [x for m in _SLICING.finditer(text) if (x := _noun_at(text, m.end())) is not None]
    if not sliced or len({x.entry.canonical for x in sliced}) != 1:
        return text
    end = re.compile(r"[.;!?]\s").search(text, sliced[0].char_end)
    if end is None:
        return text
    of = sliced[0].surface
    rest = _SLICE_SAID.sub(lambda m: f"{m['a']} {m['state']}slice of {of}", text[end.end() :])
    return text[: end.end()] + rest


def _after_place(text: str, at: int) -> bool:
    """Is the word before character `at` a preposition of place ("in the second drawer")?"""
    before = tokens(text[:at])
    return bool(before) and before[-1][0] in _PLACE_WORDS


def _lamp_used(text: str) -> str:
    def sub(m: re.Match[str]) -> str:
        lamps = [x for x in find_mentions(text) if x.char_end <= m.start() and set(x.entry.types) & LAMPS]
        return _cased(f"the {lamps[-1].surface}", m[0]) if lamps else m[0]

    return _JUST_USED.sub(sub, text)


def _counts_after(text: str) -> str:
    """ "put remotes on the sofa, two of them" -> "put two remotes on the sofa": the count said after a bare
    plural thing of its clause moves before it ("two of each": before each plural of a list)."""
    for m in reversed(list(_COUNT_AFTER.finditer(text))):
        clause = max(text.rfind(c, 0, m.start()) for c in ".;!?") + 1
        plurals = [x for x in _things(text) if clause <= x.char_start < m.start() and x.plural]
        bare = [x for x in plurals if not _counted(text, x)]
        if not bare or len(bare) != len(plurals):
            continue
        n = m["n"].lower()
        named = bare if m["of"] and m["of"].lower() == "each" else bare[-1:]
        rest = text[m.end() :]
        if m[0].lstrip().startswith(","):  # "Books and mugs, two of each, go on ...": the closing comma too
            rest = re.sub(r"^\s*,(?=\s)", "", rest)
        text = text[: m.start()] + rest
        for x in reversed(named):
            said = _cased(f"{n} {x.surface[:1].lower()}{x.surface[1:]}", x.surface)
            head = text[: x.char_start]
            if n == "both":  # "the mugs, both of them": "both mugs"
                head = re.sub(r"\bthe\s+$", "", head, flags=re.I)
            text = head + said + text[x.char_end :]
    return text


def _of_two_kinds(text: str, x: Mention) -> bool:
    """Whether the sentence that names `x` names things of another type too ("Tomato on a plate, plate on
    the counter. And the other on the table.": the other tomato or the other plate?): "the other" is then
    left as said and refused by name (h246)."""
    start = max(text.rfind(c, 0, x.char_start) for c in ".;!?\n") + 1
    kinds = {frozenset(m.entry.types) for m in _things(text) if start <= m.char_start < x.char_end}
    return len(kinds) > 1


def _counted(text: str, m: Mention) -> bool:
    """Is a count or quantifier said right before the mention ("two remotes", "all the remotes")?"""
    before = [w for w, _, _ in tokens(text[: m.char_start])][-3:]
    return bool(set(before) & {"two", "three", "four", "five", "both", "all", "each", "every", "2", "3", "4"})


# "cut the bread into two slices and put both (of them) / them (both) in the fridge": the pieces of a cut
# into two, taken together, are two slices ("both slices", a count the task keeps, h313); a cut into three
# keeps its "both" for check 1 to name (`counts._cut_into`)
_PIECES_OF_TWO = re.compile(
    r"(?P<head>\b(?:slice|cut|chop)\s+[^.;!?]*?\binto\s+(?:two|2)\s+(?P<p>slices|pieces)\b"
    r"[^.;!?]*?\b(?:put|place|set|move|bring|take|stick|drop|leave)\s+)"
    r"(?:both\s+of\s+them|them\s+both|both|them|the\s+two)"
    r"(?=\s+(?:in|on|into|onto|inside|to|at|under|next|near|beside|by|back)\b)",
    re.I,
)


def _pieces_of_two(text: str) -> str:
    """ "cut X into two slices and put both in Y" -> "... put both slices in Y"."""
    return _PIECES_OF_TWO.sub(lambda m: f"{m['head']}both {m['p']}", text)
