"""The tabletop reading's clauses that name nothing (issue 28), read by what their words are rather than
by a list of phrasings (`remarks_read`, asked by `tabletop_wording.plain_words`): a clause made only of
greetings, courtesy and the user's own time ("hey", "when you get a sec", "mind doing me a favour?", "no
rush") is removed; a list's heading made of a verb of tidying and a word for the things ("Please sort
these:", "organise this for me") is removed; a clause that speaks of the order (or of which comes first,
or of what depends on what) and says it is free ("the order in which you do them is irrelevant", "it makes
no difference which one you do first", "none of these depends on another") becomes "in any order", or
"within each group in any order" when it speaks of each group ("the order within each pair does not
matter"); a frame that opens the text (a short clause with no word that could say an action, order,
count, negation, place, manner or goal: "Helm,", "Howdy partner,", a title), a clause that only urges or
announces ("make it so", "quick one") and a question heading that asks where things go ("What goes
where?") are removed; so is a remark that asks nothing wherever it stands (`asks_nothing`: a sentence, a
clause opening or closing the text, or a reason given for a step, opened by a subject of its own, a person
addressed or thanks, with no word that asks, places, orders or counts: "I've got a bit of a weird request",
"..., me hearty", "..., so it's easy to check"). The courtesy words are `courtesy.txt`'s (`courtesy_word`,
`your_time`, `unhurried`, `urging`, `aside`).

>>> import re
>>> remarks_read("hey, carrot on the blue plate. no rush. it makes no difference which comes first",
...              re.compile("carrot"))
', carrot on the blue plate.. in any order'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import categories, free_order_phrase
from nl2hltl2plan.language.courtesy import courtesy_pattern, courtesy_words
from nl2hltl2plan.language.statements import asked_before

# the shared list (free_order.txt), anywhere in the text: "in any order", "the order is up to you", also
# with a comma between its words ("Which order, is not important", "Within each step, any order")
FREE_ORDER = re.compile(r"\b" + free_order_phrase().replace(r"\s+", r",?\s+") + r"\b")

# ---- clauses that name nothing: courtesy, list headings, freedom statements --------------------------------
# (read word by word, whatever their phrasing: every word must belong to the clause's kind)
_SENTENCE_PIECE = re.compile(r"[^.;:!?()\n]+")
_CLAUSE = re.compile(r"[^,.;:!?()\n]+?(?=\s+-\s+|[,.;:!?()\n]|$)")
_COURTESY_WORDS = courtesy_words("courtesy_word")
_UNHURRIED = re.compile(rf"\b{courtesy_pattern('unhurried')}\b")
TIDY_VERB = r"(?:sort|organi[sz]e|arrange|tidy|handle|do|fix|set\s+up|lay\s+out)"
_THE_THINGS = (
    r"(?:these|this|that|them|things|stuff|everything|the\s+(?:items|things|fruits?|plates|following))"
)
_HEADING_FRAME = re.compile(
    rf"^{TIDY_VERB}\s+(?:(?:out|up)\s+)?{_THE_THINGS}(?:\s+(?:out|up))?(?:\s+for\s+(?:me|us))?$"
)
# a freedom statement: what it is about (the order, which comes first, what depends on what; "who moves in
# first": a voice's things said as people, h262) ...
_ORDER_TOPIC = re.compile(
    r"\b(?:order(?:ing)?|sequenc(?:e|ing)|(?:which|who)(?:ever)?\b[a-z'\s]{0,24}?\b(?:first|(?:start|begin)(?:\s+with)?)|"
    # "either one can go first", "any step may come first", "either of the steps may be done first"
    r"(?:either|any|whichever)(?:\s+(?:one|step|task|placement|move|part|item)|\s+of\s+(?:them|the\s+(?:two\s+)?"
    r"(?:steps|tasks|placements|moves|parts|items)))?\s+(?:(?:can|may|could|might)\s+)?"
    r"(?:(?:go|goes|come|comes|be\s+done|be\s+placed)\s+)?first|"
    # the way to the end state: in this world what is left to choose on the way is the order
    r"how\s+you\s+get\s+(?:there|it\s+done)|(?:the\s+)?(?:route|path|way)\s+(?:there|you\s+take))\b"
)
_INDEPENDENT = re.compile(
    r"\b(?:none|neither|no\s+one)\s+of\s+(?:these|them|those|the\s+\w+)\s+depends?\s+on\s+(?:another|any\s+other|"
    r"the\s+others?|each\s+other|one\s+another)\b|\b(?:they|these|those|them)\s+(?:are|'re)\s+(?:all\s+)?"
    r"independent(?:\s+of\s+(?:each\s+other|one\s+another))?\b|"
    # "each one independent of the others", "every one is independent of the rest"
    r"\b(?:each|every)(?:\s+one)?\s+(?:(?:is|being)\s+)?independent(?:\s+of\s+(?:the\s+others?|the\s+rest|"
    r"each\s+other|one\s+another|any\s+other))?\b"
)
# ... and what it says of it
_FREE_PREDICATE = re.compile(
    r"\b(?:(?:does|do|did|will|would|should)(?:\s+not|n't|nt)\s+matter|no\s+matter|matters\s+not|irrelevant|"
    r"immaterial|inconsequential|"
    r"unimportant|not\s+(?:important|critical|crucial|essential|vital|relevant|significant)|of\s+no\s+(?:consequence|importance|import)|up\s+to\s+you|(?:your|the\s+robot's)\s+"
    r"(?:call|choice|decision|pick)|(?:are|'re|is|'s)\s+free|free\s+to\s+(?:choose|pick|decide)|"
    r"(?:can|may|get\s+to)\s+(?:choose|pick|decide)|any|either|whatever|whichever|arbitrary|flexible|optional|"
    r"not\s+(?:specified|fixed|set|required|needed|prescribed|imposed|mandated)|unspecified|no\s+(?:particular|special|specific|set|fixed|given|prescribed)|(?:i|we)\s+(?:don't|do\s+not)\s+"
    r"(?:care|mind)|(?:makes?|is)\s+no\s+(?:difference|odds)|do\s+(?:whatever|as\s+you\s+(?:like|please))|"
    r"(?:as|however|whichever\s+way)\s+you\s+(?:like|please|wish|want|prefer|see\s+fit))\b"
)
# "within each pair", "inside each", "within a priority", "for every plate": what a freedom statement is about
_EACH_GROUP = re.compile(
    r"\b(?:(?:within|inside)\s+(?:each|every|a|one|the\s+same)|(?:in|for)\s+(?:each|every))(?:\s+(?!order\b)[a-z]+)?\b"
)
_FREEDOM_FILLER = frozenset(
    "the in which you do them they these those this it that of for me us to is are be at all really totally "
    "entirely quite completely here and so just it's its can may will how place placement placements put "
    "one ones a way round i we honestly pretty much first go goes what done like want prefer wish choose "
    "pick fine ok okay good correct acceptable allowed permitted works work suits suit by with fancy mix up "
    "shuffle change vary switch thereof "
    "move moves steps tasks jobs performed carried out executed completed tackled".split()
)
_NEGATION = re.compile(r"\b(?:not|never|no|none)\b|n't\b")


def remarks_read(text: str, mention: re.Pattern[str], name_words: frozenset[str] = frozenset()) -> str:
    """`text` with each sentence, or else each clause, that names no object or plate read by its words
    (see the module docstring): courtesy, list headings and frames (`frame_read`; none with a word of a name
    in `name_words`: "the yellow" is a plate) removed, freedom statements said as "in any order" or "within
    each group in any order". Any other clause is left as it is, for the readers."""
    text = _ORDER_LABEL.sub(" the order is ", _SENTENCE_PIECE.sub(lambda m: _opener_dropped(m[0]), text))
    text = reasons_dropped(text, mention, name_words)
    for pieces in (_SENTENCE_PIECE, _CLAUSE):
        low, out, at = text.lower(), [], 0
        for piece in pieces.finditer(low):
            words = piece[0].strip(" -")
            if not words or mention.search(words):
                continue
            read = None if FREE_ORDER.fullmatch(words) else _clause_read(words)  # a listed remark stays
            if read is None:
                before, after = low[: piece.start()], low[piece.end() :]
                set_apart = before.rstrip()[-1:] in _APART and after.lstrip()[:1] in _APART  # not ") follows"
                at_start = set_apart and not _WORD.search(before)  # a closing word may say an order
                asked = low.startswith("?", piece.end())
                titled = low.startswith(":", piece.end()) and not _WORD.search(before)
                named = not name_words.isdisjoint(re.findall(r"[a-z]+", words))
                read = None if named else frame_read(words, at_start, asked, titled)
                if read is None and not named and _set_apart_aside(before, after, pieces is _CLAUSE):
                    read = "" if asks_nothing(words) else None
            if read is not None:
                out.append(text[at : piece.start()] + (f" {read}" if read else ""))
                at = piece.end()
        text = "".join(out) + text[at:]
    return re.sub(r"[ \t]+([,.;:!?])", r"\1", re.sub(r"[ \t]+", " ", text)).strip()


