"""Misspelt words: "tomatoe", "microwve", "coffe table" read as the lexicon's names, "woould", "cleean" as
English writes them (issue 28).

One rule, used by the grammar (through `grammar.everyday`) and by check 1 (which reads the same rewritten
text, so a misspelt name that a reading does not use is named, never passed over):
- a word of four letters or more that the lexicon does not know is the lexicon word it is closest to
  (difflib ratio >= 0.85, or two neighbouring letters swapped, the only way for a four-letter word: "lmap";
  one best match) when English does not know it either: "ridge" is not the fridge, "dressed" not the
  dresser, "status" not the statue;
- any other word of four letters or more that neither the lexicon, the project's word lists nor English
  knows (a British spelling is English) is the English word one edit away, when exactly one is (or
  exactly one of several is two neighbours swapped: "claen" is "clean", not "clan") and it names an
  action, a state or a count, or is a word of politeness ("woould", "cleean", "slcie"); never a word
  that builds a structure ("containign" stays unread);
- an order word only where it is the one English word one edit away ("befoer", "lastyl"; no swap
  preference: "thne" may be "the"): a guessed order word would guess its scope. One left as written is
  named by check 1 (`unknown_words.misspelt_order_words`), never read as if absent.
- any other word of four letters or more that no list and no English knows is the word of the respelling
  vocabulary (the names, verbs and structure words of the word files `respelling_vocabulary.txt` declares:
  a frame list's words are none of them) that one slip makes it, where exactly one does ("whih", "aple",
  "newspaaper"; an order, count or negation word by a margin over English's other near words, `MARGIN`);
  each respelling is said in the result's assumptions (`respelling_notes`: "read 'whih' as 'which'").
A world with a closed vocabulary may ask for more (`closed_respelt`): the tabletop world respells against
its nine name words and, as its one order form is groups in turn, its order words too.
English is pyspellchecker's frequency list; it loads only when a word passes the first tests.

Chat shorthand (`shorthand_read`, issue 28) is read in every world before any reader sees the text
(`translate`): "n", "&" and "+" between words are "and", "u" is "you", "w/" is "with" and "w/o" "without",
"pls" / "plz" is "please" (which the readers drop where "please" is dropped: "..., in that order pls").
A lone "n" or "u" after a word that names something by a letter ("region n", "plan u", "option n") stays.

>>> shorthand_read("can u put the mug n the apple in the sink w/ the lid")
'can you put the mug and the apple in the sink with the lid'
>>> shorthand_read("put it on region n and the cup on shelf u")
'put it on region n and the cup on shelf u'
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Callable
from functools import cache, lru_cache
from importlib import resources

from nl2hltl2plan.language.content_words import categories
from nl2hltl2plan.language.courtesy import courtesy_words
from nl2hltl2plan.language.grounding import lexicon

CUTOFF = 0.85  # one letter off in a five-letter word (4/5 matched is 0.8: "plate"/"place" stay apart)
_WORD = re.compile(r"(?<![A-Za-z'])[A-Za-z]{4,}(?![A-Za-z'])")  # not a part of "doesn't"
_POLITE = frozenset({"would", "could", "kindly", "please", "alright", "okay"})
# the project's own word lists: their words are read as written ("wilco" is no "wilcox")
_WORD_LISTS = ("content_words.txt", "free_order.txt", "handover_frame_words.txt")


# a word that names something by a letter after it ("region n", "plan u"): there its "n" or "u" is that
# letter, never "and" or "you", unless a determiner follows ("region i n the blue block"). Words that end a
# place ("the yellow plate n the orange", "the table n the sink") are no such words: they name by colour or
# kind, never by a letter
_BY_LETTER = frozenset(
    "region regions arm arms row column col letter plan option step part section zone area slot position "
    "grid cell point setup case line page size grade type group number no square tile station bay level "
    "unit".split()
)
# "u" after these is a letter too ("shelf u", "drawer u"): "u" is never "and", so a place that may be named
# by a letter takes it ("the plate u like": plates and blocks are named by colour)
_BY_LETTER_U = _BY_LETTER | frozenset("shelf drawer cabinet box bin spot room door".split())
_DETERMINER = re.compile(r"\s*(?:the|a|an|my|your|some|this|that|these|those)\b", re.I)
_AND = re.compile(r"(?<=\w)\s+(?P<word>n|&|\+)\s+(?=\w)|\s*(?P<amp>&)\s*(?=\w)")
_YOU = re.compile(r"(?<![\w'/-])[uU](?![\w'/-])")
_WITH = re.compile(r"(?<![\w/])w/(?P<out>o(?![\w/]))?\s*(?=[A-Za-z])", re.I)
_PLEASE = re.compile(r"(?<![\w'])(?:pls|plz)(?![\w'])", re.I)


def shorthand_read(text: str) -> str:
    """`text` with its chat shorthand written out (see the module docstring)."""

    def letter_named(m: re.Match[str], labels: frozenset[str]) -> bool:  # "region n": the letter names it
        before = re.search(r"([A-Za-z]+)\W*$", text[: m.start()])
        labelled = before is not None and before[1].lower() in labels
        return labelled and not _DETERMINER.match(text, m.end())

    def joined(m: re.Match[str]) -> str:
        return m[0] if m["word"] == "n" and letter_named(m, _BY_LETTER) else " and "

    text = _AND.sub(joined, text)
    text = _YOU.sub(lambda m: m[0] if letter_named(m, _BY_LETTER_U) else "you", text)
    text = _PLEASE.sub("please", text)
    return _WITH.sub(lambda m: "without " if m["out"] else "with ", text)


@cache
def _name_words() -> tuple[str, ...]:
    """Every word of the lexicon's phrases in their singular form ("coffee", "table", "microwave")."""
    words = {w for key, (_, plural) in lexicon().items() if not plural for w in key}
    return tuple(sorted(w for w in words if len(w) >= 4))


