"""Actions, things and tools the system has no word for (issue 23): "put the pillow on the sofa and fluff
it", "put the spoon in the goblet and put it in the sink", "use the left arm".

Actions (`unknown_verbs`). A word that opens a command (at the text's or a clause's start, or after
"and", "then", "please") and is followed by its object ("it", "them", a determiner) is the command's
verb. When English knows that word but none of the project's word tables does (the lexicon,
`content_words.txt`, the order and politeness lists), no base task does what it says: it is unread,
and the instruction is refused, never read as the commands around it.

Not judged: prepositions ("behind the mug"), words in -ly ("gently the ...") and in -ing ("containing a
knife": a participle describes a thing), and words English does not know (the spelling rule's business).

Order words misspelt (`misspelt_order_words`): the spelling rule respells an order word only where it is
the one English word one edit away ("befoer", "lastyl"). A word of four letters or more that no list and
no English knows and that is one edit from an order word, but was left as written because other words
are as near ("thne": "then", "the", "thee"; "frst": "first", "fist"), is unread: the order it may say is
never read as if it were absent.

Other misspelt words (`misspelt_words`): a word the spelling rule left as written because it is one slip
from several words of the vocabulary, one of them an order, count or negation word, or from such a word
without its margin over English ("nevr": "never" or "near"), is unread, named with what it may be.

Things (`unknown_things`): the thing a placing verb acts on, or the place after "in" / "into" / "onto" /
"to", whose head word English knows and no word table does ("put the spoon in the goblet", "move the
tray"), is unread: no object of the world is called so, and a reading without it (the spoon put in the
sink) would drop it. So is such a thing added to a task ("and the zebra too", "plus the zebra", "so does
the zebra", "The zebra too.") or named after "with" / "by" / a placing's "on" ("washed with the zebra"), and
a placing said as done already ("the carer already put the mug in the sink": `done_already`). Not judged: a
head with "of" after it (a part or an amount: "the ledge of the sink",
"a slide of lettuce"), words of position ("the corner", "the middle"), colours, sizes and states before
a noun ("the black and white statues").

Words before a name (`unknown_modifiers`): between a determiner or a placing verb and an object's name,
a word English knows that no word table knows and that is not among the words people use of household
things (colours, sizes, materials, shapes, states: `descriptive_words.txt`, built from ALFRED's train
annotations by scripts/build_descriptive_words.py) names a thing or a state no reading uses ("the heather
apple", "the garden apple"): it is unread, named, with the state word a reading could use that it may
misspell ("heather": 'heated'). An adjective English knows (lemminflect's lexicon) that is no verb's
participle describes the thing as a colour does and is read past ("the tiny / ceramic / rotten mug"),
unless it is one slip from such a state word; a participle ("the broken clock") is a state no reading
uses. Not judged: words English does not know (the spelling rule's business), words after a relation or a
clause break ("next to the sink"), words in -ly, a thing's own ("its matching plate": which of its
things, not what it is; "the hiking watch" is judged), and a proper name written with a capital inside a
sentence before a name in lower case ("the Samsung phone": a make, as "my" says whose; `maker_name`),
unless it is a slip of a state word ("the Heather apple").

Tools (`unused_tools`): "use the left arm", "using the sponge": what a task is to be done with. Only the
tools a task takes or its kind implies are read (the knife of a slice, the lamp of an examination); any
other is unread, never dropped (the plan would not use it).

>>> [u.words for u in unknown_verbs("put the pillow on the sofa and fluff it")]
['fluff']
>>> unknown_verbs("put the pillow on the sofa and then put it back")
[]
>>> [u.words for u in unknown_things("put the spoon in the goblet and put it in the sink")]
['goblet']
>>> unknown_things("put the spoon on the ledge of the sink")
[]
>>> [u.words for u in unknown_modifiers("put the heather apple in the trash bin")]
['heather']
>>> unknown_modifiers("put the small red apple in the fridge")
[]
>>> [u.words for u in misspelt_order_words("put the apple in the fridge, thne the mug in the sink")]
['thne']
"""

from __future__ import annotations

import re
from functools import cache
from importlib import resources