_YOUR_TIME = courtesy_words("your_time")
_YOU = frozenset({"you", "you're", "youre", "u"})


def _courtesy(words: list[str]) -> bool:
    """Are `words` courtesy alone? A word for time only beside "you" ("when you get a sec", "whenever
    you're free"; "second" alone is a step)."""
    said = set(words)
    return said <= _COURTESY_WORDS | _YOUR_TIME and (not _YOUR_TIME & said or bool(_YOU & said))


def _opener_dropped(sentence: str) -> str:
    """A sentence without the courtesy words it opens with when they speak of the user's time ("hey when
    you get a sec could you put ...": no comma sets them apart)."""
    words = list(re.finditer(r"[A-Za-z']+", sentence))
    run = 0
    while run < len(words) and words[run][0].lower() in _COURTESY_WORDS | _YOUR_TIME:
        run += 1
    said = [w[0].lower() for w in words[:run]]
    if run == len(words) or not (_YOUR_TIME & set(said) and _courtesy(said)):  # not "Second course:"
        return sentence
    return sentence[: words[0].start()] + sentence[words[run].start() :]


# "(order: doesn't matter)", "Sequence: up to you", also asked and answered ("Order? Doesn't matter."): a
# label with its value, read as one statement
_ORDER_LABEL = re.compile(
    r"(?:^|(?<=[(\n.;!?]))\s*(?:order(?:ing)?|sequence)\s*[:?]\s*(?=[a-z])", re.IGNORECASE
)
_ASKING = frozenset("i i'd we we'd want need would to".split())  # "I'd like you to sort the fruit:"
# a clause that only urges, closes or announces ("make it so", "off you go", "quick one")
# and a hurried voice's urgency ("No time to waste.", "Hurry up!", "..., just get it done"): how soon
_HURRY = (
    r"(?:no\s+time\s+to\s+(?:waste|lose)|hurry(?:\s+up)?|chop\s+chop|(?:be\s+)?quick(?:\s+about\s+it|\s+as\s+you\s+can)?|"
    r"sharpish|pronto|asap|on\s+the\s+double|(?:just\s+)?get\s+(?:it|this|them)\s+done(?:\s+(?:now|quickly|fast))?)"
)
_URGING = re.compile(rf"^(?:{courtesy_pattern('urging', 'aside')}|{_HURRY})$")
# a frame that opens the text: a short clause that names nothing and has no word that could say an
# action, order, count, negation, condition, place or manner (check 1's categories, and the words below):
# it greets, addresses or titles ("Arr", "Howdy partner", "Helm", "Tonight's challenge") and asks nothing
# (not a question; not a goal's heading, "Final layout:", which asks for the states listed after it:
# `statements.asked_before`)
_FRAME_MOST_WORDS = 3
_TITLE_MOST_WORDS = 6
# an adverb, a superlative or a direction may say how to order ("Alphabetically:", "Biggest first", "By size")
_HOW = re.compile(r"(?:ly|est|wards?|wise)$")
# a title may speak of tidying, which in this world is the placing the list after it asks for
_TIDYING = frozenset(
    "tidy tidying tidied sort sorting sorted arrange arranging arranged organise organize organising "
    "organizing organised organized".split()
)
_WORD = re.compile(r"\w")
_APART = ("", ",", ".", "!", "?", ";", ":")  # what sets a frame apart: punctuation or the text's edge
_MEANINGFUL = frozenset(
    "order ordered ordering sequence sequential sequentially respectively reverse reversed backwards "
    "alternate alternately together separately same only again also too except unless until while when if "
    "left right top bottom above below over under near beside between behind front back side middle centre "
    "center edge corner away off out down inside outside other others another else more less most least many "
    "much few several some any all both each every either neither no not never nothing none first then next "
    "last later before after now soon yet still already once twice plate plates empty full optional maybe "
    "perhaps possibly ideally preferably bonus extra instead alternatively undo reset today tonight tomorrow "
    "priority important urgent warning caution begin beginning start starting initially finally lastly "
    "afterwards afterward thereafter subsequently second secondly third fourth meanwhile done finished "
    "complete wait waits hold stop keep leave pause follow follows followed following sorry oops whoops "
    "actually rather mean meant scratch correction mistake bad by size colour color height weight "
    "alphabetical option options alternative alternatives or".split()
)
# a question that names nothing and asks where things go, answered by the list after it ("What should end
# up where?", "Where do things go?")
_WHERE = frozenset({"where", "what"})
_GOES = frozenset("go goes end ends up belong belongs land lands".split())
_ASKED_PLACES = _WHERE | _GOES | frozenset(
    "which do does should must will would things thing stuff everything each item items it they all of these "
    "them the".split()
)