def listed_word(word: str) -> bool:
    """Whether the lexicon or a word list holds `word` (lower case) as an entry: the words of the lists'
    comments and their category names ("label:") are not held ("and label it" is a verb no list has)."""
    return word in _listed_words()


@cache
def _listed_words() -> frozenset[str]:
    listed = (resources.files("nl2hltl2plan.language").joinpath(f).read_text() for f in _WORD_LISTS)
    lines = (ln.split(":", 1)[-1] for t in listed for ln in t.lower().splitlines() if ln.strip()[:1] != "#")
    words = {w for ln in lines for w in re.findall(r"[a-z]+", ln)}
    words |= courtesy_words("greeting") | courtesy_words("address")
    return frozenset(w for key in lexicon() for w in key) | words


@cache
def _known_words() -> frozenset[str]:
    """Every word the lexicon knows in any form (plurals included), and every word of the project's word
    lists: these are never respelt."""
    listed = (resources.files("nl2hltl2plan.language").joinpath(f).read_text() for f in _WORD_LISTS)
    words = {w for t in listed for w in re.findall(r"[a-z]+", t.lower())}
    words |= courtesy_words("greeting") | courtesy_words("address")  # the frame words kept in courtesy.txt
    return frozenset(w for key in lexicon() for w in key) | words


def known_word(word: str) -> bool:
    """Whether the lexicon or one of the project's word lists knows `word` (lower case) as written."""
    return word in _known_words()


def english_word(word: str) -> bool:
    """Whether English (pyspellchecker's frequency list) knows `word` (lower case)."""
    return bool(_english().known([word]))


@cache
def english_lemmas(word: str) -> dict[str, tuple[str, ...]]:
    """The parts of speech English uses `word` as, each with its lemmas (lemminflect's lexicon): "luck":
    {"NOUN": ("luck",), "VERB": ("luck",)}; {} for a word it does not hold."""
    from lemminflect import getAllLemmas  # type: ignore[import-untyped]  # loads its tables on first use

    return dict(getAllLemmas(word))


def english_frequency(word: str) -> int:
    """How often English (pyspellchecker's frequency list) uses `word` (lower case; 0 where it does not)."""
    return int(_english().word_frequency[word])


def one_edit(word: str) -> set[str]:
    """Every string one letter more, less, changed, or two neighbours swapped, from `word` (lower case;
    pyspellchecker's edits)."""
    return set(_english().edit_distance_1(word)) - {word}


@cache
def _english():  # type: ignore[no-untyped-def]  # pyspellchecker has no type hints
    from spellchecker import SpellChecker

    return SpellChecker(distance=1)