from nl2hltl2plan.language.content_words import (
    COMMAND_WORDS,
    DETERMINERS,
    LOCATIVE,
    OBJECT_START,
    ROOM_WORDS,
    Unread,
    categories,
    vocabulary,
    word_categories,
)
from nl2hltl2plan.language.grounding import Mention, find_mentions, lexicon, tokens
from nl2hltl2plan.language.memo import reading_memo
from nl2hltl2plan.language.parse_usage import ParseUsage
from nl2hltl2plan.language.spelling import (
    english_frequency,
    english_lemmas,
    english_word,
    known_word,
    listed_word,
    one_edit,
    structure_word,
    vocabulary_near,
    vocabulary_spelt,
)

_COMMAND_START = COMMAND_WORDS | {"next", "finally", "lastly"}
_OBJECT_START = OBJECT_START | {"both", "all", "each", "every"}
_PREPOSITIONS = LOCATIVE | {
    "to", "into", "onto", "upon", "toward", "towards", "past", "through", "via", "outside", "around",
    "beside", "besides", "within", "over", "up", "down", "out", "for", "like", "than", "as",
}  # fmt: skip
# words that open a clause without naming its action: conjunctions, pronouns, auxiliaries and the verbs
# whose object the action follows ("let it cool", "use the knife to slice ...", "have the mug in the sink")
_NO_ACTION = frozenset(
    "but or nor yet so plus except including especially even only just too either neither whether while "
    "where when which what who how why there here you we they he she i let allow have has had use need want "
    "like try help be is are was were do does did can could will would should must may might shall".split()
)
_CLAUSE_BREAK = re.compile(r"[,.;:!?()]|\s[-–—]\s")
ACTION_REASON = "no base task does this: an action the system has no word for"


Tokens = list[tuple[str, int, int]]


def unknown_verbs(instruction: str, toks: Tokens | None = None) -> list[Unread]:
    """The verbs of commands in `instruction` (its `tokens`, where the caller has them) that English knows
    and no word table of the project does."""
    toks = tokens(instruction) if toks is None else toks
    out = []
    for i, (word, start, _) in enumerate(toks[:-1]):
        opens = i == 0 or toks[i - 1][0] in _COMMAND_START or _CLAUSE_BREAK.search(
            instruction[toks[i - 1][2] : start]
        )
        closing = _closing_pronoun(instruction, toks, i)
        if opens and toks[i + 1][0] in _OBJECT_START and _unknown_action(word, closing):
            out.append(Unread(word, "action", ACTION_REASON))
    for m in _LET.finditer(instruction.lower()):  # "and let it soak": the action after its thing
        verb = m["verb"] or m["verb2"]
        if _unknown_action(verb) and verb not in {u.words for u in out}:
            out.append(Unread(verb, "action", ACTION_REASON))
    return out


# "let it soak", "leave it to drain", "allow them to cool": an action left to the thing itself (issue 23)
_LET_THING = r"(?:it|them|(?:the|that|this|those|these)\s+[a-z]+)"
_LET = re.compile(
    rf"\blet\s+{_LET_THING}\s+(?P<verb>[a-z]+)\b|\b(?:allow|leave)\s+{_LET_THING}\s+to\s+(?P<verb2>[a-z]+)\b"
)


def _unknown_action(word: str, closing: bool = False) -> bool:
    """`closing`: the command is only the word and "it"/"them" ("and label it."): there a word the lists
    name only in a comment or as a category ("label") is no word they hold; elsewhere it is ("also the
    mug", "give the watch a look": words the readers know though no list holds them)."""
    if len(word) < 3 or word in DETERMINERS | _PREPOSITIONS | _NO_ACTION:
        return False
    if word.endswith(("ly", "ing", "'s")):  # an adverb, a participle, a possessive
        return False
    known = listed_word(word) if closing else known_word(word)
    return not known and not categories(word) and english_word(word)


def _closing_pronoun(instruction: str, toks: Tokens, i: int) -> bool:
    """Is the word at i followed by "it"/"them" and then the end of its clause?"""
    if toks[i + 1][0] not in ("it", "them"):
        return False
    return i + 2 == len(toks) or bool(_CLAUSE_BREAK.search(instruction[toks[i + 1][2] : toks[i + 2][1]]))