# ---- asides: a remark that asks nothing, wherever it stands ------------------------------------------------
# (a whole sentence, or a clause that opens the text before a comma or closes it after one: "I've got a bit of
# a weird request", "..., me hearty"), and a reason given for a step ("..., so it's easy to check")
_SUBJECTS = frozenset(
    "i i'm i've i'd i'll we we're we've it it's it'd it'll that that's this there there's here here's they "
    "they're he she what how a an my our his her their".split()
)
_INTERJECTIONS = frozenset(
    "oh ah aw ok okay so well and but also hmm um right yeah yes wow hey hi hello".split()
)
# words that ask, or say what the asker wants or what a robot must do: never in an aside
_ASKS = frozenset(
    "you u ya ye your yours yourself please pls plz kindly be let lets let's make sure should shall must "
    "need needs needed want wants wanted like wish have has had gotta ought remember do does don't did "
    "can can't could would will won't robot robots prefer prefers preferred rather".split()
)
# words that may take back or turn round what was asked ("That's wrong.", "Ignore that.")
_CORRECTING = frozenset(
    "wrong incorrect ignore forget cancel nevermind disregard opposite swapped mixed muddled confused".split()
)
# verbs of placing, moving, keeping or using: a remark with one may ask for a placement
_PLACING = frozenset(
    "put puts place places placing set sets setting lay lays laying move moves moving drop drops bring "
    "brings carry take takes give gives hand hands stow deliver leave keep swap switch serve load fill stack "
    "pile toss throw transfer return remove pick grab clear empty plate arrange sort tidy organise organize "
    "go goes going come comes land lands end ends belong belongs sit sits stay stays use uses using "
    "handle touch hold match".split()
)
_THINKING = frozenset("hope hoping guess reckon suppose bet".split())
_THANKS = re.compile(
    r"^(?:(?:many\s+)?thanks|thank\s+you|thx|ty)(?:\s+(?:so|very)\s+much)?(?:\s+for\b|$)(?P<rest>.*)$"
)
_MANNER = re.compile(r"(?:ly|wards?|wise)$")  # "carefully", "clockwise" ("request" is no superlative here)
_REASON = re.compile(r"\b(?:because|since|so\s+that|so)\s+(?=[a-z'])[^,.;:!?()\n]*")