@lru_cache(maxsize=4096)
def spelt_name(word: str) -> str | None:
    """The lexicon word that `word` misspells, or None (a known word, a real English word, too short,
    or no single closest name)."""
    low = word.lower()
    if len(low) < 4 or low in _known_words():
        return None
    scored = sorted(((_score(low, w), w) for w in _close(low)), reverse=True)
    if not scored:
        return _spelt_plural(low)
    if len(scored) > 1 and scored[1][0] == scored[0][0]:
        return None
    if low in _english():
        return None
    best = scored[0][1]
    # "sptulas" is near "spatula", and a plural respelt as one name would lose its count (h293): its stem
    # spells the name, said as a plural, or the word is left as written (check 1 names it)
    plural = low.endswith("s") and not low.endswith("ss") and not best.endswith("s")
    if plural and low[:-1] not in _known_words():
        return _spelt_plural(low)
    return best


def _spelt_plural(low: str) -> str | None:
    """A misspelt plural ("candels"): the names are singular, so the word is too far from each; its stem
    misspells a name ("candel": candle), whose plural with the same ending is the word meant."""
    if not low.endswith("s") or low.endswith("ss") or low in _english():
        return None
    stem = low[:-1]
    name = spelt_name(stem)
    return None if name is None or name.endswith("s") else name + "s"


def _close(low: str) -> list[str]:
    """Names within the cutoff, and names two swapped neighbouring letters away ("kettel": difflib
    scores a swap as two edits)."""
    swapped = {low[:i] + low[i + 1] + low[i] + low[i + 2 :] for i in range(len(low) - 1)}
    names = _name_words()
    if len(low) == 4:  # "plae" may be "place" as well as "plate": a short word is a name only by a swap
        return sorted(swapped & set(names))
    return sorted({*difflib.get_close_matches(low, names, n=3, cutoff=CUTOFF), *(swapped & set(names))})


def _score(low: str, name: str) -> float:
    """How close: a swap of neighbours counts as one letter off."""
    differ = len(low) == len(name) and sum(a != b for a, b in zip(low, name, strict=True))
    if differ == 2 and sorted(low) == sorted(name):
        return 1 - 1 / len(name)
    return difflib.SequenceMatcher(None, low, name).ratio()


@lru_cache(maxsize=4096)
def spelt_word(word: str) -> str | None:
    """The English word that `word` misspells ("woould", "alriight", "cleean"): a word of four letters or
    more that neither the lexicon, the project's word lists nor English knows and that is one edit (a
    letter more, less, changed, or two neighbours swapped) from exactly one English word, or two neighbours
    swapped from exactly one of several, which `_respellable` allows; an order word only where it is the one
    word near, or the one word that a letter typed twice or two neighbours swapped make ("firsst", "fisrt");
    else None. Names are `spelt_name`'s."""
    low = word.lower()
    if len(low) < 4 or low in _known_words() or _english().known(_american(low)):
        return None
    near = _english().known(_english().edit_distance_1(low))
    if len(near) == 1 and _order_word(word := next(iter(near))):
        return word  # "befoer": an order word only where no other English word is one edit away
    # two neighbours swapped is the commonest slip: "claen" is "clean", not "clan" or "caen" (a letter
    # dropped or changed), where exactly one word is that swap away
    swapped = {w for w in near if len(w) == len(low) and _neighbours_swapped(w, low)}
    # an order word too, and a letter typed twice: "fisrt" is "first" (not "fist"), "firsst" "first" (not
    # "firsts"), where exactly one word is that slip away and it is an order word
    for slip in ({w for w in near if _letter_doubled(w, low)}, swapped):
        if len(slip) == 1 and _order_word(word := next(iter(slip))):
            return word
    close = swapped if len(near) > 1 and len(swapped) == 1 else near
    return next(iter(close)) if len(close) == 1 and _respellable(next(iter(close))) else None


def _order_word(word: str) -> bool:
    """Whether `word` says an order, or leaves it free (check 1's `order` and `any_order` words)."""
    return bool(categories(word) & {"order", "any_order"})


def _respellable(word: str) -> bool:
    """A word a misspelling may become: one that names an action, a state or a count (check 1's
    categories), or a word of politeness ("would", "kindly"); never an order word, whose scope the
    grammar would then guess, nor a word that builds a structure ("containing")."""
    found = categories(word)
    return word in _POLITE or bool(found) and not _order_word(word)


def _american(low: str) -> list[str]:
    """The word and its American spellings ("colour", "neighbours", "normalised", "marvellous",
    "travellers"): the word list is American, and a British spelling is no misspelling ("-tre" is left:
    "aftre" is "after" misspelt)."""
    out = [low, low.replace("our", "or"), re.sub(r"is(e|ed|es|ing|ation)$", r"iz\1", low)]
    return [*out, re.sub(r"ll(ed|ing|ous|ers?|ors?)$", r"l\1", low)]