# what is acted on after these words: a placing or treating verb, or the preposition of a destination
_TAKES_A_THING = frozenset(
    "in into onto to inside put place move set drop take grab pick wash rinse clean heat cool chill slice "
    "cut bring carry throw toss".split()
)
# a thing added to another: "and the zebra", "plus the zebra", "so does the zebra" (the additive rules read
# it as another task's thing; one no word table knows was dropped at exit 0)
_ADDS_A_THING = frozenset("and plus does do".split())
_POINTING = frozenset("that this these those".split())
# what a thing is done with or beside ("washed with the zebra", "put in the sink by the zebra")
_BESIDE_A_THING = frozenset("with by".split())
_THING_DETERMINERS = frozenset(
    "the a an my your its their that this these those some both two another".split()
)
# nouns of position and amount, and words that describe a thing before its noun
_NOT_A_THING = frozenset(
    "right left corner edge middle center centre front back side sides top bottom wall floor ground end "
    "rest spot location area space room way place half part bit lot other one ones same kitchen bedroom "
    "bathroom office house home black white grey gray red blue green yellow brown orange pink purple gold "
    "silver golden new old large small big little deep tall short clean dirty empty full wet dry cold hot "
    "warm closest farthest nearest time".split()
) | frozenset(w.split()[-1] for w in ROOM_WORDS)  # "in the hall", "in the living room"
# the words a noun phrase opens after: what is between one of them and a name describes the thing
MODIFIER_OPENS = _THING_DETERMINERS | _TAKES_A_THING | DETERMINERS | frozenset(
    "any each every all his her".split()
)
_THING_ENDS = LOCATIVE | _COMMAND_START | frozenset(
    "to into onto or with before after until once go goes too both each as".split()
)
THING_REASON = "no object of this world is called so"


def unknown_things(instruction: str, toks: Tokens | None = None) -> list[Unread]:
    """The things acted on or put into in `instruction` (its `tokens`, where the caller has them) whose name
    English knows and no word table does."""
    toks = tokens(instruction) if toks is None else toks
    out = []
    for i in range(len(toks) - 2):
        if not _opens_a_thing(toks, i) or toks[i + 1][0] not in _THING_DETERMINERS:
            continue
        if toks[i][0] not in _TAKES_A_THING and toks[i + 1][0] in _POINTING:
            continue  # "do that, though", "and this time": no thing added
        if toks[i][0] == "to" and i and toks[i - 1][0] in ("next", "close", "up"):
            continue  # "next to the fireplace": a landmark, where the thing is
        head = _head(instruction, toks, i + 2)
        if head is not None and _unknown_thing(head):
            out.append(Unread(head, "object", THING_REASON))
    for m in _ALSO_SAID.finditer(instruction):  # "Put the mug in the sink. The zebra too."
        if _thing_said(m):
            out.append(Unread(m.group(1).lower(), "object", THING_REASON))
    return out


def thing_alone(sentence: str) -> str | None:
    """The thing `sentence` names, alone or added ("The giraffe.", "The zebra too."), that English knows as a
    noun and no word table does: a thing the world lacks, which the frame rule keeps for check 1 to name
    (h307; "The end.", "The usual." name no thing); None where it names none."""
    m = _ALSO_SAID.fullmatch(sentence.strip())
    return m.group(1).lower() if m is not None and _thing_said(m) else None


def _thing_said(m: re.Match[str]) -> bool:
    word = m.group(1).lower()
    if known_word(word) or categories(word) or word in _NOT_A_THING or not _unknown_thing(word):
        return False
    return m.group(0).rstrip(" .!?").lower().endswith(("too", "as well", "also")) or (
        "NOUN" in english_lemmas(word)
    )


# a sentence that adds one thing to the task before it, or names one alone after a request ("Put the mug in
# the sink. The giraffe.": a thing the lexicon lacks, named, not dropped as frame, h307)
_ALSO_SAID = re.compile(
    r"(?:^|[.!?;]\s+)(?:the|a|an|my|your|that|this)\s+([a-z]+)"
    r"(?:\s+(?:too|as well|also)\b|\s*[.!?]+(?=\s|$)|\s*$)",
    re.I,
)