def _set_apart_aside(before: str, after: str, clause: bool) -> bool:
    """Does a piece stand as a whole sentence (between sentence ends, or the text's edges), or, for a clause
    (`clause`), open the text before a comma or close it after one?"""
    if clause:  # closing the text after a comma, or opening it before one
        opening = not _WORD.search(before) and after.lstrip()[:1] == ","
        return opening or (before.rstrip()[-1:] == "," and not _WORD.search(after))
    return before.rstrip()[-1:] in ("", ".", "!", "?") and after.lstrip()[:1] in ("", ".", "!", "?")


def asks_nothing(clause: str) -> bool:
    """Is `clause` (naming no object or plate) a remark that asks nothing: a clause with a subject of its own
    (or a person addressed: "me hearty"), no word that asks ("you", "please", "should", "want", a
    modal), no verb of placing, moving or using, and no word of order, count, negation, condition, time,
    place, manner or correction (`_MEANINGFUL`, `_CORRECTING`, check 1's count words, a digit, an adverb
    in "-ly")? ("me hearty", "I've got a bit of a weird request", "so it's easy to check"; not "use the
    left arm", "it can wait", "do it twice", "be careful", "that's wrong")"""
    words = re.findall(r"[a-z']+", clause)
    while words and words[0] in _INTERJECTIONS:
        words.pop(0)
    thanked = _THANKS.match(" ".join(words))  # "thank you for flying with us": its "you" asks nothing
    if thanked:
        words = thanked["rest"].split()
    if not words or re.search(r"\d", clause) or words[0] in _PLACING:
        return not words and thanked is not None
    said = set(words)
    if said & (_ASKS | _PLACING | _MEANINGFUL | _CORRECTING) or any(_MANNER.search(w) for w in words):
        return False
    if any(c.startswith("count") for w in words for c in categories(w)):
        return False
    # opened by a subject of its own (said or left out before a verb of thinking: "hope that's fine"), a
    # person addressed, or the thanks' "for", never by a verb: no imperative ("wear gloves")
    return words[0] in _SUBJECTS | _THINKING or "person" in categories(words[0]) or thanked is not None