def american(word: str) -> str:
    """`word` (lower case) as English's American list spells it, where one of its American spellings is
    English and it is not ("marvellous": "marvelous"); else `word`."""
    if english_word(word):
        return word
    return next((w for w in _american(word) if english_word(w)), word)


def respelt(text: str) -> str:
    """`text` with each misspelt name written as the lexicon writes it, and each other misspelt word as
    English writes it (a capital kept)."""

    def fix(m: re.Match[str]) -> str:
        word = _spelt(m[0])
        if word is None:
            return m[0]
        return word.capitalize() if m[0][0].isupper() else word

    return _WORD.sub(fix, text)


def _spelt(word: str) -> str | None:
    """The word `word` misspells, by the rules in turn (a name, an English word, a vocabulary word), or None:
    one place for `respelt` and `respellings`, so what is changed is what is said."""
    return spelt_name(word) or spelt_word(word) or vocabulary_spelt(word)


def closed_respelt(text: str, words: frozenset[str]) -> str:
    """A world's option: `text` with each word that misspells one of a closed list of `words` (lower case:
    a world's name words, or the order words of its one order form) written as that word (`closed_near`),
    a capital kept. `respelt` respells an order word only where no other English word is one edit away;
    a world whose order words have one reading may ask for them here."""

    def fix(m: re.Match[str]) -> str:
        near = closed_near(m[0], words)
        if len(near) != 1:
            return m[0]
        word = next(iter(near))
        return word.capitalize() if m[0][0].isupper() else word

    return _WORD.sub(fix, text)


def closed_near(word: str, words: frozenset[str]) -> set[str]:
    """The `words` that `word` may misspell: for a word of four letters or more that is none of them and
    that no list knows, the ones two neighbouring letters swapped away whatever English says ("appel": a
    rare word, the apple in a world of fruit), else, where English does not know it, the ones one edit
    away ("aple", "frist")."""
    low = word.lower()
    if len(low) < 4 or low in words or known_word(low):
        return set()
    same_letters = [w for w in words if len(w) == len(low) and sorted(w) == sorted(low)]
    swapped = {w for w in same_letters if _neighbours_swapped(w, low)}
    return swapped or (set() if english_word(low) else one_edit(low) & words)


def _letter_doubled(word: str, typed: str) -> bool:
    """Is `typed` `word` with one of its letters typed twice ("firsst", "aftter")?"""
    return len(typed) == len(word) + 1 and any(
        typed[i] == typed[i + 1] and typed[:i] + typed[i + 1 :] == word for i in range(len(typed) - 1)
    )


def _neighbours_swapped(a: str, b: str) -> bool:
    """Do `a` and `b` differ by two neighbouring letters swapped?"""
    at = [i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y]
    return len(at) == 2 and at[1] == at[0] + 1


# --- a misspelt word of the respelling vocabulary (issue 28) ---------------------------------------------
# "whih", "befoe", "newspaaper", "aple": a word no list and no English knows that one slip (a letter left out,
# one added, one replaced by its keyboard neighbour, two neighbours swapped, a letter doubled) makes from
# exactly one word of the vocabulary, the words of the word files `respelling_vocabulary.txt` declares (the
# names, verbs and structure words a reading uses; h289). An order, count or negation word needs a margin
# too: English knows no other word one edit away at more than 1/MARGIN of its frequency ("befoe" is
# "before", 30,000 times as common as "befog"; "firt" may be "first" or "fire", only 6 times rarer).
# A tie, or a margin not met, leaves the word as written; check 1 names it (`unknown_words.misspelt_words`).
MARGIN = 20
_QWERTY = ("qwertyuiop", "asdfghjkl", "zxcvbnm")
_STRUCTURE = ("order", "any_order", "negation", "quantifier_all", "quantifier_vague", "repetition")
_LABEL = re.compile(r"^([a-z_0-9]+):\s")  # "order: ...", "count_2: ...": the kind a word file's line gives
_LOWER_WORD = re.compile(r"(?<![A-Za-z])[a-z]{3,}(?![A-Za-z])")  # not "KeyChain", a type's name


@cache
def _keyboard() -> dict[str, frozenset[str]]:
    """Each letter's neighbours on a QWERTY keyboard: beside it, and the two keys that touch it in the row
    above and below (each row sits half a key right of the one above)."""
    at = {c: (r, i) for r, row in enumerate(_QWERTY) for i, c in enumerate(row)}
    touching = {-1: (0, 1), 0: (-1, 1), 1: (-1, 0)}  # row offset -> key offsets
    return {c: frozenset(d for d, (s, j) in at.items() if s - r in touching and j - i in touching[s - r])
            for c, (r, i) in at.items()}


