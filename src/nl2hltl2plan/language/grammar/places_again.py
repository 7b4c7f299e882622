"""Places said again (`everyday` calls `places_named_again` on every text): "there", "in there too", a fixture
as "it", "that (same) table", and "along with X" are written out as the place named before them, so that the
rules read a placement of their own; where no place fits, or a negation comes before, the text stays.
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.grounding import alfred_lookup, find_mentions, sentence_start


def places_named_again(text: str) -> str:
    """The text with each place said again (below) written out.

    >>> places_named_again("put the bread in the fridge, then put the egg there too")
    'put the bread in the fridge, then put the egg in the fridge too'
    """
    text = _THAT_PLACE.sub(_that_place_named, _THERE.sub(_there_named, _ALONG_WITH.sub(_along_with, text)))
    return _IT_PLACE.sub(_fixture_named, text)


# "put the egg (in) there too", "then the egg in there": "there" is the last destination named before it
# ("put the bread in the fridge, then put the egg in there too"); with none before, it stays, and is read
# or refused as it is. "on it too" / "in it as well" is the same place ("put the book on the bed. put the
# pillow on it too", "two remotes on the couch and two cards on it too"); a bare "on it" may be a thing
# just named ("put a fork in a cup and ... put the cup in it"), and is left
# a word of the thing's name is no preposition: "put an egg in there" is the egg, not "an egg in", in there
_NAME_WORD = r"\s+(?!(?:over|in|into|inside|on|onto)\b)[a-z]+"
_THERE = re.compile(
    r"(?P<head>\b(?:put|place|set|stick|pop|drop|leave|store|move|throw|toss|carry|take|bring)\s+"
    rf"(?:it|them|(?:the|a|an|two|both|\d)\s+[a-z]+(?:{_NAME_WORD})?)"
    rf"|(?:(?<=\bthen\s)|(?<=\band\s))(?:the|a|an|two|three|both|\d)\s+[a-z]+(?:{_NAME_WORD}){{0,2}}?"
    # a sentence that says where its thing goes, "The newspaper from the dresser goes on there too." (h294)
    rf"|(?:^|(?<=[.!?]\s))(?:the|a|an|two|both|\d)\s+[a-z]+(?:{_NAME_WORD})?"
    r"(?=(?:\s+from\s+[a-z ]+?)?\s+goes?\s))"
    r"(?P<source>\s+from\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)??"  # "the bottle from the toilet there"
    r"(?P<goes>\s+goes?)?"
    # "and a spoon in the bowl on there as well": the container, on the last place (users_h195dev)
    r"(?P<inner>\s+(?:in|into|inside)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?(?=\s+(?:on|onto)\s+there\b))?"
    # "and two rolls next to it": beside the thing placed last, so where it was put
    r"\s+(?:(?:(?:in|into|inside|on|onto|over)\s+)?(?:there|(?:next\s+to|beside)\s+it)\b"
    r"(?=\s*(?:too|as\s+well|also)?\s*(?:[,.;!?]|$|and\b|then\b))"
    r"|(?:in|into|inside|on|onto)\s+it\s+(?=(?:too|as\s+well|also)\s*(?:[,.;!?]|$|and\b|then\b)))",
    re.I,
)
_NEGATED = re.compile(r"(?:\bnot|n't|\bnever|\bno)\s+(?:\w+\s+)?$", re.I)


def _destination_phrase(words: int) -> re.Pattern[str]:
    """A destination: its preposition and up to `words` words after the article ("on the small black side
    table" needs four, where "that table" is the last table named)."""
    return re.compile(
        r"(?<!next )(?<!close )\b(?P<prep>in|into|inside|on|onto|to)\s+"
        # "on the back of the toilet": a part names no place, its thing does; "to that same table" is one
        r"(?:the\s+(?:back|top|side|edge|front|lid)\s+of\s+)?"
        rf"(?P<np>(?:(?:the|that)(?:\s+same)?|a|an)(?:\s+[a-z]+){{1,{words}}})",
        re.I,
    )


_DESTINATION_PHRASE = _destination_phrase(2)


def _there_named(m: re.Match[str]) -> str:
    """ "put the egg in there": the last destination named before it, written out; else as it is (and
    after a negation, "don't put the knife there", which the constraint reader reads as it is)."""
    if _NEGATED.search(m.string[: m.start()]):
        return m[0]
    moved = {x.entry.types[0] for x in find_mentions(m["head"])}  # "put it in a pan and carry the pan there"
    places = [
        (d["prep"].lower(), named[-1])
        for d in _DESTINATION_PHRASE.finditer(m.string[: m.start()])
        if (named := find_mentions(d["np"])) and not named[-1].entry.generic
        and named[-1].entry.types[0] not in moved
    ]
    if not places:
        return m[0]
    prep, place = places[-1]
    prep = "in" if prep == "to" else prep  # "walk to the sink ... in there"
    if m["head"].split()[0].lower() in ("carry", "take", "bring", "move"):
        prep = "to"  # "carry the pan over there": to the table ("carry the pan on the table": where it is)
    said = f"{m['head']}{m['source'] or ''}{m['inner'] or ''}{m['goes'] or ''} {prep} the {place.surface}"
    return said + (" " if m[0].endswith(" ") else "")


# a bare "it" as a place, where it can only be a fixture that holds things (a bed, a fridge: ALFRED cannot
# pick it up): the one thing named before ("go to the fridge and put the egg in it", "wash the sink then put
# the cup in it"), or the place of a "before you ..." clause just before, where the thing is not there yet
# ("before you put the book on the bed, put the pillow on it"). Where a thing was put there ("put the laptop
# on the bed then put the book on it", "set the cup in the sink and drop a fork into it") "it" may be that
# thing, and is left to the rules
_IT_PLACE = re.compile(
    r"(?P<head>\b(?:put|place|set|stick|pop|drop|leave|store|throw|toss)\s+"
    r"(?:the|a|an|two|both|\d)\s+[a-z]+(?:\s+[a-z]+)?)\s+(?P<prep>in|into|inside|on|onto)\s+it\b",
    re.I,
)
_BEFORE_PLACING = re.compile(
    r"(?:^|[.;!?]\s+)before\s+you\s+[a-z]+\s+(?:the|a|an|two|both|\d)\s+[a-z]+(?:\s+[a-z]+)?\s+"
    r"(?:in|into|on|onto|inside)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?\s*,?\s*$",
    re.I,
)


# "face the armchair and put the pillow on it": a step on the way names the place, and the rules read that
# "it" already (the step joins the task that follows); written out, the step was left unread
_STEP_TO = re.compile(
    r"\b(?:face|approach|go|walk|head|turn|step|move)\b(?:\s+(?:to|towards?|over\s+to))?\s+(?:the\s+)?$"
)


def _fixture_named(m: re.Match[str]) -> str:
    """ "put the pillow on it" -> "put the pillow on the bed" (see above); else as it is."""
    said = m.string[: m.start()]
    named = [x for x in find_mentions(said) if not x.entry.generic]
    look = alfred_lookup()
    if not named or named[-1].plural or look is None or (len(named) > 1 and not _BEFORE_PLACING.search(said)):
        return m[0]
    a = look(named[-1].entry.canonical)
    if a is None or a.pickupable or not a.receptacle or _STEP_TO.search(said[: named[-1].char_start]):
        return m[0]
    return f"{m['head']} {m['prep']} the {named[-1].surface}"


# "put two bottles in the cabinet, along with two rolls", "drop the towel in the tub along with two bars of
# soap": the thing after "along with" goes where the placement before it put its thing (written out as a
# placement of its own: "..., and put two rolls in the cabinet"); with no place before it, it stays
_ALONG_WITH = re.compile(
    r"\s*,?\s+along\s+with\s+(?P<np>(?:(?:the|a|an|two|three|some|both)\s+)+[a-z]+(?:\s+[a-z]+){0,3}?)"
    # where it is now may follow ("along with the hand towel from the holder": h238)
    r"(?P<source>\s+(?:from|off)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+)?)?"
    r"(?=\s*(?:[,.;!?]|$|\band\b|\bthen\b))",
    re.I,
)


def _along_with(m: re.Match[str]) -> str:
    """ ", along with two rolls": ", and put two rolls in the cabinet" (the last place named before it)."""
    before = m.string[sentence_start(m.string, m.start()) : m.start()]
    places = [
        (d["prep"].lower(), named[-1])
        for d in _DESTINATION_PHRASE.finditer(before)
        if (named := find_mentions(d["np"]))
    ]
    if not places or _NEGATED.search(before):
        return m[0]
    prep, place = places[-1]
    return f", and put {m['np']}{m['source'] or ''} {'on' if prep == 'to' else prep} the {place.surface}"


# "put a pen on that shelf too", "on that same table", "on the same one": the last destination named before
# it with that word ("the coffee table"; any word for "the same one"), written out; else as it is ("the same
# table" stays: where the scene has two, the spec cannot keep one)
_THAT_PLACE = re.compile(
    r"\b(?P<prep>in|into|inside|on|onto|to)\s+(?:that(?:\s+same)?|the\s+same(?=\s+one\b))\s+(?P<noun>[a-z]+)\b"
    r"(?!\s+(?:of|with)\b)",
    re.I,
)


_DESCRIBED_PLACE = _destination_phrase(4)  # "that table" after "on the small black side table"


def _that_place_named(m: re.Match[str]) -> str:
    """ "on that table": the last place named before it whose name ends in "table", written out."""
    if _NEGATED.search(m.string[: m.start()]):
        return m[0]
    noun = m["noun"].lower()
    any_word = noun == "one" and "same" in m[0].lower()  # "the same one", "that same one"
    for d in reversed(list(_DESCRIBED_PLACE.finditer(m.string[: m.start()]))):
        named = [x for x in find_mentions(d["np"]) if not x.entry.generic]
        if named and (any_word or named[-1].surface.lower().split()[-1] in (noun, noun + "s")):
            return f"{m['prep']} the {named[-1].surface}"
    return m[0]