# a reason's subject other than the one asked ("I", "the table", "the kids"), with its modal: what that one
# can do or how it is ("so that I can find them", "so that the table looks neat") is no request; the rest
# of the clause is judged as an aside ("so that the kids can grab them" stays: a verb of taking)
_SOMEONE_ELSE = re.compile(r"^(?:i|we|they|he|she|the\s+[a-z]+)(?:\s+(?:can|could|will|may))?\s+(?=[a-z])")


def reasons_dropped(text: str, mention: re.Pattern[str], name_words: frozenset[str]) -> str:
    """`text` without each reason given for a step that names nothing and asks nothing ("..., so it's easy
    to check", "because it matches", "so that I can find them"; not "so that the yellow plate is done
    first")."""

    def dropped(m: re.Match[str]) -> str:
        words = re.sub(r"^(?:because|since|so\s+that|so)\s+", "", m[0])
        words = _SOMEONE_ELSE.sub("it ", words)  # "so that I can find them": asks nothing of the robot
        if mention.search(m[0]) or not name_words.isdisjoint(re.findall(r"[a-z]+", m[0])):
            return m[0]
        return "" if asks_nothing(words) else m[0]

    return _REASON.sub(dropped, text)


def frame_read(clause: str, at_start: bool, asked: bool, titled: bool = False) -> str | None:
    """ "" for a frame that opens the text (`at_start`; a title before the text's first colon,
    `titled`, may be longer and may speak of tidying: "Recipe for a tidy table:"), or a question (`asked`)
    that names nothing and asks where things go; None for any other clause."""
    words = re.findall(r"[a-z']+", clause)
    if asked and set(words) <= _ASKED_PLACES and _WHERE & set(words) and _GOES & set(words):
        return ""
    most = _TITLE_MOST_WORDS if titled else _FRAME_MOST_WORDS
    short = 0 < len(words) <= most and not re.search(r"\d", clause)
    tidying = _TIDYING if titled else frozenset()
    meaningful = any(
        (categories(w) and w not in tidying) or w in _MEANINGFUL or _HOW.search(w) for w in words
    )
    if at_start and short and not asked and not meaningful and not asked_before(clause, len(clause)):
        return ""
    return None