VOCABULARY_FILE = "respelling_vocabulary.txt"  # the one declaration of the word files respelt to


@cache
def vocabulary_words() -> frozenset[str]:
    """The respelling vocabulary: the words of the word files `respelling_vocabulary.txt` declares (the
    lexicon's names, the verbs, order, count and negation words, the connectives the grammar reads),
    three letters or more, their comments left out; never a word of any other list (h289)."""
    return declared_vocabulary(_package_text) | _POLITE  # ("alrght": politeness `spelt_word` respells too)


def declared_vocabulary(read: Callable[[str], str]) -> frozenset[str]:
    """The words of the word files `respelling_vocabulary.txt` declares, each file read by `read` (its path in
    the package -> its text): a line `file` takes every entry of the file, `file: kind kind` those of the
    kinds named."""
    words: set[str] = set()
    for source in _entries(read(VOCABULARY_FILE)):
        name, _, kinds = source.partition(":")
        wanted = frozenset(kinds.split())
        for line in _entries(read(name.strip())):
            label = _LABEL.match(line)
            if not wanted or label and label[1] in wanted:
                words.update(_LOWER_WORD.findall(line[label.end() if label else 0 :]))
    return frozenset(words)


def _entries(text: str) -> list[str]:
    """A word file's lines, its comments and blank lines left out."""
    return [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]


def _package_text(name: str) -> str:
    return resources.files("nl2hltl2plan.language").joinpath(*name.split("/")).read_text()


def _one_slip(typed: str, word: str) -> bool:
    """Is `typed` `word` with one slip: a letter left out, one added (or doubled), one replaced by its
    keyboard neighbour, or two neighbours swapped?"""
    if len(typed) == len(word) - 1:
        return any(word[:i] + word[i + 1 :] == typed for i in range(len(word)))
    if len(typed) == len(word) + 1:
        return any(typed[:i] + typed[i + 1 :] == word for i in range(len(typed)))
    if len(typed) != len(word):
        return False
    at = [i for i, (a, b) in enumerate(zip(typed, word, strict=True)) if a != b]
    if len(at) == 1:
        return typed[at[0]] in _keyboard().get(word[at[0]], frozenset())
    return _neighbours_swapped(typed, word) and sorted(typed) == sorted(word)


def structure_word(word: str) -> bool:
    """Whether `word` is an order, count or negation word (check 1's categories), where a wrong respelling
    costs most."""
    return bool(categories(word) & set(_STRUCTURE)) or any(c.startswith("count_") for c in categories(word))


@lru_cache(maxsize=4096)
def vocabulary_near(word: str) -> tuple[str, ...]:
    """The vocabulary words that `word` may misspell, the likeliest first: for a word of four letters or
    more that no list and no English knows, those one slip away (`_one_slip`), and for an order, count or
    negation word among them, the English words as near that it does not outweigh by MARGIN; () else."""
    low = word.lower()
    if len(low) < 4 or not low.isalpha() or low in _known_words() or _english().known(_american(low)):
        return ()
    near = sorted(w for w in vocabulary_words() if abs(len(w) - len(low)) <= 1 and _one_slip(low, w))
    if len(near) != 1 or not structure_word(near[0]):
        return tuple(near)
    freq = _english().word_usage_frequency
    rivals = sorted(_english().known(_english().edit_distance_1(low)) - {near[0]}, key=freq, reverse=True)
    return (near[0], *(w for w in rivals[:2] if freq(w) * MARGIN > freq(near[0])))


def vocabulary_spelt(word: str) -> str | None:
    """The one vocabulary word that `word` misspells (`vocabulary_near`), or None."""
    near = vocabulary_near(word)
    return near[0] if len(near) == 1 else None


def respellings(text: str) -> list[tuple[str, str]]:
    """Each misspelt word of `text` and the word `respelt` reads it as, in order, each once."""
    out: list[tuple[str, str]] = []
    for m in _WORD.finditer(text):
        word = _spelt(m[0])
        if word is not None and (m[0].lower(), word) not in out:
            out.append((m[0].lower(), word))
    return out


def respelling_notes(text: str) -> list[str]:
    """What `respelt` changed in `text`, said ("read 'whih' as 'which'"): a result's assumptions."""
    return [f"read {typed!r} as {word!r}" for typed, word in respellings(text)]
