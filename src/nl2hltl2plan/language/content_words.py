"""The content words of an instruction: the vocabulary the word-accounting check (`accounting`) and the
readers share.

`categories(word)` gives the categories of one token from `content_words.txt` (verbs by the task they
name, counts, negations, order words, the places a verb implies), `stems(word)` the forms it may have
come from, and `Unread` is one word (or invented slot) the parse does not use, with its reason.

>>> sorted(c for c in categories("heated") if c.startswith("verb_"))
['verb_heat_place']
>>> stems("chopped") >= {"chop"}
True
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache, lru_cache
from importlib import resources

from nl2hltl2plan.errors import HTTError

# rooms people name (room_words.txt): "the laptop on the desk in the hall"
ROOM_WORDS = tuple(
    w
    for w in resources.files("nl2hltl2plan.language").joinpath("room_words.txt").read_text().splitlines()
    if w and w[0] != "#"
)
DETERMINERS = {"the", "a", "an", "that", "this", "those", "these", "its", "their", "my", "your", "of"}
# what opens the object of a verb: a determiner (not "of": "a spray of water" names a thing) or a pronoun
OBJECT_START = frozenset(DETERMINERS - {"of"} | {"it", "them", "some"})
# words after which a command opens ("and fluff it", "please polish them")
COMMAND_WORDS = frozenset({"and", "then", "please", "also", "first", "now", "pls"})
# a place named after an object and one of these describes where the object is ("the apple on the table")
LOCATIVE = frozenset(
    "on in at inside near beside by behind under next closest nearest closer from off below above beneath "
    "underneath across "
    "against between around along with of".split()
)


@dataclass(frozen=True)
class Unread:
    """A content word the parse does not use, or a slot of a base task that no word names."""

    words: str
    category: str  # object / place / action / count / negation / order / invented
    reason: str

    def __str__(self) -> str:
        return f"{self.words!r} ({self.category}): {self.reason}"


@lru_cache(maxsize=1)
def vocabulary() -> dict[str, frozenset[str]]:
    """category -> words, from `content_words.txt` (the readers' words: not the phrase lines of
    `_SHARED_PHRASES` nor the categories check 1 alone asks, `check1_categories`; the drinks and food of
    `DRINK_FOOD` are in `noun_unsupported`)."""
    every = _every_category()
    skipped = _SHARED_PHRASES + _CHECK1_ONLY + (DRINK_FOOD,)
    return {name: words for name, words in every.items() if name not in skipped}


@lru_cache(maxsize=1)
def _every_category() -> dict[str, frozenset[str]]:
    every = word_categories("content_words.txt")
    every["verb_any"] |= word_categories("placing_verbs.txt")["place"]  # h278's placing verbs (their file)
    # a drink or food is a noun no world has: its phrase's last word ("hot_chocolate": "chocolate")
    said = frozenset(p.rsplit("_", 1)[-1] for p in every[DRINK_FOOD])
    return every | {"noun_unsupported": every["noun_unsupported"] | said}


def word_categories(filename: str) -> dict[str, frozenset[str]]:
    """category -> words of one of this package's `category: word word ...` files (a comment after '#'; a
    category may go on over several lines, each repeating its name)."""
    out: dict[str, frozenset[str]] = {}
    text = resources.files("nl2hltl2plan.language").joinpath(filename).read_text()
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if line:
            name, _, words = line.partition(":")
            out[name.strip()] = out.get(name.strip(), frozenset()) | frozenset(words.split())
    return out


@cache
def free_order_phrase(kind: str | None = None) -> str:
    """The phrases of `free_order.txt` (of one kind, "adverb", "clause" or "per_group", "whole" for the
    first two: those that free a whole list, or all, the per-group ones first) as one regular expression
    (no context, no flags: each reader puts its own context around it and matches case-insensitively).

    >>> import re
    >>> bool(re.fullmatch(free_order_phrase(), "the order does not matter", re.I))
    True
    >>> bool(re.fullmatch(free_order_phrase("clause"), "in either order", re.I))
    False
    """
    if kind == "whole":
        return f"(?:{free_order_phrase('adverb')}|{free_order_phrase('clause')})"
    if kind is None:  # a per-group phrase first, where both match at one place (`free_order_remarks`)
        return f"(?:{free_order_phrase('per_group')}|{free_order_phrase('whole')})"
    return phrase_list_pattern("free_order.txt", kind)


@dataclass(frozen=True)
class FreeOrder:
    """One free-order phrase of a text: where it is, and whether it frees the order within each group only
    ("each pair in either order") rather than the whole list ("in any order")."""

    words: str
    start: int
    end: int
    per_group: bool


def free_order_remarks(text: str) -> list[FreeOrder]:
    """The free-order phrases of `text` (`free_order.txt`), left to right; where a per-group phrase and a
    whole-list one match at one place, the per-group one ("the order within each step is free").

    >>> [(r.words, r.per_group) for r in free_order_remarks("each pair in either order, then any order")]
    [('each pair in either order', True), ('any order', False)]
    """
    return list(_free_order_remarks(text))


@lru_cache(maxsize=1024)  # check 1 asks again for every reading it judges (about five per instruction)
def _free_order_remarks(text: str) -> tuple[FreeOrder, ...]:
    return tuple(
        FreeOrder(m.group(0), m.start(), m.end(), m.group("group") is not None)
        for m in _free_order_remark().finditer(text)
    )


@cache
def _free_order_remark() -> re.Pattern[str]:
    per_group, whole = free_order_phrase("per_group"), free_order_phrase("whole")
    return re.compile(rf"\b(?:(?P<group>{per_group})|{whole})\b", re.I)


@cache
def phrase_list_pattern(filename: str, kind: str | None = None) -> str:
    """The phrases of one of this package's `kind: phrase` files (the syntax of `free_order.txt`), of one
    kind or all, as one regular expression with no context and no flags."""
    text = resources.files("nl2hltl2plan.language").joinpath(filename).read_text()
    lines = [line.partition(":") for line in text.splitlines() if line.strip() and not line.startswith("#")]
    return "(?:" + "|".join(_phrase_pattern(p.strip()) for k, _, p in lines if kind in (None, k)) + ")"


def phrase_words(filename: str, kind: str) -> frozenset[str]:
    """Every word the phrases of one kind of a `kind: phrase` file use (for a kind that lists words)."""
    text = resources.files("nl2hltl2plan.language").joinpath(filename).read_text()
    lines = [line.partition(":") for line in text.splitlines() if line.strip() and not line.startswith("#")]
    return frozenset(w for k, _, p in lines if k == kind for w in re.findall(r"[^\s()\[\]|]+", p))


def _phrase_pattern(phrase: str) -> str:
    """One line of `free_order.txt` as a regular expression: "(a|b)" one of, "[x]" optional, "*" any one
    word."""
    toks = re.findall(r"[()\[\]|]|[^\s()\[\]|]+", phrase)
    pos = 0

    def alternatives(close: str) -> str:
        nonlocal pos
        options = [sequence()]
        while pos < len(toks) and toks[pos] == "|":
            pos += 1
            options.append(sequence())
        if close:
            pos += 1  # the closing bracket
        return "|".join(options)

    def sequence() -> str:
        nonlocal pos
        out, started = "", False  # started: a word that is not optional is written
        while pos < len(toks) and toks[pos] not in ")]|":
            tok, pos = toks[pos], pos + 1
            item = f"(?:{alternatives(']' if tok == '[' else ')')})" if tok in "([" else _word(tok)
            if tok == "[":
                out += f"(?:\\s+{item})?" if started else f"(?:{item}\\s+)?"
            elif tok == ":":  # a label's colon follows its word: "ordering: none"
                out += "\\s*:"
            else:
                out, started = out + (f"\\s+{item}" if started else item), True
        return out

    return alternatives("")


def _word(word: str) -> str:
    if word == "*":  # any one word ("the order of * is your choice": of play, of the stops)
        return "[a-z]+"
    if word == "*'s":  # any one word and its "'s" ("the captain's happy either way")
        return "[a-z]+['’]s"
    return re.escape(word).replace("n't", "\\s*n[o']?t")


@lru_cache(maxsize=1)
def verb_places() -> dict[str, str]:
    """verb -> the place it names ("throw" -> GarbageCan), from `implied_by_verb` in content_words.txt."""
    return dict(w.split(":", 1) for w in vocabulary()["implied_by_verb"])


def stems(word: str) -> set[str]:
    """The word and its possible stems (heated -> heat, chopped -> chop, slices -> slice)."""
    out = {word}
    for suffix in ("s", "es", "ed", "d", "ing"):
        if word.endswith(suffix) and len(word) > len(suffix) + 2:
            base = word[: -len(suffix)]
            out |= {base, base + "e"}
            if len(base) > 2 and base[-1] == base[-2]:
                out.add(base[:-1])
    return out


@lru_cache(maxsize=8192)  # asked for every token of every accounting pass, several passes per instruction
def categories(word: str) -> frozenset[str]:
    """The content-word categories of one token ({} for a function word)."""
    forms = stems(word)
    return frozenset(
        name
        for name, words in vocabulary().items()
        if forms & words and name not in _PHRASE_CATEGORIES
    )


# lines of phrases or pairs, no word of their own (`_SHARED_PHRASES`: read before any reader, by `take_backs`
# and `headings`); and the categories check 1 alone asks (`check1_categories`)
_SHARED_PHRASES = ("take_back", "empty_value", "empty_label")
_PHRASE_CATEGORIES = ("implied_by_verb",)
_CHECK1_ONLY = ("person_relation", "time", "hedge")
# drinks and food, phrases (`phrase_category`): the household reader names them in its refusal
DRINK_FOOD = "noun_drink_food"


# the lexicon's words for a thing or an action no world has, and for people: in a voice's opening or closing
# they name nothing a task could take ("Lace up your shoes", "Correct answer", "Doors closing")
VOICE_NOUNS = frozenset({"noun_unsupported", "verb_unsupported", "verb_unsupported_before_object", "person"})
# the kinds of word check 1 refuses unused that a voice's frame may hold: an action, a count, a noun no world
# has, a negation, an order, a wait or a condition (the request-unit classifier's content)
_REFUSED_PREFIXES = ("verb_", "count_", "noun_")
_REFUSED_KINDS = frozenset({"negation", "order", "any_order", "delay", "condition"})


@lru_cache(maxsize=1)
def frame_keeps() -> frozenset[str]:
    """The words that keep a frame fragment (`frame_keeps.txt`: a thing added, a relation, a wait, a time,
    an order): never filler, never a frame word."""
    return frozenset().union(*word_categories("frame_keeps.txt").values())


@lru_cache(maxsize=16384)  # asked for every word of every fragment a frame rule weighs
def names_content(
    word: str,
    voice: bool = False,
    names: frozenset[str] = frozenset(),
    kept: bool = False,
    refused_only: bool = False,
) -> bool:
    """Whether one lower-case word names content that a frame rule must keep for check 1 to judge: a word
    of the readers' vocabulary (`vocabulary`), as said or inflected ("called": call; a stem keeps four
    letters, so "noted" is not "not"). The readers' variations, each by name:

    - `voice`: in a voice's opening or closing sentence, the words of `VOICE_NOUNS` name nothing
      (`handover_discourse.empty`'s voices);
    - `names`: the world's own names are content too ("orange", "plate" in the tabletop world);
    - `kept`: so are a number and a word of `frame_keeps.txt` (the frame filler's: never filler);
    - `refused_only`: only the kinds check 1 refuses unused (an action, a count, a noun no world has, a
      negation, an order, a wait, a condition), by check 1's own inflections (`categories`: "putting",
      "rinsed"), as the request-unit classifier asks (`learned.request_units.content`).

    >>> names_content("called"), names_content("noted"), names_content("person"), names_content("zebra")
    (True, False, False, False)
    >>> names_content("guests"), names_content("guests", voice=True), names_content("too", kept=True)
    (True, False, True)
    >>> names_content("putting"), names_content("putting", refused_only=True)
    (False, True)
    """
    if word in names or kept and (word.isdigit() or word in frame_keeps()):
        return True
    if refused_only:
        return any(c.startswith(_REFUSED_PREFIXES) or c in _REFUSED_KINDS for c in categories(word))
    # an inflection's stem of at least four letters ("called": call; "noted" is not "not")
    forms = {word} | {word[: -len(e)] for e in ("s", "ed") if word.endswith(e) and len(word) - len(e) >= 4}
    skipped = VOICE_NOUNS if voice else frozenset()
    return any(f in ws for name, ws in vocabulary().items() if name not in skipped for f in forms)


@lru_cache(maxsize=8192)
def check1_categories(word: str) -> frozenset[str]:
    """The categories of one token that check 1 alone asks (a person by relation, a time to come, a hedge):
    the readers' own frames and asides ("Voice note from mum:") do not take them as content."""
    forms = stems(word)
    return frozenset(name for name in _CHECK1_ONLY if forms & _every_category()[name])
TAKEN_BACK = "takes back part of the instruction: say the instruction again as you mean it"


def take_backs(text: str) -> list[Unread]:
    """The phrases of `text` that take back what was said, with nothing in its place (`take_back` in
    content_words.txt), each where it closes its clause: no reader guesses which part is taken back.

    >>> [u.words for u in take_backs("Put the apple in the fridge. Scratch that.")]
    ['Scratch that']
    >>> take_backs("never mind the order, put the apple in the fridge")
    []
    """
    found = _take_back().finditer(text.replace("’", "'"))
    return [Unread(m.group(0), "take_back", TAKEN_BACK) for m in found]


def refuse_take_backs(instruction: str) -> None:
    """Raise HTTError naming each phrase that takes back what was said (`take_backs`): asked of every
    world's reader and every backend before any reading, since no reading can tell which part is taken
    back, and a partial plan could do exactly that part."""
    if found := take_backs(instruction):
        raise HTTError("; ".join(f"{u.words!r} {u.reason}" for u in found))


@cache
def _take_back() -> re.Pattern[str]:
    return re.compile(rf"(?<![\w'])(?:{phrase_category('take_back')})(?=\s*(?:[,.;:!?)\-—–]|$))", re.I)


def shared_words(name: str) -> frozenset[str]:
    """The words (or `_`-joined phrases) of one line of content_words.txt that no `vocabulary` holds."""
    return _every_category()[name]


@cache
def phrase_category(name: str) -> str:
    """The phrases of one `_`-joined category of content_words.txt (`take_back`, `empty_value`) as one
    regular expression, the longest first, with no context and no flags."""
    phrases = sorted(_every_category()[name], key=len, reverse=True)
    return "|".join(r"\s+".join(map(re.escape, p.split("_"))) for p in phrases)