def _clause_read(clause: str) -> str | None:
    """ "" for courtesy or a list heading, a free-order phrase for a freedom statement, None otherwise."""
    if not re.search(r"[a-z]", clause):  # a list number ("1."), not courtesy: the steps' readers read it
        return None
    words = re.findall(r"[a-z']+", _UNHURRIED.sub(" ", clause))
    if _courtesy(words) or _URGING.match(" ".join(words)):  # "no rush" alone too; "quick one"
        return ""
    while words and words[0] in _COURTESY_WORDS | _ASKING:  # "could you sort these out for me please"
        words.pop(0)
    if words and words[-1] == "please":
        words.pop()
    said = " ".join(words)
    if _HEADING_FRAME.match(said) or _URGING.match(said):  # "please, just do it"
        return ""
    if _HEADING_FRAME.match(FREE_ORDER.sub(" ", said).strip()) and FREE_ORDER.search(said):
        return "in any order"  # "tidy them up in any order": the heading and a freedom remark
    return _freedom_read(clause)


def _freedom_read(clause: str) -> str | None:
    """ "in any order" / "within each group in any order" for a clause that speaks of the order and says
    it is free; None when it says anything else (a negation outside the free phrase, another word)."""
    whole = _INDEPENDENT.search(clause)
    if whole is None and not (_ORDER_TOPIC.search(clause) and _FREE_PREDICATE.search(clause)):
        if not (_EACH_GROUP.search(clause) and _FREE_PREDICATE.search(clause)):
            return None
    rest = clause
    for said in (_INDEPENDENT, _ORDER_TOPIC, _FREE_PREDICATE, _EACH_GROUP):
        rest = said.sub(" ", rest)
    if _NEGATION.search(rest) or not set(re.findall(r"[a-z']+", rest)) <= _FREEDOM_FILLER:
        return None
    return "within each group in any order" if _EACH_GROUP.search(clause) else "in any order"


# ---- a user story's role ("As a hungry user, I want ...") --------------------------------------------------
_ROLE = re.compile(
    r"^\s*as\s+(?:a|an|the|your)\s+(?P<role>(?:[a-z'-]+\s+){0,2}[a-z'-]+)\s*,\s*(?=(?:i|we)\b)", re.IGNORECASE
)


def role_dropped(text: str, mention: re.Pattern[str]) -> str:
    """`text` without a user story's role opening it ("As a tidy person, I'd like ..."): who asks, which
    asks nothing; a role that names a thing or plate, or has a word of order, count or negation, stays ("As
    a first step, I want ...").

    >>> role_dropped("As a tidy person, I want the carrot on the blue plate.", re.compile("carrot"))
    'I want the carrot on the blue plate.'
    """
    m = _ROLE.match(text)
    if m is None or mention.search(m["role"]):
        return text
    words = m["role"].lower().split()
    if any(w in _MEANINGFUL or any(c.startswith("count") for c in categories(w)) for w in words):
        return text
    return text[m.end() :]