def _opens_a_thing(toks: Tokens, i: int) -> bool:
    word, before = toks[i][0], toks[i - 1][0] if i else ""
    if word in ("on", "upon"):  # "put it on the zebra": a destination (not "on the weekend")
        return before in _PLACED_ON
    return word in _TAKES_A_THING | _ADDS_A_THING | _BESIDE_A_THING


_PLACED_ON = frozenset("it them put set place placed go goes".split())


def _head(instruction: str, toks: Tokens, start: int) -> str | None:
    """The noun that ends the phrase opening at token `start` (at most two words), or None where a known
    word, a word of position or a part ("of") comes first."""
    for j in range(start, min(start + 2, len(toks))):
        word = toks[j][0]
        if known_word(word) or categories(word) or word in _NOT_A_THING:
            return None
        last = j + 1 == len(toks)
        nxt = "" if last else toks[j + 1][0]
        if nxt == "of":
            return None
        if last or nxt in _THING_ENDS or _CLAUSE_BREAK.search(instruction[toks[j][2] : toks[j + 1][1]]):
            return word
    return None


def _unknown_thing(word: str) -> bool:
    return len(word) > 2 and not word.endswith(("ly", "ing", "ed", "'s")) and english_word(word)


# words that end a walk back from a name without opening its phrase: a relation, a clause's start
MODIFIER_STOPS = _PREPOSITIONS | _NO_ACTION | COMMAND_WORDS
MODIFIER_REASON = "no reading uses this word before a name: a thing or a state the system has no word for"


def unknown_modifiers(instruction: str, toks: Tokens | None = None) -> list[Unread]:
    """The words before an object's name, in a phrase a determiner or a placing verb opens (at most two),
    that English knows and neither a word table nor the words people use of household things
    (`descriptive_words.txt`) does: "the heather apple", "the garden apple". Each is named, with the state
    word a reading could use that it is one or two slips from, its first letter kept as people keep it
    ("heather": may misspell 'heated'; "broken" is no slip of "frozen")."""
    toks = tokens(instruction) if toks is None else toks
    out: list[Unread] = []
    for m in find_mentions(instruction):
        if m.entry.generic:  # "the earlier tasks": no object's name
            continue
        before = modifiers_before(instruction, toks, m.start)
        for k, word in enumerate(before):  # nearest the name first
            near = _unknown_modifier(word) if word not in {u.words for u in out} else None
            if near == [] and maker_name(instruction, toks, m.start - 1 - k, m.start):
                continue  # "the Samsung phone": a make, as "my" says whose
            if near == [] and _first_word_of_its_name(word, m):
                continue  # "a tennis racquet": "tennis" opens a name of the same thing ("tennis racket")
            if near is not None:
                said = f"; may misspell {' or '.join(map(repr, near))}" if near else ""
                out.append(Unread(word, "object", MODIFIER_REASON + said))
    return out


def maker_name(instruction: str, toks: Tokens, at: int, name: int) -> bool:
    """Whether the word of token `at` is a proper name before the thing's name (token `name`): written with
    a capital inside a sentence, the name after it in lower case ("the Samsung phone", "the IKEA lamp",
    not "Put The Garden Apple ..."). A maker's or a brand's name says which make the thing is, as "my"
    says whose, not what it is."""
    start = toks[at][1]
    opens_sentence = _SENTENCE_END.search(instruction[:start]) is not None
    said = instruction[toks[name][1] : toks[name][2]]
    return instruction[start].isupper() and not opens_sentence and said.islower()


_SENTENCE_END = re.compile(r"(?:^|[.!?:;\n\"(])\s*$")


def modifiers_before(instruction: str, toks: Tokens, start: int) -> list[str]:
    """The words between the opening word of the phrase whose name starts at token `start` and the name
    (at most two; none where no opening word comes first, or a relation or a clause break does)."""
    words: list[str] = []
    for j in range(start - 1, max(start - 4, -1), -1):
        word = toks[j][0]
        if _CLAUSE_BREAK.search(instruction[toks[j][2] : toks[j + 1][1]]) or word in MODIFIER_STOPS:
            return []
        if word in MODIFIER_OPENS:  # "its designated plate", "their matching cups": the thing's own, whose
            return [] if word in _POSSESSIVE else words  # words say which of its things, not what it is
        words.append(word)
    return []


_POSSESSIVE = frozenset({"its", "their", "his", "her"})


