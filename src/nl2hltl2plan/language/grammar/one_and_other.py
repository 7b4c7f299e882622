"""Two things of one type told apart as "one" and "the other" (issue 28, h276), written out as two things
the grammar reads ("a mug" ... "another mug"). ALFRED's tasks each take any thing of their type, so the two
are two tasks on that type:

- "wash two bars of soap; throw one in the bin and put the other one in the tub": the verb said once, each
  thing its place ("wash a bar of soap and throw it in the bin, and wash another bar of soap and put it in
  the tub");
- a pair named first ("Take two forks.", "Two ladles:", "There are two tomatoes:", "Heat two apple slices:")
  or a slicing ("Slice an apple.", "Cut the tomato up;", "Slice a tomato and take two slices:"), then "one"
  ("one", "one of them", "one slice", "one of the slices") and "the other" ("the other one", "the other
  slice") in the next clauses: the pair's words are dropped (check 1 reads no count the tasks do not take)
  and the two references become "a X" / "another X" ("a slice of apple" after a slicing or of slices). A
  treatment said of the pair ("Heat two apple slices: one goes in the sink ...") is said of each.

Where a reference is not of that shape (a passive "one slice gets chilled", two "one"s, a "the other" not
after its "one"), the text stays as written: the readings after refuse what they cannot place.

>>> one_and_the_other("Take two mugs: put one in the sink and the other in the fridge.")
'Put a mug in the sink and put another mug in the fridge.'
>>> one_and_the_other("Slice an apple. Heat one slice and put it in the sink.")
'Slice an apple. Heat one slice and put it in the sink.'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import categories
from nl2hltl2plan.language.grammar.word_tables import STATE_WORDS
from nl2hltl2plan.language.grounding import SLICEABLE, Mention, find_mentions

# --- the verb said once over two plural things (session 31's rule) ------------------------------------
_PLACE_PHRASE = r"(?:in|into|inside|on|onto|to|under)\s+(?:the|a|an)\s+[a-z]+(?:\s+[a-z]+){0,3}?"
_VERB_ONCE = re.compile(
    r"\b(?P<verb>wash|rinse|clean|heat|warm|cool|chill|take|grab|get|pick\s+up)\s+(?:two|both)\s+"
    r"(?P<np>[a-z]+(?:\s+[a-z]+){0,3}?)\s*(?:[;,]|,?\s+and)\s+(?:then\s+)?"
    rf"(?P<v1>[a-z]+)\s+one\s+(?P<p1>{_PLACE_PHRASE})\s*,?\s+and\s+"
    rf"(?:(?P<v2>[a-z]+)\s+)?the\s+other(?:\s+one)?\s+(?P<p2>{_PLACE_PHRASE})(?=\s*(?:[.;!?,]|$))",
    re.I,
)

# --- a pair or a slicing named first, then "one" and "the other" ---------------------------------------
_NP = r"[a-z]+(?:\s+[a-z]+){0,3}?"
_SEP = r"\s*(?:[:;.!]\s*|,?\s+and\s+(?:then\s+)?|,\s*)"
_PAIR = re.compile(
    rf"(?<![\w,])(?:(?P<verb>[a-z]+(?:\s+up|\s+down)?)\s+|there\s+are\s+)?(?:two|both|2)\s+(?P<np>{_NP})(?={_SEP})"
    rf"|(?<![\w,])(?P<cut>slice|cut|chop)\s+(?P<det>an?|the)\s+(?P<whole>{_NP})"
    rf"(?:\s+(?:up|into\s+(?:slices|pieces)))?"
    rf"(?:\s*,?\s+and\s+(?P<verb2>[a-z]+)\s+two\s+(?:of\s+the\s+)?(?:slices|pieces))?(?={_SEP})",
    re.I,
)
_ONE = re.compile(
    r"\bone(?:\s+of\s+(?:them|those|the\s+(?:slices|pieces|two)))?(?:\s+(?:slice|piece))?"
    r"(?=\s+(?:in|into|on|onto|inside|to|under|back|and|goes|go|can|should)\b|\s*[,;.!]|$)",
    re.I,
)
_OTHER = re.compile(
    r"\bthe\s+other(?:\s+(?:one|slice|piece))?"
    r"(?=\s+(?:in|into|on|onto|inside|to|under|back|and|goes|go|can|should)\b|\s*[,;.!]|$)",
    re.I,
)
_MORE_THAN_TWO = re.compile(r"\b(?:third|fourth|fifth|rest|remaining|others)\b", re.I)
_GOES = re.compile(
    r"^\s*(?:goes|go|can\s+go|should\s+go)?\s*(?=(?:back\s+)?(?:in|into|on|onto|inside|to|under)\b)"
)
_CLAUSE_START = re.compile(r"(?:^|[,:;.!]|\band|\bthen)\s*$", re.I)
_SENTENCE_END = re.compile(r"[.!?](?=\s|$)")
_TREATMENTS = frozenset({"verb_heat_place", "verb_cool_place", "verb_clean_place"})
_PLAIN = frozenset({"take", "get", "grab", "find", "fetch", "bring", "pick"})


def one_and_the_other(text: str) -> str:
    """`text` with each "verb two Xs; one ... the other ..." written as two things of the type."""
    text = _VERB_ONCE.sub(_each_of_two, text)
    for m in _PAIR.finditer(text):
        said = _apart(text, m)
        if said is not None:
            return said
    return _one_named(text)


def _one_named(text: str) -> str:
    """ "Warm one apple ... and warm the other ...": "warm an apple ... and warm another apple ..." (the
    "one X" a verb's object, and "the other" in its sentence, no other "one" between)."""
    for m in re.finditer(r"(?<![\w-])(?<!\bthe\s)one\s+", text, re.I):
        verb = re.search(r"([a-z]+)\s*$", text[: m.start()], re.I)
        if verb is None or not any(c.startswith("verb_") for c in categories(verb[1].lower())):
            continue  # "Rinse these ...: one bar of soap in the cabinet and the other ...": a list of "these"
        x = next((x for x in find_mentions(text) if x.char_start == m.end()), None)
        if x is None or x.entry.generic or x.plural:
            continue
        other = _OTHER.search(text, x.char_end, _end(text, x.char_end))
        if other is None or re.search(r"\bone\b", text[x.char_end : other.start()], re.I):
            continue
        rest = _said(text[x.char_end : other.start()], text[other.end() :], "another", x.entry.phrase, "")
        if rest is not None:
            article = "an" if x.entry.phrase[0] in "aeiou" else "a"
            return text[: m.start()] + _cased(article, m[0]) + " " + text[x.char_start : x.char_end] + rest
    return text


def _cased(word: str, like: str) -> str:
    return word.capitalize() if like[:1].isupper() else word


def _each_of_two(m: re.Match[str]) -> str:
    """ "wash two bars of soap; throw one in the bin and put the other one in the tub": "wash a bar of soap
    and throw it in the bin, and wash another bar of soap and put it in the tub" (two plural things only)."""
    named = [x for x in find_mentions(m["np"]) if not x.entry.generic]
    if len(named) != 1 or not named[0].plural or named[0].surface.lower() != m["np"].lower():
        return m[0]
    one, verb = named[0].entry.phrase, m["verb"]
    first = f"{verb} {'an' if one[0] in 'aeiou' else 'a'} {one} and {m['v1']} it {m['p1']}"
    return f"{first}, and {verb.lower()} another {one} and {m['v2'] or m['v1']} it {m['p2']}"


def _apart(text: str, m: re.Match[str]) -> str | None:
    """The text with the pair `m` written out as two things, or None where its "one" and "the other" are
    not each said once, in that order, in the sentence after it (or the sentences up to "the other")."""
    noun, treat = _noun_and_treatment(m)
    if noun is None or treat is None:
        return None
    after = re.match(_SEP, text[m.end() :])
    start = m.end() + (after.end() if after else 0)
    other = _OTHER.search(text, start)
    if other is None or len(_SENTENCE_END.findall(text, start, other.start())) > 1:
        return None
    ones = list(_ONE.finditer(text, start, other.start()))
    if len(ones) != 1 or re.search(r"\b(?:one|other)\b", text[other.end() : _end(text, other.end())], re.I):
        return None
    one, end = ones[0], _end(text, other.end())
    if _MORE_THAN_TWO.search(text, start, end):
        return None  # "two mugs: one in the sink, the other in the cabinet, the third ...": not a pair
    # the later reference first: the earlier one's words after it ("goes in ...") are read from its result
    rest = _said(text[one.end() : other.start()], text[other.end() : end], "another", noun, treat)
    said = None if rest is None else _said(text[start : one.start()], rest, "a", noun, treat)
    if said is None:
        return None
    head = text[: m.start()]
    if (m["verb"] or "").lower() in _WISHES:  # "i also need two clean cloths, ...": "also wash a cloth ..."
        head = re.sub(r"\b(?:i|we)\s+(?=(?:also\s+|still\s+)?$)", "", head, flags=re.I)
    body = said
    if not head.strip() or re.search(r"[.!?:;]\s*$", head):
        body = body[:1].upper() + body[1:]
    return head + body + text[end:]


def _end(text: str, at: int) -> int:
    """Where the sentence holding `at` ends (its stop included), or the text's end."""
    stop = _SENTENCE_END.search(text, at)
    return stop.start() if stop else len(text)


def _said(before: str, after: str, det: str, noun: str, treat: str) -> str | None:
    """before + the reference written as "DET NOUN" + after (the pair's treatment said of it); None where a
    reference that opens its clause is not followed by a place ("one gets chilled")."""
    thing = f"{'an' if det == 'a' and noun[0] in 'aeiou' else det} {noun}"
    if _CLAUSE_START.search(before):  # "one goes in the sink", "the other in the bin"
        goes = _GOES.match(after)
        if goes is None:
            return None
        said = f"{treat} {thing} and put it " if treat else f"put {thing} "
        return before + said + after[goes.end() :].lstrip()
    if treat:  # "Warm up two tomatoes. Throw one of them in the bin": warm a tomato and throw it in the bin
        verb = re.search(r"([a-z]+)\s*$", before, re.I)
        if verb is None or categories(verb[1].lower()) & _TREATMENTS:
            return before + thing + after
        return before[: verb.start()] + f"{treat} {thing} and {verb[1].lower()} it" + after
    return before + thing + after


def _noun_and_treatment(m: re.Match[str]) -> tuple[str | None, str | None]:
    """The noun each of the pair is written with ("mug", "slice of apple") and the treatment the pair's own
    verb says of both ("heat", "" for "take", a slicing or none); None where the pair names no one thing."""
    if m["cut"]:
        whole = _one_thing(m["whole"])
        if whole is None or whole.plural or not set(whole.entry.types) & (SLICEABLE - {"Egg"}):
            return None, ""
        return f"slice of {whole.entry.phrase}", _treatment(m["verb2"])
    if re.search(r"\b(?:slices|pieces)\b", m["np"], re.I):  # "two apple slices", "two slices of bread"
        whole = _one_thing(re.sub(r"\b(?:slices|pieces)(?:\s+of)?\b", " ", m["np"], flags=re.I))
        if whole is None or not set(whole.entry.types) & (SLICEABLE - {"Egg"}):
            return None, ""
        treat = _treatment(m["verb"])
        return f"slice of {whole.entry.phrase}", treat
    np, state = _state_said(m["np"])
    thing = _one_thing(np)
    if thing is None or not thing.plural or thing.surface.lower() != np.lower().strip():
        return None, ""
    treat = _treatment(m["verb"])
    if state and (treat == "" or (m["verb"] or "").lower() in _WISHES):
        return thing.entry.phrase, state  # "I need two clean cloths, put one ...": wash each (h300's line 85)
    return thing.entry.phrase, treat


# a pair's state said as its adjective ("two clean cloths", "two chilled apples"): the treatment of each
_STATE_VERB = {"clean": "wash", "heat": "heat", "cool": "chill"}
_WISHES = frozenset({"need", "want", "like"})  # "I need two clean cloths": a wish, its verb moves nothing


def _state_said(np: str) -> tuple[str, str]:
    """The pair's words without a treatment's state adjective before its thing, and that treatment's verb
    ("clean cloths": "cloths", "wash"); the words as said and "" where none opens them."""
    first, _, rest = np.strip().partition(" ")
    verb = _STATE_VERB.get(STATE_WORDS.get(first.lower(), ""), "")
    return (rest, verb) if verb and rest else (np, "")


def _one_thing(words: str) -> Mention | None:
    """The one named thing `words` say, or None."""
    named = [x for x in find_mentions(words.strip()) if not x.entry.generic]
    return named[0] if len(named) == 1 else None


def _treatment(verb: str | None) -> str | None:
    """The pair's verb where it treats the things ("heat", "warm up"), "" where it only takes or slices them
    or no verb is said; None for a verb of another kind ("throw two apples: ..."), which is left as said."""
    if not verb:
        return ""
    first = verb.lower().split()[0]
    if first in _PLAIN or categories(first) & {"verb_take", "verb_sliced"}:
        return ""
    return verb.lower() if categories(first) & _TREATMENTS else None