def _unknown_modifier(word: str) -> list[str] | None:
    """None where `word` before a name is read past; else the state words it may misspell (`_near_state`,
    computed once: the adjective test and the hint both use it)."""
    if len(word) < 3 or not word.isalpha() or word.endswith("ly") or word in _NOT_A_THING:
        return None
    if categories(word) or word in descriptive_words():
        return None
    if name_part(word):  # "the tennis book": "tennis" names a tennis racket, a thing no reading uses
        return []
    near = _near_state(word)
    if known_word(word):  # a name ("cleaner", a spray) used as an adjective one slip from a state word
        return near if adjective(word) and any(s in one_edit(word) for s in near) else None
    if adjective(word) and not any(s in one_edit(word) for s in near):
        return None  # "the tiny mug" describes the mug; "the heather apple" names a plant, or 'heated'
    if not english_word(word):  # "a cean rag", "the rnsed cloth": one slip from a state word (a reading
        # that reads past it loses the treatment), unless the respelling makes it one vocabulary word
        slips = [s for s in near if s in one_edit(word)]
        return slips if slips and not vocabulary_spelt(word) else None
    return near if not _slip_of_descriptive(word) else None


def _first_word_of_its_name(word: str, m: Mention) -> bool:
    """Whether `word` opens a name of many words (the lexicon's) of a type the name after it names too."""
    return any(
        key[0] == word and len(key) > 1 and set(entry.types) & set(m.entry.types)
        for key, (entry, _) in lexicon().items()
    )


@cache
def name_part(word: str) -> bool:
    """Is `word` only a first word of the lexicon's names of many words ("tennis" of "tennis racket",
    "cell" of "cell phone"), never a name alone, and a word English knows only as a noun? Before another
    name it names another thing ("the tennis book"), as "the garden apple" does; a word English also
    uses as an adjective or a verb's form ("standing lamp", "dining table") may describe the thing."""
    from lemminflect import getAllLemmas  # type: ignore[import-untyped]

    keys = lexicon().keys()
    if (word,) in keys or not any(word in key[:-1] for key in keys if len(key) > 1):
        return False
    return set(getAllLemmas(word)) == {"NOUN"}


def _near_state(word: str) -> list[str]:
    """The state words a reading could use that `word` is one or two slips from, its first letter kept."""
    near = [s for s in state_words() if s[0] == word[0] and _two_slips(word, s)]
    return [s for s in near if not any(n != s and n.startswith(s) for n in near)]  # "sliced", not "slice"


def _two_slips(a: str, b: str) -> bool:
    """Whether `b` is at most two slips from `a`: `spelling.one_edit` (a letter more, less, changed, two
    neighbours swapped) composed, met in the middle."""
    near_a = one_edit(a) | {a}
    return b in near_a or bool(near_a & one_edit(b))


@cache
def adjective(word: str) -> bool:
    """Whether English uses `word` as an adjective and not as a verb's form (lemminflect's lexicon): "the
    tiny / ceramic / favorite mug" describes the thing the name names, as a colour does; a noun ("the
    heather apple", "the garden hose") names another thing, and a participle ("the broken clock", "the
    chipped mug") a state the thing was brought into, which no reading uses."""
    from lemminflect import getAllLemmas  # type: ignore[import-untyped]  # here: its lexicon loads in 0.3 s

    said = getAllLemmas(word)
    return "ADJ" in said and all(lemma == word for lemma in said.get("VERB", ()))  # "spare", not "broken"


SLIP_RATIO = 0.01  # "wite" (60) is a slip of "white" (228,772); "heather" (1,677) is no slip of "leather"


def _slip_of_descriptive(word: str) -> bool:
    """Whether `word` is one slip from a descriptive word that English uses a hundred times as often: a
    rare word so near a common one is its misspelling ("the wite safe"), and describes as it does."""
    freq = english_frequency(word)
    return any(freq < SLIP_RATIO * english_frequency(d) for d in one_edit(word) & descriptive_words())


@cache
def descriptive_words() -> frozenset[str]:
    """The words people use before the names of household things (`descriptive_words.txt`)."""
    return word_categories("descriptive_words.txt")["words"]


@cache
def state_words() -> tuple[str, ...]:
    """The states a reading uses, as said of a thing ("heated", "chilled", "sliced", "clean"): the verbs of
    heating, cooling, cleaning and slicing (`content_words.txt`) and the past forms English knows of them."""
    kinds = ("verb_heat_place", "verb_cool_place", "verb_clean_place", "verb_sliced")
    verbs = sorted(w for k in kinds for w in vocabulary()[k])
    forms = (f for v in verbs for f in (v + "ed", v + "d", v + v[-1] + "ed") if english_word(f))
    return tuple(dict.fromkeys([*forms, *verbs]))


_USE = re.compile(r"\b(?:use|using|utili[sz]e|utili[sz]ing|with the help of)\s+")
_TOOL_END = re.compile(r"[,.;:!?()]|\s(?:to|and|then|for|so|in order)\b")


def unused_tools(instruction: str, mentions: list[Mention], parse: ParseUsage) -> list[Unread]:
    """ "Use X" / "using X" where X names nothing a task takes or its kind implies (a knife to slice)."""
    lowered = instruction.lower()
    used = {t for _, _, types in parse.slots() for t in types} | parse.implied()
    out = []
    for m in _USE.finditer(lowered):
        end = _TOOL_END.search(lowered, m.end())
        stop = end.start() if end else len(lowered)
        named = [x for x in mentions if m.end() <= x.char_start < stop]
        if not any(set(x.entry.types) & used for x in named):
            out.append(Unread(instruction[m.start() : stop].strip(), "action", TOOL_REASON))
    return out


TOOL_REASON = "no base task is done with this: a task uses only the tools its kind implies"


ORDER_TYPO_REASON = "may misspell an order word, as near to other words: say the order as you mean it"
_ORDER_WORD_SHAPE = re.compile(r"(?<![A-Za-z'])[A-Za-z]{4,}(?![A-Za-z'])")  # as the spelling rule's words


@reading_memo  # a function of the text alone: check 1 asks it again for each other set of tasks
def unread_words(instruction: str, toks: Tokens | None = None) -> list[Unread]:
    """Unknown verbs, things and modifiers, and misspelt order words, in that order (check 1's unknown
    words)."""
    toks = tokens(instruction) if toks is None else toks
    unknown = unknown_verbs(instruction, toks) + placeless_arrangements(instruction, toks)
    unknown += exclaimed_things(instruction) + unknown_things(instruction, toks)
    unknown += unknown_modifiers(instruction, toks) + done_already(instruction)
    unknown += foreign_sentences(instruction)
    order = misspelt_order_words(instruction)
    return unknown + order + misspelt_words(instruction, {u.words for u in order})


FOREIGN_REASON = (
    "no word of it is one the reader knows (a foreign or unknown phrase): say it in English or leave it out"
)
_SENTENCE_PART = re.compile(r"[^.!?;,\n]+")  # (not at a colon: "[10:02] Kai: ..." labels its line)


def foreign_sentences(instruction: str) -> list[Unread]:
    """A sentence (or a part set off by a comma) in which no word is one the reader's lists know
    and some word no list of English knows ("Rien ne va plus.", "Zorblax quing."): it was read as nothing,
    and what it says (a foreign "no more", a name) is not known to be frame. Only the frame rule drops a
    sentence, and a word English does not know is never its filler (`frame_filler.filler`), so it is
    unread, named in the user's words."""
    out = []
    for m in _SENTENCE_PART.finditer(instruction):
        words = re.findall(r"[a-z]+", m[0].lower())
        if not words or any(known_word(w) or categories(w) for w in words):
            continue
        if any(not english_word(w) for w in words):
            out.append(Unread(" ".join(m[0].split()), "words", FOREIGN_REASON))
    return out


# a placing said as done ("the morning carer already put the mug in the sink"): a statement, no request
_DONE_ALREADY = re.compile(
    r"\balready\s+(?:been\s+)?(?:put|placed|moved|set|thrown|done|took|taken|brought|tidied)\b", re.I
)


def done_already(instruction: str) -> list[Unread]:
    """A placing said as done already, which a reading would do again: unread, named."""
    reason = "said as done already: say it as a request if it is to be done"
    return [Unread(m[0], "action", reason) for m in _DONE_ALREADY.finditer(instruction)]


def misspelt_order_words(instruction: str) -> list[Unread]:
    """The words of `instruction` (as the spelling rule left it) that no list and no English knows and that
    are one edit from an order word (`content_words.txt`'s `order` and `any_order`)."""
    words = vocabulary()["order"] | vocabulary()["any_order"]
    out: list[Unread] = []
    for m in _ORDER_WORD_SHAPE.finditer(instruction):
        low = m[0].lower()
        if known_word(low) or english_word(low) or not one_edit(low) & words:
            continue
        if low not in {u.words for u in out}:
            out.append(Unread(low, "order", ORDER_TYPO_REASON))
    return out


def misspelt_words(instruction: str, named: set[str] | frozenset[str] = frozenset()) -> list[Unread]:
    """The words of `instruction` (as the spelling rule left it) that may misspell an order, count or
    negation word and another word (`spelling.vocabulary_near`: a tie, or a margin not met), each named with
    what it may be ("'nevr': may misspell 'never' or 'near'"); not the words in `named`. A tie of other
    words ("plae": "place" or "plate") is left to check 1's other tests: a name or a verb a reading does
    not use is named there (an invented slot, a clause unread), and one it does not need is no loss."""
    out: list[Unread] = []
    for m in _ORDER_WORD_SHAPE.finditer(instruction):
        low = m[0].lower()
        near = vocabulary_near(low)
        if any(map(structure_word, near)) and low not in named and low not in {u.words for u in out}:
            said = " or ".join(filter(None, [", ".join(map(repr, near[:-1])), repr(near[-1])]))
            out.append(Unread(low, "spelling", f"may misspell {said}: say it as you mean it"))
    return out


ARRANGING_REASON = "no base task lays things together: say where each thing goes"


def placeless_arrangements(instruction: str, toks: Tokens) -> list[Unread]:
    """A command in an arranging verb (`arranging_verbs.txt`: stack, arrange, serve) with nothing after it but
    "it"/"them" before its clause ends ("Then stack them.", "Then serve."): no place and no thing of its
    own, it asks how things lie together, which no base task does (read as nothing, it was dropped)."""
    out = []
    for i, (word, start, end) in enumerate(toks):
        opens = i == 0 or toks[i - 1][0] in _COMMAND_START or _CLAUSE_BREAK.search(
            instruction[toks[i - 1][2] : start]
        )
        if not opens or word not in _arranging_verbs():
            continue
        rest = _CLAUSE_BREAK.split(instruction[end:], maxsplit=1)[0]
        # "Arrange, in any order: ...": a list follows, the places in it
        stop = instruction[end + len(rest) : end + len(rest) + 1]
        if set(rest.lower().split()) <= _ARRANGED and stop in ("", ".", "!", "?", ";"):
            out.append(Unread(word, "action", ARRANGING_REASON))
    return out


_ARRANGED = frozenset("it them all up neatly nicely together please".split())


@cache
def _arranging_verbs() -> frozenset[str]:
    text = resources.files("nl2hltl2plan.language").joinpath("arranging_verbs.txt").read_text()
    return frozenset(w for ln in text.splitlines() if not ln.startswith("#") for w in ln.split())

EXCLAIMED_REASON = "an exclamation names a thing and asks nothing: say what to do with it"
_SENTENCE = re.compile(r"[^.!?;]+!")
_NO_THING = frozenset("too also next now then first last and please".split())


def exclaimed_things(instruction: str) -> list[Unread]:
    """A sentence ending in "!" that names a thing and, besides it, only words no list holds ("Carrot
    time!", "Carrot duty!"): it asks no action, and read as a placing it would invent one. An additive or
    order word ("The carrot too!", "Carrot next!") or a place ("Carrot on the plate!") asks one."""
    out = []
    for m in _SENTENCE.finditer(instruction):
        text = m[0].strip(" !")
        named = [x for x in find_mentions(text) if not x.entry.generic]  # "Sure thing!" names nothing
        if not named:
            continue
        words = [w for w, s, _ in tokens(text) if not any(x.char_start <= s < x.char_end for x in named)]
        words = [w for w in words if w not in DETERMINERS]
        if words and not set(words) & (_NO_THING | _PREPOSITIONS) and not any(map(categories, words)):
            out.append(Unread(text, "action", EXCLAIMED_REASON))
    return out
